//! Structure of arrays: eight rays side by side, one number of each per lane.
//!
//! The scalar chapters keep a ray as one struct (`origin`, `direction`, …):
//! an *array of structures*. To work on eight rays at once, the eight
//! origins' x coordinates must sit next to each other in one register, the
//! y coordinates in another, and so on. So a wave of rays is stored as one
//! array per number (a *structure of arrays*), and eight consecutive
//! entries load straight into one `f32x8`.

use std::ops::{Add, Neg, Sub};

use raylab::{RayKind, Vec3};
use wide::f32x8;

/// How many rays are traced at once: one AVX register of `f32`.
pub const LANES: usize = 8;

/// Eight vectors: the x of every lane in `x`, and so on.
#[derive(Clone, Copy, Debug)]
pub struct Vec3x8 {
    pub x: f32x8,
    pub y: f32x8,
    pub z: f32x8,
}

impl Vec3x8 {
    /// The same vector in every lane.
    pub fn splat(v: Vec3) -> Self {
        Vec3x8 {
            x: f32x8::splat(v.x),
            y: f32x8::splat(v.y),
            z: f32x8::splat(v.z),
        }
    }

    // ANCHOR: dot
    /// Eight dot products. Summed as glam sums them, `(x·x' + y·y') + z·z'`:
    /// float addition is not associative, and the bytes must match.
    pub fn dot(self, o: Vec3x8) -> f32x8 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Eight unit vectors, made as glam's `normalize` makes one: each
    /// component divided by the square root of the dot product (not
    /// multiplied by its reciprocal, which rounds differently).
    pub fn normalize(self) -> Vec3x8 {
        let length = self.dot(self).sqrt();
        Vec3x8 {
            x: self.x / length,
            y: self.y / length,
            z: self.z / length,
        }
    }
    // ANCHOR_END: dot

    /// Each lane's vector times that lane's number.
    pub fn scale(self, s: f32x8) -> Vec3x8 {
        Vec3x8 {
            x: s * self.x,
            y: s * self.y,
            z: s * self.z,
        }
    }

    /// Lane by lane, `a` where `mask` is set and `b` elsewhere.
    pub fn select(mask: f32x8, a: Vec3x8, b: Vec3x8) -> Vec3x8 {
        Vec3x8 {
            x: mask.blend(a.x, b.x),
            y: mask.blend(a.y, b.y),
            z: mask.blend(a.z, b.z),
        }
    }

    /// Lane `lane` as a glam vector.
    pub fn lane(&self, lane: usize) -> Vec3 {
        Vec3::new(
            self.x.as_array_ref()[lane],
            self.y.as_array_ref()[lane],
            self.z.as_array_ref()[lane],
        )
    }
}

/// `-x`, exactly: only the sign bit changes.
pub fn negate(x: f32x8) -> f32x8 {
    x ^ f32x8::splat(-0.0)
}

/// `-v` in every lane: the sign bit flipped, as `-v` does in scalar code
/// (`wide`'s own negation is `0 − v`, which turns −0 into +0).
impl Neg for Vec3x8 {
    type Output = Vec3x8;
    fn neg(self) -> Vec3x8 {
        Vec3x8 {
            x: negate(self.x),
            y: negate(self.y),
            z: negate(self.z),
        }
    }
}

impl Add for Vec3x8 {
    type Output = Vec3x8;
    fn add(self, o: Vec3x8) -> Vec3x8 {
        Vec3x8 {
            x: self.x + o.x,
            y: self.y + o.y,
            z: self.z + o.z,
        }
    }
}

impl Sub for Vec3x8 {
    type Output = Vec3x8;
    fn sub(self, o: Vec3x8) -> Vec3x8 {
        Vec3x8 {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

// ANCHOR: rays
/// A wave of rays, one array per number. The arrays are kept longer than
/// the wave (see [`Rays::make_room`]) and written in place, eight entries
/// at a time, with no check of capacity per ray; the first `len` entries
/// are the real rays, and [`Rays::pad`] fills the last 8-lane group.
#[derive(Clone, Debug, Default)]
pub struct Rays {
    ox: Vec<f32>,
    oy: Vec<f32>,
    oz: Vec<f32>,
    dx: Vec<f32>,
    dy: Vec<f32>,
    dz: Vec<f32>,
    /// The share of the ray's light that reaches its sample.
    weight: Vec<f32>,
    /// Which of the row's samples the ray belongs to.
    pub sample: Vec<u32>,
    pub kind: Vec<RayKind>,
    /// The ray that the scalar stack pops once this ray's whole subtree is
    /// done, as a number in the row's ledger ([`crate::wave::Ledger`]), or
    /// [`crate::wave::END`] where the sample is then finished.
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
    pub weight: f32x8,
    pub sample: [u32; LANES],
    pub kind: [RayKind; LANES],
    pub after: [u32; LANES],
}

impl Rays {
    /// Empty, keeping the memory (and its length) for the next row.
    pub fn clear(&mut self) {
        self.len = 0;
    }

    fn numbers_mut(&mut self) -> [&mut Vec<f32>; 7] {
        [
            &mut self.ox,
            &mut self.oy,
            &mut self.oz,
            &mut self.dx,
            &mut self.dy,
            &mut self.dz,
            &mut self.weight,
        ]
    }

    /// Make the arrays long enough for `more` rays after the real ones,
    /// and a whole 8-lane group written after those.
    pub fn make_room(&mut self, more: usize) {
        let room = (self.len + more).next_multiple_of(LANES) + LANES;
        if self.sample.len() < room {
            for numbers in self.numbers_mut() {
                numbers.resize(room, 0.0);
            }
            self.sample.resize(room, 0);
            self.kind.resize(room, RayKind::Primary);
            self.after.resize(room, 0);
        }
    }

    /// Append one ray; there must be room for it.
    pub fn push(&mut self, origin: Vec3, direction: Vec3, weight: f32, sample: u32, kind: RayKind) {
        let i = self.len;
        (self.ox[i], self.oy[i], self.oz[i]) = (origin.x, origin.y, origin.z);
        (self.dx[i], self.dy[i], self.dz[i]) = (direction.x, direction.y, direction.z);
        (self.weight[i], self.sample[i], self.kind[i]) = (weight, sample, kind);
        self.after[i] = crate::wave::END;
        self.len += 1;
    }

    // ANCHOR: packed
    /// Append the lanes of `rays` that `mask` selects (lane `k` in bit
    /// `k`), packed densely in lane order; there must be room for them.
    pub fn push_packed(&mut self, mask: i32, rays: &Group) {
        // Every lane at once where all eight are sent on (inside the glass,
        // most groups): eight entries of each array copied as a block.
        if mask == 0xff {
            self.push_all(rays);
            return;
        }
        // Otherwise lane by lane: the registers read out once, then one
        // loop over the selected lanes writes each lane's ten numbers.
        let (o, d) = (&rays.origin, &rays.direction);
        let [ox, oy, oz] = [o.x, o.y, o.z].map(f32x8::to_array);
        let [dx, dy, dz] = [d.x, d.y, d.z].map(f32x8::to_array);
        let weight = rays.weight.to_array();
        let mut lanes = mask;
        while lanes != 0 {
            let lane = lanes.trailing_zeros() as usize % LANES;
            lanes &= lanes - 1; // the lowest selected lane is done
            let i = self.len;
            (self.ox[i], self.oy[i], self.oz[i]) = (ox[lane], oy[lane], oz[lane]);
            (self.dx[i], self.dy[i], self.dz[i]) = (dx[lane], dy[lane], dz[lane]);
            self.weight[i] = weight[lane];
            (self.sample[i], self.kind[i]) = (rays.sample[lane], rays.kind[lane]);
            self.after[i] = rays.after[lane];
            self.len += 1;
        }
    }
    // ANCHOR_END: packed

    /// Append all eight rays of `rays`; there must be room for them.
    fn push_all(&mut self, rays: &Group) {
        let at = self.len..self.len + LANES;
        let (o, d) = (&rays.origin, &rays.direction);
        self.ox[at.clone()].copy_from_slice(o.x.as_array_ref());
        self.oy[at.clone()].copy_from_slice(o.y.as_array_ref());
        self.oz[at.clone()].copy_from_slice(o.z.as_array_ref());
        self.dx[at.clone()].copy_from_slice(d.x.as_array_ref());
        self.dy[at.clone()].copy_from_slice(d.y.as_array_ref());
        self.dz[at.clone()].copy_from_slice(d.z.as_array_ref());
        self.weight[at.clone()].copy_from_slice(rays.weight.as_array_ref());
        self.sample[at.clone()].copy_from_slice(&rays.sample);
        self.kind[at.clone()].copy_from_slice(&rays.kind);
        self.after[at].copy_from_slice(&rays.after);
        self.len += LANES;
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
        for numbers in self.numbers_mut() {
            let last = numbers[len - 1];
            numbers[len..padded].fill(last);
        }
    }

    fn load(numbers: &[f32], group: usize) -> f32x8 {
        f32x8::from(lanes_of(numbers, group))
    }

    pub fn origins(&self, group: usize) -> Vec3x8 {
        Vec3x8 {
            x: Rays::load(&self.ox, group),
            y: Rays::load(&self.oy, group),
            z: Rays::load(&self.oz, group),
        }
    }

    pub fn directions(&self, group: usize) -> Vec3x8 {
        Vec3x8 {
            x: Rays::load(&self.dx, group),
            y: Rays::load(&self.dy, group),
            z: Rays::load(&self.dz, group),
        }
    }

    pub fn weights(&self, group: usize) -> f32x8 {
        Rays::load(&self.weight, group)
    }

    /// Group `group`'s eight rays (the padding lanes' sample, kind and
    /// link are stale: only the real lanes' are read).
    pub fn group(&self, group: usize) -> Group {
        Group {
            origin: self.origins(group),
            direction: self.directions(group),
            weight: self.weights(group),
            sample: lanes_of(&self.sample, group),
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
    fn eight_normalised_vectors_equal_glams_to_the_bit() {
        let vs: Vec<Vec3> = (0..8)
            .map(|i| Vec3::new(0.1 + i as f32, -0.37 * i as f32, 1.0 / (i as f32 + 3.0)))
            .collect();
        let wide = Vec3x8 {
            x: f32x8::from(std::array::from_fn::<f32, 8, _>(|i| vs[i].x)),
            y: f32x8::from(std::array::from_fn::<f32, 8, _>(|i| vs[i].y)),
            z: f32x8::from(std::array::from_fn::<f32, 8, _>(|i| vs[i].z)),
        };
        let n = wide.normalize();
        let d = wide.dot(Vec3x8::splat(Vec3::new(0.3, -0.7, 0.2)));
        for (i, v) in vs.iter().enumerate() {
            assert_eq!(n.lane(i), v.normalize());
            assert_eq!(d.as_array_ref()[i], v.dot(Vec3::new(0.3, -0.7, 0.2)));
        }
    }

    #[test]
    fn negating_keeps_the_sign_of_zero_as_scalar_code_does() {
        let minus = negate(f32x8::splat(0.0)).as_array_ref()[0];
        assert!(minus == 0.0 && minus.is_sign_negative());
    }

    #[test]
    fn a_wave_of_three_rays_pads_to_one_group_of_copies() {
        let mut rays = Rays::default();
        rays.make_room(3);
        for i in 0..3 {
            rays.push(Vec3::ZERO, Vec3::X, i as f32, i, RayKind::Primary);
        }
        rays.pad();
        assert_eq!((rays.len(), rays.groups()), (3, 1));
        assert_eq!(rays.weights(0).to_array(), [0., 1., 2., 2., 2., 2., 2., 2.]);
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
        assert_eq!(rays.weights(0).to_array(), [1., 4., 6., 0., 1., 2., 3., 4.]);
        assert_eq!(rays.weights(1).to_array(), [5., 6., 7., 7., 7., 7., 7., 7.]);
        assert_eq!(&rays.sample[..4], &[11, 14, 16, 10]);
        assert_eq!(&rays.after[..4], &[21, 24, 26, 20]);
    }
}
