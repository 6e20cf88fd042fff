//! Figures for the workbook: line plots, heatmaps, montages of renders and
//! difference images, drawn in a plain textbook style (white page, dark
//! grey text, light grey grid).
//!
//! Everything ends as an [`image::RgbImage`], ready to save as PNG or to
//! compare in a test. The pieces, from the bottom up:
//!
//! - [`canvas::Canvas`]: a pixel surface with lines, arrows, circles,
//!   rectangles, image blits and text;
//! - [`text`]: anchors, measuring, word wrapping;
//! - [`colormap`]: matplotlib's viridis and magma;
//! - [`ticks`]: round-number tick positions and labels;
//! - [`line_plot::LinePlot`]: series on linear or log axes (with `scale.rs`
//!   mapping data to positions);
//! - [`heatmap`]: a grid of numbers as colours, with a colour bar;
//! - [`montage::montage`]: labelled images in a grid;
//! - [`diff`]: where and how much two renders differ.
//!
//! # Drawing and fonts
//!
//! Shapes are rasterised by `tiny-skia` (anti-aliased). Text uses `ab_glyph`
//! to turn glyph outlines into pixel coverage, with pair kerning read from
//! the font's GPOS table by `ttf-parser`. There are no font files to ship
//! or find: the typeface is **Noto Sans Regular** (version 1.04, © 2012
//! Google Inc.), compiled in from the `ttf-noto-sans` crate. That font is
//! licensed under the **Apache License, Version 2.0**: the crate ships the
//! licence text as `assets/LICENSE-2.0.txt` beside `NotoSans-Regular.ttf`,
//! and the font's own name table says "Licensed under the Apache License,
//! Version 2.0". (The crate's Rust code is MIT OR Apache-2.0.)
//!
//! # Colour data
//!
//! The viridis and magma tables are matplotlib's (`_cm_listed.py`), by
//! Nathaniel J. Smith, Stéfan van der Walt and Eric Firing, dedicated to
//! the public domain under CC0.

pub mod canvas;
pub mod colormap;
mod colormap_tables;
pub mod colour;
pub mod diff;
mod font;
pub mod heatmap;
pub mod label_box;
pub mod line_plot;
pub mod montage;
mod scale;
pub mod text;
pub mod ticks;

pub use canvas::Canvas;
pub use colormap::{Colormap, magma, viridis};
pub use colour::Rgb;
pub use diff::{changed_pixels, magnified_difference, max_change, with_change_scale};
pub use heatmap::{ColourScale, HeatmapFigure, heatmap_figure, heatmap_image};
pub use label_box::LabelBox;
pub use line_plot::{Corner, LinePlot, Series};
pub use montage::montage;
pub use text::{Anchor, HAlign, VAlign};
