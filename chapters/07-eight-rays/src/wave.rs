//! Waves: every ray of one depth, for a whole image row, eight at a time.
//!
//! The scalar tracer follows one sample's ray tree to the bottom before it
//! starts the next sample. Here the row's primary rays are traced first,
//! all of them (wave 1); their reflected and refracted rays, packed densely,
//! form wave 2; and so on. Each ray leaves a [`Node`] behind: what it added
//! to its sample, and where its children are in the next wave. The sample's
//! colour is then summed by walking its tree in the scalar tracer's order,
//! so the sums round exactly as chapter 5's do.

use raylab::trace::{RAY_BUDGET, RayCounts};
use raylab::{RayKind, Vec3};
use wide::f32x8;

use crate::intersect::{SceneX8, senders};
use crate::like::Features;
use crate::shade::{Light, reflect, refract};
use crate::soa::{LANES, Rays, Vec3x8};

/// What one traced ray did, kept until its sample's colour is summed.
#[derive(Clone, Copy, Debug)]
pub struct Node {
    /// What the ray added to its sample: `w · (1 − r − t) · local`, or `w · sky`.
    pub added: Vec3,
    /// Its children are rays `first_child ..` of the next wave, the
    /// transmitted one first: the order the scalar ray stack pops them.
    pub first_child: u32,
    pub children: u8,
    pub kind: RayKind,
    /// Whether it cast a shadow ray.
    pub shadow: bool,
}

/// The fixed part of a render: the scene in lanes, the light, the limits.
pub struct Setup {
    pub scene: SceneX8,
    pub light: Light,
    pub features: Features,
    pub max_depth: u32,
    pub epsilon: f32,
}

/// What eight rays' shading computed: the light they add, and the rays
/// they send on (for lanes whose masks are set).
struct Shaded {
    added: Vec3x8,
    hit: f32x8,
    reflects: f32x8,
    transmits: f32x8,
    reflected: Option<(Vec3x8, Vec3x8)>,
    /// The transmitted direction and origin, and the mask of total
    /// internal reflection (where the mirror direction is used instead).
    transmitted: Option<(Vec3x8, Vec3x8, f32x8)>,
    reflection: f32x8,
    transmission: f32x8,
}

// ANCHOR: group
/// Trace and shade one group of eight rays of a wave.
fn shade_group(setup: &Setup, rays: &Rays, group: usize, can_send: bool) -> Shaded {
    let (o, d) = (rays.origins(group), rays.directions(group));
    let w = rays.weights(group);
    let hits = setup.scene.nearest(o, d);
    let sky = setup.light.sky(d).scale(w);
    let mut shaded = Shaded {
        added: sky,
        hit: hits.hit,
        reflects: f32x8::ZERO,
        transmits: f32x8::ZERO,
        reflected: None,
        transmitted: None,
        reflection: f32x8::ZERO,
        transmission: f32x8::ZERO,
    };
    // Divergence, the cheap way out: when all eight rays see the sky,
    // none of the surface work below is needed.
    if hits.hit.none() {
        return shaded;
    }
    let s = setup.scene.surfaces(o, d, &hits);
    let eps = f32x8::splat(setup.epsilon);

    // Shadow rays from every lane; only hit lanes' answers are used.
    let in_shadow = if setup.features.shadows {
        let to_sun = setup.light.to_sun;
        setup.scene.any(s.point + to_sun.scale(eps), to_sun)
    } else {
        f32x8::ZERO
    };
    let local = setup.light.local(&s, in_shadow);
    // `(1 − r) − t`, subtracted one share at a time as `Surface::send` does.
    let kept = f32x8::ONE - s.reflection - s.transmission;
    let surface = local.scale(w * kept);
    // Mask: lanes that hit something show their surface, the others the sky.
    shaded.added = Vec3x8::select(hits.hit, surface, sky);

    let (reflects, transmits) = senders(&s, &hits, setup.features);
    shaded.reflects = reflects;
    shaded.transmits = transmits;
    // Divergence again: in most groups no lane hit the mirror or the
    // glass, and the optics is skipped. When 3 of 8 did, all 8 lanes
    // compute it and the masks keep the 3 answers.
    if can_send && (reflects | transmits).any() {
        let mirrored = reflect(d, s.facing_normal);
        let mirrored_from = s.point + mirrored.scale(eps);
        if reflects.any() {
            shaded.reflected = Some((mirrored_from, mirrored));
            shaded.reflection = w * s.reflection;
        }
        if transmits.any() {
            let eta = s.entering.blend(f32x8::ONE / s.ior, s.ior);
            let (bent, total) = refract(d, s.facing_normal, eta);
            let direction = Vec3x8::select(total, mirrored, bent);
            let from = s.point + direction.scale(eps);
            shaded.transmitted = Some((from, direction, total));
            shaded.transmission = w * s.transmission;
        }
    }
    shaded
}
// ANCHOR_END: group

/// A row's waves and trees, kept by one worker and reused for every row.
#[derive(Default)]
pub struct Waves {
    /// `rays[d]`: the rays of depth `d + 1`.
    pub rays: Vec<Rays>,
    /// `nodes[d][i]`: what ray `i` of `rays[d]` did.
    pub nodes: Vec<Vec<Node>>,
    /// Per sample: rays traced so far, shadow rays included; kept only
    /// when a tree can reach the budget at all (see [`budget_matters`]).
    pub sample_rays: Vec<u32>,
    /// The row's rays by kind, counted a group at a time.
    pub counts: RayCounts,
}

/// Whether any sample's tree can reach [`RAY_BUDGET`]: a ray sends on at
/// most two rays and casts one shadow ray, so a tree `max_depth` deep
/// holds at most `2 · (2^max_depth − 1)` rays: 4094 at depth 11, below
/// the budget of 4096. Only deeper renders need to count every sample's.
pub fn budget_matters(max_depth: u32) -> bool {
    2 * ((1u64 << max_depth.min(63)) - 1) >= u64::from(RAY_BUDGET)
}

impl Waves {
    /// Start a row: `samples` samples, none traced yet.
    pub fn start(&mut self, samples: usize, max_depth: u32) {
        let depths = max_depth as usize;
        if self.rays.len() < depths {
            self.rays.resize_with(depths, Rays::default);
            self.nodes.resize_with(depths, Vec::new);
        }
        for (rays, nodes) in self.rays.iter_mut().zip(&mut self.nodes) {
            rays.clear();
            nodes.clear();
        }
        self.sample_rays.clear();
        if budget_matters(max_depth) {
            self.sample_rays.resize(samples, 0);
        }
        self.counts = RayCounts::default();
    }

    /// Whether a sample's tree grew to [`RAY_BUDGET`] rays. The scalar
    /// tracer cuts such a tree short at a point that depends on its
    /// depth-first order, so these samples are traced again by it.
    pub fn over_budget(&self, sample: usize) -> bool {
        self.sample_rays
            .get(sample)
            .is_some_and(|&rays| rays >= RAY_BUDGET)
    }

    // ANCHOR: waves
    /// Trace every wave of the row, from the primary rays in `rays[0]`
    /// down to `max_depth` or until a wave is empty.
    pub fn trace(&mut self, setup: &Setup) {
        for depth in 1..=setup.max_depth as usize {
            if self.rays[depth - 1].is_empty() {
                break;
            }
            self.trace_wave(setup, depth);
        }
    }
    // ANCHOR_END: waves

    /// Trace the wave of rays at `depth`, and pack the rays they send on
    /// densely into the next wave.
    // One lane number indexes the wave, the light and the masks at once.
    #[allow(clippy::needless_range_loop)]
    fn trace_wave(&mut self, setup: &Setup, depth: usize) {
        let can_send = depth < setup.max_depth as usize;
        let (this, rest) = self.rays.split_at_mut(depth);
        let rays = &mut this[depth - 1];
        let mut empty = Rays::default();
        let next = rest.first_mut().unwrap_or(&mut empty);
        let nodes = &mut self.nodes[depth - 1];
        rays.pad();
        next.reserve(2 * rays.len());
        let counting = !self.sample_rays.is_empty();
        let mut shadows = 0;
        for group in 0..rays.groups() {
            let shaded = shade_group(setup, rays, group, can_send);
            let lanes = (rays.len() - group * LANES).min(LANES);
            // The masks as bits, and the light as plain arrays: one lane at
            // a time from here on.
            let real = (1 << lanes) - 1;
            let hit = shaded.hit.move_mask() & real;
            let sends = (shaded.reflects | shaded.transmits).move_mask() & real;
            let bits = Bits {
                reflects: shaded.reflects.move_mask(),
                transmits: shaded.transmits.move_mask(),
                total: shaded.transmitted.map_or(0, |t| t.2.move_mask()),
            };
            if setup.features.shadows {
                shadows += hit.count_ones();
            }
            let added = [shaded.added.x, shaded.added.y, shaded.added.z].map(|c| c.to_array());
            for lane in 0..lanes {
                let i = group * LANES + lane;
                let sample = rays.sample[i];
                let shadow = setup.features.shadows && hit & (1 << lane) != 0;
                let mut node = Node {
                    added: Vec3::new(added[0][lane], added[1][lane], added[2][lane]),
                    first_child: next.len() as u32,
                    children: 0,
                    kind: rays.kind[i],
                    shadow,
                };
                let mut within_budget = true;
                if counting {
                    let counted = &mut self.sample_rays[sample as usize];
                    *counted += 1 + u32::from(shadow);
                    within_budget = *counted < RAY_BUDGET;
                }
                if can_send && sends & (1 << lane) != 0 && within_budget {
                    node.children = pack_children(&shaded, &bits, lane, sample, next);
                }
                nodes.push(node);
            }
        }
        self.counts.0[RayKind::Shadow.index()] += u64::from(shadows);
        for kind in &rays.kind[..rays.len()] {
            self.counts.0[kind.index()] += 1;
        }
    }
}

// ANCHOR: pack
/// A group's masks as bits, lane `k` in bit `k`.
struct Bits {
    reflects: i32,
    transmits: i32,
    total: i32,
}

/// Append lane `lane`'s transmitted and reflected rays to the next wave,
/// in the order the scalar ray stack pops them; returns how many.
fn pack_children(shaded: &Shaded, bits: &Bits, lane: usize, sample: u32, next: &mut Rays) -> u8 {
    let set = |mask: i32| mask & (1 << lane) != 0;
    let mut children = 0;
    if let Some((from, direction, _)) = &shaded.transmitted
        && set(bits.transmits)
    {
        let kind = if set(bits.total) {
            RayKind::TotalInternalReflection
        } else {
            RayKind::Refraction
        };
        let weight = shaded.transmission.as_array_ref()[lane];
        next.push(from.lane(lane), direction.lane(lane), weight, sample, kind);
        children += 1;
    }
    if let Some((from, direction)) = &shaded.reflected
        && set(bits.reflects)
    {
        let weight = shaded.reflection.as_array_ref()[lane];
        let kind = RayKind::Reflection;
        next.push(from.lane(lane), direction.lane(lane), weight, sample, kind);
        children += 1;
    }
    children
}
// ANCHOR_END: pack
