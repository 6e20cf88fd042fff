//! Chapter 9's tree searched eight rays at a time ([`BvhX8`]) finds what
//! the lanes' list ([`SceneX8`]) finds, lane for lane and to the bit: the
//! same nearest hit (distance, object, hit and "anything met") and the
//! same blocked shadow rays, on the very cases chapter 9 holds its scalar
//! tree to (`chapters/09-many-spheres/tests/tree_matches_list.rs`).

#[path = "../../../chapters/09-many-spheres/tests/cases/mod.rs"]
mod cases;

use cases::{far_and_every_size, key, one_centre, random_case, tiny_far_away};
use ch09_many_spheres::Bvh;
use proptest::prelude::*;
use raylab::Ray;
use raylab::scene::Scene;
use raylab_lanes::{BvhX8, LANES, SceneQueryX8, SceneX8, Vec3x8, lanes_of, mask_from_bits};

/// Eight lanes of `rays` at a time (the last group filled with its last
/// ray): the tree's search of eight against the lanes' list, in every
/// lane, and for shadow rays with every lane asked and with some. Each
/// ray alone, the tree's scalar answer is the list's too.
fn assert_same_x8(scene: &Scene, rays: &[Ray]) -> Result<(), TestCaseError> {
    let tree = Bvh::build(scene);
    let (list, lanes) = (SceneX8::new(scene), BvhX8::new(&tree));
    for group in rays.chunks(LANES) {
        let ray = |l: usize| group[l.min(group.len() - 1)];
        let o = Vec3x8::from_lanes(std::array::from_fn(|l| ray(l).origin));
        let d = Vec3x8::from_lanes(std::array::from_fn(|l| ray(l).direction));
        let (theirs, ours) = (list.nearest_in_list(o, d), lanes.nearest(o, d));
        for l in 0..LANES {
            let bits = |x: wide::f32x8| x.as_array_ref()[l].to_bits();
            prop_assert_eq!(
                bits(theirs.t),
                bits(ours.t),
                "t, lane {} of {:?}",
                l,
                ray(l)
            );
            prop_assert_eq!(bits(theirs.object), bits(ours.object), "object, lane {}", l);
            prop_assert_eq!(bits(theirs.hit), bits(ours.hit), "hit, lane {}", l);
            prop_assert_eq!(bits(theirs.any), bits(ours.any), "any, lane {}", l);
            // The rare ray a tracer follows alone: the scalar tree's answer.
            prop_assert_eq!(
                key(scene.nearest_hit(&ray(l))),
                key(raylab::SceneQuery::nearest_hit(&lanes, &ray(l)))
            );
        }
        for asked in [0xff, 0b1010_0101, 0b0000_0001] {
            let mask = mask_from_bits(asked);
            let (theirs, ours) = (list.any_in_list(o, d, mask), lanes.any(o, d, mask));
            for l in lanes_of(asked) {
                let bit = |x: wide::f32x8| x.as_array_ref()[l].to_bits();
                prop_assert_eq!(
                    bit(theirs),
                    bit(ours),
                    "blocked, lane {} of {:?}",
                    l,
                    ray(l)
                );
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn eight_rays_through_the_tree_find_the_lists_hits_on_random_scenes((scene, rays) in random_case()) {
        if !rays.is_empty() {
            assert_same_x8(&scene, &rays)?;
        }
    }
}

#[test]
fn eight_rays_at_ten_thousand_spheres_on_one_centre_find_the_lists_hits() {
    let (scene, rays) = one_centre();
    assert_same_x8(&scene, &rays).unwrap();
}

#[test]
fn eight_rays_at_spheres_far_away_and_of_every_size_find_the_lists_hits() {
    let (scene, rays) = far_and_every_size();
    assert_same_x8(&scene, &rays).unwrap();
}

#[test]
fn eight_rays_at_a_tiny_sphere_far_away_find_the_lists_hits() {
    let (scene, rays) = tiny_far_away();
    assert_same_x8(&scene, &rays).unwrap();
}
