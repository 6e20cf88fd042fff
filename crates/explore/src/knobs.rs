//! The knobs a learner turns: which chapter traces, how deep, how many
//! rays per pixel, the offset, and chapter 6's sun and materials.

use ch06_path_tracing::Materials;
use ch07_eight_rays::{EightRays, Like};
use raylab::Settings;
use raylab::sampling::{Pattern, Sampling, SamplingError};

/// The counts of rays (or paths) per pixel the `r` key steps through: the
/// pixel centre, the lab's five, then squares for the jittered pattern.
pub const SPP_STEPS: [u32; 6] = [1, 5, 16, 64, 256, 1024];

/// The sun's sizes the `[` and `]` keys step through, in degrees: a point,
/// the real sun, then ever larger discs whose shadows blur.
pub const SUN_SIZES: [Option<f32>; 5] = [None, Some(0.53), Some(5.0), Some(20.0), Some(45.0)];

/// The lab's offset for secondary and shadow rays (the lab model).
pub const LAB_EPSILON: f32 = 1e-4;

/// Chapter 6's default count of paths per pixel.
pub const PATHS_DEFAULT: u32 = 256;

/// Everything the keys set, apart from the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Knobs {
    /// The Whitted chapter traced (chapters 1–5), and the one whose ray
    /// tree a click shows in path tracing, where a path has no tree.
    pub like: Like,
    /// Chapter 6: path tracing instead of the ray stack.
    pub paths: bool,
    pub max_depth: u32,
    /// Rays per pixel of a still Whitted frame, or the paths per pixel at
    /// which path tracing stops accumulating.
    pub spp: u32,
    pub epsilon: f32,
    pub sun_size: Option<f32>,
    pub materials: Materials,
    pub help: bool,
}

impl Default for Knobs {
    /// Chapter 5 with its defaults: the lab's picture.
    fn default() -> Knobs {
        let mut knobs = Knobs {
            like: Like::AntiAliasing,
            paths: false,
            max_depth: 10,
            spp: 5,
            epsilon: LAB_EPSILON,
            sun_size: None,
            materials: Materials::Lab,
            help: false,
        };
        knobs.chapter(5);
        knobs
    }
}

impl Knobs {
    /// Switch to chapter `n` (1–5 Whitted, 6 path tracing) with that
    /// chapter's own depth and rays per pixel, so that a still frame is
    /// what the chapter's program draws when given no flags.
    pub fn chapter(&mut self, n: u32) -> bool {
        match n {
            1..=5 => {
                self.like = Like::ALL[n as usize - 1];
                self.paths = false;
                let raylab_like::Defaults { max_depth, spp, .. } = self.like.defaults();
                self.max_depth = max_depth;
                self.spp = spp;
                true
            }
            6 => {
                self.paths = true;
                self.max_depth = 10;
                self.spp = PATHS_DEFAULT;
                true
            }
            _ => false,
        }
    }

    /// The chapter's number, 1 to 6.
    pub fn chapter_number(&self) -> u32 {
        if self.paths { 6 } else { self.like as u32 + 1 }
    }

    /// The program whose render a still frame reproduces.
    pub fn binary(&self) -> &'static str {
        if self.paths {
            ch08_eight_paths::PROGRAM.program.binary
        } else {
            self.like.binary()
        }
    }

    pub fn deeper(&mut self, by: i32) {
        let limit = raylab::stack::MAX_DEPTH_LIMIT as i64;
        self.max_depth = (i64::from(self.max_depth) + i64::from(by)).clamp(1, limit) as u32;
    }

    /// The next (or previous) count of [`SPP_STEPS`].
    pub fn step_spp(&mut self, forward: bool) {
        let at = SPP_STEPS.iter().position(|&n| n >= self.spp).unwrap_or(0);
        let next = if forward {
            (at + 1) % SPP_STEPS.len()
        } else {
            (at + SPP_STEPS.len() - 1) % SPP_STEPS.len()
        };
        self.spp = SPP_STEPS[next];
    }

    pub fn toggle_epsilon(&mut self) {
        self.epsilon = if self.epsilon == 0.0 {
            LAB_EPSILON
        } else {
            0.0
        };
    }

    pub fn step_sun(&mut self, forward: bool) {
        let at = SUN_SIZES
            .iter()
            .position(|&s| s == self.sun_size)
            .unwrap_or(0);
        let n = SUN_SIZES.len();
        self.sun_size = SUN_SIZES[if forward {
            (at + 1) % n
        } else {
            (at + n - 1) % n
        }];
    }

    pub fn toggle_materials(&mut self) {
        self.materials = match self.materials {
            Materials::Lab => Materials::Fresnel,
            Materials::Fresnel => Materials::Lab,
        };
    }

    /// The step chapter 7 traces with, as the chosen chapter.
    pub fn step(&self) -> EightRays {
        EightRays { like: self.like }
    }

    /// The settings of a Whitted frame of `width` × `height` at `spp` rays
    /// per pixel: the chapter program's own for the same flags (the
    /// default pattern, seed 0, the chapter's five points).
    pub fn whitted(&self, width: u32, height: u32, spp: u32) -> Result<Settings, SamplingError> {
        use raylab::Step;
        Ok(Settings {
            width,
            height,
            max_depth: self.max_depth,
            epsilon: self.epsilon,
            sampling: Sampling::new(spp, None, 0)?.with_lab_five(self.step().lab_five()),
        })
    }

    /// The settings of path-tracing pass `pass`: one random path per pixel,
    /// seeded by the pass, so that successive passes average to the image.
    pub fn path_pass(
        &self,
        width: u32,
        height: u32,
        pass: u32,
    ) -> Result<ch06_path_tracing::PathSettings, SamplingError> {
        Ok(ch06_path_tracing::PathSettings {
            width,
            height,
            sampling: Sampling::new(1, Some(Pattern::Random), u64::from(pass))?,
            max_depth: self.max_depth,
            epsilon: self.epsilon,
            materials: self.materials,
            sun_size: self.sun_size,
            caustics: false,
            photons_per_sphere: 0,
            keep_terms: false,
        })
    }

    /// The chapter's name as the overlay shows it.
    pub fn chapter_name(&self) -> &'static str {
        if self.paths {
            return "path tracing";
        }
        match self.like {
            Like::RayCast => "ray casting",
            Like::Shadows => "shadows",
            Like::Reflection => "reflection",
            Like::Refraction => "refraction",
            Like::AntiAliasing => "anti-aliasing",
        }
    }

    pub fn sun_name(&self) -> String {
        match self.sun_size {
            None => "point".into(),
            Some(d) => format!("{d}°"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_chapter_key_brings_that_chapters_defaults() {
        let mut knobs = Knobs::default();
        assert_eq!(
            (knobs.chapter_number(), knobs.max_depth, knobs.spp),
            (5, 10, 5)
        );
        knobs.chapter(1);
        assert_eq!(
            (knobs.max_depth, knobs.spp, knobs.binary()),
            (1, 1, "ch01-ray-cast")
        );
        knobs.chapter(6);
        assert!(knobs.paths);
        assert_eq!(knobs.binary(), "ch08-eight-paths");
        assert!(!knobs.chapter(7));
    }

    #[test]
    fn the_rays_per_pixel_key_goes_round() {
        let mut knobs = Knobs::default();
        knobs.step_spp(true);
        assert_eq!(knobs.spp, 16);
        knobs.step_spp(false);
        knobs.step_spp(false);
        assert_eq!(knobs.spp, 1);
        knobs.step_spp(false);
        assert_eq!(knobs.spp, 1024);
    }

    #[test]
    fn depth_stays_between_one_and_the_limit() {
        let mut knobs = Knobs::default();
        knobs.deeper(-100);
        assert_eq!(knobs.max_depth, 1);
        knobs.deeper(1000);
        assert_eq!(knobs.max_depth, raylab::stack::MAX_DEPTH_LIMIT);
    }
}
