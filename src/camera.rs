//! The pinhole camera: which ray goes through which pixel.

use crate::Vec3;
use crate::ray::Ray;

/// A pinhole camera looking from `eye` at `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub eye: Vec3,
    /// Unit vector the camera looks along.
    forward: Vec3,
    /// Unit vector to the right of the image.
    right: Vec3,
    /// Unit vector to the top of the image.
    up: Vec3,
    /// `tan(fov / 2)`: the half-height of the image at distance 1.
    half_height: f32,
}

/// Why a camera cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CameraError {
    #[error("the camera's eye and target must be different finite points")]
    NoViewDirection,
    #[error("the camera's up vector must be finite and not parallel to the view direction")]
    UpParallelToView,
    #[error("the field of view is {0}°, but it must be between 0° and 180°, exclusive")]
    FieldOfView(f32),
}

impl Camera {
    /// A camera at `eye` looking at `target`, tilted so that `up` points
    /// up in the image, with a vertical field of view in degrees.
    pub fn look_at(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        fov_degrees: f32,
    ) -> Result<Self, CameraError> {
        if !(fov_degrees > 0.0 && fov_degrees < 180.0) {
            return Err(CameraError::FieldOfView(fov_degrees));
        }
        let forward = (target - eye)
            .try_normalize()
            .ok_or(CameraError::NoViewDirection)?;
        let right = forward
            .cross(up)
            .try_normalize()
            .ok_or(CameraError::UpParallelToView)?;
        Ok(Camera {
            eye,
            forward,
            right,
            up: right.cross(forward),
            half_height: (fov_degrees.to_radians() / 2.0).tan(),
        })
    }

    /// The lab's camera (LAB.md).
    pub fn lab() -> Self {
        Camera::look_at(
            Vec3::new(0.0, 1.2, 4.5),
            Vec3::new(0.0, 0.6, 0.0),
            Vec3::Y,
            45.0,
        )
        .expect("the lab camera is valid")
    }

    // ANCHOR: ray
    /// The ray through the point `(sx, sy)` ∈ [0,1]² of pixel column `i`,
    /// row `j` (row 0 at the top) of a `width` × `height` image.
    #[inline]
    pub fn ray(&self, i: u32, j: u32, (sx, sy): (f32, f32), width: u32, height: u32) -> Ray {
        let (w, h) = (width as f32, height as f32);
        let aspect = w / h;
        // Map the pixel to [-1, 1] on the image plane at distance 1,
        // then scale by the half-height (and half-width) of the view.
        let x = (2.0 * (i as f32 + sx) / w - 1.0) * self.half_height * aspect;
        let y = (1.0 - 2.0 * (j as f32 + sy) / h) * self.half_height;
        let direction = (self.forward + x * self.right + y * self.up).normalize();
        Ray::new(self.eye, direction)
    }
    // ANCHOR_END: ray

    /// The unit view direction.
    pub fn forward(&self) -> Vec3 {
        self.forward
    }

    /// The unit vector to the right of the image.
    pub fn right(&self) -> Vec3 {
        self.right
    }

    /// The unit vector to the top of the image.
    pub fn up(&self) -> Vec3 {
        self.up
    }

    /// `tan(fov / 2)`, as [`Camera::ray`] uses it.
    pub fn half_height(&self) -> f32 {
        self.half_height
    }

    /// The screen point `(x, y)` in pixels where the world point `p` is
    /// seen, or `None` when it lies behind the camera. The inverse of
    /// [`Camera::ray`], used to find a sphere's pixel for a probe.
    pub fn project(&self, p: Vec3, width: u32, height: u32) -> Option<(f32, f32)> {
        let v = p - self.eye;
        let z = v.dot(self.forward);
        if z <= 0.0 {
            return None;
        }
        let aspect = width as f32 / height as f32;
        let x = v.dot(self.right) / z / (self.half_height * aspect);
        let y = v.dot(self.up) / z / self.half_height;
        Some((
            (x + 1.0) / 2.0 * width as f32,
            (1.0 - y) / 2.0 * height as f32,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lab_half_height_is_tan_22_5_degrees_in_f32() {
        assert_eq!(Camera::lab().half_height, 0.414_213_57);
    }

    #[test]
    fn the_ray_through_the_image_centre_looks_at_the_target() {
        // Pixel (1, 1) of a 2 × 2 image at offset (0, 0) is the exact centre.
        let camera = Camera::lab();
        let ray = camera.ray(1, 1, (0.0, 0.0), 2, 2);
        let expected = Vec3::new(0.0, -0.6, -4.5).normalize();
        assert_eq!(ray.origin, Vec3::new(0.0, 1.2, 4.5));
        assert!(
            ray.direction.abs_diff_eq(expected, 1e-6),
            "{}",
            ray.direction
        );
    }

    #[test]
    fn the_ray_through_the_top_left_corner_spans_half_the_field_of_view() {
        // A 4:3 image; the corner of pixel (0, 0) is at x = -h·a, y = +h.
        let camera = Camera::lab();
        let ray = camera.ray(0, 0, (0.0, 0.0), 4, 3);
        let h = 0.414_213_57f32;
        let f = Vec3::new(0.0, -0.6, -4.5).normalize();
        let r = Vec3::X; // cross(f, up) has no y or z part here
        let u = r.cross(f);
        let expected = (f - h * 4.0 / 3.0 * r + h * u).normalize();
        assert!(ray.direction.abs_diff_eq(expected, 1e-6));
        // The vertical angle to the view direction is the half field of view, 22.5°.
        let vertical = (ray.direction - ray.direction.dot(r) * r).normalize();
        assert!((vertical.dot(f).acos().to_degrees() - 22.5).abs() < 1e-3);
    }

    #[test]
    fn projecting_a_pixel_ray_point_lands_on_that_pixel() {
        let camera = Camera::lab();
        let ray = camera.ray(123, 45, (0.5, 0.5), 800, 600);
        let (x, y) = camera.project(ray.at(3.0), 800, 600).unwrap();
        assert!(
            (x - 123.5).abs() < 1e-2 && (y - 45.5).abs() < 1e-2,
            "{x}, {y}"
        );
    }

    #[test]
    fn a_camera_with_up_along_the_view_is_rejected() {
        let err = Camera::look_at(Vec3::ZERO, Vec3::Y, Vec3::Y, 45.0).unwrap_err();
        assert_eq!(err, CameraError::UpParallelToView);
        assert!(Camera::look_at(Vec3::ZERO, Vec3::X, Vec3::Y, 180.0).is_err());
        assert!(Camera::look_at(Vec3::ZERO, Vec3::ZERO, Vec3::Y, 45.0).is_err());
    }
}
