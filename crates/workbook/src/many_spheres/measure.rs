//! What chapter 9's figures measure: rays per second through the list and
//! through the tree, the tree's build time, and where the lab's offset
//! speckles a field most.

use std::time::Instant;

use ch09_many_spheres::field::field_scene;
use ch09_many_spheres::{Bvh, Like};
use raylab::NoProgress;
use raylab::frame::{Keep, Rendered};
use raylab_cli::CliError;

use crate::Size;
use crate::speed::settings_of;

/// Rays per second of one render, the list against the tree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedPoint {
    pub spheres: usize,
    /// Millions of rays per second, every sphere tested.
    pub list: f64,
    /// The image the list was timed on: the figure's own, or for a large
    /// field a smaller one of the same view ([`list_size`]).
    pub list_size: Size,
    /// Millions of rays per second through the tree (its build included).
    pub tree: f64,
}

/// The largest field the list is timed on at the figure's full size.
pub const LIST_FULL_SIZE_UP_TO: usize = 500;

/// The image the list is timed on for a field of `spheres`: the same view
/// with fewer pixels, about `LIST_FULL_SIZE_UP_TO / spheres` as many, so
/// that every field past 500 costs the list about as many ray–sphere tests
/// as the field of 500 does. A rate is rays over time, and the view is the
/// same, so the smaller image measures the same rate; at full size the
/// fields of 5,000 and 10,000 spheres were most of the main job's time.
pub fn list_size(size: Size, spheres: usize) -> Size {
    let scale = (LIST_FULL_SIZE_UP_TO as f64 / spheres.max(1) as f64)
        .min(1.0)
        .sqrt();
    let shrink = |pixels: u32| ((f64::from(pixels) * scale).round() as u32).clamp(1, pixels);
    Size {
        width: shrink(size.width),
        height: shrink(size.height),
    }
}

/// Render a field of each of `counts` spheres at chapter 5's settings
/// (its defaults at this `size`), through the list and through the tree,
/// and time each (the fastest of a few renders where one is quick). The
/// list is timed on [`list_size`]'s image, where the tree is rendered
/// again to check that it gives the list's image.
pub fn measure_speed(counts: &[usize], size: Size) -> Result<Vec<SpeedPoint>, CliError> {
    let settings = settings_of(&ch05_antialiasing::CHAPTER, size)?;
    let step = Like::AntiAliasing;
    // Chapter 9's renderer: the tree built, then searched.
    let through_tree = ch09_many_spheres::chapter(step).render;
    let keep = Keep {
        linear: false,
        maps: false,
    };
    counts
        .iter()
        .map(|&n| {
            let (scene, camera) = field_scene(n);
            let small = list_size(size, n);
            let list_settings = settings_of(&ch05_antialiasing::CHAPTER, small)?;
            let list = fastest(|| {
                raylab::render(&scene, &camera, &step, &list_settings, keep, &NoProgress)
            });
            let tree =
                fastest(|| through_tree(&scene, &camera, &step, &settings, keep, &NoProgress));
            let same_size_tree = if small == size {
                tree.srgb.clone()
            } else {
                through_tree(&scene, &camera, &step, &list_settings, keep, &NoProgress).srgb
            };
            assert_eq!(
                list.srgb, same_size_tree,
                "the tree must give the list's image"
            );
            Ok(SpeedPoint {
                spheres: n,
                list: list.mrays_per_second(),
                list_size: small,
                tree: tree.mrays_per_second(),
            })
        })
        .collect()
}

/// The fastest of up to five renders, made again while they took under a
/// third of a second together: a render of a few milliseconds is timed as
/// much by the machine's other work as by its own.
fn fastest(render: impl Fn() -> Rendered) -> Rendered {
    let mut best = render();
    let mut spent = best.elapsed;
    for _ in 1..5 {
        if spent.as_secs_f64() >= 1.0 / 3.0 {
            break;
        }
        let again = render();
        spent += again.elapsed;
        if again.elapsed < best.elapsed {
            best = again;
        }
    }
    best
}

/// The time to build the tree over a field of each of `counts` spheres, on
/// one core, in milliseconds (the best of `rounds`).
pub fn measure_build(counts: &[usize], rounds: usize) -> Vec<(usize, f64)> {
    counts
        .iter()
        .map(|&n| {
            let (scene, _) = field_scene(n);
            let best = (0..rounds.max(1))
                .map(|_| {
                    let start = Instant::now();
                    let tree = Bvh::build(&scene);
                    let elapsed = start.elapsed();
                    assert!(tree.depth() <= ch09_many_spheres::bvh::MAX_DEPTH);
                    elapsed.as_secs_f64() * 1e3
                })
                .fold(f64::INFINITY, f64::min);
            (n, best)
        })
        .collect()
}

/// The top-left corner of the `w` × `h` window of a `width`-wide `mask`
/// that holds the most `true` pixels (the first such, scanning in steps of
/// 8 pixels), and how many it holds.
pub fn densest_window(mask: &[bool], width: u32, w: u32, h: u32) -> ((u32, u32), usize) {
    let height = mask.len() as u32 / width.max(1);
    let count = |x0: u32, y0: u32| {
        (y0..y0 + h)
            .map(|y| {
                let row = (y * width) as usize;
                mask[row + x0 as usize..row + (x0 + w) as usize]
                    .iter()
                    .filter(|&&s| s)
                    .count()
            })
            .sum::<usize>()
    };
    let mut best = ((0, 0), 0);
    for y0 in (0..=height.saturating_sub(h)).step_by(8) {
        for x0 in (0..=width.saturating_sub(w)).step_by(8) {
            let n = count(x0, y0);
            if n > best.1 {
                best = ((x0, y0), n);
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_densest_window_is_where_the_speckles_are() {
        let (width, height) = (64u32, 48u32);
        let mut mask = vec![false; (width * height) as usize];
        for (x, y) in [(3, 3), (41, 25), (44, 30), (52, 38)] {
            mask[(y * width + x) as usize] = true;
        }
        assert_eq!(densest_window(&mask, width, 16, 16), ((40, 24), 3));
    }

    const FIGURE: Size = Size {
        width: 120,
        height: 90,
    };

    #[test]
    fn fields_up_to_500_spheres_time_the_list_at_the_figures_full_size() {
        assert_eq!(list_size(FIGURE, 5), FIGURE);
        assert_eq!(list_size(FIGURE, 500), FIGURE);
    }

    #[test]
    fn a_field_of_10000_spheres_times_the_list_on_a_twentieth_of_the_pixels() {
        // √(500/10,000) = 0.2236: 120 × 0.2236 = 26.8, 90 × 0.2236 = 20.1.
        assert_eq!(
            list_size(FIGURE, 10_000),
            Size {
                width: 27,
                height: 20
            }
        );
        // √(500/5,000) = 0.3162: 37.9 and 28.5.
        assert_eq!(
            list_size(FIGURE, 5_000),
            Size {
                width: 38,
                height: 28
            }
        );
    }

    #[test]
    fn a_huge_field_still_times_the_list_on_at_least_one_pixel() {
        assert_eq!(
            list_size(FIGURE, usize::MAX),
            Size {
                width: 1,
                height: 1
            }
        );
    }
}
