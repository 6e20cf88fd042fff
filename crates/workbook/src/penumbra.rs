//! How wide a shadow's soft edge is, measured on the ground.
//!
//! A ground point sees a share of the sun's disc: all of it in the light,
//! none in the umbra, part of it in the penumbra between. Along the axis of
//! a ball's shadow (the sun's azimuth, where the shadow is longest), that
//! share rises from 0 to 1 at the shadow's far tip; the distance between
//! the last point that sees none of the disc and the first that sees all
//! of it is the penumbra's width there. The share is counted over a fixed
//! grid of directions on the disc, the same for every point, so it is a
//! deterministic and (for one ball) monotone function of the position, and
//! bisection finds both ends.

use raylab::scene::SceneSphere;
use raylab::{Camera, Ray, Vec3};

use ch06_path_tracing::sun::Sunlight;

/// Directions per side of the grid on the disc: 64² = 4096 in all.
const GRID: u32 = 64;
/// Bisection steps: the range shrinks 2⁴⁰-fold, far below f32's grain.
const STEPS: u32 = 40;

/// The penumbra at the far tip of one ball's shadow.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Penumbra {
    /// The last ground point on the axis that sees none of the sun.
    pub umbra_end: Vec3,
    /// The first one that sees all of it.
    pub light_start: Vec3,
    /// From the penumbra's middle to where its light grazes the ball.
    pub distance_to_ball: f32,
}

impl Penumbra {
    /// The width on the ground, in scene units.
    pub fn width(&self) -> f32 {
        self.umbra_end.distance(self.light_start)
    }

    /// The width in pixels of an image `width × height` from `camera`.
    pub fn pixels(&self, camera: &Camera, width: u32, height: u32) -> Option<f32> {
        let a = camera.project(self.umbra_end, width, height)?;
        let b = camera.project(self.light_start, width, height)?;
        Some(((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt())
    }

    /// The first-order estimate of the width: distance × the disc's angle
    /// across the light, stretched by 1/sin(elevation) where the light
    /// meets the ground at a slant.
    pub fn estimate(&self, sun_degrees: f32, to_sun: Vec3) -> f32 {
        self.distance_to_ball * sun_degrees.to_radians() / to_sun.y
    }
}

/// The fixed grid of directions on the sun's disc every point is tested
/// with: 64 × 64 cells of the disc's two uniform numbers, at their centres.
pub fn disc_directions(sun: &Sunlight) -> Vec<Vec3> {
    let cell = |k: u32| (k as f32 + 0.5) / GRID as f32;
    (0..GRID)
        .flat_map(|i| (0..GRID).map(move |j| sun.sample(cell(i), cell(j))))
        .collect()
}

/// The share of the sun's disc, given as its `directions`, that the ground
/// point `p` sees past `ball` (the other objects are left out, so that no
/// other shadow overlaps).
pub fn visible_share(directions: &[Vec3], ball: &SceneSphere, p: Vec3) -> f32 {
    let seen = directions
        .iter()
        .filter(|&&to_sun| ball.shape.intersect(&Ray::new(p, to_sun)).is_none())
        .count();
    seen as f32 / directions.len() as f32
}

/// The penumbra at the far tip of `ball`'s shadow on the ground (y = 0),
/// for a sun that is a disc.
pub fn at_shadow_tip(sun: &Sunlight, ball: &SceneSphere) -> Penumbra {
    let (c, r) = (ball.shape.centre, ball.shape.radius);
    let l = sun.direction;
    // The shadow of the centre, and the axis pointing away from the sun.
    let centre_shadow = c - l * (c.y / l.y);
    let axis = Vec3::new(-l.x, 0.0, -l.z).normalize();
    let at = |s: f32| centre_shadow + axis * s;
    // The tip of the shadow is R / sin(elevation) out for a point sun; a
    // disc's penumbra lies around it, well inside three times that.
    let far = 3.0 * r / l.y;
    let directions = disc_directions(sun);
    let share = |s: f32| visible_share(&directions, ball, at(s));
    // The last s that sees none, between a point in the umbra and a lit one.
    let umbra_end = bisect(0.0, far, |s| share(s) == 0.0);
    // The first s that sees all of it.
    let light_start = bisect(0.0, far, |s| share(s) < 1.0);
    let middle = at(0.5 * (umbra_end + light_start));
    Penumbra {
        umbra_end: at(umbra_end),
        light_start: at(light_start),
        distance_to_ball: (c - middle).dot(l),
    }
}

/// The boundary between `lo`, where `inside` holds, and `hi`, where it does
/// not, found by halving.
fn bisect(mut lo: f32, mut hi: f32, inside: impl Fn(f32) -> bool) -> f32 {
    debug_assert!(inside(lo) && !inside(hi));
    for _ in 0..STEPS {
        let mid = 0.5 * (lo + hi);
        if inside(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Scene;
    use raylab::light::Sun;

    /// The lab's glass ball, moved to height `h` above the origin, radius `r`.
    fn ball_at_height(h: f32, r: f32) -> SceneSphere {
        let scene = Scene::lab();
        let mut ball = scene.spheres()[scene.sphere_named("glass").unwrap()].clone();
        ball.shape.centre = Vec3::new(0.0, h, 0.0);
        ball.shape.radius = r;
        ball
    }

    #[test]
    fn a_sun_straight_overhead_gives_the_penumbra_of_similar_triangles() {
        // A ball of radius 0.5 at height 2, the sun overhead and 2° across:
        // the light that makes the shadow's edge grazes the ball 2 units up,
        // so the penumbra is 2 · (2° in radians) = 0.0698 wide, to first
        // order (the ball's edge seen from the ground turns at 0.5 rad per
        // unit there, and the disc is 0.0349 rad across).
        let sun = Sunlight::new(
            &Sun {
                direction: Vec3::new(1e-4, 1.0, 0.0).normalize(),
                brightness: 25.0,
            },
            Some(2.0),
        );
        let p = at_shadow_tip(&sun, &ball_at_height(2.0, 0.5));
        let expected = 2.0 * 2f32.to_radians();
        assert!(
            (p.width() - expected).abs() < 0.03 * expected,
            "{} against {expected}",
            p.width()
        );
        assert!((p.distance_to_ball - 2.0).abs() < 0.01, "{p:?}");
        assert!((p.estimate(2.0, sun.direction) - expected).abs() < 0.01 * expected);
    }

    #[test]
    fn a_point_deep_in_the_shadow_sees_none_of_the_sun_and_one_far_away_all() {
        let sun = Sunlight::new(&Scene::lab().sun, Some(5.0));
        let directions = disc_directions(&sun);
        assert_eq!(directions.len(), 4096);
        let ball = ball_at_height(1.0, 0.5);
        let below = Vec3::new(0.0, 1.0, 0.0) - sun.direction * (1.0 / sun.direction.y);
        assert_eq!(visible_share(&directions, &ball, below), 0.0);
        assert_eq!(
            visible_share(&directions, &ball, Vec3::new(10.0, 0.0, 10.0)),
            1.0
        );
    }
}
