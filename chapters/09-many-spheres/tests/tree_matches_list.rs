//! The tree finds what the list finds, to the bit: the same nearest hit
//! (object and distance) and the same answer to "anything at all?", on
//! random scenes and rays, wild ones included. (Its search of eight rays
//! at a time is held to the same cases beside the lanes,
//! `crates/lanes/tests/tree_x8_matches_list.rs`.)

mod cases;

use cases::{far_and_every_size, key, one_centre, random_case, tiny_far_away};
use ch09_many_spheres::Bvh;
use proptest::prelude::*;
use raylab::Ray;
use raylab::scene::{Object, Scene, SceneQuery};

fn assert_same(scene: &Scene, tree: &Bvh, ray: &Ray) -> Result<(), TestCaseError> {
    prop_assert_eq!(
        key(scene.nearest_hit(ray)),
        key(tree.nearest_hit(ray)),
        "{:?}",
        ray
    );
    prop_assert_eq!(
        scene.any_hit(ray),
        SceneQuery::any_hit(tree, ray),
        "{:?}",
        ray
    );
    Ok(())
}

fn assert_all_same(scene: &Scene, rays: &[Ray]) {
    let tree = Bvh::build(scene);
    for ray in rays {
        assert_same(scene, &tree, ray).unwrap();
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn the_tree_finds_the_lists_hit_on_random_scenes_and_rays((scene, rays) in random_case()) {
        let tree = Bvh::build(&scene);
        for ray in &rays {
            assert_same(&scene, &tree, ray)?;
        }
    }
}

#[test]
fn ten_thousand_spheres_at_one_centre_build_a_shallow_tree_and_answer_as_the_list() {
    let (scene, rays) = one_centre();
    let tree = Bvh::build(&scene);
    assert!(
        tree.depth() <= ch09_many_spheres::bvh::MAX_DEPTH,
        "{}",
        tree.depth()
    );
    assert_all_same(&scene, &rays);
}

#[test]
fn spheres_far_outside_the_view_and_of_every_size_answer_as_the_list() {
    let (scene, rays) = far_and_every_size();
    assert_all_same(&scene, &rays);
}

#[test]
fn a_tiny_sphere_far_away_is_hit_by_the_tree_wherever_the_list_says_so() {
    let (scene, rays) = tiny_far_away();
    let hits = rays
        .iter()
        .filter(|ray| {
            scene
                .nearest_hit(ray)
                .is_some_and(|h| h.object != Object::Ground)
        })
        .count();
    assert!(hits > 0);
    assert_all_same(&scene, &rays);
}
