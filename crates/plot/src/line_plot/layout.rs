//! Where everything goes: the plotting rectangle, the scales of its axes
//! and their ticks, worked out from the data and the room the labels need.

use super::{LABEL_SIZE, LinePlot, PAD, RIGHT_ALLOWANCE, TICK_LENGTH, TICK_SIZE, TITLE_SIZE};
use crate::scale::{Scale, decade_range, padded_range};
use crate::text::{line_metrics, text_width};
use crate::ticks::Ticks;

impl LinePlot {
    /// Works out the plotting rectangle and the ticks. The margins depend
    /// on the tick labels and the tick count on the space left, so this
    /// goes in order: vertical margins → y ticks → left margin → x ticks.
    pub(super) fn layout(&self, width: u32, height: u32) -> Layout {
        let (width, height) = (width as f32, height as f32);
        let title_h = line_metrics(TITLE_SIZE).line_height();
        let label_h = line_metrics(LABEL_SIZE).line_height();
        let tick_h = line_metrics(TICK_SIZE).line_height();

        let top = if self.title.is_empty() {
            PAD
        } else {
            PAD + title_h + 10.0
        };
        let bottom = height - (PAD + label_h + 6.0 + tick_h + 3.0 + TICK_LENGTH);

        let y_scale = self.y_scale();
        // Labels are one line tall, so a fixed spacing suffices vertically.
        let mut y_ticks = y_scale.ticks(bottom - top, 42.0, false);
        if let Some(zero) = self.zero_row() {
            y_ticks.values.insert(0, zero);
            y_ticks.labels.insert(0, "0".to_owned());
        }
        let widest_y_label = y_ticks
            .labels
            .iter()
            .map(|label| text_width(label, TICK_SIZE))
            .fold(0.0, f32::max);
        let left = PAD + label_h + 10.0 + widest_y_label + 6.0 + TICK_LENGTH;
        // A right axis takes the same room on its side as the left one.
        let right_ticks = self.right.as_ref().map(|right| {
            let scale = right.y_scale();
            let mut ticks = scale.ticks(bottom - top, 42.0, false);
            if let Some(zero) = right.zero_row() {
                ticks.values.insert(0, zero);
                ticks.labels.insert(0, "0".to_owned());
            }
            (scale, ticks)
        });
        let right = match &right_ticks {
            None => width - PAD - RIGHT_ALLOWANCE,
            Some((_, ticks)) => {
                let widest = ticks
                    .labels
                    .iter()
                    .map(|label| text_width(label, TICK_SIZE))
                    .fold(0.0, f32::max);
                width - (PAD + label_h + 10.0 + widest + 6.0 + TICK_LENGTH)
            }
        };

        let x_scale = self.x_scale();
        let x_ticks = x_scale.spaced_ticks(right - left, self.integer_x_ticks, TICK_SIZE);
        let frame = Frame {
            left,
            top,
            right: right.max(left + 1.0),
            bottom: bottom.max(top + 1.0),
            x: x_scale,
            y: y_scale,
        };
        Layout {
            frame,
            x_ticks,
            y_ticks,
            right: right_ticks.map(|(y, ticks)| RightAxis {
                frame: Frame { y, ..frame },
                ticks,
            }),
        }
    }

    fn x_scale(&self) -> Scale {
        let (min, max) = self.x_range.unwrap_or_else(|| {
            let xs = self
                .series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.0));
            let marker_xs = self.markers.iter().map(|m| m.x);
            if self.log_x {
                decade_range(xs.chain(marker_xs), f64::MIN_POSITIVE)
            } else {
                padded_range(xs.chain(marker_xs))
            }
        });
        Scale {
            min,
            max: if self.log_x && max <= min {
                min * 10.0
            } else {
                max
            },
            log: self.log_x,
        }
    }

    fn y_scale(&self) -> Scale {
        let ys = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| self.clamp_y(p.1)));
        match self.log_y_floor {
            None => {
                let (min, max) = self.y_range.unwrap_or_else(|| padded_range(ys));
                Scale {
                    min,
                    max,
                    log: false,
                }
            }
            Some(floor) => {
                let (min, max) = self
                    .y_range
                    .map(|(min, max)| (min.max(floor), max.max(floor)))
                    .unwrap_or_else(|| decade_range(ys, floor));
                Scale {
                    min: self.zero_row().unwrap_or(min),
                    max: if max > min { max } else { min * 10.0 },
                    log: true,
                }
            }
        }
    }

    /// On a log axis, values below the floor move up to it, and zeros (and
    /// anything below) go to a row of their own under it.
    pub(super) fn clamp_y(&self, y: f64) -> f64 {
        match self.log_y_floor {
            // NaN fails the comparisons and stays NaN, so it still breaks the line.
            Some(_) if y <= 0.0 => self.zero_row().unwrap_or(y),
            Some(floor) if y < floor => floor,
            _ => y,
        }
    }

    /// Where a log axis draws zero: half a decade under its floor, with a
    /// tick of its own, so that "nothing" never looks like "one".
    fn zero_row(&self) -> Option<f64> {
        let floor = self.log_y_floor?;
        let any_zero = self
            .series
            .iter()
            .flat_map(|s| s.points.iter())
            .any(|p| p.1 <= 0.0);
        any_zero.then(|| floor / 10f64.sqrt())
    }
}

/// The outcome of laying a plot out: where the data goes, and the ticks.
pub(super) struct Layout {
    pub(super) frame: Frame,
    pub(super) x_ticks: Ticks,
    pub(super) y_ticks: Ticks,
    pub(super) right: Option<RightAxis>,
}

/// A second y axis: the same rectangle with the right axis's y range.
pub(super) struct RightAxis {
    pub(super) frame: Frame,
    pub(super) ticks: Ticks,
}

/// The plotting rectangle in pixels and the data range each axis shows.
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame {
    pub(super) left: f32,
    pub(super) top: f32,
    pub(super) right: f32,
    pub(super) bottom: f32,
    pub(super) x: Scale,
    pub(super) y: Scale,
}

impl Frame {
    pub(super) fn x_pixel(&self, x: f64) -> f32 {
        self.left + (self.right - self.left) * self.x.fraction(x) as f32
    }

    /// Screen y grows downwards, data y upwards: hence `bottom -`.
    pub(super) fn y_pixel(&self, y: f64) -> f32 {
        self.bottom - (self.bottom - self.top) * self.y.fraction(y) as f32
    }

    pub(super) fn pixel_of(&self, x: f64, y: f64) -> (f32, f32) {
        (self.x_pixel(x), self.y_pixel(y))
    }
}

/// The centre of the pixel that `v` falls in, so a 1 px line drawn there
/// covers exactly one row or column instead of blurring over two.
pub(super) fn crisp(v: f32) -> f32 {
    v.floor() + 0.5
}
