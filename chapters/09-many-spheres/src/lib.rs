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
//! - [`field`]: seeded fields of N spheres to try it on.
//!
//! The tree is a [`raylab::SceneQuery`]: any tracer that asks a query
//! rather than the scene (the core's `Tracer::with_query`, chapter 6's
//! `render_with`) traces through it and makes the same bytes. `--like
//! chNN-…` traces as any of chapters 1–5.

pub mod aabb;
pub mod bvh;
pub mod bvh_x8;
pub mod field;
pub mod figures;

use ch06_path_tracing::{PathProgram, PathRender, PathSettings};
use ch07_eight_rays::EightRays;
use ch07_eight_rays::render::render_waves_with;
use ch08_eight_paths::render_eight_with;
use raylab::camera::Camera;
use raylab::frame::{Keep, Rendered, Settings};
use raylab::render::{Progress, render_with_query};
use raylab::{Hit, Ray, Scene, Step, Surface, Vec3};
use raylab_cli::{Chapter, Program, Renderer};

pub use bvh::Bvh;
pub use bvh_x8::BvhX8;
pub use raylab_like::Like;

/// The program's name, which is also its default output folder.
pub const BINARY: &str = "ch09-many-spheres";

/// Chapter 9's step: a Whitted chapter's shading, unchanged. What this
/// chapter changes is how each ray finds its hit ([`render_tree`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ManySpheres {
    pub like: Like,
}

impl Step for ManySpheres {
    fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        self.like.shade(ray, hit, surface)
    }

    fn lab_five(&self) -> [(f32, f32); 5] {
        self.like.lab_five()
    }
}

// ANCHOR: render
/// The core's render, with every ray's hit found through a tree built
/// over the scene's spheres first (the build is part of the time).
pub fn render_tree(
    scene: &Scene,
    camera: &Camera,
    step: &ManySpheres,
    settings: &Settings,
    keep: Keep,
    progress: &dyn Progress,
) -> Rendered {
    let tree = Bvh::build(scene);
    render_with_query(scene, &tree, camera, step, settings, keep, progress)
}
// ANCHOR_END: render

// ANCHOR: eight
/// Chapter 7's render, eight rays at a time in waves, with every hit
/// found through the tree, eight rays against each node ([`BvhX8`]).
pub fn render_tree_waves(
    scene: &Scene,
    camera: &Camera,
    step: &EightRays,
    settings: &Settings,
    keep: Keep,
    progress: &dyn Progress,
) -> Rendered {
    let tree = Bvh::build(scene);
    let lanes = BvhX8::new(&tree);
    render_waves_with(scene, &lanes, camera, step, settings, keep, progress)
}

/// Chapter 8's render, eight paths at a time, with every hit found
/// through the tree: the paths' eight at a time ([`BvhX8`]), the
/// photons' one at a time.
pub fn render_tree_paths(
    scene: &Scene,
    camera: &Camera,
    settings: &PathSettings,
    progress: &dyn Progress,
) -> PathRender {
    let tree = Bvh::build(scene);
    render_eight_with(scene, &BvhX8::new(&tree), camera, settings, progress)
}
// ANCHOR_END: eight

/// Chapter 9's program with `--eight`: chapter 7's, tracing as the
/// chapter `like` does, through the tree.
pub fn chapter_eight(like: Like) -> Chapter<EightRays> {
    chapter_with(EightRays { like }, like, render_tree_waves)
}

/// Chapter 9's program with `--paths`: chapter 8's (chapter 6's flags and
/// files), through the tree.
pub const PATHS: PathProgram = PathProgram {
    program: Program {
        binary: BINARY,
        about: "Chapter 9 --paths: chapter 6's path-traced image, to the byte, traced eight paths \
                at a time as chapter 8 does, every hit found through a bounding volume hierarchy.",
        max_depth: 10,
        spp: 256,
    },
    render: render_tree_paths,
};

/// Chapter 9's program, tracing as the chapter `like` does, with its
/// defaults (chapter 5's when `--like` is not given).
pub fn chapter(like: Like) -> Chapter<ManySpheres> {
    chapter_with(ManySpheres { like }, like, render_tree)
}

fn chapter_with<S: Step>(step: S, like: Like, render: Renderer<S>) -> Chapter<S> {
    let defaults = like.defaults();
    Chapter {
        binary: BINARY,
        about: "Chapter 9, many spheres: every ray's hit found through a bounding volume hierarchy, \
                to the same bytes as testing every sphere. --like ch01-ray-cast … ch05-antialiasing \
                traces as that chapter does (default: ch05-antialiasing); --eight traces eight rays \
                at a time as chapter 7 does; --paths path-traces eight paths at a time as chapter \
                8 does (chapter 6's flags); --generate-field N [--seed S] prints a scene file of N \
                random spheres.",
        max_depth: defaults.max_depth,
        spp: defaults.spp,
        probe: defaults.probe,
        step,
        render,
    }
}
