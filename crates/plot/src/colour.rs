//! The one colour type used throughout the plot module, and the palette the
//! figures share so that every chart in the workbook looks alike.

/// An opaque sRGB colour, one byte per channel: `[red, green, blue]`.
///
/// A plain array (rather than a struct) because it is exactly what
/// `image::Rgb` wraps, so colours move between the two without conversion.
pub type Rgb = [u8; 3];

/// Figure background.
pub const WHITE: Rgb = [255, 255, 255];
/// Pure black, used for "nothing changed" in difference images.
pub const BLACK: Rgb = [0, 0, 0];
/// Titles, labels and tick numbers: dark grey reads softer than black.
pub const TEXT: Rgb = [34, 34, 34];
/// Captions and other secondary text.
pub const TEXT_MUTED: Rgb = [85, 85, 85];
/// Axis lines and tick marks.
pub const AXIS: Rgb = [68, 68, 68];
/// Grid lines: light enough that data drawn over them stays dominant.
pub const GRID: Rgb = [224, 224, 224];
/// Legend frames and other quiet outlines.
pub const FRAME: Rgb = [190, 190, 190];

/// Colours for successive data series: matplotlib's "tab10" palette (its
/// default colour cycle), which stays distinguishable for most readers
/// with colour-vision deficiencies.
pub const SERIES: [Rgb; 8] = [
    [31, 119, 180],  // blue
    [255, 127, 14],  // orange
    [44, 160, 44],   // green
    [214, 39, 40],   // red
    [148, 103, 189], // purple
    [140, 86, 75],   // brown
    [227, 119, 194], // pink
    [127, 127, 127], // grey
];

/// The colour for series number `index`, cycling through [`SERIES`].
pub fn series_colour(index: usize) -> Rgb {
    SERIES[index % SERIES.len()]
}

/// Linear blend from `a` (at `t = 0`) to `b` (at `t = 1`); `t` is clamped.
pub fn mix(a: Rgb, b: Rgb, t: f32) -> Rgb {
    let t = t.clamp(0.0, 1.0);
    let channel = |i: usize| (a[i] as f32 + (b[i] as f32 - a[i] as f32) * t).round() as u8;
    [channel(0), channel(1), channel(2)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mix_hits_both_ends_and_the_middle() {
        assert_eq!(mix(BLACK, WHITE, 0.0), BLACK);
        assert_eq!(mix(BLACK, WHITE, 1.0), WHITE);
        assert_eq!(mix(BLACK, WHITE, 0.5), [128, 128, 128]);
        assert_eq!(mix(BLACK, WHITE, 7.0), WHITE, "t is clamped");
    }

    #[test]
    fn series_colours_cycle() {
        assert_eq!(series_colour(0), SERIES[0]);
        assert_eq!(series_colour(SERIES.len() + 2), SERIES[2]);
    }
}
