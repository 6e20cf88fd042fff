//! Helpers for the tests of the whole workbook: comparing images the way
//! the lab model's tolerance says, and the golden images kept in `tests/golden/`.

use std::path::PathBuf;

use image::RgbImage;

/// The lab model's tolerance, kept once in the core: the learner's `check` judges
/// with the same copy.
pub use raylab::tolerance::{Agreement, compare};

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
