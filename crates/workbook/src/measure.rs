//! The numbers behind chapter 6's figures: how much brighter one render is
//! than another, which pixels show the ground in the sun's shadow, how the
//! light splits into terms over them, and how far a render lies from a
//! long one.
//!
//! Everything here works on linear radiance, never on the 8-bit encoding,
//! so that "twice the number" means "twice the light".

use raylab::linear_image::LinearImage;
use raylab::scene::Object;
use raylab::{Camera, Hit, Ray, Scene, Vec3};

/// The light a colour carries as the eye weighs it: Rec. 709 luminance,
/// `0.2126 R + 0.7152 G + 0.0722 B` (of linear values).
pub fn luminance(c: Vec3) -> f32 {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

/// Below this luminance a pixel counts as black in [`log2_ratio`]: far
/// under the darkest 8-bit step, so only truly black pixels are affected.
pub const RATIO_FLOOR: f32 = 1e-5;

/// Per pixel, how many times more light `b` has than `a`, as a power of
/// two: +1 where `b` is twice as bright, −2 where it has a quarter of the
/// light, 0 where both are black. A ratio and not a difference, so a dark
/// shadow that gains little light in absolute terms still shows how much
/// it gained compared with what it had.
///
/// # Panics
///
/// If the images differ in size.
pub fn log2_ratio(a: &LinearImage, b: &LinearImage) -> Vec<f32> {
    compare_luminance(a, b, |a, b| {
        (b.max(RATIO_FLOOR) / a.max(RATIO_FLOOR)).log2()
    })
}

/// Per pixel, how much more light `b` has than `a`: the difference of
/// their luminances (positive where `b` is brighter).
///
/// # Panics
///
/// If the images differ in size.
pub fn signed_difference(a: &LinearImage, b: &LinearImage) -> Vec<f32> {
    compare_luminance(a, b, |a, b| b - a)
}

/// `compare(luminance of a, luminance of b)` for each pair of pixels.
fn compare_luminance(
    a: &LinearImage,
    b: &LinearImage,
    compare: impl Fn(f32, f32) -> f32,
) -> Vec<f32> {
    assert_eq!(
        (a.width(), a.height()),
        (b.width(), b.height()),
        "can only compare images of the same size"
    );
    a.pixels()
        .iter()
        .zip(b.pixels())
        .map(|(&a, &b)| compare(luminance(a), luminance(b)))
        .collect()
}

/// A range `±m` for a signed colour map: the `quantile` (0..=1) of the
/// values' sizes, rounded up to 1, 2 or 5 times a power of ten, so that a
/// few extreme pixels do not wash out the rest and the scale bar gets
/// round numbers.
pub fn symmetric_range(values: &[f32], quantile: f32) -> f32 {
    let mut sizes: Vec<f32> = values
        .iter()
        .filter(|v| v.is_finite())
        .map(|v| v.abs())
        .collect();
    if sizes.is_empty() {
        return 1.0;
    }
    sizes.sort_by(f32::total_cmp);
    let at = ((sizes.len() - 1) as f32 * quantile.clamp(0.0, 1.0)).round() as usize;
    round_up_125(sizes[at])
}

/// The smallest of 1, 2, 5 × 10^k at or above `x` (1 for nothing positive).
fn round_up_125(x: f32) -> f32 {
    // NaN, zero and below: no scale to round.
    if x.is_nan() || x <= 0.0 {
        return 1.0;
    }
    // Dividing by 10^k rather than multiplying by 10^−k keeps 0.05 the
    // nearest f32 to 0.05.
    let exponent = x.log10().floor() as i32;
    let times_power = |m: f32| {
        if exponent >= 0 {
            m * 10f32.powi(exponent)
        } else {
            m / 10f32.powi(-exponent)
        }
    };
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(times_power)
        .find(|&m| m >= x * (1.0 - 1e-6))
        .unwrap_or(times_power(10.0))
}

/// What the primary ray through each pixel's centre meets first, row by
/// row: the core's own scene query, as the Whitted chapters ask it.
pub fn primary_hits(scene: &Scene, camera: &Camera, width: u32, height: u32) -> Vec<Option<Hit>> {
    (0..height)
        .flat_map(|j| (0..width).map(move |i| (i, j)))
        .map(|(i, j)| scene.nearest_hit(&camera.ray(i, j, (0.5, 0.5), width, height)))
        .collect()
}

/// The ground as the eye sees it, split by the sun's shadow ray.
#[derive(Clone, Debug, PartialEq)]
pub struct GroundMasks {
    /// The pixel's centre sees the ground, and the sun reaches that point.
    pub lit: Vec<bool>,
    /// The pixel's centre sees the ground, and something blocks the sun.
    pub shadowed: Vec<bool>,
    /// The ground's checker albedo where the pixel's centre sees it (zero
    /// elsewhere).
    pub albedo: Vec<Vec3>,
}

/// Which pixels see the ground first, and of those which are in the sun's
/// shadow: a shadow ray from the hit towards the sun, started `epsilon`
/// along it, as the lab model's shading does.
pub fn ground_masks(hits: &[Option<Hit>], scene: &Scene, epsilon: f32) -> GroundMasks {
    let to_sun = scene.sun.direction;
    let mut masks = GroundMasks {
        lit: vec![false; hits.len()],
        shadowed: vec![false; hits.len()],
        albedo: vec![Vec3::ZERO; hits.len()],
    };
    for (k, hit) in hits.iter().enumerate() {
        let Some(hit) = hit.filter(|h| h.object == Object::Ground) else {
            continue;
        };
        let shadow = Ray::new(hit.point + to_sun * epsilon, to_sun);
        if scene.any_hit(&shadow) {
            masks.shadowed[k] = true;
        } else {
            masks.lit[k] = true;
        }
        masks.albedo[k] = hit.material.albedo();
    }
    masks
}

/// Each term's share of the light (luminance summed over the pixels of
/// `mask`, or over all of them), as a fraction of the terms' sum.
pub fn shares<const N: usize>(terms: &[LinearImage; N], mask: Option<&[bool]>) -> [f64; N] {
    let chosen = |k: usize| mask.is_none_or(|m| m[k]);
    let sums = terms.each_ref().map(|term| {
        term.pixels()
            .iter()
            .enumerate()
            .filter(|&(k, _)| chosen(k))
            .map(|(_, &c)| f64::from(luminance(c)))
            .sum::<f64>()
    });
    let total: f64 = sums.iter().sum();
    sums.map(|s| if total > 0.0 { s / total } else { 0.0 })
}

/// The mean luminance over the pixels of `mask` (or over all of them), and
/// how many pixels that is; 0 for an empty mask.
pub fn mean_luminance(image: &LinearImage, mask: Option<&[bool]>) -> (f64, usize) {
    let (sum, count) = image
        .pixels()
        .iter()
        .enumerate()
        .filter(|&(k, _)| mask.is_none_or(|m| m[k]))
        .fold((0f64, 0usize), |(s, n), (_, &c)| {
            (s + f64::from(luminance(c)), n + 1)
        });
    (sum / count.max(1) as f64, count)
}

/// The mean, over the pixels of `mask`, of each channel's radiance divided
/// by the albedo there: the light a surface *receives* (irradiance / π for
/// a matte one), whatever the checker's colour. `None` for an empty mask.
pub fn mean_over_albedo(image: &LinearImage, albedo: &[Vec3], mask: &[bool]) -> Option<Vec3> {
    let (mut sum, mut count) = ([0f64; 3], 0usize);
    for ((&c, &a), _) in image
        .pixels()
        .iter()
        .zip(albedo)
        .zip(mask)
        .filter(|(_, m)| **m)
    {
        for (channel, (c, a)) in c.to_array().into_iter().zip(a.to_array()).enumerate() {
            sum[channel] += f64::from(c) / f64::from(a.max(1e-6));
        }
        count += 1;
    }
    (count > 0).then(|| {
        let n = count as f64;
        Vec3::new(
            (sum[0] / n) as f32,
            (sum[1] / n) as f32,
            (sum[2] / n) as f32,
        )
    })
}

/// How dark the lab's shading makes a shadow, as a fraction of the lit
/// ground beside it: `(0.01 E cos/π + 0.04) / (0.1 E cos/π + 0.04)` per
/// unit albedo, with the sun's brightness `E` and `cos` its angle to the
/// ground's normal (the lab model, "Local shading").
pub fn lab_shadow_ratio(brightness: f32, cos: f32) -> f32 {
    let sun = brightness * cos / std::f32::consts::PI;
    (0.01 * sun + 0.04) / (0.1 * sun + 0.04)
}

/// The root-mean-square difference between two linear images, over every
/// channel of every pixel.
///
/// # Panics
///
/// If the images differ in size.
pub fn rmse(a: &LinearImage, b: &LinearImage) -> f64 {
    assert_eq!(
        (a.width(), a.height()),
        (b.width(), b.height()),
        "can only compare images of the same size"
    );
    let sum: f64 = a
        .pixels()
        .iter()
        .zip(b.pixels())
        .flat_map(|(&a, &b)| (a - b).to_array())
        .map(|d| f64::from(d) * f64::from(d))
        .sum();
    (sum / (3 * a.pixels().len()).max(1) as f64).sqrt()
}

/// The mean of a variance image over every channel of every pixel: the
/// expected squared error of the estimate, so its root is the RMSE the
/// render's own samples predict.
pub fn mean_variance(variance: &LinearImage) -> f64 {
    let sum: f64 = variance
        .pixels()
        .iter()
        .flat_map(|v| v.to_array())
        .map(f64::from)
        .sum();
    sum / (3 * variance.pixels().len()).max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Material;
    use raylab::light::{Sky, Sun};

    #[test]
    fn the_mean_luminance_counts_only_the_masked_pixels() {
        // Luminance of white is 1, of pure green 0.7152.
        let image = LinearImage::from_pixels(
            3,
            1,
            vec![Vec3::ONE, Vec3::new(0.0, 1.0, 0.0), Vec3::splat(3.0)],
        );
        let (mean, n) = mean_luminance(&image, Some(&[true, true, false]));
        assert_eq!(n, 2);
        assert!((mean - (1.0 + 0.7152) / 2.0).abs() < 1e-6, "{mean}");
        let (all, n) = mean_luminance(&image, None);
        assert_eq!(n, 3);
        assert!((all - (4.0 + 0.7152) / 3.0).abs() < 1e-6, "{all}");
        assert_eq!(mean_luminance(&image, Some(&[false; 3])), (0.0, 0));
    }
    use raylab::plane::{Checker, Plane};
    use raylab::scene::Ground;
    use raylab::sphere::Sphere;

    fn image(pixels: &[Vec3]) -> LinearImage {
        LinearImage::from_pixels(pixels.len() as u32, 1, pixels.to_vec())
    }

    #[test]
    fn white_has_a_luminance_of_one_and_green_weighs_most() {
        assert!((luminance(Vec3::ONE) - 1.0).abs() < 1e-6);
        assert_eq!(luminance(Vec3::new(0.0, 1.0, 0.0)), 0.7152);
        assert_eq!(luminance(Vec3::new(2.0, 0.0, 0.0)), 0.4252);
    }

    #[test]
    fn the_signed_difference_is_positive_where_the_second_image_is_brighter() {
        let a = image(&[Vec3::splat(0.5), Vec3::splat(0.5)]);
        let b = image(&[Vec3::splat(0.75), Vec3::new(0.5, 0.0, 0.5)]);
        let d = signed_difference(&a, &b);
        assert!((d[0] - 0.25).abs() < 1e-6);
        // Green lost: 0.7152 × 0.5.
        assert!((d[1] + 0.3576).abs() < 1e-6, "{d:?}");
    }

    #[test]
    fn the_log_ratio_counts_doublings_of_the_second_image_over_the_first() {
        let a = image(&[Vec3::splat(0.2), Vec3::splat(0.4), Vec3::ZERO]);
        let b = image(&[Vec3::splat(0.8), Vec3::splat(0.1), Vec3::ZERO]);
        let r = log2_ratio(&a, &b);
        // 0.8 / 0.2 = 4 = 2², 0.1 / 0.4 = 1/4, and black against black is 0.
        assert!((r[0] - 2.0).abs() < 1e-5, "{r:?}");
        assert!((r[1] + 2.0).abs() < 1e-5, "{r:?}");
        assert_eq!(r[2], 0.0);
    }

    #[test]
    fn the_symmetric_range_rounds_the_quantile_up_to_one_two_or_five() {
        // Sizes 0.01 .. 1.00; the 90th percentile is 0.9 (index 89 of 99
        // rounds to 0.90), rounded up to 1.
        let values: Vec<f32> = (1..=100).map(|k| -(k as f32) / 100.0).collect();
        assert_eq!(symmetric_range(&values, 0.9), 1.0);
        assert_eq!(symmetric_range(&values, 0.15), 0.2);
        assert_eq!(symmetric_range(&[0.03, -0.004], 1.0), 0.05);
        assert_eq!(symmetric_range(&[0.2], 1.0), 0.2);
        assert_eq!(symmetric_range(&[], 0.5), 1.0);
        assert_eq!(symmetric_range(&[0.0, f32::NAN], 1.0), 1.0);
    }

    /// A grey ground, a white sky, the sun at 45° towards +x and, when
    /// asked, a ball two units over the origin; a camera ten units up,
    /// looking straight down.
    fn scene_with_ball(ball: bool) -> (Scene, Camera) {
        let ground = Ground {
            plane: Plane {
                point: Vec3::ZERO,
                normal: Vec3::Y,
            },
            checker: Checker {
                even: Vec3::splat(0.5),
                odd: Vec3::splat(0.5),
            },
        };
        let sky = Sky {
            horizon: Vec3::ONE,
            zenith: Vec3::ONE,
        };
        let sun = Sun {
            direction: Vec3::new(1.0, 1.0, 0.0).normalize(),
            brightness: 25.0,
        };
        let mut scene = Scene::new(ground, sky, sun).unwrap();
        if ball {
            let matte = Material::diffuse(Vec3::splat(0.8)).unwrap();
            let shape = Sphere {
                centre: Vec3::new(0.0, 2.0, 0.0),
                radius: 0.5,
            };
            scene.add_sphere("ball", shape, matte).unwrap();
        }
        let camera =
            Camera::look_at(Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, Vec3::NEG_Z, 30.0).unwrap();
        (scene, camera)
    }

    #[test]
    fn the_ground_under_a_ball_is_in_its_shadow_and_the_rest_is_lit() {
        // 9 × 9 pixels over 5.36 × 5.36 units of ground (0.6 a pixel). The
        // ball hides the ground under it; its shadow is an ellipse around
        // x = −2 (the sun is at 45°), x from −2.71 to −1.29 and z within
        // ±0.5: on the middle row, the pixels whose centres see x = −2.38
        // and x = −1.79, and no others.
        let (scene, camera) = scene_with_ball(true);
        let hits = primary_hits(&scene, &camera, 9, 9);
        let masks = ground_masks(&hits, &scene, 1e-4);
        let centre = 4 * 9 + 4;
        assert_eq!(hits[centre].unwrap().object, Object::Sphere(0));
        assert!(!masks.lit[centre] && !masks.shadowed[centre]);
        let shadowed: Vec<usize> = (0..81).filter(|&k| masks.shadowed[k]).collect();
        assert_eq!(shadowed.len(), 2, "{shadowed:?}");
        for k in shadowed {
            assert_eq!(k / 9, 4, "the shadow lies on the middle row");
            let x = hits[k].unwrap().point.x;
            assert!((-2.71..-1.29).contains(&x), "{x}");
            assert_eq!(masks.albedo[k], Vec3::splat(0.5));
        }
        let on_the_ball = hits
            .iter()
            .filter(|h| h.is_some_and(|h| h.object == Object::Sphere(0)))
            .count();
        let lit = masks.lit.iter().filter(|&&m| m).count();
        assert_eq!(
            lit + 2 + on_the_ball,
            81,
            "every pixel sees the ground or the ball"
        );
        // Without the ball, every pixel is lit ground.
        let (scene, camera) = scene_with_ball(false);
        let masks = ground_masks(&primary_hits(&scene, &camera, 9, 9), &scene, 1e-4);
        assert!(masks.lit.iter().all(|&m| m));
    }

    #[test]
    fn shares_are_each_terms_part_of_the_luminance_over_the_mask() {
        let a = image(&[Vec3::splat(0.3), Vec3::splat(1.0)]);
        let b = image(&[Vec3::splat(0.1), Vec3::ZERO]);
        let [sa, sb] = shares(&[a.clone(), b.clone()], None);
        assert!((sa - 1.3 / 1.4).abs() < 1e-6 && (sb - 0.1 / 1.4).abs() < 1e-6);
        let [sa, sb] = shares(&[a, b], Some(&[true, false]));
        assert!((sa - 0.75).abs() < 1e-6 && (sb - 0.25).abs() < 1e-6);
    }

    #[test]
    fn the_light_received_divides_out_the_albedo_over_the_mask() {
        let radiance = image(&[Vec3::splat(0.2), Vec3::splat(0.6), Vec3::splat(9.0)]);
        let albedo = [Vec3::splat(0.25), Vec3::splat(0.75), Vec3::splat(0.5)];
        let mean = mean_over_albedo(&radiance, &albedo, &[true, true, false]).unwrap();
        assert!(
            (mean - Vec3::splat(0.8)).abs().max_element() < 1e-6,
            "{mean}"
        );
        assert_eq!(mean_over_albedo(&radiance, &albedo, &[false; 3]), None);
    }

    #[test]
    fn the_labs_shadow_is_a_sixth_of_the_lit_ground_in_the_lab_scene() {
        // Sun straight overhead: (0.25/π + 0.04) / (2.5/π + 0.04)
        // = 0.119577 / 0.835775 = 0.143074.
        assert!((lab_shadow_ratio(25.0, 1.0) - 0.143074).abs() < 1e-5);
        // The lab's sun, cos = 1.2 / |(-1, 1.2, 0.8)| = 0.683763:
        // (0.054413 + 0.04) / (0.544130 + 0.04) = 0.161632.
        assert!((lab_shadow_ratio(25.0, 0.683763) - 0.161632).abs() < 1e-5);
    }

    #[test]
    fn the_rmse_is_the_root_of_the_mean_squared_channel_difference() {
        let a = image(&[Vec3::new(1.0, 0.0, 0.0), Vec3::ZERO]);
        let b = image(&[Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0)]);
        // (1 + 4) / 6 channels.
        assert!((rmse(&a, &b) - (5.0f64 / 6.0).sqrt()).abs() < 1e-12);
        assert_eq!(rmse(&a, &a), 0.0);
        assert!((mean_variance(&b) - 2.0 / 6.0).abs() < 1e-12);
    }
}
