//! The camera's rays for a whole row, eight at a time.

use raylab::{Camera, RayKind, Settings};
use wide::f32x8;

use crate::soa::{LANES, Rays, Vec3x8};

// ANCHOR: primary
/// Every sample's primary ray of row `j`, in the order pixel by pixel and
/// within a pixel in the pattern's order: sample `i · spp + k` is pixel
/// `i`'s `k`-th ray. The arithmetic is `Camera::ray`'s, operation for
/// operation, so the directions are the same to the bit.
pub fn primary_rays(camera: &Camera, j: u32, settings: &Settings, rays: &mut Rays) {
    let spp = settings.sampling.spp() as usize;
    let (w, h) = (settings.width as f32, settings.height as f32);
    let aspect = w / h;
    let half_height = f32x8::splat(camera.half_height());
    let (forward, right, up) = (
        Vec3x8::splat(camera.forward()),
        Vec3x8::splat(camera.right()),
        Vec3x8::splat(camera.up()),
    );
    let eye = Vec3x8::splat(camera.eye);
    let samples = settings.width as usize * spp;
    for first in (0..samples).step_by(LANES) {
        let count = (samples - first).min(LANES);
        // Where in the image each lane's sample lies, in pixels.
        let mut column = [0.0f32; LANES];
        let mut row = [0.0f32; LANES];
        let mut ids = [0u32; LANES];
        for lane in 0..count {
            let sample = first + lane;
            let i = sample / spp;
            let (sx, sy) = settings
                .sampling
                .offset((i as u32, j), (sample % spp) as u32);
            column[lane] = i as f32 + sx;
            row[lane] = j as f32 + sy;
            ids[lane] = sample as u32;
        }
        let two = f32x8::splat(2.0);
        let x = (two * f32x8::from(column) / f32x8::splat(w) - f32x8::ONE)
            * half_height
            * f32x8::splat(aspect);
        let y = (f32x8::ONE - two * f32x8::from(row) / f32x8::splat(h)) * half_height;
        let direction = (forward + right.scale(x) + up.scale(y)).normalize();
        rays.push_lanes(eye, direction, f32x8::ONE, &ids[..count], RayKind::Primary);
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
            let mut rays = Rays::default();
            primary_rays(&camera, j, &settings, &mut rays);
            assert_eq!(rays.len(), 13 * 5);
            rays.pad();
            for s in 0..rays.len() {
                let i = s / 5;
                let offset = settings.sampling.offset((i as u32, j), (s % 5) as u32);
                let expected = camera.ray(i as u32, j, offset, 13, 7);
                let (group, lane) = (s / LANES, s % LANES);
                assert_eq!(rays.directions(group).lane(lane), expected.direction);
                assert_eq!(rays.origins(group).lane(lane), expected.origin);
            }
        }
    }
}
