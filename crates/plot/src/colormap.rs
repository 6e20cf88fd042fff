//! Perceptually uniform colormaps: numbers in `[0, 1]` to colours.
//!
//! Viridis and magma are matplotlib's defaults for a reason: equal steps in
//! the value look like equal steps in colour, they stay readable in
//! greyscale and for common colour-vision deficiencies, and their lightness
//! rises steadily so "brighter" always means "more". The 256-entry tables
//! come from matplotlib (see `colormap_tables.rs` for source and licence).

use super::colormap_tables::{MAGMA, VIRIDIS};
use super::colour::{Rgb, SERIES};

/// Which colormap a figure uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Colormap {
    /// Dark purple through teal to yellow.
    Viridis,
    /// Black through purple and orange to pale yellow; good when "zero"
    /// should look like nothing, as in difference images.
    Magma,
    /// Blue through light grey to red (Moreland's "cool to warm"), for
    /// signed values: 0.5 is zero, below it blue, above it red, with equal
    /// lightness at equal distances either side.
    Diverging,
    /// Ten colours far apart, one per whole number, for counts such as a
    /// ray's depth where 2 and 3 must not look alike: the first a pale grey
    /// (the common case recedes), then matplotlib's "tab10" hues, and the
    /// last a near-black (the limit stands out). Meant for
    /// [`ColourScale::steps`](crate::ColourScale::steps).
    Distinct,
}

impl Colormap {
    /// The colour for `t`, clamped to `[0, 1]`; NaN gives the low end.
    pub fn sample(self, t: f32) -> Rgb {
        match self {
            Colormap::Viridis => viridis(t),
            Colormap::Magma => magma(t),
            Colormap::Diverging => diverging(t),
            Colormap::Distinct => {
                let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
                DISTINCT[(t * (DISTINCT.len() - 1) as f32).round() as usize]
            }
        }
    }

    /// The colour of step `index` of `count` whole-number steps: for
    /// [`Colormap::Distinct`] its own entry (so step 0 is always the grey,
    /// however many steps there are), for the others the map at
    /// `index / (count - 1)`.
    pub fn step(self, index: usize, count: usize) -> Rgb {
        match self {
            Colormap::Distinct => DISTINCT[index.min(DISTINCT.len() - 1)],
            _ => self.sample(index as f32 / count.saturating_sub(1).max(1) as f32),
        }
    }
}

/// The entries of [`Colormap::Distinct`]: pale grey, the first seven
/// series colours (tab10's blue to pink), tab10's olive, and near-black.
const DISTINCT: [Rgb; 10] = [
    [222, 222, 222],
    SERIES[0],
    SERIES[1],
    SERIES[2],
    SERIES[3],
    SERIES[4],
    SERIES[5],
    SERIES[6],
    [188, 189, 34],
    [30, 30, 30],
];

/// matplotlib's viridis at `t` in `[0, 1]` (clamped; NaN gives the low end).
pub fn viridis(t: f32) -> Rgb {
    sample_table(&VIRIDIS, t)
}

/// matplotlib's magma at `t` in `[0, 1]` (clamped; NaN gives the low end).
pub fn magma(t: f32) -> Rgb {
    sample_table(&MAGMA, t)
}

/// Kenneth Moreland's cool-to-warm map ("Diverging Color Maps for
/// Scientific Visualization", 2009), from his published 33-entry table
/// at every eighth entry: blue at 0, light grey at 0.5, red at 1.
const COOL_WARM: [[u8; 3]; 9] = [
    [59, 76, 192],
    [98, 130, 234],
    [141, 176, 254],
    [184, 208, 249],
    [221, 221, 221],
    [245, 196, 173],
    [244, 154, 123],
    [222, 96, 77],
    [180, 4, 38],
];

/// The diverging map at `t` in `[0, 1]` (clamped; NaN gives the middle,
/// "no difference").
pub fn diverging(t: f32) -> Rgb {
    let t = if t.is_nan() { 0.5 } else { t.clamp(0.0, 1.0) };
    let position = t * 8.0;
    let below = (position.floor() as usize).min(7);
    let fraction = position - below as f32;
    let (a, b) = (COOL_WARM[below], COOL_WARM[below + 1]);
    let channel = |i: usize| {
        let value = f32::from(a[i]) + (f32::from(b[i]) - f32::from(a[i])) * fraction;
        value.round() as u8
    };
    [channel(0), channel(1), channel(2)]
}

/// Reads a colour table at fraction `t`, blending linearly between the two
/// nearest entries so that the result changes smoothly with `t`.
fn sample_table(table: &[[u8; 3]; 256], t: f32) -> Rgb {
    // `f32::clamp` keeps NaN as NaN, so test for it first.
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let position = t * 255.0;
    let below = (position.floor() as usize).min(254);
    let fraction = position - below as f32;
    let (a, b) = (table[below], table[below + 1]);
    let channel = |i: usize| {
        let value = f32::from(a[i]) + (f32::from(b[i]) - f32::from(a[i])) * fraction;
        value.round() as u8
    };
    [channel(0), channel(1), channel(2)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viridis_endpoints_match_matplotlib() {
        assert_eq!(viridis(0.0), [68, 1, 84]);
        assert_eq!(viridis(1.0), [253, 231, 37]);
        // Entry 128 of matplotlib's table: (0.127568, 0.566949, 0.550556) × 255.
        assert_eq!(viridis(128.0 / 255.0), [33, 145, 140]);
    }

    #[test]
    fn magma_endpoints_match_matplotlib() {
        assert_eq!(magma(0.0), [0, 0, 4]);
        assert_eq!(magma(1.0), [252, 253, 191]);
    }

    #[test]
    fn out_of_range_is_clamped_and_nan_is_low() {
        assert_eq!(viridis(-3.0), viridis(0.0));
        assert_eq!(viridis(7.0), viridis(1.0));
        assert_eq!(viridis(f32::NAN), viridis(0.0));
        assert_eq!(magma(f32::NAN), magma(0.0));
        assert_eq!(magma(f32::INFINITY), magma(1.0));
        assert_eq!(magma(f32::NEG_INFINITY), magma(0.0));
    }

    #[test]
    fn lightness_rises_monotonically() {
        // Rough luma; both maps are designed so this never goes down.
        let luma = |c: Rgb| 0.299 * c[0] as f32 + 0.587 * c[1] as f32 + 0.114 * c[2] as f32;
        for map in [Colormap::Viridis, Colormap::Magma] {
            let mut previous = -1.0;
            for i in 0..=64 {
                let l = luma(map.sample(i as f32 / 64.0));
                assert!(l >= previous - 0.5, "{map:?} darkens at {i}/64");
                previous = l;
            }
        }
    }

    #[test]
    fn interpolates_between_entries() {
        // Halfway between entries 0 and 1 lies between their colours.
        let mid = viridis(0.5 / 255.0);
        let (a, b) = (VIRIDIS[0], VIRIDIS[1]);
        for i in 0..3 {
            assert!(mid[i] >= a[i].min(b[i]) && mid[i] <= a[i].max(b[i]));
        }
    }

    #[test]
    fn distinct_steps_are_their_own_entries_and_all_differ() {
        assert_eq!(Colormap::Distinct.step(0, 2), DISTINCT[0]);
        assert_eq!(
            Colormap::Distinct.step(1, 2),
            DISTINCT[1],
            "not the far end"
        );
        assert_eq!(Colormap::Distinct.step(9, 10), [30, 30, 30]);
        assert_eq!(Colormap::Distinct.step(42, 10), DISTINCT[9], "clamped");
        assert_eq!(Colormap::Viridis.step(1, 3), viridis(0.5));
        // Every pair differs by at least 60 in some channel.
        for (i, a) in DISTINCT.iter().enumerate() {
            for b in &DISTINCT[i + 1..] {
                let far = (0..3).any(|c| a[c].abs_diff(b[c]) >= 60);
                assert!(far, "{a:?} and {b:?} look alike");
            }
        }
    }

    #[test]
    fn the_diverging_map_is_grey_at_zero_blue_below_and_red_above() {
        assert_eq!(diverging(0.5), [221, 221, 221]);
        assert_eq!(diverging(f32::NAN), [221, 221, 221]);
        assert_eq!(diverging(0.0), [59, 76, 192]);
        assert_eq!(diverging(1.0), [180, 4, 38]);
        let luma = |c: Rgb| 0.299 * c[0] as f32 + 0.587 * c[1] as f32 + 0.114 * c[2] as f32;
        for i in 1..=8 {
            let d = i as f32 / 16.0;
            let (cool, warm) = (diverging(0.5 - d), diverging(0.5 + d));
            assert!(cool[2] > cool[0] && warm[0] > warm[2], "{cool:?} {warm:?}");
            // Both sides darken away from the middle, at about the same rate.
            assert!(luma(cool) < 221.0 && luma(warm) < 221.0);
            assert!((luma(cool) - luma(warm)).abs() < 30.0, "{cool:?} {warm:?}");
        }
    }
}
