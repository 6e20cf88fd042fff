//! The book's concept diagrams: one picture per formula, drawn from the
//! code's own numbers (the lab camera, the lab scene's materials and sun,
//! the optics and the sRGB curve of `raylab`), so that a figure cannot
//! drift from what the programs do.
//!
//! Each diagram is laid out on a [`Sheet`] in logical pixels and rendered
//! at twice that size, so lines and text stay crisp on high-density
//! screens; the line plots (sRGB, weights) use `raylab-plot`'s plots.

pub mod camera;
pub mod lambert;
pub mod offset;
pub mod optics;
pub mod sphere;
pub mod srgb;
pub mod weights;

use std::path::{Path, PathBuf};

use image::RgbImage;
use raylab_cli::output::save_png;
use raylab_plot::colour::{TEXT, TEXT_MUTED, WHITE};
use raylab_plot::{Anchor, Canvas, Rgb};

use crate::JobError;

/// Device pixels per logical pixel.
pub const SCALE: f32 = 2.0;
/// Title size, in logical pixels.
pub const TITLE: f32 = 20.0;
/// Labels on arrows and points.
pub const LABEL: f32 = 14.0;
/// Notes and numbers of secondary importance.
pub const SMALL: f32 = 12.5;

/// A figure under construction, in logical pixels (origin top left, y
/// down), drawn at [`SCALE`] times its size.
pub struct Sheet {
    canvas: Canvas,
    width: f32,
    height: f32,
}

/// A point in logical pixels.
pub type P = (f32, f32);

fn s(p: P) -> P {
    (p.0 * SCALE, p.1 * SCALE)
}

impl Sheet {
    /// A white sheet `width` × `height` logical pixels with a title.
    pub fn new(width: f32, height: f32, title: &str) -> Sheet {
        let canvas = Canvas::new(
            (width * SCALE).round() as u32,
            (height * SCALE).round() as u32,
            WHITE,
        );
        let mut sheet = Sheet {
            canvas,
            width,
            height,
        };
        sheet.text((width / 2.0, 14.0), title, TITLE, TEXT, Anchor::TOP_CENTRE);
        sheet
    }

    pub fn width(&self) -> f32 {
        self.width
    }

    pub fn height(&self) -> f32 {
        self.height
    }

    pub fn text(&mut self, at: P, text: &str, size: f32, colour: Rgb, anchor: Anchor) {
        let at = s(at);
        self.canvas
            .text(at.0, at.1, text, size * SCALE, colour, anchor);
    }

    /// Text on a white patch, for labels that sit over lines.
    pub fn label(&mut self, at: P, text: &str, size: f32, colour: Rgb, anchor: Anchor) {
        let width = self.text_width(text, size);
        let height = size * 1.3;
        let left = match anchor.h {
            raylab_plot::HAlign::Left => at.0,
            raylab_plot::HAlign::Centre => at.0 - width / 2.0,
            raylab_plot::HAlign::Right => at.0 - width,
        };
        let top = match anchor.v {
            raylab_plot::VAlign::Top => at.1,
            raylab_plot::VAlign::Middle => at.1 - height / 2.0,
            raylab_plot::VAlign::Baseline => at.1 - size,
            raylab_plot::VAlign::Bottom => at.1 - height,
        };
        self.fill_rect((left - 3.0, top - 1.0), (width + 6.0, height + 2.0), WHITE);
        self.text(at, text, size, colour, anchor);
    }

    /// A muted note along the bottom edge, `line` lines up from it.
    pub fn note(&mut self, line: usize, text: &str) {
        let y = self.height - 12.0 - 17.0 * line as f32;
        self.text(
            (self.width / 2.0, y),
            text,
            SMALL,
            TEXT_MUTED,
            Anchor::BASELINE_CENTRE,
        );
    }

    pub fn text_width(&self, text: &str, size: f32) -> f32 {
        self.canvas.text_width(text, size * SCALE) / SCALE
    }

    pub fn line(&mut self, a: P, b: P, colour: Rgb, width: f32) {
        let (a, b) = (s(a), s(b));
        self.canvas
            .stroke_line(a.0, a.1, b.0, b.1, colour, width * SCALE);
    }

    pub fn dashed(&mut self, a: P, b: P, colour: Rgb, width: f32) {
        self.canvas
            .dashed_line(s(a), s(b), colour, width * SCALE, 5.0 * SCALE, 4.0 * SCALE);
    }

    pub fn arrow(&mut self, a: P, b: P, colour: Rgb, width: f32) {
        let head = 7.0 + 2.5 * width;
        self.canvas
            .arrow(s(a), s(b), colour, width * SCALE, head * SCALE);
    }

    pub fn polyline(&mut self, points: &[P], colour: Rgb, width: f32) {
        let points: Vec<P> = points.iter().map(|&p| s(p)).collect();
        self.canvas.polyline(&points, colour, width * SCALE);
    }

    pub fn circle(&mut self, centre: P, radius: f32, fill: Option<Rgb>, stroke: Option<Rgb>) {
        self.canvas.circle(
            s(centre),
            radius * SCALE,
            fill,
            stroke.map(|c| (c, 2.0 * SCALE)),
        );
    }

    pub fn dot(&mut self, centre: P, colour: Rgb) {
        self.circle(centre, 4.0, Some(colour), None);
    }

    pub fn fill_rect(&mut self, at: P, size: P, colour: Rgb) {
        let (at, size) = (s(at), s(size));
        self.canvas.fill_rect(at.0, at.1, size.0, size.1, colour);
    }

    pub fn stroke_rect(&mut self, at: P, size: P, colour: Rgb, width: f32) {
        let (at, size) = (s(at), s(size));
        self.canvas
            .stroke_rect(at.0, at.1, size.0, size.1, colour, width * SCALE);
    }

    /// A legend of coloured swatches, one line each, from `at` (top left).
    pub fn legend(&mut self, at: P, entries: &[(Rgb, &str)]) {
        for (n, (colour, text)) in entries.iter().enumerate() {
            let y = at.1 + 20.0 * n as f32;
            self.fill_rect((at.0, y + 3.0), (18.0, 4.0), *colour);
            self.text(
                (at.0 + 24.0, y + 5.0),
                text,
                SMALL,
                TEXT,
                Anchor::MIDDLE_LEFT,
            );
        }
    }

    pub fn finish(self) -> RgbImage {
        self.canvas.to_rgb_image()
    }
}

/// Adds two points.
pub fn add(a: P, b: P) -> P {
    (a.0 + b.0, a.1 + b.1)
}

/// `a + k·b`.
pub fn along(a: P, b: P, k: f32) -> P {
    (a.0 + k * b.0, a.1 + k * b.1)
}

/// An angle in degrees, as the figures print it.
pub fn degrees(radians: f32) -> String {
    format!("{:.1}°", radians.to_degrees())
}

/// The concept figures' files, in the order [`make_concepts`] writes them.
pub const NAMES: [&str; 8] = [
    "camera.png",
    "sphere-roots.png",
    "reflection.png",
    "snell.png",
    "lambert.png",
    "shadow-offset.png",
    "srgb.png",
    "weights.png",
];

/// Write every concept diagram into `dir`; the weights figure marks the
/// depths at which the depth sweeps under `figures` settled, and its line
/// for the book goes into `weights.md`.
pub fn make_concepts(dir: &Path, figures: &Path) -> Result<Vec<PathBuf>, JobError> {
    let settled = weights::measured(figures)?;
    raylab_cli::prepare_out_dir(dir)?;
    let images = [
        camera::figure(),
        sphere::figure(),
        optics::reflection_figure(),
        optics::snell_figure(),
        lambert::figure(),
        offset::figure(),
        srgb::figure(),
        weights::figure(&settled),
    ];
    let mut written = Vec::new();
    for (name, image) in NAMES.iter().zip(&images) {
        let path = dir.join(name);
        save_png(image, &path)?;
        written.push(path);
    }
    let caption = dir.join("weights.md");
    raylab_cli::output::save_text(&weights::caption(&settled), &caption)?;
    written.push(caption);
    Ok(written)
}
