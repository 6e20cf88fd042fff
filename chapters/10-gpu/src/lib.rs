//! Chapter 10: the lab as it ran — the tracer as a WGSL shader.
//!
//! The lab's tracer was a shader: the GPU ran it once per pixel, thousands
//! of pixels at a time. This chapter runs the tracer of chapters 1–5 the
//! same way, written in WGSL (`src/tracer.wgsl`) as a compute shader with
//! one invocation per pixel, through wgpu:
//!
//! - [`shader`]: the tracer's source, and naga's check of it (a mistake
//!   is one line, `tracer.wgsl:57:12: …`);
//! - [`scene_buffer`]: the core's `Scene` and `Camera` packed as the
//!   shader reads them;
//! - [`gpu`]: the adapter (lavapipe on a CPU), the compiled tracer, and a
//!   frame — dispatch and readback;
//! - [`run`]: one render, encoded by the core's sRGB encoder and written
//!   as every chapter writes it;
//! - [`watch`]: `--watch`, which compiles the shader again on every save;
//! - [`like`]: `--like chNN-…`, which of chapters 1–5 it traces as.
//!
//! # Where it differs from the CPU chapters
//!
//! The formulas are the lab model's, in the same order, but the arithmetic is
//! the GPU's: WGSL's `normalize`, `reflect`, `refract` and `sqrt` are the
//! driver's, which may compute `1/√x` another way or fuse a multiply and
//! an add, so a few values differ in their last bit. Where that moves a
//! grazing ray onto another checker square or the other side of an edge,
//! a pixel changes; the lab model's tolerance (99.5 % of pixels within 3 levels,
//! mean difference under 0.5) is the bar, and the tests hold the shader
//! to it against chapters 1–5. Smaller differences: the shader counts
//! rays in 32-bit numbers per image row; `--pattern` jittered, random and
//! halton (points drawn per pixel on the CPU) are refused; and the ray
//! stack has `--max-depth` places, written into the shader's `STACK_SIZE`
//! line before it is compiled, where the core's has room for any depth
//! (a GPU pays for every place, in every invocation).

pub mod cli;
pub mod gpu;
pub mod like;
pub mod run;
pub mod scene_buffer;
pub mod shader;
pub mod watch;

pub use like::Like;

/// The program's name, which is also its default output folder.
pub const BINARY: &str = "ch10-gpu";
