//! The sun as chapter 6 sees it: a point in the sky (a delta light) or,
//! with `--sun-size D`, a disc of directions `D` degrees across, of uniform
//! radiance, giving the same irradiance `E_sun = 0.1 · E` (the lab model).

use std::f32::consts::PI;

use raylab::Vec3;
use raylab::light::Sun;

use crate::random::Random;

/// The largest `--sun-size`: a disc 180° across is the whole hemisphere
/// around `L`; a wider "disc" would wrap round onto itself.
pub const MAX_SUN_SIZE: f32 = 180.0;

/// The sun, ready to be sampled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sunlight {
    /// `L`, from a surface towards the sun's centre.
    pub direction: Vec3,
    /// `E_sun`: the irradiance on a surface facing the sun.
    pub irradiance: f32,
    /// Two unit vectors at right angles to `L` and to each other.
    tangent: Vec3,
    bitangent: Vec3,
    /// `1 − cos(D/2)` of the disc, 0 for a point. Kept in this form (from
    /// `2 sin²(D/4)`) because for a tiny disc `cos(D/2)` rounds to 1.
    one_minus_cos: f32,
}

impl Sunlight {
    /// The scene's sun, as a point (`size_degrees = None`) or a disc.
    ///
    /// # Panics
    /// If the size is not in `(0, MAX_SUN_SIZE]` (the command line checks).
    pub fn new(sun: &Sun, size_degrees: Option<f32>) -> Sunlight {
        let one_minus_cos = size_degrees.map_or(0.0, |d| {
            assert!(d > 0.0 && d <= MAX_SUN_SIZE, "sun size {d}");
            2.0 * (d.to_radians() / 4.0).sin().powi(2)
        });
        let (tangent, bitangent) = sun.direction.any_orthonormal_pair();
        Sunlight {
            direction: sun.direction,
            irradiance: 0.1 * sun.brightness,
            tangent,
            bitangent,
            one_minus_cos,
        }
    }

    /// `1 − cos(D/2)`: the disc's radius as [`Sunlight::radiance_along`]
    /// compares it (0 for a point).
    pub fn one_minus_cos(&self) -> f32 {
        self.one_minus_cos
    }

    /// Whether the sun is a single direction.
    pub fn is_point(&self) -> bool {
        self.one_minus_cos == 0.0
    }

    /// `Ω = 2π (1 − cos(D/2))`, the disc's solid angle (0 for a point).
    pub fn solid_angle(&self) -> f32 {
        2.0 * PI * self.one_minus_cos
    }

    /// The disc's radiance `E_sun / Ω` (infinite for a point: never used).
    pub fn radiance(&self) -> f32 {
        self.irradiance / self.solid_angle()
    }

    /// The sun's radiance seen along unit direction `d`: `E_sun / Ω` inside
    /// the disc, 0 outside it and always 0 for a point sun (a ray never
    /// hits a single direction).
    pub fn radiance_along(&self, d: Vec3) -> f32 {
        // |d − L|² = 2 (1 − cos θ): exact for small angles, where 1 − d·L
        // would be lost to rounding.
        if !self.is_point() && (d - self.direction).length_squared() <= 2.0 * self.one_minus_cos {
            self.radiance()
        } else {
            0.0
        }
    }

    // ANCHOR: sample
    /// A direction towards the sun, uniform over its disc, from two uniform
    /// numbers: `L` itself for a point sun. With this density (`1/Ω`) the
    /// sun's light on a surface is estimated by `E_sun · cos θ`, whatever
    /// the disc's size.
    pub fn sample(&self, u1: f32, u2: f32) -> Vec3 {
        if self.is_point() {
            return self.direction;
        }
        // a = 1 − cos θ uniform in [0, 1 − cos(D/2)]: uniform in solid angle.
        let a = u1 * self.one_minus_cos;
        let sin_theta = (a * (2.0 - a)).max(0.0).sqrt();
        let (sin_phi, cos_phi) = (2.0 * PI * u2).sin_cos();
        let d = (1.0 - a) * self.direction
            + sin_theta * (cos_phi * self.tangent + sin_phi * self.bitangent);
        d.normalize()
    }

    /// [`Sunlight::sample`] with the path's random numbers, drawn only for
    /// a disc: a point sun is one direction, and takes none.
    pub fn draw(&self, random: &mut Random) -> Vec3 {
        if self.is_point() {
            self.direction
        } else {
            self.sample(random.uniform(), random.uniform())
        }
    }
    // ANCHOR_END: sample
}
