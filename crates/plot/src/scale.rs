//! The mapping from data values to positions along an axis, and the
//! choice of range and ticks for it.

use super::text::text_width;
use super::ticks::{Ticks, integer_ticks, linear_ticks, log_ticks, thin};

/// The data range one axis shows, and whether it is logarithmic.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Scale {
    /// Data value at the start of the axis.
    pub(crate) min: f64,
    /// Data value at the end of the axis.
    pub(crate) max: f64,
    /// Whether positions follow log10 of the value.
    pub(crate) log: bool,
}

impl Scale {
    /// How far along the axis `v` lies: 0 at `min`, 1 at `max`.
    pub(crate) fn fraction(&self, v: f64) -> f64 {
        let (v, min, max) = if self.log {
            (v.log10(), self.min.log10(), self.max.log10())
        } else {
            (v, self.min, self.max)
        };
        if max == min {
            0.5
        } else {
            (v - min) / (max - min)
        }
    }

    /// Ticks for a horizontal axis `length` pixels long: as many as fit
    /// with a clear gap between neighbouring labels.
    pub(crate) fn spaced_ticks(&self, length: f32, integers: bool, label_size: f32) -> Ticks {
        let mut spacing = 30.0;
        let mut ticks = self.ticks(length, spacing, integers);
        // Each round asks for fewer ticks. The bound only matters for
        // absurd inputs: 40 rounds take the spacing past 200,000 pixels.
        for _ in 0..40 {
            if self.labels_fit(&ticks, length, label_size) {
                break;
            }
            spacing *= 1.25;
            ticks = self.ticks(length, spacing, integers);
        }
        ticks
    }

    /// Whether the widest label, plus a gap, fits between two neighbouring
    /// ticks (ticks are evenly spaced, so checking the first pair is enough).
    fn labels_fit(&self, ticks: &Ticks, length: f32, label_size: f32) -> bool {
        let gap = 16.0;
        let widest = ticks
            .labels
            .iter()
            .map(|label| text_width(label, label_size))
            .fold(0.0, f32::max);
        match ticks.values.as_slice() {
            [a, b, ..] => {
                let room = (self.fraction(*b) - self.fraction(*a)).abs() as f32 * length;
                room >= widest + gap
            }
            _ => true, // zero or one tick cannot collide
        }
    }

    /// Ticks for an axis `length` pixels long, aiming for no more than one
    /// tick per `spacing` pixels.
    pub(crate) fn ticks(&self, length: f32, spacing: f32, integers: bool) -> Ticks {
        let max_ticks = ((length / spacing).floor() as usize).max(2);
        if self.log {
            thin(log_ticks(self.min, self.max), max_ticks)
        } else if integers {
            integer_ticks(self.min, self.max, max_ticks)
        } else {
            linear_ticks(self.min, self.max, max_ticks)
        }
    }
}

/// The range of the finite `values`, widened by 4% at each end so that no
/// point sits right on the frame. Falls back to 0..1 with no data.
pub(crate) fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (min, max) = finite_extent(values).unwrap_or((0.0, 1.0));
    if min == max {
        // A single value (or a flat line): give it some room around it.
        let half = if min == 0.0 { 1.0 } else { min.abs() * 0.1 };
        return (min - half, max + half);
    }
    let pad = (max - min) * 0.04;
    (min - pad, max + pad)
}

/// Whole decades enclosing the `values` (all already at least `floor`),
/// e.g. 3..450 → 1..1000.
pub(crate) fn decade_range(values: impl Iterator<Item = f64>, floor: f64) -> (f64, f64) {
    let (min, max) = finite_extent(values).unwrap_or((floor, floor * 10.0));
    let low = 10f64.powf(min.max(floor).log10().floor());
    let high = 10f64.powf(max.max(floor).log10().ceil());
    (low, if high > low { high } else { low * 10.0 })
}

fn finite_extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .filter(|v| v.is_finite())
        .fold(None, |extent, v| match extent {
            None => Some((v, v)),
            Some((min, max)) => Some((min.min(v), max.max(v))),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fraction_is_linear_or_logarithmic() {
        let linear = Scale {
            min: 0.0,
            max: 10.0,
            log: false,
        };
        assert_eq!(linear.fraction(2.5), 0.25);
        let log = Scale {
            min: 1.0,
            max: 1000.0,
            log: true,
        };
        assert!((log.fraction(10.0) - 1.0 / 3.0).abs() < 1e-12);
        let flat = Scale {
            min: 3.0,
            max: 3.0,
            log: false,
        };
        assert_eq!(
            flat.fraction(3.0),
            0.5,
            "a zero-width range puts values mid-axis"
        );
    }

    #[test]
    fn automatic_ranges_pad_or_round_to_decades() {
        assert_eq!(padded_range([0.0, 100.0].into_iter()), (-4.0, 104.0));
        assert_eq!(padded_range([5.0].into_iter()), (4.5, 5.5));
        assert_eq!(padded_range([f64::NAN].into_iter()), (-0.04, 1.04));
        assert_eq!(decade_range([3.0, 450.0].into_iter(), 1.0), (1.0, 1000.0));
        assert_eq!(decade_range([1.0, 1.0].into_iter(), 1.0), (1.0, 10.0));
    }

    #[test]
    fn spaced_ticks_thin_out_when_labels_would_touch() {
        let scale = Scale {
            min: 0.0,
            max: 100_000.0,
            log: false,
        };
        let roomy = scale.spaced_ticks(2000.0, false, 13.0);
        let cramped = scale.spaced_ticks(200.0, false, 13.0);
        assert!(cramped.values.len() < roomy.values.len());
        assert!(cramped.values.len() >= 2);
    }
}
