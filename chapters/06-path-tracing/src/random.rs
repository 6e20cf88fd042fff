//! The path's random numbers: uniform floats from the sample's generator.

use rand_core::Rng;
use rand_pcg::Pcg32;

/// One sample's stream of random numbers in [0, 1).
pub struct Random(pub Pcg32);

impl Random {
    /// A uniform number in [0, 1): the top 24 bits of the next output, the
    /// most an `f32` below 1 can hold, so that 1.0 itself never comes out.
    #[inline]
    pub fn next(&mut self) -> f32 {
        (self.0.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
    }
}
