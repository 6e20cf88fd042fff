//! # raylab-lanes: eight at a time
//!
//! The faster floor beside the tracer a learner reads. The core crate
//! (`raylab`) traces one ray at a time; the tracers of chapters 7 and 8
//! trace eight, one per lane of an AVX register (`wide::f32x8`), with the
//! same arithmetic in the same order, so that their images are the core's
//! to the bit. This crate holds what both need, once: eight vectors side
//! by side, the camera, the scene, the sky and the optics in lanes, and
//! the samples' generators eight at a time, and chapter 9's tree searched
//! by eight rays at once ([`BvhX8`]). It depends on the core and on
//! chapter 9's tree, whose search it mirrors; nothing depends on it but
//! the fast chapters (7 and 8) and what runs them.
//!
//! ## The map of mirrors
//!
//! Each lane function reproduces one scalar definition of the core to the
//! bit; the test beside it binds the two.
//!
//! | here | mirrors (in `raylab`) | bound by |
//! |---|---|---|
//! | [`Vec3x8::dot`], [`Vec3x8::normalize`], the operators | glam's `Vec3A` | `vec3x8::tests::eight_normalised_vectors_equal_glams_to_the_bit` |
//! | [`negate`] | scalar `-x` (keeps `-0`) | `vec3x8::tests::negating_keeps_the_sign_of_zero_as_scalar_code_does` |
//! | [`plane_hits`], [`sphere_hits`] | `Plane::intersect`, `Sphere::intersect` | `scene::tests` (every lane against `Scene::nearest_hit`) |
//! | [`CameraX8`] | `Camera::ray` | `camera::tests::eight_camera_rays_at_a_time_are_camera_ray_to_the_bit` |
//! | [`SceneX8::nearest_in_list`], [`SceneX8::any_in_list`] | `Scene::nearest_hit`, `Scene::any_hit` | `scene::tests::eight_rays_hit_what_the_scalar_scene_says_at_the_same_distance`, `…a_shadow_ray_is_blocked_in_exactly_the_lanes_the_scalar_scene_says` |
//! | [`SceneX8::surfaces`], [`SceneX8::hit`], [`SceneX8::hit_of`] | `Scene::hit_record`, `Checker::albedo_at` | `scene::tests` (the same test, and `…the_checker_parity_matches_the_scalar_one_far_out_and_at_nan`) |
//! | [`SkyX8::radiance`] | `Sky::radiance` | `light::tests::the_sky_of_eight_directions_is_the_scalar_sky_nan_and_minus_zero_included` |
//! | [`reflect`], [`refract`] | `optics::reflect`, `optics::refract` | `optics::tests::eight_reflections_and_refractions_equal_the_scalar_ones_to_the_bit` |
//! | [`SceneQueryX8`] for [`BvhX8`] (another way to find the hits: chapter 9's tree, eight rays against each node) | `ch09_many_spheres::Bvh::nearest_hit`, `Bvh::any_hit`, and so the list's [`SceneX8::nearest_in_list`], [`SceneX8::any_in_list`] | `tests/tree_x8_matches_list.rs` (chapter 9's random scenes and rays, every lane) |
//! | [`SpheresX8`] (one ray, eight spheres) | `Scene::nearest_hit`, `Scene::any_hit` | `spheres::tests` (50,000 random rays, ties, padding) |
//! | [`Pcg32x8`] (and [`Pcg32x8::uniform_in_lane`], one lane's draw in scalar arithmetic), [`sample_hashes`], [`sample_rngs`] | `sample_rng` and its `Pcg32` | `rng::tests` |
//! | [`offsets_x8`] | `PixelSamples::offset` (`jittered`, `random`) | `samples::tests::eight_jittered_or_random_points_at_once_are_offset_s_points_to_the_bit` |
//!
//! What the chapters do with these (chapter 7's shading, chapter 8's
//! paths) mirrors the chapters' own steps, and is bound by whole-image
//! byte tests: `tests/eight_rays.rs` for chapter 7 and
//! `chapters/08-eight-paths/tests/eight_paths.rs` for chapter 8.
//!
//! Every "to the bit" rests on one build flag: the workspace compiles
//! without FMA (`.cargo/config.toml`), so that `a·b + c` rounds twice in
//! lanes as it does in scalar code.

#![warn(missing_docs)]

pub mod bvh_x8;
pub mod camera;
pub mod light;
pub mod optics;
pub mod rng;
pub mod samples;
pub mod scene;
pub mod shapes;
pub mod spheres;
pub mod vec3x8;

pub use bvh_x8::BvhX8;
pub use camera::CameraX8;
pub use light::SkyX8;
pub use optics::{reflect, refract};
pub use rng::{Pcg32x8, U64x8, lane_mask, sample_hashes, sample_rngs};
pub use samples::{offsets_in_lanes, offsets_x8};
pub use scene::{GROUND, Hits, NOTHING, SceneQueryX8, SceneX8, Surfaces};
pub use shapes::{plane_hits, sphere_hits};
pub use spheres::SpheresX8;
pub use vec3x8::{LANES, Vec3x8, blend_back, lanes_of, mask_from_bits, negate};
