//! Comparing two renders of the same scene: a picture of where they
//! differ, and counts of how much.
//!
//! A pixel's change is the largest of its three channel differences, so a
//! pixel that changed in only one channel still counts in full.

use image::RgbImage;

use super::canvas::Canvas;
use super::colormap::magma;
use super::colour::{AXIS, BLACK, TEXT, WHITE};
use super::text::Anchor;
use super::ticks::linear_ticks;

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

/// The height of the strip [`with_change_scale`] adds under an image.
pub const SCALE_STRIP: u32 = 58;

/// A [`magnified_difference`] image with its scale under it: the magma bar
/// from no change to the change that reaches the top of the colormap
/// (255 / `gain` levels), labelled in 8-bit levels, so that a reader can
/// tell how large a colour's change is.
pub fn with_change_scale(difference: &RgbImage, gain: f32) -> RgbImage {
    let (width, height) = difference.dimensions();
    let mut canvas = Canvas::new(width, height + SCALE_STRIP, WHITE);
    canvas.draw_rgb_image(difference, 0, 0, 1);
    let full = 255.0 / gain.max(1.0);
    let (x0, x1) = (40.0, (width as f32 - 40.0).max(41.0));
    let top = height as f32 + 8.0;
    let bar = 10.0;
    let steps = (x1 - x0).ceil() as u32;
    for i in 0..steps {
        let t = i as f32 / (steps - 1).max(1) as f32;
        canvas.fill_rect(x0 + i as f32, top, 1.0, bar, magma(t));
    }
    canvas.stroke_rect(x0, top, x1 - x0, bar, AXIS, 1.0);
    let ticks = linear_ticks(0.0, f64::from(full), 6);
    for (value, label) in ticks.values.iter().zip(&ticks.labels) {
        let x = x0 + (x1 - x0) * (*value as f32 / full);
        canvas.stroke_line(x, top + bar, x, top + bar + 4.0, AXIS, 1.0);
        canvas.text(x, top + bar + 5.0, label, 11.0, TEXT, Anchor::TOP_CENTRE);
    }
    let note = if gain > 1.0 {
        format!(
            "change in 8-bit levels, largest channel; black: unchanged; {full:.0} and more: top of the scale"
        )
    } else {
        "change in 8-bit levels, largest channel; black: unchanged".to_owned()
    };
    canvas.text(
        width as f32 / 2.0,
        top + bar + 22.0,
        &note,
        12.0,
        TEXT,
        Anchor::TOP_CENTRE,
    );
    canvas.to_rgb_image()
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
    fn a_difference_image_gains_a_scale_strip_and_keeps_its_pixels() {
        let a = gradient();
        let mut b = a.clone();
        b.get_pixel_mut(3, 2).0[2] = 77 + 40;
        let diff = magnified_difference(&a, &b, 4.0);
        let scaled = with_change_scale(&diff, 4.0);
        assert_eq!(scaled.dimensions(), (16, 8 + SCALE_STRIP));
        for (x, y, pixel) in diff.enumerate_pixels() {
            assert_eq!(scaled.get_pixel(x, y), pixel);
        }
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
