//! Chapter 2's ε at scale: on the field of 500 spheres, 20–30 units from
//! the eye, the lab's 1e-4 is smaller than the rounding error of a hit
//! point, and feelers and reflected rays that start inside their own
//! sphere speckle it; the field's own `epsilon` leaves none.

use std::path::Path;

use ch09_many_spheres::Like;
use ch09_many_spheres::acne::speckled;
use image::RgbImage;
use raylab::{Keep, NoProgress, Settings};
use raylab_cli::scene_file::load_file;

/// An offset far above any rounding error here, and still far below the
/// size of anything in the scene: the render without acne to compare with.
const LARGE: f32 = 1e-2;

fn render(epsilon: f32) -> RgbImage {
    let field = load_file(Path::new("../../scenes/field-500.toml")).unwrap();
    let nine = ch09_many_spheres::chapter(Like::Refraction);
    let settings = Settings {
        width: 240,
        height: 180,
        max_depth: 10,
        epsilon,
        sampling: raylab::Sampling::PIXEL_CENTRE,
    };
    (nine.render)(
        &field.scene,
        &field.camera,
        &nine.step,
        &settings,
        Keep::IMAGE,
        &NoProgress,
    )
    .srgb
}

/// Pixels that differ from `reference` by more than `SPECKLE` levels.
fn speckles(image: &RgbImage, reference: &RgbImage) -> usize {
    speckled(image, reference).iter().filter(|&&s| s).count()
}

#[test]
fn the_field_speckles_at_the_labs_epsilon_and_not_at_its_own() {
    let field = load_file(Path::new("../../scenes/field-500.toml")).unwrap();
    let own = field.epsilon.expect("the field sets its epsilon");
    let reference = render(LARGE);
    let lab = speckles(&render(1e-4), &reference);
    let fixed = speckles(&render(own), &reference);
    println!("speckled pixels: {lab} at 1e-4, {fixed} at {own}");
    assert!(lab >= 100, "the lab's 1e-4 speckles {lab} pixels");
    assert_eq!(fixed, 0, "the field's own {own} still speckles");
}
