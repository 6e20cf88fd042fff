//! The frame: grid, spines, ticks, tick labels, axis labels and the
//! title, and the right axis when there is one.

use super::layout::{Layout, RightAxis, crisp};
use super::{LABEL_SIZE, LinePlot, PAD, TICK_LENGTH, TICK_SIZE, TITLE_SIZE};
use crate::canvas::Canvas;
use crate::colour::{AXIS, GRID, TEXT};
use crate::text::{Anchor, text_width};

impl LinePlot {
    /// The y label, plus a note on log scaling and on any clamped values.
    pub(super) fn y_label_text(&self) -> String {
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

    pub(super) fn draw_grid(&self, canvas: &mut Canvas, layout: &Layout) {
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

    pub(super) fn draw_labels(&self, canvas: &mut Canvas, layout: &Layout) {
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
}

/// The right axis: its spine, ticks, tick labels and rotated label.
pub(super) fn draw_right_axis(canvas: &mut Canvas, plot: &LinePlot, axis: &RightAxis) {
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
pub(super) fn draw_axes(canvas: &mut Canvas, layout: &Layout) {
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
