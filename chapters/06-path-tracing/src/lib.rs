//! Chapter 6: the rendering equation, solved.
//!
//! The Whitted chapters approximate the light at a surface by a sum of a
//! few terms: the sun through one shadow ray, a constant for everything
//! else, a mirror ray and a refracted ray. This chapter computes what those
//! terms stand in for, by Monte Carlo path tracing of the same scene: the
//! sky lights the scene, light bounces between matte surfaces, shadows get
//! the light they really receive, and the sun may be a disc. Every pixel
//! is the average of many random paths, so the image is noisy, and the
//! noise itself is measured (`variance.exr`).
//!
//! A path's throughput is a colour, not the Whitted tracer's scalar weight,
//! and a path follows one direction per surface rather than a tree: the
//! chapter has its own integrator ([`integrator`]) and its own render loop
//! ([`render`]) instead of a `raylab::Step`.

pub mod agreement;
pub mod caustics;
pub mod exr;
pub mod integrator;
pub mod photons;
pub mod pixel;
pub mod random;
pub mod render;
pub mod run;
pub mod sun;

pub use integrator::{Materials, PathTracer, Terms};
pub use render::{PathRender, PathSettings, path_frame, render_paths, render_paths_with_query};
pub use run::{Flags, PROGRAM, PathProgram, main, run, run_matches};
