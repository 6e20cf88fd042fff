//! `--measure`: the frame time while the camera moves, chapter by chapter,
//! without a window: what a learner's drag costs.

use std::time::{Duration, Instant};

use crate::input::{Input, Key};
use crate::source::Loaded;
use crate::state::Explorer;

/// One chapter's frames while moving.
#[derive(Clone, Debug)]
pub struct Measured {
    pub chapter: u32,
    pub binary: &'static str,
    /// Render only (what `Stats::frame` times).
    pub render: Duration,
    /// Render and compose (overlay, drawing into the frame).
    pub frame: Duration,
    pub mrays: f64,
}

fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times.get(times.len() / 2).copied().unwrap_or_default()
}

/// Chapters 1–6 at one ray (or path) per pixel, the camera turning every
/// frame; `frames` timed after two to warm up.
pub fn measure(load: impl Fn() -> Loaded, width: u32, height: u32, frames: u32) -> Vec<Measured> {
    (1..=6)
        .map(|chapter| {
            let mut explorer = Explorer::new(load(), width, height);
            explorer.handle(Input::Key(Key::Char(
                char::from_digit(chapter, 10).unwrap_or('5'),
            )));
            explorer.knobs.spp = 1;
            let (mut render, mut frame, mut mrays) = (Vec::new(), Vec::new(), Vec::new());
            for i in 0..frames + 2 {
                explorer.handle(Input::Key(Key::Right));
                let start = Instant::now();
                explorer.frame();
                let composed = explorer.compose();
                let whole = start.elapsed();
                std::hint::black_box(composed);
                if i >= 2 {
                    render.push(explorer.stats().frame);
                    frame.push(whole);
                    mrays.push(explorer.stats().mrays_per_second());
                }
            }
            mrays.sort_by(f64::total_cmp);
            Measured {
                chapter,
                binary: explorer.knobs.binary(),
                render: median(render),
                frame: median(frame),
                mrays: mrays.get(mrays.len() / 2).copied().unwrap_or(0.0),
            }
        })
        .collect()
}

/// The measurements as a table.
pub fn table(width: u32, height: u32, rows: &[Measured]) -> String {
    let mut text = format!(
        "{width}×{height}, one ray (path) per pixel, camera turning every frame, medians:\n\
         chapter  program             render ms  frame ms   fps   Mrays/s\n"
    );
    for r in rows {
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        text.push_str(&format!(
            "{:>7}  {:<18} {:>9.1} {:>9.1} {:>5.0} {:>9.0}\n",
            r.chapter,
            r.binary,
            ms(r.render),
            ms(r.frame),
            1.0 / r.frame.as_secs_f64().max(1e-9),
            r.mrays
        ));
    }
    text
}
