//! The path's random numbers: uniform floats from the sample's generator.

use rand_pcg::Pcg32;
use raylab::sampling::unit_f32;

/// One sample's stream of random numbers in [0, 1).
pub struct Random(pub Pcg32);

impl Random {
    /// A uniform number in [0, 1) (1.0 itself never comes out).
    #[inline]
    pub fn uniform(&mut self) -> f32 {
        unit_f32(&mut self.0)
    }
}
