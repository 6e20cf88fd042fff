//! Chapter 9: many spheres.
//!
//! Every ray of chapters 1–8 is tested against every sphere: fine for the
//! lab's five, hopeless for a field of thousands, where nearly every test
//! misses. This chapter puts the spheres in a tree of boxes — a bounding
//! volume hierarchy — and lets a ray skip every sphere whose box it does
//! not pass through, while finding exactly the hit the list finds:
//!
//! - [`aabb`]: axis-aligned boxes and the slab test;
//! - [`bvh`]: the tree, built top-down by the surface area heuristic over
//!   binned centres, stored as one flat array, searched nearest child
//!   first (and, for shadow rays, to the first hit);
//! - [`field`]: seeded fields of N spheres to try it on, and [`acne`]:
//!   what the lab's offset does at their scale;
//! - [`objects`]: `--objects list|tree`, the choice chapters 7 and 8 offer;
//! - [`program`]: the program's command line (`generate-field`).
//!
//! The tree is a [`raylab::SceneQuery`]: any tracer that asks a query
//! rather than the scene (the core's `Tracer::with_query`, chapter 6's
//! `render_paths_with_query`) traces through it and makes the same bytes. `--like
//! chNN-…` traces as any of chapters 1–5.
//!
//! This crate is floor A: the tree and the program that teaches it, on the
//! core, the Whitted chapters (through `raylab-like`) and the program
//! shell. The tree's faster floor lives beside the lanes, not here:
//! `raylab_lanes::BvhX8` searches it eight rays at a time, and chapters 7
//! and 8 take it with `--objects tree` (`ch07-eight-rays --objects tree`,
//! `ch08-eight-paths --objects tree`), choosing their renderer once per
//! render. So the faster chapters depend on this one, as they depend on
//! the core, and never the other way: a learner of the tree builds no
//! SIMD, and a later floor-A chapter (a new shape in the tree) changes
//! one crate. The explorer does not search the tree yet: it would take
//! it the same way, through chapter 7's and chapter 8's renderers. The
//! figures of the page are drawn by the workbook, as every chapter's are.

pub mod aabb;
pub mod acne;
pub mod bvh;
pub mod field;
pub mod objects;
pub mod program;

use raylab::render::render_with_query;
use raylab_cli::Chapter;

pub use bvh::Bvh;
pub use objects::Objects;
pub use raylab_like::Like;

/// The program's name, which is also its default output folder.
pub const BINARY: &str = "ch09-many-spheres";

/// What `--help` says of chapter 9's program.
const ABOUT: &str = "Chapter 9, many spheres: every ray's hit found through a bounding volume \
                     hierarchy, to the same bytes as testing every sphere. --like ch01-ray-cast … \
                     ch05-antialiasing traces as that chapter does (default: ch05-antialiasing); \
                     `generate-field N [--seed S]` prints a scene file of N random spheres. \
                     Chapters 7 and 8 search the same tree with --objects tree.";

// ANCHOR: render
/// Chapter 9's program, tracing as the chapter `like` does, with its
/// defaults (chapter 5's when `--like` is not given). Its renderer is the
/// core's [`render_with_query`], with every ray's hit found through a tree
/// built over the scene's spheres first (the build is part of the time).
/// The step is a Whitted chapter's shading, unchanged: what this chapter
/// changes is how each ray finds its hit.
pub fn chapter(like: Like) -> Chapter<Like> {
    let defaults = like.defaults();
    Chapter {
        binary: BINARY,
        about: ABOUT,
        max_depth: defaults.max_depth,
        spp: defaults.spp,
        probe: defaults.probe,
        step: like,
        render: |scene, camera, step, settings, keep, progress| {
            let tree = Bvh::build(scene);
            render_with_query(scene, &tree, camera, step, settings, keep, progress)
        },
    }
}
// ANCHOR_END: render
