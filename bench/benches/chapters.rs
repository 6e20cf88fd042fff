//! Every chapter's default render at 800 × 600, timed by criterion, with
//! its throughput in rays (shadow rays included): criterion prints it as
//! "Melem/s", that is, millions of rays per second.
//!
//! `cargo bench -p raylab-bench`

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use raylab::indicatif::ProgressBar;
use raylab::{Camera, Scene, Step, render};
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

fn chapters(c: &mut Criterion) {
    bench_chapter(c, &ch01_ray_cast::CHAPTER);
    bench_chapter(c, &ch02_shadows::CHAPTER);
    bench_chapter(c, &ch03_reflection::CHAPTER);
    bench_chapter(c, &ch04_refraction::CHAPTER);
    bench_chapter(c, &ch05_antialiasing::CHAPTER);
}

criterion_group!(benches, chapters);
criterion_main!(benches);
