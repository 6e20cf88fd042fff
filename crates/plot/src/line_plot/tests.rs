//! The line plot's tests: where data lands, ticks, log axes, the right
//! axis, the legend and the markers' labels.

use super::layout::crisp;
use super::*;
use crate::colour::{AXIS, series_colour};

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
    assert!(distance(pixel_at(&image, between), BLUE) < distance(pixel_at(&image, between), WHITE));
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
