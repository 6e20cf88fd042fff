//! Every chapter's default render at 800 × 600, timed by criterion, with
//! its throughput in rays (shadow rays included): criterion prints it as
//! "Melem/s", that is, millions of rays per second.
//!
//! `cargo bench -p raylab-bench`

use ch07_eight_rays::Like;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use raylab::indicatif::ProgressBar;
use raylab::{Camera, Scene, Step};
use raylab_cli::{Chapter, Options};

/// Each chapter's program renders with its step's `render_image`: the
/// scalar `raylab::render` for chapters 1-5, waves of eight for chapter 7.
fn bench_chapter<S: Step>(c: &mut Criterion, chapter: &Chapter<S>) {
    let settings = Options::defaults(chapter)
        .settings()
        .expect("the defaults are valid");
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let hidden = ProgressBar::hidden();
    // One render first, to know how many rays a render traces.
    let render = || {
        chapter
            .step
            .render_image(&scene, &camera, &settings, &hidden)
    };
    let rays = render().counts.total();
    let mut group = c.benchmark_group("render 800x600");
    group.throughput(Throughput::Elements(rays));
    group.sample_size(20);
    group.bench_function(chapter.binary, |b| b.iter(render));
    group.finish();
}

fn chapters(c: &mut Criterion) {
    bench_chapter(c, &ch01_ray_cast::CHAPTER);
    bench_chapter(c, &ch02_shadows::CHAPTER);
    bench_chapter(c, &ch03_reflection::CHAPTER);
    bench_chapter(c, &ch04_refraction::CHAPTER);
    bench_chapter(c, &ch05_antialiasing::CHAPTER);
    // Chapter 7 at chapter 5's settings (its default), then as chapter 4.
    bench_chapter(c, &ch07_eight_rays::chapter(Like::AntiAliasing));
    bench_chapter(c, &ch07_like_ch04());
}

/// Chapter 7 tracing as chapter 4 does, under its own name in the report.
fn ch07_like_ch04() -> Chapter<ch07_eight_rays::EightRays> {
    Chapter {
        binary: "ch07-eight-rays --like ch04-refraction",
        ..ch07_eight_rays::chapter(Like::Refraction)
    }
}

/// Chapter 5 and chapter 7 in turn, several rounds: the machine's speed
/// drifts from minute to minute, and interleaving shows the two under the
/// same conditions. `cargo bench -p raylab-bench -- interleaved`
fn interleaved(c: &mut Criterion) {
    let seven = ch07_eight_rays::chapter(Like::AntiAliasing);
    for round in 1..=3 {
        let mut group = c.benchmark_group(format!("interleaved round {round}"));
        group.sample_size(10);
        bench_in(&mut group, &ch05_antialiasing::CHAPTER);
        bench_in(&mut group, &seven);
        group.finish();
    }
}

fn bench_in<S: Step>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    chapter: &Chapter<S>,
) {
    let settings = Options::defaults(chapter)
        .settings()
        .expect("the defaults are valid");
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let hidden = ProgressBar::hidden();
    let render = || {
        chapter
            .step
            .render_image(&scene, &camera, &settings, &hidden)
    };
    group.throughput(Throughput::Elements(render().counts.total()));
    group.bench_function(chapter.binary, |b| b.iter(render));
}

criterion_group!(benches, chapters, interleaved);
criterion_main!(benches);
