//! Every chapter's default render at 800 × 600, timed by criterion, with
//! its throughput in rays (shadow rays included): criterion prints it as
//! "Melem/s", that is, millions of rays per second.
//!
//! Chapter 6, the path tracer, is timed the same way at 800 × 600 with 16
//! paths per pixel (its default 256 would take seconds per iteration): its
//! throughput is in rays too (every segment and shadow ray), and it prints
//! its rays per path once, so that paths/s = Mrays/s ÷ that number.
//!
//! `cargo bench -p raylab-bench`

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use raylab::indicatif::ProgressBar;
use raylab::{Camera, Sampling, Scene, Settings, Step, render};
use raylab_cli::{Chapter, Options};

fn bench_chapter<S: Step>(c: &mut Criterion, chapter: &Chapter<S>) {
    let settings = Options::defaults(chapter)
        .settings()
        .expect("the defaults are valid");
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let hidden = ProgressBar::hidden();
    // One render first, to know how many rays a render traces.
    let rays = render(&scene, &camera, &chapter.step, &settings, &hidden)
        .counts
        .total();
    let mut group = c.benchmark_group("render 800x600");
    group.throughput(Throughput::Elements(rays));
    group.sample_size(20);
    group.bench_function(chapter.binary, |b| {
        b.iter(|| render(&scene, &camera, &chapter.step, &settings, &hidden))
    });
    group.finish();
}

fn bench_path_tracing(c: &mut Criterion) {
    use ch06_path_tracing::{PathSettings, run};
    let (options, flags) =
        run::parse(["ch06-path-tracing", "--spp", "16"]).expect("the defaults parse");
    let settings: PathSettings = run::settings(&options, &flags).expect("valid");
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let hidden = ProgressBar::hidden();
    let first = ch06_path_tracing::render(&scene, &camera, &settings, &hidden);
    println!(
        "ch06-path-tracing, {}: {} rays per path",
        settings,
        first.rays as f64 / first.paths as f64
    );
    let mut group = c.benchmark_group("render 800x600");
    group.throughput(Throughput::Elements(first.rays));
    group.sample_size(10);
    group.bench_function("ch06-path-tracing 16 spp", |b| {
        b.iter(|| ch06_path_tracing::render(&scene, &camera, &settings, &hidden))
    });
    group.finish();
}

fn chapters(c: &mut Criterion) {
    bench_chapter(c, &ch01_ray_cast::CHAPTER);
    bench_chapter(c, &ch02_shadows::CHAPTER);
    bench_chapter(c, &ch03_reflection::CHAPTER);
    bench_chapter(c, &ch04_refraction::CHAPTER);
    bench_chapter(c, &ch05_antialiasing::CHAPTER);
    bench_path_tracing(c);
}

/// Chapter 5 at 5 rays per pixel (the lab's) and at 64 (jittered), on a
/// 200 × 150 image so that 64 rays stay quick: the throughput in rays per
/// second must not fall as the count grows (nothing is allocated per ray,
/// and an offset costs a hash and a few multiplications).
/// `cargo bench -p raylab-bench -- spp` runs just these two, one after the other.
fn rays_per_pixel(c: &mut Criterion) {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let hidden = ProgressBar::hidden();
    let step = &ch05_antialiasing::CHAPTER.step;
    let mut group = c.benchmark_group("spp 200x150");
    group.sample_size(20);
    for (name, sampling) in [
        ("ch05 spp 5", Sampling::LAB_FIVE),
        ("ch05 spp 64", Sampling::new(64, None, 0).expect("valid")),
    ] {
        let settings = Settings {
            width: 200,
            height: 150,
            max_depth: 10,
            epsilon: 1e-4,
            sampling,
        };
        let rays = render(&scene, &camera, step, &settings, &hidden)
            .counts
            .total();
        group.throughput(Throughput::Elements(rays));
        group.bench_function(name, |b| {
            b.iter(|| render(&scene, &camera, step, &settings, &hidden))
        });
    }
    group.finish();
}

criterion_group!(benches, chapters, rays_per_pixel);
criterion_main!(benches);
