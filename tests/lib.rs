//! Helpers for the tests of the whole workbook: comparing images the way
//! LAB.md's tolerance says, and the golden images kept in `tests/golden/`.

use std::path::PathBuf;

use image::RgbImage;

/// How closely two 8-bit images agree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Agreement {
    /// Share of pixels whose every channel is within 3 of 255.
    pub within_3: f64,
    /// Mean absolute difference over every channel of every pixel.
    pub mean: f64,
    /// The largest difference in any channel.
    pub max: u8,
    /// Pixels equal in every channel.
    pub identical: usize,
}

impl Agreement {
    /// LAB.md's bar for two correct implementations: at least 99.5 % of
    /// pixels within 3 in every channel, and a mean difference under 0.5.
    pub fn meets_lab_tolerance(&self) -> bool {
        self.within_3 >= 0.995 && self.mean < 0.5
    }
}

/// Compare two images of the same size.
///
/// # Panics
/// If their sizes differ: that is a failed comparison, not a measurement.
pub fn compare(a: &RgbImage, b: &RgbImage) -> Agreement {
    assert_eq!(a.dimensions(), b.dimensions(), "the images differ in size");
    let (mut within_3, mut identical, mut sum, mut max) = (0usize, 0usize, 0u64, 0u8);
    for (pa, pb) in a.pixels().zip(b.pixels()) {
        let diffs = [0, 1, 2].map(|c| pa.0[c].abs_diff(pb.0[c]));
        let worst = diffs.into_iter().max().unwrap_or(0);
        within_3 += usize::from(worst <= 3);
        identical += usize::from(worst == 0);
        max = max.max(worst);
        sum += diffs.iter().map(|&d| u64::from(d)).sum::<u64>();
    }
    let pixels = (a.width() * a.height()) as f64;
    Agreement {
        within_3: within_3 as f64 / pixels,
        mean: sum as f64 / (3.0 * pixels),
        max,
        identical,
    }
}

/// Where the golden image of a chapter lives.
pub fn golden_path(binary: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("golden")
        .join(format!("{binary}.png"))
}

/// Whether this run should rewrite the golden images instead of checking
/// them: only on purpose, with `RAYLAB_BLESS=1` (see the README).
pub fn blessing() -> bool {
    std::env::var_os("RAYLAB_BLESS").is_some_and(|v| v == "1")
}

/// Check `image` against the golden image of `binary`, or rewrite that
/// golden image when blessing.
pub fn check_golden(binary: &str, image: &RgbImage) {
    let path = golden_path(binary);
    if blessing() {
        std::fs::create_dir_all(path.parent().expect("a folder")).expect("create tests/golden");
        image.save(&path).expect("write the golden image");
        eprintln!("blessed {}", path.display());
        return;
    }
    let golden = image::open(&path)
        .unwrap_or_else(|e| {
            panic!(
                "cannot read {}: {e}; make it on purpose with RAYLAB_BLESS=1 cargo test -p raylab-tests --test golden",
                path.display()
            )
        })
        .to_rgb8();
    let agreement = compare(image, &golden);
    assert!(
        agreement.meets_lab_tolerance(),
        "{binary} no longer renders its golden image: {agreement:?}"
    );
}

/// Run a chapter's program in-process, as `<binary> --width W --height H
/// --quiet --out DIR/<binary> <extra flags>` would, and return its report.
///
/// # Panics
/// If the flags do not parse or the run fails: these are tests.
pub fn run_chapter<S: raylab::Step>(
    chapter: &raylab_cli::Chapter<S>,
    (width, height): (u32, u32),
    dir: &std::path::Path,
    extra: &[&str],
) -> raylab_cli::Report {
    let out = dir.join(chapter.binary);
    let mut args: Vec<String> = [chapter.binary, "--quiet"].map(String::from).to_vec();
    args.extend([format!("--width={width}"), format!("--height={height}")]);
    args.push(format!("--out={}", out.display()));
    args.extend(extra.iter().map(|a| a.to_string()));
    let options = raylab_cli::Options::parse_for(chapter, args).expect("the flags parse");
    raylab_cli::run(chapter, &options).expect("the chapter runs")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_images_agree_completely() {
        let a = RgbImage::from_pixel(4, 4, image::Rgb([10, 20, 30]));
        let agreement = compare(&a, &a);
        assert_eq!(agreement.within_3, 1.0);
        assert_eq!(agreement.identical, 16);
        assert_eq!(agreement.max, 0);
    }

    #[test]
    fn one_pixel_off_by_four_in_two_hundred_is_the_limit() {
        // 1 of 200 pixels off by more than 3 is exactly 99.5 % within 3.
        let a = RgbImage::from_pixel(20, 10, image::Rgb([100, 100, 100]));
        let mut b = a.clone();
        b.put_pixel(0, 0, image::Rgb([104, 100, 100]));
        let agreement = compare(&a, &b);
        assert_eq!(agreement.within_3, 0.995);
        assert!(agreement.meets_lab_tolerance());
        b.put_pixel(1, 0, image::Rgb([100, 96, 100]));
        assert!(!compare(&a, &b).meets_lab_tolerance());
    }

    #[test]
    fn a_mean_difference_of_half_a_level_fails() {
        let a = RgbImage::from_pixel(4, 4, image::Rgb([100, 100, 100]));
        let b = RgbImage::from_pixel(4, 4, image::Rgb([101, 100, 100]));
        let agreement = compare(&a, &b);
        assert!((agreement.mean - 1.0 / 3.0).abs() < 1e-12);
        assert!(agreement.meets_lab_tolerance());
        let c = RgbImage::from_pixel(4, 4, image::Rgb([101, 101, 100]));
        assert!(!compare(&a, &c).meets_lab_tolerance());
    }
}
