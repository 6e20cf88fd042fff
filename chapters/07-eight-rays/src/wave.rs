//! Waves: every ray of one depth, for a whole image row, eight at a time.
//!
//! The scalar tracer follows one sample's ray tree to the bottom before it
//! starts the next sample. Here the row's primary rays are traced first,
//! all of them (wave 1); their reflected and refracted rays, packed densely,
//! form wave 2 ([`crate::pack`]); and so on. Each ray leaves an entry in
//! the row's [`Ledger`] ([`crate::ledger`]):
//! what it added to its sample, and which entry the scalar ray stack would
//! pop after it. The sample's colour is then summed by following those
//! links from its primary ray, so the sums round exactly as chapter 5's do.
//!
//! Everything the sum does not need is counted a group at a time (the rays
//! by kind) or per sample (its rays and depth, for the heat maps), and the
//! latter only when it is asked for.

use raylab::RayKind;
use raylab::trace::{RAY_BUDGET, RayCounts};
use raylab_lanes::{SceneX8, reflect, refract};
use wide::{CmpGt, f32x8};

use crate::Features;
use crate::camera::{Primary, PrimaryRays};
use crate::ledger::Ledger;
use crate::link::LATER;
use crate::pack::{Links, Sends, pack_children};
use crate::shade::{Light, Shaded, senders};
use crate::soa::{Group, LANES, Rays, Vec3x8};

/// The fixed part of a render: the scene in lanes, the light, the limits.
pub struct Setup<'s> {
    /// What every row's primary rays share.
    pub primary: Primary,
    pub scene: SceneX8<'s>,
    pub light: Light,
    pub features: Features,
    pub max_depth: u32,
    pub epsilon: f32,
    /// Whether each sample's rays and depth are kept, for the heat maps.
    pub maps: bool,
}

// ANCHOR: group
/// Trace and shade one group of eight rays of a wave.
fn shade_group(setup: &Setup, rays: &Group, can_send: bool) -> Shaded {
    let (o, d, w) = (rays.origin, rays.direction, rays.weight);
    let hits = setup.scene.nearest(o, d);
    // Divergence: where all eight rays hit something, no lane sees the sky.
    let sky = if hits.hit.all() {
        Vec3x8::ZERO
    } else {
        setup.light.sky.radiance(d).scale(w)
    };
    let mut shaded = Shaded {
        added: sky,
        hit: hits.hit,
        reflects: f32x8::ZERO,
        transmits: f32x8::ZERO,
        reflected: None,
        transmitted: None,
        reflection: f32x8::ZERO,
        transmission: f32x8::ZERO,
        entering: f32x8::ZERO,
    };
    // Divergence, the cheap way out: when all eight rays see the sky,
    // none of the surface work below is needed.
    if hits.hit.none() {
        return shaded;
    }
    let s = setup.scene.surfaces(o, d, &hits);
    let eps = f32x8::splat(setup.epsilon);

    // Shadow rays from every lane that hit, as the scalar tracer casts
    // them; but only a surface that faces the sun needs the answer (on the
    // far side `cos θ` is 0, lit or not), so only those lanes are asked.
    let in_shadow = if setup.features.shadows {
        let to_sun = setup.light.to_sun;
        let faces_sun = hits.hit & s.facing_normal.dot(to_sun).cmp_gt(f32x8::ZERO);
        if faces_sun.none() {
            f32x8::ZERO
        } else {
            setup
                .scene
                .any(s.point + to_sun.scale(eps), to_sun, faces_sun)
        }
    } else {
        f32x8::ZERO
    };
    let local = setup.light.local(&s, in_shadow);
    // `(1 − r) − t`, subtracted one share at a time as `Surface::send` does.
    let kept = f32x8::ONE - s.reflection - s.transmission;
    let surface = local.scale(w * kept);
    // Mask: lanes that hit something show their surface, the others the sky.
    shaded.added = Vec3x8::select(hits.hit, surface, sky);

    shaded.entering = s.entering;
    let (reflects, transmits) = senders(&s, &hits, setup.features);
    shaded.reflects = reflects;
    shaded.transmits = transmits;
    // Divergence again: in most groups no lane hit the mirror or the
    // glass, and the optics is skipped. When 3 of 8 did, all 8 lanes
    // compute it and the masks keep the 3 answers.
    if can_send && (reflects | transmits).any() {
        let mirrored = reflect(d, s.facing_normal).normalize();
        let mirrored_from = s.point + mirrored.scale(eps);
        if reflects.any() {
            shaded.reflected = Some((mirrored_from, mirrored));
            shaded.reflection = w * s.reflection;
        }
        if transmits.any() {
            let eta = s.entering.blend(f32x8::ONE / s.ior, s.ior);
            let (bent, total) = refract(d, s.facing_normal, eta);
            let direction = Vec3x8::select(total, mirrored, bent.normalize());
            let from = s.point + direction.scale(eps);
            shaded.transmitted = Some((from, direction, total));
            shaded.transmission = w * s.transmission;
        }
    }
    shaded
}
// ANCHOR_END: group

/// A row's waves and ledger, kept by one worker and reused for every row.
#[derive(Default)]
pub struct Waves {
    /// The rays of the wave being traced (from wave 2 on; wave 1's are
    /// made by the camera as they are traced).
    rays: Rays,
    /// The rays it sends on: the next wave. Once a wave is traced, its
    /// rays are never read again (the ledger keeps what they did), so two
    /// arrays, swapped after each wave, serve every depth, and their
    /// memory stays warm in the cache from row to row.
    next: Rays,
    /// The rays sent on that travel inside a sphere, kept apart while the
    /// wave is traced and then put after the others in `next`, so that
    /// groups of the next wave hold rays that do the same things.
    inside: Rays,
    /// Every traced ray's light and link, numbered wave after wave.
    pub ledger: Ledger,
    /// Per ledger entry, the ray's kind and whether it cast a shadow ray;
    /// kept only when a tree can reach the budget (to count its rays again).
    pub kinds: Vec<(RayKind, bool)>,
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
        self.rays.clear();
        self.next.clear();
        self.inside.clear();
        self.ledger.clear();
        // Room for a typical row from the start (chapter 5's trees hold
        // about 2.8 rays besides their shadow rays): a ledger that grew by
        // doubling would copy itself over, into fresh pages, on the first
        // rows of every worker.
        self.ledger.reserve(4 * samples);
        self.kinds.clear();
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
    /// Trace every wave of the row: the primary rays (wave 1, made by the
    /// camera as they are traced), then the rays they sent on, down to
    /// `max_depth` or until a wave is empty.
    pub fn trace(&mut self, setup: &Setup, primary: &PrimaryRays) {
        self.counts.add(RayKind::Primary, primary.len() as u64);
        self.trace_wave(setup, 1, Some(primary));
        for depth in 2..=setup.max_depth as usize {
            // The rays just sent on become the wave to trace.
            std::mem::swap(&mut self.rays, &mut self.next);
            self.next.clear();
            if self.rays.is_empty() {
                break;
            }
            self.trace_wave(setup, depth, None);
        }
    }
    // ANCHOR_END: waves

    /// [`Waves::trace`], noting how many rays the ledger holds after each
    /// wave: entry `k` is the number of rays of waves 1 to `k + 1`. For the
    /// statistics of [`crate::stats`], kept apart from the render's loop.
    pub fn trace_noting_waves(&mut self, setup: &Setup, primary: &PrimaryRays) -> Vec<usize> {
        self.counts.add(RayKind::Primary, primary.len() as u64);
        self.trace_wave(setup, 1, Some(primary));
        let mut ends = vec![self.ledger.len()];
        for depth in 2..=setup.max_depth as usize {
            std::mem::swap(&mut self.rays, &mut self.next);
            self.next.clear();
            if self.rays.is_empty() {
                break;
            }
            self.trace_wave(setup, depth, None);
            ends.push(self.ledger.len());
        }
        ends
    }

    /// Trace the wave of rays at `depth` (the camera's `primary` rays, or
    /// those in `rays`), and pack the rays they send on densely into
    /// `next`, those inside a sphere after the others.
    fn trace_wave(&mut self, setup: &Setup, depth: usize, primary: Option<&PrimaryRays>) {
        let can_send = depth < setup.max_depth as usize;
        let (rays, next, inside) = (&mut self.rays, &mut self.next, &mut self.inside);
        let len = match primary {
            Some(primary) => primary.len(),
            None => {
                rays.pad();
                rays.len()
            }
        };
        // The next wave's rays get the ledger's numbers after this wave's.
        let next_wave_starts = (self.ledger.len() + len) as u32;
        if can_send {
            next.make_room(2 * len);
            inside.make_room(2 * len);
        }
        self.ledger.reserve(len);
        let mut per_sample = PerSample {
            rays: &mut self.sample_rays,
            deepest: &mut self.sample_deepest,
            kinds: self.counting.then_some(&mut self.kinds),
            depth: depth as u8,
        };
        let mut shadows = 0;
        for group in 0..len.div_ceil(LANES) {
            let eight = match primary {
                Some(primary) => primary.group(group),
                None => rays.group(group),
            };
            let shaded = shade_group(setup, &eight, can_send);
            let lanes = (len - group * LANES).min(LANES);
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
                ..Sends::NONE
            };
            if !can_send {
                sends = Sends::NONE;
            }
            if !per_sample.rays.is_empty() {
                per_sample.count(&eight, lanes, cast_shadow, &mut sends);
            }
            if sends.any() {
                // Sorting: rays that travel inside a sphere (transmitted
                // into it, or reflected inside it, totally or not) are
                // packed apart from the others. In the lab's scene half
                // the rays of the deeper waves bounce inside the glass and
                // half leave it for the ground or the sky: mixed, a group
                // would run the glass's optics and the ground's checker
                // and shadow ray both; sorted, most groups run one.
                let total = shaded.transmitted.map_or(f32x8::ZERO, |t| t.2);
                sends.transmits_inside = sends.transmits & (shaded.entering | total).move_mask();
                sends.reflects_inside = sends.reflects & (!shaded.entering).move_mask();
                let first = [
                    next_wave_starts + next.len() as u32,
                    LATER | inside.len() as u32,
                ];
                let links = Links::new(&sends, first, eight.after);
                let entry = self.ledger.len();
                self.ledger.push_group(shaded.added, links.next, lanes);
                self.ledger.unsettled(entry, links.unsettled);
                pack_children(
                    &shaded,
                    &sends,
                    eight.sample,
                    &links,
                    [&mut *next, &mut *inside],
                    &mut self.counts,
                );
            } else {
                // Nothing sent on: each lane's sample goes on where it would have.
                self.ledger.push_group(shaded.added, eight.after, lanes);
            }
        }
        self.counts.add(RayKind::Shadow, u64::from(shadows));
        // The rays inside spheres go after the others: now their numbers
        // are known, and the links to them are made final.
        if !inside.is_empty() {
            let base = next_wave_starts + next.len() as u32;
            self.ledger.settle(base);
            next.settle(base);
            inside.settle(base);
            next.append(inside);
            inside.clear();
        }
    }
}

/// Where a wave counts its rays into their samples.
struct PerSample<'a> {
    rays: &'a mut [u32],
    /// Empty when the heat maps are not drawn.
    deepest: &'a mut [u8],
    /// Kept only when a tree can reach the budget.
    kinds: Option<&'a mut Vec<(RayKind, bool)>>,
    depth: u8,
}

impl PerSample<'_> {
    /// Count one group's rays `at` into their samples (for the heat maps
    /// and the budget), and stop the trees that reached the budget.
    fn count(&mut self, rays: &Group, lanes: usize, cast_shadow: i32, sends: &mut Sends) {
        for lane in 0..lanes {
            let sample = rays.sample[lane] as usize;
            let shadow = cast_shadow & (1 << lane) != 0;
            let counted = &mut self.rays[sample];
            *counted += 1 + u32::from(shadow);
            if let Some(deepest) = self.deepest.get_mut(sample) {
                *deepest = self.depth;
            }
            if let Some(kinds) = &mut self.kinds {
                if *counted >= RAY_BUDGET {
                    sends.reflects &= !(1 << lane);
                    sends.transmits &= !(1 << lane);
                }
                kinds.push((rays.kind[lane], shadow));
            }
        }
    }
}
