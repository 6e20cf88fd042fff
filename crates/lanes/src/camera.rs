//! The pinhole camera, eight rays at a time.

use raylab::Camera;
use wide::f32x8;

use crate::vec3x8::Vec3x8;

/// What every camera ray of an image shares, in all eight lanes: eight
/// camera rays at once, operation for operation as `Camera::ray` makes one,
/// so the directions are the same to the bit.
#[derive(Clone, Copy, Debug)]
pub struct CameraX8 {
    /// The camera's eye in every lane: where every primary ray starts.
    pub eye: Vec3x8,
    size: (f32x8, f32x8),
    aspect: f32x8,
    half_height: f32x8,
    forward: Vec3x8,
    right: Vec3x8,
    up: Vec3x8,
}

impl CameraX8 {
    /// The camera's rays for a `width` × `height` image, eight at a time.
    pub fn new(camera: &Camera, width: u32, height: u32) -> Self {
        let (w, h) = (width as f32, height as f32);
        CameraX8 {
            eye: Vec3x8::splat(camera.eye),
            size: (f32x8::splat(w), f32x8::splat(h)),
            aspect: f32x8::splat(w / h),
            half_height: f32x8::splat(camera.half_height()),
            forward: Vec3x8::splat(camera.forward()),
            right: Vec3x8::splat(camera.right()),
            up: Vec3x8::splat(camera.up()),
        }
    }

    /// The unit directions through image points (`i + sx`, `j + sy`), in
    /// pixels, one per lane.
    #[inline]
    pub fn directions(&self, column: f32x8, row: f32x8) -> Vec3x8 {
        self.through(self.across(column), self.down(row))
    }

    /// The part of a direction that depends only on the point's column:
    /// `forward + right · x`. The same for every row, so a tracer that
    /// makes the same columns in every row can work it out once.
    #[inline]
    pub fn across(&self, column: f32x8) -> Vec3x8 {
        let two = f32x8::splat(2.0);
        let x = (two * column / self.size.0 - f32x8::ONE) * self.half_height * self.aspect;
        self.forward + self.right.scale(x)
    }

    /// The part that depends only on the point's row: `y`, the distance
    /// up the image plane.
    #[inline]
    pub fn down(&self, row: f32x8) -> f32x8 {
        let two = f32x8::splat(2.0);
        (f32x8::ONE - two * row / self.size.1) * self.half_height
    }

    /// The unit direction from the two parts: `forward + right · x + up ·
    /// y`, added in that order as `Camera::ray` adds them, and normalised.
    #[inline]
    pub fn through(&self, across: Vec3x8, y: f32x8) -> Vec3x8 {
        (across + self.up.scale(y)).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eight_camera_rays_at_a_time_are_camera_ray_to_the_bit() {
        let camera = Camera::lab();
        let wide = CameraX8::new(&camera, 803, 7);
        let pixel = |l: usize| (100 * l as u32 + 2, l as u32 % 7);
        let offset = |l: usize| (0.37 + 0.07 * l as f32, 0.93 - 0.11 * l as f32);
        let column = f32x8::new(std::array::from_fn(|l| pixel(l).0 as f32 + offset(l).0));
        let row = f32x8::new(std::array::from_fn(|l| pixel(l).1 as f32 + offset(l).1));
        let d = wide.directions(column, row).to_lanes();
        for (l, d) in d.iter().enumerate() {
            let (i, j) = pixel(l);
            assert_eq!(
                *d,
                camera.ray(i, j, offset(l), 803, 7).direction,
                "lane {l}"
            );
        }
    }
}
