//! Eight vectors side by side: the x of every lane in one `f32x8`, and so
//! on, a *structure of arrays*. Every operation is the one glam's `Vec3A`
//! does, component by component and in the same order, so each lane's
//! result is the scalar code's to the bit.

use std::ops::{Add, Mul, Neg, Sub};

use raylab::Vec3;
use wide::f32x8;

/// How many rays are traced at once: one AVX register of `f32`.
pub const LANES: usize = 8;

/// Eight vectors, one per lane.
#[derive(Clone, Copy, Debug)]
pub struct Vec3x8 {
    /// The eight vectors' x components.
    pub x: f32x8,
    /// Their y components.
    pub y: f32x8,
    /// Their z components.
    pub z: f32x8,
}

impl Vec3x8 {
    /// The zero vector in every lane.
    pub const ZERO: Vec3x8 = Vec3x8::splat_const(0.0);
    /// `(1, 1, 1)` in every lane: white, as a colour.
    pub const ONE: Vec3x8 = Vec3x8::splat_const(1.0);

    const fn splat_const(v: f32) -> Vec3x8 {
        let lanes = f32x8::new([v; LANES]);
        Vec3x8 {
            x: lanes,
            y: lanes,
            z: lanes,
        }
    }

    /// The same vector in every lane.
    #[inline]
    pub fn splat(v: Vec3) -> Vec3x8 {
        Vec3x8 {
            x: f32x8::splat(v.x),
            y: f32x8::splat(v.y),
            z: f32x8::splat(v.z),
        }
    }

    /// Lane `l` is `vectors[l]`.
    #[inline]
    pub fn from_lanes(vectors: [Vec3; LANES]) -> Vec3x8 {
        Vec3x8 {
            x: f32x8::new(vectors.map(|v| v.x)),
            y: f32x8::new(vectors.map(|v| v.y)),
            z: f32x8::new(vectors.map(|v| v.z)),
        }
    }

    /// The eight vectors as glam vectors, read out of the registers once.
    #[inline]
    pub fn to_lanes(self) -> [Vec3; LANES] {
        let (x, y, z) = (self.x.to_array(), self.y.to_array(), self.z.to_array());
        std::array::from_fn(|l| Vec3::new(x[l], y[l], z[l]))
    }

    /// Lane `l` as a glam vector.
    #[inline]
    pub fn lane(&self, l: usize) -> Vec3 {
        Vec3::new(
            self.x.as_array_ref()[l],
            self.y.as_array_ref()[l],
            self.z.as_array_ref()[l],
        )
    }

    // ANCHOR: dot
    /// Eight dot products. Summed as glam sums them, `(x·x' + y·y') + z·z'`:
    /// float addition is not associative, and the bytes must match.
    #[inline]
    pub fn dot(self, o: Vec3x8) -> f32x8 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Eight unit vectors, made as glam's `normalize` makes one: each
    /// component divided by the square root of the dot product (not
    /// multiplied by its reciprocal, which rounds differently).
    #[inline]
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
    #[inline]
    pub fn scale(self, s: f32x8) -> Vec3x8 {
        Vec3x8 {
            x: s * self.x,
            y: s * self.y,
            z: s * self.z,
        }
    }

    /// Lane by lane, `a` where `mask` is set and `b` elsewhere.
    #[inline]
    pub fn select(mask: f32x8, a: Vec3x8, b: Vec3x8) -> Vec3x8 {
        Vec3x8 {
            x: mask.blend(a.x, b.x),
            y: mask.blend(a.y, b.y),
            z: mask.blend(a.z, b.z),
        }
    }

    /// [`blend_back`] for each coordinate: `new` where `mask` is set and
    /// `old` elsewhere, for a vector stored back where `old` was read from.
    #[inline]
    pub fn blend_back(mask: f32x8, new: Vec3x8, old: Vec3x8) -> Vec3x8 {
        Vec3x8 {
            x: blend_back(mask, new.x, old.x),
            y: blend_back(mask, new.y, old.y),
            z: blend_back(mask, new.z, old.z),
        }
    }
}

/// `-x`, exactly: only the sign bit changes, as in scalar code (`wide`'s
/// own negation is `0 − x`, which turns −0 into +0).
#[inline]
pub fn negate(x: f32x8) -> f32x8 {
    x ^ f32x8::splat(-0.0)
}

// ANCHOR: blend_back
/// Lane by lane, `new` where `mask` is set and `old` elsewhere, like
/// `mask.blend(new, old)`, for a result stored back where `old` was read
/// from: a lane state kept in memory from one step to the next, such as
/// a path's between two bounces.
///
/// `old` is read through `black_box`. Without it, LLVM may turn a blend of
/// a value loaded from memory and stored back to the same place into one
/// masked store (`vmaskmovps`), which some processors run
/// in microcode, many times slower than a blend and a store. The lanes
/// chosen are the same either way. Where no lane needs its old value, a
/// whole store needs no blend at all, and where a count grows, a sum
/// (chapter 8's `Paths` does both).
#[inline]
pub fn blend_back(mask: f32x8, new: f32x8, old: f32x8) -> f32x8 {
    mask.blend(new, std::hint::black_box(old))
}
// ANCHOR_END: blend_back

/// A mask from the low eight bits of `bits` (lane `l` set where bit `l`
/// is): the form `move_mask` reads a mask out in, turned back.
#[inline]
pub fn mask_from_bits(bits: u32) -> f32x8 {
    f32x8::new(std::array::from_fn(|l| {
        f32::from_bits(if bits >> l & 1 == 1 { u32::MAX } else { 0 })
    }))
}

/// The lanes set in `bits`, lowest first.
#[inline]
pub fn lanes_of(mut bits: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (bits != 0).then(|| {
            let lane = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            lane
        })
    })
}

impl Neg for Vec3x8 {
    type Output = Vec3x8;
    #[inline]
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
    #[inline]
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
    #[inline]
    fn sub(self, o: Vec3x8) -> Vec3x8 {
        Vec3x8 {
            x: self.x - o.x,
            y: self.y - o.y,
            z: self.z - o.z,
        }
    }
}

/// Component by component, as a colour times a colour.
impl Mul for Vec3x8 {
    type Output = Vec3x8;
    #[inline]
    fn mul(self, o: Vec3x8) -> Vec3x8 {
        Vec3x8 {
            x: self.x * o.x,
            y: self.y * o.y,
            z: self.z * o.z,
        }
    }
}

/// Every component times the same number, as `Vec3A * f32`.
impl Mul<f32> for Vec3x8 {
    type Output = Vec3x8;
    #[inline]
    fn mul(self, s: f32) -> Vec3x8 {
        self.scale(f32x8::splat(s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eight_normalised_vectors_equal_glams_to_the_bit() {
        let vs: [Vec3; LANES] = std::array::from_fn(|i| {
            Vec3::new(0.1 + i as f32, -0.37 * i as f32, 1.0 / (i as f32 + 3.0))
        });
        let wide = Vec3x8::from_lanes(vs);
        let n = wide.normalize().to_lanes();
        let d = wide
            .dot(Vec3x8::splat(Vec3::new(0.3, -0.7, 0.2)))
            .to_array();
        for (i, v) in vs.iter().enumerate() {
            assert_eq!(n[i], v.normalize());
            assert_eq!(d[i], v.dot(Vec3::new(0.3, -0.7, 0.2)));
        }
    }

    #[test]
    fn negating_keeps_the_sign_of_zero_as_scalar_code_does() {
        let minus = negate(f32x8::splat(0.0)).as_array_ref()[0];
        assert!(minus == 0.0 && minus.is_sign_negative());
        assert!((-Vec3x8::ZERO).lane(3).x.is_sign_negative());
    }

    #[test]
    fn a_blend_stored_back_sets_the_masked_lanes_and_keeps_the_others_to_the_bit() {
        let old = f32x8::new([1.5, -0.0, f32::NAN, f32::INFINITY, 7.0, 0.0, -3.25, 1e-40]);
        let new = f32x8::new([0.0, 2.0, -0.0, 4.0, f32::NAN, -6.0, 7.5, 8.0]);
        for bits in [0, 0b0110_1001, 0b1001_0110, 0xff] {
            let mask = mask_from_bits(bits);
            let kept = blend_back(mask, new, old).to_array().map(f32::to_bits);
            let expected: [u32; LANES] = std::array::from_fn(|l| {
                let from = if bits >> l & 1 == 1 { new } else { old };
                from.as_array_ref()[l].to_bits()
            });
            assert_eq!(kept, expected, "mask {bits:08b}");
        }
    }

    #[test]
    fn a_mask_made_from_bits_reads_back_as_the_same_bits() {
        for bits in [0, 1, 0b1010_0101, 0xff] {
            assert_eq!(mask_from_bits(bits).move_mask() as u32, bits);
        }
        assert_eq!(lanes_of(0b1001_0010).collect::<Vec<_>>(), [1, 4, 7]);
    }
}
