//! # raylab: the skeleton of a Whitted-style ray tracer
//!
//! Everything the workbook's steps share: vectors (glam), rays, the lab's
//! shapes and scene, the pinhole camera, the ray stack and its tracing
//! loop, sampling, rendering on every core and image encoding. A chapter
//! crate supplies one thing, a [`Step`]: what happens when a ray hits a
//! surface. Everything here is scalar, one ray at a time; the tracers that
//! work eight rays at a time are beside it (`raylab-lanes`, chapters 7 and
//! 8), never in it.
//!
//! ## What to read, in order
//!
//! 1. [`ray`]: a point that moves along a unit direction;
//! 2. [`sphere`] and [`plane`]: where a ray meets the lab's two shapes,
//!    and the checker;
//! 3. [`material`] and [`light`]: what a surface does with light, the sky
//!    and the sun;
//! 4. [`scene`]: the lab scene, the nearest hit and the hit record;
//! 5. [`camera`]: the ray through a pixel;
//! 6. [`optics`]: `reflect` and `refract`;
//! 7. [`stack`] and [`trace`]: the ray stack and its loop, and the
//!    [`Step`] seam a chapter plugs into;
//! 8. [`sampling`] and [`render`](mod@render): where a pixel's rays go, and a whole
//!    image on every core.
//!
//! ## Plumbing you may skip
//!
//! [`frame`] (what a render is asked for and gives back), [`outputs`]
//! (each row written straight into the image), [`srgb`] and
//! [`linear_image`] (encoding, with a table that is checked against the
//! formula for every `f32`), [`probe`] (one pixel's ray tree, for the
//! diagrams), the tracer's bookkeeping beside its loop (`src/trace/record.rs`:
//! rays counted by kind, the probe's log, the per-depth colours) and
//! [`tolerance`] (how close two correct images must be).
//!
//! Nothing here draws a figure, reads a file or parses a command line: the
//! program around a step is `raylab-cli`'s, and its figures are drawn with
//! `raylab-plot`. The lab model (the book's appendix)
//! defines every formula used here.

#![warn(missing_docs)]

pub mod camera;
pub mod frame;
pub mod light;
pub mod linear_image;
pub mod material;
pub mod optics;
pub mod outputs;
pub mod plane;
pub mod probe;
pub mod ray;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod sphere;
pub mod srgb;
pub mod stack;
pub mod tolerance;
pub mod trace;

/// The vector of every point, direction and colour: glam's `Vec3A`, a
/// `Vec3` padded to 16 bytes so that it fills one SIMD register (SSE2 on
/// x86-64, NEON on ARM). The arithmetic is the same as `Vec3`'s, lane by
/// lane, but it loads, stores and adds in one instruction where `Vec3`
/// needs three.
pub use glam::Vec3A as Vec3;

pub use camera::Camera;
pub use frame::{Keep, PixelMaps, Rendered, Settings};
pub use material::Material;
pub use ray::{Ray, RayKind};
pub use render::{NoProgress, Progress, render, render_every_depth, render_with_query};
pub use sampling::{Pattern, Sampling};
pub use scene::{Hit, Object, Scene, SceneQuery};
pub use trace::{Step, Surface, Tracer};
