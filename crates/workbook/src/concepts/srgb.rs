//! The sRGB curve: linear light to the encoded value a PNG stores, against
//! the straight line of storing linear light as it is. Near black the curve
//! is 12.92 times steeper, so a small change of linear light there is
//! several 8-bit levels: the levels are spent where the eye needs them.

use image::RgbImage;
use raylab::srgb::{encode_channel, linear_to_srgb, quantise};
use raylab_plot::colour::{TEXT, WHITE, series_colour};
use raylab_plot::{Anchor, Canvas, Corner, LinePlot, Series};

/// Two dark linear values a tenth of a percent apart, and their levels.
pub const DARK: (f32, f32) = (0.002, 0.003);

/// The 8-bit levels of `c` encoded by sRGB, and stored linearly.
pub fn levels(c: f32) -> (u8, u8) {
    (encode_channel(c), quantise(c))
}

/// The curve's slope at black: the linear segment's factor.
pub fn slope_at_black() -> f32 {
    linear_to_srgb(1e-4) / 1e-4
}

const W: u32 = 560;
const H: u32 = 440;

fn full_plot() -> LinePlot {
    let curve = (0..=200).map(|k| {
        let c = k as f64 / 200.0;
        (c, f64::from(linear_to_srgb(c as f32)))
    });
    LinePlot::new("linear light → the value a PNG stores")
        .x_label("linear light c")
        .y_label("encoded value (× 255 = 8-bit level)")
        .x_range(0.0, 1.0)
        .y_range(0.0, 1.0)
        .series(Series::new("sRGB: linear_to_srgb(c)", series_colour(0), curve).without_markers())
        .series(
            Series::new(
                "stored as it is: c",
                series_colour(7),
                [(0.0, 0.0), (1.0, 1.0)],
            )
            .without_markers(),
        )
        .legend(Corner::BottomRight)
}

fn dark_plot() -> LinePlot {
    let steps = 400;
    let top = 0.01;
    let points = |f: fn(f32) -> u8| {
        (0..=steps).map(move |k| {
            let c = top * k as f64 / steps as f64;
            (c, f64::from(f(c as f32)))
        })
    };
    let (a, b) = DARK;
    LinePlot::new("near black, in 8-bit levels")
        .x_label("linear light c")
        .y_label("8-bit level")
        .x_range(0.0, top)
        .y_range(0.0, 30.0)
        .series(
            Series::new("sRGB, 8 bits", series_colour(0), points(encode_channel)).without_markers(),
        )
        .series(
            Series::new("linear, 8 bits", series_colour(7), points(quantise_linear))
                .without_markers(),
        )
        .vertical_marker(f64::from(a), format!("c = {a}"), series_colour(3))
        .vertical_marker(f64::from(b), format!("c = {b}"), series_colour(3))
        .legend(Corner::BottomRight)
}

fn quantise_linear(c: f32) -> u8 {
    quantise(c.clamp(0.0, 1.0))
}

pub fn figure() -> RgbImage {
    let mut canvas = Canvas::new(2 * W, H + 70, WHITE);
    let full = full_plot();
    let mut left = full.render_canvas(W, H);
    // The curve's first, straight piece: slope 12.92 from black.
    let slope = f64::from(slope_at_black());
    let from = full.data_to_pixel(W, H, 0.0, 0.0);
    let to = full.data_to_pixel(W, H, 0.035, 0.035 * slope);
    left.dashed_line(from, to, series_colour(3), 2.0, 6.0, 4.0);
    left.text(
        to.0 + 6.0,
        to.1,
        &format!("slope {slope:.2} at black"),
        13.0,
        series_colour(3),
        Anchor::MIDDLE_LEFT,
    );
    canvas.draw_rgb_image(&left.to_rgb_image(), 0, 0, 1);
    let dark = dark_plot();
    let mut right = dark.render_canvas(W, H);
    // The two dark values' levels, written beside the sRGB steps.
    let (a, b) = DARK;
    for c in [a, b] {
        let (srgb, _) = levels(c);
        let (x, y) = dark.data_to_pixel(W, H, f64::from(c), f64::from(srgb));
        right.circle((x, y), 4.0, Some(series_colour(3)), None);
        right.text(
            x - 6.0,
            y - 6.0,
            &format!("level {srgb}"),
            13.0,
            series_colour(3),
            Anchor::BASELINE_RIGHT,
        );
    }
    canvas.draw_rgb_image(&right.to_rgb_image(), W as i32, 0, 1);
    let ((sa, la), (sb, lb)) = (levels(a), levels(b));
    let lines = [
        format!(
            "Near black the curve is {:.2} times steeper than the line: from c = {a} to {b}, sRGB goes from level {sa} to {sb} ({} levels),",
            slope_at_black(),
            sb - sa
        ),
        if la == lb {
            format!(
                "while stored as it is both would be level {la}: dark tones would band, and bright ones waste levels."
            )
        } else {
            format!("while stored as it is they would be levels {la} and {lb}.")
        },
    ];
    for (n, line) in lines.iter().enumerate() {
        canvas.text(
            W as f32,
            H as f32 + 22.0 + 20.0 * n as f32,
            line,
            14.0,
            TEXT,
            Anchor::BASELINE_CENTRE,
        );
    }
    canvas.to_rgb_image()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tenth_of_a_percent_near_black_is_three_srgb_levels_and_none_linear() {
        // 12.92 · 0.002 · 255 = 6.59 → 7; 12.92 · 0.003 · 255 = 9.88 → 10;
        // linear: 0.51 → 1 and 0.765 → 1.
        assert_eq!(levels(0.002), (7, 1));
        assert_eq!(levels(0.003), (10, 1));
        assert!((slope_at_black() - 12.92).abs() < 1e-3);
    }
}
