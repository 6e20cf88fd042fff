//! Chapter 5: anti-aliasing.
//!
//! One ray per pixel sees one point of the scene; an edge that crosses the
//! pixel is either wholly in or wholly out, and edges become staircases.
//! The lab's fix traces five rays per pixel — the centre and the middle of
//! each quarter — and averages them in linear light. The tracing itself is
//! chapter 4's, unchanged: what this step adds is where the five rays go,
//! [`lab_five`]. The average over them is the core's `render` (every
//! chapter takes `--spp N`), and so are the other patterns of
//! `raylab::sampling`.

use raylab::probe::ProbeTarget;
use raylab::{Hit, Ray, Step, Surface, Vec3};
use raylab_cli::Chapter;

pub use ch04_refraction::Refraction;

// ANCHOR: lab_five
/// Where the lab's five rays cross a pixel, as offsets (sx, sy) from its
/// top-left corner, a pixel being 1 × 1: first the centre, then the middle
/// of each quarter — top left, top right, bottom left, bottom right. They
/// are summed in this order.
pub fn lab_five() -> [(f32, f32); 5] {
    // ANCHOR: todo_lab_five "Return the pixel centre (0.5, 0.5), then the middle of each quarter: top left, top right, bottom left, bottom right."
    [
        (0.5, 0.5),
        (0.25, 0.25),
        (0.75, 0.25),
        (0.25, 0.75),
        (0.75, 0.75),
    ]
    // ANCHOR_END: todo_lab_five
}
// ANCHOR_END: lab_five

// ANCHOR: step
/// Chapter 4's tracing, with this chapter's five rays per pixel.
pub struct AntiAliasing;

impl Step for AntiAliasing {
    fn shade(&self, ray: &Ray, hit: &Hit, surface: &mut Surface) -> Vec3 {
        Refraction.shade(ray, hit, surface)
    }

    fn lab_five(&self) -> [(f32, f32); 5] {
        lab_five()
    }
}
// ANCHOR_END: step

// ANCHOR: chapter
/// Chapter 5's program: chapter 4's tracing with five rays per pixel.
pub const CHAPTER: Chapter<AntiAliasing> = Chapter {
    binary: "ch05-antialiasing",
    about: "Chapter 5, anti-aliasing: five rays per pixel, averaged in linear light.",
    max_depth: 10,
    spp: 5,
    // A pixel on the glass ball's top edge, against the horizon: of its
    // five rays some hit the glass, some the ground, some the sky.
    probe: ProbeTarget::OnSphere {
        name: "glass",
        right: 0.1,
        up: 1.01,
    },
    step: AntiAliasing,
    render: raylab::render,
};
// ANCHOR_END: chapter

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_of_the_five_rays_goes_through_the_pixel_centre() {
        assert_eq!(lab_five()[0], (0.5, 0.5));
    }

    #[test]
    fn the_other_four_sit_in_the_middle_of_each_quarter_in_reading_order() {
        // Quarters of the 1 × 1 pixel have their middles a quarter in from
        // each side: x and y are 0.25 or 0.75, left before right, top first.
        assert_eq!(
            lab_five()[1..],
            [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)]
        );
    }

    #[test]
    fn the_five_points_are_inside_the_pixel_and_centred_on_average() {
        let five = lab_five();
        assert!(
            five.iter()
                .all(|&(x, y)| (0.0..1.0).contains(&x) && (0.0..1.0).contains(&y))
        );
        let (sx, sy) = five
            .iter()
            .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x, b + y));
        assert_eq!((sx / 5.0, sy / 5.0), (0.5, 0.5));
    }

    #[test]
    fn the_step_hands_its_five_points_to_the_sampler() {
        // `--spp 5` renders with the step's points: with these, the lab's.
        assert_eq!(AntiAliasing.lab_five(), raylab::sampling::LAB_FIVE);
        let sampling = raylab::Sampling::LAB_FIVE.with_lab_five(AntiAliasing.lab_five());
        let offsets: Vec<_> = sampling.offsets((3, 2)).collect();
        assert_eq!(offsets, lab_five());
    }
}
