//! Chapter 7: eight rays at a time.
//!
//! The lab's tracer was a fragment shader: the GPU ran it for many pixels
//! at once, in lockstep, each lane of a SIMD unit on its own ray. Chapters
//! 1–5 trace one ray at a time. This chapter traces the same rays, with the
//! same arithmetic, eight at a time in one AVX register (`wide::f32x8`),
//! and makes the same image to the byte:
//!
//! - [`soa`]: eight rays side by side, one array per number;
//! - [`camera`]: a row's primary rays, eight at a time;
//! - [`shade`]: the lab's shading, lane by lane;
//! - [`link`]: how each ray links to the next one of its sample;
//! - [`wave`]: one pass per depth over a whole row, eight rays a group;
//! - [`pack`]: the rays a group sends on, packed densely into the next wave;
//! - [`ledger`]: what each ray added to its sample, and the ray its
//!   sample's stack pops next;
//! - [`render`]: every row on every core, each sample's ray tree summed in
//!   the scalar tracer's order;
//! - [`stats`]: how busy the lanes are, wave by wave (for the book's figures).
//!
//! The scene, the sky and the optics in lanes (eight rays against the
//! ground and every sphere, masks instead of branches) are
//! `raylab-lanes`', shared with chapter 8. With `--like chNN-…`
//! ([`raylab_like`]) it traces as any of chapters 1–5; with `--objects
//! tree` ([`Objects`]) every hit is found through chapter 9's tree, eight
//! rays against each node (`raylab_lanes::BvhX8`).

pub mod camera;
pub mod ledger;
pub mod link;
pub mod pack;
pub mod render;
pub mod shade;
pub mod soa;
pub mod stats;
pub mod wave;

use ch09_many_spheres::Bvh;
use raylab::{Hit, Ray, Step, Surface, Vec3};
use raylab_cli::Chapter;
use raylab_lanes::BvhX8;

pub use ch09_many_spheres::Objects;
pub use raylab_like::{Features, Like};

/// Chapter 7's step: a Whitted chapter's shading, rendered in waves.
///
/// `shade` and `lab_five` are that chapter's own, one ray at a time: the
/// probe, the depth sweep and the rare over-budget sample use them. The
/// program's render ([`render::render_waves`]) traces eight rays at a time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EightRays {
    pub like: Like,
}

impl Step for EightRays {
    fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        self.like.shade(ray, hit, surface)
    }

    fn lab_five(&self) -> [(f32, f32); 5] {
        self.like.lab_five()
    }
}

/// The program's name, which is also its default output folder.
pub const BINARY: &str = "ch07-eight-rays";

/// Chapter 7's program, tracing as the chapter `like` does, with its
/// defaults (chapter 5's when `--like` is not given).
pub fn chapter(like: Like) -> Chapter<EightRays> {
    chapter_through(like, Objects::List)
}

/// What `--help` says of chapter 7's program.
const ABOUT: &str = "Chapter 7, eight rays at a time: chapter 5's image, to the byte, traced in \
                     waves of 8-wide SIMD. --like ch01-ray-cast … ch05-antialiasing traces as \
                     that chapter does, with its defaults (default: ch05-antialiasing); \
                     --objects tree finds every hit through chapter 9's tree of boxes.";

// ANCHOR: tree
/// Chapter 7's program, its hits found as `objects` says: the renderer is
/// chosen here, once for the whole render. With `--objects tree` it is
/// [`render::render_waves_with_query`] over chapter 9's tree, built first
/// (the build is part of the time) and searched eight rays against each
/// node ([`BvhX8`]): the same bytes.
pub fn chapter_through(like: Like, objects: Objects) -> Chapter<EightRays> {
    let defaults = like.defaults();
    Chapter {
        binary: BINARY,
        about: ABOUT,
        max_depth: defaults.max_depth,
        spp: defaults.spp,
        probe: defaults.probe,
        step: EightRays { like },
        render: match objects {
            Objects::List => render::render_waves,
            Objects::Tree => |scene, camera, step, settings, keep, progress| {
                let tree = Bvh::build(scene);
                let lanes = BvhX8::new(&tree);
                render::render_waves_with_query(
                    scene, &lanes, camera, step, settings, keep, progress,
                )
            },
        },
    }
}
// ANCHOR_END: tree
