//! The depth sweep: how the image changes as the maximum depth grows, and
//! the depth after which it stops changing.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use image::RgbImage;

use crate::output::{WriteError, save_png, save_text};
use raylab_plot::colour::SERIES;
use raylab_plot::{
    Corner, LinePlot, Series, changed_pixels, magnified_difference, max_change, montage,
    with_change_scale,
};

/// How much the image changed going from depth `depth − 1` to `depth`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Change {
    pub depth: u32,
    /// Pixels that changed at all (in 8 bits).
    pub changed_pixels: usize,
    /// Pixels that changed by more than 3 of 255 in some channel.
    pub changed_over_3: usize,
    /// The largest change of any channel of any pixel.
    pub max_change: u8,
}

/// The images at depths 1 to N and what changed between them.
#[derive(Clone, Debug)]
pub struct DepthSweep {
    /// `images[d − 1]` is the image at max depth `d`, 8-bit sRGB.
    pub images: Vec<RgbImage>,
    /// One row per depth from 2 to N.
    pub changes: Vec<Change>,
}

/// The most a pixel may change and still count as "not changing": one
/// level of 255, the size of a rounding difference.
pub const SETTLED: u8 = 1;

impl DepthSweep {
    /// Compare each depth's image with the one before.
    pub fn new(images: Vec<RgbImage>) -> Self {
        let changes = images
            .windows(2)
            .zip(2..)
            .map(|(pair, depth)| Change {
                depth,
                changed_pixels: changed_pixels(&pair[0], &pair[1], 0),
                changed_over_3: changed_pixels(&pair[0], &pair[1], 3),
                max_change: max_change(&pair[0], &pair[1]),
            })
            .collect();
        DepthSweep { images, changes }
    }

    /// The smallest depth after which no pixel changes by more than
    /// [`SETTLED`] levels, within the depths swept.
    pub fn settles_at(&self) -> u32 {
        settles_at(&self.changes)
    }

    /// The sweep's conclusion in one sentence, read off the same numbers as
    /// the table and the CSV: the depth at which the picture settles, the
    /// largest change that depth still made, and that no deeper one changes
    /// any pixel by more than [`SETTLED`] level.
    pub fn settled_sentence(&self, binary: &str) -> String {
        let n = self.settles_at();
        let last = self.images.len();
        let made = self
            .changes
            .iter()
            .find(|c| c.depth == n)
            .map_or(0, |c| c.max_change);
        let deeper = if n as usize >= last {
            format!("the sweep stopped there (at depth {last}): sweep deeper to see it settle")
        } else if n as usize + 1 == last {
            format!("depth {last} changes no pixel by more than {SETTLED} level")
        } else {
            format!(
                "from depth {} to {last}, no pixel changes by more than {SETTLED} level",
                n + 1
            )
        };
        if n <= 1 {
            return format!("In `{binary}`, the picture settles at depth 1: {deeper}.");
        }
        format!(
            "In `{binary}`, the picture settles at depth {n}: going from depth {} to {n} still \
             changed a pixel by {made} levels, and {deeper}.",
            n - 1
        )
    }

    /// The numbers, as CSV.
    pub fn csv(&self) -> String {
        let mut out = String::from("depth,changed_pixels,changed_over_3,max_change\n");
        for c in &self.changes {
            let _ = writeln!(
                out,
                "{},{},{},{}",
                c.depth, c.changed_pixels, c.changed_over_3, c.max_change
            );
        }
        out
    }

    /// The numbers as a markdown table with a one-line conclusion, for the book.
    pub fn summary_markdown(&self, binary: &str) -> String {
        let pixels = self.images.first().map_or(1, |i| i.width() * i.height()) as f64;
        let mut out = String::from(
            "| depth d | pixels changed from d − 1 | changed by more than 3 | largest change (of 255) |\n\
             |---:|---:|---:|---:|\n",
        );
        for c in &self.changes {
            let _ = writeln!(
                out,
                "| {} | {} ({:.2} %) | {} | {} |",
                c.depth,
                c.changed_pixels,
                100.0 * c.changed_pixels as f64 / pixels,
                c.changed_over_3,
                c.max_change
            );
        }
        let _ = writeln!(out, "\n{}", self.settled_sentence(binary));
        out
    }

    /// The plot of [`DepthSweep::changes`], on a log axis.
    pub fn changes_plot(&self, binary: &str) -> RgbImage {
        let settles = self.settles_at();
        let at_all = self
            .changes
            .iter()
            .map(|c| (f64::from(c.depth), c.changed_pixels as f64));
        let over_3 = self
            .changes
            .iter()
            .map(|c| (f64::from(c.depth), c.changed_over_3 as f64));
        let largest = self
            .changes
            .iter()
            .map(|c| (f64::from(c.depth), f64::from(c.max_change)));
        // The settle criterion itself, in levels of 255, on its own axis:
        // the picture has settled where this drops to 1 and stays there.
        let right = LinePlot::new("")
            .y_label("largest change, levels of 255")
            .log_y(1.0)
            .y_range(1.0, 255.0)
            .series(Series::new(
                "largest change of any pixel (right axis)",
                SERIES[3],
                largest,
            ));
        let last = self.images.len() as f64;
        let mut plot = LinePlot::new(format!(
            "{binary}: pixels that change when the max depth grows by one"
        ))
        .x_label("max depth d (compared with d − 1)")
        .y_label("pixels changed")
        .x_range(1.5, last + 0.5)
        .integer_x_ticks()
        .log_y(1.0)
        .series(Series::new("changed at all", SERIES[0], at_all))
        .series(Series::new(
            "changed by more than 3 of 255",
            SERIES[1],
            over_3,
        ))
        .right_axis(right)
        .legend(Corner::TopRight);
        if settles < self.images.len() as u32 {
            plot = plot.vertical_marker(
                f64::from(settles) + 0.5,
                format!("after depth {settles}: no change above {SETTLED} level"),
                [85, 85, 85],
            );
        }
        plot.render(900, 500)
    }

    /// Every image, labelled with its depth.
    pub fn montage(&self, binary: &str) -> RgbImage {
        let labels: Vec<String> = (1..=self.images.len())
            .map(|d| format!("max depth {d}"))
            .collect();
        // Thumbnails: ten full-size renders side by side would be too wide to read.
        let thumbnails: Vec<RgbImage> = self.images.iter().map(thumbnail).collect();
        let tiles: Vec<(&str, &RgbImage)> =
            labels.iter().map(String::as_str).zip(&thumbnails).collect();
        let columns = if self.images.len() > 6 { 5 } else { 3 };
        montage(&format!("{binary} at every max depth"), &tiles, columns)
    }

    /// Write everything into `dir`: `depth-NN.png`, `montage.png`,
    /// `changes.png`, `changes.csv`, `diff-1-vs-N.png`, and for the book
    /// `summary.md` (the table) and `diff.md` (the line that shows the diff).
    /// `book_dir` is how the book reaches `dir`, for the summary's image link.
    pub fn write(
        &self,
        dir: &Path,
        binary: &str,
        book_dir: &str,
    ) -> Result<Vec<PathBuf>, WriteError> {
        let mut written = Vec::new();
        let mut png = |name: &str, image: &RgbImage| -> Result<(), WriteError> {
            let path = dir.join(name);
            save_png(image, &path)?;
            written.push(path);
            Ok(())
        };
        for (d, image) in self.images.iter().enumerate() {
            png(&format!("depth-{:02}.png", d + 1), image)?;
        }
        png("montage.png", &self.montage(binary))?;
        png("changes.png", &self.changes_plot(binary))?;
        let settles = self.settles_at() as usize;
        let diff_name = format!("diff-1-vs-{settles}.png");
        // The scale's top is the largest change, so that nothing saturates.
        let (first, settled) = (&self.images[0], &self.images[settles - 1]);
        let largest = max_change(first, settled).max(1);
        let gain = 255.0 / f32::from(largest);
        let diff = with_change_scale(&magnified_difference(first, settled, gain), gain);
        png(&diff_name, &diff)?;
        let mut text = |name: &str, contents: String| -> Result<(), WriteError> {
            let path = dir.join(name);
            save_text(&contents, &path)?;
            written.push(path);
            Ok(())
        };
        text("changes.csv", self.csv())?;
        text("summary.md", self.summary_markdown(binary))?;
        // The book cannot know N in advance: it includes this line instead.
        let diff_md = format!(
            "![{binary}: how much each pixel changes from depth 1 to depth {settles}, on a scale up to the largest change, {largest} levels]({book_dir}/{diff_name})\n"
        );
        text("diff.md", diff_md)?;
        Ok(written)
    }
}

/// The smallest depth after which no pixel changes by more than
/// [`SETTLED`] levels, read off a sweep's changes (1 if none is larger).
pub fn settles_at(changes: &[Change]) -> u32 {
    changes
        .iter()
        .rev()
        .find(|c| c.max_change > SETTLED)
        .map_or(1, |c| c.depth)
}

/// A sweep's changes read back from the `changes.csv` it wrote, so that a
/// figure drawn later marks the depths the sweep measured.
pub fn changes_from_csv(text: &str) -> Result<Vec<Change>, String> {
    let mut lines = text.lines();
    let header = "depth,changed_pixels,changed_over_3,max_change";
    if lines.next() != Some(header) {
        return Err(format!("a sweep's changes.csv starts with '{header}'"));
    }
    lines
        .filter(|line| !line.is_empty())
        .map(|line| {
            let bad = || format!("'{line}' is not a row of a sweep's changes.csv");
            let fields: Vec<&str> = line.split(',').collect();
            let [depth, changed, over_3, max] = fields[..] else {
                return Err(bad());
            };
            Ok(Change {
                depth: depth.parse().map_err(|_| bad())?,
                changed_pixels: changed.parse().map_err(|_| bad())?,
                changed_over_3: over_3.parse().map_err(|_| bad())?,
                max_change: max.parse().map_err(|_| bad())?,
            })
        })
        .collect()
}

/// The image scaled down to at most 320 pixels wide, averaging as it goes.
fn thumbnail(image: &RgbImage) -> RgbImage {
    const WIDTH: u32 = 320;
    if image.width() <= WIDTH {
        return image.clone();
    }
    let height = (image.height() * WIDTH / image.width()).max(1);
    image::imageops::thumbnail(image, WIDTH, height)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey(level: u8) -> RgbImage {
        RgbImage::from_pixel(4, 2, image::Rgb([level; 3]))
    }

    #[test]
    fn a_sweep_settles_after_its_last_change_above_one_level() {
        let mut third = grey(50);
        third.put_pixel(0, 0, image::Rgb([52, 50, 50]));
        let mut fourth = third.clone();
        fourth.put_pixel(1, 0, image::Rgb([51, 50, 50]));
        let sweep = DepthSweep::new(vec![grey(10), grey(50), third, fourth.clone(), fourth]);
        assert_eq!(
            sweep.changes[0],
            Change {
                depth: 2,
                changed_pixels: 8,
                changed_over_3: 8,
                max_change: 40
            }
        );
        assert_eq!(sweep.changes[1].max_change, 2);
        assert_eq!(
            sweep.changes[2],
            Change {
                depth: 4,
                changed_pixels: 1,
                changed_over_3: 0,
                max_change: 1
            }
        );
        assert_eq!(sweep.settles_at(), 3);
        assert_eq!(
            sweep.settled_sentence("ch"),
            "In `ch`, the picture settles at depth 3: going from depth 2 to 3 still changed a \
             pixel by 2 levels, and from depth 4 to 5, no pixel changes by more than 1 level."
        );
        assert_eq!(
            sweep.csv().lines().take(2).collect::<Vec<_>>(),
            ["depth,changed_pixels,changed_over_3,max_change", "2,8,8,40"]
        );
        assert_eq!(changes_from_csv(&sweep.csv()), Ok(sweep.changes.clone()));
    }

    #[test]
    fn a_changes_file_that_is_not_a_sweeps_is_refused_with_its_line() {
        assert!(changes_from_csv("depth,x\n").is_err());
        let text = "depth,changed_pixels,changed_over_3,max_change\n2,8,8\n";
        assert_eq!(
            changes_from_csv(text),
            Err("'2,8,8' is not a row of a sweep's changes.csv".to_owned())
        );
    }
}
