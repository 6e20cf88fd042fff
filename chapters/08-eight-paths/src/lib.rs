//! Chapter 8: eight paths at a time.
//!
//! Chapter 6's path tracer, to the same bytes, eight paths at a time.
//!
//! `PathTracer::trace` follows one path; here eight paths are in flight,
//! one per lane of an `f32x8`, and every bounce is made for all eight at
//! once: the camera rays, the hits against the ground and the spheres, the
//! hit records, the sky, the sun's shadow rays, the new directions, the
//! throughputs and the terms. Only what is rare, or the learner's, is done
//! lane by lane: the choice of lobe where a material has one (the
//! learner's `choose_lobe`), the disc sun's sample (`--sun-size`) and the
//! caustic lookup (`--caustics`), which reads each lane's photons eight at
//! a time ([`density`]).
//!
//! The bytes are the scalar tracer's because each lane does the scalar
//! code's operations in its order (the workspace builds without FMA), and
//! draws from its sample's own generator exactly where the scalar code
//! draws. When a path ends, its lane takes the row's next sample at once
//! (path regeneration), and `window` puts the finished samples back in
//! sample order before they are summed.
//!
//! - [`paths`]: eight paths in flight, and one bounce of all of them;
//! - [`density`]: the caustic lookup, eight photons at a time;
//! - [`starts`]: the row's next samples, made ready eight at a time;
//! - [`terms`]: the five terms of eight paths;
//! - [`window`]: finished samples put back in order;
//! - [`render`]: every row on every core, in chapter 6's frame;
//! - [`lane_use`]: how many lanes each step of a bounce runs for.
//!
//! The scene, the camera, the sky and the optics in lanes are
//! `raylab-lanes'`, shared with chapter 7. The program is chapter 6's, with
//! this renderer: the same flags, the same files, and one more,
//! `--objects tree` ([`Objects`]), which finds every hit through chapter
//! 9's tree ([`program_through`]).

pub mod density;
pub mod lane_use;
pub mod paths;
pub mod render;
pub mod starts;
pub mod terms;
pub mod window;

use ch06_path_tracing::PathProgram;
use ch09_many_spheres::Bvh;
use raylab_cli::Program;
use raylab_lanes::BvhX8;

pub use ch09_many_spheres::Objects;
pub use render::{lane_use, render_eight, render_eight_with_query};

/// Chapter 8's program: chapter 6's, with its defaults, rendered eight
/// paths at a time.
pub const PROGRAM: PathProgram = PathProgram {
    program: Program {
        binary: "ch08-eight-paths",
        about: "Chapter 8, eight paths at a time: chapter 6's path-traced image, to the byte, \
                traced in 8-wide SIMD lanes. --objects tree finds every hit through chapter 9's \
                tree of boxes.",
        max_depth: 10,
        spp: 256,
    },
    render: render_eight,
};

// ANCHOR: tree
/// Chapter 8's program, its hits found as `objects` says: the renderer
/// is chosen here, once for the whole render. With `--objects tree` it is
/// [`render_eight_with_query`] over chapter 9's tree, built first (the
/// build is part of the time): the paths search it eight at a time
/// ([`BvhX8`]), the photons one at a time. The same bytes.
pub fn program_through(objects: Objects) -> PathProgram {
    PathProgram {
        render: match objects {
            Objects::List => render_eight,
            Objects::Tree => |scene, camera, settings, progress| {
                let tree = Bvh::build(scene);
                render_eight_with_query(scene, &BvhX8::new(&tree), camera, settings, progress)
            },
        },
        ..PROGRAM
    }
}
// ANCHOR_END: tree
