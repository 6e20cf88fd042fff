//! Comparing two renders of the same scene: a picture of where they
//! differ, and counts of how much.
//!
//! A pixel's change is the largest of its three channel differences, so a
//! pixel that changed in only one channel still counts in full.

use image::RgbImage;

use super::colormap::magma;
use super::colour::BLACK;

/// An image of where `a` and `b` differ: each pixel's change (0..=255)
/// times `gain`, shown through magma so that small changes glow dim purple
/// and large ones bright yellow. Pixels that did not change at all are
/// pure black, so even a one-level change stands out from "no change".
///
/// `gain` magnifies faint differences: with a gain of 10, a change of 26
/// levels (about 10%) already reaches the top of the colormap.
///
/// # Panics
///
/// If the images differ in size; pixels could not be paired up.
pub fn magnified_difference(a: &RgbImage, b: &RgbImage, gain: f32) -> RgbImage {
    assert_same_size(a, b);
    RgbImage::from_fn(a.width(), a.height(), |x, y| {
        let change = pixel_change(a.get_pixel(x, y).0, b.get_pixel(x, y).0);
        let colour = if change == 0 {
            BLACK
        } else {
            magma(f32::from(change) / 255.0 * gain)
        };
        image::Rgb(colour)
    })
}

/// How many pixels changed by more than `threshold` levels (0..=255) in
/// their most-changed channel. A threshold of 0 counts every change.
///
/// # Panics
///
/// If the images differ in size.
pub fn changed_pixels(a: &RgbImage, b: &RgbImage, threshold: u8) -> usize {
    changes(a, b).filter(|&change| change > threshold).count()
}

/// The largest change of any pixel (0 for identical images).
///
/// # Panics
///
/// If the images differ in size.
pub fn max_change(a: &RgbImage, b: &RgbImage) -> u8 {
    changes(a, b).max().unwrap_or(0)
}

/// Every pixel's change, in reading order.
fn changes<'a>(a: &'a RgbImage, b: &'a RgbImage) -> impl Iterator<Item = u8> + 'a {
    assert_same_size(a, b);
    a.pixels()
        .zip(b.pixels())
        .map(|(pa, pb)| pixel_change(pa.0, pb.0))
}

/// The largest absolute difference between matching channels.
fn pixel_change(a: [u8; 3], b: [u8; 3]) -> u8 {
    (0..3).map(|i| a[i].abs_diff(b[i])).max().unwrap_or(0)
}

fn assert_same_size(a: &RgbImage, b: &RgbImage) {
    assert_eq!(
        a.dimensions(),
        b.dimensions(),
        "can only compare images of the same size"
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gradient() -> RgbImage {
        RgbImage::from_fn(16, 8, |x, y| {
            image::Rgb([(x * 16) as u8, (y * 30) as u8, 77])
        })
    }

    #[test]
    fn identical_images_give_black_and_no_changes() {
        let a = gradient();
        let diff = magnified_difference(&a, &a.clone(), 8.0);
        assert_eq!(diff.dimensions(), a.dimensions());
        assert!(diff.pixels().all(|p| p.0 == BLACK));
        assert_eq!(changed_pixels(&a, &a, 0), 0);
        assert_eq!(max_change(&a, &a), 0);
    }

    #[test]
    fn changes_are_counted_by_their_largest_channel() {
        let a = gradient();
        let mut b = a.clone();
        b.get_pixel_mut(3, 2).0[2] = 77 + 40; // blue up by 40
        b.get_pixel_mut(5, 5).0[0] ^= 1; // red off by one
        assert_eq!(changed_pixels(&a, &b, 0), 2);
        assert_eq!(
            changed_pixels(&a, &b, 1),
            1,
            "the off-by-one is under the threshold"
        );
        assert_eq!(max_change(&a, &b), 40);
    }

    #[test]
    fn magnified_difference_brightens_with_gain() {
        let a = gradient();
        let mut b = a.clone();
        b.get_pixel_mut(0, 0).0[1] += 10;
        let low = magnified_difference(&a, &b, 1.0).get_pixel(0, 0).0;
        let high = magnified_difference(&a, &b, 20.0).get_pixel(0, 0).0;
        assert_ne!(low, BLACK, "a change is never shown as no change");
        assert_eq!(low, magma(10.0 / 255.0));
        assert_eq!(high, magma(200.0 / 255.0));
        assert_eq!(
            magnified_difference(&a, &b, 1e6).get_pixel(0, 0).0,
            magma(1.0)
        );
    }

    #[test]
    #[should_panic(expected = "same size")]
    fn different_sizes_are_refused() {
        changed_pixels(&RgbImage::new(2, 2), &RgbImage::new(3, 2), 0);
    }
}
