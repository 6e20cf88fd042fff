//! The sky along eight directions at once.

use raylab::light::Sky;
use wide::{CmpGt, CmpLt, f32x8};

use crate::vec3x8::Vec3x8;

/// The lab's sky, its two colours in all eight lanes.
#[derive(Clone, Copy, Debug)]
pub struct SkyX8 {
    horizon: Vec3x8,
    zenith: Vec3x8,
}

impl SkyX8 {
    /// The scalar sky's two colours, in every lane.
    pub fn new(sky: &Sky) -> Self {
        SkyX8 {
            horizon: Vec3x8::splat(sky.horizon),
            zenith: Vec3x8::splat(sky.zenith),
        }
    }

    // ANCHOR: sky
    /// The radiance arriving from eight unit directions (`Sky::radiance`).
    #[inline]
    pub fn radiance(&self, d: Vec3x8) -> Vec3x8 {
        // `f32::clamp(0, 1)` exactly: a NaN stays NaN, and −0 stays −0.
        let y = d.y.cmp_lt(f32x8::ZERO).blend(f32x8::ZERO, d.y);
        let y = d.y.cmp_gt(f32x8::ONE).blend(f32x8::ONE, y);
        let t = y.sqrt();
        self.horizon.scale(f32x8::ONE - t) + self.zenith.scale(t)
    }
    // ANCHOR_END: sky
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::{Scene, Vec3};

    #[test]
    fn the_sky_of_eight_directions_is_the_scalar_sky_nan_and_minus_zero_included() {
        let scene = Scene::lab();
        let d: [Vec3; 8] = std::array::from_fn(|i| {
            let a = i as f32 * 0.37;
            Vec3::new(a.sin(), 0.2 + 0.1 * i as f32, a.cos()).normalize()
        });
        let mut d = d;
        d[0].y = -0.0;
        d[1].y = f32::NAN;
        d[2].y = -0.5;
        d[3].y = 1.5;
        let sky = SkyX8::new(&scene.sky).radiance(Vec3x8::from_lanes(d));
        for (lane, &d) in d.iter().enumerate() {
            let (wide, scalar) = (sky.lane(lane), scene.sky.radiance(d));
            let bits = |v: Vec3| v.to_array().map(f32::to_bits);
            assert_eq!(bits(wide), bits(scalar), "lane {lane}: {d}");
        }
    }
}
