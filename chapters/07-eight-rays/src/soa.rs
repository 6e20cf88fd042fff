//! Structure of arrays: eight rays side by side, one number of each per lane.
//!
//! The scalar chapters keep a ray as one struct (`origin`, `direction`, …):
//! an *array of structures*. To work on eight rays at once, the eight
//! origins' x coordinates must sit next to each other in one register, the
//! y coordinates in another, and so on: a *structure of arrays*. Between
//! waves a ray is kept as one record of eight numbers, and a transpose
//! turns eight records into eight such registers and back.

use raylab::RayKind;
use raylab::Vec3;
use wide::f32x8;

/// Eight vectors side by side, from `raylab-lanes`, which chapter 8's
/// paths use too.
pub use raylab_lanes::{LANES, Vec3x8, negate};

// ANCHOR: rays
/// A wave of rays. Each ray is one *record* of eight numbers, exactly one
/// `f32x8`: its origin, its direction, its weight, and the number of its
/// sample (as an `f32`'s bits). In registers a group is eight arrays, one
/// per number; in memory a wave is records, one per ray. An 8 × 8
/// transpose turns one form into the other ([`Rays::group`],
/// [`Rays::push_packed`]), so that loading a group is eight loads and
/// packing a ray sent on is one store, where one array per number would
/// take ten stores to ten places for every ray.
///
/// The arrays are kept longer than the wave (see [`Rays::make_room`]) and
/// written in place with no check of capacity per ray; the first `len`
/// entries are the real rays, and [`Rays::pad`] fills the last group.
#[derive(Clone, Debug, Default)]
pub struct Rays {
    /// `[ox, oy, oz, dx, dy, dz, weight, sample]` per ray.
    records: Vec<f32x8>,
    pub kind: Vec<RayKind>,
    /// The ray that the scalar stack pops once this ray's whole subtree is
    /// done, as a number in the row's ledger ([`crate::ledger::Ledger`]), or
    /// [`crate::link::END`] where the sample is then finished.
    pub after: Vec<u32>,
    len: usize,
}
// ANCHOR_END: rays

/// Eight rays in registers, as the shading takes them and as a group's
/// rays sent on are packed into the next wave: with each lane's sample,
/// kind, and the ray its sample goes on with after this ray's subtree.
#[derive(Clone, Copy, Debug)]
pub struct Group {
    pub origin: Vec3x8,
    pub direction: Vec3x8,
    /// The share of the ray's light that reaches its sample.
    pub weight: f32x8,
    /// Which of the row's samples the ray belongs to.
    pub sample: [u32; LANES],
    pub kind: [RayKind; LANES],
    pub after: [u32; LANES],
}

impl Group {
    // ANCHOR: records
    /// The eight rays as eight records, lane `k`'s in entry `k`: the
    /// registers (one number of every ray each) transposed.
    fn records(&self) -> [f32x8; LANES] {
        let (o, d) = (self.origin, self.direction);
        // A sample's number travels in a float lane as its bits; the
        // transpose moves bits and never does arithmetic on them.
        let sample = f32x8::from(self.sample.map(f32::from_bits));
        f32x8::transpose([o.x, o.y, o.z, d.x, d.y, d.z, self.weight, sample])
    }
    // ANCHOR_END: records
}

impl Rays {
    /// Empty, keeping the memory (and its length) for the next row.
    pub fn clear(&mut self) {
        self.len = 0;
    }

    /// Make the arrays long enough for `more` rays after the real ones,
    /// and a whole 8-lane group written after those.
    pub fn make_room(&mut self, more: usize) {
        let room = (self.len + more).next_multiple_of(LANES) + LANES;
        if self.records.len() < room {
            self.records.resize(room, f32x8::ZERO);
            self.kind.resize(room, RayKind::Primary);
            self.after.resize(room, 0);
        }
    }

    /// Append one ray; there must be room for it.
    pub fn push(&mut self, origin: Vec3, direction: Vec3, weight: f32, sample: u32, kind: RayKind) {
        let i = self.len;
        let (o, d) = (origin, direction);
        let sample = f32::from_bits(sample);
        self.records[i] = f32x8::from([o.x, o.y, o.z, d.x, d.y, d.z, weight, sample]);
        (self.kind[i], self.after[i]) = (kind, crate::link::END);
        self.len += 1;
    }

    // ANCHOR: packed
    /// Append the lanes of `rays` that `mask` selects (lane `k` in bit
    /// `k`), packed densely in lane order; there must be room for them.
    #[inline]
    pub fn push_packed(&mut self, mask: i32, rays: &Group) {
        if mask == 0 {
            return;
        }
        let records = rays.records();
        let at = self.len..self.len + LANES;
        let (to, kinds, afters) = (
            &mut self.records[at.clone()],
            &mut self.kind[at.clone()],
            &mut self.after[at],
        );
        // Every lane at once where all eight are sent on (inside the glass,
        // most groups): eight records copied as a block.
        if mask == 0xff {
            to.copy_from_slice(&records);
            kinds.copy_from_slice(&rays.kind);
            afters.copy_from_slice(&rays.after);
            self.len += LANES;
            return;
        }
        // Otherwise one record per selected lane, in lane order.
        let mut packed = 0;
        let mut lanes = mask;
        while lanes != 0 {
            let lane = lanes.trailing_zeros() as usize % LANES;
            lanes &= lanes - 1; // the lowest selected lane is done
            to[packed] = records[lane];
            (kinds[packed], afters[packed]) = (rays.kind[lane], rays.after[lane]);
            packed += 1;
        }
        self.len += packed;
    }
    // ANCHOR_END: packed

    /// Append `other`'s rays; there must be room for them.
    pub fn append(&mut self, other: &Rays) {
        let (at, n) = (self.len, other.len);
        self.records[at..at + n].copy_from_slice(&other.records[..n]);
        self.kind[at..at + n].copy_from_slice(&other.kind[..n]);
        self.after[at..at + n].copy_from_slice(&other.after[..n]);
        self.len += n;
    }

    /// Make the provisional links in `after` final (see
    /// [`crate::link::settle`]).
    pub fn settle(&mut self, base: u32) {
        for after in &mut self.after[..self.len] {
            crate::link::settle(after, base);
        }
    }

    /// The real rays (without the padding).
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The number of 8-lane groups, the last one perhaps partly padding.
    pub fn groups(&self) -> usize {
        self.len.div_ceil(LANES)
    }

    /// Fill the last group with copies of the last ray, so that every
    /// group loads eight real numbers (never NaN left from an earlier row,
    /// nor a stale ray). What the copies compute is thrown away.
    pub fn pad(&mut self) {
        let (len, padded) = (self.len, self.groups() * LANES);
        if len == 0 {
            return;
        }
        self.make_room(0);
        let last = self.records[len - 1];
        self.records[len..padded].fill(last);
    }

    /// Group `group`'s eight rays (the padding lanes' kind and link are
    /// stale: only the real lanes' are read).
    pub fn group(&self, group: usize) -> Group {
        let [ox, oy, oz, dx, dy, dz, weight, sample] =
            f32x8::transpose(lanes_of(&self.records, group));
        Group {
            origin: Vec3x8 {
                x: ox,
                y: oy,
                z: oz,
            },
            direction: Vec3x8 {
                x: dx,
                y: dy,
                z: dz,
            },
            weight,
            sample: sample.to_array().map(f32::to_bits),
            kind: lanes_of(&self.kind, group),
            after: lanes_of(&self.after, group),
        }
    }
}

/// Group `group`'s eight entries of one of the arrays.
fn lanes_of<T: Copy>(numbers: &[T], group: usize) -> [T; LANES] {
    numbers[group * LANES..(group + 1) * LANES]
        .try_into()
        .expect("waves are padded to whole groups")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_wave_of_three_rays_pads_to_one_group_of_copies() {
        let mut rays = Rays::default();
        rays.make_room(3);
        for i in 0..3 {
            rays.push(Vec3::ZERO, Vec3::X, i as f32, i, RayKind::Primary);
        }
        rays.pad();
        assert_eq!((rays.len(), rays.groups()), (3, 1));
        assert_eq!(
            rays.group(0).weight.to_array(),
            [0., 1., 2., 2., 2., 2., 2., 2.]
        );
    }

    #[test]
    fn packing_lanes_1_4_and_6_writes_them_first_in_order() {
        let mut rays = Rays::default();
        rays.make_room(LANES);
        let lane_numbers = f32x8::from(std::array::from_fn::<f32, 8, _>(|i| i as f32));
        let eight = Group {
            origin: Vec3x8::splat(Vec3::ZERO),
            direction: Vec3x8::splat(Vec3::X),
            weight: lane_numbers,
            sample: std::array::from_fn(|i| 10 + i as u32),
            kind: [RayKind::Reflection; LANES],
            after: std::array::from_fn(|i| 20 + i as u32),
        };
        rays.push_packed(0b0101_0010, &eight);
        rays.push_packed(0b1111_1111, &eight);
        rays.pad();
        assert_eq!((rays.len(), rays.groups()), (11, 2));
        assert_eq!(
            rays.group(0).weight.to_array(),
            [1., 4., 6., 0., 1., 2., 3., 4.]
        );
        assert_eq!(
            rays.group(1).weight.to_array(),
            [5., 6., 7., 7., 7., 7., 7., 7.]
        );
        assert_eq!(&rays.group(0).sample[..4], &[11, 14, 16, 10]);
        assert_eq!(&rays.after[..4], &[21, 24, 26, 20]);
    }
}
