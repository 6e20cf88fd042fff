//! Chapter 6's density estimate, `CausticMap::irradiance`, eight photons
//! at a time in the lanes of an `f32x8`: the same partial sums in the same
//! order, so the same bits.
//!
//! Chapter 6 adds a run's photons one at a time, the k-th of each group of
//! eight into partial sum k. Here the eight partial sums are the eight
//! lanes, and each group of eight photons is one step. A path that lands
//! in the glass ball's caustic reads thousands of photons, so this is
//! where `--caustics` spends its time.

use ch06_path_tracing::caustics::{CausticMap, KERNEL_RADIUS};
use raylab::Vec3;
use wide::{CmpLe, CmpLt, f32x8};

// ANCHOR: density
/// [`CausticMap::irradiance`] at ground point `p`, for photons of at most
/// `max_bounces` mirror and glass bounces, to the bit.
pub fn irradiance_x8(map: &CausticMap, p: Vec3, max_bounces: u32) -> Vec3 {
    if max_bounces == 0 {
        return Vec3::ZERO;
    }
    let Some(near) = map.near(p) else {
        return Vec3::ZERO;
    };
    let h = KERNEL_RADIUS;
    let (u, v) = (f32x8::splat(near.u), f32x8::splat(near.v));
    let (h2, most) = (f32x8::splat(h * h), f32x8::splat(max_bounces as f32));
    // Lane k holds partial sum k: the k-th photon of every group of eight.
    let lane = f32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
    let photons = near.photons;
    let mut sum = f32x8::ZERO;
    for run in near.runs {
        for i in run.clone().step_by(8) {
            let column = |c: &[f32]| f32x8::from(&c[i..i + 8]);
            let (du, dv) = (column(&photons.u) - u, column(&photons.v) - v);
            let d2 = du * du + dv * dv;
            // Lanes past the run's end are the next cells' photons.
            let in_run = lane.cmp_lt(f32x8::splat((run.end - i).min(8) as f32));
            let counts = d2.cmp_lt(h2) & column(&photons.bounces).cmp_le(most) & in_run;
            let kernel = f32x8::ONE - d2 / h2;
            sum += counts.blend(column(&photons.power) * kernel, f32x8::ZERO);
        }
    }
    // The eight sums added pairwise, as chapter 6 adds them.
    let [s0, s1, s2, s3, s4, s5, s6, s7] = sum.to_array();
    let total = ((s0 + s4) + (s2 + s6)) + ((s1 + s5) + (s3 + s7));
    Vec3::splat(total * (2.0 / (std::f32::consts::PI * h * h)))
}
// ANCHOR_END: density

#[cfg(test)]
mod tests {
    use super::*;
    use ch06_path_tracing::Materials;
    use ch06_path_tracing::integrator::PathTracer;
    use ch06_path_tracing::photons::trace_caustics;
    use ch06_path_tracing::sun::Sunlight;
    use raylab::Scene;

    #[test]
    fn the_caustic_lookup_in_lanes_is_chapter_6s_to_the_bit() {
        // The lab's real caustics (few photons, so that the test is quick),
        // looked up on a grid of ground points across the glass ball's
        // bright spot and its dim surroundings, for every bounce limit.
        let scene = Scene::lab();
        let tracer = PathTracer {
            scene: &scene,
            objects: &scene,
            sun: Sunlight::new(&scene.sun, None),
            materials: Materials::Lab,
            max_depth: 10,
            epsilon: 1e-4,
            caustics: None,
        };
        let map = trace_caustics(&tracer, 20_000, 1);
        assert!(map.len() > 1_000, "{} photons landed", map.len());
        let (u_axis, v_axis) = scene.ground.plane.normal.any_orthonormal_pair();
        let origin = scene.ground.plane.point;
        let mut lit = 0;
        for i in -40..=40 {
            for j in -40..=40 {
                let p = origin + u_axis * (i as f32 * 0.037) + v_axis * (j as f32 * 0.041);
                for bounces in 0..=4 {
                    let want = map.irradiance(p, bounces).to_array().map(f32::to_bits);
                    let got = irradiance_x8(&map, p, bounces).to_array().map(f32::to_bits);
                    assert_eq!(got, want, "at {p} with {bounces} bounces");
                    lit += usize::from(want[0] != 0);
                }
            }
        }
        assert!(lit > 100, "only {lit} lookups found light");
    }
}
