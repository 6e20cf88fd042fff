//! Where the light comes from: a sky that fills every direction, and a sun.

use crate::Vec3;

/// The sky seen along a direction: pale at the horizon, deep blue overhead.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    pub horizon: Vec3,
    pub zenith: Vec3,
}

impl Sky {
    // ANCHOR: sky
    /// The radiance arriving from unit direction `d`.
    pub fn radiance(&self, d: Vec3) -> Vec3 {
        // The square root widens the bright band near the horizon.
        let t = d.y.clamp(0.0, 1.0).sqrt();
        (1.0 - t) * self.horizon + t * self.zenith
    }
    // ANCHOR_END: sky
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
}
