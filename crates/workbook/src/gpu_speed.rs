//! Chapter 10's frame times on this machine's GPU adapter, measured by the
//! main job: the lab scene as chapters 1–5 render it, each frame's three
//! parts apart (dispatch, readback, encoding), naming the adapter and the
//! processor. Without an adapter the table says so, and the job goes on.

use std::time::Duration;

use ch10_gpu::gpu::Gpu;
use ch10_gpu::like::Like;
use ch10_gpu::run::{Framed, render_image};
use ch10_gpu::shader::Source;
use raylab::frame::thousands;
use raylab::{Camera, Sampling, Scene, Settings};

use std::path::{Path, PathBuf};

use image::RgbImage;
use raylab_cli::output::{save_png, save_text};

use crate::speed::{ROUNDS, machine, median};
use crate::{JobError, Size};

/// One chapter's median frame on the GPU.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuTiming {
    pub like: &'static str,
    pub rays: u64,
    pub dispatch: Duration,
    pub readback: Duration,
    pub encoding: Duration,
}

impl GpuTiming {
    fn total(&self) -> Duration {
        self.dispatch + self.readback + self.encoding
    }
}

/// The settings of the chapter `like` imitates, with its defaults, at `size`.
fn chapter_settings(like: Like, size: Size) -> Result<Settings, String> {
    let raylab_like::Defaults { max_depth, spp, .. } = like.defaults();
    Ok(Settings {
        width: size.width,
        height: size.height,
        max_depth,
        epsilon: 1e-4,
        sampling: Sampling::new(spp, None, 0).map_err(|e| e.to_string())?,
    })
}

/// Chapter 10's frame of the lab scene as chapter 4 renders it, and the
/// CPU's image of the same at `size`: `(gpu, cpu)`, 8-bit sRGB. `Err` is
/// the one line that says why there is none (no adapter, a failed frame).
pub fn chapter4_frames(size: Size) -> Result<(String, RgbImage, RgbImage), String> {
    let gpu = Gpu::new().map_err(|e| e.to_string())?;
    let like = Like::Refraction;
    let settings = chapter_settings(like, size)?;
    let max_depth = settings.max_depth;
    let scene = (Scene::lab(), Camera::lab());
    let tracer = gpu
        .compile(&Source::built_in(), max_depth)
        .map_err(|e| e.to_string())?;
    let framed =
        render_image(&gpu, &tracer, like, &settings, &scene, false).map_err(|e| e.to_string())?;
    let cpu = raylab::render(
        &scene.0,
        &scene.1,
        &ch04_refraction::CHAPTER.step,
        &settings,
        raylab::Keep::IMAGE,
        &raylab::NoProgress,
    );
    Ok((gpu.adapter.clone(), framed.rendered.srgb, cpu.srgb))
}

/// Chapter 10's figures into `dir`: its frame (`render.png`) and how it
/// differs from the CPU's (`difference.png`), and `figure.md`, the lines
/// that show them, or, without an adapter, the line that says why not.
pub fn figures(dir: &Path, size: Size) -> Result<Vec<PathBuf>, JobError> {
    use raylab_plot::{changed_pixels, magnified_difference, max_change, with_change_scale};
    raylab_cli::prepare_out_dir(dir)?;
    let mut written = Vec::new();
    let text = match chapter4_frames(size) {
        Err(why) => format!(
            "*The main job found no GPU adapter on the machine that built this book ({why}), \
             so this page has no frame of chapter 10's.*\n"
        ),
        Ok((adapter, gpu, cpu)) => {
            let largest = max_change(&gpu, &cpu);
            let gain = 255.0 / f32::from(largest.max(1));
            let difference = with_change_scale(&magnified_difference(&cpu, &gpu, gain), gain);
            // A map of no difference is black: then the sentence says it.
            let images = if largest == 0 {
                vec![("render.png", &gpu)]
            } else {
                vec![("render.png", &gpu), ("difference.png", &difference)]
            };
            for (name, image) in images {
                let path = dir.join(name);
                save_png(image, &path)?;
                written.push(path);
            }
            let pixels = u64::from(gpu.width()) * u64::from(gpu.height());
            let changed = changed_pixels(&gpu, &cpu, 0) as u64;
            let over_3 = changed_pixels(&gpu, &cpu, 3) as u64;
            let against = if largest == 0 {
                format!(
                    "*Against chapter 4's image on the CPU, at the same size: not one of its {} \
                     pixels differs, on this adapter; the lab model's tolerance would allow \
                     0.5 % to differ by more than 3 levels.*\n",
                    thousands(pixels)
                )
            } else {
                format!(
                    "*Against chapter 4's image on the CPU: {} of its {} pixels differ at all, {} \
                     by more than 3 levels in some channel, at most by {largest}. The lab \
                     model's tolerance asks that 99.5 % agree within 3.*\n",
                    thousands(changed),
                    thousands(pixels),
                    thousands(over_3),
                )
            };
            let map = if largest == 0 {
                String::new()
            } else {
                format!(
                    "![How each pixel of chapter 10's frame differs from chapter 4's on the CPU, \
                     on a scale up to the largest difference, {largest} \
                     levels](figures/ch10-gpu/difference.png)\n\n"
                )
            };
            format!(
                "![Chapter 10's frame of the lab scene as chapter 4 renders it, {w} × {h}, on \
                 {adapter}](figures/ch10-gpu/render.png)\n\n\
                 *`cargo run --release -p ch10-gpu -- --like ch04-refraction --width {w} --height \
                 {h}`, on {adapter}, as the main job rendered it.*\n\n\
                 {map}{against}",
                w = gpu.width(),
                h = gpu.height(),
            )
        }
    };
    let path = dir.join("figure.md");
    save_text(&text, &path)?;
    written.push(path);
    Ok(written)
}

/// Each of chapters 1–5's looks at `size`, [`ROUNDS`] warm frames after a
/// first one that is not counted; the median of each part. `Err` is the
/// one line that says why there is no table (no adapter, a failed frame).
pub fn measure(size: Size) -> Result<(String, Vec<GpuTiming>), String> {
    let gpu = Gpu::new().map_err(|e| e.to_string())?;
    let scene = (Scene::lab(), Camera::lab());
    let mut timings = Vec::new();
    for like in Like::ALL {
        let settings = chapter_settings(like, size)?;
        let max_depth = settings.max_depth;
        let tracer = gpu
            .compile(&Source::built_in(), max_depth)
            .map_err(|e| e.to_string())?;
        let frame = || render_image(&gpu, &tracer, like, &settings, &scene, false);
        let first = frame().map_err(|e| e.to_string())?;
        let mut frames: Vec<Framed> = Vec::with_capacity(ROUNDS);
        for _ in 0..ROUNDS {
            frames.push(frame().map_err(|e| e.to_string())?);
        }
        let part = |f: fn(&Framed) -> Duration| median(frames.iter().map(f).collect());
        timings.push(GpuTiming {
            like: like.binary(),
            rays: first.rendered.counts.total(),
            dispatch: part(|f| f.dispatch),
            readback: part(|f| f.readback),
            encoding: part(|f| f.encoding),
        });
    }
    Ok((gpu.adapter.clone(), timings))
}

/// The table for chapter 10's page, or the line that says why there is none.
pub fn table(size: Size, measured: &Result<(String, Vec<GpuTiming>), String>) -> String {
    let (adapter, timings) = match measured {
        Ok(found) => found,
        Err(why) => {
            return format!(
                "No table: the machine that built this book has no GPU adapter chapter 10 \
                 could use ({why}).\n"
            );
        }
    };
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let mut text = String::from(
        "| like | rays | dispatch | readback | encoding | frame | Mrays/s |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
    );
    for t in timings {
        text.push_str(&format!(
            "| `{}` | {} | {:.1} ms | {:.1} ms | {:.1} ms | {:.1} ms | {:.1} |\n",
            t.like,
            thousands(t.rays),
            ms(t.dispatch),
            ms(t.readback),
            ms(t.encoding),
            ms(t.total()),
            t.rays as f64 / t.total().as_secs_f64().max(1e-9) / 1e6,
        ));
    }
    text.push_str(&format!(
        "\n`ch10-gpu --like …` on the lab scene at {} × {}, each chapter's defaults: the median \
         of {ROUNDS} warm frames in the main job's process. The adapter: {adapter}. The \
         processor: {}.\n",
        size.width,
        size.height,
        machine()
    ));
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_an_adapter_the_table_says_so_in_one_line() {
        let size = Size {
            width: 8,
            height: 6,
        };
        let text = table(size, &Err("no GPU adapter found".to_owned()));
        assert_eq!(text.lines().count(), 1, "{text}");
        assert!(text.contains("no GPU adapter found"), "{text}");
    }

    #[test]
    fn the_table_names_the_adapter_and_splits_each_frame_in_three() {
        let size = Size {
            width: 800,
            height: 600,
        };
        let timing = GpuTiming {
            like: "ch05-antialiasing",
            rays: 2_000_000,
            dispatch: Duration::from_millis(90),
            readback: Duration::from_millis(4),
            encoding: Duration::from_millis(6),
        };
        let text = table(size, &Ok(("a test adapter".to_owned(), vec![timing])));
        // 2 million rays in 100 ms: 20 Mrays/s.
        assert!(
            text.contains(
                "| `ch05-antialiasing` | 2,000,000 | 90.0 ms | 4.0 ms | 6.0 ms | 100.0 ms | 20.0 |"
            ),
            "{text}"
        );
        assert!(
            text.contains("a test adapter") && text.contains("800 × 600"),
            "{text}"
        );
    }
}
