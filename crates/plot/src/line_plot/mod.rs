//! Line plots: one or more data series on x/y axes, with grid, ticks,
//! labels, a legend and optional labelled vertical marker lines.
//!
//! Build a [`LinePlot`] step by step, then [`LinePlot::render`] it:
//!
//! ```
//! # use raylab_plot::line_plot::{LinePlot, Series};
//! # use raylab_plot::colour::series_colour;
//! let image = LinePlot::new("Pixels still changing")
//!     .x_label("max depth")
//!     .y_label("changed pixels")
//!     .integer_x_ticks()
//!     .series(Series::new("mirror scene", series_colour(0), [(1.0, 900.0), (2.0, 120.0)]))
//!     .render(800, 500);
//! assert_eq!(image.dimensions(), (800, 500));
//! ```
//!
//! The plot is one builder, [`LinePlot`]; drawing it is split by what is
//! drawn: the data ([`series`]), where everything goes ([`layout`]), the
//! frame with its ticks and labels ([`axes`]), and the legend with the
//! markers' labels ([`legend`]).

use image::RgbImage;

use crate::canvas::Canvas;
use crate::colour::{Rgb, WHITE};

mod axes;
mod layout;
mod legend;
mod series;
#[cfg(test)]
mod tests;

use axes::{draw_axes, draw_right_axis};
pub use legend::Corner;
pub use series::{Series, VerticalMarker};

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

    /// Where the data point `(x, y)` lands in a `width` × `height` render,
    /// in canvas pixels (log-axis clamping applied).
    pub fn data_to_pixel(&self, width: u32, height: u32, x: f64, y: f64) -> (f32, f32) {
        self.layout(width, height)
            .frame
            .pixel_of(x, self.clamp_y(y))
    }
}
