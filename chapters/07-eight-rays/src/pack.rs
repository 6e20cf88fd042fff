//! Packing: the rays a group sends on, put densely into the next wave,
//! and the ledger's links that say which ray its sample's stack pops next.
//!
//! A group of eight rays sends on reflected and transmitted rays in only
//! some lanes. They are appended to the next wave in lane order, with no
//! gaps, so that its groups are full; the rays that travel inside a
//! sphere are kept apart and put after the others once the wave is done
//! (their numbers provisional until then, see [`crate::link::LATER`]).

use raylab::RayKind;
use raylab::trace::RayCounts;

use crate::shade::Shaded;
use crate::soa::{Group, LANES, Rays};

// ANCHOR: pack
/// Which lanes of a group send on a reflected and a transmitted ray, lane
/// `k` in bit `k`, and which of those rays travel inside a sphere.
pub(crate) struct Sends {
    pub reflects: i32,
    pub transmits: i32,
    /// Of the reflected rays, those reflected inside a sphere's surface.
    pub reflects_inside: i32,
    /// Of the transmitted rays, those that go into a sphere, or stay in
    /// it by total internal reflection.
    pub transmits_inside: i32,
}

impl Sends {
    pub const NONE: Sends = Sends {
        reflects: 0,
        transmits: 0,
        reflects_inside: 0,
        transmits_inside: 0,
    };

    pub fn any(&self) -> bool {
        self.reflects | self.transmits != 0
    }
}

/// The ledger's links of a group whose rays send rays on. The next wave's
/// rays are packed in two places, the rays outside spheres (numbered from
/// `first[0]` on) and those inside (numbered provisionally from `first[1]`,
/// see [`crate::link::LATER`]). Each place takes the group's transmitted
/// rays first, then its reflected ones. The scalar stack pops a ray's transmitted
/// child first, then its reflected one, then goes on `after`.
pub(crate) struct Links {
    /// Each lane's link: its first child, or `after` if it sent nothing.
    pub next: [u32; LANES],
    /// The transmitted children's: their sibling, or their parent's `after`.
    pub transmitted_after: [u32; LANES],
    /// The reflected children's: their parent's `after`.
    pub reflected_after: [u32; LANES],
    /// The lanes whose link (`next`) is provisional: a child inside.
    pub unsettled: i32,
}

impl Links {
    pub fn new(sends: &Sends, first: [u32; 2], after: [u32; LANES]) -> Links {
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
pub(crate) fn pack_children(
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
    use crate::link::{END, LATER, settle};

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
