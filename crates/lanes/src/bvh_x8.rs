//! Chapter 9's tree for eight rays at a time: chapter 7's waves and
//! chapter 8's paths find their hits through it (`--objects tree`), to the
//! same bytes as testing every sphere.
//!
//! This is the faster floor beside [`Bvh`]'s search, which a learner reads
//! first in chapter 9: the same tree, the same widened boxes, the same tie
//! rule, with eight rays in the lanes of an `f32x8`, as [`SceneX8`] holds
//! them. It mirrors `Bvh::nearest_hit` and `Bvh::any_hit` as `SceneX8`
//! mirrors the list's.
//!
//! Two shapes of search would suit eight lanes. *One ray against several
//! boxes* needs a tree with eight children per node, and takes the rays
//! out of their lanes one by one; *eight rays against one node* keeps the
//! tree as it is and the rays where the tracers hold them. This is the
//! second: every node is tested against all eight rays at once, and opened
//! if any lane's ray enters it no farther than that lane's nearest hit so
//! far (a mask of the lanes says which). The eight rays of a group are
//! alike — a wave's rays come from one image row, and the shadow rays all
//! go towards the sun — so they mostly want the same nodes, and one test
//! serves eight. Rays that scatter every way (chapter 8's diffuse
//! bounces) visit the union of what each needs: still right, less of a
//! gain.

use ch09_many_spheres::bvh::{Bvh, COORDINATE_SLACK, DISTANCE_SLACK, MAX_DEPTH, Node};
use raylab::scene::{Hit, SceneQuery};
use raylab::{Ray, Vec3};
use wide::{CmpEq, CmpLe, CmpLt, f32x8};

#[cfg(doc)]
use crate::SceneX8;
use crate::{GROUND, Hits, NOTHING, SceneQueryX8, Vec3x8, plane_hits, sphere_hits};

/// [`Bvh`] searched by eight rays at a time.
#[derive(Clone, Debug)]
pub struct BvhX8<'t> {
    tree: &'t Bvh<'t>,
    plane_point: Vec3x8,
    plane_normal: Vec3x8,
}

impl<'t> BvhX8<'t> {
    /// The tree, and the ground's plane in every lane.
    pub fn new(tree: &'t Bvh<'t>) -> Self {
        let plane = &tree.scene().ground.plane;
        BvhX8 {
            tree,
            plane_point: Vec3x8::splat(plane.point),
            plane_normal: Vec3x8::splat(plane.normal),
        }
    }

    /// The tree it searches.
    pub fn tree(&self) -> &'t Bvh<'t> {
        self.tree
    }

    // ANCHOR: enter
    /// The lanes whose ray enters `node`'s widened box no farther than
    /// `t_max`: [`Bvh`]'s slab test and widening, lane by lane. `wide`'s
    /// `max` and `min` keep the left number where the right is NaN, as
    /// `f32::max` and `f32::min` do, so a NaN distance sets no limit here
    /// too.
    #[inline]
    fn enter(
        &self,
        node: &Node,
        o: Vec3x8,
        inverse: Vec3x8,
        coordinates: f32x8,
        t_max: f32x8,
    ) -> f32x8 {
        let (min, max) = (
            Vec3x8::splat(Vec3::from(node.min)),
            Vec3x8::splat(Vec3::from(node.max)),
        );
        let far = |lo: f32x8, hi: f32x8, o: f32x8| (o - lo).max(hi - o);
        let reach = far(min.x, max.x, o.x) + far(min.y, max.y, o.y) + far(min.z, max.z, o.z);
        let pad = f32x8::splat(DISTANCE_SLACK) * reach + coordinates;
        let (mut enter, mut leave) = (f32x8::ZERO, t_max);
        for (lo, hi, o, inverse) in [
            (min.x, max.x, o.x, inverse.x),
            (min.y, max.y, o.y, inverse.y),
            (min.z, max.z, o.z, inverse.z),
        ] {
            let low = (lo - pad - o) * inverse;
            let high = (hi + pad - o) * inverse;
            let backwards = inverse.cmp_lt(f32x8::ZERO);
            enter = enter.max(backwards.blend(high, low));
            leave = leave.min(backwards.blend(low, high));
        }
        enter.cmp_le(leave)
    }
    // ANCHOR_END: enter

    /// What every search of these eight rays shares: `1/d` per lane, and
    /// the widening for the coordinates' size.
    #[inline]
    fn prepare(&self, o: Vec3x8, d: Vec3x8) -> (Vec3x8, f32x8) {
        let inverse = Vec3x8 {
            x: f32x8::ONE / d.x,
            y: f32x8::ONE / d.y,
            z: f32x8::ONE / d.z,
        };
        let largest = o.x.abs().max(o.y.abs()).max(o.z.abs());
        let coordinates =
            f32x8::splat(COORDINATE_SLACK) * (largest + f32x8::splat(self.tree.scale()));
        (inverse, coordinates)
    }

    /// Sphere `k` of the leaves' order: its centre and squared radius in
    /// every lane, and its number as the lanes count objects (its index in
    /// the scene's list plus one).
    #[inline]
    fn sphere(&self, k: usize) -> (Vec3x8, f32x8, f32x8) {
        let [x, y, z, radius] = self.tree.leaf_spheres()[k];
        let number = self.tree.order()[k] as f32 + 1.0;
        (
            Vec3x8::splat(Vec3::new(x, y, z)),
            f32x8::splat(radius * radius),
            f32x8::splat(number),
        )
    }
}

impl SceneQueryX8 for BvhX8<'_> {
    // ANCHOR: nearest
    /// The nearest hit of eight rays, as `SceneX8::nearest_in_list` finds
    /// it, lane for lane and to the bit.
    ///
    /// The ground first, as the list does. Then the tree: a node is opened
    /// if some lane's ray enters its box no farther than that lane's
    /// nearest hit so far. Of two children, the one nearer along the
    /// rays' summed direction is searched first. A sphere replaces a
    /// lane's best hit if it is nearer, or as near and earlier in the
    /// list. `any` gathers every hit met on the way: a lane with a nearest
    /// hit meets something, and a lane without one opened every box its
    /// ray enters, so met every sphere the list would.
    #[inline]
    fn nearest(&self, o: Vec3x8, d: Vec3x8) -> Hits {
        let (t_plane, on_plane) = plane_hits(self.plane_point, self.plane_normal, o, d);
        let mut t = on_plane.blend(t_plane, f32x8::splat(f32::INFINITY));
        let mut object = on_plane.blend(f32x8::splat(GROUND), f32x8::splat(NOTHING));
        let mut any = on_plane;
        let nodes = self.tree.nodes();
        if !nodes.is_empty() {
            let (inverse, coordinates) = self.prepare(o, d);
            let towards = Vec3::new(d.x.reduce_add(), d.y.reduce_add(), d.z.reduce_add());
            // One pending node per level at most, plus the one just pushed.
            let mut stack = [0u32; MAX_DEPTH + 2];
            let mut len = 1;
            while len > 0 {
                len -= 1;
                let index = stack[len];
                let node = &nodes[index as usize];
                if self.enter(node, o, inverse, coordinates, t).none() {
                    continue;
                }
                if node.is_leaf() {
                    let first = node.first as usize;
                    for k in first..first + node.count as usize {
                        let (centre, radius_squared, number) = self.sphere(k);
                        let (t_sphere, hit) = sphere_hits(centre, radius_squared, o, d);
                        any |= hit;
                        let earlier = t_sphere.cmp_eq(t) & number.cmp_lt(object);
                        let better = hit & (t_sphere.cmp_lt(t) | earlier);
                        t = better.blend(t_sphere, t);
                        object = better.blend(number, object);
                    }
                    continue;
                }
                // Push the farther child first, so that the nearer is
                // popped next.
                let (a, b) = (index + 1, node.first);
                let centre = |i: u32| nodes[i as usize].bounds().centre();
                let a_nearer = (centre(b) - centre(a)).dot(towards) >= 0.0;
                let (near, far) = if a_nearer { (a, b) } else { (b, a) };
                stack[len] = far;
                stack[len + 1] = near;
                len += 2;
            }
        }
        Hits::found(t, object, any)
    }
    // ANCHOR_END: nearest

    /// Whether eight shadow rays are blocked, in the lanes of `asked`, as
    /// `SceneX8::any_in_list` says: a node is opened while some lane asked
    /// about is not yet known to be blocked and its ray enters the box.
    #[inline]
    fn any(&self, o: Vec3x8, d: Vec3x8, asked: f32x8) -> f32x8 {
        let mut blocked = plane_hits(self.plane_point, self.plane_normal, o, d).1;
        let nodes = self.tree.nodes();
        if nodes.is_empty() {
            return blocked;
        }
        let (inverse, coordinates) = self.prepare(o, d);
        let far = f32x8::splat(f32::INFINITY);
        let mut stack = [0u32; MAX_DEPTH + 2];
        let mut len = 1;
        while len > 0 {
            let open = asked & !blocked;
            if open.none() {
                break;
            }
            len -= 1;
            let index = stack[len];
            let node = &nodes[index as usize];
            if (open & self.enter(node, o, inverse, coordinates, far)).none() {
                continue;
            }
            if node.is_leaf() {
                let first = node.first as usize;
                for k in first..first + node.count as usize {
                    let (centre, radius_squared, _) = self.sphere(k);
                    blocked |= sphere_hits(centre, radius_squared, o, d).1;
                }
                continue;
            }
            stack[len] = node.first;
            stack[len + 1] = index + 1;
            len += 2;
        }
        blocked
    }
}

/// One ray at a time, the scalar tree answers: for the rare ray a tracer
/// follows alone (chapter 7's over-budget samples, chapter 8's photons).
impl SceneQuery for BvhX8<'_> {
    fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        self.tree.nearest_hit(ray)
    }

    fn any_hit(&self, ray: &Ray) -> bool {
        self.tree.any_hit(ray)
    }
}
