//! The scenes and rays on which the tree must answer as the list does:
//! random ones, wild ones included, and three made by hand. Chapter 9's
//! `tree_matches_list` asks them of the tree one ray at a time; the
//! lanes' `tree_x8_matches_list` asks them of its search of eight rays at
//! a time, so both floors face the same cases.

use proptest::prelude::*;
use raylab::light::{Sky, Sun};
use raylab::material::Material;
use raylab::plane::{Checker, Plane};
use raylab::scene::{Ground, Object, Scene};
use raylab::sphere::Sphere;
use raylab::{Ray, Vec3};

fn empty_scene(ground_y: f32) -> Scene {
    Scene::new(
        Ground {
            plane: Plane {
                point: Vec3::new(0.0, ground_y, 0.0),
                normal: Vec3::Y,
            },
            checker: Checker {
                even: Vec3::ONE,
                odd: Vec3::ZERO,
            },
        },
        Sky {
            horizon: Vec3::ONE,
            zenith: Vec3::ONE,
        },
        Sun {
            direction: Vec3::Y,
            brightness: 1.0,
        },
    )
    .unwrap()
}

/// The ground at `ground_y` and these spheres, all matte.
pub fn scene_of(ground_y: f32, spheres: &[Sphere]) -> Scene {
    let mut scene = empty_scene(ground_y);
    let matte = Material::diffuse(Vec3::splat(0.5)).unwrap();
    for (i, s) in spheres.iter().enumerate() {
        scene.add_sphere(&format!("s{i}"), *s, matte).unwrap();
    }
    scene
}

/// A hit as bits: which object, and exactly how far.
pub fn key(hit: Option<raylab::Hit>) -> Option<(Object, u32)> {
    hit.map(|h| (h.object, h.t.to_bits()))
}

/// A radius anywhere from 1e-6 to 1e6, most of them ordinary.
fn radius() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => 0.05f32..2.0,
        1 => (-6i32..=6, 1.0f32..10.0).prop_map(|(e, m)| m * 10f32.powi(e)),
        1 => Just(1e-6f32),
        1 => Just(1e6f32),
    ]
}

/// A coordinate: mostly near the origin, some far away, some exact.
fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![
        6 => -5.0f32..5.0,
        1 => -1e6f32..1e6,
        1 => (-3i32..=3).prop_map(|k| k as f32),
    ]
}

fn point() -> impl Strategy<Value = Vec3> {
    (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// Spheres, with repeats (exact ties), shared centres (spheres inside
/// others) and one centre for many (a flat box).
fn spheres() -> impl Strategy<Value = Vec<Sphere>> {
    let pool = prop::collection::vec((point(), radius()), 1..8);
    (
        pool,
        prop::collection::vec((0usize..64, 0usize..64, any::<bool>(), radius()), 0..60),
    )
        .prop_map(|(pool, picks)| {
            picks
                .into_iter()
                .map(|(a, _b, own_radius, r)| {
                    let (centre, pool_r) = pool[a % pool.len()];
                    Sphere {
                        centre,
                        radius: if own_radius { r } else { pool_r },
                    }
                })
                .collect()
        })
}

/// A direction: random, along an axis (zero components), or a diagonal.
fn direction() -> impl Strategy<Value = Vec3> {
    prop_oneof![
        4 => (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0)
            .prop_filter("not zero", |(x, y, z)| x * x + y * y + z * z > 1e-6)
            .prop_map(|(x, y, z)| Vec3::new(x, y, z).normalize()),
        1 => prop::sample::select(vec![Vec3::X, Vec3::NEG_X, Vec3::Y, Vec3::NEG_Y, Vec3::Z, Vec3::NEG_Z]),
        1 => (prop::sample::select(vec![-1.0f32, 0.0, 1.0]), prop::sample::select(vec![-1.0f32, 0.0, 1.0]), prop::sample::select(vec![-1.0f32, 1.0]))
            .prop_map(|(x, y, z)| Vec3::new(x, y, z).normalize()),
    ]
}

/// A random scene (the ground at 0, far below, or near) and rays into it.
/// Some rays start at a sphere's centre, on its surface or aim at it:
/// inside boxes, on faces, at exact ties.
pub fn random_case() -> impl Strategy<Value = (Scene, Vec<Ray>)> {
    (
        prop_oneof![Just(0.0f32), Just(-1e7f32), -2.0f32..2.0],
        spheres(),
        prop::collection::vec(
            (point(), direction(), 0usize..64, 0u8..4, -1.0f32..2.0),
            1..24,
        ),
    )
        .prop_map(|(ground_y, spheres, rays)| {
            let rays = rays
                .into_iter()
                .filter_map(|(origin, d, pick, kind, s)| {
                    let aimed = spheres.get(pick % spheres.len().max(1));
                    let origin = match (kind, aimed) {
                        (1, Some(sp)) => sp.centre,
                        (2, Some(sp)) => sp.centre + d * sp.radius * s,
                        _ => origin,
                    };
                    let direction = match (kind, aimed) {
                        (3, Some(sp)) if (sp.centre - origin).length() > 0.0 => {
                            (sp.centre - origin).normalize()
                        }
                        _ => d,
                    };
                    (direction.is_finite() && origin.is_finite())
                        .then_some(Ray { origin, direction })
                })
                .collect();
            (scene_of(ground_y, &spheres), rays)
        })
}

/// 10,000 spheres of radii from 1e-6 up, all on one centre (a box that is
/// a point, which no cut can split), and three rays at them.
pub fn one_centre() -> (Scene, Vec<Ray>) {
    let spheres: Vec<Sphere> = (0..10_000)
        .map(|i| Sphere {
            centre: Vec3::new(0.0, 1.0, 0.0),
            radius: 1e-6 * 1.01f32.powi(i % 2100),
        })
        .collect();
    let rays = [
        (Vec3::new(0.0, 1.0, 5.0), Vec3::NEG_Z),
        (Vec3::new(0.0, 1.0, 0.0), Vec3::X),
        (
            Vec3::new(3.0, 4.0, 5.0),
            (Vec3::new(0.0, 1.0, 0.0) - Vec3::new(3.0, 4.0, 5.0)).normalize(),
        ),
    ]
    .map(|(origin, direction)| Ray { origin, direction });
    (scene_of(0.0, &spheres), rays.to_vec())
}

/// Rows of spheres of radius 1e-6 to 1e6, far outside the view, and 2,000
/// rays from the lab's eye.
pub fn far_and_every_size() -> (Scene, Vec<Ray>) {
    let mut spheres = Vec::new();
    for (i, r) in [1e-6f32, 1e-3, 1.0, 1e3, 1e6].iter().enumerate() {
        for k in 0..20 {
            let x = (k as f32 - 10.0) * 1e5;
            spheres.push(Sphere {
                centre: Vec3::new(x, i as f32 * 1e5, -9e5),
                radius: *r,
            });
        }
    }
    let rays = (0..2000)
        .map(|k| {
            let a = k as f32 * 0.618_034;
            let d = Vec3::new(a.sin() * 0.5, (a * 1.3).cos() * 0.5, -1.0).normalize();
            Ray {
                origin: Vec3::new(0.0, 1.0, 5.0),
                direction: d,
            }
        })
        .collect();
    (scene_of(0.0, &spheres), rays)
}

/// One sphere of radius 1e-3, 1,000 units away, and a fan of rays around
/// it. The list's test is loose there: b² − q cancels numbers of size 1e6
/// against a radius of 1e-3, and it reports hits well outside the sphere.
pub fn tiny_far_away() -> (Scene, Vec<Ray>) {
    let sphere = Sphere {
        centre: Vec3::new(0.0, 1.0, -1000.0),
        radius: 1e-3,
    };
    let origin = Vec3::new(0.0, 1.0, 0.0);
    let mut rays = Vec::new();
    for i in -200..=200 {
        for j in -20..=20 {
            let target = sphere.centre + Vec3::new(i as f32 * 1e-4, j as f32 * 1e-3, 0.0);
            rays.push(Ray {
                origin,
                direction: (target - origin).normalize(),
            });
        }
    }
    (scene_of(-10.0, &[sphere]), rays)
}
