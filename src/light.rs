//! Where the light comes from: a sky that fills every direction, and a sun.

use crate::Vec3;

/// The sky seen along a direction: pale at the horizon, deep blue overhead.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    /// The radiance of a ray level with the ground, or below it.
    pub horizon: Vec3,
    /// The radiance of a ray straight up.
    pub zenith: Vec3,
}

impl Sky {
    // ANCHOR: sky
    /// The radiance arriving from unit direction `d`.
    #[inline]
    pub fn radiance(&self, d: Vec3) -> Vec3 {
        // ANCHOR: todo_sky "With t = sqrt(clamp(d.y, 0, 1)), return (1 − t) · horizon + t · zenith."
        // The square root widens the bright band near the horizon.
        let t = d.y.clamp(0.0, 1.0).sqrt();
        (1.0 - t) * self.horizon + t * self.zenith
        // ANCHOR_END: todo_sky
    }
    // ANCHOR_END: sky

    // ANCHOR: sky_irradiance
    /// The irradiance the whole sky gives a horizontal surface facing up
    /// with nothing in its way: `π (0.2 · horizon + 0.8 · zenith)`.
    ///
    /// `E = ∫ sky(ω) cos θ dω` over the upper hemisphere. The sky depends
    /// only on `μ = cos θ = d.y`, and `dω = dμ dφ`, so
    /// `E = 2π ∫₀¹ ((1 − √μ) horizon + √μ zenith) μ dμ`
    /// `  = 2π (horizon (1/2 − 2/5) + zenith · 2/5) = π (0.2 horizon + 0.8 zenith)`.
    pub fn irradiance_facing_up(&self) -> Vec3 {
        std::f32::consts::PI * (0.2 * self.horizon + 0.8 * self.zenith)
    }
    // ANCHOR_END: sky_irradiance
}

/// A directional light: infinitely far away, so every point sees it along
/// the same direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sun {
    /// Unit vector from a surface towards the sun (`L`).
    pub direction: Vec3,
    /// Its brightness `E`.
    pub brightness: f32,
}

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;

    const LAB_SKY: Sky = Sky {
        horizon: Vec3::new(0.85, 0.90, 1.00),
        zenith: Vec3::new(0.25, 0.45, 0.85),
    };

    #[test]
    fn the_sky_at_the_horizon_is_the_horizon_colour() {
        assert_eq!(LAB_SKY.radiance(Vec3::X), LAB_SKY.horizon);
        // Below the horizon the sky does not get darker: d.y is clamped to 0.
        assert_eq!(LAB_SKY.radiance(Vec3::NEG_Y), LAB_SKY.horizon);
    }

    #[test]
    fn the_sky_at_the_zenith_is_the_zenith_colour() {
        assert_eq!(LAB_SKY.radiance(Vec3::Y), LAB_SKY.zenith);
    }

    #[test]
    fn the_sky_a_quarter_up_is_half_way_between() {
        // d.y = 0.25 gives t = sqrt(0.25) = 0.5.
        let d = Vec3::new((1.0f32 - 0.0625).sqrt(), 0.25, 0.0);
        let mid = 0.5 * (LAB_SKY.horizon + LAB_SKY.zenith);
        assert!(LAB_SKY.radiance(d).abs_diff_eq(mid, 1e-6));
    }

    /// the lab sky gives open ground an irradiance of π · (0.37, 0.54, 0.88)
    #[test]
    fn the_lab_sky_gives_open_ground_an_irradiance_of_pi_times_0_37_0_54_0_88() {
        let e = LAB_SKY.irradiance_facing_up();
        let expected = std::f32::consts::PI * Vec3::new(0.37, 0.54, 0.88);
        assert!(e.abs_diff_eq(expected, 1e-6), "{e}");
    }

    #[test]
    fn the_sky_irradiance_closed_form_matches_a_numerical_integral() {
        // Midpoint rule in μ = cos θ: E = 2π ∫ sky(μ) μ dμ.
        let n = 100_000;
        let mut sum = Vec3::ZERO;
        for k in 0..n {
            let mu = (k as f32 + 0.5) / n as f32;
            let d = Vec3::new((1.0 - mu * mu).sqrt(), mu, 0.0);
            sum += LAB_SKY.radiance(d) * mu;
        }
        let numeric = 2.0 * std::f32::consts::PI * sum / n as f32;
        assert!(
            numeric.abs_diff_eq(LAB_SKY.irradiance_facing_up(), 1e-4),
            "{numeric}"
        );
    }
}
// ANCHOR_END: tests
