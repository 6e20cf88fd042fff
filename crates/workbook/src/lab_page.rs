//! What the book's page "The lab in your browser" (`lab-in-browser.md`)
//! needs beside it: chapter 10's shader as the file is, the same shader
//! with the lab's three tasks blanked as `learn start shader` blanks them,
//! the scenes packed as chapter 10 packs them for its GPU, and the
//! chapters' CPU renders that the page's renders and `check shader`'s
//! pictures are judged against.
//!
//! It is all one generated script, `lab-data.js`, and not files the page
//! fetches: a book opened from disk (`file://`) may not `fetch()` its own
//! files in Chromium, while a `<script src>` loads from disk and from a
//! server alike. The renders go in as the PNG files' bytes (base64), which
//! the page decodes itself: an image read from disk into a canvas is
//! "tainted" there, and its pixels cannot be read back to compare.

use std::path::{Path, PathBuf};

use ch10_gpu::like::{Like, feature_bits};
use ch10_gpu::scene_buffer::{self, Inputs};
use ch10_gpu::shader;
use image::RgbImage;
use raylab::{Camera, Keep, NoProgress, Pattern, Sampling, Scene, Settings, Step};
use raylab_cli::output::{save_png, save_text};
use raylab_cli::{Chapter, CliError, Options};
use serde_json::{Value, json};

use crate::JobError;

/// The page's data script, in its folder of figures.
pub const SCRIPT: &str = "lab-data.js";

/// The size the page renders at first and compares with the CPU: chapter
/// 10's tests compare the shader with chapters 1–5 at this size too.
pub const COMPARE: (u32, u32) = (320, 240);

/// The rays per pixel the page offers: the pixel centre, the lab's five,
/// and grids (the shader takes one set of points for every pixel, so no
/// pattern drawn per pixel).
pub const SPP_CHOICES: [u32; 5] = [1, 4, 5, 9, 16];

/// The scene `check shader`'s last picture is judged on.
const UNDER_WATER: &str = "total-internal-reflection.toml";

/// Write the page's data and the CPU renders it shows into `dir`
/// (`book/src/figures/lab-in-browser/`); `scenes` is the folder of scene
/// files. Returns the files written.
pub fn make_lab_page(dir: &Path, scenes: &Path) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let mut written = Vec::new();

    // Chapters 1–5's own renders at the page's size, as PNG files the
    // page shows (with or without WebGPU) and carries as bytes to compare.
    let mut chapters = Vec::new();
    for like in Like::ALL {
        let image = chapter_render(like, COMPARE)?;
        let name = format!("{}.png", like.binary());
        let path = dir.join(&name);
        save_png(&image, &path)?;
        let raylab_like::Defaults { max_depth, spp, .. } = like.defaults();
        chapters.push(json!({
            "number": like as u32 + 1,
            "binary": like.binary(),
            "features": feature_bits(like.features()),
            "maxDepth": max_depth,
            "spp": spp,
            "figure": name,
            "png": base64(&read(&path)?),
        }));
        written.push(path);
    }

    // `check shader`'s pictures: each stage's chapter, at the check's
    // size, on its scene, the very images `learn` compares with.
    let under_water = scenes.join(UNDER_WATER);
    let mut stages = Vec::new();
    for (i, stage) in learn::shader::STAGES.iter().enumerate() {
        let scene = stage.scene.map(|_| under_water.as_path());
        let image = learn_check::picture::reference_image_in(stage.chapter, scene)
            .map_err(|e| JobError::Book(format!("the lab page's reference {i}: {e}")))?;
        let path = dir.join(format!("check-{}.png", i + 1));
        save_png(&image, &path)?;
        let like = Like::ALL[usize::from(stage.chapter) - 1];
        let raylab_like::Defaults { max_depth, spp, .. } = like.defaults();
        stages.push(json!({
            "chapter": stage.chapter,
            "package": stage.package,
            "label": stage.label(),
            "shows": stage.shows,
            "region": stage.region,
            "task": stage.task,
            "scene": if stage.scene.is_some() { "underWater" } else { "lab" },
            "features": feature_bits(like.features()),
            "maxDepth": max_depth,
            "spp": spp,
            "png": base64(&read(&path)?),
        }));
        written.push(path);
    }

    let lab = (Scene::lab(), Camera::lab());
    let water = raylab_cli::scene_file::load(&under_water)
        .map_err(|e| JobError::Book(format!("the lab page's scene: {e}")))?;
    let data = page_data(&lab, &water, chapters, stages)?;
    let script = format!(
        "// Made by the main job (crates/workbook/src/lab_page.rs) for \
         lab-in-browser.md: do not edit.\nwindow.RAYLAB_LAB = {data};\n"
    );
    let path = dir.join(SCRIPT);
    save_text(&script, &path)?;
    written.push(path);
    Ok(written)
}

/// Everything the page's script reads, as one JSON object.
fn page_data(
    lab: &(Scene, Camera),
    water: &(Scene, Camera),
    chapters: Vec<Value>,
    stages: Vec<Value>,
) -> Result<Value, JobError> {
    let blanked = learn::shader::blank_shader(shader::BUILT_IN)
        .map_err(|e| JobError::Book(format!("tracer.wgsl's todo regions: {e}")))?;
    let samples: serde_json::Map<String, Value> = SPP_CHOICES
        .iter()
        .map(|&spp| Ok((spp.to_string(), json!(base64(&packed(lab, spp)?.samples)))))
        .collect::<Result<_, JobError>>()?;
    let scene = |scene: &(Scene, Camera)| -> Result<Value, JobError> {
        let inputs = packed(scene, 1)?;
        Ok(json!({
            "params": base64(&inputs.params),
            "spheres": base64(&inputs.spheres),
        }))
    };
    use scene_buffer as b;
    Ok(json!({
        "shader": shader::BUILT_IN,
        "shaderName": shader::BUILT_IN_NAME,
        "blank": blanked.exercise,
        "stackSizeLine": shader::STACK_SIZE_LINE,
        "tile": ch10_gpu::gpu::TILE,
        "params": {
            "size": b::PARAMS_SIZE,
            "width": b::WIDTH_AT,
            "height": b::HEIGHT_AT,
            "epsilon": b::EPSILON_AT,
            "maxDepth": b::MAX_DEPTH_AT,
            "spp": b::SPP_AT,
            "features": b::FEATURES_AT,
            "firstRow": b::FIRST_ROW_AT,
            "bandRows": b::BAND_ROWS_AT,
        },
        "progressSize": b::PROGRESS_SIZE,
        "pendingSize": b::PENDING_SIZE,
        "scenes": { "lab": scene(lab)?, "underWater": scene(water)? },
        "samples": samples,
        "compare": { "width": COMPARE.0, "height": COMPARE.1 },
        "check": { "width": learn::limits::WIDTH, "height": learn::limits::HEIGHT },
        "tolerance": {
            "withinLevels": raylab::tolerance::WITHIN_LEVELS,
            "shareWithin": raylab::tolerance::SHARE_WITHIN,
            "meanBelow": raylab::tolerance::MEAN_BELOW,
        },
        "differenceGain": learn_check::compare::GAIN,
        "srgbThresholds": srgb_thresholds(),
        "chapters": chapters,
        "stages": stages,
    }))
}

/// A scene packed as chapter 10 packs it, at the check's size, one ray
/// per pixel unless `spp` says otherwise, chapter 5's features: the page
/// sets the size, depth, ε, rays and features where the bytes keep them.
fn packed((scene, camera): &(Scene, Camera), spp: u32) -> Result<Inputs, JobError> {
    let pattern = (spp != 1 && spp != 5).then_some(Pattern::Grid);
    let settings = Settings {
        width: learn::limits::WIDTH,
        height: learn::limits::HEIGHT,
        max_depth: 10,
        epsilon: 1e-4,
        sampling: Sampling::new(spp, pattern, 0).map_err(|e| JobError::Book(e.to_string()))?,
    };
    scene_buffer::pack(scene, camera, &settings, Like::AntiAliasing.features())
        .map_err(|e| JobError::Book(e.to_string()))
}

/// Chapter `like`'s own render of the lab scene on the CPU at `size`,
/// with its defaults, as `cargo run -p chNN-… -- --width W --height H`.
fn chapter_render(like: Like, size: (u32, u32)) -> Result<RgbImage, JobError> {
    match like {
        Like::RayCast => render(&ch01_ray_cast::CHAPTER, size),
        Like::Shadows => render(&ch02_shadows::CHAPTER, size),
        Like::Reflection => render(&ch03_reflection::CHAPTER, size),
        Like::Refraction => render(&ch04_refraction::CHAPTER, size),
        Like::AntiAliasing => render(&ch05_antialiasing::CHAPTER, size),
    }
}

fn render<S: Step>(
    chapter: &Chapter<S>,
    (width, height): (u32, u32),
) -> Result<RgbImage, JobError> {
    let args = [
        chapter.binary.to_owned(),
        format!("--width={width}"),
        format!("--height={height}"),
    ];
    let options = Options::parse_for(chapter, args).map_err(|e| CliError::Usage(e.to_string()))?;
    let settings = options.settings()?;
    let rendered = raylab::render(
        &Scene::lab(),
        &Camera::lab(),
        &chapter.step,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    );
    Ok(rendered.srgb)
}

fn read(path: &Path) -> Result<Vec<u8>, JobError> {
    std::fs::read(path).map_err(|e| JobError::Book(format!("{}: {e}", path.display())))
}

/// The core's sRGB encoding as 255 numbers: `thresholds[v - 1]` is the
/// smallest linear `f32` that [`raylab::srgb::encode_channel`] takes to
/// level `v` or above. The encoding only goes up with its input, so the
/// page finds a channel's byte by counting the thresholds at or below it,
/// and gets the core's byte for every `f32` without computing a power
/// (JavaScript's `Math.pow` works in doubles, Rust's `powf` in `f32`).
pub fn srgb_thresholds() -> Vec<f32> {
    use raylab::srgb::encode_channel;
    (1..=255u8)
        .map(|level| {
            // Positive floats are ordered as their bit patterns: halve the
            // bits of [0, 1] until the first that reaches `level`.
            let (mut low, mut high) = (0u32, 1.0f32.to_bits());
            while low < high {
                let mid = low + (high - low) / 2;
                if encode_channel(f32::from_bits(mid)) >= level {
                    high = mid;
                } else {
                    low = mid + 1;
                }
            }
            f32::from_bits(low)
        })
        .collect()
}

/// Standard base64 (RFC 4648, with padding): how bytes travel in the
/// script; the browser's `atob` reads it back.
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut text = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let word = chunk
            .iter()
            .enumerate()
            .fold(0u32, |w, (i, &b)| w | u32::from(b) << (16 - 8 * i));
        for k in 0..4 {
            if k <= chunk.len() {
                text.push(char::from(ALPHABET[(word >> (18 - 6 * k) & 63) as usize]));
            } else {
                text.push('=');
            }
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_of_the_rfc_s_examples() {
        // RFC 4648, section 10.
        let cases = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ];
        for (plain, encoded) in cases {
            assert_eq!(base64(plain.as_bytes()), encoded, "{plain}");
        }
        assert_eq!(base64(&[0xff, 0xfe]), "//4=");
    }

    #[test]
    fn the_srgb_thresholds_give_the_core_s_byte_on_either_side_of_each() {
        use raylab::srgb::encode_channel;
        let thresholds = srgb_thresholds();
        assert_eq!(thresholds.len(), 255);
        for (i, &t) in thresholds.iter().enumerate() {
            let level = i as u8 + 1;
            assert_eq!(encode_channel(t), level, "at {t}");
            let below = f32::from_bits(t.to_bits() - 1);
            assert_eq!(encode_channel(below), level - 1, "below {t}");
        }
        // Level 1 starts half a level up the linear segment: 0.5 / 255 / 12.92.
        assert!((thresholds[0] - 0.5 / 255.0 / 12.92).abs() < 1e-9);
        assert_eq!(encode_channel(1.0), 255);
    }
}
