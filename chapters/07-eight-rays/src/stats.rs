//! How busy the eight lanes are, wave by wave: statistics of a render for
//! the book's figures. Not part of the render: it traces the image again,
//! wave by wave as the render does, and counts.

use raylab::{Camera, Scene, Settings};
use raylab_lanes::SceneX8;
use rayon::prelude::*;

use crate::EightRays;
use crate::camera::{Primary, PrimaryRays};
use crate::shade::Light;
use crate::soa::LANES;
use crate::wave::{Setup, Waves};

/// One depth's wave, summed over every row of an image.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WaveStats {
    /// Rays traced in this wave (shadow rays are not counted).
    pub rays: u64,
    /// The groups of eight they were packed into: each row's wave is
    /// packed densely, so only its last group can be part empty.
    pub groups: u64,
    /// The samples with a ray at this depth: the busy lanes if every
    /// sample kept its own lane all the way down, as a fragment shader's
    /// invocation does.
    pub busy_in_place: u64,
    /// The groups of eight neighbouring samples with at least one such
    /// lane: the groups that would still be running at this depth.
    pub groups_in_place: u64,
}

impl WaveStats {
    /// The share of the lanes of the groups traced that hold a ray, packed.
    pub fn packed_share(&self) -> f64 {
        share(self.rays, self.groups)
    }

    /// The same share if each sample's rays stayed in its lane.
    pub fn in_place_share(&self) -> f64 {
        share(self.busy_in_place, self.groups_in_place)
    }
}

fn share(busy: u64, groups: u64) -> f64 {
    if groups == 0 {
        0.0
    } else {
        busy as f64 / (groups * LANES as u64) as f64
    }
}

impl std::ops::Add for WaveStats {
    type Output = WaveStats;
    fn add(self, o: WaveStats) -> WaveStats {
        WaveStats {
            rays: self.rays + o.rays,
            groups: self.groups + o.groups,
            busy_in_place: self.busy_in_place + o.busy_in_place,
            groups_in_place: self.groups_in_place + o.groups_in_place,
        }
    }
}

/// Every wave of a render as `step`'s chapter traces it: entry `k` is wave
/// `k + 1`, the rays at depth `k + 1`.
pub fn wave_stats(
    scene: &Scene,
    camera: &Camera,
    step: &EightRays,
    settings: &Settings,
) -> Vec<WaveStats> {
    let features = step.like.features();
    let setup = Setup {
        primary: Primary::new(camera, settings),
        scene: SceneX8::new(scene).with_optics(features.reflection, features.transmission),
        light: Light::new(scene),
        features,
        max_depth: settings.max_depth,
        epsilon: settings.epsilon,
        maps: true,
    };
    let samples = settings.width as usize * settings.sampling.spp() as usize;
    let depths = settings.max_depth as usize;
    (0..settings.height)
        .into_par_iter()
        .map_init(Waves::default, |waves, j| {
            waves.start(samples, &setup);
            let ends =
                waves.trace_noting_waves(&setup, &PrimaryRays::new(&setup.primary, settings, j));
            let mut row = vec![WaveStats::default(); depths];
            let mut before = 0;
            for (wave, &end) in row.iter_mut().zip(&ends) {
                let rays = (end - before) as u64;
                before = end;
                wave.rays = rays;
                wave.groups = rays.div_ceil(LANES as u64);
            }
            for lanes in waves.sample_deepest.chunks(LANES) {
                for (depth, wave) in row.iter_mut().enumerate() {
                    let busy = lanes.iter().filter(|&&d| usize::from(d) > depth).count() as u64;
                    wave.busy_in_place += busy;
                    wave.groups_in_place += u64::from(busy > 0);
                }
            }
            row
        })
        .reduce(
            || vec![WaveStats::default(); depths],
            |a, b| a.into_iter().zip(b).map(|(a, b)| a + b).collect(),
        )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Like;
    use raylab::{Keep, NoProgress, RayKind, Sampling};

    #[test]
    fn the_waves_hold_every_ray_the_render_counts_and_the_first_is_full() {
        let (scene, camera) = (Scene::lab(), Camera::lab());
        let step = EightRays {
            like: Like::Refraction,
        };
        let settings = Settings {
            width: 64,
            height: 48,
            max_depth: 10,
            epsilon: 1e-4,
            sampling: Sampling::PIXEL_CENTRE,
        };
        let stats = wave_stats(&scene, &camera, &step, &settings);
        let rendered = crate::render::render_waves(
            &scene,
            &camera,
            &step,
            &settings,
            Keep::IMAGE,
            &NoProgress,
        );
        let counts = rendered.counts;
        let traced: u64 = stats.iter().map(|w| w.rays).sum();
        assert_eq!(traced, counts.total() - counts.get(RayKind::Shadow));
        // Wave 1: every pixel's ray, 64 / 8 = 8 full groups a row.
        assert_eq!(stats[0].rays, 64 * 48);
        assert_eq!(stats[0].groups, 8 * 48);
        assert_eq!(stats[0].packed_share(), 1.0);
        assert_eq!(stats[0].in_place_share(), 1.0);
        // Deeper, packing keeps the groups fuller than lanes kept in place.
        assert!(stats[1].rays > 0);
        assert!(stats[1].packed_share() > stats[1].in_place_share());
    }
}
