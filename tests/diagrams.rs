//! The diagrams every chapter writes: their files, their sizes, and what
//! they say about the ray trees.

use std::path::Path;

use raylab::Step;
use raylab_cli::{Chapter, Options, Report};

/// Run a chapter at 80 × 60 into a fresh folder, with extra flags.
fn run_small<S: Step>(chapter: &Chapter<S>, dir: &Path, extra: &[&str]) -> Report {
    raylab_tests::run_chapter(chapter, (80, 60), dir, extra)
}

fn png_size(path: &Path) -> (u32, u32) {
    let image = image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (image.width(), image.height())
}

#[test]
fn every_chapter_writes_its_diagrams_as_valid_pngs_of_the_documented_size() {
    let dir = tempfile::tempdir().unwrap();
    fn check<S: Step>(chapter: &Chapter<S>, dir: &Path, sweeps: bool) {
        let report = run_small(chapter, dir, &[]);
        let out = &report.out_dir;
        assert_eq!(png_size(&out.join("render.png")), (80, 60));
        for heat_map in ["depth.png", "rays.png"] {
            let (w, h) = png_size(&out.join(heat_map));
            assert!(
                w > 80 && h > 60,
                "{heat_map} holds the image plus a colour bar"
            );
        }
        assert_eq!(png_size(&out.join("ray-tree.png")), (1240, 700));
        assert!(
            std::fs::read_to_string(out.join("probe.txt"))
                .unwrap()
                .starts_with("ray tree")
        );
        let sweep = out.join("depth-sweep");
        assert_eq!(sweep.exists(), sweeps, "{}", chapter.binary);
        if sweeps {
            assert_eq!(png_size(&sweep.join("depth-01.png")), (80, 60));
            assert_eq!(png_size(&sweep.join("changes.png")), (900, 500));
            png_size(&sweep.join("montage.png"));
            let settles = report.sweep.as_ref().unwrap().0.settles_at();
            // The picture, with its scale of changes under it.
            assert_eq!(
                png_size(&sweep.join(format!("diff-1-vs-{settles}.png"))),
                (80, 60 + raylab_plot::diff::SCALE_STRIP)
            );
            the_sentence_agrees_with_the_csv(&sweep);
        }
        // Nothing half-written is left behind.
        for entry in std::fs::read_dir(out).unwrap() {
            let name = entry.unwrap().file_name();
            assert!(!name.to_string_lossy().ends_with(".tmp"), "{name:?}");
        }
    }
    check(&ch01_ray_cast::CHAPTER, dir.path(), false);
    check(&ch02_shadows::CHAPTER, dir.path(), false);
    check(&ch03_reflection::CHAPTER, dir.path(), true);
    check(&ch04_refraction::CHAPTER, dir.path(), true);
    check(&ch05_antialiasing::CHAPTER, dir.path(), true);
}

#[test]
fn the_heat_map_of_chapter_1_is_uniform() {
    let dir = tempfile::tempdir().unwrap();
    let report = run_small(&ch01_ray_cast::CHAPTER, dir.path(), &[]);
    let maps = report
        .rendered
        .maps
        .as_ref()
        .expect("kept for the diagrams");
    assert!(maps.deepest.iter().all(|&d| d == 1));
    assert!(maps.rays.iter().all(|&n| n == 1));
    // The drawn map: every pixel of the 80 × 60 grid has depth 1's colour
    // (the legend's block for depth 1 has it too).
    let map = image::open(report.out_dir.join("depth.png"))
        .unwrap()
        .to_rgb8();
    let depth_1 =
        raylab_plot::ColourScale::steps(1, 2).colour(1.0, raylab_plot::Colormap::Distinct);
    // Rows with an unbroken run of 80 such pixels: the grid's 60 rows (the
    // legend's block is far narrower).
    let full_rows = map
        .rows()
        .filter(|row| {
            let mut run = 0;
            row.clone().any(|p| {
                run = if p.0 == depth_1 { run + 1 } else { 0 };
                run >= 80
            })
        })
        .count();
    assert_eq!(full_rows, 60);
}

#[test]
fn the_sweep_changes_pixels_from_depth_1_to_2_and_ends_at_the_render() {
    let dir = tempfile::tempdir().unwrap();
    fn check<S: Step>(chapter: &Chapter<S>, dir: &Path) {
        let report = run_small(chapter, dir, &[]);
        let csv = std::fs::read_to_string(report.out_dir.join("depth-sweep/changes.csv")).unwrap();
        let mut lines = csv.lines();
        assert_eq!(
            lines.next(),
            Some("depth,changed_pixels,changed_over_3,max_change")
        );
        let first: Vec<u64> = lines
            .next()
            .unwrap()
            .split(',')
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(first[0], 2);
        assert!(first[1] > 0, "{}: depth 2 changes pixels", chapter.binary);
        assert_eq!(csv.lines().count(), 10, "rows for depths 2 to 10");
        let last = image::open(report.out_dir.join("depth-sweep/depth-10.png"))
            .unwrap()
            .to_rgb8();
        let render = image::open(&report.render_png).unwrap().to_rgb8();
        assert_eq!(
            last, render,
            "{}: the sweep's last image is render.png",
            chapter.binary
        );
    }
    check(&ch03_reflection::CHAPTER, dir.path());
    check(&ch04_refraction::CHAPTER, dir.path());
    check(&ch05_antialiasing::CHAPTER, dir.path());
}

#[test]
fn probing_the_mirror_shows_one_reflection_of_weight_0_6_at_depth_2() {
    let dir = tempfile::tempdir().unwrap();
    let report = run_small(&ch03_reflection::CHAPTER, dir.path(), &["--no-diagrams"]);
    assert_eq!(
        report.written.len(),
        1,
        "--no-diagrams writes only render.png"
    );
    let report = run_small(&ch03_reflection::CHAPTER, dir.path(), &[]);
    let (_, text) = report.probe.expect("chapter 3 probes the mirror");
    let reflections: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with("reflection"))
        .collect();
    assert_eq!(reflections.len(), 1, "{text}");
    assert!(
        reflections[0].contains("(depth 2, weight 0.6000)"),
        "{text}"
    );
    assert!(
        text.lines().nth(1).unwrap().contains("hits mirror"),
        "{text}"
    );
}

#[test]
fn probing_the_glass_centre_shows_a_refracted_ray_leaving_at_depth_3() {
    let dir = tempfile::tempdir().unwrap();
    let report = run_small(
        &ch04_refraction::CHAPTER,
        dir.path(),
        &["--probe", "40,30", "--sweep", "3"],
    );
    let (pixel, text) = report.probe.unwrap();
    assert_eq!(pixel, (40, 30));
    assert_eq!(
        report.sweep.unwrap().0.images.len(),
        3,
        "--sweep 3 sweeps depths 1 to 3"
    );
    let default = run_small(&ch04_refraction::CHAPTER, dir.path(), &[]);
    let (_, text_default) = default.probe.unwrap();
    assert_ne!(text, text_default);
    let lines: Vec<&str> = text_default.lines().collect();
    assert!(lines[1].contains("hits glass"), "{text_default}");
    let leaving = lines
        .iter()
        .find(|l| l.trim_start().starts_with("refraction (depth 3"))
        .expect("a refracted ray at depth 3");
    assert!(
        !leaving.contains("hits glass"),
        "it has left the glass: {leaving}"
    );
}

#[test]
fn chapter_2_probes_a_ground_pixel_whose_feeler_is_blocked() {
    let dir = tempfile::tempdir().unwrap();
    let report = run_small(&ch02_shadows::CHAPTER, dir.path(), &[]);
    let (_, text) = report.probe.unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[1].contains("hits ground"), "{text}");
    assert!(
        lines[2].trim_start().starts_with("shadow") && lines[2].contains("in shadow"),
        "{text}"
    );
}

#[test]
fn chapter_5_probes_one_tree_per_sample() {
    let dir = tempfile::tempdir().unwrap();
    let report = run_small(&ch05_antialiasing::CHAPTER, dir.path(), &[]);
    let (_, text) = report.probe.unwrap();
    assert!(text.starts_with("ray trees of pixel"), "{text}");
    assert_eq!(
        text.lines().filter(|l| l.starts_with("sample ")).count(),
        5,
        "{text}"
    );
    assert!(
        text.contains("sample 2 at (0.25, 0.25) in the pixel:"),
        "{text}"
    );
}

#[test]
fn at_64_rays_per_pixel_the_probe_lists_16_trees_and_counts_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let report = run_small(&ch05_antialiasing::CHAPTER, dir.path(), &["--spp=64"]);
    let (_, text) = report.probe.unwrap();
    assert_eq!(
        text.lines().filter(|l| l.starts_with("sample ")).count(),
        16,
        "{text}"
    );
    assert!(text.contains("the average of 64 samples"), "{text}");
    assert!(
        text.contains("… and 48 more samples (") && text.contains("--probe-full lists every one"),
        "{text}"
    );
    let full = run_small(
        &ch05_antialiasing::CHAPTER,
        dir.path(),
        &["--spp=64", "--probe-full", "--probe=40,30"],
    );
    let (_, text) = full.probe.unwrap();
    assert_eq!(
        text.lines().filter(|l| l.starts_with("sample ")).count(),
        64
    );
}

#[test]
fn above_16_rays_per_pixel_a_chapter_sweeps_the_depth_only_when_asked() {
    let dir = tempfile::tempdir().unwrap();
    let report = run_small(&ch04_refraction::CHAPTER, dir.path(), &["--spp=25"]);
    assert!(report.sweep.is_none() && report.sweep_skipped);
    assert!(!report.out_dir.join("depth-sweep").exists());
    let asked = run_small(
        &ch04_refraction::CHAPTER,
        dir.path(),
        &["--spp=25", "--sweep=3"],
    );
    assert_eq!(asked.sweep.as_ref().map(|s| s.0.images.len()), Some(3));
    assert!(!asked.sweep_skipped);
    let sixteen = run_small(&ch04_refraction::CHAPTER, dir.path(), &["--spp=16"]);
    assert!(sixteen.sweep.is_some());
}

#[test]
fn a_probe_outside_the_image_is_refused() {
    let chapter = &ch04_refraction::CHAPTER;
    let options = Options::parse_for(
        chapter,
        [
            chapter.binary,
            "--width",
            "80",
            "--height",
            "60",
            "--probe",
            "80,10",
        ],
    )
    .unwrap();
    let err = options.settings().unwrap_err();
    assert!(
        err.to_string()
            .contains("--probe 80,10 is outside the 80×60 image"),
        "{err}"
    );
}

#[test]
fn the_glass_probe_folds_subtrees_too_faint_to_show_and_probe_full_lists_every_ray() {
    let dir = tempfile::tempdir().unwrap();
    let folded = run_small(&ch04_refraction::CHAPTER, dir.path(), &[])
        .probe
        .unwrap()
        .1;
    let full = run_small(&ch04_refraction::CHAPTER, dir.path(), &["--probe-full"])
        .probe
        .unwrap()
        .1;
    let rays: usize = full
        .lines()
        .next()
        .and_then(|l| l.split(": ").nth(1))
        .and_then(|l| l.split(' ').next())
        .and_then(|n| n.parse().ok())
        .expect("the first line counts the rays");
    assert_eq!(full.lines().count(), 1 + rays, "one line a ray: {full}");
    assert!(!full.contains("lists them"), "{full}");
    assert!(
        !full.contains("weight 0.0000") && !full.contains("0.0000)"),
        "{full}"
    );
    assert!(
        full.contains("e-"),
        "the faint rays' numbers are legible: {full}"
    );

    // Every ray is either on a line of its own or counted in a fold.
    let fold_lines: Vec<&str> = folded
        .lines()
        .filter(|l| l.contains("lists them"))
        .collect();
    assert!(!fold_lines.is_empty(), "{folded}");
    let in_folds: usize = fold_lines
        .iter()
        .map(|l| {
            let below = l.split(" and ").nth(1).unwrap().split(' ').next().unwrap();
            1 + below.parse::<usize>().unwrap()
        })
        .sum();
    let shown = folded.lines().count() - 1 - fold_lines.len();
    assert_eq!(shown + in_folds, rays, "{folded}");
    assert!(
        folded.lines().count() < full.lines().count() * 2 / 3,
        "{folded}"
    );
    // The first three levels, which make the glass, are never folded.
    assert!(
        folded.contains("refraction (depth 3, weight 0.4900) from"),
        "{folded}"
    );
}

/// The depth sweep's generated sentence (`summary.md`'s last line) says what
/// its own CSV says: the depth it names still changed a pixel by more than
/// one level, by as many levels as it states, and no deeper one did.
fn the_sentence_agrees_with_the_csv(sweep: &Path) {
    let summary = std::fs::read_to_string(sweep.join("summary.md")).unwrap();
    let sentence = summary.trim_end().lines().last().unwrap();
    let after = |marker: &str| -> u32 {
        let rest = &sentence[sentence
            .find(marker)
            .unwrap_or_else(|| panic!("{sentence}"))
            + marker.len()..];
        rest.split(|c: char| !c.is_ascii_digit())
            .next()
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("no number after {marker:?} in {sentence}"))
    };
    let settles = after("settles at depth ");
    let csv = std::fs::read_to_string(sweep.join("changes.csv")).unwrap();
    let rows: Vec<(u32, u32)> = csv
        .lines()
        .skip(1)
        .map(|line| {
            let fields: Vec<u32> = line.split(',').map(|f| f.parse().unwrap()).collect();
            (fields[0], fields[3])
        })
        .collect();
    for &(depth, max_change) in &rows {
        if depth > settles {
            assert!(
                max_change <= 1,
                "{sentence}, but depth {depth} changed {max_change}"
            );
        }
        if depth == settles {
            assert!(
                max_change > 1,
                "{sentence}, but depth {depth} changed only {max_change}"
            );
            assert_eq!(after("still changed a pixel by "), max_change, "{sentence}");
        }
    }
}

#[test]
fn a_scene_file_sets_the_offset_unless_epsilon_is_given() {
    let dir = tempfile::tempdir().unwrap();
    let lab = std::fs::read_to_string("../scenes/lab.toml").unwrap();
    let with = dir.path().join("with.toml");
    std::fs::write(&with, format!("epsilon = 0.002\n{lab}")).unwrap();
    let chapter = &ch02_shadows::CHAPTER;
    let epsilon = |extra: &[&str]| {
        let mut args = vec![chapter.binary];
        args.extend_from_slice(extra);
        let options = Options::parse_for(chapter, args).unwrap();
        options.settings().unwrap().epsilon
    };
    let file = with.to_str().unwrap();
    assert_eq!(epsilon(&[]), 1e-4);
    assert_eq!(epsilon(&["--scene", "../scenes/lab.toml"]), 1e-4);
    assert_eq!(epsilon(&["--scene", file]), 0.002);
    assert_eq!(epsilon(&["--scene", file, "--epsilon", "0"]), 0.0);
}
