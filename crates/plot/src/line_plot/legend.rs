//! The legend in a corner of the frame, and the vertical markers' labels,
//! placed clear of the legend, of each other and of the lines.

use super::layout::Frame;
use super::{LEGEND_SIZE, LINE_WIDTH, LinePlot, MARKER_RADIUS, Series};
use crate::canvas::Canvas;
use crate::colour::{FRAME, TEXT, WHITE};
use crate::label_box::LabelBox;
use crate::text::{Anchor, line_metrics, text_width};

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

impl LinePlot {
    /// Draws the legend (if any series is named) and returns its box.
    pub(super) fn draw_legend(&self, canvas: &mut Canvas, frame: &Frame) -> Option<LabelBox> {
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
    pub(super) fn draw_marker_labels(
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
