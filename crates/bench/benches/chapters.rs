//! Every chapter's default render at 800 × 600, timed by criterion, with
//! its throughput in rays (shadow rays included): criterion prints it as
//! "Melem/s", that is, millions of rays per second.
//!
//! Chapters 6 and 8, the path tracers, are timed the same way at 800 × 600
//! with 16 paths per pixel (the default 256 would take seconds per
//! iteration): their throughput is in rays too (every segment and shadow
//! ray), and chapter 6 prints its rays per path once, so that paths/s =
//! Mrays/s ÷ that number.
//!
//! Two groups interleave chapters, several rounds of each pair, since the
//! machine's speed drifts: chapter 5 against chapter 7 (`-- interleaved`),
//! and chapter 5 against chapters 6 and 8 (`-- "path tracer"`), which
//! prints the path tracers' Mrays/s as a share of chapter 5's and their
//! M paths/s.
//!
//! `cargo bench -p raylab-bench`

use ch07_eight_rays::Like;
use std::cell::Cell;
use std::time::{Duration, Instant};

use criterion::{Criterion, SamplingMode, Throughput, criterion_group, criterion_main};
use raylab::{Camera, Keep, NoProgress, Sampling, Scene, Settings, Step, render};
use raylab_cli::{Chapter, Options};

/// Each chapter's program renders with its own renderer (`Chapter::render`):
/// the scalar `raylab::render` for chapters 1-5, waves of eight for chapter 7.
fn bench_chapter<S: Step>(c: &mut Criterion, chapter: &Chapter<S>) {
    let mut group = c.benchmark_group("render 800x600");
    group.sample_size(20);
    bench_in(&mut group, chapter);
    group.finish();
}

/// Chapter 6's settings at 16 paths per pixel.
fn path_settings() -> ch06_path_tracing::PathSettings {
    use ch06_path_tracing::run;
    let program = &ch06_path_tracing::PROGRAM.program;
    let (options, flags) =
        run::parse(program, ["ch06-path-tracing", "--spp", "16"]).expect("the defaults parse");
    run::settings(&options, &flags).expect("valid")
}

fn bench_path_tracing(c: &mut Criterion) {
    let settings = path_settings();
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let first = ch06_path_tracing::render_paths(&scene, &camera, &settings, &NoProgress);
    println!(
        "ch06-path-tracing, {}: {} rays per path",
        settings,
        first.rays as f64 / first.paths as f64
    );
    let mut group = c.benchmark_group("render 800x600");
    group.throughput(Throughput::Elements(first.rays));
    group.sample_size(10);
    for program in [ch06_path_tracing::PROGRAM, ch08_eight_paths::PROGRAM] {
        let name = format!("{} 16 spp", program.program.binary);
        group.bench_function(name, |b| {
            b.iter(|| (program.render)(&scene, &camera, &settings, &NoProgress))
        });
    }
    group.finish();
}

fn chapters(c: &mut Criterion) {
    bench_chapter(c, &ch01_ray_cast::CHAPTER);
    bench_chapter(c, &ch02_shadows::CHAPTER);
    bench_chapter(c, &ch03_reflection::CHAPTER);
    bench_chapter(c, &ch04_refraction::CHAPTER);
    bench_chapter(c, &ch05_antialiasing::CHAPTER);
    bench_path_tracing(c);
    // Chapter 7 at chapter 5's settings (its default), then as chapter 4.
    bench_chapter(c, &ch07_eight_rays::chapter(Like::AntiAliasing));
    bench_chapter(c, &ch07_like_ch04());
}

/// Chapter 7 tracing as chapter 4 does, under its own name in the report.
fn ch07_like_ch04() -> Chapter<ch07_eight_rays::EightRays> {
    ch07_like(Like::Refraction, "ch07-eight-rays --like ch04-refraction")
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

/// Chapter 5 (its default, the lab's five rays per pixel) and the path
/// tracers (16 paths per pixel, lab materials), one path at a time
/// (chapter 6) and eight at a time (chapter 8), in turn, several rounds, at
/// 800 × 600. The two trace different rays, so what is compared is the
/// cost of one: after each round it prints both chapters' Mrays/s (every
/// segment and shadow ray counted), chapter 6's as a share of chapter 5's,
/// and its paths per second. `cargo bench -p raylab-bench -- "path tracer"`
fn interleaved_path_tracer(c: &mut Criterion) {
    let six = path_settings();
    let five = Options::defaults(&ch05_antialiasing::CHAPTER)
        .settings()
        .expect("the defaults are valid");
    let chapter_five = &ch05_antialiasing::CHAPTER;
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let render_five = || {
        let step = &chapter_five.step;
        (chapter_five.render)(&scene, &camera, step, &five, Keep::IMAGE, &NoProgress)
    };
    let render_scalar = || ch06_path_tracing::render_paths(&scene, &camera, &six, &NoProgress);
    let render_eight = || ch08_eight_paths::render_eight(&scene, &camera, &six, &NoProgress);
    let rays_five = render_five().counts.total();
    let first = render_scalar();
    let (rays_six, paths_six) = (first.rays, first.paths);
    assert_eq!(
        render_eight().rays,
        rays_six,
        "the two tracers trace the same rays"
    );
    for round in 1..=3 {
        let tallies = [Tally::default(), Tally::default(), Tally::default()];
        let [tally_five, tally_scalar, tally_eight] = &tallies;
        let mut group = c.benchmark_group(format!("path tracer round {round}"));
        // One iteration of chapter 6 takes about a second: the same number
        // of them in every sample, not criterion's 1, 2, … 10.
        group.sampling_mode(SamplingMode::Flat);
        group.sample_size(10);
        group.warm_up_time(Duration::from_secs(1));
        group.throughput(Throughput::Elements(rays_five));
        group.bench_function("ch05-antialiasing", |b| tally_five.time(b, render_five));
        group.throughput(Throughput::Elements(rays_six));
        group.bench_function("ch06-path-tracing 16 spp", |b| {
            tally_scalar.time(b, render_scalar)
        });
        group.bench_function("ch08-eight-paths 16 spp", |b| {
            tally_eight.time(b, render_eight)
        });
        group.finish();
        // A filter (`cargo bench -- interleaved`) left the round out.
        if tallies.iter().any(|tally| tally.renders.get() == 0) {
            continue;
        }
        let mrays_five = tally_five.per_second(rays_five) / 1e6;
        for (name, tally) in [("ch06", tally_scalar), ("ch08", tally_eight)] {
            let mrays_six = tally.per_second(rays_six) / 1e6;
            println!(
                "path tracer round {round}: ch05 {mrays_five:.1} Mrays/s; {name} \
                 {mrays_six:.1} Mrays/s ({:.2} × ch05's), {:.2} M paths/s, {:.2} rays per path",
                mrays_six / mrays_five,
                tally.per_second(paths_six) / 1e6,
                rays_six as f64 / paths_six as f64
            );
        }
        println!(
            "path tracer round {round}: chapter 8 {:.2} × chapter 6's paths/s",
            tally_eight.per_second(paths_six) / tally_scalar.per_second(paths_six)
        );
    }
}

/// The renders criterion timed in one benchmark and the time they took,
/// warm-up included, to print a rate that criterion has no place for.
#[derive(Default)]
struct Tally {
    renders: Cell<u64>,
    elapsed: Cell<Duration>,
}

impl Tally {
    fn time<T>(&self, b: &mut criterion::Bencher<'_>, mut render: impl FnMut() -> T) {
        b.iter_custom(|iterations| {
            let start = Instant::now();
            for _ in 0..iterations {
                std::hint::black_box(render());
            }
            let elapsed = start.elapsed();
            self.renders.set(self.renders.get() + iterations);
            self.elapsed.set(self.elapsed.get() + elapsed);
            elapsed
        });
    }

    /// `per_render` things (rays, paths) per second.
    fn per_second(&self, per_render: u64) -> f64 {
        (self.renders.get() * per_render) as f64 / self.elapsed.get().as_secs_f64().max(1e-9)
    }
}

/// The table: each of chapters 1-5 beside chapter 7 tracing as it
/// (`--like`), in turn, then chapter 5's settings at `--max-depth 1` (the
/// primary and shadow rays alone) for both tracers: the full-depth rows
/// less these are the secondary rays' share.
/// `cargo bench -p raylab-bench -- "by chapter"`
fn by_chapter(c: &mut Criterion) {
    let mut group = c.benchmark_group("by chapter");
    group.sample_size(10);
    bench_in(&mut group, &ch01_ray_cast::CHAPTER);
    bench_in(&mut group, &ch07_like(Like::RayCast, "ch07 --like ch01"));
    bench_in(&mut group, &ch02_shadows::CHAPTER);
    bench_in(&mut group, &ch07_like(Like::Shadows, "ch07 --like ch02"));
    bench_in(&mut group, &ch03_reflection::CHAPTER);
    bench_in(&mut group, &ch07_like(Like::Reflection, "ch07 --like ch03"));
    bench_in(&mut group, &ch04_refraction::CHAPTER);
    bench_in(&mut group, &ch07_like(Like::Refraction, "ch07 --like ch04"));
    bench_in(&mut group, &ch05_antialiasing::CHAPTER);
    bench_in(
        &mut group,
        &ch07_like(Like::AntiAliasing, "ch07 --like ch05"),
    );
    let ch05 = Chapter {
        binary: "ch05 --max-depth 1",
        max_depth: 1,
        ..ch05_antialiasing::CHAPTER
    };
    bench_in(&mut group, &ch05);
    let ch07 = Chapter {
        max_depth: 1,
        ..ch07_like(Like::AntiAliasing, "ch07 --max-depth 1")
    };
    bench_in(&mut group, &ch07);
    group.finish();
}

/// Chapter 7 tracing as `like` does, under `binary` in the report.
fn ch07_like(like: Like, binary: &'static str) -> Chapter<ch07_eight_rays::EightRays> {
    Chapter {
        binary,
        ..ch07_eight_rays::chapter(like)
    }
}

/// Add `chapter`'s default render to `group`, with its throughput in rays
/// (one render first, to know how many rays a render traces).
fn bench_in<S: Step>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    chapter: &Chapter<S>,
) {
    let settings = Options::defaults(chapter)
        .settings()
        .expect("the defaults are valid");
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let render = || {
        let step = &chapter.step;
        (chapter.render)(&scene, &camera, step, &settings, Keep::IMAGE, &NoProgress)
    };
    group.throughput(Throughput::Elements(render().counts.total()));
    group.bench_function(chapter.binary, |b| b.iter(render));
}

/// Chapter 5 at 5 rays per pixel (the lab's) and at 64 (jittered), on a
/// 200 × 150 image so that 64 rays stay quick: the throughput in rays per
/// second must not fall as the count grows (nothing is allocated per ray,
/// and an offset costs a hash and a few multiplications).
/// `cargo bench -p raylab-bench -- spp` runs just these two, one after the other.
fn rays_per_pixel(c: &mut Criterion) {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let hidden = NoProgress;
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
        let rays = render(&scene, &camera, step, &settings, Keep::IMAGE, &hidden)
            .counts
            .total();
        group.throughput(Throughput::Elements(rays));
        group.bench_function(name, |b| {
            b.iter(|| render(&scene, &camera, step, &settings, Keep::IMAGE, &hidden))
        });
    }
    group.finish();
}

/// Chapter 9: rays per second against the number of spheres, every
/// sphere tested against the tree, one ray at a time and eight: chapter 5
/// (the list), chapter 7 (the list, in waves), chapter 9 (the tree) and
/// chapter 7 `--objects tree` (the tree, in waves), in two rounds over every
/// N, on seeded fields of spheres at chapter 5's settings, 400 × 300, the
/// tree's build included. Testing every one of 5,000 or 10,000 spheres
/// takes seconds a render, so the list is timed there at 100 × 75, the same
/// view with a sixteenth of the rays: its rays per second hardly depend on
/// the image size. Then the tree's build over 1,000 and 10,000 spheres (one
/// core: the build is sequential) and its bytes per sphere, and the lab
/// scene through chapter 9 against chapter 5.
/// `cargo bench -p raylab-bench -- "many spheres"`
fn many_spheres(c: &mut Criterion) {
    use ch07_eight_rays::Objects;
    use ch09_many_spheres::Bvh;
    use ch09_many_spheres::field::field_scene;
    let step = Like::AntiAliasing;
    // The programs' renderers through the tree: each builds it first.
    let through_tree = ch09_many_spheres::chapter(step).render;
    let waves_through_tree = ch07_eight_rays::chapter_through(step, Objects::Tree).render;
    // Chapter 5's settings (depth 10, the lab's five rays) at this size.
    let chapter5_settings = |width: u32, height: u32| Settings {
        width,
        height,
        max_depth: 10,
        epsilon: 1e-4,
        sampling: Sampling::new(5, None, 0)
            .expect("5 rays per pixel")
            .with_lab_five(step.lab_five()),
    };
    let eight = ch07_eight_rays::EightRays {
        like: Like::AntiAliasing,
    };
    // Two rounds over every N, so that each pair is timed twice, minutes
    // apart: the machine's drift shows as the rounds' difference.
    for (round, n) in (1..=2).flat_map(|r| [5, 50, 500, 5_000, 10_000].map(|n| (r, n))) {
        let (scene, camera) = field_scene(n);
        let mut group = c.benchmark_group(format!("many spheres {n} round {round}"));
        group.sampling_mode(SamplingMode::Flat);
        group.sample_size(10);
        group.warm_up_time(Duration::from_millis(500));
        let big = chapter5_settings(400, 300);
        let list_settings = if n > 1_000 {
            chapter5_settings(100, 75)
        } else {
            big
        };
        let variants: [(&str, Settings, bool, bool); 4] = [
            ("ch05 list", list_settings, false, false),
            ("ch07 list", list_settings, false, true),
            ("ch09 tree", big, true, false),
            ("ch07 --objects tree", big, true, true),
        ];
        for (name, settings, tree, lanes) in variants {
            let draw = || match (tree, lanes) {
                (false, false) => {
                    render(&scene, &camera, &step, &settings, Keep::IMAGE, &NoProgress)
                }
                (true, false) => {
                    through_tree(&scene, &camera, &step, &settings, Keep::IMAGE, &NoProgress)
                }
                (false, true) => ch07_eight_rays::render::render_waves(
                    &scene,
                    &camera,
                    &eight,
                    &settings,
                    Keep::IMAGE,
                    &NoProgress,
                ),
                (true, true) => {
                    waves_through_tree(&scene, &camera, &eight, &settings, Keep::IMAGE, &NoProgress)
                }
            };
            group.throughput(Throughput::Elements(draw().counts.total()));
            group.bench_function(
                format!("{name} {}x{}", settings.width, settings.height),
                |b| b.iter(draw),
            );
        }
        group.finish();
    }
    for n in [1_000, 10_000] {
        let (scene, _) = field_scene(n);
        let tree = Bvh::build(&scene);
        eprintln!(
            "many spheres: the tree over {n} spheres: {} nodes, depth {}, {:.1} bytes per sphere",
            tree.nodes().len(),
            tree.depth(),
            tree.bytes() as f64 / n as f64
        );
        let mut group = c.benchmark_group("many spheres build");
        group.sample_size(20);
        group.bench_function(format!("build {n}"), |b| b.iter(|| Bvh::build(&scene)));
        group.finish();
    }
    let nine = ch09_many_spheres::chapter(Like::AntiAliasing);
    for round in 1..=3 {
        let mut group = c.benchmark_group(format!("many spheres lab round {round}"));
        group.sample_size(10);
        bench_in(&mut group, &ch05_antialiasing::CHAPTER);
        bench_in(&mut group, &nine);
        group.finish();
    }
}

criterion_group!(
    benches,
    chapters,
    rays_per_pixel,
    interleaved,
    interleaved_path_tracer,
    by_chapter,
    many_spheres
);
criterion_main!(benches);
