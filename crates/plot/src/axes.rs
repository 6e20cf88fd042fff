//! Line plots: one or more data series on x/y axes, with grid, ticks,
//! labels, a legend and optional labelled vertical marker lines.
//!
//! Build a [`LinePlot`] step by step, then [`LinePlot::render`] it:
//!
//! ```
//! # use raylab_plot::axes::{LinePlot, Series};
//! # use raylab_plot::colour::series_colour;
//! let image = LinePlot::new("Pixels still changing")
//!     .x_label("max depth")
//!     .y_label("changed pixels")
//!     .integer_x_ticks()
//!     .series(Series::new("mirror scene", series_colour(0), [(1.0, 900.0), (2.0, 120.0)]))
//!     .render(800, 500);
//! assert_eq!(image.dimensions(), (800, 500));
//! ```

use image::RgbImage;

use super::canvas::Canvas;
use super::colour::{AXIS, FRAME, GRID, Rgb, TEXT, WHITE};
use super::label_box::LabelBox;
use super::scale::{Scale, decade_range, padded_range};
use super::text::{Anchor, line_metrics, text_width};
use super::ticks::Ticks;

// Sizes in pixels, chosen for figures around 800 × 500.
const PAD: f32 = 16.0;
const TITLE_SIZE: f32 = 20.0;
const LABEL_SIZE: f32 = 15.0;
const TICK_SIZE: f32 = 13.0;
const LEGEND_SIZE: f32 = 13.0;
const TICK_LENGTH: f32 = 5.0;
const LINE_WIDTH: f32 = 2.0;
const MARKER_RADIUS: f32 = 3.5;
/// Room left of the frame's right edge for half of the last x tick label.
const RIGHT_ALLOWANCE: f32 = 14.0;

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

/// A corner of the plotting area, for placing the legend.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Corner {
    /// Upper left.
    TopLeft,
    /// Upper right.
    TopRight,
    /// Lower left.
    BottomLeft,
    /// Lower right.
    BottomRight,
}

/// A line plot under construction. Every setter takes and returns the plot,
/// so a whole figure reads as one chain of calls.
#[derive(Clone, Debug, PartialEq)]
pub struct LinePlot {
    title: String,
    x_label: String,
    y_label: String,
    x_range: Option<(f64, f64)>,
    y_range: Option<(f64, f64)>,
    /// `Some(floor)` for a log y axis; values below `floor` are drawn at it.
    log_y_floor: Option<f64>,
    /// Whether the x axis is logarithmic (every x must then be positive).
    log_x: bool,
    integer_x_ticks: bool,
    series: Vec<Series>,
    markers: Vec<VerticalMarker>,
    legend: Option<Corner>,
    /// A second y axis on the right, for series in other units: a plot of
    /// its own whose y label, y range, log scale and series are used (its
    /// title, x settings, markers and legend are not).
    right: Option<Box<LinePlot>>,
}

impl LinePlot {
    /// An empty plot with a title; the legend defaults to the top right.
    pub fn new(title: impl Into<String>) -> LinePlot {
        LinePlot {
            title: title.into(),
            x_label: String::new(),
            y_label: String::new(),
            x_range: None,
            y_range: None,
            log_y_floor: None,
            log_x: false,
            integer_x_ticks: false,
            series: Vec::new(),
            markers: Vec::new(),
            legend: Some(Corner::TopRight),
            right: None,
        }
    }

    /// Adds a second y axis on the right for the series of `axis`, in its
    /// units: its y label, range and log scale make the axis. Its series
    /// join the legend (name them so that the reader knows which axis).
    pub fn right_axis(mut self, axis: LinePlot) -> LinePlot {
        self.right = Some(Box::new(axis));
        self
    }

    /// Text under the x axis.
    pub fn x_label(mut self, label: impl Into<String>) -> LinePlot {
        self.x_label = label.into();
        self
    }

    /// Text beside the y axis (drawn rotated, reading upwards).
    pub fn y_label(mut self, label: impl Into<String>) -> LinePlot {
        self.y_label = label.into();
        self
    }

    /// Fixes the x axis to `min..=max` instead of fitting it to the data.
    pub fn x_range(mut self, min: f64, max: f64) -> LinePlot {
        self.x_range = Some((min, max));
        self
    }

    /// Fixes the y axis to `min..=max` instead of fitting it to the data.
    pub fn y_range(mut self, min: f64, max: f64) -> LinePlot {
        self.y_range = Some((min, max));
        self
    }

    /// Makes the y axis logarithmic, with ticks at powers of ten.
    ///
    /// A log axis cannot show zero, so any value below `floor` (zero
    /// included) is drawn at `floor`, and the y label says so.
    pub fn log_y(mut self, floor: f64) -> LinePlot {
        // A non-positive floor would bring the zero problem straight back.
        let floor = if floor > 0.0 { floor } else { 1.0 };
        self.log_y_floor = Some(floor);
        self
    }

    /// Makes the x axis logarithmic, with ticks at powers of ten, for
    /// data whose x values are all positive (a sample count, say).
    pub fn log_x(mut self) -> LinePlot {
        self.log_x = true;
        self
    }

    /// Puts x ticks on whole numbers only, e.g. for a depth or a count.
    pub fn integer_x_ticks(mut self) -> LinePlot {
        self.integer_x_ticks = true;
        self
    }

    /// Adds a data series.
    pub fn series(mut self, series: Series) -> LinePlot {
        self.series.push(series);
        self
    }

    /// Adds a dashed vertical line at `x` with a label.
    pub fn vertical_marker(mut self, x: f64, label: impl Into<String>, colour: Rgb) -> LinePlot {
        self.markers.push(VerticalMarker {
            x,
            label: label.into(),
            colour,
        });
        self
    }

    /// Puts the legend in `corner` of the plotting area.
    pub fn legend(mut self, corner: Corner) -> LinePlot {
        self.legend = Some(corner);
        self
    }

    /// Leaves the legend out.
    pub fn no_legend(mut self) -> LinePlot {
        self.legend = None;
        self
    }

    /// Draws the plot as a `width` × `height` image.
    pub fn render(&self, width: u32, height: u32) -> RgbImage {
        self.render_canvas(width, height).to_rgb_image()
    }

    /// Draws the plot onto a fresh canvas, so that callers can add their
    /// own annotations (arrows, notes) before turning it into an image.
    /// [`LinePlot::data_to_pixel`] says where data points ended up.
    pub fn render_canvas(&self, width: u32, height: u32) -> Canvas {
        let mut canvas = Canvas::new(width, height, WHITE);
        let layout = self.layout(canvas.width(), canvas.height());
        // Back to front: grid and axes first so data is never hidden by them.
        self.draw_grid(&mut canvas, &layout);
        draw_axes(&mut canvas, &layout);
        self.draw_marker_lines(&mut canvas, &layout.frame);
        self.draw_series(&mut canvas, &layout.frame);
        if let (Some(right), Some(axis)) = (&self.right, &layout.right) {
            right.draw_series(&mut canvas, &axis.frame);
            draw_right_axis(&mut canvas, right, axis);
        }
        self.draw_labels(&mut canvas, &layout);
        let legend_box = self.draw_legend(&mut canvas, &layout.frame);
        let ink = self.ink(&layout);
        self.draw_marker_labels(&mut canvas, &layout.frame, legend_box, &ink);
        canvas
    }

    /// Points along every drawn line, a pixel or two apart: what a label
    /// must not cover.
    fn ink(&self, layout: &Layout) -> Vec<(f32, f32)> {
        let mut ink = Vec::new();
        if self.markers.is_empty() {
            return ink; // only marker labels look for it
        }
        let mut trace = |plot: &LinePlot, frame: &Frame| {
            for series in &plot.series {
                let pixels: Vec<Option<(f32, f32)>> = series
                    .points
                    .iter()
                    .map(|&(x, y)| {
                        let y = plot.clamp_y(y);
                        (x.is_finite() && y.is_finite()).then(|| frame.pixel_of(x, y))
                    })
                    .collect();
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

    /// Where the data point `(x, y)` lands in a `width` × `height` render,
    /// in canvas pixels (log-axis clamping applied).
    pub fn data_to_pixel(&self, width: u32, height: u32, x: f64, y: f64) -> (f32, f32) {
        self.layout(width, height)
            .frame
            .pixel_of(x, self.clamp_y(y))
    }

    // ----- layout ----------------------------------------------------------

    /// Works out the plotting rectangle and the ticks. The margins depend
    /// on the tick labels and the tick count on the space left, so this
    /// goes in order: vertical margins → y ticks → left margin → x ticks.
    fn layout(&self, width: u32, height: u32) -> Layout {
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
    fn clamp_y(&self, y: f64) -> f64 {
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

    /// The y label, plus a note on log scaling and on any clamped values.
    fn y_label_text(&self) -> String {
        let Some(floor) = self.log_y_floor else {
            return self.y_label.clone();
        };
        let clamped: Vec<f64> = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.1))
            .filter(|&y| y > 0.0 && y < floor)
            .collect();
        let note = if clamped.is_empty() {
            "log scale".to_string()
        } else {
            format!("log scale; values below {floor} shown as {floor}")
        };
        if self.y_label.is_empty() {
            note
        } else {
            format!("{} ({note})", self.y_label)
        }
    }

    // ----- drawing ---------------------------------------------------------

    fn draw_grid(&self, canvas: &mut Canvas, layout: &Layout) {
        let frame = &layout.frame;
        for &x in &layout.x_ticks.values {
            let px = crisp(frame.x_pixel(x));
            canvas.stroke_line(px, frame.top, px, frame.bottom, GRID, 1.0);
        }
        for &y in &layout.y_ticks.values {
            let py = crisp(frame.y_pixel(y));
            canvas.stroke_line(frame.left, py, frame.right, py, GRID, 1.0);
        }
    }

    fn draw_marker_lines(&self, canvas: &mut Canvas, frame: &Frame) {
        for marker in &self.markers {
            let x = crisp(frame.x_pixel(marker.x));
            if x >= frame.left && x <= frame.right {
                let (from, to) = ((x, frame.top), (x, frame.bottom));
                canvas.dashed_line(from, to, marker.colour, 1.5, 6.0, 4.0);
            }
        }
    }

    fn draw_series(&self, canvas: &mut Canvas, frame: &Frame) {
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
            let pixels: Vec<Option<(f32, f32)>> = series
                .points
                .iter()
                .map(|&(x, y)| {
                    let y = self.clamp_y(y);
                    (x.is_finite() && y.is_finite()).then(|| frame.pixel_of(x, y))
                })
                .collect();
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

    fn draw_labels(&self, canvas: &mut Canvas, layout: &Layout) {
        let frame = &layout.frame;
        let middle_x = (frame.left + frame.right) / 2.0;
        let middle_y = (frame.top + frame.bottom) / 2.0;

        let tick_top = frame.bottom + TICK_LENGTH + 3.0;
        for (value, label) in layout.x_ticks.values.iter().zip(&layout.x_ticks.labels) {
            let x = frame.x_pixel(*value);
            canvas.text(x, tick_top, label, TICK_SIZE, TEXT, Anchor::TOP_CENTRE);
        }
        let tick_right = frame.left - TICK_LENGTH - 6.0;
        for (value, label) in layout.y_ticks.values.iter().zip(&layout.y_ticks.labels) {
            let y = frame.y_pixel(*value);
            canvas.text(tick_right, y, label, TICK_SIZE, TEXT, Anchor::MIDDLE_RIGHT);
        }

        // Axis labels hug the canvas edges; the margins were sized for them.
        let (x_label, y_label) = (&self.x_label, self.y_label_text());
        let bottom = canvas.height() as f32 - PAD;
        canvas.text(
            middle_x,
            bottom,
            x_label,
            LABEL_SIZE,
            TEXT,
            Anchor::BOTTOM_CENTRE,
        );
        canvas.text_vertical(
            PAD,
            middle_y,
            &y_label,
            LABEL_SIZE,
            TEXT,
            Anchor::TOP_CENTRE,
        );

        // Centre the title over the plotting area, but never let it run off
        // the canvas.
        let title_width = text_width(&self.title, TITLE_SIZE);
        let width = canvas.width() as f32;
        let title_x = middle_x
            .min(width - PAD - title_width / 2.0)
            .max(PAD + title_width / 2.0);
        let title = &self.title;
        canvas.text(title_x, PAD, title, TITLE_SIZE, TEXT, Anchor::TOP_CENTRE);
    }

    /// Draws the legend (if any series is named) and returns its box.
    fn draw_legend(&self, canvas: &mut Canvas, frame: &Frame) -> Option<LabelBox> {
        let corner = self.legend?;
        let right_series = self.right.iter().flat_map(|right| &right.series);
        let named: Vec<&Series> = (self.series.iter().chain(right_series))
            .filter(|s| !s.name.is_empty())
            .collect();
        if named.is_empty() {
            return None;
        }
        let row_h = (line_metrics(LEGEND_SIZE).line_height() * 1.15).round();
        let sample_w = 24.0;
        let inner = 8.0;
        let widest = named
            .iter()
            .map(|s| text_width(&s.name, LEGEND_SIZE))
            .fold(0.0, f32::max);
        let w = (inner * 2.0 + sample_w + 8.0 + widest).ceil();
        let h = (inner * 2.0 + row_h * named.len() as f32).ceil();
        let inset = 10.0;
        let x = match corner {
            Corner::TopLeft | Corner::BottomLeft => frame.left + inset,
            Corner::TopRight | Corner::BottomRight => frame.right - inset - w,
        }
        .round();
        let y = match corner {
            Corner::TopLeft | Corner::TopRight => frame.top + inset,
            Corner::BottomLeft | Corner::BottomRight => frame.bottom - inset - h,
        }
        .round();

        // Slightly see-through, so a line passing under it is not lost.
        canvas.fill_rect_translucent(x, y, w, h, WHITE, 0.9);
        canvas.stroke_rect(x + 0.5, y + 0.5, w - 1.0, h - 1.0, FRAME, 1.0);
        for (row, series) in named.iter().enumerate() {
            let row_y = y + inner + row_h * (row as f32 + 0.5);
            let (start, end) = (x + inner, x + inner + sample_w);
            let colour = series.colour;
            canvas.stroke_line(start, row_y, end, row_y, colour, LINE_WIDTH);
            if series.markers {
                let centre = ((start + end) / 2.0, row_y);
                canvas.circle(centre, MARKER_RADIUS, Some(colour), Some((WHITE, 1.0)));
            }
            let (name, anchor) = (&series.name, Anchor::MIDDLE_LEFT);
            canvas.text(end + 8.0, row_y, name, LEGEND_SIZE, TEXT, anchor);
        }
        Some(LabelBox { x, y, w, h })
    }

    /// Writes each marker's label near the top of its line, on a pale
    /// backing so grid lines do not cut through the letters. Labels move
    /// down out of the way of the legend, of each other and of the lines
    /// (`ink`); if no spot is clear of the lines, the first clear of the
    /// legend and the other labels will do.
    fn draw_marker_labels(
        &self,
        canvas: &mut Canvas,
        frame: &Frame,
        legend: Option<LabelBox>,
        ink: &[(f32, f32)],
    ) {
        let metrics = line_metrics(LEGEND_SIZE);
        let h = metrics.line_height();
        let mut taken: Vec<LabelBox> = legend.into_iter().collect();
        for marker in &self.markers {
            let line_x = frame.x_pixel(marker.x);
            if marker.label.is_empty() || line_x < frame.left || line_x > frame.right {
                continue;
            }
            let w = text_width(&marker.label, LEGEND_SIZE);
            // Candidate spots, best first: right of the line, then left of
            // it, starting at the top and stepping down a line at a time.
            let right_x = line_x + 6.0;
            let left_x = line_x - 6.0 - w;
            let sides = [right_x, left_x]
                .into_iter()
                .filter(|&x| x >= frame.left + 4.0 && x + w <= frame.right - 4.0);
            let sides: Vec<f32> = sides.collect();
            let rows = (0..).map(|row| frame.top + 6.0 + row as f32 * (h + 2.0));
            let spots: Vec<LabelBox> = rows
                .take_while(|&y| y + h <= frame.bottom)
                .flat_map(|y| {
                    sides.iter().map(move |&x| LabelBox {
                        x: x - 3.0,
                        y,
                        w: w + 6.0,
                        h,
                    })
                })
                .filter(|spot| !taken.iter().any(|other| other.overlaps(spot)))
                .collect();
            let inked = |spot: &LabelBox| {
                ink.iter().any(|&(x, y)| {
                    let near = LINE_WIDTH + 1.0;
                    x >= spot.x - near
                        && x <= spot.x + spot.w + near
                        && y >= spot.y - near
                        && y <= spot.y + spot.h + near
                })
            };
            let spot = spots
                .iter()
                .find(|spot| !inked(spot))
                .or(spots.first())
                .copied();
            let Some(spot) = spot else {
                continue; // no free room anywhere: leave the line unlabelled
            };
            canvas.fill_rect_translucent(spot.x, spot.y, spot.w, spot.h, WHITE, 0.85);
            let (x, y) = (spot.x + 3.0, spot.y);
            canvas.text(
                x,
                y,
                &marker.label,
                LEGEND_SIZE,
                marker.colour,
                Anchor::TOP_LEFT,
            );
            taken.push(spot);
        }
    }
}

/// The right axis: its spine, ticks, tick labels and rotated label.
fn draw_right_axis(canvas: &mut Canvas, plot: &LinePlot, axis: &RightAxis) {
    let frame = &axis.frame;
    let right = crisp(frame.right);
    canvas.stroke_line(right, frame.top, right, frame.bottom + 0.5, AXIS, 1.0);
    let label_left = frame.right + TICK_LENGTH + 6.0;
    let mut widest: f32 = 0.0;
    for (value, label) in axis.ticks.values.iter().zip(&axis.ticks.labels) {
        let y = frame.y_pixel(*value);
        let py = crisp(y);
        canvas.stroke_line(right, py, right + TICK_LENGTH, py, AXIS, 1.0);
        canvas.text(label_left, y, label, TICK_SIZE, TEXT, Anchor::MIDDLE_LEFT);
        widest = widest.max(text_width(label, TICK_SIZE));
    }
    let middle_y = (frame.top + frame.bottom) / 2.0;
    let x = label_left + widest + 10.0;
    let label = plot.y_label_text();
    canvas.text_vertical(x, middle_y, &label, LABEL_SIZE, TEXT, Anchor::TOP_CENTRE);
}

/// Frame, spines and tick marks.
fn draw_axes(canvas: &mut Canvas, layout: &Layout) {
    let frame = &layout.frame;
    let (left, bottom) = (crisp(frame.left), crisp(frame.bottom));
    canvas.stroke_line(left, frame.top, left, bottom + 0.5, AXIS, 1.0);
    canvas.stroke_line(left - 0.5, bottom, frame.right, bottom, AXIS, 1.0);
    for &x in &layout.x_ticks.values {
        let px = crisp(frame.x_pixel(x));
        canvas.stroke_line(px, bottom, px, bottom + TICK_LENGTH, AXIS, 1.0);
    }
    for &y in &layout.y_ticks.values {
        let py = crisp(frame.y_pixel(y));
        canvas.stroke_line(left - TICK_LENGTH, py, left, py, AXIS, 1.0);
    }
}

/// The centre of the pixel that `v` falls in, so a 1 px line drawn there
/// covers exactly one row or column instead of blurring over two.
fn crisp(v: f32) -> f32 {
    v.floor() + 0.5
}

/// The outcome of laying a plot out: where the data goes, and the ticks.
struct Layout {
    frame: Frame,
    x_ticks: Ticks,
    y_ticks: Ticks,
    right: Option<RightAxis>,
}

/// A second y axis: the same rectangle with the right axis's y range.
struct RightAxis {
    frame: Frame,
    ticks: Ticks,
}

/// The plotting rectangle in pixels and the data range each axis shows.
#[derive(Clone, Copy, Debug)]
struct Frame {
    left: f32,
    top: f32,
    right: f32,
    bottom: f32,
    x: Scale,
    y: Scale,
}

impl Frame {
    fn x_pixel(&self, x: f64) -> f32 {
        self.left + (self.right - self.left) * self.x.fraction(x) as f32
    }

    /// Screen y grows downwards, data y upwards: hence `bottom -`.
    fn y_pixel(&self, y: f64) -> f32 {
        self.bottom - (self.bottom - self.top) * self.y.fraction(y) as f32
    }

    fn pixel_of(&self, x: f64, y: f64) -> (f32, f32) {
        (self.x_pixel(x), self.y_pixel(y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::colour::series_colour;

    const BLUE: Rgb = [31, 119, 180];

    fn identity_plot() -> LinePlot {
        let points = (0..=10).map(|i| (f64::from(i), f64::from(i)));
        LinePlot::new("y = x")
            .x_label("x")
            .y_label("y")
            .x_range(0.0, 10.0)
            .y_range(0.0, 10.0)
            .series(Series::new("y = x", BLUE, points))
            .no_legend()
    }

    fn pixel_at(image: &RgbImage, (x, y): (f32, f32)) -> Rgb {
        image.get_pixel(x as u32, y as u32).0
    }

    fn distance(a: Rgb, b: Rgb) -> u32 {
        (0..3).map(|i| a[i].abs_diff(b[i]) as u32).sum()
    }

    #[test]
    fn identity_line_is_where_the_data_says() {
        let plot = identity_plot();
        let (w, h) = (600, 400);
        let image = plot.render(w, h);
        assert_eq!(image.dimensions(), (w, h));

        // Every data point carries a marker in the series colour.
        for i in 0..=10 {
            let p = plot.data_to_pixel(w, h, f64::from(i), f64::from(i));
            assert_eq!(pixel_at(&image, p), BLUE, "marker at ({i}, {i})");
        }
        // Between markers the line itself is (nearly) the series colour.
        let between = plot.data_to_pixel(w, h, 4.5, 4.5);
        assert!(
            distance(pixel_at(&image, between), BLUE) < distance(pixel_at(&image, between), WHITE)
        );
        // Far from the line, away from grid lines, is background.
        let far = plot.data_to_pixel(w, h, 7.3, 2.7);
        assert_eq!(pixel_at(&image, far), WHITE);
    }

    #[test]
    fn data_mapping_puts_ranges_on_the_frame_edges() {
        let plot = identity_plot();
        let layout = plot.layout(600, 400);
        let (x0, y0) = plot.data_to_pixel(600, 400, 0.0, 0.0);
        let (x1, y1) = plot.data_to_pixel(600, 400, 10.0, 10.0);
        assert_eq!((x0, y0), (layout.frame.left, layout.frame.bottom));
        assert_eq!((x1, y1), (layout.frame.right, layout.frame.top));
        assert!(x0 > 40.0 && y1 > 30.0, "room for labels and title");
    }

    #[test]
    fn axes_are_drawn_in_axis_colour() {
        let plot = identity_plot();
        let image = plot.render(600, 400);
        let layout = plot.layout(600, 400);
        let left_spine = crisp(layout.frame.left) as u32;
        let mid_y = ((layout.frame.top + layout.frame.bottom) / 2.0) as u32;
        assert_eq!(image.get_pixel(left_spine, mid_y).0, AXIS);
    }

    #[test]
    fn lines_outside_the_range_are_clipped() {
        let plot = LinePlot::new("clipped")
            .x_range(0.0, 1.0)
            .y_range(0.0, 1.0)
            .series(Series::new("", BLUE, [(0.0, 0.0), (1.0, 50.0)]).without_markers());
        let image = plot.render(400, 300);
        // The line heads straight up past the frame: nothing in the title band
        // may be blue.
        let layout = plot.layout(400, 300);
        let band = (0..(layout.frame.top - 8.0) as u32)
            .flat_map(|y| (0..400).map(move |x| (x, y)))
            .filter(|&(x, y)| image.get_pixel(x, y).0 == BLUE)
            .count();
        assert_eq!(band, 0);
    }

    #[test]
    fn integer_x_ticks_are_whole_numbers() {
        let plot = LinePlot::new("").integer_x_ticks().series(Series::new(
            "",
            BLUE,
            (1..=10).map(|d| (f64::from(d), 1.0)),
        ));
        let layout = plot.layout(800, 500);
        assert_eq!(
            layout.x_ticks.labels,
            ["1", "2", "3", "4", "5", "6", "7", "8", "9", "10"]
        );
    }

    #[test]
    fn linear_ticks_use_one_two_five_steps() {
        let plot = identity_plot().y_range(0.0, 0.7);
        let layout = plot.layout(800, 500);
        let steps: Vec<f64> = layout
            .y_ticks
            .values
            .windows(2)
            .map(|w| w[1] - w[0])
            .collect();
        let step = steps[0];
        assert!(steps.iter().all(|s| (s - step).abs() < 1e-9));
        let mantissa = step / 10f64.powf(step.log10().floor());
        assert!([1.0, 2.0, 5.0].iter().any(|m| (m - mantissa).abs() < 1e-9));
    }

    #[test]
    fn a_log_axis_draws_zero_on_a_row_of_its_own_below_one() {
        let points = [(1.0, 5000.0), (2.0, 300.0), (3.0, 1.0), (4.0, 0.0)];
        let plot = LinePlot::new("")
            .y_label("changed pixels")
            .log_y(1.0)
            .series(Series::new("", BLUE, points));
        let layout = plot.layout(800, 500);
        assert_eq!(
            layout.y_ticks.labels,
            ["0", "1", "10", "100", "1000", "10000"]
        );
        assert_eq!(plot.y_label_text(), "changed pixels (log scale)");
        // Zero sits on the frame's bottom, one apart from it, higher up.
        let (_, zero) = plot.data_to_pixel(800, 500, 4.0, 0.0);
        let (_, one) = plot.data_to_pixel(800, 500, 3.0, 1.0);
        assert_eq!(zero, layout.frame.bottom);
        assert!(zero - one > 20.0, "0 at {zero} and 1 at {one} look alike");
        // A value between zero and the floor is still drawn on the floor.
        let small = LinePlot::new("")
            .y_label("changed pixels")
            .log_y(1.0)
            .series(Series::new("", BLUE, [(1.0, 100.0), (2.0, 0.5)]));
        assert_eq!(
            small.y_label_text(),
            "changed pixels (log scale; values below 1 shown as 1)"
        );
        // A plot with nothing clamped just says "log scale".
        let plain = LinePlot::new("").y_label("time").log_y(0.1);
        assert_eq!(plain.y_label_text(), "time (log scale)");
    }

    #[test]
    fn legend_and_marker_label_are_drawn() {
        let base =
            LinePlot::new("").series(Series::new("a", series_colour(1), [(0.0, 0.0), (1.0, 1.0)]));
        let bare = base.clone().no_legend().render(500, 300);
        let with_legend = base.clone().legend(Corner::BottomRight).render(500, 300);
        assert_ne!(bare, with_legend);
        let marked = base
            .vertical_marker(0.5, "half way", [200, 0, 0])
            .render(500, 300);
        let reddish = marked
            .pixels()
            .filter(|p| p.0[0] > 150 && p.0[1] < 80)
            .count();
        assert!(reddish > 30, "dashed line and label in the marker colour");
    }

    #[test]
    fn a_right_axis_maps_its_series_to_its_own_range_and_joins_the_legend() {
        let left = Series::new("pixels", BLUE, [(1.0, 0.0), (2.0, 100.0)]);
        let right_points = [(1.0, 255.0), (2.0, 0.0)];
        let red = series_colour(3);
        let axis = LinePlot::new("")
            .y_label("largest change")
            .y_range(0.0, 255.0)
            .series(Series::new(
                "largest change (right axis)",
                red,
                right_points,
            ));
        let plot = LinePlot::new("")
            .y_range(0.0, 100.0)
            .series(left)
            .right_axis(axis)
            .legend(Corner::BottomLeft);
        let (w, h) = (600, 400);
        let layout = plot.layout(w, h);
        let axis = layout.right.as_ref().expect("a right axis");
        // 255 on the right is the frame's top, where 100 is on the left.
        assert_eq!(axis.frame.y_pixel(255.0), layout.frame.top);
        assert_eq!(layout.frame.y_pixel(100.0), layout.frame.top);
        assert!(layout.frame.right < w as f32 - 60.0, "room for the labels");
        let image = plot.render(w, h);
        // The right series' first point, (1, 255), is at the top left corner
        // of the frame; the left series' point (1, 0) at the bottom left.
        let corner = axis.frame.pixel_of(1.0, 255.0);
        assert_eq!(pixel_at(&image, corner), red);
        let plain = LinePlot::new("")
            .y_range(0.0, 100.0)
            .series(Series::new("pixels", BLUE, [(1.0, 0.0), (2.0, 100.0)]))
            .legend(Corner::BottomLeft)
            .layout(w, h);
        assert!(plain.right.is_none());
    }

    #[test]
    fn a_marker_label_moves_off_a_line_it_would_cover() {
        // A falling line passes through the top right of the marker at x = 2,
        // where its label would go first.
        let points = [(1.0, 10.0), (2.0, 10.0), (3.0, 9.0), (4.0, 0.0)];
        let plot = LinePlot::new("")
            .x_range(1.0, 4.0)
            .y_range(0.0, 10.0)
            .series(Series::new("", BLUE, points).without_markers())
            .vertical_marker(2.5, "here", [200, 0, 0])
            .no_legend();
        let image = plot.render(500, 300);
        let layout = plot.layout(500, 300);
        let ink = plot.ink(&layout);
        // Find the red label's pixels and check none lies on the line's ink.
        let red: Vec<(u32, u32)> = image
            .enumerate_pixels()
            .filter(|(x, _, p)| {
                p.0[0] > 150 && p.0[1] < 80 && (*x as f32 - layout.frame.x_pixel(2.5)).abs() > 3.0
            })
            .map(|(x, y, _)| (x, y))
            .collect();
        assert!(!red.is_empty(), "the label is drawn");
        // The box the label's letters fill, and a pixel around it.
        let left = red.iter().map(|p| p.0).min().unwrap_or(0) as f32 - 1.0;
        let right = red.iter().map(|p| p.0).max().unwrap_or(0) as f32 + 1.0;
        let top = red.iter().map(|p| p.1).min().unwrap_or(0) as f32 - 1.0;
        let bottom = red.iter().map(|p| p.1).max().unwrap_or(0) as f32 + 1.0;
        let covered = ink
            .iter()
            .any(|&(x, y)| x >= left && x <= right && y >= top && y <= bottom);
        assert!(
            !covered,
            "the label ({left}..{right}, {top}..{bottom}) covers the line"
        );
        // The first spot, right of the marker at the top, is on the line:
        // the label moved down from there.
        assert!(top > layout.frame.top + 10.0, "{top}");
    }

    #[test]
    fn empty_plot_still_renders() {
        let image = LinePlot::new("nothing yet").render(300, 200);
        assert_eq!(image.dimensions(), (300, 200));
        let tiny = LinePlot::new("too small").render(10, 10);
        assert_eq!(tiny.dimensions(), (10, 10));
    }
}
