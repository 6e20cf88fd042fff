//! One render: the scene packed for the shader, a frame on the GPU, the
//! image encoded by the core's sRGB encoder and written as every chapter
//! writes it.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use raylab::linear_image::LinearImage;
use raylab::trace::RayCounts;
use raylab::{Camera, PixelMaps, RayKind, Rendered, Scene, Settings, Vec3};
use raylab_cli::diagrams::heatmaps;
use raylab_cli::output::save_png;
use raylab_cli::{CliError, CommonFlags, prepare_out_dir};

use crate::BINARY;
use crate::gpu::{Gpu, GpuError, Pipeline};
use crate::like::Like;
use crate::scene_buffer::{self, PackError};
use crate::shader::ShaderError;

/// Why chapter 10 could not render; each is one line.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    #[error(transparent)]
    Cli(#[from] CliError),
    #[error(transparent)]
    Shader(#[from] ShaderError),
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error(transparent)]
    Pack(#[from] PackError),
    #[error("{0}")]
    Usage(String),
}

/// What one render made, and how long each part took.
pub struct Report {
    pub rendered: Rendered,
    pub dispatch: Duration,
    pub readback: Duration,
    pub encoding: Duration,
    pub out_dir: PathBuf,
    /// Every file written, `render.png` first.
    pub written: Vec<PathBuf>,
}

/// The scene to render: the lab's, or a scene file's.
pub fn load_scene(options: &CommonFlags) -> Result<(Scene, Camera), CliError> {
    options.load_scene()
}

/// The folder the chapter writes into.
pub fn out_dir(options: &CommonFlags) -> PathBuf {
    options.out_dir(BINARY)
}

/// An image from the GPU, and how long each part of the frame took.
pub struct Framed {
    pub rendered: Rendered,
    pub dispatch: Duration,
    pub readback: Duration,
    pub encoding: Duration,
}

/// Render `scene` with the compiled tracer as the chapter `like` would,
/// and encode it: the image and its maps, nothing written.
pub fn render_image(
    gpu: &Gpu,
    tracer: &Pipeline,
    like: Like,
    settings: &Settings,
    (scene, camera): &(Scene, Camera),
    keep_maps: bool,
) -> Result<Framed, Error> {
    let inputs = scene_buffer::pack(scene, camera, settings, like.features())?;
    let frame = gpu.render(tracer, &inputs)?;

    // ANCHOR: encode
    // The core's encoder, as every chapter's: clamp, sRGB, 8 bits. A pixel
    // that came back NaN or infinite is set black and counted, as the
    // core's render does.
    let start = Instant::now();
    let mut non_finite = 0;
    let pixels = frame
        .pixels
        .iter()
        .map(|&[r, g, b]| {
            let colour = Vec3::new(r, g, b);
            if colour.is_finite() {
                colour
            } else {
                non_finite += 1;
                Vec3::ZERO
            }
        })
        .collect();
    let srgb = LinearImage::from_pixels(settings.width, settings.height, pixels).to_srgb8();
    let encoding = start.elapsed();
    // ANCHOR_END: encode

    let maps = keep_maps.then(|| PixelMaps {
        deepest: frame.maps.iter().map(|m| m[0].min(255) as u8).collect(),
        rays: frame.maps.iter().map(|m| m[1]).collect(),
    });
    let rendered = Rendered {
        settings: *settings,
        srgb,
        linear: None,
        maps,
        counts: {
            let mut counts = RayCounts::default();
            for (kind, n) in RayKind::ALL.into_iter().zip(frame.counts) {
                counts.add(kind, n);
            }
            counts
        },
        elapsed: frame.dispatch + frame.readback + encoding,
        non_finite,
        over_budget: frame.over_budget,
    };
    Ok(Framed {
        rendered,
        dispatch: frame.dispatch,
        readback: frame.readback,
        encoding,
    })
}

/// Render the scene with the compiled tracer and write `render.png` (and,
/// unless `--no-diagrams`, the heat maps of depth and rays).
pub fn render(
    gpu: &Gpu,
    tracer: &Pipeline,
    like: Like,
    options: &CommonFlags,
    scene: &(Scene, Camera),
) -> Result<Report, Error> {
    let settings = options.settings()?;
    // Checked before anything is written: a bad request writes nothing.
    scene_buffer::pack(&scene.0, &scene.1, &settings, like.features())?;
    let out_dir = out_dir(options);
    prepare_out_dir(&out_dir)?;
    let framed = render_image(gpu, tracer, like, &settings, scene, !options.no_diagrams)?;
    let rendered = framed.rendered;

    let render_png = out_dir.join("render.png");
    save_png(&rendered.srgb, &render_png).map_err(CliError::from)?;
    let mut written = vec![render_png];
    if let Some(maps) = &rendered.maps {
        let figures = [
            ("depth.png", heatmaps::depth_figure(BINARY, &rendered, maps)),
            ("rays.png", heatmaps::rays_figure(BINARY, &rendered, maps)),
        ];
        for (name, figure) in figures {
            let path = out_dir.join(name);
            save_png(&figure, &path).map_err(CliError::from)?;
            written.push(path);
        }
    }
    Ok(Report {
        rendered,
        dispatch: framed.dispatch,
        readback: framed.readback,
        encoding: framed.encoding,
        out_dir,
        written,
    })
}

/// The summary line, the times of the frame's parts, and the files.
pub fn report_text(report: &Report, tracer: &Pipeline, gpu: &Gpu) -> String {
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let names: Vec<String> = report
        .written
        .iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    format!(
        "{BINARY}: {} (dispatch {:.1} ms, readback {:.1} ms, encoding {:.1} ms)\n  \
         {} compiled in {:.0} ms for {}\n  wrote {} in {}\n",
        report.rendered,
        ms(report.dispatch),
        ms(report.readback),
        ms(report.encoding),
        tracer.name,
        ms(tracer.compile_time),
        gpu.adapter,
        names.join(", "),
        report.out_dir.display()
    )
}
