//! Chapter 5: anti-aliasing.
//!
//! One ray per pixel sees one point of the scene; an edge that crosses the
//! pixel is either wholly in or wholly out, and edges become staircases.
//! The lab's fix traces five rays per pixel — the centre and the middle of
//! each quarter — and averages them in linear light. The tracing itself is
//! chapter 4's, unchanged: what this step adds is where the rays go, the
//! pattern `raylab::sampling::LAB_FIVE`, and the average over it in
//! `raylab::render`. Both live in the core so that every chapter takes
//! `--spp 5`.

use raylab::probe::ProbeTarget;
use raylab_cli::Chapter;

pub use ch04_refraction::Refraction;

// ANCHOR: chapter
/// Chapter 5's program: chapter 4's tracing with five rays per pixel.
pub const CHAPTER: Chapter<Refraction> = Chapter {
    binary: "ch05-antialiasing",
    about: "Chapter 5, anti-aliasing: five rays per pixel, averaged in linear light.",
    max_depth: 10,
    spp: 5,
    probe: ProbeTarget::SphereCentre("glass"),
    step: Refraction,
};
// ANCHOR_END: chapter
