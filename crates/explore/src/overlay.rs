//! The overlay, always on: the knobs and their values, the frame time and
//! rays per second, how far the image has refined, the last error; the
//! help on `?`; the clicked pixel's tree as text beside it. Drawn with
//! `raylab-plot`'s text (Noto Sans), the figures' own.

use raylab_plot::{Anchor, Canvas, Rgb};

use crate::input::HELP;
use crate::state::Explorer;

const SIZE: f32 = 13.0;
const LINE: f32 = 17.0;
const PAD: f32 = 6.0;
const PANEL: Rgb = [16, 16, 20];
const TEXT: Rgb = [240, 240, 240];
const MUTED: Rgb = [170, 175, 185];
const WARN: Rgb = [255, 170, 90];

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
    if let Some(status) = explorer.status() {
        lines.push((status.to_owned(), WARN));
    }
    lines
}

pub fn draw(canvas: &mut Canvas, explorer: &Explorer) {
    let lines = status_lines(explorer);
    panel(canvas, PAD, PAD, &lines, canvas.width() as f32 - 2.0 * PAD);
    if let Some(probe) = explorer.probe() {
        // Along the bottom, where the ground is, so that the tree and the
        // spheres stay in sight; the coordinates are left out, as the
        // tree itself shows where each ray goes.
        let room = (canvas.height() as f32 * 0.36 / LINE).floor().max(1.0) as usize;
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
        let top = canvas.height() as f32 - PAD - LINE * text.len() as f32 - PAD;
        panel(canvas, PAD, top, &text, canvas.width() as f32 - 2.0 * PAD);
    }
    if explorer.knobs.help {
        help(canvas, PAD, PAD * 3.0 + LINE * 3.0);
    }
}

/// The keys in two columns: the key, and what it does.
fn help(canvas: &mut Canvas, x: f32, y: f32) {
    const KEYS: f32 = 64.0;
    let widest = HELP
        .iter()
        .map(|(_, what)| canvas.text_width(what, SIZE))
        .fold(0.0, f32::max);
    let height = LINE * HELP.len() as f32 + PAD;
    canvas.fill_rect_translucent(x, y, KEYS + widest + 2.0 * PAD, height, PANEL, 0.8);
    for (i, (key, what)) in HELP.iter().enumerate() {
        let top = y + PAD / 2.0 + LINE * i as f32;
        canvas.text(x + PAD, top, key, SIZE, WARN, Anchor::TOP_LEFT);
        canvas.text(x + PAD + KEYS, top, what, SIZE, TEXT, Anchor::TOP_LEFT);
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

/// Lines of text on a dark translucent box at most `width` wide; a line
/// too long is cut with an ellipsis.
fn panel(canvas: &mut Canvas, x: f32, y: f32, lines: &[(String, Rgb)], width: f32) {
    if lines.is_empty() || width <= 2.0 * PAD {
        return;
    }
    let room = width - 2.0 * PAD;
    let fitted: Vec<(String, Rgb)> = lines
        .iter()
        .map(|(line, colour)| (fit(canvas, line, room), *colour))
        .collect();
    let widest = fitted
        .iter()
        .map(|(l, _)| canvas.text_width(l, SIZE))
        .fold(0.0, f32::max);
    let height = LINE * fitted.len() as f32 + PAD;
    canvas.fill_rect_translucent(x, y, widest + 2.0 * PAD, height, PANEL, 0.72);
    for (i, (line, colour)) in fitted.iter().enumerate() {
        canvas.text(
            x + PAD,
            y + PAD / 2.0 + LINE * i as f32,
            line,
            SIZE,
            *colour,
            Anchor::TOP_LEFT,
        );
    }
}

fn fit(canvas: &Canvas, line: &str, room: f32) -> String {
    if canvas.text_width(line, SIZE) <= room {
        return line.to_owned();
    }
    let mut cut: String = line.to_owned();
    while !cut.is_empty() && canvas.text_width(&format!("{cut}…"), SIZE) > room {
        cut.pop();
    }
    format!("{cut}…")
}
