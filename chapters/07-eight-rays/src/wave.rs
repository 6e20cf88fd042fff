//! Waves: every ray of one depth, for a whole image row, eight at a time.
//!
//! The scalar tracer follows one sample's ray tree to the bottom before it
//! starts the next sample. Here the row's primary rays are traced first,
//! all of them (wave 1); their reflected and refracted rays, packed densely,
//! form wave 2; and so on. Each ray leaves a [`Node`] behind: what it added
//! to its sample, and where its children are in the next wave. The sample's
//! colour is then summed by walking its tree in the scalar tracer's order,
//! so the sums round exactly as chapter 5's do.
//!
//! Everything a node does not need for that sum is counted a group at a
//! time (the rays by kind) or per sample (its rays and depth, for the
//! heat maps), and the latter only when it is asked for.

use raylab::RayKind;
use raylab::trace::{RAY_BUDGET, RayCounts};
use wide::f32x8;

use crate::intersect::{SceneX8, senders};
use crate::like::Features;
use crate::shade::{Light, reflect, refract};
use crate::soa::{LANES, LaneRays, Rays, Vec3x8};

/// What one traced ray did, kept until its sample's colour is summed.
/// Its children are rays `first_child ..` of the next wave, up to the next
/// node's `first_child` (each wave's nodes end with one more node, which
/// only marks the end), the transmitted one first: the order the scalar
/// ray stack pops them.
#[derive(Clone, Copy, Debug)]
pub struct Node {
    /// What the ray added to its sample: `w · (1 − r − t) · local`, or `w · sky`.
    pub added: [f32; 3],
    pub first_child: u32,
}

impl Node {
    /// The rays this node's ray sent on, as indices into the next wave.
    pub fn children(nodes: &[Node], index: usize) -> std::ops::Range<usize> {
        nodes[index].first_child as usize..nodes[index + 1].first_child as usize
    }
}

/// The fixed part of a render: the scene in lanes, the light, the limits.
pub struct Setup {
    pub scene: SceneX8,
    pub light: Light,
    pub features: Features,
    pub max_depth: u32,
    pub epsilon: f32,
    /// Whether each sample's rays and depth are kept, for the heat maps.
    pub maps: bool,
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
    /// `cast_shadow[d][i]`: whether ray `i` of `rays[d]` cast a shadow ray;
    /// kept only when a tree can reach the budget (to count its rays again).
    pub cast_shadow: Vec<Vec<bool>>,
    /// Per sample: rays traced so far, shadow rays included; kept for the
    /// heat maps, and when a tree can reach the budget at all (see
    /// [`budget_matters`]).
    pub sample_rays: Vec<u32>,
    /// Per sample: the depth of its deepest ray; kept for the heat maps.
    pub sample_deepest: Vec<u8>,
    /// Whether a tree can reach the budget in this render.
    counting: bool,
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
    pub fn start(&mut self, samples: usize, setup: &Setup) {
        let depths = setup.max_depth as usize;
        if self.rays.len() < depths {
            self.rays.resize_with(depths, Rays::default);
            self.nodes.resize_with(depths, Vec::new);
            self.cast_shadow.resize_with(depths, Vec::new);
        }
        for ((rays, nodes), shadows) in self
            .rays
            .iter_mut()
            .zip(&mut self.nodes)
            .zip(&mut self.cast_shadow)
        {
            rays.clear();
            nodes.clear();
            shadows.clear();
        }
        self.counting = budget_matters(setup.max_depth);
        self.sample_rays.clear();
        if self.counting || setup.maps {
            self.sample_rays.resize(samples, 0);
        }
        self.sample_deepest.clear();
        if setup.maps {
            self.sample_deepest.resize(samples, 0);
        }
        self.counts = RayCounts::default();
    }

    /// Whether a sample's tree grew to [`RAY_BUDGET`] rays. The scalar
    /// tracer cuts such a tree short at a point that depends on its
    /// depth-first order, so these samples are traced again by it.
    pub fn over_budget(&self, sample: usize) -> bool {
        self.counting && self.sample_rays[sample] >= RAY_BUDGET
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
    fn trace_wave(&mut self, setup: &Setup, depth: usize) {
        let can_send = depth < setup.max_depth as usize;
        let (this, rest) = self.rays.split_at_mut(depth);
        let rays = &mut this[depth - 1];
        let mut empty = Rays::default();
        let next = rest.first_mut().unwrap_or(&mut empty);
        let nodes = &mut self.nodes[depth - 1];
        rays.pad();
        if can_send {
            next.make_room(2 * rays.len());
        }
        nodes.reserve(rays.len() + 1);
        let mut per_sample = PerSample {
            rays: &mut self.sample_rays,
            deepest: &mut self.sample_deepest,
            cast_shadow: self.counting.then(|| &mut self.cast_shadow[depth - 1]),
            depth: depth as u8,
        };
        let mut shadows = 0;
        for group in 0..rays.groups() {
            let shaded = shade_group(setup, rays, group, can_send);
            let lanes = (rays.len() - group * LANES).min(LANES);
            let samples = &rays.sample[group * LANES..group * LANES + lanes];
            // The masks as bits, lane `k` in bit `k`; padding lanes cleared.
            let real = (1 << lanes) - 1;
            let cast_shadow = if setup.features.shadows {
                shaded.hit.move_mask() & real
            } else {
                0
            };
            shadows += cast_shadow.count_ones();
            let mut sends = Sends {
                reflects: shaded.reflects.move_mask() & real,
                transmits: shaded.transmits.move_mask() & real,
            };
            if !can_send {
                sends = Sends::NONE;
            }
            if !per_sample.rays.is_empty() {
                per_sample.count(samples, cast_shadow, &mut sends);
            }
            // The group's eight nodes at once: each lane's light, and where
            // its children will start (after the earlier lanes' children).
            let [x, y, z] = [shaded.added.x, shaded.added.y, shaded.added.z].map(|c| c.to_array());
            let mut first_child = next.len() as u32;
            let group_nodes: [Node; LANES] = std::array::from_fn(|lane| {
                let node = Node {
                    added: [x[lane], y[lane], z[lane]],
                    first_child,
                };
                first_child += sends.children(lane);
                node
            });
            // All eight copied (a copy of known size, inlined), then the
            // padding lanes' dropped: cheaper than a copy of `lanes`.
            let before = nodes.len();
            nodes.extend_from_slice(&group_nodes);
            nodes.truncate(before + lanes);
            if sends.any() {
                pack_children(&shaded, &sends, samples, next, &mut self.counts);
            }
        }
        nodes.push(Node {
            added: [0.0; 3],
            first_child: next.len() as u32,
        });
        self.counts.0[RayKind::Shadow.index()] += u64::from(shadows);
    }
}

/// Where a wave counts its rays into their samples.
struct PerSample<'a> {
    rays: &'a mut [u32],
    /// Empty when the heat maps are not drawn.
    deepest: &'a mut [u8],
    /// Kept only when a tree can reach the budget.
    cast_shadow: Option<&'a mut Vec<bool>>,
    depth: u8,
}

impl PerSample<'_> {
    /// Count one group's rays into their samples (for the heat maps and
    /// the budget), and stop the trees that reached the budget.
    fn count(&mut self, samples: &[u32], cast_shadow: i32, sends: &mut Sends) {
        for (lane, &sample) in samples.iter().enumerate() {
            let sample = sample as usize;
            let shadow = cast_shadow & (1 << lane) != 0;
            let counted = &mut self.rays[sample];
            *counted += 1 + u32::from(shadow);
            if let Some(deepest) = self.deepest.get_mut(sample) {
                *deepest = self.depth;
            }
            if let Some(cast_shadow) = &mut self.cast_shadow {
                if *counted >= RAY_BUDGET {
                    sends.reflects &= !(1 << lane);
                    sends.transmits &= !(1 << lane);
                }
                cast_shadow.push(shadow);
            }
        }
    }
}

// ANCHOR: pack
/// Which lanes of a group send on a reflected and a transmitted ray, lane
/// `k` in bit `k`.
struct Sends {
    reflects: i32,
    transmits: i32,
}

impl Sends {
    const NONE: Sends = Sends {
        reflects: 0,
        transmits: 0,
    };

    fn any(&self) -> bool {
        self.reflects | self.transmits != 0
    }

    /// How many rays lane `lane` sends on: 0, 1 or 2.
    fn children(&self, lane: usize) -> u32 {
        ((self.reflects >> lane) & 1) as u32 + ((self.transmits >> lane) & 1) as u32
    }
}

/// Append the group's transmitted and reflected rays to the next wave,
/// lane by lane and within a lane in the order the scalar ray stack pops
/// them (transmitted first), and count them by kind: every ray sent on is
/// traced. The registers are read out once per group.
fn pack_children(
    shaded: &Shaded,
    sends: &Sends,
    samples: &[u32],
    next: &mut Rays,
    counts: &mut RayCounts,
) {
    // Mask: where the light cannot leave the glass, the "transmitted" ray
    // is the mirror one, and counted as such.
    let total = shaded.transmitted.map_or(0, |t| t.2.move_mask());
    let mut count = |kind: RayKind, lanes: i32| {
        counts.0[kind.index()] += u64::from(lanes.count_ones());
    };
    count(RayKind::Reflection, sends.reflects);
    count(RayKind::Refraction, sends.transmits & !total);
    count(RayKind::TotalInternalReflection, sends.transmits & total);
    let transmitted = shaded
        .transmitted
        .map(|(from, direction, _)| LaneRays::new(from, direction, shaded.transmission));
    let reflected = shaded
        .reflected
        .map(|(from, direction)| LaneRays::new(from, direction, shaded.reflection));
    let mut lanes = sends.reflects | sends.transmits;
    while lanes != 0 {
        let lane = lanes.trailing_zeros() as usize;
        lanes &= lanes - 1;
        let sample = samples[lane];
        if let Some(rays) = &transmitted
            && sends.transmits & (1 << lane) != 0
        {
            let kind = if total & (1 << lane) != 0 {
                RayKind::TotalInternalReflection
            } else {
                RayKind::Refraction
            };
            next.push_lane(rays, lane, sample, kind);
        }
        if let Some(rays) = &reflected
            && sends.reflects & (1 << lane) != 0
        {
            next.push_lane(rays, lane, sample, RayKind::Reflection);
        }
    }
}
// ANCHOR_END: pack
