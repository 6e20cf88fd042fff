//! Laying out and rasterising single lines of text, plus word wrapping.
//!
//! Text here is deliberately simple: one font, left-to-right, no shaping
//! beyond pair kerning. That covers titles, axis labels and tick numbers.
//! Drawing onto pixels is left to [`super::canvas::Canvas`]; this file only
//! says *where* ink goes and *how much* of each pixel it covers.

use ab_glyph::{Font, GlyphId, ScaleFont, point};

use super::font::face;

/// Horizontal placement of text relative to its anchor point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HAlign {
    /// The text starts at the anchor.
    Left,
    /// The text is centred on the anchor.
    Centre,
    /// The text ends at the anchor.
    Right,
}

/// Vertical placement of text relative to its anchor point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VAlign {
    /// The anchor is the top of the line (the font's ascent), so nothing
    /// of the text pokes above it.
    Top,
    /// The anchor is halfway up the capital letters, which is where the
    /// eye puts the centre of a number: right for tick labels.
    Middle,
    /// The anchor is on the baseline that letters sit on.
    Baseline,
    /// The anchor is the bottom of the line (the font's descent), so
    /// descenders such as "g" and "y" stay above it.
    Bottom,
}

/// Where a piece of text sits relative to the point it is drawn at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Anchor {
    /// Horizontal alignment.
    pub h: HAlign,
    /// Vertical alignment.
    pub v: VAlign,
}

impl Anchor {
    /// Anchor from its two alignments.
    pub const fn new(h: HAlign, v: VAlign) -> Anchor {
        Anchor { h, v }
    }
    /// Top-left corner: the usual anchor for paragraphs.
    pub const TOP_LEFT: Anchor = Anchor::new(HAlign::Left, VAlign::Top);
    /// Top edge, centred: titles and x-axis tick labels.
    pub const TOP_CENTRE: Anchor = Anchor::new(HAlign::Centre, VAlign::Top);
    /// Top-right corner.
    pub const TOP_RIGHT: Anchor = Anchor::new(HAlign::Right, VAlign::Top);
    /// Left end, vertically centred: legend entries.
    pub const MIDDLE_LEFT: Anchor = Anchor::new(HAlign::Left, VAlign::Middle);
    /// Centred both ways.
    pub const MIDDLE_CENTRE: Anchor = Anchor::new(HAlign::Centre, VAlign::Middle);
    /// Right end, vertically centred: y-axis tick labels.
    pub const MIDDLE_RIGHT: Anchor = Anchor::new(HAlign::Right, VAlign::Middle);
    /// Start of the baseline: how typesetters think of text.
    pub const BASELINE_LEFT: Anchor = Anchor::new(HAlign::Left, VAlign::Baseline);
    /// Middle of the baseline.
    pub const BASELINE_CENTRE: Anchor = Anchor::new(HAlign::Centre, VAlign::Baseline);
    /// End of the baseline.
    pub const BASELINE_RIGHT: Anchor = Anchor::new(HAlign::Right, VAlign::Baseline);
    /// Bottom edge, centred.
    pub const BOTTOM_CENTRE: Anchor = Anchor::new(HAlign::Centre, VAlign::Bottom);
}

/// Vertical measurements of the font at one size, in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineMetrics {
    /// Height of the tallest letters above the baseline.
    pub ascent: f32,
    /// Depth of descenders below the baseline (a positive number).
    pub descent: f32,
    /// Height of capital letters and digits above the baseline.
    pub cap_height: f32,
}

impl LineMetrics {
    /// Distance from one baseline to the next for single-spaced lines.
    pub fn line_height(&self) -> f32 {
        self.ascent + self.descent
    }
}

/// The vertical metrics of the font at `size_px` (the em size, as in CSS).
pub fn line_metrics(size_px: f32) -> LineMetrics {
    let face = face();
    let scaled = face.font.as_scaled(face.scale(size_px));
    LineMetrics {
        ascent: scaled.ascent(),
        descent: -scaled.descent(),
        cap_height: face.cap_height_em * size_px,
    }
}

/// One glyph of a laid-out line: which glyph, and how far along the line
/// its pen position is.
#[derive(Clone, Copy, Debug)]
struct PlacedGlyph {
    id: GlyphId,
    x: f32,
}

/// A line of text laid out at one size, ready to measure or rasterise.
#[derive(Clone, Debug)]
pub(crate) struct Line {
    glyphs: Vec<PlacedGlyph>,
    size_px: f32,
    /// Total advance: where the pen ends up after the last glyph.
    pub(crate) width: f32,
}

/// Places each character of `text` along a line starting at 0.
///
/// Each glyph advances the pen by its own width, and neighbouring pairs are
/// nudged by the font's kerning so that "AV" or "To" do not look gappy.
/// Control characters (such as a stray newline) are skipped: this draws a
/// single line, and the font would show them as empty boxes.
pub(crate) fn layout_line(text: &str, size_px: f32) -> Line {
    let face = face();
    let scaled = face.font.as_scaled(face.scale(size_px));
    let px_per_unit = face.px_per_unit(size_px);

    let mut glyphs = Vec::with_capacity(text.len());
    let mut pen = 0.0;
    let mut previous: Option<GlyphId> = None;
    for c in text.chars().filter(|c| !c.is_control()) {
        let id = face.font.glyph_id(c);
        if let Some(previous) = previous {
            pen += face.kerning_units(previous, id) * px_per_unit;
        }
        glyphs.push(PlacedGlyph { id, x: pen });
        pen += scaled.h_advance(id);
        previous = Some(id);
    }
    Line {
        glyphs,
        size_px,
        width: pen,
    }
}

/// Width of `text` at `size_px`: the distance the pen travels, kerning
/// included. This is what alignment uses, so centred text is centred on
/// its advance rather than on its ink.
pub fn text_width(text: &str, size_px: f32) -> f32 {
    layout_line(text, size_px).width
}

/// Where the start of the baseline goes, relative to the anchor point, for
/// text of the given width. Positive y is down, as on screen.
pub(crate) fn baseline_offset(width: f32, size_px: f32, anchor: Anchor) -> (f32, f32) {
    let metrics = line_metrics(size_px);
    let dx = match anchor.h {
        HAlign::Left => 0.0,
        HAlign::Centre => -width / 2.0,
        HAlign::Right => -width,
    };
    let dy = match anchor.v {
        VAlign::Top => metrics.ascent,
        VAlign::Middle => metrics.cap_height / 2.0,
        VAlign::Baseline => 0.0,
        VAlign::Bottom => -metrics.descent,
    };
    (dx, dy)
}

/// Rasterises a laid-out line whose baseline starts at `origin`, calling
/// `plot(x, y, coverage)` for every pixel the glyphs touch.
///
/// `coverage` is the fraction of the pixel inside the glyph outline (0..=1);
/// the caller blends the text colour by that much, which is what makes the
/// edges smooth instead of jagged.
pub(crate) fn rasterise_line(line: &Line, origin: (f32, f32), mut plot: impl FnMut(i32, i32, f32)) {
    let face = face();
    let scale = face.scale(line.size_px);
    for placed in &line.glyphs {
        let position = point(origin.0 + placed.x, origin.1);
        let glyph = placed.id.with_scale_and_position(scale, position);
        // Spaces and other blank glyphs have no outline: nothing to draw.
        let Some(outlined) = face.font.outline_glyph(glyph) else {
            continue;
        };
        let bounds = outlined.px_bounds();
        let (left, top) = (bounds.min.x as i32, bounds.min.y as i32);
        outlined.draw(|gx, gy, coverage| {
            if coverage > 0.0 {
                plot(left + gx as i32, top + gy as i32, coverage.min(1.0));
            }
        });
    }
}

/// Breaks `text` into lines no wider than `max_width` pixels at `size_px`,
/// breaking only at spaces. A single word wider than the limit gets a line
/// of its own rather than being cut.
pub fn wrap_text(text: &str, size_px: f32, max_width: f32) -> Vec<String> {
    let mut lines = Vec::new();
    let mut current = String::new();
    for word in text.split_whitespace() {
        let candidate = if current.is_empty() {
            word.to_string()
        } else {
            format!("{current} {word}")
        };
        if current.is_empty() || text_width(&candidate, size_px) <= max_width {
            current = candidate;
        } else {
            lines.push(std::mem::replace(&mut current, word.to_string()));
        }
    }
    if !current.is_empty() {
        lines.push(current);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn longer_text_is_wider_and_bigger_text_is_wider() {
        let short = text_width("depth", 14.0);
        let long = text_width("maximum depth", 14.0);
        assert!(short > 0.0);
        assert!(long > short);
        assert!(text_width("depth", 28.0) > 1.9 * short);
        assert_eq!(text_width("", 14.0), 0.0);
        assert_eq!(
            text_width("depth\n", 14.0),
            short,
            "control characters are skipped"
        );
    }

    #[test]
    fn kerning_is_applied_during_layout() {
        // Without kerning "AV" would be exactly as wide as "A" plus "V".
        // Noto Sans pulls the pair 40/2048 em closer: about 2 px at 100 px.
        let apart = text_width("A", 100.0) + text_width("V", 100.0);
        assert!(text_width("AV", 100.0) < apart - 1.5);
    }

    #[test]
    fn rasterising_covers_pixels_inside_the_line_box() {
        let size = 20.0;
        let metrics = line_metrics(size);
        let line = layout_line("Hg", size);
        let width = line.width;
        let mut touched = 0;
        rasterise_line(&line, (10.0, 30.0), |x, y, coverage| {
            assert!((0.0..=1.0).contains(&coverage));
            assert!((9..=(11 + width as i32)).contains(&x), "x = {x}");
            let top = (30.0 - metrics.ascent).floor() as i32;
            let bottom = (30.0 + metrics.descent).ceil() as i32;
            assert!((top..=bottom).contains(&y), "y = {y}");
            touched += 1;
        });
        assert!(touched > 50, "only {touched} pixels touched");
    }

    #[test]
    fn anchors_move_the_baseline_as_documented() {
        let m = line_metrics(10.0);
        assert_eq!(
            baseline_offset(40.0, 10.0, Anchor::TOP_LEFT),
            (0.0, m.ascent)
        );
        assert_eq!(
            baseline_offset(40.0, 10.0, Anchor::BASELINE_CENTRE),
            (-20.0, 0.0)
        );
        let (dx, dy) = baseline_offset(40.0, 10.0, Anchor::MIDDLE_RIGHT);
        assert_eq!((dx, dy), (-40.0, m.cap_height / 2.0));
        assert_eq!(
            baseline_offset(0.0, 10.0, Anchor::BOTTOM_CENTRE).1,
            -m.descent
        );
    }

    #[test]
    fn wrapping_respects_the_width_and_keeps_every_word() {
        let caption = "Each pixel shows how many bounces its ray took before it \
                       escaped or hit the depth limit; brighter means more.";
        let lines = wrap_text(caption, 14.0, 200.0);
        assert!(lines.len() > 2);
        for line in &lines {
            assert!(text_width(line, 14.0) <= 200.0, "too wide: {line}");
        }
        assert_eq!(
            lines.join(" "),
            caption.split_whitespace().collect::<Vec<_>>().join(" ")
        );
        assert!(wrap_text("   ", 14.0, 100.0).is_empty());
    }
}
