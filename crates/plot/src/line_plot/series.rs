//! The data: a series and a vertical marker, and how they are drawn.

use super::layout::{Frame, Layout, crisp};
use super::{LINE_WIDTH, LinePlot, MARKER_RADIUS};
use crate::canvas::Canvas;
use crate::colour::{Rgb, WHITE};

/// One data series: a named, coloured polyline through its points.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Shown in the legend; an empty name leaves the series out of it.
    pub name: String,
    /// Line and marker colour.
    pub colour: Rgb,
    /// Data points `(x, y)` in drawing order. A point with a NaN or
    /// infinite coordinate breaks the line in two.
    pub points: Vec<(f64, f64)>,
    /// Whether to draw a round marker at every point.
    pub markers: bool,
}

impl Series {
    /// A series with markers at its points.
    pub fn new(
        name: impl Into<String>,
        colour: Rgb,
        points: impl IntoIterator<Item = (f64, f64)>,
    ) -> Series {
        Series {
            name: name.into(),
            colour,
            points: points.into_iter().collect(),
            markers: true,
        }
    }

    /// The same series drawn as a bare line, for dense data where markers
    /// would merge into a smudge.
    pub fn without_markers(mut self) -> Series {
        self.markers = false;
        self
    }
}

/// A dashed vertical line at `x` with a short text label, for pointing out
/// a value such as "stops changing after depth 5".
#[derive(Clone, Debug, PartialEq)]
pub struct VerticalMarker {
    /// Position in data units.
    pub x: f64,
    /// Text written next to the top of the line.
    pub label: String,
    /// Colour of the line and its label.
    pub colour: Rgb,
}

impl LinePlot {
    pub(super) fn draw_marker_lines(&self, canvas: &mut Canvas, frame: &Frame) {
        for marker in &self.markers {
            let x = crisp(frame.x_pixel(marker.x));
            if x >= frame.left && x <= frame.right {
                let (from, to) = ((x, frame.top), (x, frame.bottom));
                canvas.dashed_line(from, to, marker.colour, 1.5, 6.0, 4.0);
            }
        }
    }

    pub(super) fn draw_series(&self, canvas: &mut Canvas, frame: &Frame) {
        // Clip a little outside the frame so markers sitting exactly on the
        // edge are drawn whole, while runaway lines are still cut off.
        let margin = MARKER_RADIUS + 1.5;
        canvas.set_clip_rect(
            frame.left - margin,
            frame.top - margin,
            frame.right - frame.left + 2.0 * margin,
            frame.bottom - frame.top + 2.0 * margin,
        );
        for series in &self.series {
            let pixels = self.pixels(series, frame);
            // Each run of drawable points is one unbroken polyline.
            for run in pixels.split(Option::is_none) {
                let run: Vec<(f32, f32)> = run.iter().flatten().copied().collect();
                canvas.polyline(&run, series.colour, LINE_WIDTH);
            }
            if series.markers {
                for &point in pixels.iter().flatten() {
                    // A white rim keeps neighbouring markers apart.
                    let rim = Some((WHITE, 1.0));
                    canvas.circle(point, MARKER_RADIUS, Some(series.colour), rim);
                }
            }
        }
        canvas.clear_clip();
    }

    /// Where each point of `series` lands on `frame`, or `None` for a
    /// point that breaks the line (a NaN or infinite coordinate).
    fn pixels(&self, series: &Series, frame: &Frame) -> Vec<Option<(f32, f32)>> {
        series
            .points
            .iter()
            .map(|&(x, y)| {
                let y = self.clamp_y(y);
                (x.is_finite() && y.is_finite()).then(|| frame.pixel_of(x, y))
            })
            .collect()
    }

    /// Points along every drawn line, a pixel or two apart: what a label
    /// must not cover.
    pub(super) fn ink(&self, layout: &Layout) -> Vec<(f32, f32)> {
        let mut ink = Vec::new();
        if self.markers.is_empty() {
            return ink; // only marker labels look for it
        }
        let mut trace = |plot: &LinePlot, frame: &Frame| {
            for series in &plot.series {
                let pixels = plot.pixels(series, frame);
                for pair in pixels.windows(2) {
                    let (Some(a), Some(b)) = (pair[0], pair[1]) else {
                        continue;
                    };
                    let steps = ((b.0 - a.0).hypot(b.1 - a.1) / 2.0).ceil().max(1.0) as usize;
                    ink.extend((0..=steps).map(|k| {
                        let f = k as f32 / steps as f32;
                        (a.0 + (b.0 - a.0) * f, a.1 + (b.1 - a.1) * f)
                    }));
                }
                ink.extend(pixels.iter().flatten());
            }
        };
        trace(self, &layout.frame);
        if let (Some(right), Some(axis)) = (&self.right, &layout.right) {
            trace(right, &axis.frame);
        }
        ink
    }
}
