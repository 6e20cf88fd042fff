//! Eight paths in flight, one per lane, and one bounce of all of them at
//! once: [`PathTracer::trace`]'s loop body, eight wide.
//!
//! Each lane is a path at its own depth (a finished lane takes a new path
//! at once), so the per-path numbers are lanes too: the depth, the count
//! of diffuse bounces `k`, whether the last vertex was diffuse. They are
//! small whole numbers, kept in `f32` lanes (exact below 2²⁴) so that
//! they compare and blend with the same masks as everything else.
//!
//! Every lane has its own scalar generator, the one its sample would have
//! in the scalar tracer, and draws from it exactly where the scalar code
//! draws: a lane that does not draw at some point (a matte surface has no
//! lobe to choose) leaves its generator alone, so each consumes the scalar
//! sequence and the paths are the same to the bit.

use std::f32::consts::FRAC_1_PI;

use ch06_path_tracing::caustics::CausticMap;
use ch06_path_tracing::integrator::{Lobe, PathTracer};
use raylab::sampling::{PixelHash, Stream};
use raylab::{SceneQuery, Vec3};
use raylab_lanes::{
    Hits, LANES, Pcg32x8, SceneX8, SkyX8, Surfaces, Vec3x8, blend_back, lane_mask, lanes_of,
    mask_from_bits, negate, reflect, refract, sample_hashes, sample_rngs,
};
use wide::{CmpGt, CmpLe, CmpLt, CmpNe, f32x8};

use crate::density::irradiance_x8;
use crate::lane_use::{LaneUse, Stage};
use crate::terms::TermsX8;

/// Eight paths between two bounces.
pub struct Paths {
    pub origin: Vec3x8,
    pub direction: Vec3x8,
    /// The share of the light found further along that reaches the eye.
    throughput: Vec3x8,
    pub terms: TermsX8,
    /// Diffuse scatterings so far (`k`).
    diffuse_bounces: f32x8,
    /// Set where the last vertex was diffuse (the sun was counted there).
    after_diffuse: f32x8,
    /// Surface hits asked for so far, this one included (scalar `hits`).
    hits: f32x8,
    /// Segments and shadow rays traced on each path.
    pub rays: f32x8,
    /// Set where the lane holds a path being traced. An idle lane's
    /// numbers are stale; every mask below leaves them unread.
    pub active: f32x8,
    /// Each lane's own sample generator, `hash.sample_rng(sample,
    /// Stream::Path)` as the scalar tracer seeds it, replaced when the lane
    /// takes a new sample; all eight side by side, so that the lanes that
    /// draw at the same point draw together.
    pub random: Pcg32x8,
    /// How many lanes each step ran for (counted, never read by the paths).
    pub lane_use: LaneUse,
}

/// Eight idle lanes (each takes a path with [`Paths::start`]).
impl Default for Paths {
    fn default() -> Paths {
        Paths {
            origin: Vec3x8::ZERO,
            direction: Vec3x8::ONE,
            throughput: Vec3x8::ONE,
            terms: TermsX8::ZERO,
            diffuse_bounces: f32x8::ZERO,
            after_diffuse: f32x8::ZERO,
            hits: f32x8::ZERO,
            rays: f32x8::ZERO,
            active: f32x8::ZERO,
            random: sample_rngs(
                sample_hashes([PixelHash::new(0, (0, 0)); LANES], [0; LANES]),
                Stream::Path,
            ),
            lane_use: LaneUse::default(),
        }
    }
}

impl Paths {
    /// New paths in the lanes of `mask`, from the eye along `origin`,
    /// `direction`, as the start of `PathTracer::trace` sets them up (their
    /// generators are set by the caller).
    #[inline]
    pub fn start(&mut self, mask: f32x8, origin: Vec3x8, direction: Vec3x8) {
        self.origin = Vec3x8::blend_back(mask, origin, self.origin);
        self.direction = Vec3x8::blend_back(mask, direction, self.direction);
        self.throughput = Vec3x8::blend_back(mask, Vec3x8::ONE, self.throughput);
        self.terms.clear(mask);
        let zero = f32x8::ZERO;
        self.diffuse_bounces = blend_back(mask, zero, self.diffuse_bounces);
        self.after_diffuse = blend_back(mask, zero, self.after_diffuse);
        self.hits = blend_back(mask, zero, self.hits);
        self.rays = blend_back(mask, zero, self.rays);
        self.active |= mask;
    }

    // ANCHOR: bounce
    /// One segment of every active path: where it goes, what it finds, and
    /// where it goes next. Returns the lanes whose path ended here (they
    /// are no longer active; their terms and rays are final).
    pub fn bounce(
        &mut self,
        tracer: &PathTracer<'_, impl SceneQuery + ?Sized>,
        scene: &SceneX8,
    ) -> f32x8 {
        let active = self.active;
        // One more hit asked for and one more ray traced on each active path.
        self.hits += ones(active);
        self.rays += ones(active);
        let (o, d) = (self.origin, self.direction);
        let hits = scene.nearest(o, d);
        // Mask: one hit more than the depth allows, where only whether the
        // path escapes matters (the scalar code asks `any_hit` there).
        let last = self.hits.cmp_gt(f32x8::splat(tracer.max_depth as f32));
        let escaped = active & !last.blend(hits.any, hits.hit);
        if escaped.any() {
            self.escape(tracer, escaped);
        }
        let shading = active & !last & hits.hit;
        if shading.any() {
            let surfaces = scene.surfaces(o, d, &hits);
            self.scatter(tracer, scene, &hits, &surfaces, shading);
        }
        // Every path that did not go on to a new segment has ended.
        let ended = active & !shading;
        self.active = active & shading;
        ended
    }
    // ANCHOR_END: bounce

    /// The light of the paths in `escaped`, which left the scene: the sky,
    /// and the sun's disc where no diffuse vertex has counted it already.
    fn escape(&mut self, tracer: &PathTracer<'_, impl SceneQuery + ?Sized>, escaped: f32x8) {
        self.lane_use.note(Stage::Escape, escaped);
        let d = self.direction;
        let sky = SkyX8::new(&tracer.scene.sky).radiance(d);
        let k = self.diffuse_bounces;
        self.terms.add_sky(escaped, k, self.throughput * sky);
        let sun = &tracer.sun;
        if sun.is_point() {
            return; // a ray never hits a single direction
        }
        // Mask: the sun was counted elsewhere, by the shadow ray of the
        // diffuse vertex just before, or by the photons (with --caustics)
        // after any diffuse vertex.
        let mut counted_elsewhere = self.after_diffuse;
        if tracer.caustics.is_some() {
            counted_elsewhere |= k.cmp_gt(f32x8::ZERO);
        }
        // Mask: the direction is inside the disc, |d − L|² ≤ 2 (1 − cos(D/2)).
        let off = d - Vec3x8::splat(sun.direction);
        let limit = 2.0 * sun.one_minus_cos();
        let inside = off.dot(off).cmp_le(f32x8::splat(limit));
        let radiance = sun.radiance();
        if radiance > 0.0 {
            let seen = escaped & !counted_elsewhere & inside;
            self.terms.add_sun(seen, k, self.throughput * radiance);
        }
    }

    /// The paths in `shading` met a surface: choose each one's lobe, add the
    /// sun and the caustics at diffuse vertices, and set up the next segment.
    fn scatter(
        &mut self,
        tracer: &PathTracer<'_, impl SceneQuery + ?Sized>,
        scene: &SceneX8,
        hits: &Hits,
        s: &Surfaces,
        shading: f32x8,
    ) {
        self.lane_use.note(Stage::Surface, shading);
        let (o, d) = (self.origin, self.direction);
        let nf = s.facing_normal;
        // The lobe, only where there is a choice (a matte surface draws no
        // number for it, as in `PathTracer::draw_lobe`): the numbers drawn
        // in lanes, then the learner's `choose_lobe` per lane.
        let (mut mirror, mut refraction) = (0u32, 0u32);
        let choosing = (shading & s.chooses).move_mask() as u32;
        if choosing != 0 {
            let u = self.random.uniform(lane_mask(choosing));
            for lane in lanes_of(choosing) {
                let hit = scene.hit_of(o, d, hits, s, lane);
                match tracer.choose_lobe(d.lane(lane), &hit, u.as_array_ref()[lane]) {
                    Lobe::Mirror => mirror |= 1 << lane,
                    Lobe::Refraction => refraction |= 1 << lane,
                    Lobe::Diffuse => {}
                }
            }
        }
        let (mirror, refraction) = (mask_from_bits(mirror), mask_from_bits(refraction));
        let diffuse = shading & !(mirror | refraction);
        let specular = shading & (mirror | refraction);
        // Where each path goes next, from a diffuse or a specular vertex.
        let from_diffuse = diffuse.any().then(|| {
            self.lane_use.note(Stage::Diffuse, diffuse);
            self.diffuse(tracer, scene, s, diffuse)
        });
        let mut from_specular = None;
        if specular.any() {
            self.lane_use.note(Stage::Specular, specular);
            let reflected = reflect(d, nf);
            let mut direction = reflected;
            if refraction.any() {
                let eta = s.entering.blend(f32x8::ONE / s.ior, s.ior);
                let (refracted, total) = refract(d, nf, eta);
                // Mask: total internal reflection sends the light along
                // the mirror instead.
                let through = refraction & !total;
                direction = Vec3x8::select(through, refracted, reflected);
            }
            let direction = direction.normalize();
            let origin = s.point + direction * tracer.epsilon;
            from_specular = Some((origin, direction));
        }
        // Stored whole, not blended into the old numbers: a lane that is
        // neither diffuse nor specular here has ended, and its numbers are
        // stale until a new path starts in it.
        let (origin, direction) = match (from_diffuse, from_specular) {
            (Some(d), Some(s)) => (
                Vec3x8::select(diffuse, d.0, s.0),
                Vec3x8::select(diffuse, d.1, s.1),
            ),
            (Some(next), None) | (None, Some(next)) => next,
            (None, None) => (self.origin, self.direction),
        };
        self.origin = origin;
        self.direction = direction;
        self.after_diffuse = diffuse;
    }

    /// The diffuse vertices (`diffuse`): the sun by next-event estimation,
    /// the caustics on the ground, and a cosine-distributed new direction,
    /// returned with the point it starts from.
    fn diffuse(
        &mut self,
        tracer: &PathTracer<'_, impl SceneQuery + ?Sized>,
        scene: &SceneX8,
        s: &Surfaces,
        diffuse: f32x8,
    ) -> (Vec3x8, Vec3x8) {
        let sun = &tracer.sun;
        let nf = s.facing_normal;
        let k = self.diffuse_bounces;
        // A point sun is one direction; a disc draws two numbers per lane
        // (in lanes, in `Sunlight::draw`'s order), and each lane's point on
        // the disc is found as the scalar tracer finds it.
        let to_sun = if sun.is_point() {
            Vec3x8::splat(sun.direction)
        } else {
            let drawing = diffuse.move_mask() as u32;
            let u = self.random.uniform(lane_mask(drawing));
            let v = self.random.uniform(lane_mask(drawing));
            let mut towards = [sun.direction; LANES];
            for lane in lanes_of(drawing) {
                towards[lane] = sun.sample(u.as_array_ref()[lane], v.as_array_ref()[lane]);
            }
            Vec3x8::from_lanes(towards)
        };
        let cos = nf.dot(to_sun);
        // Mask: the surface faces the sun, so a shadow ray is traced.
        let lit = diffuse & cos.cmp_gt(f32x8::ZERO);
        if lit.any() {
            self.lane_use.note(Stage::ShadowRay, lit);
            self.rays += ones(lit);
            let origin = s.point + to_sun * tracer.epsilon;
            let open = lit & !scene.any(origin, to_sun, lit);
            let light = (s.albedo * FRAC_1_PI * sun.irradiance).scale(cos);
            self.terms
                .add_sun(open, k + f32x8::ONE, self.throughput * light);
        }
        if let Some(map) = tracer.caustics {
            self.caustics(tracer, map, s, diffuse & s.on_ground);
        }
        // The albedo where the path scattered diffusely, 1 (which leaves
        // a number exactly as it is) where it did not.
        self.throughput = self.throughput * Vec3x8::select(diffuse, s.albedo, Vec3x8::ONE);
        self.diffuse_bounces = k + ones(diffuse);
        let direction = self.cosine_direction(nf, diffuse);
        (s.point + nf * tracer.epsilon, direction)
    }

    /// The caustic light the photons left at the ground points of `ground`
    /// (looked up per lane: a scan of the photons near each point, eight
    /// photons at a time).
    fn caustics(
        &mut self,
        tracer: &PathTracer<'_, impl SceneQuery + ?Sized>,
        map: &CausticMap,
        s: &Surfaces,
        ground: f32x8,
    ) {
        let bits = ground.move_mask() as u32;
        if bits == 0 {
            return;
        }
        self.lane_use.note(Stage::Caustics, ground);
        let points = s.point.to_lanes();
        let hits = self.hits.to_array();
        let mut irradiance = [Vec3::ZERO; LANES];
        for lane in lanes_of(bits) {
            let left = tracer.max_depth - hits[lane] as u32;
            irradiance[lane] = irradiance_x8(map, points[lane], left);
        }
        let light = (self.throughput * s.albedo * FRAC_1_PI) * Vec3x8::from_lanes(irradiance);
        self.terms.add_caustics(ground, light);
    }

    // ANCHOR: cosine
    /// `ch06_path_tracing::integrator::cosine_direction` in the lanes of
    /// `mask`: every lane draws its first point (x, then y, from its own
    /// stream) together; the few whose point falls outside the disc draw
    /// again one lane at a time, so that the others do not wait, each
    /// with the scalar arithmetic of its own generator. Each lane draws
    /// exactly the numbers its scalar path draws.
    fn cosine_direction(&mut self, n: Vec3x8, mask: f32x8) -> Vec3x8 {
        let (two, one) = (f32x8::splat(2.0), f32x8::ONE);
        let bits = mask.move_mask() as u32;
        let drawing = lane_mask(bits);
        let u = self.random.uniform(drawing);
        let v = self.random.uniform(drawing);
        let (mut x, mut y) = (two * u - one, two * v - one);
        let mut r2 = x * x + y * y;
        let outside = bits & !(r2.cmp_lt(one).move_mask() as u32);
        if outside != 0 {
            let (mut xs, mut ys, mut r2s) = (x.to_array(), y.to_array(), r2.to_array());
            for lane in lanes_of(outside) {
                loop {
                    let x = 2.0 * self.random.uniform_in_lane(lane) - 1.0;
                    let y = 2.0 * self.random.uniform_in_lane(lane) - 1.0;
                    let r2 = x * x + y * y;
                    (xs[lane], ys[lane], r2s[lane]) = (x, y, r2);
                    if r2 < 1.0 {
                        break;
                    }
                }
            }
            (x, y, r2) = (f32x8::new(xs), f32x8::new(ys), f32x8::new(r2s));
        }
        let (t, b) = any_orthonormal_pair(n);
        let z = (one - r2).max(f32x8::ZERO).sqrt();
        t.scale(x) + b.scale(y) + n.scale(z)
    }
    // ANCHOR_END: cosine
}

/// 1 in each lane of `mask`, +0 elsewhere: what a count goes up by. A count
/// is a whole number from +0, so adding +0 leaves it as it is, to the bit.
#[inline]
fn ones(mask: f32x8) -> f32x8 {
    mask & f32x8::ONE
}

/// glam's `any_orthonormal_pair` in every lane (Duff et al.'s basis):
/// `signum(z)` is ±1 by the sign bit, and NaN where `z` is.
fn any_orthonormal_pair(n: Vec3x8) -> (Vec3x8, Vec3x8) {
    let sign_bit = n.z & f32x8::splat(-0.0);
    let sign = f32x8::ONE | sign_bit;
    let sign = n.z.cmp_ne(n.z).blend(n.z, sign);
    let a = f32x8::splat(-1.0) / (sign + n.z);
    let b = n.x * n.y * a;
    (
        Vec3x8 {
            x: f32x8::ONE + sign * n.x * n.x * a,
            y: sign * b,
            z: negate(sign) * n.x,
        },
        Vec3x8 {
            x: b,
            y: sign + n.y * n.y * a,
            z: negate(n.y),
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_orthonormal_pair_in_lanes_is_glams_to_the_bit() {
        let ns: [Vec3; LANES] = [
            Vec3::Y,
            Vec3::NEG_Z,
            Vec3::Z,
            Vec3::new(0.3, 0.9, -0.2).normalize(),
            Vec3::new(-0.6, 0.1, 0.7).normalize(),
            Vec3::new(0.0, 0.0, -0.0),
            Vec3::new(0.5, -0.5, 0.0).normalize(),
            Vec3::new(-0.1, -0.2, -0.97).normalize(),
        ];
        let (t, b) = any_orthonormal_pair(Vec3x8::from_lanes(ns));
        let (t, b) = (t.to_lanes(), b.to_lanes());
        for (l, n) in ns.iter().enumerate() {
            let (tt, bb) = n.any_orthonormal_pair();
            assert_eq!(
                t[l].to_array().map(f32::to_bits),
                tt.to_array().map(f32::to_bits)
            );
            assert_eq!(
                b[l].to_array().map(f32::to_bits),
                bb.to_array().map(f32::to_bits)
            );
        }
    }
}
