//! Montages: several images side by side in a grid, each with a caption
//! underneath, under one title — e.g. the same scene at max depth 1, 2, 3 ….

use image::RgbImage;

use super::canvas::Canvas;
use super::colour::{TEXT, WHITE};
use super::text::{Anchor, line_metrics, text_width, wrap_text};

/// Space around the figure and between cells, in pixels.
const PAD: u32 = 16;
/// Space between an image and its caption.
const LABEL_GAP: u32 = 6;
const TITLE_SIZE: f32 = 20.0;
const LABEL_SIZE: f32 = 14.0;

/// Lays out `tiles` in rows of `columns` (the last row may be short), each
/// image centred in its cell with its label under it, and `title` centred
/// over the whole. A `columns` of 0 is treated as 1.
///
/// Every cell has the size of the largest image, so images of different
/// sizes still line up in a tidy grid. Labels wider than that wrap onto
/// more lines (cells widen to at least 120 px, or the longest word, so
/// labels under small images do not become towers of single words).
pub fn montage(title: &str, tiles: &[(&str, &RgbImage)], columns: usize) -> RgbImage {
    let layout = MontageLayout::new(title, tiles, columns);
    let mut canvas = Canvas::new(layout.width, layout.height, WHITE);
    let centre_x = layout.width as f32 / 2.0;
    canvas.text(
        centre_x,
        PAD as f32,
        title,
        TITLE_SIZE,
        TEXT,
        Anchor::TOP_CENTRE,
    );

    let line_h = line_metrics(LABEL_SIZE).line_height();
    for (index, (_, image)) in tiles.iter().enumerate() {
        let (cell_x, cell_y) = layout.cell_origin(index);
        // Centre the image horizontally; align it to the bottom of the image
        // area so all captions in a row start on one line.
        let x = cell_x + (layout.cell_w - image.width()) / 2;
        let y = cell_y + (layout.image_h - image.height());
        canvas.draw_rgb_image(image, x as i32, y as i32, 1);

        let label_x = cell_x as f32 + layout.cell_w as f32 / 2.0;
        let label_top = (cell_y + layout.image_h + LABEL_GAP) as f32;
        for (i, line) in layout.labels[index].iter().enumerate() {
            let line_y = label_top + line_h * i as f32;
            canvas.text(label_x, line_y, line, LABEL_SIZE, TEXT, Anchor::TOP_CENTRE);
        }
    }
    canvas.to_rgb_image()
}

/// Labels narrower than this never need to wrap, however small the images.
const MIN_LABEL_WIDTH: u32 = 120;

/// Sizes and positions for a montage, worked out before drawing.
#[derive(Clone, Debug, PartialEq, Eq)]
struct MontageLayout {
    columns: u32,
    rows: u32,
    /// Width of one cell: the widest image, or more for labels.
    cell_w: u32,
    /// Height of the tallest image; labels go below this.
    image_h: u32,
    /// Height of the label area: the most lines any label wrapped to.
    label_h: u32,
    /// Each tile's label, wrapped to the cell width.
    labels: Vec<Vec<String>>,
    /// Top of the first row of cells (below the title).
    grid_top: u32,
    /// Left edge of the first column (the grid is centred if the title is
    /// wider than it).
    grid_left: u32,
    width: u32,
    height: u32,
}

impl MontageLayout {
    fn new(title: &str, tiles: &[(&str, &RgbImage)], columns: usize) -> MontageLayout {
        let columns = columns.clamp(1, tiles.len().max(1)) as u32;
        let rows = tiles.len().div_ceil(columns as usize) as u32;
        let cell_w = cell_width(tiles);
        let image_h = tiles
            .iter()
            .map(|(_, image)| image.height())
            .max()
            .unwrap_or(0);
        let labels: Vec<Vec<String>> = tiles
            .iter()
            .map(|(label, _)| wrap_text(label, LABEL_SIZE, cell_w as f32))
            .collect();
        let lines = labels.iter().map(Vec::len).max().unwrap_or(0) as f32;
        let label_h = (lines * line_metrics(LABEL_SIZE).line_height()).ceil() as u32;
        let title_h = line_metrics(TITLE_SIZE).line_height().ceil() as u32;

        // Cells with PAD between them and PAD around the outside.
        let grid_w = columns * cell_w + (columns - 1) * PAD;
        let title_w = text_width(title, TITLE_SIZE).ceil() as u32;
        let width = grid_w.max(title_w) + 2 * PAD;
        let grid_top = PAD + title_h + PAD;
        let row_h = image_h + LABEL_GAP + label_h;
        let grid_h = rows * row_h + rows.saturating_sub(1) * PAD;
        MontageLayout {
            columns,
            rows,
            cell_w,
            image_h,
            label_h,
            labels,
            grid_top,
            grid_left: (width - grid_w) / 2,
            width,
            height: grid_top + grid_h + PAD,
        }
    }

    /// Top-left corner of cell `index`, counting along rows.
    fn cell_origin(&self, index: usize) -> (u32, u32) {
        let (column, row) = (index as u32 % self.columns, index as u32 / self.columns);
        let row_h = self.image_h + LABEL_GAP + self.label_h;
        (
            self.grid_left + column * (self.cell_w + PAD),
            self.grid_top + row * (row_h + PAD),
        )
    }
}

/// The widest image, widened if needed so that labels wrap sensibly: up to
/// `MIN_LABEL_WIDTH` for long labels, and always to the longest word.
fn cell_width(tiles: &[(&str, &RgbImage)]) -> u32 {
    let width = |text: &str| text_width(text, LABEL_SIZE).ceil() as u32;
    let widest_image = tiles
        .iter()
        .map(|(_, image)| image.width())
        .max()
        .unwrap_or(0);
    let widest_label = tiles
        .iter()
        .map(|(label, _)| width(label))
        .max()
        .unwrap_or(0);
    let widest_word = tiles
        .iter()
        .flat_map(|(label, _)| label.split_whitespace())
        .map(width)
        .max()
        .unwrap_or(0);
    let label_room = widest_label.min(widest_image.max(MIN_LABEL_WIDTH));
    widest_image.max(label_room).max(widest_word)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn solid(width: u32, height: u32, colour: [u8; 3]) -> RgbImage {
        RgbImage::from_pixel(width, height, image::Rgb(colour))
    }

    #[test]
    fn size_is_cells_plus_padding() {
        let image = solid(120, 90, [200, 50, 50]);
        let labels = [
            "max depth 1",
            "max depth 2",
            "max depth 3",
            "max depth 4",
            "max depth 5",
        ];
        let tiles: Vec<(&str, &RgbImage)> = labels.iter().map(|l| (*l, &image)).collect();
        let out = montage("Depth", &tiles, 3);

        // 5 tiles in 3 columns: 2 rows.
        let label_h = line_metrics(LABEL_SIZE).line_height().ceil() as u32;
        let title_h = line_metrics(TITLE_SIZE).line_height().ceil() as u32;
        let expected_w = 3 * 120 + 4 * PAD;
        let expected_h = PAD + title_h + PAD + 2 * (90 + LABEL_GAP + label_h) + PAD + PAD;
        assert_eq!(out.dimensions(), (expected_w, expected_h));
    }

    #[test]
    fn images_land_in_their_cells() {
        let red = solid(50, 40, [220, 0, 0]);
        let blue = solid(50, 40, [0, 0, 220]);
        let tiles = [("red", &red), ("blue", &blue), ("red again", &red)];
        let layout = MontageLayout::new("t", &tiles, 2);
        let out = montage("t", &tiles, 2);
        let centre = |index: usize| {
            let (x, y) = layout.cell_origin(index);
            out.get_pixel(x + layout.cell_w / 2, y + layout.image_h / 2)
                .0
        };
        assert_eq!(centre(0), [220, 0, 0]);
        assert_eq!(centre(1), [0, 0, 220]);
        assert_eq!(centre(2), [220, 0, 0], "wraps to the second row");
        assert_eq!(layout.rows, 2);
    }

    #[test]
    fn long_labels_wrap_to_the_cell_and_small_images_get_room() {
        let wide = solid(160, 90, [0, 0, 0]);
        let label = "difference × 8 (3959 pixels changed, max 11)";
        let tiles = [("max depth 3", &wide), (label, &wide)];
        let layout = MontageLayout::new("", &tiles, 2);
        assert_eq!(layout.cell_w, 160, "cells stay as wide as the images");
        assert_eq!(layout.labels[1].len(), 2, "the long label takes two lines");
        let line_h = line_metrics(LABEL_SIZE).line_height();
        assert_eq!(layout.label_h, (2.0 * line_h).ceil() as u32);

        let small = solid(20, 10, [0, 0, 0]);
        let tall = solid(30, 60, [0, 0, 0]);
        let tiles = [
            ("a rather long caption for a tiny image", &small),
            ("b", &tall),
        ];
        let layout = MontageLayout::new("", &tiles, 2);
        assert_eq!(layout.cell_w, MIN_LABEL_WIDTH);
        assert_eq!(layout.image_h, 60);
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        let image = solid(10, 10, [9, 9, 9]);
        assert!(montage("empty", &[], 3).width() > 0);
        let one = montage("zero columns", &[("x", &image)], 0);
        assert!(one.width() >= 10 + 2 * PAD);
    }
}
