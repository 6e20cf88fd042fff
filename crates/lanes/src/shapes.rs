//! The lab's two shapes against eight rays at once: `Plane::intersect`
//! and `Sphere::intersect`, operation for operation, with masks where the
//! scalar code branches.

use wide::{CmpGt, CmpLt, f32x8};

use crate::vec3x8::{Vec3x8, negate};

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
