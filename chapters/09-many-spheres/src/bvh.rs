//! The tree of boxes: built top-down by the surface area heuristic over
//! binned centres, kept as one flat array of nodes, and searched nearest
//! child first.

use raylab::scene::{Hit, Object, Scene, SceneQuery};
use raylab::sphere::Sphere;
use raylab::{Ray, Vec3};

use crate::aabb::{Aabb, SlabRay};

// ANCHOR: node
/// One node of the tree, 32 bytes. Its box holds every sphere below it.
///
/// The nodes are stored depth first in one `Vec`: an inner node's first
/// child is the very next node, so only the second child's index is kept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    pub min: [f32; 3],
    pub max: [f32; 3],
    /// A leaf: the position of its first sphere in [`Bvh::order`]. An inner
    /// node: the index of its second child.
    pub first: u32,
    /// A leaf: how many spheres it holds (1 or more). An inner node: 0.
    pub count: u32,
}
// ANCHOR_END: node

impl Node {
    pub fn bounds(&self) -> Aabb {
        Aabb {
            min: Vec3::from(self.min),
            max: Vec3::from(self.max),
        }
    }

    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

/// The deepest a leaf may lie (the root is at depth 0). The build keeps to
/// it (see [`SAH_LEVELS`]) so that a search needs only a small fixed stack.
pub const MAX_DEPTH: usize = 64;

/// The surface area heuristic chooses splits down to this depth; below it
/// every split halves the spheres, which can take at most 32 more levels
/// for any count that fits in a `u32`: `32 + 32 = MAX_DEPTH`. Without it a
/// long run of lopsided splits (one sphere off, the rest on) could make
/// the tree as deep as it has spheres.
pub const SAH_LEVELS: usize = MAX_DEPTH - 32;

/// The number of bins the centres are sorted into along the split axis.
///
/// pbrt uses 12: the heuristic's cost is smooth in the split position, so
/// a dozen candidate planes already come within a few per cent of trying
/// every sphere's centre (Wald 2007 measured 16 bins as good as a full
/// sweep). 16 costs nothing more here: the binning pass is linear in the
/// spheres, and the sweep over the bins is 15 steps.
pub const BINS: usize = 16;

/// The most spheres a leaf may hold.
pub const MAX_LEAF: usize = 8;

/// The heuristic's cost of stepping into a node, counted in sphere tests.
/// The search tests both children's boxes there, and a slab test with its
/// widening (a dozen subtractions and multiplications, and the widening's
/// sum) does about twice the arithmetic of a ray–sphere test (two dot
/// products, mostly): 2 × 2 = 4. Between 2 and 6 the search over a field of
/// 10,000 spheres is about as fast, but at 4 the leaves hold five or six
/// spheres, the tree keeps a third less memory than at 2, and a scene as
/// small as the lab's five spheres becomes a single leaf, which the search
/// tests as the list does, with no box at all (the bench's "many spheres
/// lab" group compares the two).
pub const TRAVERSAL_COST: f32 = 4.0;

/// The share of the distance from the ray's start to a box by which the
/// box is widened during the search. The ray–sphere test of the core
/// cancels `b² − q`, two numbers of the size of `|o − c|²`, so it may
/// report a hit as far as about `√(15u)·|o − c| ≈ 9.5e-4·|o − c|` outside
/// the sphere (`u = 2⁻²⁴`). The list of spheres keeps such hits; so must
/// the tree, to give the same bytes: `2⁻⁹ ≈ 2e-3` covers it twice over.
pub const DISTANCE_SLACK: f32 = 1.0 / 512.0;

/// The share of the coordinates' size by which every box is widened: for
/// the rounding of `o − c` and of the box's own faces, a few `u` of the
/// largest coordinate involved. `2⁻²⁰ = 16u`.
pub const COORDINATE_SLACK: f32 = 1.0 / 1_048_576.0;

/// A bounding volume hierarchy over a scene's spheres. The ground plane,
/// which no box can hold, stays outside it and is tested first, as the
/// list of objects does.
#[derive(Clone, Debug)]
pub struct Bvh<'s> {
    scene: &'s Scene,
    nodes: Vec<Node>,
    /// The spheres (centre and radius) in the order the leaves hold them.
    spheres: Vec<[f32; 4]>,
    /// For each of those, its index in the scene's list, which breaks ties.
    order: Vec<u32>,
    /// The largest coordinate of any sphere's centre, for [`COORDINATE_SLACK`].
    scale: f32,
    depth: usize,
}

/// The best hit of a search so far: how far, and which object (none
/// yet: `t` is infinite).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Best {
    t: f32,
    object: Option<Object>,
}

impl Best {
    const NONE: Best = Best {
        t: f32::INFINITY,
        object: None,
    };
}

/// What the search of one ray did, for the figures.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SearchStats {
    /// Boxes tested with the slab test.
    pub boxes: u32,
    /// Spheres tested with the ray–sphere test.
    pub spheres: u32,
}

/// Where a search counts its work: nowhere (`()`, which the compiler
/// removes, for the search that renders), or in [`SearchStats`].
trait Tally {
    fn boxes(&mut self, n: u32);
    fn spheres(&mut self, n: u32);
}

impl Tally for () {
    #[inline(always)]
    fn boxes(&mut self, _: u32) {}
    #[inline(always)]
    fn spheres(&mut self, _: u32) {}
}

impl Tally for SearchStats {
    fn boxes(&mut self, n: u32) {
        self.boxes += n;
    }
    fn spheres(&mut self, n: u32) {
        self.spheres += n;
    }
}

/// One sphere during the build: its box, its box's centre, its index.
#[derive(Clone, Copy, Debug)]
struct Item {
    bounds: Aabb,
    centre: Vec3,
    index: u32,
}

impl<'s> Bvh<'s> {
    // ANCHOR: build
    /// Build the tree over `scene`'s spheres, top down.
    ///
    /// # Panics
    /// If the scene has more than `u32::MAX` spheres.
    pub fn build(scene: &'s Scene) -> Bvh<'s> {
        let mut items: Vec<Item> = scene
            .spheres()
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let bounds = Aabb::around_sphere(&s.shape);
                let index = u32::try_from(i).expect("at most u32::MAX spheres");
                Item {
                    bounds,
                    centre: bounds.centre(),
                    index,
                }
            })
            .collect();
        let mut bvh = Bvh {
            scene,
            nodes: Vec::with_capacity(items.len()),
            spheres: Vec::with_capacity(items.len()),
            order: Vec::with_capacity(items.len()),
            scale: items
                .iter()
                .map(|i| i.centre.abs().max_element())
                .fold(0.0, f32::max),
            depth: 0,
        };
        if !items.is_empty() {
            bvh.build_node(&mut items, 0);
        }
        for &index in &bvh.order {
            let s = &scene.spheres()[index as usize].shape;
            bvh.spheres
                .push([s.centre.x, s.centre.y, s.centre.z, s.radius]);
        }
        bvh
    }

    /// Add the node for `items` (and everything below it) at `depth`;
    /// return its index.
    fn build_node(&mut self, items: &mut [Item], depth: usize) -> usize {
        self.depth = self.depth.max(depth);
        let bounds = items.iter().fold(Aabb::EMPTY, |b, i| b.union(i.bounds));
        let me = self.nodes.len();
        self.nodes.push(Node {
            min: bounds.min.into(),
            max: bounds.max.into(),
            first: 0,
            count: 0,
        });
        let Some(half) = self.split(items, bounds, depth) else {
            // A leaf: its spheres, in their new order.
            self.nodes[me].first = self.order.len() as u32;
            self.nodes[me].count = items.len() as u32;
            self.order.extend(items.iter().map(|i| i.index));
            return me;
        };
        let (left, right) = items.split_at_mut(half);
        self.build_node(left, depth + 1);
        let second = self.build_node(right, depth + 1);
        self.nodes[me].first = second as u32;
        me
    }

    /// Where to cut `items` in two (after reordering them), or `None` to
    /// make them a leaf.
    fn split(&self, items: &mut [Item], bounds: Aabb, depth: usize) -> Option<usize> {
        let n = items.len();
        if n == 1 {
            return None;
        }
        let centres = items.iter().fold(Aabb::EMPTY, |b, i| b.grow(i.centre));
        let extent = centres.max - centres.min;
        let axis = extent.max_position();
        if depth < SAH_LEVELS && extent[axis] > 0.0 {
            match sah_split(items, bounds, centres, axis) {
                Decision::Leaf if n <= MAX_LEAF => return None,
                Decision::Split(half) => return Some(half),
                // Too many for a leaf, or the bins found no cut.
                Decision::Leaf | Decision::NoCut => {}
            }
        }
        if n <= MAX_LEAF {
            return None;
        }
        // Halve by count at the median centre: always progress, even when
        // every centre is the same point.
        let half = n / 2;
        items.select_nth_unstable_by(half, |a, b| a.centre[axis].total_cmp(&b.centre[axis]));
        Some(half)
    }
    // ANCHOR_END: build

    /// The nodes, root first, depth first.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// The depth of the deepest leaf (the root alone is depth 0).
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// The scene the tree was built over.
    pub fn scene(&self) -> &'s Scene {
        self.scene
    }

    /// The spheres' indices in the scene's list, in the leaves' order.
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    /// The spheres (centre and radius), in the leaves' order.
    pub fn leaf_spheres(&self) -> &[[f32; 4]] {
        &self.spheres
    }

    /// The largest coordinate of any sphere's centre, which sets the
    /// boxes' widening for rounding ([`COORDINATE_SLACK`]).
    pub fn scale(&self) -> f32 {
        self.scale
    }

    /// The bytes the tree keeps beside the scene: its nodes, the spheres'
    /// copies and their indices.
    pub fn bytes(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<Node>()
            + self.spheres.len() * std::mem::size_of::<[f32; 4]>()
            + self.order.len() * std::mem::size_of::<u32>()
    }

    // ANCHOR: pad
    /// How far the boxes are widened for this ray, at `node`: a small share
    /// of the distance from the ray's start to `node`'s farthest corner
    /// (bounding the distance to every centre inside), for the sphere
    /// test's cancellation, plus a rounding's worth of the coordinates'
    /// size. The search widens `node`'s children by it too: their corners
    /// are no farther, so it covers them.
    #[inline]
    fn pad(&self, origin: Vec3, node: &Node, coordinates: f32) -> f32 {
        // Along each axis, the farther of the box's two faces.
        let far = (origin - Vec3::from(node.min)).max(Vec3::from(node.max) - origin);
        DISTANCE_SLACK * far.element_sum() + coordinates
    }
    // ANCHOR_END: pad

    /// The entry distance of the ray into `node`'s box widened by `pad`,
    /// up to `t_max`.
    #[inline]
    fn enter(&self, ray: &SlabRay, node: usize, pad: f32, t_max: f32) -> Option<f32> {
        self.nodes[node].bounds().slab_test(ray, pad, 0.0, t_max)
    }

    #[inline]
    fn sphere(&self, k: usize) -> Sphere {
        let [x, y, z, radius] = self.spheres[k];
        Sphere {
            centre: Vec3::new(x, y, z),
            radius,
        }
    }

    // ANCHOR: nearest
    /// The nearest hit, as [`Scene::nearest_hit`] finds it, to the bit.
    ///
    /// The ground first, as the list does. Then the tree: a node is opened
    /// only if the ray enters its box no farther than the nearest hit so
    /// far (a box entered exactly there may hold a tie), the nearer child
    /// first, so that the farther one is often skipped. A sphere replaces
    /// the best hit if it is nearer, or as near and earlier in the list:
    /// the list's own rule, "ties go to the earlier object".
    #[inline]
    pub fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        self.nearest_hit_tallied(ray, &mut ())
    }

    /// [`Bvh::nearest_hit`], its work counted in `tally`.
    #[inline]
    fn nearest_hit_tallied(&self, ray: &Ray, tally: &mut impl Tally) -> Option<Hit> {
        let mut best = Best::NONE;
        if let Some(t) = self.scene.ground.plane.intersect(ray) {
            best = Best {
                t,
                object: Some(Object::Ground),
            };
        }
        self.search_nearest(ray, &mut best, tally);
        best.object.map(|o| self.scene.hit_record(ray, best.t, o))
    }

    /// Replace `best` with any sphere hit nearer (or as near and earlier
    /// in the list).
    #[inline]
    fn search_nearest(&self, ray: &Ray, best: &mut Best, tally: &mut impl Tally) {
        let Some(root) = self.nodes.first() else {
            return;
        };
        if root.is_leaf() {
            // A few spheres, one leaf: the list, with no box to test.
            return self.search_leaf(root, ray, best, tally);
        }
        let slabs = SlabRay::new(ray.origin, ray.direction);
        let coordinates = COORDINATE_SLACK * (ray.origin.abs().max_element() + self.scale);
        tally.boxes(1);
        let root_pad = self.pad(ray.origin, root, coordinates);
        let Some(t) = self.enter(&slabs, 0, root_pad, best.t) else {
            return;
        };
        // One pending node per level at most, plus the one just pushed.
        let mut stack = [(0u32, 0.0f32); MAX_DEPTH + 2];
        stack[0] = (0, t);
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let (index, entered) = stack[len];
            if entered > best.t {
                continue; // something nearer was found since it was pushed
            }
            let node = &self.nodes[index as usize];
            if node.is_leaf() {
                self.search_leaf(node, ray, best, tally);
                continue;
            }
            let (a, b) = (index as usize + 1, node.first as usize);
            tally.boxes(2);
            // The parent's widening covers both children's (its box holds
            // theirs, so its farthest corner is at least as far): one
            // widening for two boxes, and no hit is lost.
            let pad = self.pad(ray.origin, node, coordinates);
            let ta = self.enter(&slabs, a, pad, best.t);
            let tb = self.enter(&slabs, b, pad, best.t);
            // Push the farther child first, so that the nearer is popped next.
            let mut push = |child: usize, t: f32| {
                stack[len] = (child as u32, t);
                len += 1;
            };
            match (ta, tb) {
                (Some(ta), Some(tb)) if ta <= tb => (push(b, tb), push(a, ta)),
                (Some(ta), Some(tb)) => (push(a, ta), push(b, tb)),
                (Some(ta), None) => (push(a, ta), ()),
                (None, Some(tb)) => (push(b, tb), ()),
                (None, None) => ((), ()),
            };
        }
    }

    /// Test a leaf's spheres, keeping the list's rule: a sphere replaces
    /// the best hit if it is nearer, or as near and earlier in the list.
    #[inline]
    fn search_leaf(&self, leaf: &Node, ray: &Ray, best: &mut Best, tally: &mut impl Tally) {
        let first = leaf.first as usize;
        for k in first..first + leaf.count as usize {
            tally.spheres(1);
            let Some(t) = self.sphere(k).intersect(ray) else {
                continue;
            };
            let i = self.order[k] as usize;
            let earlier = matches!(best.object, Some(Object::Sphere(j)) if i < j);
            if t < best.t || (t == best.t && earlier) {
                *best = Best {
                    t,
                    object: Some(Object::Sphere(i)),
                };
            }
        }
    }
    // ANCHOR_END: nearest

    /// [`Bvh::nearest_hit`], and what its search did: the boxes and the
    /// spheres it tested (for the figures and the exercises). The same
    /// search, counted beside it rather than in its signature, as pbrt
    /// counts its nodes with a statistics macro outside `Intersect`.
    pub fn nearest_hit_counted(&self, ray: &Ray) -> (Option<Hit>, SearchStats) {
        let mut stats = SearchStats::default();
        let hit = self.nearest_hit_tallied(ray, &mut stats);
        (hit, stats)
    }

    // ANCHOR: any
    /// Whether the ray meets anything, as [`Scene::any_hit`] says: the
    /// shadow ray's question, answered at the first hit found, in any order.
    pub fn any_hit(&self, ray: &Ray) -> bool {
        if self.scene.ground.plane.intersect(ray).is_some() {
            return true;
        }
        let hits_leaf = |leaf: &Node| {
            let first = leaf.first as usize;
            (first..first + leaf.count as usize).any(|k| self.sphere(k).intersect(ray).is_some())
        };
        let Some(root) = self.nodes.first() else {
            return false;
        };
        if root.is_leaf() {
            return hits_leaf(root);
        }
        let slabs = SlabRay::new(ray.origin, ray.direction);
        let coordinates = COORDINATE_SLACK * (ray.origin.abs().max_element() + self.scale);
        // Whether the ray passes through `node`'s box, widened by `pad`.
        let passes = |node: usize, pad: f32| self.enter(&slabs, node, pad, f32::INFINITY).is_some();
        if !passes(0, self.pad(ray.origin, root, coordinates)) {
            return false;
        }
        let mut stack = [0u32; MAX_DEPTH + 2];
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let index = stack[len] as usize;
            let node = &self.nodes[index];
            if node.is_leaf() {
                if hits_leaf(node) {
                    return true;
                }
                continue;
            }
            // One widening for both children, as in the nearest-hit search.
            let pad = self.pad(ray.origin, node, coordinates);
            for child in [index + 1, node.first as usize] {
                if passes(child, pad) {
                    stack[len] = child as u32;
                    len += 1;
                }
            }
        }
        false
    }
    // ANCHOR_END: any
}

impl SceneQuery for Bvh<'_> {
    fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        Bvh::nearest_hit(self, ray)
    }

    fn any_hit(&self, ray: &Ray) -> bool {
        Bvh::any_hit(self, ray)
    }
}

/// What the binned surface area heuristic decided for a node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Decision {
    /// Keep the spheres together: a leaf is cheaper than any cut.
    Leaf,
    /// Cut after this many spheres (the items have been reordered).
    Split(usize),
    /// Every cut leaves one side empty (or the costs are not numbers).
    NoCut,
}

// ANCHOR: sah
/// The surface area heuristic, over [`BINS`] bins of the centres along
/// `axis`.
///
/// A ray that passes through a box passes through a box inside it with a
/// probability of about the ratio of their surface areas. So a cut of `n`
/// spheres into `A` (`n_A` spheres) and `B` costs, in sphere tests,
///
/// ```text
/// cost = TRAVERSAL_COST + (area(A)·n_A + area(B)·n_B) / area(node)
/// ```
///
/// against `n` for a leaf. Trying a cut at every bin boundary takes one
/// pass over the spheres (binning) and two over the bins (the boxes and
/// counts to the left and to the right of each boundary).
fn sah_split(items: &mut [Item], bounds: Aabb, centres: Aabb, axis: usize) -> Decision {
    let (low, extent) = (centres.min[axis], centres.max[axis] - centres.min[axis]);
    let bin_of = |item: &Item| {
        let f = (item.centre[axis] - low) / extent * BINS as f32;
        // `as` saturates (and sends NaN to 0): never outside the bins.
        (f as usize).min(BINS - 1)
    };
    let mut bins = [(Aabb::EMPTY, 0usize); BINS];
    for item in items.iter() {
        let bin = &mut bins[bin_of(item)];
        *bin = (bin.0.union(item.bounds), bin.1 + 1);
    }
    // right[k]: the area and count of bins k.. (the right side of cut k).
    let mut right = [(0.0f32, 0usize); BINS];
    let mut acc = (Aabb::EMPTY, 0);
    for k in (1..BINS).rev() {
        acc = (acc.0.union(bins[k].0), acc.1 + bins[k].1);
        right[k] = (acc.0.surface_area(), acc.1);
    }
    let mut best = (f32::INFINITY, 0);
    let mut left = (Aabb::EMPTY, 0);
    for k in 1..BINS {
        left = (left.0.union(bins[k - 1].0), left.1 + bins[k - 1].1);
        let (n_a, (area_b, n_b)) = (left.1, right[k]);
        if n_a == 0 || n_b == 0 {
            continue;
        }
        let cost = left.0.surface_area() * n_a as f32 + area_b * n_b as f32;
        if cost < best.0 {
            best = (cost, k);
        }
    }
    if best.1 == 0 {
        return Decision::NoCut;
    }
    let area = bounds.surface_area();
    let cost = TRAVERSAL_COST + best.0 / area;
    // A flat or point node (area 0) gives NaN or ∞: cut it, by count.
    if !cost.is_finite() {
        return Decision::NoCut;
    }
    if cost >= items.len() as f32 {
        return Decision::Leaf;
    }
    let half = partition(items, |item| bin_of(item) < best.1);
    if half == 0 || half == items.len() {
        Decision::NoCut
    } else {
        Decision::Split(half)
    }
}
// ANCHOR_END: sah

/// Move the items for which `left` holds to the front; return how many.
fn partition(items: &mut [Item], left: impl Fn(&Item) -> bool) -> usize {
    let mut first = 0;
    for k in 0..items.len() {
        if left(&items[k]) {
            items.swap(first, k);
            first += 1;
        }
    }
    first
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_node_is_32_bytes() {
        assert_eq!(std::mem::size_of::<Node>(), 32);
    }

    #[test]
    fn the_tree_over_ten_thousand_spheres_keeps_at_most_64_bytes_per_sphere() {
        let (scene, _) = crate::field::field_scene(10_000);
        let tree = Bvh::build(&scene);
        let per_sphere = tree.bytes() as f64 / 10_000.0;
        eprintln!(
            "{} nodes, {per_sphere:.1} bytes per sphere",
            tree.nodes().len()
        );
        assert!(per_sphere <= 64.0, "{per_sphere:.1} bytes per sphere");
    }

    #[test]
    fn the_bound_on_depth_holds_for_any_u32_count() {
        // Past SAH_LEVELS every split halves: ⌈log2(u32::MAX)⌉ = 32 levels more.
        assert_eq!(SAH_LEVELS + 32, MAX_DEPTH);
    }

    #[test]
    fn the_heuristic_cuts_two_far_clusters_apart() {
        // Four unit boxes at x = 0 and four at x = 100: cutting between
        // them costs 4 + (6·4 + 6·4)/406 ≈ 4.1, below the leaf's 8.
        let mut items: Vec<Item> = (0..8)
            .map(|i| {
                let x = if i % 2 == 0 { 0.0 } else { 100.0 };
                let min = Vec3::new(x, 0.0, 0.0);
                let bounds = Aabb {
                    min,
                    max: min + Vec3::ONE,
                };
                Item {
                    bounds,
                    centre: bounds.centre(),
                    index: i,
                }
            })
            .collect();
        let bounds = items.iter().fold(Aabb::EMPTY, |b, i| b.union(i.bounds));
        let centres = items.iter().fold(Aabb::EMPTY, |b, i| b.grow(i.centre));
        assert_eq!(
            sah_split(&mut items, bounds, centres, 0),
            Decision::Split(4)
        );
        assert!(items[..4].iter().all(|i| i.index % 2 == 0));
    }

    #[test]
    fn the_lab_scenes_five_spheres_are_one_leaf() {
        let scene = Scene::lab();
        let tree = Bvh::build(&scene);
        assert_eq!(tree.nodes().len(), 1);
        assert_eq!(tree.nodes()[0].count, 5);
    }

    #[test]
    fn the_counted_search_finds_the_same_hit_and_counts_what_it_tested() {
        // The lab's five spheres are one leaf: no box, all five spheres.
        let scene = Scene::lab();
        let tree = Bvh::build(&scene);
        let ray = raylab::Camera::lab().ray(400, 300, (0.5, 0.5), 800, 600);
        let (hit, stats) = tree.nearest_hit_counted(&ray);
        assert_eq!(hit, tree.nearest_hit(&ray));
        assert_eq!(
            hit.map(|h| h.object),
            scene.nearest_hit(&ray).map(|h| h.object)
        );
        assert_eq!(
            stats,
            SearchStats {
                boxes: 0,
                spheres: 5
            }
        );
        // Two groups of four spheres, 200 apart, are cut into two leaves
        // (a cut costs 4 + (96·4 + 96·4)/1,696 ≈ 4.5, less than the 8 of
        // one leaf): a ray that misses the root's box tests that one box
        // and no sphere; a ray down onto the first group tests the root and
        // both children (3 boxes) and the four spheres of its leaf.
        let lab = Scene::lab();
        let mut scene = Scene::new(lab.ground, lab.sky, lab.sun).unwrap();
        let matte = raylab::Material::diffuse(Vec3::splat(0.5)).unwrap();
        for (i, x) in [-100.0, -97.0, -94.0, -91.0, 100.0, 103.0, 106.0, 109.0]
            .into_iter()
            .enumerate()
        {
            let sphere = Sphere {
                centre: Vec3::new(x, 1.0, 0.0),
                radius: 1.0,
            };
            scene.add_sphere(&format!("s{i}"), sphere, matte).unwrap();
        }
        let tree = Bvh::build(&scene);
        assert_eq!(tree.nodes().len(), 3);
        let up = Ray {
            origin: Vec3::new(0.0, 5.0, 0.0),
            direction: Vec3::Y,
        };
        assert_eq!(
            tree.nearest_hit_counted(&up).1,
            SearchStats {
                boxes: 1,
                spheres: 0
            }
        );
        let down = Ray {
            origin: Vec3::new(-100.0, 5.0, 0.0),
            direction: Vec3::NEG_Y,
        };
        let (hit, stats) = tree.nearest_hit_counted(&down);
        assert_eq!(hit.map(|h| h.object), Some(Object::Sphere(0)));
        assert_eq!(
            stats,
            SearchStats {
                boxes: 3,
                spheres: 4
            }
        );
    }

    #[test]
    fn the_heuristic_keeps_two_overlapping_spheres_in_one_leaf() {
        // Two unit boxes overlapping almost entirely: a cut costs
        // 4 + (6·1 + 6·1)/area(node) ≈ 6 > 2, the leaf's cost.
        let mut items: Vec<Item> = [0.0, 0.01]
            .iter()
            .enumerate()
            .map(|(i, &x)| {
                let min = Vec3::new(x, 0.0, 0.0);
                let bounds = Aabb {
                    min,
                    max: min + Vec3::ONE,
                };
                Item {
                    bounds,
                    centre: bounds.centre(),
                    index: i as u32,
                }
            })
            .collect();
        let bounds = items.iter().fold(Aabb::EMPTY, |b, i| b.union(i.bounds));
        let centres = items.iter().fold(Aabb::EMPTY, |b, i| b.grow(i.centre));
        assert_eq!(sah_split(&mut items, bounds, centres, 0), Decision::Leaf);
    }
}
