//! The book's concept diagrams: one picture per formula, drawn from the
//! code's own numbers (the lab camera, the lab scene's materials and sun,
//! the optics and the sRGB curve of `raylab`), so that a figure cannot
//! drift from what the programs do.
//!
//! Each diagram is laid out on a [`Sheet`] in the pixels of the image it
//! becomes, at most 1,200 wide: the book's text column is 750 pixels, so a
//! figure is shown at 0.6 to 0.75 of its size, and its smallest type, 20
//! pixels, reads as 12.5 or more. The line plots (sRGB, weights) use
//! `raylab-plot`'s plots.

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

/// The widest a diagram is drawn, in pixels.
pub const WIDEST: u32 = 1200;
/// The width of the book's text column (mdBook's `--content-max-width`):
/// a wider figure is shown scaled down to it.
pub const COLUMN: f32 = 750.0;

/// How tall type of `size` pixels is shown in the text column, on a figure
/// `width` pixels wide.
pub fn shown(size: f32, width: u32) -> f32 {
    size * (COLUMN / width as f32).min(1.0)
}

/// Title size, in pixels.
pub const TITLE: f32 = 28.0;
/// Labels on arrows and points.
pub const LABEL: f32 = 22.0;
/// Notes and numbers of secondary importance: the smallest type a figure
/// uses, shown 12.5 pixels tall on a figure 1,200 pixels wide.
pub const SMALL: f32 = 20.0;
/// From one line of [`SMALL`] text to the next.
pub const LINE: f32 = 26.0;

/// A figure under construction, in pixels (origin top left, y down).
pub struct Sheet {
    canvas: Canvas,
    width: f32,
    height: f32,
}

/// A point in pixels.
pub type P = (f32, f32);

impl Sheet {
    /// A white sheet `width` × `height` pixels with a title.
    pub fn new(width: f32, height: f32, title: &str) -> Sheet {
        let canvas = Canvas::new(width.round() as u32, height.round() as u32, WHITE);
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
        self.canvas.text(at.0, at.1, text, size, colour, anchor);
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
        self.fill_rect((left - 4.0, top - 1.0), (width + 8.0, height + 2.0), WHITE);
        self.text(at, text, size, colour, anchor);
    }

    /// A muted note along the bottom edge, `line` lines up from it.
    pub fn note(&mut self, line: usize, text: &str) {
        let y = self.height - 14.0 - LINE * line as f32;
        self.text(
            (self.width / 2.0, y),
            text,
            SMALL,
            TEXT_MUTED,
            Anchor::BASELINE_CENTRE,
        );
    }

    pub fn text_width(&self, text: &str, size: f32) -> f32 {
        self.canvas.text_width(text, size)
    }

    pub fn line(&mut self, a: P, b: P, colour: Rgb, width: f32) {
        self.canvas.stroke_line(a.0, a.1, b.0, b.1, colour, width);
    }

    pub fn dashed(&mut self, a: P, b: P, colour: Rgb, width: f32) {
        self.canvas.dashed_line(a, b, colour, width, 5.0, 4.0);
    }

    pub fn arrow(&mut self, a: P, b: P, colour: Rgb, width: f32) {
        let head = 7.0 + 2.5 * width;
        self.canvas.arrow(a, b, colour, width, head);
    }

    pub fn polyline(&mut self, points: &[P], colour: Rgb, width: f32) {
        self.canvas.polyline(points, colour, width);
    }

    pub fn circle(&mut self, centre: P, radius: f32, fill: Option<Rgb>, stroke: Option<Rgb>) {
        self.canvas
            .circle(centre, radius, fill, stroke.map(|c| (c, 2.0)));
    }

    pub fn dot(&mut self, centre: P, colour: Rgb) {
        self.circle(centre, 4.0, Some(colour), None);
    }

    pub fn fill_rect(&mut self, at: P, size: P, colour: Rgb) {
        self.canvas.fill_rect(at.0, at.1, size.0, size.1, colour);
    }

    pub fn stroke_rect(&mut self, at: P, size: P, colour: Rgb, width: f32) {
        self.canvas
            .stroke_rect(at.0, at.1, size.0, size.1, colour, width);
    }

    /// A legend of coloured swatches, one line each, from `at` (top left).
    pub fn legend(&mut self, at: P, entries: &[(Rgb, &str)]) {
        for (n, (colour, text)) in entries.iter().enumerate() {
            let y = at.1 + 28.0 * n as f32;
            self.fill_rect((at.0, y + 4.0), (24.0, 5.0), *colour);
            self.text(
                (at.0 + 32.0, y + 6.5),
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn type_of_20_pixels_on_a_1200_pixel_figure_is_shown_12_5_pixels_tall() {
        // 20 · 750 / 1200 = 12.5; a figure narrower than the column is
        // shown at its own size.
        assert!((shown(20.0, 1200) - 12.5).abs() < 1e-6);
        assert_eq!(shown(20.0, 600), 20.0);
    }

    #[test]
    fn every_diagram_fits_1200_pixels_and_its_smallest_type_reads_12_pixels_tall() {
        let figures = [
            ("camera", camera::figure()),
            ("sphere-roots", sphere::figure()),
            ("reflection", optics::reflection_figure()),
            ("snell", optics::snell_figure()),
            ("lambert", lambert::figure()),
            ("shadow-offset", offset::figure()),
        ];
        for (name, image) in figures {
            assert!(image.width() <= WIDEST, "{name}: {}", image.width());
            let small = shown(SMALL, image.width());
            assert!(small >= 12.0, "{name}: small type shown {small} px tall");
        }
    }
}
