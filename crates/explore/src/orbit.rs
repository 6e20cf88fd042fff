//! The camera the mouse moves: orbit around a target, zoom, pan; and the
//! camera it started from, kept exactly so that a still frame before any
//! move is the chapter's own picture to the byte.

use raylab::{Camera, Vec3};

/// The steepest the orbit looks up or down: short of straight down, where
/// the up vector would be parallel to the view.
const MAX_PITCH: f32 = 89.0;

/// Where the camera is, as angles around a target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    pub target: Vec3,
    pub distance: f32,
    /// Degrees around the vertical axis; 0 looks along −z.
    pub yaw: f32,
    /// Degrees above the target.
    pub pitch: f32,
    /// The vertical field of view, degrees.
    pub fov: f32,
}

impl Orbit {
    /// The orbit whose camera sits at `camera`'s eye looking at `target`.
    pub fn around(camera: &Camera, target: Vec3) -> Orbit {
        let offset = camera.eye - target;
        let distance = offset.length().max(1e-3);
        Orbit {
            target,
            distance,
            yaw: offset.x.atan2(offset.z).to_degrees(),
            pitch: (offset.y / distance).clamp(-1.0, 1.0).asin().to_degrees(),
            fov: 2.0 * camera.half_height().atan().to_degrees(),
        }
    }

    pub fn eye(&self) -> Vec3 {
        let (yaw, pitch) = (self.yaw.to_radians(), self.pitch.to_radians());
        self.target
            + self.distance
                * Vec3::new(
                    pitch.cos() * yaw.sin(),
                    pitch.sin(),
                    pitch.cos() * yaw.cos(),
                )
    }

    /// The camera, or `None` where no camera can be built (a field of view
    /// or target gone non-finite).
    pub fn camera(&self) -> Option<Camera> {
        Camera::look_at(self.eye(), self.target, Vec3::Y, self.fov).ok()
    }

    /// Turn by degrees: right moves the eye to the right around the target.
    pub fn turn(&mut self, yaw: f32, pitch: f32) {
        self.yaw = (self.yaw - yaw).rem_euclid(360.0);
        self.pitch = (self.pitch + pitch).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// Closer (`steps` > 0) or further, by a tenth of the distance a step.
    pub fn zoom(&mut self, steps: f32) {
        self.distance = (self.distance * 0.9f32.powf(steps)).clamp(0.05, 1000.0);
    }

    /// Move the target (and the eye with it) across the view by a
    /// fraction of the view's height at the target.
    pub fn pan(&mut self, camera: &Camera, right: f32, up: f32) {
        let span = 2.0 * self.distance * camera.half_height();
        self.target += span * (right * camera.right() + up * camera.up());
    }
}

/// The camera as the learner sees it: the scene's own until the mouse
/// moves it, then an orbit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    home: Camera,
    home_target: Vec3,
    orbit: Option<Orbit>,
}

impl View {
    pub fn new(home: Camera, home_target: Vec3) -> View {
        View {
            home,
            home_target,
            orbit: None,
        }
    }

    pub fn camera(&self) -> Camera {
        self.orbit.and_then(|o| o.camera()).unwrap_or(self.home)
    }

    /// Whether this is the scene's own camera, untouched.
    pub fn is_home(&self) -> bool {
        self.orbit.is_none()
    }

    /// The orbit, made from the home camera on the first move.
    pub fn orbit_mut(&mut self) -> &mut Orbit {
        let (home, target) = (self.home, self.home_target);
        self.orbit
            .get_or_insert_with(|| Orbit::around(&home, target))
    }

    pub fn orbit(&self) -> Option<&Orbit> {
        self.orbit.as_ref()
    }

    pub fn reset(&mut self) {
        self.orbit = None;
    }

    /// A new home (the scene file's camera changed); an orbit is kept.
    pub fn set_home(&mut self, home: Camera, target: Vec3) {
        self.home = home;
        self.home_target = target;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_orbit_around_the_lab_target_starts_at_the_lab_eye() {
        let lab = Camera::lab();
        let orbit = Orbit::around(&lab, Vec3::new(0.0, 0.6, 0.0));
        assert!((orbit.eye() - lab.eye).length() < 1e-5);
        assert!((orbit.fov - 45.0).abs() < 1e-4);
        let camera = orbit.camera().unwrap();
        assert!((camera.forward() - lab.forward()).length() < 1e-5);
    }

    #[test]
    fn the_orbit_never_looks_straight_down() {
        let mut orbit = Orbit::around(&Camera::lab(), Vec3::new(0.0, 0.6, 0.0));
        orbit.turn(0.0, 500.0);
        assert_eq!(orbit.pitch, MAX_PITCH);
        assert!(orbit.camera().is_some());
    }

    #[test]
    fn reset_brings_back_the_exact_home_camera() {
        let mut view = View::new(Camera::lab(), Vec3::new(0.0, 0.6, 0.0));
        view.orbit_mut().turn(30.0, 10.0);
        assert_ne!(view.camera(), Camera::lab());
        view.reset();
        assert_eq!(view.camera(), Camera::lab());
    }
}
