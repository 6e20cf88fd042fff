//! The pinhole camera: which ray goes through which pixel.

use crate::Vec3;
use crate::ray::Ray;

/// A pinhole camera looking from `eye` at `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Where every primary ray starts: the pinhole.
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
    /// The eye and the target give no direction to look along.
    #[error("the camera's eye and target must be different finite points")]
    NoViewDirection,
    /// The up vector gives no right and up for the image.
    #[error("the camera's up vector must be finite and not parallel to the view direction")]
    UpParallelToView,
    /// The field of view, in degrees, leaves no image to see.
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

    /// The lab's camera (the lab model).
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
    /// The ray through the point `(sx, sy)` ∈ \[0,1\]² of pixel column `i`,
    /// row `j` (row 0 at the top) of a `width` × `height` image.
    #[inline]
    pub fn ray(&self, i: u32, j: u32, (sx, sy): (f32, f32), width: u32, height: u32) -> Ray {
        // ANCHOR: todo_camera_ray "Map pixel (i + sx, j + sy) to x in [-h·a, h·a] (left to right) and y in [h, -h] (top to bottom) on the image plane at distance 1, and return the unit ray from the eye through forward + x·right + y·up."
        let (w, h) = (width as f32, height as f32);
        let aspect = w / h;
        // Map the pixel to [-1, 1] on the image plane at distance 1,
        // then scale by the half-height (and half-width) of the view.
        let x = (2.0 * (i as f32 + sx) / w - 1.0) * self.half_height * aspect;
        let y = (1.0 - 2.0 * (j as f32 + sy) / h) * self.half_height;
        let direction = (self.forward + x * self.right + y * self.up).normalize();
        Ray::new(self.eye, direction)
        // ANCHOR_END: todo_camera_ray
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

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;

    /// the lab's half height is tan 22.5°, in f32
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

    #[test]
    fn every_camera_ray_starts_at_the_eye_and_has_unit_length() {
        let camera = Camera::lab();
        for (i, j) in [(0, 0), (799, 0), (0, 599), (799, 599), (123, 456)] {
            let ray = camera.ray(i, j, (0.5, 0.5), 800, 600);
            assert_eq!(ray.origin, Vec3::new(0.0, 1.2, 4.5), "pixel {i},{j}");
            let length = ray.direction.length();
            assert!(
                (length - 1.0).abs() < 1e-6,
                "pixel {i},{j}: length {length}"
            );
        }
    }

    #[test]
    fn the_pixel_centre_ray_of_an_800_by_600_image_goes_just_right_of_and_below_the_target() {
        // Pixel (400, 300) at offset (0.5, 0.5): x = (2 · 400.5 / 800 − 1) · h · 4/3
        // = 0.00069036 and y = (1 − 2 · 300.5 / 600) · h = −0.00069036, so the
        // direction is normalize(f + x·r + y·u) with f = (0, −0.13216, −0.99123),
        // r = (1, 0, 0) and u = (0, 0.99123, −0.13216).
        let ray = Camera::lab().ray(400, 300, (0.5, 0.5), 800, 600);
        let expected = Vec3::new(0.000_690_356, -0.132_847_96, -0.991_136_2);
        assert!(
            ray.direction.abs_diff_eq(expected, 1e-6),
            "{}",
            ray.direction
        );
    }

    #[test]
    fn row_0_is_the_top_of_the_image_and_column_0_its_left() {
        let camera = Camera::lab();
        let top_left = camera.ray(0, 0, (0.5, 0.5), 4, 4).direction;
        let bottom_right = camera.ray(3, 3, (0.5, 0.5), 4, 4).direction;
        assert!(
            top_left.dot(camera.up()) > 0.0,
            "row 0 must look up (y = +h at the top): {top_left}"
        );
        assert!(
            top_left.dot(camera.right()) < 0.0,
            "column 0 must look left (x = −h·a): {top_left}"
        );
        assert!(bottom_right.dot(camera.up()) < 0.0 && bottom_right.dot(camera.right()) > 0.0);
    }

    #[test]
    fn a_twice_as_wide_image_reaches_twice_as_far_to_the_side_as_up() {
        // The left edge of a 2:1 image is at x = −h · 2, its top at y = +h.
        let camera = Camera::lab();
        let ray = camera.ray(0, 0, (0.0, 0.0), 200, 100);
        let along = ray.direction.dot(camera.forward());
        let x = ray.direction.dot(camera.right()) / along;
        let y = ray.direction.dot(camera.up()) / along;
        let h = 0.414_213_57f32;
        assert!(
            (x + 2.0 * h).abs() < 1e-5,
            "x = {x}, not −2h = {}",
            -2.0 * h
        );
        assert!((y - h).abs() < 1e-5, "y = {y}, not h = {h}");
    }
}
// ANCHOR_END: tests
