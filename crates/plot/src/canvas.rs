//! A drawing surface: a tiny-skia pixmap with a background colour, plus the
//! handful of shapes the figures need, text, and image blits.
//!
//! Coordinates are in pixels with the origin at the top-left corner and y
//! pointing down. A pixel's centre is at `(x + 0.5, y + 0.5)`, so a 1 px
//! line drawn along `y = 10.5` fills exactly row 10, whereas one along
//! `y = 10.0` is smeared half-and-half over rows 9 and 10.

use image::RgbImage;
use tiny_skia::{
    Color, FillRule, LineCap, LineJoin, Mask, Paint, Path, PathBuilder, Pixmap,
    PremultipliedColorU8, Rect, Stroke, StrokeDash, Transform,
};

use super::colour::Rgb;
use super::text::{self, Anchor};

/// A pixel surface to draw a figure on.
pub struct Canvas {
    pixmap: Pixmap,
    background: Rgb,
    /// When set, shapes only paint inside this mask (text and images ignore it).
    clip: Option<Mask>,
}

impl Canvas {
    /// The largest width or height a canvas can have. Far more than any
    /// figure needs, and well inside tiny-skia's own limits.
    pub const MAX_SIDE: u32 = 16_384;

    /// A `width` × `height` canvas filled with `background`.
    ///
    /// Sizes are clamped to `1..=MAX_SIDE`, so a zero-sized request gives a
    /// 1 × 1 canvas instead of failing.
    pub fn new(width: u32, height: u32, background: Rgb) -> Canvas {
        let width = width.clamp(1, Self::MAX_SIDE);
        let height = height.clamp(1, Self::MAX_SIDE);
        let mut pixmap = Pixmap::new(width, height)
            .expect("a pixmap of 1..=16384 pixels a side is always allowed");
        pixmap.fill(opaque(background));
        Canvas {
            pixmap,
            background,
            clip: None,
        }
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.pixmap.width()
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.pixmap.height()
    }

    /// The colour the canvas was created with.
    pub fn background(&self) -> Rgb {
        self.background
    }

    // ----- clipping --------------------------------------------------------

    /// Restricts later shapes (lines, rectangles, circles, arrows) to the
    /// given rectangle, e.g. so a data line cannot spill out of a plot.
    pub fn set_clip_rect(&mut self, x: f32, y: f32, width: f32, height: f32) {
        let mask = Mask::new(self.width(), self.height()).and_then(|mut mask| {
            let rect = Rect::from_xywh(x, y, width, height)?;
            mask.fill_path(
                &PathBuilder::from_rect(rect),
                FillRule::Winding,
                false,
                Transform::identity(),
            );
            Some(mask)
        });
        // A degenerate rectangle yields no mask; clip to nothing then, by
        // keeping an empty mask, so the caller's intent "draw only in here"
        // still holds.
        self.clip = mask.or_else(|| Mask::new(self.width(), self.height()));
    }

    /// Lets shapes paint anywhere again.
    pub fn clear_clip(&mut self) {
        self.clip = None;
    }

    // ----- shapes ----------------------------------------------------------

    /// Fills an axis-aligned rectangle.
    pub fn fill_rect(&mut self, x: f32, y: f32, width: f32, height: f32, colour: Rgb) {
        self.fill_rect_translucent(x, y, width, height, colour, 1.0);
    }

    /// Fills a rectangle that lets `1 - opacity` of what is underneath show
    /// through; used behind labels that sit on top of data.
    pub fn fill_rect_translucent(
        &mut self,
        x: f32,
        y: f32,
        width: f32,
        height: f32,
        colour: Rgb,
        opacity: f32,
    ) {
        let Some(rect) = Rect::from_xywh(x, y, width, height) else {
            return; // zero or negative size: nothing to fill
        };
        let mut paint = paint(colour);
        paint.set_color(with_opacity(colour, opacity));
        self.pixmap
            .fill_rect(rect, &paint, Transform::identity(), self.clip.as_ref());
    }

    /// Outlines a rectangle with a line `line_width` pixels wide centred on
    /// its edges.
    pub fn stroke_rect(
        &mut self,
        x: f32,
        y: f32,
        width: f32,
        height: f32,
        colour: Rgb,
        line_width: f32,
    ) {
        if let Some(rect) = Rect::from_xywh(x, y, width, height) {
            let path = PathBuilder::from_rect(rect);
            self.stroke_path(&path, colour, plain_stroke(line_width));
        }
    }

    /// A straight line with square-cut ends.
    pub fn stroke_line(&mut self, x0: f32, y0: f32, x1: f32, y1: f32, colour: Rgb, width: f32) {
        if let Some(path) = line_path(&[(x0, y0), (x1, y1)]) {
            self.stroke_path(&path, colour, plain_stroke(width));
        }
    }

    /// A dashed straight line: `dash` pixels drawn, then `gap` pixels skipped.
    pub fn dashed_line(
        &mut self,
        from: (f32, f32),
        to: (f32, f32),
        colour: Rgb,
        width: f32,
        dash: f32,
        gap: f32,
    ) {
        let Some(path) = line_path(&[from, to]) else {
            return;
        };
        let mut style = plain_stroke(width);
        // StrokeDash rejects non-positive lengths; fall back to a solid line.
        style.dash = StrokeDash::new(vec![dash, gap], 0.0);
        self.stroke_path(&path, colour, style);
    }

    /// Joins `points` with straight segments, rounding the corners so that
    /// sharp turns in data do not produce spiky mitre joins.
    pub fn polyline(&mut self, points: &[(f32, f32)], colour: Rgb, width: f32) {
        if let Some(path) = line_path(points) {
            let mut style = plain_stroke(width);
            style.line_join = LineJoin::Round;
            style.line_cap = LineCap::Round;
            self.stroke_path(&path, colour, style);
        }
    }

    /// An arrow from `from` to `to`: a shaft plus a filled triangular head
    /// `head_size` pixels long whose tip is exactly at `to`.
    pub fn arrow(
        &mut self,
        from: (f32, f32),
        to: (f32, f32),
        colour: Rgb,
        width: f32,
        head_size: f32,
    ) {
        let (dx, dy) = (to.0 - from.0, to.1 - from.1);
        let length = (dx * dx + dy * dy).sqrt();
        if length == 0.0 {
            return; // no direction to point in
        }
        let (ux, uy) = (dx / length, dy / length); // unit vector along the arrow
        let head = head_size.min(length);
        // The shaft stops inside the head so its square end cannot poke
        // out past the sides of the triangle.
        let base = (to.0 - ux * head, to.1 - uy * head);
        let shaft_end = (to.0 - ux * head * 0.5, to.1 - uy * head * 0.5);
        self.stroke_line(from.0, from.1, shaft_end.0, shaft_end.1, colour, width);

        let half = head * 0.45; // half the width of the head's base
        let (px, py) = (-uy * half, ux * half); // perpendicular to the shaft
        let mut builder = PathBuilder::new();
        builder.move_to(to.0, to.1);
        builder.line_to(base.0 + px, base.1 + py);
        builder.line_to(base.0 - px, base.1 - py);
        builder.close();
        if let Some(path) = builder.finish() {
            self.fill_path(&path, colour);
        }
    }

    /// A circle, filled and/or outlined. `stroke` is `(colour, line width)`.
    pub fn circle(
        &mut self,
        centre: (f32, f32),
        radius: f32,
        fill: Option<Rgb>,
        stroke: Option<(Rgb, f32)>,
    ) {
        let Some(path) = PathBuilder::from_circle(centre.0, centre.1, radius) else {
            return; // zero or negative radius
        };
        if let Some(colour) = fill {
            self.fill_path(&path, colour);
        }
        if let Some((colour, width)) = stroke {
            self.stroke_path(&path, colour, plain_stroke(width));
        }
    }

    fn fill_path(&mut self, path: &Path, colour: Rgb) {
        self.pixmap.fill_path(
            path,
            &paint(colour),
            FillRule::Winding,
            Transform::identity(),
            self.clip.as_ref(),
        );
    }

    fn stroke_path(&mut self, path: &Path, colour: Rgb, style: Stroke) {
        self.pixmap.stroke_path(
            path,
            &paint(colour),
            &style,
            Transform::identity(),
            self.clip.as_ref(),
        );
    }

    // ----- images ----------------------------------------------------------

    /// Copies `image` onto the canvas with its top-left corner at `(x, y)`,
    /// each source pixel becoming a `scale` × `scale` block (nearest
    /// neighbour, so pixels stay sharp squares when enlarged). Parts that
    /// fall outside the canvas are skipped. A scale of 0 is treated as 1.
    pub fn draw_rgb_image(&mut self, image: &RgbImage, x: i32, y: i32, scale: u32) {
        let scale = scale.max(1) as i32;
        let (canvas_w, canvas_h) = (self.width() as i32, self.height() as i32);
        for (sx, sy, pixel) in image.enumerate_pixels() {
            let colour = premultiplied(pixel.0, 1.0);
            let (left, top) = (x + sx as i32 * scale, y + sy as i32 * scale);
            for py in top.max(0)..(top + scale).min(canvas_h) {
                for px in left.max(0)..(left + scale).min(canvas_w) {
                    let index = (py * canvas_w + px) as usize;
                    self.pixmap.pixels_mut()[index] = colour;
                }
            }
        }
    }

    // ----- text ------------------------------------------------------------

    /// Draws one line of text at `(x, y)`, placed according to `anchor`.
    /// `size_px` is the em size in pixels (the CSS meaning of font-size).
    pub fn text(&mut self, x: f32, y: f32, text: &str, size_px: f32, colour: Rgb, anchor: Anchor) {
        let line = text::layout_line(text, size_px);
        let (dx, dy) = text::baseline_offset(line.width, size_px, anchor);
        // Whole-pixel baselines keep repeated labels (tick numbers) looking
        // identical instead of each being blurred differently.
        let origin = ((x + dx).round(), (y + dy).round());
        text::rasterise_line(&line, origin, |px, py, coverage| {
            self.blend_pixel(px, py, colour, coverage);
        });
    }

    /// Draws text turned 90° anticlockwise, reading from bottom to top, as
    /// for a y-axis label. The anchor is understood in the text's own frame:
    /// `HAlign` runs along the text (upwards on screen) and `VAlign::Top`
    /// means the tops of the letters, which face left, touch `x`.
    pub fn text_vertical(
        &mut self,
        x: f32,
        y: f32,
        text: &str,
        size_px: f32,
        colour: Rgb,
        anchor: Anchor,
    ) {
        let line = text::layout_line(text, size_px);
        let (dx, dy) = text::baseline_offset(line.width, size_px, anchor);
        let (ax, ay) = (x.round() as i32, y.round() as i32);
        // Lay the text out horizontally around (0, 0), then turn each pixel
        // (u, v) of that layout into screen pixel (ax + v, ay - 1 - u):
        // "along the text" becomes "up the screen" and "down the text"
        // becomes "right on the screen".
        text::rasterise_line(&line, (dx.round(), dy.round()), |u, v, coverage| {
            self.blend_pixel(ax + v, ay - 1 - u, colour, coverage);
        });
    }

    /// Width of `text` at `size_px`, for laying things out before drawing.
    pub fn text_width(&self, text: &str, size_px: f32) -> f32 {
        text::text_width(text, size_px)
    }

    /// Mixes `colour` into one pixel by `amount` (0 = leave it, 1 = replace).
    /// Pixels outside the canvas are ignored.
    fn blend_pixel(&mut self, x: i32, y: i32, colour: Rgb, amount: f32) {
        let (width, height) = (self.width() as i32, self.height() as i32);
        if x < 0 || y < 0 || x >= width || y >= height {
            return;
        }
        let index = (y * width + x) as usize;
        let under = self.pixmap.pixels()[index];
        // Premultiplied "source over": result = source + under × (1 − amount).
        let keep = 1.0 - amount;
        let mix = |source: u8, below: u8| f32::from(source) * amount + f32::from(below) * keep;
        let alpha = (255.0 * amount + f32::from(under.alpha()) * keep).round();
        let channel = |c: u8, below: u8| mix(c, below).round().min(alpha) as u8;
        self.pixmap.pixels_mut()[index] = PremultipliedColorU8::from_rgba(
            channel(colour[0], under.red()),
            channel(colour[1], under.green()),
            channel(colour[2], under.blue()),
            alpha as u8,
        )
        .expect("colour channels were clamped to the alpha value");
    }

    // ----- output ----------------------------------------------------------

    /// The colour of one pixel after compositing on the background, or
    /// `None` outside the canvas.
    pub fn pixel(&self, x: u32, y: u32) -> Option<Rgb> {
        self.pixmap
            .pixel(x, y)
            .map(|p| over_background(p, self.background))
    }

    /// The finished picture as an RGB image. Any pixel that is not fully
    /// opaque is composited onto the background colour first.
    pub fn to_rgb_image(&self) -> RgbImage {
        let (width, height) = (self.width(), self.height());
        let mut out = RgbImage::new(width, height);
        for (target, source) in out.pixels_mut().zip(self.pixmap.pixels()) {
            target.0 = over_background(*source, self.background);
        }
        out
    }
}

/// A premultiplied pixel laid over an opaque background colour.
fn over_background(pixel: PremultipliedColorU8, background: Rgb) -> Rgb {
    let keep = 1.0 - f32::from(pixel.alpha()) / 255.0;
    let channel = |c: u8, b: u8| (f32::from(c) + f32::from(b) * keep).round().min(255.0) as u8;
    [
        channel(pixel.red(), background[0]),
        channel(pixel.green(), background[1]),
        channel(pixel.blue(), background[2]),
    ]
}

fn opaque(colour: Rgb) -> Color {
    Color::from_rgba8(colour[0], colour[1], colour[2], 255)
}

fn with_opacity(colour: Rgb, opacity: f32) -> Color {
    let alpha = (opacity.clamp(0.0, 1.0) * 255.0).round() as u8;
    Color::from_rgba8(colour[0], colour[1], colour[2], alpha)
}

fn premultiplied(colour: Rgb, opacity: f32) -> PremultipliedColorU8 {
    with_opacity(colour, opacity).premultiply().to_color_u8()
}

/// An anti-aliased solid paint.
fn paint(colour: Rgb) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color(opaque(colour));
    paint.anti_alias = true;
    paint
}

/// A plain stroke of the given width with butt caps and mitre joins.
fn plain_stroke(width: f32) -> Stroke {
    Stroke {
        width,
        ..Stroke::default()
    }
}

/// An open path through `points`, or `None` if there are fewer than two.
fn line_path(points: &[(f32, f32)]) -> Option<Path> {
    let (first, rest) = points.split_first()?;
    if rest.is_empty() {
        return None;
    }
    let mut builder = PathBuilder::new();
    builder.move_to(first.0, first.1);
    for point in rest {
        builder.line_to(point.0, point.1);
    }
    builder.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::colour::{BLACK, TEXT, WHITE};

    const RED: Rgb = [220, 30, 30];

    /// Pixels in the rectangle that differ from the background.
    fn inked(canvas: &Canvas, x0: u32, y0: u32, x1: u32, y1: u32) -> usize {
        let background = canvas.background();
        (y0..y1)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .filter(|&(x, y)| canvas.pixel(x, y).is_some_and(|p| p != background))
            .count()
    }

    #[test]
    fn new_canvas_is_background_and_zero_size_is_clamped() {
        let canvas = Canvas::new(4, 3, [10, 20, 30]);
        let image = canvas.to_rgb_image();
        assert_eq!(image.dimensions(), (4, 3));
        assert!(image.pixels().all(|p| p.0 == [10, 20, 30]));
        assert_eq!(Canvas::new(0, 0, WHITE).width(), 1);
    }

    #[test]
    fn fill_rect_paints_exactly_its_pixels() {
        let mut canvas = Canvas::new(10, 10, WHITE);
        canvas.fill_rect(2.0, 3.0, 4.0, 5.0, RED);
        assert_eq!(canvas.pixel(2, 3), Some(RED));
        assert_eq!(canvas.pixel(5, 7), Some(RED));
        assert_eq!(canvas.pixel(6, 7), Some(WHITE));
        assert_eq!(canvas.pixel(2, 8), Some(WHITE));
        assert_eq!(inked(&canvas, 0, 0, 10, 10), 20);
    }

    #[test]
    fn pixel_centred_line_fills_one_row() {
        let mut canvas = Canvas::new(20, 20, WHITE);
        canvas.stroke_line(2.0, 10.5, 18.0, 10.5, BLACK, 1.0);
        assert_eq!(canvas.pixel(10, 10), Some(BLACK));
        assert_eq!(canvas.pixel(10, 9), Some(WHITE));
        assert_eq!(canvas.pixel(10, 11), Some(WHITE));
    }

    #[test]
    fn clip_rect_keeps_shapes_inside() {
        let mut canvas = Canvas::new(20, 20, WHITE);
        canvas.set_clip_rect(5.0, 5.0, 10.0, 10.0);
        canvas.fill_rect(0.0, 0.0, 20.0, 20.0, RED);
        canvas.clear_clip();
        assert_eq!(canvas.pixel(4, 4), Some(WHITE));
        assert_eq!(canvas.pixel(10, 10), Some(RED));
        assert_eq!(inked(&canvas, 0, 0, 20, 20), 100);
    }

    #[test]
    fn arrow_head_is_filled_at_the_tip() {
        let mut canvas = Canvas::new(60, 30, WHITE);
        canvas.arrow((5.0, 15.5), (55.0, 15.5), BLACK, 1.0, 12.0);
        // Inside the head, a few pixels off the shaft's row, is solid ink.
        assert_eq!(canvas.pixel(46, 17), Some(BLACK));
        // Along the shaft.
        assert_eq!(canvas.pixel(20, 15), Some(BLACK));
        // Beyond the tip: nothing.
        assert_eq!(canvas.pixel(57, 15), Some(WHITE));
    }

    #[test]
    fn circle_fill_and_outline() {
        let mut canvas = Canvas::new(40, 40, WHITE);
        canvas.circle((20.0, 20.0), 10.0, Some(RED), Some((BLACK, 2.0)));
        assert_eq!(canvas.pixel(20, 20), Some(RED));
        assert_eq!(canvas.pixel(20, 10), Some(BLACK), "top of the outline");
        assert_eq!(canvas.pixel(2, 2), Some(WHITE));
    }

    #[test]
    fn draw_rgb_image_scales_by_whole_pixels_and_clips() {
        let mut image = RgbImage::new(2, 1);
        image.put_pixel(0, 0, image::Rgb(RED));
        image.put_pixel(1, 0, image::Rgb(BLACK));
        let mut canvas = Canvas::new(10, 10, WHITE);
        canvas.draw_rgb_image(&image, 1, 1, 3);
        assert_eq!(canvas.pixel(1, 1), Some(RED));
        assert_eq!(canvas.pixel(3, 3), Some(RED));
        assert_eq!(canvas.pixel(4, 1), Some(BLACK));
        assert_eq!(canvas.pixel(6, 3), Some(BLACK));
        assert_eq!(canvas.pixel(7, 1), Some(WHITE));
        assert_eq!(canvas.pixel(1, 4), Some(WHITE));
        // Partly off the canvas: no panic, the visible part is drawn.
        canvas.draw_rgb_image(&image, 8, -2, 3);
        assert_eq!(canvas.pixel(9, 0), Some(RED));
    }

    #[test]
    fn text_leaves_ink_in_its_box_and_longer_text_leaves_more() {
        let size = 16.0;
        let mut canvas = Canvas::new(400, 40, WHITE);
        canvas.text(10.0, 20.0, "depth", size, TEXT, Anchor::MIDDLE_LEFT);
        let short_ink = inked(&canvas, 0, 0, 400, 40);
        let short_right = rightmost_ink(&canvas);
        assert!(short_ink > 0);

        let mut canvas = Canvas::new(400, 40, WHITE);
        canvas.text(
            10.0,
            20.0,
            "depth of the ray tree",
            size,
            TEXT,
            Anchor::MIDDLE_LEFT,
        );
        let long_width = canvas.text_width("depth of the ray tree", size);
        assert!(inked(&canvas, 0, 0, 400, 40) > short_ink);
        assert!(rightmost_ink(&canvas) > short_right + 50);
        // All ink lies within the measured line box (plus a pixel of slack).
        let metrics = text::line_metrics(size);
        let top = (20.0 + metrics.cap_height / 2.0 - metrics.ascent).floor() as u32;
        let bottom = (20.0 + metrics.cap_height / 2.0 + metrics.descent).ceil() as u32 + 1;
        let right = (10.0 + long_width).ceil() as u32 + 1;
        assert_eq!(
            inked(&canvas, 9, top, right, bottom),
            inked(&canvas, 0, 0, 400, 40)
        );
    }

    fn rightmost_ink(canvas: &Canvas) -> u32 {
        (0..canvas.width())
            .rev()
            .find(|&x| (0..canvas.height()).any(|y| canvas.pixel(x, y) != Some(WHITE)))
            .unwrap_or(0)
    }

    #[test]
    fn vertical_text_is_tall_not_wide() {
        let mut canvas = Canvas::new(60, 200, WHITE);
        canvas.text_vertical(20.0, 100.0, "bounce count", 14.0, TEXT, Anchor::TOP_CENTRE);
        let ink: Vec<(u32, u32)> = (0..60)
            .flat_map(|x| (0..200).map(move |y| (x, y)))
            .filter(|&(x, y)| canvas.pixel(x, y) != Some(WHITE))
            .collect();
        let (min_x, max_x) = (ink.iter().map(|p| p.0).min(), ink.iter().map(|p| p.0).max());
        let (min_y, max_y) = (ink.iter().map(|p| p.1).min(), ink.iter().map(|p| p.1).max());
        let (Some(min_x), Some(max_x), Some(min_y), Some(max_y)) = (min_x, max_x, min_y, max_y)
        else {
            panic!("vertical text drew nothing");
        };
        assert!(max_y - min_y > 3 * (max_x - min_x));
        assert!(min_x >= 20, "the tops of the letters face x = 20");
        // Centred on y = 100.
        assert!(((min_y + max_y) as i32 / 2 - 100).abs() <= 3);
    }
}
