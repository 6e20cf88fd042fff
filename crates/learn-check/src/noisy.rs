//! Chapter 6's picture check: a path-traced render is noise around its
//! answer, so the learner's is judged against the reference within the two
//! renders' own noise, with chapter 6's per-pixel z-test
//! ([`ch06_path_tracing::agreement`]), not pixel by pixel. Any correct
//! estimator passes, whatever random numbers it draws and in whatever
//! order; a biased one stands out where its bias exceeds the noise.

use std::io::Write;
use std::path::Path;
use std::sync::{Arc, Mutex};

use ch06_path_tracing::agreement::{FAR, WorstZ, ZTest, z_test};
use ch06_path_tracing::exr::load_exr;
use image::RgbImage;
use raylab::linear_image::LinearImage;
use raylab::{Camera, NoProgress, Scene};

use crate::compare::save_images;
use crate::compare::signed_colour;
use learn::run::shown;

/// The most pixel channels that may lie more than [`FAR`] standard errors
/// from the reference: 0.1 %. Normal noise puts 0.006 % there; a pixel's
/// variance estimated from a few dozen paths, some of them rare bright
/// ones (the glass, the mirror), gives a z with heavier tails, and a
/// correct learner must never fail by chance: two seeds of the reference
/// at the check's 64 paths put up to 0.01 % there, at 16 paths up to
/// 0.05 %. The wrong answers the author checks try put 0.9 % or more.
pub const MAX_FAR_SHARE: f64 = 0.001;
/// The largest mean z over every pixel channel: a correct render is as
/// often brighter as darker than the reference (two seeds of it differ
/// by at most ±0.01), an estimator that loses or adds light a little
/// everywhere shifts the mean even where no pixel is far (the wrong
/// answers tried: 0.23 and more).
pub const MAX_MEAN_Z: f64 = 0.1;

/// What the z-test found, as a verdict keeps it.
#[derive(Clone, Debug, PartialEq)]
pub struct NoiseAgreement {
    pub values: usize,
    pub far: usize,
    pub mean_z: f64,
    pub worst: Option<WorstZ>,
}

impl NoiseAgreement {
    pub fn passes(&self) -> bool {
        self.far_share() <= MAX_FAR_SHARE && self.mean_z.abs() <= MAX_MEAN_Z
    }

    pub fn far_share(&self) -> f64 {
        self.far as f64 / self.values.max(1) as f64
    }
}

impl From<&ZTest> for NoiseAgreement {
    fn from(a: &ZTest) -> Self {
        NoiseAgreement {
            values: a.values,
            far: a.far,
            mean_z: a.mean_z,
            worst: a.worst,
        }
    }
}

/// A render and the variance of its mean, per pixel.
pub struct NoisyImage {
    pub image: LinearImage,
    pub variance: LinearImage,
}

/// The learner's render as their program wrote it into `dir`.
pub fn read_render(dir: &Path) -> Result<NoisyImage, String> {
    let read = |name: &str| {
        load_exr(&dir.join(name)).map_err(|e| format!("cannot read the render's {name}: {e}"))
    };
    Ok(NoisyImage {
        image: read("render.exr")?,
        variance: read("variance.exr")?,
    })
}

/// The reference chapter 6 at the check's size and `flags`, traced by
/// chapter 6's own renderer, once per run of `learn`: `watch` and the
/// author checks ask for it again and again.
pub fn reference(args: Vec<String>) -> Arc<NoisyImage> {
    static MADE: Mutex<Vec<(Vec<String>, Arc<NoisyImage>)>> = Mutex::new(Vec::new());
    let mut made = MADE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, image)) = made.iter().find(|(a, _)| *a == args) {
        return Arc::clone(image);
    }
    let program = &ch06_path_tracing::PROGRAM.program;
    let (options, flags) =
        ch06_path_tracing::run::parse(program, args.clone()).expect("the check's flags parse");
    let settings =
        ch06_path_tracing::run::settings(&options, &flags).expect("the check's size is allowed");
    let rendered =
        ch06_path_tracing::render_paths(&Scene::lab(), &Camera::lab(), &settings, &NoProgress);
    let image = Arc::new(NoisyImage {
        image: rendered.image,
        variance: rendered.variance,
    });
    made.push((args, Arc::clone(&image)));
    image
}

/// Judge `learner` against `reference`; on a mismatch say where and why,
/// and write the images that show it into `dir`.
pub fn judge(
    learner: &NoisyImage,
    reference: &NoisyImage,
    dir: &Path,
    here: &Path,
    out: &mut dyn Write,
) -> NoiseAgreement {
    let agreement = z_test(
        (&learner.image, &learner.variance),
        (&reference.image, &reference.variance),
    );
    let summary = NoiseAgreement::from(&agreement);
    if summary.passes() {
        return summary;
    }
    let _ = writeln!(
        out,
        "  ✗ its render differs from the reference by more than their noise: {:.2} % of pixel \
         channels are over {FAR} standard errors off (chance allows {:.1} %), mean z {:+.2} \
         (allowed ±{MAX_MEAN_Z})",
        summary.far_share() * 100.0,
        MAX_FAR_SHARE * 100.0,
        summary.mean_z,
    );
    if let Some(w) = summary.worst {
        let channel = ["red", "green", "blue"][w.channel];
        let _ = writeln!(
            out,
            "      worst pixel ({}, {}), {channel}: yours {:.4}, the reference {:.4}, z = {:+.1} \
             (standard error {:.4}); {}",
            w.x,
            w.y,
            w.a,
            w.b,
            w.z,
            w.standard_error,
            if w.z > 0.0 {
                "yours is brighter"
            } else {
                "yours is darker"
            }
        );
    }
    let images = [
        ("learner.png", learner.image.to_srgb8()),
        ("reference.png", reference.image.to_srgb8()),
        ("z-map.png", z_map(&agreement, learner.image.width())),
    ];
    if save_images(&images, dir, out) {
        let _ = writeln!(
            out,
            "      look at {}/learner.png, reference.png and z-map.png (red: yours brighter, \
             blue: darker, full strength at {} standard errors)",
            shown(dir, here),
            2.0 * FAR
        );
    }
    summary
}

/// Each pixel's z as a picture: black within the noise, red where the
/// learner's is brighter, blue where darker, by its channel furthest off.
pub fn z_map(agreement: &ZTest, width: u32) -> RgbImage {
    let height = agreement.z.len() as u32 / width.max(1);
    RgbImage::from_fn(width, height, |x, y| {
        let z = agreement.z[(y * width + x) as usize];
        let furthest = z
            .into_iter()
            .fold(0.0f64, |m, v| if v.abs() > m.abs() { v } else { m });
        let level = (255.0 * (furthest.abs() / (2.0 * FAR)).min(1.0)) as u8;
        signed_colour(level, furthest >= 0.0)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Vec3;

    #[test]
    fn the_z_map_is_red_where_the_learner_is_brighter_and_blue_where_darker() {
        let agreement = ZTest {
            z: vec![[8.0, 0.0, 0.0], [0.5, -9.0, 1.0], [0.0; 3]],
            values: 9,
            far: 2,
            mean_z: 0.0,
            worst: None,
        };
        let map = z_map(&agreement, 3);
        assert_eq!(map.get_pixel(0, 0).0, [255, 51, 0]);
        assert_eq!(map.get_pixel(1, 0).0, [0, 85, 255]);
        assert_eq!(map.get_pixel(2, 0).0, [0, 0, 0]);
    }

    #[test]
    fn a_render_judged_against_itself_passes() {
        let image = LinearImage::from_pixels(2, 1, vec![Vec3::splat(0.3); 2]);
        let variance = LinearImage::from_pixels(2, 1, vec![Vec3::splat(0.01); 2]);
        let noisy = NoisyImage { image, variance };
        let dir = tempfile::tempdir().unwrap();
        let mut out = Vec::new();
        let verdict = judge(&noisy, &noisy, dir.path(), dir.path(), &mut out);
        assert!(verdict.passes() && out.is_empty());
    }
}
