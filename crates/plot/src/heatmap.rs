//! Heatmaps: a grid of numbers shown as colours, with a colour bar that
//! says which colour means which number.
//!
//! The grid is row-major with row 0 at the top, the same layout as an
//! image, so a per-pixel quantity from the renderer (bounces, samples,
//! time) can be shown in place.

use image::RgbImage;

use super::canvas::Canvas;
use super::colormap::Colormap;
use super::colour::{FRAME, Rgb, TEXT, TEXT_MUTED, WHITE};
use super::text::{Anchor, line_metrics, text_width, wrap_text};
use super::ticks::{Ticks, integer_ticks, linear_ticks, log_ticks, log_ticks_at, thin};

const PAD: f32 = 16.0;
const TITLE_SIZE: f32 = 20.0;
const CAPTION_SIZE: f32 = 14.0;
const TICK_SIZE: f32 = 13.0;
const LABEL_SIZE: f32 = 15.0;
const BAR_GAP: u32 = 18;
const BAR_WIDTH: u32 = 18;
const TICK_LENGTH: f32 = 4.0;
/// The least room between two tick labels on the colour bar, in pixels: a
/// 13 px label needs about this much to stay apart from the next.
const TICK_GAP: f32 = 14.0;
/// The automatic pixel scale aims for this many pixels on the longer side.
const TARGET_SIDE: usize = 480;

/// Which values map to the two ends of the colormap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColourScale {
    /// Value shown in the colormap's lowest colour (and anything below it).
    pub min: f32,
    /// Value shown in the colormap's highest colour (and anything above it).
    pub max: f32,
    /// Spread colours evenly over orders of magnitude instead of over the
    /// values themselves: 1, 10 and 100 are equally far apart.
    pub log: bool,
    /// Whole numbers, each its own colour block: the colour bar becomes a
    /// legend with one entry per number (see [`ColourScale::steps`]).
    pub steps: bool,
}

impl ColourScale {
    /// Evenly spaced colours from `min` to `max`.
    pub fn linear(min: f32, max: f32) -> ColourScale {
        ColourScale {
            min,
            max,
            log: false,
            steps: false,
        }
    }

    /// One colour per whole number from `min` to `max` (values are rounded
    /// first): for counts such as depth, where a smooth bar would make 1, 2
    /// and 3 three near-identical shades. Best with [`Colormap::Distinct`].
    pub fn steps(min: u32, max: u32) -> ColourScale {
        ColourScale {
            min: min as f32,
            max: max.max(min) as f32,
            log: false,
            steps: true,
        }
    }

    /// Logarithmic colours from `min` to `max`; `min` must be positive (a
    /// non-positive `min` is treated as `max / 1000`).
    pub fn log(min: f32, max: f32) -> ColourScale {
        ColourScale {
            min,
            max,
            log: true,
            steps: false,
        }
    }

    /// How many whole-number steps a [`ColourScale::steps`] scale has.
    fn step_count(&self) -> usize {
        (self.max - self.min).round().max(0.0) as usize + 1
    }

    /// The colour of `value` in `colormap`: its step's colour on a steps
    /// scale (rounded, clamped to the ends), else the map at its place.
    pub fn colour(&self, value: f32, colormap: Colormap) -> Rgb {
        if self.steps {
            let count = self.step_count();
            let index = if value.is_nan() {
                0
            } else {
                ((value.round() - self.min).max(0.0) as usize).min(count - 1)
            };
            colormap.step(index, count)
        } else {
            colormap.sample(self.normalise(value))
        }
    }

    /// Where `value` falls between `min` (0) and `max` (1), clamped. NaN
    /// stays NaN, which every colormap shows as its low end; on a log scale
    /// zero and negative values also go to the low end.
    pub fn normalise(&self, value: f32) -> f32 {
        let (min, max) = self.effective_range();
        let t = if self.log {
            if value <= 0.0 {
                return 0.0;
            }
            (value.ln() - min.ln()) / (max.ln() - min.ln())
        } else {
            (value - min) / (max - min)
        };
        // A zero-width range would give ∞ or NaN; call everything "low".
        if max > min { t.clamp(0.0, 1.0) } else { 0.0 }
    }

    /// The range actually used, with a log scale's minimum kept positive.
    fn effective_range(&self) -> (f32, f32) {
        if self.log && self.min <= 0.0 {
            (self.max / 1000.0, self.max)
        } else {
            (self.min, self.max)
        }
    }

    /// Tick positions for a colour bar `length` pixels long: every whole
    /// number on a steps scale; on a log scale 1, 2, 3, 4, 5 of every
    /// decade when their labels fit (so that "2" or "4" can be read off),
    /// else 1, 2, 5, else the decades alone.
    fn ticks(&self, length: f32) -> Ticks {
        let (min, max) = self.effective_range();
        let (min, max) = (f64::from(min), f64::from(max));
        let max_ticks = (length as usize / 28).max(2);
        if self.steps {
            integer_ticks(min, max, usize::MAX)
        } else if self.log {
            let per_decade = f64::from(length) / (max / min).log10().max(1e-9);
            // The closest pairs: 4 and 5 in the first set, 1 and 2 in the second.
            let fits = |ratio: f64| per_decade * ratio.log10() >= f64::from(TICK_GAP);
            if fits(5.0 / 4.0) {
                log_ticks_at(min, max, &[1.0, 2.0, 3.0, 4.0, 5.0])
            } else if fits(2.0) {
                log_ticks_at(min, max, &[1.0, 2.0, 5.0])
            } else {
                thin(log_ticks(min, max), max_ticks)
            }
        } else if min.fract() == 0.0 && max.fract() == 0.0 {
            // Whole-number ends usually mean counts: keep ticks whole.
            integer_ticks(min, max, max_ticks)
        } else {
            linear_ticks(min, max, max_ticks)
        }
    }
}

/// Colours a `width` × `height` grid of `values` (row 0 at the top) and
/// enlarges each cell to `scale` × `scale` pixels.
///
/// # Panics
///
/// If `values.len()` is not `width * height`: the grid would be ambiguous.
pub fn heatmap_image(
    values: &[f32],
    width: usize,
    height: usize,
    scale: u32,
    colour_scale: ColourScale,
    colormap: Colormap,
) -> RgbImage {
    assert_eq!(
        values.len(),
        width * height,
        "heatmap: {width} × {height} grid needs {} values",
        width * height
    );
    let scale = scale.max(1);
    let (out_w, out_h) = (width as u32 * scale, height as u32 * scale);
    RgbImage::from_fn(out_w, out_h, |x, y| {
        let (column, row) = ((x / scale) as usize, (y / scale) as usize);
        image::Rgb(colour_scale.colour(values[row * width + column], colormap))
    })
}

/// A complete heatmap figure: title, coloured grid, colour bar with ticks
/// and label, and a caption wrapped to the figure's width.
///
/// Written as a struct so that a call site names every part:
///
/// ```
/// # use raylab_plot::heatmap::{ColourScale, HeatmapFigure};
/// # use raylab_plot::colormap::Colormap;
/// let counts = vec![1.0; 16 * 12];
/// let image = HeatmapFigure {
///     title: "Bounces per pixel",
///     caption: "Each ray stops after at most 10 bounces.",
///     values: &counts,
///     width: 16,
///     height: 12,
///     colour_scale: ColourScale::linear(1.0, 10.0),
///     colour_bar_label: "bounces",
///     colormap: Colormap::Viridis,
///     pixel_scale: None,
/// }
/// .render();
/// assert!(image.width() > 16 && image.height() > 12);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct HeatmapFigure<'a> {
    /// Line above the figure.
    pub title: &'a str,
    /// Explanation under the figure; wrapped, so it may be long.
    pub caption: &'a str,
    /// Row-major values, row 0 at the top; `width * height` of them.
    pub values: &'a [f32],
    /// Cells per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Which values map to which end of the colormap.
    pub colour_scale: ColourScale,
    /// What the colours measure, written along the colour bar.
    pub colour_bar_label: &'a str,
    /// Viridis or magma.
    pub colormap: Colormap,
    /// Pixels per cell; `None` picks a whole number that makes the longer
    /// side about 480 pixels.
    pub pixel_scale: Option<u32>,
}

/// Shorthand for [`HeatmapFigure::render`] with an automatic pixel scale.
///
/// # Panics
///
/// If `values.len()` is not `width * height`.
#[allow(clippy::too_many_arguments)] // mirrors the figure's parts, each named in HeatmapFigure
pub fn heatmap_figure(
    title: &str,
    caption: &str,
    values: &[f32],
    width: usize,
    height: usize,
    colour_scale: ColourScale,
    colour_bar_label: &str,
    colormap: Colormap,
) -> RgbImage {
    HeatmapFigure {
        title,
        caption,
        values,
        width,
        height,
        colour_scale,
        colour_bar_label,
        colormap,
        pixel_scale: None,
    }
    .render()
}

impl HeatmapFigure<'_> {
    /// Draws the figure.
    ///
    /// # Panics
    ///
    /// If `values.len()` is not `width * height`.
    pub fn render(&self) -> RgbImage {
        let scale = self
            .pixel_scale
            .unwrap_or_else(|| auto_scale(self.width, self.height));
        let grid = heatmap_image(
            self.values,
            self.width,
            self.height,
            scale,
            self.colour_scale,
            self.colormap,
        );
        let layout = self.layout(grid.width(), grid.height());
        let mut canvas = Canvas::new(layout.width, layout.height, WHITE);

        let centre_x = layout.width as f32 / 2.0;
        canvas.text(
            centre_x,
            PAD,
            self.title,
            TITLE_SIZE,
            TEXT,
            Anchor::TOP_CENTRE,
        );

        let (x, y) = (layout.image_x, layout.top);
        canvas.draw_rgb_image(&grid, x as i32, y as i32, 1);
        outline(&mut canvas, x, y, grid.width(), grid.height());
        self.draw_colour_bar(&mut canvas, &layout);

        let caption_h = line_metrics(CAPTION_SIZE).line_height();
        for (i, line) in layout.caption.iter().enumerate() {
            let line_y = layout.caption_top + caption_h * i as f32;
            canvas.text(
                PAD,
                line_y,
                line,
                CAPTION_SIZE,
                TEXT_MUTED,
                Anchor::TOP_LEFT,
            );
        }
        canvas.to_rgb_image()
    }

    /// Sizes and positions of every part, worked out before drawing so that
    /// the canvas can be made exactly big enough.
    fn layout(&self, image_w: u32, image_h: u32) -> HeatmapLayout {
        let ticks = self.colour_scale.ticks(image_h as f32);
        let widest_tick = ticks
            .labels
            .iter()
            .map(|label| text_width(label, TICK_SIZE))
            .fold(0.0, f32::max);
        let label_h = line_metrics(LABEL_SIZE).line_height();
        // Image, gap, bar, tick, gap, tick labels, gap, rotated label.
        let content_w = image_w
            + BAR_GAP
            + BAR_WIDTH
            + (TICK_LENGTH + 4.0 + widest_tick + 10.0 + label_h).ceil() as u32;
        let title_w = text_width(self.title, TITLE_SIZE).ceil() as u32;
        let width = content_w.max(title_w) + 2 * PAD as u32;
        // Centre the image-and-bar block when the title makes the figure wider.
        let image_x = (width - content_w) / 2;

        let title_h = line_metrics(TITLE_SIZE).line_height();
        let top = (PAD + title_h + 10.0).round() as u32;
        let caption = wrap_text(self.caption, CAPTION_SIZE, width as f32 - 2.0 * PAD);
        let caption_top = (top + image_h) as f32 + 12.0;
        let caption_h = line_metrics(CAPTION_SIZE).line_height() * caption.len() as f32;
        let height = (caption_top + caption_h + PAD).ceil() as u32;
        HeatmapLayout {
            width,
            height,
            image_x,
            top,
            image_h,
            bar_x: image_x + image_w + BAR_GAP,
            ticks,
            caption,
            caption_top,
        }
    }

    /// A strip of the colormap, high values at the top, with ticks, their
    /// labels and the rotated bar label to its right. On a steps scale the
    /// strip is a stack of blocks, one per number, each labelled at its
    /// middle: a legend.
    fn draw_colour_bar(&self, canvas: &mut Canvas, layout: &HeatmapLayout) {
        let (x, top, h) = (layout.bar_x, layout.top, layout.image_h);
        let scale = self.colour_scale;
        let count = scale.step_count() as f32;
        // One row at a time: row 0 is the top (t = 1), the last row t = 0.
        let last = h.saturating_sub(1).max(1) as f32;
        for row in 0..h {
            let t = 1.0 - row as f32 / last;
            let colour = if scale.steps {
                let from_bottom = (h - 1 - row) as f32 * count / h as f32;
                scale.colour(scale.min + from_bottom.floor(), self.colormap)
            } else {
                self.colormap.sample(t)
            };
            canvas.fill_rect(x as f32, (top + row) as f32, BAR_WIDTH as f32, 1.0, colour);
        }
        if scale.steps {
            // A white line between blocks, so that pale neighbours stay apart.
            for step in 1..scale.step_count() {
                let y = top as f32 + h as f32 * (1.0 - step as f32 / count);
                canvas.fill_rect(x as f32, y.round() - 0.5, BAR_WIDTH as f32, 1.0, WHITE);
            }
        }
        outline(canvas, x, top, BAR_WIDTH, h);

        let bar_right = (x + BAR_WIDTH) as f32;
        let label_x = bar_right + TICK_LENGTH + 4.0;
        for (value, label) in layout.ticks.values.iter().zip(&layout.ticks.labels) {
            let y = if scale.steps {
                // The middle of the value's block.
                let from_bottom = (*value as f32 - scale.min + 0.5) / count;
                top as f32 + (1.0 - from_bottom) * h as f32
            } else {
                // The centre of the row whose colour is this value's colour.
                let t = scale.normalise(*value as f32);
                top as f32 + (1.0 - t) * last + 0.5
            };
            canvas.stroke_line(bar_right, y, bar_right + TICK_LENGTH, y, TEXT, 1.0);
            canvas.text(label_x, y, label, TICK_SIZE, TEXT, Anchor::MIDDLE_LEFT);
        }

        let widest = layout
            .ticks
            .labels
            .iter()
            .map(|label| text_width(label, TICK_SIZE))
            .fold(0.0, f32::max);
        let middle = top as f32 + h as f32 / 2.0;
        let text_x = label_x + widest + 10.0;
        let label = self.colour_bar_label;
        canvas.text_vertical(text_x, middle, label, LABEL_SIZE, TEXT, Anchor::TOP_CENTRE);
    }
}

struct HeatmapLayout {
    width: u32,
    height: u32,
    image_x: u32,
    top: u32,
    image_h: u32,
    bar_x: u32,
    ticks: Ticks,
    caption: Vec<String>,
    caption_top: f32,
}

/// The largest whole scale that keeps the longer side near 480 pixels
/// (at least 1, so big grids are shown one cell per pixel).
fn auto_scale(width: usize, height: usize) -> u32 {
    (TARGET_SIDE / width.max(height).max(1)).max(1) as u32
}

/// A 1 px frame just outside a `w` × `h` block at `(x, y)`, so that pale
/// colours do not melt into the white page.
fn outline(canvas: &mut Canvas, x: u32, y: u32, w: u32, h: u32) {
    let (x, y) = (x as f32 - 0.5, y as f32 - 0.5);
    canvas.stroke_rect(x, y, w as f32 + 1.0, h as f32 + 1.0, FRAME, 1.0);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::colormap::viridis;

    /// Bounce counts 1..=10 rising left to right.
    fn ramp(width: usize, height: usize) -> Vec<f32> {
        (0..height)
            .flat_map(|_| (0..width).map(move |x| 1.0 + (9 * x / (width - 1)) as f32))
            .collect()
    }

    fn figure(values: &[f32]) -> HeatmapFigure<'_> {
        HeatmapFigure {
            title: "Bounces per pixel",
            caption: "Each pixel is coloured by how many times its ray bounced before \
                      leaving the scene or reaching the depth limit of ten; the long \
                      caption wraps onto several lines.",
            values,
            width: 40,
            height: 30,
            colour_scale: ColourScale::linear(1.0, 10.0),
            colour_bar_label: "bounces",
            colormap: Colormap::Viridis,
            pixel_scale: None,
        }
    }

    #[test]
    fn normalise_linear_log_and_nan() {
        let linear = ColourScale::linear(1.0, 10.0);
        assert_eq!(linear.normalise(1.0), 0.0);
        assert_eq!(linear.normalise(10.0), 1.0);
        assert_eq!(linear.normalise(5.5), 0.5);
        assert_eq!(linear.normalise(99.0), 1.0);
        assert!(linear.normalise(f32::NAN).is_nan());
        let log = ColourScale::log(1.0, 100.0);
        assert!((log.normalise(10.0) - 0.5).abs() < 1e-6);
        assert_eq!(log.normalise(0.0), 0.0);
        assert_eq!(ColourScale::linear(3.0, 3.0).normalise(3.0), 0.0);
    }

    #[test]
    fn heatmap_image_scales_cells_and_keeps_row_zero_on_top() {
        let values = [0.0, 1.0, 1.0, 0.0]; // 2 × 2: dark, bright / bright, dark
        let image = heatmap_image(
            &values,
            2,
            2,
            3,
            ColourScale::linear(0.0, 1.0),
            Colormap::Viridis,
        );
        assert_eq!(image.dimensions(), (6, 6));
        assert_eq!(image.get_pixel(0, 0).0, viridis(0.0));
        assert_eq!(image.get_pixel(5, 0).0, viridis(1.0));
        assert_eq!(image.get_pixel(0, 5).0, viridis(1.0));
        assert_eq!(image.get_pixel(2, 2).0, viridis(0.0));
    }

    #[test]
    #[should_panic(expected = "grid needs 6 values")]
    fn heatmap_image_rejects_a_wrong_value_count() {
        heatmap_image(
            &[0.0; 5],
            3,
            2,
            1,
            ColourScale::linear(0.0, 1.0),
            Colormap::Magma,
        );
    }

    #[test]
    fn figure_has_the_laid_out_size_and_contains_the_grid() {
        let values = ramp(40, 30);
        let fig = figure(&values);
        let image = fig.render();
        let scale = auto_scale(40, 30);
        assert_eq!(scale, 12);
        let layout = fig.layout(40 * scale, 30 * scale);
        assert_eq!(image.dimensions(), (layout.width, layout.height));
        assert!(layout.caption.len() >= 2, "the long caption wraps");
        // The grid is drawn unchanged at its place: first cell is value 1.
        let corner = image.get_pixel(layout.image_x + 1, layout.top + 1).0;
        assert_eq!(corner, viridis(0.0));
        let far = image
            .get_pixel(layout.image_x + 40 * scale - 2, layout.top + 1)
            .0;
        assert_eq!(far, viridis(1.0));
    }

    #[test]
    fn colour_bar_runs_from_top_colour_to_bottom_colour() {
        let values = ramp(40, 30);
        let fig = figure(&values);
        let image = fig.render();
        let layout = fig.layout(480, 360);
        let middle_x = layout.bar_x + BAR_WIDTH / 2;
        let top = image.get_pixel(middle_x, layout.top).0;
        let bottom = image.get_pixel(middle_x, layout.top + layout.image_h - 1).0;
        assert_eq!(top, viridis(1.0));
        assert_eq!(bottom, viridis(0.0));
    }

    #[test]
    fn colour_bar_ticks_are_integers_for_counts_and_decades_for_log() {
        let counts = ColourScale::linear(1.0, 10.0).ticks(480.0);
        assert_eq!(
            counts.labels,
            ["1", "2", "3", "4", "5", "6", "7", "8", "9", "10"]
        );
        // 120 px for three decades: too short for 1, 2, 5 in each.
        let log = ColourScale::log(1.0, 1000.0).ticks(120.0);
        assert_eq!(log.labels, ["1", "10", "100", "1000"]);
        let fractions = ColourScale::linear(0.0, 0.5).ticks(230.0);
        assert_eq!(fractions.labels.first().map(String::as_str), Some("0.0"));
    }

    #[test]
    fn a_tall_log_colour_bar_labels_two_three_four_and_five() {
        // 600 px over three decades: 4 and 5 are 19 px apart, room enough.
        let tall = ColourScale::log(1.0, 1000.0).ticks(600.0);
        assert_eq!(&tall.labels[..6], ["1", "2", "3", "4", "5", "10"]);
        assert_eq!(tall.labels.last().map(String::as_str), Some("1000"));
        // 300 px: 4 and 5 would be 10 px apart, so only 1, 2 and 5.
        let short = ColourScale::log(1.0, 1000.0).ticks(300.0);
        assert_eq!(&short.labels[..4], ["1", "2", "5", "10"]);
    }

    #[test]
    fn a_steps_scale_gives_each_whole_number_its_own_colour_and_legend_entry() {
        let depth = ColourScale::steps(1, 10);
        assert_eq!(depth.colour(1.0, Colormap::Distinct), [222, 222, 222]);
        assert_eq!(depth.colour(2.0, Colormap::Distinct), [31, 119, 180]);
        assert_eq!(depth.colour(10.0, Colormap::Distinct), [30, 30, 30]);
        assert_eq!(depth.colour(12.0, Colormap::Distinct), [30, 30, 30]);
        assert_eq!(depth.ticks(60.0).labels.len(), 10, "one entry per depth");
        // Drawn: the bar's bottom block is depth 1, its top block depth 10,
        // and the block in the middle of the bar's lower half is depth 3.
        let values: Vec<f32> = (0..100).map(|i| (1 + i % 10) as f32).collect();
        let mut fig = figure(&values);
        (fig.width, fig.height, fig.pixel_scale) = (10, 10, Some(20));
        fig.colour_scale = depth;
        fig.colormap = Colormap::Distinct;
        let image = fig.render();
        let layout = fig.layout(200, 200);
        let x = layout.bar_x + BAR_WIDTH / 2;
        let block = |depth: u32| image.get_pixel(x, layout.top + 200 - 20 * depth + 10).0;
        assert_eq!(block(1), [222, 222, 222]);
        assert_eq!(block(3), [255, 127, 14]);
        assert_eq!(block(10), [30, 30, 30]);
        // And the grid's second cell is depth 2's blue.
        let cell = image.get_pixel(layout.image_x + 30, layout.top + 10).0;
        assert_eq!(cell, [31, 119, 180]);
    }

    #[test]
    fn a_long_title_widens_the_figure() {
        let values = vec![0.5; 4];
        let mut fig = figure(&values);
        fig.width = 2;
        fig.height = 2;
        fig.pixel_scale = Some(10);
        fig.title = "A title much longer than a twenty-pixel heatmap and its colour bar";
        let image = fig.render();
        assert!(image.width() as f32 >= text_width(fig.title, TITLE_SIZE) + 2.0 * PAD);
    }
}
