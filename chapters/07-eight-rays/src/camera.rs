//! The camera's rays for a whole row, eight at a time.

use raylab::{Camera, RayKind, Settings};
use wide::f32x8;

use crate::soa::{Group, LANES, Vec3x8};
use crate::wave::END;

// ANCHOR: primary
/// Every sample's primary ray of row `j`, eight at a time, in the order
/// pixel by pixel and within a pixel in the pattern's order: sample
/// `i · spp + k` is pixel `i`'s `k`-th ray. The rays are made in registers
/// when wave 1 traces them, never stored. The arithmetic is `Camera::ray`'s,
/// operation for operation, so the directions are the same to the bit.
pub struct PrimaryRays<'a> {
    settings: &'a Settings,
    j: u32,
    spp: usize,
    size: (f32x8, f32x8),
    aspect: f32x8,
    half_height: f32x8,
    forward: Vec3x8,
    right: Vec3x8,
    up: Vec3x8,
    eye: Vec3x8,
}

impl<'a> PrimaryRays<'a> {
    pub fn new(camera: &Camera, settings: &'a Settings, j: u32) -> Self {
        let (w, h) = (settings.width as f32, settings.height as f32);
        PrimaryRays {
            settings,
            j,
            spp: settings.sampling.spp() as usize,
            size: (f32x8::splat(w), f32x8::splat(h)),
            aspect: f32x8::splat(w / h),
            half_height: f32x8::splat(camera.half_height()),
            forward: Vec3x8::splat(camera.forward()),
            right: Vec3x8::splat(camera.right()),
            up: Vec3x8::splat(camera.up()),
            eye: Vec3x8::splat(camera.eye),
        }
    }

    /// How many samples (primary rays) the row has.
    pub fn len(&self) -> usize {
        self.settings.width as usize * self.spp
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Samples `8 · group ..`, the last group's padding lanes aimed at the
    /// row's first pixel (traced, and thrown away).
    pub fn group(&self, group: usize) -> Group {
        let first = group * LANES;
        let count = (self.len() - first).min(LANES);
        // Where in the image each lane's sample lies, in pixels.
        let mut column = [0.0f32; LANES];
        let mut row = [0.0f32; LANES];
        let mut sample = [0u32; LANES];
        let (mut i, mut k) = (first / self.spp, first % self.spp);
        // What a pixel's samples share (a random pattern's hash of the
        // pixel), worked out once per pixel rather than once per sample.
        let sampling = &self.settings.sampling;
        let mut pixel = sampling.pixel((i as u32, self.j));
        for lane in 0..count {
            let (sx, sy) = pixel.offset(k as u32);
            column[lane] = i as f32 + sx;
            row[lane] = self.j as f32 + sy;
            sample[lane] = (first + lane) as u32;
            k += 1;
            if k == self.spp && lane + 1 < count {
                (i, k) = (i + 1, 0);
                pixel = sampling.pixel((i as u32, self.j));
            }
        }
        let two = f32x8::splat(2.0);
        let (w, h) = self.size;
        let x = (two * f32x8::from(column) / w - f32x8::ONE) * self.half_height * self.aspect;
        let y = (f32x8::ONE - two * f32x8::from(row) / h) * self.half_height;
        let direction = (self.forward + self.right.scale(x) + self.up.scale(y)).normalize();
        Group {
            origin: self.eye,
            direction,
            weight: f32x8::ONE,
            sample,
            kind: [RayKind::Primary; LANES],
            // A primary ray's sample is done once its tree is.
            after: [END; LANES],
        }
    }
}
// ANCHOR_END: primary

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Sampling;

    #[test]
    fn eight_camera_rays_at_a_time_are_camera_ray_to_the_bit() {
        let camera = Camera::lab();
        let settings = Settings {
            width: 13,
            height: 7,
            max_depth: 1,
            epsilon: 1e-4,
            sampling: Sampling::LAB_FIVE,
        };
        for j in 0..7 {
            let rays = PrimaryRays::new(&camera, &settings, j);
            assert_eq!(rays.len(), 13 * 5);
            for s in 0..rays.len() {
                let i = s / 5;
                let offset = settings.sampling.offset((i as u32, j), (s % 5) as u32);
                let expected = camera.ray(i as u32, j, offset, 13, 7);
                let group = rays.group(s / LANES);
                let lane = s % LANES;
                assert_eq!(group.direction.lane(lane), expected.direction);
                assert_eq!(group.origin.lane(lane), expected.origin);
                assert_eq!(group.sample[lane], s as u32);
            }
        }
    }
}
