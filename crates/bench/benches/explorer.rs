//! The explorer's frame path, as the window runs it while the camera
//! moves: the orbit turns a step, the frame renders at one ray (or one
//! path) per pixel with the fast floor, and the overlay is drawn on it.
//! Chapters 1–5 (chapter 7's waves) and path tracing (chapter 8's paths),
//! at 640 × 480 and 800 × 600 on the lab scene, in rounds that take every
//! mode in turn, since the machine's speed drifts.
//!
//! `cargo bench -p raylab-bench --bench explorer`

use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use raylab_explore::{Explorer, Input, Key, Loaded};

/// The sizes the issue asks for: the explorer's window and the chapters'.
const SIZES: [(u32, u32); 2] = [(640, 480), (800, 600)];

/// An explorer of the lab scene at `width` × `height`, on chapter `n`'s
/// look (6: path tracing), at one ray per pixel while moving.
fn explorer(width: u32, height: u32, chapter: char) -> Explorer {
    let mut explorer = Explorer::new(Loaded::lab(), width, height);
    explorer.handle(Input::Key(Key::Char(chapter)));
    explorer
}

/// One frame while the camera moves: turn, render, draw the overlay. The
/// turns go left and right in turn, so the camera stays near the lab's.
fn moving_frame(explorer: &mut Explorer, left: &mut bool) {
    *left = !*left;
    let key = if *left { Key::Left } else { Key::Right };
    explorer.handle(Input::Key(key));
    assert!(explorer.frame());
    std::hint::black_box(explorer.compose());
}

fn explorer_frames(c: &mut Criterion) {
    for round in 1..=2 {
        let mut group = c.benchmark_group(format!("explorer round {round}"));
        group.sample_size(10);
        group.warm_up_time(Duration::from_millis(500));
        group.measurement_time(Duration::from_secs(2));
        for (width, height) in SIZES {
            for chapter in '1'..='6' {
                let mut explorer = explorer(width, height, chapter);
                let name = format!("{width}x{height} {}", explorer.knobs.binary());
                let mut left = false;
                group.bench_function(name, |b| b.iter(|| moving_frame(&mut explorer, &mut left)));
            }
        }
        group.finish();
    }
}

criterion_group!(benches, explorer_frames);
criterion_main!(benches);
