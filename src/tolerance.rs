//! The lab model's tolerance: how closely two 8-bit images must agree for two
//! correct implementations of the lab.
//!
//! Float sums in another order, a fused multiply-add or a `powf` one ulp
//! off move a few pixels, so the bar is not bit equality: at least 99.5 %
//! of pixels within 3 of 255 in every channel, and a mean difference under
//! 0.5 of 255. The golden-image tests and the learner's `check` both judge
//! with this one copy.

use image::RgbImage;

/// The largest change, in 8-bit levels, that still counts as "within".
pub const WITHIN_LEVELS: u8 = 3;
/// The share of pixels that must be within [`WITHIN_LEVELS`].
pub const SHARE_WITHIN: f64 = 0.995;
/// The mean absolute difference, over every channel, must be below this.
pub const MEAN_BELOW: f64 = 0.5;

/// How closely two 8-bit images agree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Agreement {
    /// Share of pixels whose every channel is within 3 of 255.
    pub within_3: f64,
    /// Mean absolute difference over every channel of every pixel.
    pub mean: f64,
    /// The largest difference in any channel.
    pub max: u8,
    /// Pixels equal in every channel.
    pub identical: usize,
    /// The first pixel, in reading order, with the largest difference;
    /// `None` if the images are identical.
    pub worst: Option<WorstPixel>,
}

/// A pixel where two images differ, and both its values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WorstPixel {
    /// Its column, 0 at the left.
    pub x: u32,
    /// Its row, 0 at the top.
    pub y: u32,
    /// The value in the first image compared (the one being judged).
    pub ours: [u8; 3],
    /// The value in the second (the reference).
    pub reference: [u8; 3],
}

impl WorstPixel {
    /// The largest difference of its three channels.
    pub fn change(&self) -> u8 {
        (0..3)
            .map(|c| self.ours[c].abs_diff(self.reference[c]))
            .max()
            .unwrap_or(0)
    }
}

impl Agreement {
    /// The lab model's bar for two correct implementations.
    pub fn meets_lab_tolerance(&self) -> bool {
        self.within_3 >= SHARE_WITHIN && self.mean < MEAN_BELOW
    }
}

/// Compare `ours` with `reference`, two images of the same size.
///
/// # Panics
/// If their sizes differ: that is a failed comparison, not a measurement.
pub fn compare(ours: &RgbImage, reference: &RgbImage) -> Agreement {
    assert_eq!(
        ours.dimensions(),
        reference.dimensions(),
        "the images differ in size"
    );
    let (mut within, mut identical, mut sum) = (0usize, 0usize, 0u64);
    let mut worst: Option<WorstPixel> = None;
    for ((x, y, a), b) in ours.enumerate_pixels().zip(reference.pixels()) {
        let pixel = WorstPixel {
            x,
            y,
            ours: a.0,
            reference: b.0,
        };
        let change = pixel.change();
        within += usize::from(change <= WITHIN_LEVELS);
        identical += usize::from(change == 0);
        sum += (0..3)
            .map(|c| u64::from(a.0[c].abs_diff(b.0[c])))
            .sum::<u64>();
        if change > 0 && worst.is_none_or(|w| change > w.change()) {
            worst = Some(pixel);
        }
    }
    let pixels = f64::from(ours.width()) * f64::from(ours.height());
    Agreement {
        within_3: within as f64 / pixels,
        mean: sum as f64 / (3.0 * pixels),
        max: worst.map_or(0, |w| w.change()),
        identical,
        worst,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::Rgb;

    #[test]
    fn identical_images_agree_completely_with_no_worst_pixel() {
        let a = RgbImage::from_pixel(4, 4, Rgb([10, 20, 30]));
        let agreement = compare(&a, &a);
        assert_eq!(agreement.within_3, 1.0);
        assert_eq!(agreement.identical, 16);
        assert_eq!(agreement.max, 0);
        assert_eq!(agreement.worst, None);
        assert!(agreement.meets_lab_tolerance());
    }

    #[test]
    fn one_pixel_off_by_four_in_two_hundred_is_the_limit() {
        // 1 of 200 pixels off by more than 3 is exactly 99.5 % within 3.
        let a = RgbImage::from_pixel(20, 10, Rgb([100, 100, 100]));
        let mut b = a.clone();
        b.put_pixel(0, 0, Rgb([104, 100, 100]));
        let agreement = compare(&a, &b);
        assert_eq!(agreement.within_3, 0.995);
        assert!(agreement.meets_lab_tolerance());
        b.put_pixel(1, 0, Rgb([100, 96, 100]));
        assert!(!compare(&a, &b).meets_lab_tolerance());
    }

    #[test]
    fn a_mean_difference_of_half_a_level_fails() {
        let a = RgbImage::from_pixel(4, 4, Rgb([100, 100, 100]));
        let b = RgbImage::from_pixel(4, 4, Rgb([101, 100, 100]));
        let agreement = compare(&a, &b);
        assert!((agreement.mean - 1.0 / 3.0).abs() < 1e-12);
        assert!(agreement.meets_lab_tolerance());
        let c = RgbImage::from_pixel(4, 4, Rgb([101, 101, 100]));
        assert!(!compare(&a, &c).meets_lab_tolerance());
    }

    #[test]
    fn the_worst_pixel_is_the_first_of_the_largest_change_with_both_values() {
        let reference = RgbImage::from_pixel(20, 10, Rgb([100, 100, 100]));
        let mut ours = reference.clone();
        ours.put_pixel(3, 2, Rgb([100, 90, 100]));
        ours.put_pixel(7, 5, Rgb([130, 100, 100]));
        ours.put_pixel(9, 9, Rgb([70, 100, 100]));
        let agreement = compare(&ours, &reference);
        assert_eq!(
            agreement.worst,
            Some(WorstPixel {
                x: 7,
                y: 5,
                ours: [130, 100, 100],
                reference: [100, 100, 100]
            })
        );
        assert_eq!(agreement.max, 30);
        // 3 of 200 pixels off by more than 3: 98.5 %, below the bar.
        assert_eq!(agreement.within_3, 0.985);
        assert!(!agreement.meets_lab_tolerance());
    }
}
