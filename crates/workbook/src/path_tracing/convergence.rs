//! Chapter 6's figures, 6: how the noise falls with the paths per pixel.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use image::RgbImage;
use raylab_plot::colour::{WHITE, series_colour};
use raylab_plot::{Anchor, Canvas, Corner, LinePlot, Series, montage};

use super::{COUNTS, REFERENCE_SPP, magnified_crop, path_render, save_all, size_flags, with};
use crate::measure::{mean_variance, rmse};
use crate::{JobError, Size};

/// One measured count: its RMSE against the reference, and the RMSE its own
/// variance estimate predicts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergencePoint {
    pub spp: u32,
    pub rmse: f64,
    /// `sqrt(measured² − the reference's own variance)`: the error against
    /// the true image, as far as the reference can tell.
    pub corrected: f64,
    /// `sqrt(mean variance of the mean)` from the render's own samples
    /// (`None` with one sample per pixel, where it is unknown).
    pub predicted: Option<f64>,
}

/// The convergence image size: a tenth of the job's each way.
fn convergence_size(size: Size) -> (u32, u32) {
    ((size.width / 10).max(8), (size.height / 10).max(6))
}

pub(super) fn convergence_figures(
    dir: &Path,
    size: Size,
    quiet: bool,
) -> Result<Vec<PathBuf>, JobError> {
    let (w, h) = convergence_size(size);
    let reference = path_render(&with(size_flags(w, h, REFERENCE_SPP), &["--seed=1"]), quiet)?;
    let reference_variance = mean_variance(&reference.variance);
    let mut points = Vec::new();
    let mut noise: Vec<(u32, RgbImage)> = Vec::new();
    for spp in COUNTS {
        let render = path_render(&with(size_flags(w, h, spp), &["--seed=0"]), true)?;
        let measured = rmse(&render.image, &reference.image);
        points.push(ConvergencePoint {
            spp,
            rmse: measured,
            corrected: (measured * measured - reference_variance).max(0.0).sqrt(),
            predicted: (spp > 1).then(|| mean_variance(&render.variance).sqrt()),
        });
        if [1, 16, 256].contains(&spp) {
            noise.push((spp, render.image.to_srgb8()));
        }
    }
    noise.push((REFERENCE_SPP, reference.image.to_srgb8()));
    let scale = (240 / w).max(1);
    let magnified: Vec<(String, RgbImage)> = noise
        .into_iter()
        .map(|(spp, image)| {
            let label = match spp {
                REFERENCE_SPP => format!("{spp} (the reference, seed 1)"),
                1 => "1 path per pixel".to_owned(),
                _ => format!("{spp} paths per pixel"),
            };
            (label, magnified_crop(&image, (0.0, 0.0), (w, h), scale))
        })
        .collect();
    let refs: Vec<(&str, &RgbImage)> = magnified.iter().map(|(l, i)| (l.as_str(), i)).collect();
    let crops = montage(
        &format!("The noise: the whole {w}×{h} image, magnified ×{scale}"),
        &refs,
        4,
    );
    let csv = convergence_csv(&points);
    let table = convergence_markdown(&points, (w, h), reference_variance.sqrt());
    let plot = convergence_plot(&points, (w, h), reference_variance.sqrt());
    save_all(
        dir,
        &[("convergence.png", &plot), ("noise.png", &crops)],
        &[("convergence.csv", &csv), ("convergence.md", &table)],
    )
}

/// Two panels. Above, the error as measured on log–log axes with the
/// 1/√N line and the reference's own noise as a dashed floor. Below, the
/// series the page reads, each times √N, where 1/√N is a flat line: the
/// error as measured, the error without the reference's noise, and what
/// the render's own variance predicts.
fn convergence_plot(points: &[ConvergencePoint], (w, h): (u32, u32), floor: f64) -> RgbImage {
    let start = points[0].corrected;
    let guide: Vec<(f64, f64)> = COUNTS
        .iter()
        .map(|&n| (f64::from(n), start / f64::from(n).sqrt()))
        .collect();
    let series = |f: fn(&ConvergencePoint) -> Option<f64>| -> Vec<(f64, f64)> {
        points
            .iter()
            .filter_map(|p| f(p).map(|v| (f64::from(p.spp), v.max(1e-6))))
            .collect()
    };
    let times_root_n = |f: fn(&ConvergencePoint) -> Option<f64>| -> Vec<(f64, f64)> {
        series(f)
            .into_iter()
            .map(|(n, v)| (n, v * n.sqrt()))
            .collect()
    };
    let last = f64::from(COUNTS[COUNTS.len() - 1]);
    let error = LinePlot::new("The error, as measured")
        .x_label("paths per pixel N (log scale)")
        .y_label("RMSE, linear radiance")
        .log_x()
        .x_range(1.0, last)
        .log_y(1e-3)
        .legend(Corner::TopRight)
        .series(Series::new(
            "measured against the reference",
            series_colour(0),
            series(|p| Some(p.rmse)),
        ))
        .series(Series::new("1/√N from N = 1", [150, 150, 150], guide).without_markers());
    let highest = times_root_n(|p| Some(p.rmse))
        .iter()
        .map(|p| p.1)
        .fold(start, f64::max);
    let flat = LinePlot::new("The same times √N: flat where the error falls as 1/√N")
        .x_label("paths per pixel N (log scale)")
        .y_label("RMSE × √N")
        .log_x()
        .x_range(1.0, last)
        .y_range(0.0, highest * 1.25)
        .legend(Corner::BottomLeft)
        .series(Series::new(
            "measured against the reference",
            series_colour(0),
            times_root_n(|p| Some(p.rmse)),
        ))
        .series(Series::new(
            "without the reference's own noise",
            series_colour(2),
            times_root_n(|p| Some(p.corrected)),
        ))
        .series(Series::new(
            "predicted by the render's own variance",
            series_colour(1),
            times_root_n(|p| p.predicted),
        ));
    let (width, panel_h, title_h) = (820u32, 420u32, 44u32);
    let mut top = error.render_canvas(width, panel_h);
    let from = error.data_to_pixel(width, panel_h, 1.0, floor);
    let to = error.data_to_pixel(width, panel_h, last, floor);
    top.dashed_line(from, to, [85, 85, 85], 1.5, 6.0, 4.0);
    // Under the line at its left end, far below the error at few paths.
    top.text(
        from.0 + 8.0,
        from.1 + 5.0,
        &format!("the reference's own noise, {floor:.4}"),
        13.0,
        [85, 85, 85],
        Anchor::TOP_LEFT,
    );
    let mut canvas = Canvas::new(width, title_h + 2 * panel_h, WHITE);
    canvas.text(
        width as f32 / 2.0,
        14.0,
        &format!("Chapter 6's error against a {REFERENCE_SPP}-path render, {w}×{h}"),
        20.0,
        raylab_plot::colour::TEXT,
        Anchor::TOP_CENTRE,
    );
    canvas.draw_rgb_image(&top.to_rgb_image(), 0, title_h as i32, 1);
    canvas.draw_rgb_image(
        &flat.render(width, panel_h),
        0,
        (title_h + panel_h) as i32,
        1,
    );
    canvas.to_rgb_image()
}

fn convergence_csv(points: &[ConvergencePoint]) -> String {
    let mut text = String::from("spp,rmse,rmse_corrected,rmse_predicted\n");
    for p in points {
        let _ = writeln!(
            text,
            "{},{:.6},{:.6},{}",
            p.spp,
            p.rmse,
            p.corrected,
            p.predicted.map_or(String::new(), |v| format!("{v:.6}"))
        );
    }
    text
}

/// The slope of log RMSE against log N between the first and last points.
pub fn log_log_slope(points: &[(f64, f64)]) -> f64 {
    let (first, last) = (points[0], points[points.len() - 1]);
    (last.1.ln() - first.1.ln()) / (last.0.ln() - first.0.ln())
}

fn convergence_markdown(points: &[ConvergencePoint], (w, h): (u32, u32), floor: f64) -> String {
    let mut text = String::from(
        "| paths per pixel | RMSE | without the reference's noise | predicted by its own variance | \
         RMSE × √N |\n|---:|---:|---:|---:|---:|\n",
    );
    for p in points {
        let _ = writeln!(
            text,
            "| {} | {:.4} | {:.4} | {} | {:.3} |",
            p.spp,
            p.rmse,
            p.corrected,
            p.predicted.map_or("—".to_owned(), |v| format!("{v:.4}")),
            p.rmse * f64::from(p.spp).sqrt()
        );
    }
    let measured: Vec<(f64, f64)> = points
        .iter()
        .map(|p| (f64::from(p.spp), p.corrected.max(1e-9)))
        .collect();
    let _ = writeln!(
        text,
        "\nRMSE over every channel of every pixel of the {w}×{h} image, in linear radiance, \
         against a {REFERENCE_SPP}-path render with another seed (seed 1; these use seed 0). \
         The reference's own noise, from its variance, is {floor:.4}; without it, the error \
         falls with a log–log slope of {:.2} from 1 to {} paths (−0.5 is 1/√N).",
        log_log_slope(&measured),
        COUNTS[COUNTS.len() - 1]
    );
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_over_root_n_has_a_log_log_slope_of_minus_a_half() {
        let points: Vec<(f64, f64)> = [1.0, 4.0, 16.0, 64.0]
            .iter()
            .map(|&n: &f64| (n, 0.3 / n.sqrt()))
            .collect();
        assert!((log_log_slope(&points) + 0.5).abs() < 1e-12);
    }
}
