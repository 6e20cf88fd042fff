//! The overlay, always on: the knobs and their values, the frame time and
//! rays per second, how far the image has refined, the last error; the
//! help on `?`; the clicked pixel's tree as text beside it. Drawn with
//! `raylab-plot`'s text (Noto Sans), the figures' own.

use image::RgbImage;
use raylab_plot::text::text_width;
use raylab_plot::{Anchor, Canvas, Rgb};

use crate::gpu::Outcome;
use crate::input::HELP;
use crate::state::Explorer;
use raylab::tolerance::WITHIN_LEVELS;

const SIZE: f32 = 13.0;
const LINE: f32 = 17.0;
const PAD: f32 = 6.0;
const PANEL: Rgb = [16, 16, 20];
const TEXT: Rgb = [240, 240, 240];
const MUTED: Rgb = [170, 175, 185];
const WARN: Rgb = [255, 170, 90];
/// The probe's box: its top this many paddings (and the status lines)
/// down, at most this share of the frame's width, on the side away from
/// the tree.
const PROBE_TOP_LINES: f32 = 3.0;
const PROBE_WIDTH: f32 = 0.46;
/// The help's column of keys.
const HELP_KEYS: f32 = 64.0;

/// The overlay's lines for the knobs and the frame.
pub fn status_lines(explorer: &Explorer) -> Vec<(String, Rgb)> {
    let knobs = &explorer.knobs;
    let (done, asked) = explorer.samples();
    let mut first = format!(
        "{} · chapter {}  {}   depth {}   ",
        knobs.binary(),
        knobs.chapter_number(),
        knobs.chapter_name(),
        knobs.max_depth
    );
    if knobs.paths {
        first.push_str(&format!(
            "sun {}   {} materials   ε {}",
            knobs.sun_name(),
            knobs.materials.name(),
            knobs.epsilon
        ));
    } else {
        let rays = if asked == 1 { "ray" } else { "rays" };
        first.push_str(&format!("{asked} {rays}/px   ε {}", knobs.epsilon));
    }
    let stats = explorer.stats();
    let unit = match (knobs.paths, asked) {
        (true, 1) => "path/px",
        (true, _) => "paths/px",
        (false, 1) => "ray/px",
        (false, _) => "rays/px",
    };
    let second = format!(
        "{:.1} ms/frame   {:.1} Mrays/s   {done} of {asked} {unit}{}   {}",
        stats.frame.as_secs_f64() * 1e3,
        stats.mrays_per_second(),
        if explorer.view.is_home() {
            ""
        } else {
            "   (camera moved: c resets)"
        },
        "? help"
    );
    let mut lines = vec![(first, TEXT), (second, MUTED)];
    lines.extend(gpu_lines(explorer));
    if let Some(status) = explorer.status() {
        lines.push((status.to_owned(), WARN));
    }
    lines
}

/// With `g` on: the GPU frame's time beside the CPU's, and how the two
/// images agree under the lab model's tolerance; or why there is no GPU frame.
fn gpu_lines(explorer: &Explorer) -> Vec<(String, Rgb)> {
    let Some(outcome) = explorer.gpu().outcome() else {
        return Vec::new();
    };
    let frame = match outcome {
        Outcome::Pending => {
            return vec![("GPU: rendered once the view is still…".to_owned(), MUTED)];
        }
        Outcome::Refused(why) => return vec![(why.clone(), WARN)],
        Outcome::Frame(frame) => frame,
    };
    let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
    let time = format!(
        "GPU frame {:.0} ms (dispatch + readback) on {}; the CPU's {:.0} ms",
        ms(frame.time),
        explorer.gpu().adapter().unwrap_or("the GPU"),
        ms(explorer.stats().frame)
    );
    let agreement = &frame.agreement;
    let (verdict, colour) = if agreement.meets_lab_tolerance() {
        ("the lab model's tolerance met", TEXT)
    } else {
        ("outside the lab model's tolerance", WARN)
    };
    let compared = format!(
        "GPU against CPU: {:.2} % of pixels within {WITHIN_LEVELS} levels, largest difference {}: \
         {verdict}",
        // Down, so that a share just short of all never reads 100.00 %.
        (agreement.within_3 * 1e4).floor() / 1e2,
        agreement.max,
    );
    vec![(time, MUTED), (compared, colour)]
}

/// The labels under the two halves of a split frame.
fn split_labels(explorer: &Explorer, width: f32, height: f32) -> Vec<Panel> {
    if explorer.gpu().frame(explorer.size()).is_none() {
        return Vec::new();
    }
    let adapter = explorer.gpu().adapter().unwrap_or("the GPU");
    let labels = [
        "CPU (chapter 7's waves)".to_owned(),
        format!("GPU (chapter 10's shader, {adapter})"),
    ];
    let half = (width / 2.0).floor();
    let y = height - PAD - LINE - PAD;
    labels
        .into_iter()
        .zip([PAD, half + PAD])
        .filter_map(|(label, x)| lines_panel(x, y, vec![(label, TEXT)], half - 2.0 * PAD))
        .collect()
}

/// A thin light line down the middle of a split frame, where the CPU's
/// half meets the GPU's.
pub fn draw_seam(frame: &mut RgbImage, explorer: &Explorer) {
    if explorer.gpu().frame(frame.dimensions()).is_none() {
        return;
    }
    let x = frame.width() / 2;
    for y in 0..frame.height() {
        let pixel = frame.get_pixel_mut(x, y);
        pixel.0 = pixel.0.map(|c| c / 2 + 128);
    }
}

/// What a box of the overlay holds.
enum Content {
    Lines(Vec<(String, Rgb)>),
    Help,
}

/// A box of the overlay, laid out: where it goes, its size, its text.
struct Panel {
    x: f32,
    y: f32,
    width: f32,
    height: f32,
    content: Content,
}

/// The overlay's boxes on a `width` × `height` frame.
fn panels(explorer: &Explorer, width: f32, height: f32) -> Vec<Panel> {
    let mut panels = split_labels(explorer, width, height);
    let status = status_lines(explorer);
    let lines = status.len();
    panels.extend(lines_panel(PAD, PAD, status, width - 2.0 * PAD));
    if let Some(probe) = explorer.probe() {
        // On the right, under the status lines and above the lower third
        // of the frame, where the ground, the spheres' bottoms and most of
        // a tree's rays are; the coordinates are left out, as the tree
        // itself shows where each ray goes.
        let top = PROBE_TOP_LINES * PAD + LINE * lines as f32;
        let room = ((height * 2.0 / 3.0 - top - PAD) / LINE).floor().max(2.0) as usize;
        let mut text: Vec<(String, Rgb)> = probe
            .text
            .lines()
            .map(|l| (without_coordinates(l.trim_start()), TEXT))
            .collect();
        if text.len() > room {
            let rest = text.len() - room + 1;
            text.truncate(room - 1);
            text.push((format!("… {rest} more lines in the terminal"), MUTED));
        }
        if let Some(mut panel) = lines_panel(0.0, top, text, width * PROBE_WIDTH) {
            // On the side of the frame away from the tree.
            let size = (width as u32, height as u32);
            let tree_x = crate::tree3d::mean_x(&explorer.camera(), size, probe);
            panel.x = match tree_x {
                Some(x) if x < width / 2.0 => (width - PAD - panel.width).max(PAD),
                _ => PAD,
            };
            panels.push(panel);
        }
    }
    if explorer.knobs.help {
        let widest = HELP
            .iter()
            .map(|(_, what)| text_width(what, SIZE))
            .fold(0.0, f32::max);
        panels.push(Panel {
            x: PAD,
            y: PAD * 3.0 + LINE * lines as f32,
            width: HELP_KEYS + widest + 2.0 * PAD,
            height: LINE * HELP.len() as f32 + PAD,
            content: Content::Help,
        });
    }
    panels
}

/// Draw the overlay on a canvas the size of the frame.
pub fn draw(canvas: &mut Canvas, explorer: &Explorer) {
    for panel in panels(explorer, canvas.width() as f32, canvas.height() as f32) {
        draw_panel(canvas, &panel, (panel.x, panel.y));
    }
}

/// Draw the overlay straight onto the frame, a small canvas per box: the
/// frame itself never goes through a canvas, which would cost two passes
/// over every pixel of it, every frame.
pub fn draw_on(frame: &mut RgbImage, explorer: &Explorer) {
    let (width, height) = frame.dimensions();
    for panel in panels(explorer, width as f32, height as f32) {
        let x = panel.x.max(0.0) as u32;
        let y = panel.y.max(0.0) as u32;
        if x >= width || y >= height {
            continue;
        }
        let w = (panel.width.ceil() as u32 + 1).min(width - x);
        let h = (panel.height.ceil() as u32 + 1).min(height - y);
        let under = image::imageops::crop_imm(frame, x, y, w, h).to_image();
        let mut canvas = Canvas::new(w, h, [0, 0, 0]);
        canvas.draw_rgb_image(&under, 0, 0, 1);
        draw_panel(
            &mut canvas,
            &panel,
            (panel.x - x as f32, panel.y - y as f32),
        );
        image::imageops::replace(frame, &canvas.to_rgb_image(), i64::from(x), i64::from(y));
    }
}

/// One box, its top left at `(x, y)` of the canvas.
fn draw_panel(canvas: &mut Canvas, panel: &Panel, (x, y): (f32, f32)) {
    match &panel.content {
        Content::Lines(lines) => {
            canvas.fill_rect_translucent(x, y, panel.width, panel.height, PANEL, 0.72);
            for (i, (line, colour)) in lines.iter().enumerate() {
                let top = y + PAD / 2.0 + LINE * i as f32;
                canvas.text(x + PAD, top, line, SIZE, *colour, Anchor::TOP_LEFT);
            }
        }
        Content::Help => {
            canvas.fill_rect_translucent(x, y, panel.width, panel.height, PANEL, 0.8);
            for (i, (key, what)) in HELP.iter().enumerate() {
                let top = y + PAD / 2.0 + LINE * i as f32;
                canvas.text(x + PAD, top, key, SIZE, WARN, Anchor::TOP_LEFT);
                canvas.text(x + PAD + HELP_KEYS, top, what, SIZE, TEXT, Anchor::TOP_LEFT);
            }
        }
    }
}

/// Lines of text on a dark translucent box at most `width` wide; a line
/// too long is cut with an ellipsis.
fn lines_panel(x: f32, y: f32, lines: Vec<(String, Rgb)>, width: f32) -> Option<Panel> {
    if lines.is_empty() || width <= 2.0 * PAD {
        return None;
    }
    let room = width - 2.0 * PAD;
    let fitted: Vec<(String, Rgb)> = lines
        .into_iter()
        .map(|(line, colour)| (fit(&line, room), colour))
        .collect();
    let widest = fitted
        .iter()
        .map(|(l, _)| text_width(l, SIZE))
        .fold(0.0, f32::max);
    Some(Panel {
        x,
        y,
        width: widest + 2.0 * PAD,
        height: LINE * fitted.len() as f32 + PAD,
        content: Content::Lines(fitted),
    })
}

fn fit(line: &str, room: f32) -> String {
    let full = text_width(line, SIZE);
    if full <= room {
        return line.to_owned();
    }
    // Cut to the share of characters that fits, then by one until it does.
    let chars: Vec<char> = line.chars().collect();
    let mut keep = ((chars.len() as f32 * room / full) as usize).min(chars.len());
    loop {
        let cut: String = chars[..keep].iter().collect();
        let cut = format!("{cut}…");
        if keep == 0 || text_width(&cut, SIZE) <= room {
            return cut;
        }
        keep -= 1;
    }
}

/// A probe line without its ` from (…) along (…)`.
fn without_coordinates(line: &str) -> String {
    match line.find(" from (") {
        Some(from) => match line[from..].find("): ") {
            Some(end) => format!("{}{}", &line[..from], &line[from + end + 1..]),
            None => line.to_owned(),
        },
        None => line.to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Input, Loaded};

    #[test]
    fn a_clicked_pixel_s_text_leaves_the_lower_third_of_the_frame_uncovered() {
        let mut explorer = Explorer::new(Loaded::lab(), 640, 480);
        explorer.frame();
        // The glass sphere's centre: a deep tree, many lines of text.
        let glass = raylab::Scene::lab().spheres()[1].shape.centre;
        let (x, y) = raylab::Camera::lab().project(glass, 640, 480).unwrap();
        let (button, x, y) = (crate::Button::Left, f64::from(x), f64::from(y));
        explorer.handle(Input::Press { button, x, y });
        explorer.handle(Input::Release { button, x, y });
        assert!(explorer.probe().is_some());
        let boxes = panels(&explorer, 640.0, 480.0);
        assert_eq!(boxes.len(), 2, "the status lines and the probe's text");
        // The tree is right of the middle (the glass sphere): the text is on the left.
        assert_eq!(boxes[1].x, PAD);
        for panel in boxes {
            assert!(
                panel.y + panel.height <= 480.0 * 2.0 / 3.0,
                "{}",
                panel.y + panel.height
            );
            assert!(panel.x >= 0.0 && panel.x + panel.width <= 640.0);
        }
    }
}
