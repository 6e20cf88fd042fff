//! The learner's render against the reference, as LAB.md's tolerance
//! judges two implementations, and as OpenImageIO's `idiff` reports it.

use image::{Rgb, RgbImage};

/// How closely the learner's image agrees with the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Share of pixels whose every channel is within 3 of 255.
    pub within_3: f64,
    /// Mean absolute difference over every channel of every pixel.
    pub mean: f64,
    /// The pixel that differs most, (x, y), and both its values.
    pub worst: Option<WorstPixel>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WorstPixel {
    pub x: u32,
    pub y: u32,
    pub learner: [u8; 3],
    pub reference: [u8; 3],
}

impl WorstPixel {
    /// The largest difference of its three channels.
    pub fn change(&self) -> u8 {
        (0..3)
            .map(|c| self.learner[c].abs_diff(self.reference[c]))
            .max()
            .unwrap_or(0)
    }
}

impl Comparison {
    /// LAB.md's bar: at least 99.5 % of pixels within 3 of 255 in every
    /// channel, and a mean difference under 0.5 of 255.
    pub fn passes(&self) -> bool {
        self.within_3 >= 0.995 && self.mean < 0.5
    }
}

/// Compare two images of the same size.
///
/// # Panics
/// If their sizes differ: the check renders both at one size.
pub fn compare(learner: &RgbImage, reference: &RgbImage) -> Comparison {
    assert_eq!(learner.dimensions(), reference.dimensions());
    let (mut within_3, mut sum) = (0u64, 0u64);
    let mut worst: Option<WorstPixel> = None;
    for ((x, y, a), b) in learner.enumerate_pixels().zip(reference.pixels()) {
        let pixel = WorstPixel {
            x,
            y,
            learner: a.0,
            reference: b.0,
        };
        let change = pixel.change();
        within_3 += u64::from(change <= 3);
        sum += (0..3)
            .map(|c| u64::from(a.0[c].abs_diff(b.0[c])))
            .sum::<u64>();
        // The first pixel of the largest change, in reading order.
        if change > 0 && worst.is_none_or(|w| change > w.change()) {
            worst = Some(pixel);
        }
    }
    let pixels = f64::from(learner.width()) * f64::from(learner.height());
    Comparison {
        within_3: within_3 as f64 / pixels,
        mean: sum as f64 / (3.0 * pixels),
        worst,
    }
}

/// How much the signed difference image magnifies: a difference of 16
/// levels (about 6 %) already shows at full strength.
pub const GAIN: f32 = 16.0;

/// A picture of `learner − reference`: black where they agree, red where
/// the learner's pixel is brighter, blue where it is darker, magnified by
/// [`GAIN`]. The sign tells a missing light (blue: a shadow too many, a
/// reflection missing) from an extra one (red).
pub fn signed_difference(learner: &RgbImage, reference: &RgbImage) -> RgbImage {
    assert_eq!(learner.dimensions(), reference.dimensions());
    RgbImage::from_fn(learner.width(), learner.height(), |x, y| {
        let (a, b) = (learner.get_pixel(x, y).0, reference.get_pixel(x, y).0);
        // The mean signed change of the three channels, so that a colour
        // shift counts as much as a brightness one.
        let signed: f32 = (0..3)
            .map(|c| f32::from(a[c]) - f32::from(b[c]))
            .sum::<f32>()
            / 3.0;
        let strength = (signed.abs() / 255.0 * GAIN).min(1.0);
        // Even a one-level change shows, dimly, against pure black.
        let level = if a == b {
            0
        } else {
            (40.0 + 215.0 * strength) as u8
        };
        if signed >= 0.0 && a != b {
            Rgb([level, level / 5, 0])
        } else {
            Rgb([0, level / 3, level])
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_images_pass_with_no_worst_pixel() {
        let a = RgbImage::from_pixel(4, 4, Rgb([10, 20, 30]));
        let c = compare(&a, &a);
        assert!(c.passes());
        assert_eq!(c.worst, None);
        assert_eq!(c.within_3, 1.0);
    }

    #[test]
    fn the_worst_pixel_is_named_with_both_values() {
        let reference = RgbImage::from_pixel(20, 10, Rgb([100, 100, 100]));
        let mut learner = reference.clone();
        learner.put_pixel(3, 2, Rgb([100, 90, 100]));
        learner.put_pixel(7, 5, Rgb([130, 100, 100]));
        let c = compare(&learner, &reference);
        assert_eq!(
            c.worst,
            Some(WorstPixel {
                x: 7,
                y: 5,
                learner: [130, 100, 100],
                reference: [100, 100, 100]
            })
        );
        // 2 of 200 pixels off by more than 3: 99 %, below the bar.
        assert_eq!(c.within_3, 0.99);
        assert!(!c.passes());
    }

    #[test]
    fn one_pixel_in_two_hundred_off_is_within_the_tolerance() {
        let reference = RgbImage::from_pixel(20, 10, Rgb([100, 100, 100]));
        let mut learner = reference.clone();
        learner.put_pixel(0, 0, Rgb([104, 100, 100]));
        assert!(compare(&learner, &reference).passes());
    }

    #[test]
    fn a_mean_difference_of_half_a_level_fails() {
        let reference = RgbImage::from_pixel(4, 4, Rgb([100, 100, 100]));
        let learner = RgbImage::from_pixel(4, 4, Rgb([101, 101, 100]));
        assert!(!compare(&learner, &reference).passes());
    }

    #[test]
    fn a_brighter_pixel_is_red_and_a_darker_one_blue_in_the_difference() {
        let reference = RgbImage::from_pixel(3, 1, Rgb([100, 100, 100]));
        let mut learner = reference.clone();
        learner.put_pixel(0, 0, Rgb([200, 200, 200]));
        learner.put_pixel(2, 0, Rgb([0, 0, 0]));
        let diff = signed_difference(&learner, &reference);
        assert_eq!(diff.get_pixel(0, 0).0, [255, 51, 0]);
        assert_eq!(diff.get_pixel(1, 0).0, [0, 0, 0]);
        assert_eq!(diff.get_pixel(2, 0).0, [0, 85, 255]);
    }
}
