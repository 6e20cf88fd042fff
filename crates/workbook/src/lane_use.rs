//! Chapter 8's figure: how many of the eight lanes each step of a bounce
//! runs for, measured on chapter 8's own render of the lab scene.

use std::path::{Path, PathBuf};

use ch06_path_tracing::run;
use ch08_eight_paths::lane_use::{LaneUse, Stage};
use image::RgbImage;
use raylab_cli::CliError;
use raylab_cli::output::{save_png, save_text};
use raylab_plot::colour::{FRAME, TEXT, TEXT_MUTED, WHITE, series_colour};
use raylab_plot::{Anchor, Canvas, HAlign, VAlign};

use crate::{JobError, Size};

/// The render measured: chapter 6's defaults at a quarter of the size each
/// way, and 16 paths per pixel (the share hardly moves with either).
fn flags(size: Size) -> Vec<String> {
    vec![
        format!("--width={}", (size.width / 4).max(8)),
        format!("--height={}", (size.height / 4).max(8)),
        "--spp=16".to_owned(),
    ]
}

/// `lane-use.png` and its caption's numbers, `lane-use.md`, into `dir`.
pub fn make_figure(dir: &Path, size: Size) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let program = &ch08_eight_paths::PROGRAM.program;
    let args = std::iter::once(program.binary.to_owned()).chain(flags(size));
    let (options, chapter_flags) =
        run::parse(program, args).map_err(|e| CliError::Usage(e.to_string()))?;
    let settings = run::settings(&options, &chapter_flags)?;
    let (scene, camera) = options.load_scene()?;
    let used = ch08_eight_paths::lane_use(&scene, &camera, &settings);
    let figure = dir.join("lane-use.png");
    save_png(&lane_use_figure(&used, &settings.to_string()), &figure)?;
    let caption = dir.join("lane-use.md");
    save_text(&caption_text(&used), &caption)?;
    Ok(vec![figure, caption])
}

/// One bar per step: the share of the eight lanes busy when it ran.
pub fn lane_use_figure(used: &LaneUse, what: &str) -> RgbImage {
    let (width, row) = (900.0, 46.0);
    let stages: Vec<Stage> = Stage::ALL
        .into_iter()
        .filter(|&s| used.runs(s) > 0)
        .collect();
    let height = 110.0 + row * stages.len() as f32;
    let mut canvas = Canvas::new(width as u32, height as u32, WHITE);
    let title = "When a step runs, how many of the eight lanes it runs for";
    canvas.text(width / 2.0, 14.0, title, 20.0, TEXT, Anchor::TOP_CENTRE);
    canvas.text(
        width / 2.0,
        42.0,
        what,
        14.0,
        TEXT_MUTED,
        Anchor::TOP_CENTRE,
    );
    let (left, bar_width) = (250.0, width - 250.0 - 110.0);
    let middle = Anchor::new(HAlign::Right, VAlign::Middle);
    for (i, &stage) in stages.iter().enumerate() {
        let y = 80.0 + row * i as f32;
        let share = used.share(stage) as f32;
        canvas.text(
            left - 12.0,
            y + row / 2.0 - 4.0,
            stage.name(),
            15.0,
            TEXT,
            middle,
        );
        canvas.stroke_rect(left, y, bar_width, row - 14.0, FRAME, 1.0);
        canvas.fill_rect(left, y, bar_width * share, row - 14.0, series_colour(i));
        let label = format!("{:.1} of 8 lanes", share * 8.0);
        let at = Anchor::new(HAlign::Left, VAlign::Middle);
        let x = left + bar_width + 10.0;
        canvas.text(x, y + row / 2.0 - 4.0, &label, 14.0, TEXT, at);
    }
    canvas.to_rgb_image()
}

/// The numbers the page's sentence about the figure needs.
pub fn caption_text(used: &LaneUse) -> String {
    let lanes = |stage| used.share(stage) * 8.0;
    format!(
        "The nearest hit runs for {:.1} of the eight lanes on average, the matte \
         surfaces' step for {:.1} and the mirror and glass for {:.1}.\n",
        lanes(Stage::Trace),
        lanes(Stage::Diffuse),
        lanes(Stage::Specular),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lane_figure_has_a_bar_per_step_that_ran_and_the_caption_its_numbers() {
        let dir = tempfile::tempdir().unwrap();
        let size = Size {
            width: 64,
            height: 48,
        };
        let written = make_figure(dir.path(), size).unwrap();
        assert_eq!(written.len(), 2);
        let figure = image::open(&written[0]).unwrap();
        assert_eq!(figure.width(), 900);
        let caption = std::fs::read_to_string(&written[1]).unwrap();
        assert!(
            caption.starts_with("The nearest hit runs for "),
            "{caption}"
        );
    }
}
