//! Eight vectors side by side, for the tracers that work on eight rays or
//! paths at once (chapter 7, and chapter 6's eight lanes): the x of every
//! lane in one `f32x8`, and so on, a *structure of arrays*. Every operation
//! is the one glam's `Vec3A` does, component by component and in the same
//! order, so each lane's result is the scalar code's to the bit.

use std::ops::{Add, Mul, Neg, Sub};

use crate::{Camera, Vec3};
use wide::{CmpGt, CmpLt, f32x8};

/// How many rays are traced at once: one AVX register of `f32`.
pub const LANES: usize = 8;

/// Eight vectors, one per lane.
#[derive(Clone, Copy, Debug)]
pub struct Vec3x8 {
    pub x: f32x8,
    pub y: f32x8,
    pub z: f32x8,
}

impl Vec3x8 {
    pub const ZERO: Vec3x8 = Vec3x8::splat_const(0.0);
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
/// `old` is read through `black_box`. Without it, LLVM (version 22 in Rust
/// 1.95) turns a blend of a value loaded from memory, stored back to the
/// same place, into one masked store (`vmaskmovps`). AMD's Zen 1–3
/// processors run that instruction in microcode, many times slower than a
/// blend and a store: on this project's Zen 3 machine it made chapter 6's
/// eight lanes slower than one path at a time. (LLVM's pull request
/// 214187, of August 2026, stops that on those processors.) The lanes
/// chosen are the same either way. Where no lane needs its old value, a
/// whole store needs no blend at all, and where a count grows, a sum
/// (chapter 6's `Paths` does both).
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

// ANCHOR: plane
/// Where eight rays meet a plane (a point on it and its unit normal, in
/// every lane): `t` in every lane, and a mask of the lanes it counts in.
#[inline]
pub fn plane_hits(point: Vec3x8, normal: Vec3x8, o: Vec3x8, d: Vec3x8) -> (f32x8, f32x8) {
    let denom = d.dot(normal);
    let t = (point - o).dot(normal) / denom;
    // Mask 1: a ray parallel to the plane never meets it. Its lane
    // divided by (almost) zero above; the mask throws that away.
    let crosses = !denom.abs().cmp_lt(f32x8::splat(1e-8));
    // Mask 2: only crossings in front of the ray count.
    (t, crosses & t.cmp_gt(f32x8::ZERO))
}
// ANCHOR_END: plane

// ANCHOR: sphere
/// Where eight rays meet a sphere (its centre and squared radius, in every
/// lane): the nearest `t > 0` in every lane, and the lanes that hit it.
/// The arithmetic is `Sphere::intersect`'s, operation for operation.
#[inline]
pub fn sphere_hits(centre: Vec3x8, radius_squared: f32x8, o: Vec3x8, d: Vec3x8) -> (f32x8, f32x8) {
    let oc = o - centre;
    let b = oc.dot(d);
    let q = oc.dot(oc) - radius_squared;
    let disc = b * b - q;
    let meets = !disc.cmp_lt(f32x8::ZERO);
    // Divergence: most spheres are missed by all eight rays of a
    // group, and then the square root (the slow part) is skipped.
    if meets.none() {
        return (f32x8::ZERO, meets);
    }
    // A lane whose line misses the sphere takes the square root of a
    // negative number (NaN); its mask is clear, so nothing reads it.
    let root = disc.sqrt();
    let minus_b = negate(b);
    let t0 = minus_b - root;
    let t1 = minus_b + root;
    // Mask: where the ray enters in front of its origin, t0 counts;
    // where the origin is inside the sphere (t0 ≤ 0), the exit t1.
    let front = t0.cmp_gt(f32x8::ZERO);
    let t = front.blend(t0, t1);
    let hit = meets & (front | t1.cmp_gt(f32x8::ZERO));
    (t, hit)
}
// ANCHOR_END: sphere

/// What every camera ray of an image shares, in all eight lanes: eight
/// camera rays at once, operation for operation as `Camera::ray` makes one,
/// so the directions are the same to the bit.
#[derive(Clone, Copy, Debug)]
pub struct CameraX8 {
    pub eye: Vec3x8,
    size: (f32x8, f32x8),
    aspect: f32x8,
    half_height: f32x8,
    forward: Vec3x8,
    right: Vec3x8,
    up: Vec3x8,
}

impl CameraX8 {
    pub fn new(camera: &Camera, width: u32, height: u32) -> Self {
        let (w, h) = (width as f32, height as f32);
        CameraX8 {
            eye: Vec3x8::splat(camera.eye),
            size: (f32x8::splat(w), f32x8::splat(h)),
            aspect: f32x8::splat(w / h),
            half_height: f32x8::splat(camera.half_height()),
            forward: Vec3x8::splat(camera.forward()),
            right: Vec3x8::splat(camera.right()),
            up: Vec3x8::splat(camera.up()),
        }
    }

    /// The unit directions through image points (`i + sx`, `j + sy`), in
    /// pixels, one per lane.
    #[inline]
    pub fn directions(&self, column: f32x8, row: f32x8) -> Vec3x8 {
        self.through(self.across(column), self.down(row))
    }

    /// The part of a direction that depends only on the point's column:
    /// `forward + right · x`. The same for every row, so a tracer that
    /// makes the same columns in every row can work it out once.
    #[inline]
    pub fn across(&self, column: f32x8) -> Vec3x8 {
        let two = f32x8::splat(2.0);
        let x = (two * column / self.size.0 - f32x8::ONE) * self.half_height * self.aspect;
        self.forward + self.right.scale(x)
    }

    /// The part that depends only on the point's row: `y`, the distance
    /// up the image plane.
    #[inline]
    pub fn down(&self, row: f32x8) -> f32x8 {
        let two = f32x8::splat(2.0);
        (f32x8::ONE - two * row / self.size.1) * self.half_height
    }

    /// The unit direction from the two parts: `forward + right · x + up ·
    /// y`, added in that order as `Camera::ray` adds them, and normalised.
    #[inline]
    pub fn through(&self, across: Vec3x8, y: f32x8) -> Vec3x8 {
        (across + self.up.scale(y)).normalize()
    }
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

    #[test]
    fn eight_camera_rays_at_a_time_are_camera_ray_to_the_bit() {
        let camera = Camera::lab();
        let wide = CameraX8::new(&camera, 803, 7);
        let pixel = |l: usize| (100 * l as u32 + 2, l as u32 % 7);
        let offset = |l: usize| (0.37 + 0.07 * l as f32, 0.93 - 0.11 * l as f32);
        let column = f32x8::new(std::array::from_fn(|l| pixel(l).0 as f32 + offset(l).0));
        let row = f32x8::new(std::array::from_fn(|l| pixel(l).1 as f32 + offset(l).1));
        let d = wide.directions(column, row).to_lanes();
        for (l, d) in d.iter().enumerate() {
            let (i, j) = pixel(l);
            assert_eq!(
                *d,
                camera.ray(i, j, offset(l), 803, 7).direction,
                "lane {l}"
            );
        }
    }
}
