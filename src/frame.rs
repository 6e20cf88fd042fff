//! What a render is asked for and what it gives back: the settings, the
//! finished image with its tallies, and what a render keeps besides its
//! 8-bit image. Every renderer shares these, the scalar one of
//! [`render`](fn@crate::render) and the faster ones beside it.

use std::fmt;
use std::time::Duration;

use image::RgbImage;

use crate::linear_image::LinearImage;
use crate::ray::RayKind;
use crate::sampling::Sampling;
use crate::trace::{RAY_BUDGET, RayCounts};

/// How to render: the image size, the limits of the ray tree and the samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// The deepest ray traced; 1 traces only the primary rays.
    pub max_depth: u32,
    /// How far secondary and shadow rays start from their surface.
    pub epsilon: f32,
    /// How many rays per pixel, where, and the seed of their random choices.
    pub sampling: Sampling,
}

/// A rendered image, with what the renderer did to make it.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// What the render was asked for.
    pub settings: Settings,
    /// The image as `render.png` stores it: the lab model's 8-bit sRGB, encoded
    /// by the workers as they finish each row.
    pub srgb: RgbImage,
    /// The image in linear light, when the render was asked to keep it.
    pub linear: Option<LinearImage>,
    /// The depth and ray-count maps, when the render was asked to keep them.
    pub maps: Option<PixelMaps>,
    /// The rays traced for the whole image, by kind.
    pub counts: RayCounts,
    /// How long the render took, encoding included.
    pub elapsed: Duration,
    /// Pixels whose colour came out NaN or infinite and were set to black.
    /// Always 0 for a correct step; reported rather than hidden.
    pub non_finite: usize,
    /// Samples whose ray tree reached [`RAY_BUDGET`] and was cut short.
    pub over_budget: u64,
}

/// What a row of the image adds to the totals, besides its pixels (rows
/// are summed with `+`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RowTally {
    /// The rays traced for the row, by kind.
    pub counts: RayCounts,
    /// Pixels that came out NaN or infinite.
    pub non_finite: usize,
    /// Samples whose tree reached the ray budget.
    pub over_budget: u64,
}

impl std::ops::Add for RowTally {
    type Output = RowTally;
    fn add(self, other: RowTally) -> RowTally {
        RowTally {
            counts: self.counts + other.counts,
            non_finite: self.non_finite + other.non_finite,
            over_budget: self.over_budget + other.over_budget,
        }
    }
}

/// What a render keeps besides its 8-bit image, which it always makes.
///
/// Each is bookkeeping a program may not need: a program that only writes
/// `render.png` keeps neither, and one that draws no diagrams
/// (`--no-diagrams`) no maps. The image is the same either way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Keep {
    /// The image in linear light ([`Rendered::linear`]), for arithmetic on
    /// it: differences, averages, tests. At 800 × 600 it is 7.7 MB, which
    /// the kernel hands out and clears page by page as it is first written.
    pub linear: bool,
    /// The per-pixel depth and ray-count maps the heat maps draw.
    pub maps: bool,
}

impl Keep {
    /// The 8-bit image only: all that writing `render.png` needs.
    pub const IMAGE: Keep = Keep {
        linear: false,
        maps: false,
    };
    /// The image in linear light too.
    pub const LINEAR: Keep = Keep {
        linear: true,
        maps: false,
    };
    /// Everything: the linear image and the maps.
    pub const ALL: Keep = Keep {
        linear: true,
        maps: true,
    };
}

/// Per pixel, what its ray trees cost: the heat maps' numbers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PixelMaps {
    /// Per pixel: the depth of the deepest ray of its trees.
    pub deepest: Vec<u8>,
    /// Per pixel: every ray traced for it, shadow rays included.
    pub rays: Vec<u32>,
}

impl Rendered {
    /// The image in linear light.
    ///
    /// # Panics
    /// If the render was not asked to keep it ([`Keep::linear`]).
    pub fn linear_image(&self) -> &LinearImage {
        self.linear
            .as_ref()
            .expect("a render asked to keep its linear image (Keep::linear)")
    }

    /// Millions of rays traced per second of wall time.
    pub fn mrays_per_second(&self) -> f64 {
        self.counts.total() as f64 / self.elapsed.as_secs_f64().max(1e-9) / 1e6
    }
}

/// "800×600, 1 spp, max depth 10": what a render was asked for.
impl fmt::Display for Settings {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}×{}, {}, max depth {}",
            self.width, self.height, self.sampling, self.max_depth
        )
    }
}

/// The one-line summary: resolution, rays by kind, time and speed.
impl fmt::Display for Rendered {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} rays (",
            self.settings,
            thousands(self.counts.total())
        )?;
        for (n, kind) in RayKind::ALL.into_iter().enumerate() {
            let sep = if n == 0 { "" } else { ", " };
            write!(
                f,
                "{sep}{} {}",
                thousands(self.counts.get(kind)),
                kind.name()
            )?;
        }
        write!(
            f,
            ") in {:.1} ms, {:.1} Mrays/s",
            self.elapsed.as_secs_f64() * 1e3,
            self.mrays_per_second()
        )?;
        if self.over_budget > 0 {
            write!(
                f,
                "; WARNING: {} samples reached the budget of {RAY_BUDGET} rays and were cut short \
                 (is --epsilon 0?)",
                thousands(self.over_budget)
            )?;
        }
        if self.non_finite > 0 {
            write!(
                f,
                "; WARNING: {} pixels were NaN or infinite",
                self.non_finite
            )?;
        }
        Ok(())
    }
}

/// `1234567` as `1,234,567`.
pub fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thousands_are_grouped_by_three() {
        assert_eq!(thousands(0), "0");
        assert_eq!(thousands(999), "999");
        assert_eq!(thousands(1000), "1,000");
        assert_eq!(thousands(12_345_678), "12,345,678");
    }
}
