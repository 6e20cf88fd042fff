//! # raylab: the skeleton of a Whitted-style ray tracer
//!
//! Everything the workbook's steps share: vectors (glam), rays, the lab's
//! shapes and scene, the pinhole camera, the ray stack and its tracing
//! loop, sampling, rendering on every core, image encoding, and eight
//! vectors side by side for the eight-lane tracers. A chapter
//! crate supplies one thing, a [`Step`]: what happens when a ray hits a
//! surface.
//!
//! Nothing here draws a figure, reads a file or parses a command line: the
//! program around a step is `raylab-cli`'s, and its figures are drawn with
//! `raylab-plot`.
//!
//! `../shared/LAB.md` in the workbook defines every formula used here.

pub mod camera;
pub mod lanes;
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
/// needs three. That alone made chapters 4 and 5 over 20 % faster.
pub use glam::Vec3A as Vec3;
pub use indicatif;

pub use camera::Camera;
pub use material::Material;
pub use outputs::{Keep, PixelMaps};
pub use ray::{Ray, RayKind};
pub use render::{Rendered, Settings, render, render_every_depth};
pub use sampling::{Pattern, Sampling};
pub use scene::{Hit, Object, Scene};
pub use trace::{Step, Surface, Tracer};
