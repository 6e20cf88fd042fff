//! Waves: every ray of one depth, for a whole image row, eight at a time.
//!
//! The scalar tracer follows one sample's ray tree to the bottom before it
//! starts the next sample. Here the row's primary rays are traced first,
//! all of them (wave 1); their reflected and refracted rays, packed densely,
//! form wave 2; and so on. Each ray leaves an entry in the row's [`Ledger`]:
//! what it added to its sample, and which entry the scalar ray stack would
//! pop after it. The sample's colour is then summed by following those
//! links from its primary ray, so the sums round exactly as chapter 5's do.
//!
//! Everything the sum does not need is counted a group at a time (the rays
//! by kind) or per sample (its rays and depth, for the heat maps), and the
//! latter only when it is asked for.

use raylab::trace::{RAY_BUDGET, RayCounts};
use raylab::{RayKind, Vec3};
use raylab_lanes::{SceneX8, reflect, refract};
use wide::{CmpGt, f32x8};

use crate::Features;
use crate::camera::{Primary, PrimaryRays};
use crate::link::{LATER, settle};
use crate::shade::{Light, senders};
use crate::soa::{Group, LANES, Rays, Vec3x8};

// ANCHOR: ledger
/// One entry per ray traced in a row, numbered in the order the waves
/// trace them (wave 1's rays first, so a primary ray's number is its
/// sample's): the light the ray added to its sample, `w · (1 − r − t) ·
/// local` or `w · sky`, and the number of the ray that the scalar ray stack
/// pops next for the same sample ([`END`](crate::link::END) after its last).
///
/// A ray that sends rays on links to its first child (the transmitted one,
/// which the stack pops first); the child links to its sibling, and the
/// last child to whatever its parent linked to before. The links are made
/// when the children are packed, so summing a sample is a walk along them.
///
/// Each entry is one record of 16 bytes, the light and the link side by
/// side: the walk reads one cache line per ray, not one from each of four
/// arrays.
#[derive(Clone, Debug, Default)]
pub struct Ledger {
    entries: Vec<Entry>,
    /// The entries whose link is provisional (see [`LATER`]) until the
    /// wave is done.
    unsettled: Vec<u32>,
}

/// One ray's entry: the light it added, and the ray popped after it.
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(16))]
struct Entry {
    light: [f32; 3],
    next: u32,
}
// ANCHOR_END: ledger

impl Ledger {
    pub fn clear(&mut self) {
        self.entries.clear();
        self.unsettled.clear();
    }

    /// How many rays are in the ledger: the number the next one gets.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// What ray `ray` added to its sample.
    pub fn light(&self, ray: usize) -> Vec3 {
        Vec3::from_array(self.entries[ray].light)
    }

    /// The ray its sample's stack pops after ray `ray`, or [`END`](crate::link::END).
    pub fn next(&self, ray: usize) -> u32 {
        self.entries[ray].next
    }

    /// Append a group's first `lanes` rays: the four numbers of each lane
    /// transposed into its record (a link travels as an `f32`'s bits).
    fn push_group(&mut self, light: Vec3x8, next: [u32; LANES], lanes: usize) {
        let next = f32x8::from(next.map(f32::from_bits));
        let zero = f32x8::ZERO;
        let rows = f32x8::transpose([light.x, light.y, light.z, next, zero, zero, zero, zero]);
        self.entries.extend(rows[..lanes].iter().map(|row| {
            let [x, y, z, next, ..] = row.to_array();
            Entry {
                light: [x, y, z],
                next: next.to_bits(),
            }
        }));
    }

    fn reserve(&mut self, more: usize) {
        self.entries.reserve(more + LANES);
    }

    /// Note that the links of the lanes of `unsettled` (lane `k` in bit
    /// `k`) of the group whose first entry is `first` are provisional.
    fn unsettled(&mut self, first: usize, unsettled: i32) {
        let lanes = raylab_lanes::lanes_of(unsettled as u32);
        self.unsettled
            .extend(lanes.map(|lane| (first + lane) as u32));
    }

    /// Make the provisional links final.
    fn settle(&mut self, base: u32) {
        for entry in self.unsettled.drain(..) {
            settle(&mut self.entries[entry as usize].next, base);
        }
    }
}

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
    /// Set where the ray arrived from outside its surface.
    entering: f32x8,
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

// ANCHOR: pack
/// Which lanes of a group send on a reflected and a transmitted ray, lane
/// `k` in bit `k`, and which of those rays travel inside a sphere.
struct Sends {
    reflects: i32,
    transmits: i32,
    /// Of the reflected rays, those reflected inside a sphere's surface.
    reflects_inside: i32,
    /// Of the transmitted rays, those that go into a sphere, or stay in
    /// it by total internal reflection.
    transmits_inside: i32,
}

impl Sends {
    const NONE: Sends = Sends {
        reflects: 0,
        transmits: 0,
        reflects_inside: 0,
        transmits_inside: 0,
    };

    fn any(&self) -> bool {
        self.reflects | self.transmits != 0
    }
}

/// The ledger's links of a group whose rays send rays on. The next wave's
/// rays are packed in two places, the rays outside spheres (numbered from
/// `first[0]` on) and those inside (numbered provisionally from `first[1]`,
/// see [`LATER`]). Each place takes the group's transmitted rays first,
/// then its reflected ones. The scalar stack pops a ray's transmitted
/// child first, then its reflected one, then goes on `after`.
struct Links {
    /// Each lane's link: its first child, or `after` if it sent nothing.
    next: [u32; LANES],
    /// The transmitted children's: their sibling, or their parent's `after`.
    transmitted_after: [u32; LANES],
    /// The reflected children's: their parent's `after`.
    reflected_after: [u32; LANES],
    /// The lanes whose link (`next`) is provisional: a child inside.
    unsettled: i32,
}

impl Links {
    fn new(sends: &Sends, first: [u32; 2], after: [u32; LANES]) -> Links {
        let (t, r) = (sends.transmits, sends.reflects);
        let (ti, ri) = (sends.transmits_inside, sends.reflects_inside);
        // Per place (outside, inside): the transmitted rays packed there,
        // the reflected ones, and the number of the first.
        let places = [(t & !ti, r & !ri, first[0]), (ti, ri, first[1])];
        let mut links = Links {
            next: after,
            transmitted_after: after,
            reflected_after: after,
            unsettled: (t & ti) | (r & !t & ri),
        };
        for lane in 0..LANES {
            let bit = 1 << lane;
            // The lanes before this one, whose children are packed first.
            let before = bit - 1;
            let number = |inside: i32, transmitted: bool| {
                let (pt, pr, first) = places[usize::from(inside & bit != 0)];
                if transmitted {
                    first + (pt & before).count_ones()
                } else {
                    first + pt.count_ones() + (pr & before).count_ones()
                }
            };
            if r & bit != 0 {
                let reflected = number(ri, false);
                links.next[lane] = reflected;
                links.transmitted_after[lane] = reflected;
            }
            if t & bit != 0 {
                links.next[lane] = number(ti, true);
            }
        }
        links
    }
}

/// Append the group's transmitted rays, then its reflected ones, to the
/// next wave, each packed densely in lane order: the rays that travel
/// inside a sphere to `inside`, the others to `next`. Count them by kind:
/// every ray sent on is traced.
fn pack_children(
    shaded: &Shaded,
    sends: &Sends,
    sample: [u32; LANES],
    links: &Links,
    [next, inside]: [&mut Rays; 2],
    counts: &mut RayCounts,
) {
    // Mask: where the light cannot leave the glass, the "transmitted" ray
    // is the mirror one, and counted as such.
    let total = shaded.transmitted.map_or(0, |t| t.2.move_mask());
    let mut count = |kind: RayKind, lanes: i32| {
        counts.add(kind, u64::from(lanes.count_ones()));
    };
    count(RayKind::Reflection, sends.reflects);
    count(RayKind::Refraction, sends.transmits & !total);
    count(RayKind::TotalInternalReflection, sends.transmits & total);
    if let Some((origin, direction, _)) = shaded.transmitted
        && sends.transmits != 0
    {
        let kind = std::array::from_fn(|lane| {
            if total & (1 << lane) != 0 {
                RayKind::TotalInternalReflection
            } else {
                RayKind::Refraction
            }
        });
        let rays = Group {
            origin,
            direction,
            weight: shaded.transmission,
            sample,
            kind,
            after: links.transmitted_after,
        };
        next.push_packed(sends.transmits & !sends.transmits_inside, &rays);
        inside.push_packed(sends.transmits_inside, &rays);
    }
    if let Some((origin, direction)) = shaded.reflected
        && sends.reflects != 0
    {
        let rays = Group {
            origin,
            direction,
            weight: shaded.reflection,
            sample,
            kind: [RayKind::Reflection; LANES],
            after: links.reflected_after,
        };
        next.push_packed(sends.reflects & !sends.reflects_inside, &rays);
        inside.push_packed(sends.reflects_inside, &rays);
    }
}
// ANCHOR_END: pack

#[cfg(test)]
mod tests {
    use super::*;
    use crate::link::END;

    #[test]
    fn a_ray_that_sends_both_links_to_its_transmitted_child_then_its_reflected_one() {
        // Lane 1 sends both rays, lane 3 only a reflected one, lane 6 only
        // a transmitted one; the others nothing. The next wave's rays are
        // numbered from 100: transmitted ones (lanes 1, 6) first, then the
        // reflected ones (lanes 1, 3).
        let sends = Sends {
            transmits: 0b0100_0010,
            reflects: 0b0000_1010,
            ..Sends::NONE
        };
        let after: [u32; LANES] = std::array::from_fn(|lane| 10 + lane as u32);
        let links = Links::new(&sends, [100, LATER], after);
        assert_eq!(links.next, [10, 100, 12, 103, 14, 15, 101, 17]);
        // Lane 1's transmitted ray goes on with its sibling (102), lane 6's
        // with what lane 6 went on with.
        assert_eq!(links.transmitted_after[1], 102);
        assert_eq!(links.transmitted_after[6], 16);
        assert_eq!(links.reflected_after[1], 11);
        assert_eq!(links.reflected_after[3], 13);
    }

    #[test]
    fn rays_inside_a_sphere_are_numbered_after_the_others_once_the_wave_is_done() {
        // As above, but lane 1's transmitted ray goes into the glass and
        // lane 3's reflected ray stays inside it. The others are packed
        // from 100 (lane 6's transmitted ray, then lane 1's reflected
        // one); the two inside get provisional numbers, and once the wave
        // is done they follow the others: 102 and 103.
        let sends = Sends {
            transmits: 0b0100_0010,
            reflects: 0b0000_1010,
            transmits_inside: 0b0000_0010,
            reflects_inside: 0b0000_1000,
        };
        let after: [u32; LANES] = std::array::from_fn(|lane| 10 + lane as u32);
        let links = Links::new(&sends, [100, LATER], after);
        assert_eq!(links.unsettled, 0b0000_1010, "lanes 1 and 3 link inside");
        let mut next = links.next;
        next.iter_mut().for_each(|n| settle(n, 102));
        assert_eq!(next, [10, 102, 12, 103, 14, 15, 100, 17]);
        assert_eq!(links.transmitted_after[1], 101);
        assert_eq!(links.transmitted_after[6], 16);
        let mut end = END;
        settle(&mut end, 102);
        assert_eq!(end, END);
    }
}
