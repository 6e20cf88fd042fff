//! What the bench accepts: the largest image, and the offset of shadow and
//! secondary rays. The flags and the scene files check against the same
//! numbers.

/// The largest image side accepted.
pub const MAX_SIDE: u32 = 16_384;
/// The most pixels accepted in all: 64 Mi (8192 × 8192).
pub const MAX_PIXELS: u64 = 64 * 1024 * 1024;

/// The lab's offset of shadow and secondary rays, in scene units.
pub const DEFAULT_EPSILON: f32 = 1e-4;
/// The largest offset `--epsilon` or a scene file may ask for.
pub const MAX_EPSILON: f32 = 0.1;
