//! The sun as a disc: its solid angle, its radiance, and where its samples
//! fall (`--sun-size`).

use std::f32::consts::PI;

use ch06_path_tracing::sun::Sunlight;
use raylab::Scene;

#[test]
fn the_real_suns_half_degree_disc_covers_67_millionths_of_a_steradian() {
    let sun = Sunlight::new(&Scene::lab().sun, Some(0.53));
    assert!(
        (sun.solid_angle() - 6.720e-5).abs() < 1e-7,
        "{}",
        sun.solid_angle()
    );
    assert!((sun.radiance() * sun.solid_angle() - 2.5).abs() < 1e-5);
}

#[test]
fn a_180_degree_sun_is_the_whole_hemisphere() {
    let sun = Sunlight::new(&Scene::lab().sun, Some(180.0));
    assert!((sun.solid_angle() - 2.0 * PI).abs() < 1e-5);
}

#[test]
fn a_hundredth_of_a_degree_sun_has_a_finite_radiance() {
    let sun = Sunlight::new(&Scene::lab().sun, Some(0.01));
    assert!(sun.radiance().is_finite() && sun.radiance() > 1e7);
    assert_eq!(sun.radiance_along(sun.direction), sun.radiance());
    assert!(sun.sample(0.5, 0.5).is_finite());
}

#[test]
fn sun_samples_stay_inside_the_disc_and_cover_it() {
    let sun = Sunlight::new(&Scene::lab().sun, Some(10.0));
    let cos_half = 5f32.to_radians().cos();
    let mut outer = 0;
    for i in 0..64 {
        for j in 0..64 {
            let d = sun.sample((i as f32 + 0.5) / 64.0, (j as f32 + 0.5) / 64.0);
            assert!((d.length() - 1.0).abs() < 1e-5);
            let cos = d.dot(sun.direction);
            assert!(cos >= cos_half - 1e-6, "{cos}");
            assert!(sun.radiance_along(d) > 0.0);
            outer += usize::from(cos < 2.5f32.to_radians().cos());
        }
    }
    // Uniform in solid angle: three quarters of the disc lie beyond half its radius.
    let share = outer as f32 / 4096.0;
    assert!((share - 0.75).abs() < 0.01, "{share}");
}

#[test]
fn a_point_sun_is_never_seen() {
    let sun = Sunlight::new(&Scene::lab().sun, None);
    assert_eq!(sun.radiance_along(sun.direction), 0.0);
    assert_eq!(sun.sample(0.3, 0.7), sun.direction);
}
