//! The book's speed tables, measured by the main job on the reader's own
//! machine: which processor it is, and chapters timed in turn, round after
//! round, so that the machine's drift from minute to minute falls on both
//! sides of every ratio alike.

use std::time::{Duration, Instant};

use ch06_path_tracing::{PathRender, PathSettings};
use ch07_eight_rays::Like;
use raylab::frame::thousands;
use raylab::{Camera, Keep, NoProgress, Rendered, Scene, Settings, Step};
use raylab_cli::{Chapter, CliError, Options};

use crate::Size;

/// How many rounds each pair runs: the median of a handful of warm
/// renders, each pair in turn within a round.
pub const ROUNDS: usize = 5;

/// The machine the tables were measured on, in one line: the processor's
/// name where the system says it (Linux's `/proc/cpuinfo`), its
/// architecture, and the cores the renders could use.
pub fn machine() -> String {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|l| l.starts_with("model name") || l.starts_with("Model"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, name)| name.trim().to_owned())
        })
        .unwrap_or_else(|| "a processor that does not give its name".to_owned());
    let build = if cfg!(debug_assertions) {
        "a debug build"
    } else {
        "a release build"
    };
    format!(
        "{model} ({}), {cores} core{}, {build}",
        std::env::consts::ARCH,
        if cores == 1 { "" } else { "s" }
    )
}

/// One pair's rounds: the two programs' median times and rays.
#[derive(Clone, Debug, PartialEq)]
pub struct Pair {
    pub what: String,
    pub first: &'static str,
    pub second: String,
    pub rays: u64,
    pub first_median: Duration,
    pub second_median: Duration,
}

impl Pair {
    /// How many times as fast the second program was as the first.
    pub fn ratio(&self) -> f64 {
        self.first_median.as_secs_f64() / self.second_median.as_secs_f64().max(1e-12)
    }
}

/// The middle of `times` (the mean of the two middle ones for an even count).
pub fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    let n = times.len();
    match n {
        0 => Duration::ZERO,
        _ if n % 2 == 1 => times[n / 2],
        _ => (times[n / 2 - 1] + times[n / 2]) / 2,
    }
}

/// Time `a` and `b` in turn, `rounds` times each (after one warm-up each),
/// and return their median times.
fn interleave(rounds: usize, mut a: impl FnMut(), mut b: impl FnMut()) -> (Duration, Duration) {
    a();
    b();
    let (mut ta, mut tb) = (Vec::new(), Vec::new());
    for _ in 0..rounds {
        let start = Instant::now();
        a();
        ta.push(start.elapsed());
        let start = Instant::now();
        b();
        tb.push(start.elapsed());
    }
    (median(ta), median(tb))
}

/// A Whitted chapter's default settings at `size`.
pub(crate) fn settings_of<S: Step>(chapter: &Chapter<S>, size: Size) -> Result<Settings, CliError> {
    let args = [
        chapter.binary.to_owned(),
        format!("--width={}", size.width),
        format!("--height={}", size.height),
    ];
    let options = Options::parse_for(chapter, args).map_err(|e| CliError::Usage(e.to_string()))?;
    let settings = options.settings()?;
    Ok(Settings {
        sampling: settings.sampling.with_lab_five(chapter.step.lab_five()),
        ..settings
    })
}

/// A chapter's render as its program makes it.
fn render_chapter<S: Step>(chapter: &Chapter<S>, settings: &Settings) -> Rendered {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    (chapter.render)(
        &scene,
        &camera,
        &chapter.step,
        settings,
        Keep::IMAGE,
        &NoProgress,
    )
}

/// A Whitted chapter against chapter 7 tracing as it does, in rounds.
fn whitted_pair<S: Step>(chapter: &Chapter<S>, like: Like, size: Size) -> Result<Pair, CliError> {
    let seven = ch07_eight_rays::chapter(like);
    let settings = settings_of(chapter, size)?;
    let rays = render_chapter(chapter, &settings).counts.total();
    assert_eq!(
        rays,
        render_chapter(&seven, &settings).counts.total(),
        "chapter 7 traces the same rays"
    );
    let (first_median, second_median) = interleave(
        ROUNDS,
        || drop(render_chapter(chapter, &settings)),
        || drop(render_chapter(&seven, &settings)),
    );
    Ok(Pair {
        what: settings.to_string(),
        first: chapter.binary,
        second: format!("{} --like {}", seven.binary, &like.binary()[..4]),
        rays,
        first_median,
        second_median,
    })
}

/// Chapter 6 against chapter 8, the same paths, in rounds.
fn path_pair(size: Size) -> Result<Pair, CliError> {
    use ch06_path_tracing::run;
    let program = &ch06_path_tracing::PROGRAM.program;
    let args = [
        program.binary.to_owned(),
        format!("--width={}", size.width),
        format!("--height={}", size.height),
        "--spp=16".to_owned(),
    ];
    let (options, flags) = run::parse(program, args).map_err(|e| CliError::Usage(e.to_string()))?;
    let settings: PathSettings = run::settings(&options, &flags)?;
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let six = || ch06_path_tracing::render_paths(&scene, &camera, &settings, &NoProgress);
    let eight = || ch08_eight_paths::render_eight(&scene, &camera, &settings, &NoProgress);
    let rays = six().rays;
    let (first_median, second_median) =
        interleave(ROUNDS, || drop::<PathRender>(six()), || drop(eight()));
    Ok(Pair {
        what: settings.to_string(),
        first: program.binary,
        second: ch08_eight_paths::PROGRAM.program.binary.to_owned(),
        rays,
        first_median,
        second_median,
    })
}

/// Every pair the book compares: chapters 1-5 against chapter 7 at the
/// chapters' size, and chapter 6 against chapter 8 at half of it each way.
pub fn measure(size: Size) -> Result<Vec<Pair>, CliError> {
    let half = Size {
        width: (size.width / 2).max(1),
        height: (size.height / 2).max(1),
    };
    Ok(vec![
        whitted_pair(&ch01_ray_cast::CHAPTER, Like::RayCast, size)?,
        whitted_pair(&ch02_shadows::CHAPTER, Like::Shadows, size)?,
        whitted_pair(&ch03_reflection::CHAPTER, Like::Reflection, size)?,
        whitted_pair(&ch04_refraction::CHAPTER, Like::Refraction, size)?,
        whitted_pair(&ch05_antialiasing::CHAPTER, Like::AntiAliasing, size)?,
        path_pair(half)?,
    ])
}

/// A figure's points, `(x, y)`.
pub type Points = Vec<(f64, f64)>;

/// Each pair's speed, one ray (or path) at a time and eight at a time, in
/// millions of rays per second, at its chapter's number: chapters 1-5 for
/// the Whitted pairs (their eight-at-a-time twin is chapter 7), 6 for the
/// path tracers' (its twin is chapter 8).
pub fn pair_speeds(pairs: &[Pair]) -> (Points, Points) {
    let mrays = |rays: u64, time: Duration| rays as f64 / time.as_secs_f64().max(1e-12) / 1e6;
    let at = |i: usize| (i + 1) as f64;
    let one = pairs.iter().enumerate();
    (
        one.clone()
            .map(|(i, p)| (at(i), mrays(p.rays, p.first_median)))
            .collect(),
        one.map(|(i, p)| (at(i), mrays(p.rays, p.second_median)))
            .collect(),
    )
}

/// The pairs as a figure: rays per second, one at a time against eight at
/// a time, per chapter (what the table beside it lists).
pub fn pairs_figure(pairs: &[Pair]) -> image::RgbImage {
    use raylab_plot::colour::series_colour;
    use raylab_plot::{Corner, LinePlot, Series};
    let (one, eight) = pair_speeds(pairs);
    let speeds = || eight.iter().chain(&one).map(|p| p.1);
    let (low, high) = (
        speeds().fold(f64::MAX, f64::min),
        speeds().fold(1.0, f64::max),
    );
    LinePlot::new("Rays per second, warm, measured in rounds")
        .x_label("chapter (1-5 Whitted, 6 path tracing)")
        .y_label("millions of rays per second")
        .integer_x_ticks()
        .x_range(0.5, one.len() as f64 + 0.5)
        // On a log scale the gap between the lines is the ratio itself.
        .log_y(low / 2.0)
        .y_range(low / 2.0, high * 2.0)
        .series(Series::new(
            "one at a time (chapters 1-6)",
            series_colour(0),
            one,
        ))
        .series(Series::new(
            "eight at a time (chapter 7 --like, and chapter 8)",
            series_colour(2),
            eight,
        ))
        .legend(Corner::TopRight)
        .render(900, 520)
}

/// The pairs as the book's table, with the machine they ran on.
pub fn pairs_table(pairs: &[Pair], machine: &str) -> String {
    let mut text = String::from(
        "| one at a time | eight at a time | rays | median, one | median, eight | ratio |\n\
         |---|---|---:|---:|---:|---:|\n",
    );
    for p in pairs {
        text.push_str(&format!(
            "| `{}` | `{}` | {} | {:.1} ms | {:.1} ms | {:.2} × |\n",
            p.first,
            p.second,
            thousands(p.rays),
            p.first_median.as_secs_f64() * 1e3,
            p.second_median.as_secs_f64() * 1e3,
            p.ratio()
        ));
    }
    let settings: Vec<String> = pairs
        .iter()
        .map(|p| format!("`{}` {}", p.first, p.what))
        .collect();
    text.push_str(&format!(
        "\nWarm renders in the main job's process, each pair in turn, {ROUNDS} rounds after \
         one warm-up each; the median of each. The settings: {}. Measured on the machine \
         that built this book: {machine}.\n",
        settings.join("; ")
    ));
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_median_of_an_odd_count_is_the_middle_one_and_of_an_even_count_the_mean_of_two() {
        let ms = |v: &[u64]| v.iter().map(|&m| Duration::from_millis(m)).collect();
        assert_eq!(median(ms(&[30, 10, 20])), Duration::from_millis(20));
        assert_eq!(median(ms(&[40, 10, 30, 20])), Duration::from_millis(25));
        assert_eq!(median(Vec::new()), Duration::ZERO);
    }

    #[test]
    fn the_table_states_each_ratio_and_the_machine() {
        let pair = Pair {
            what: "800×600, 5 spp".into(),
            first: "ch05-antialiasing",
            second: "ch07 --like ch05".into(),
            rays: 11_611_362,
            first_median: Duration::from_micros(130_000),
            second_median: Duration::from_micros(29_000),
        };
        let table = pairs_table(&[pair], "a test processor (x86_64), 2 cores");
        assert!(table.contains("| 11,611,362 |"), "{table}");
        assert!(
            table.contains("| 130.0 ms |") && table.contains("| 29.0 ms |"),
            "{table}"
        );
        assert!(table.contains("| 4.48 × |"), "{table}");
        assert!(
            table.contains("a test processor (x86_64), 2 cores"),
            "{table}"
        );
    }

    #[test]
    fn a_pair_of_11_6_million_rays_in_130_ms_runs_at_89_3_mrays_per_second() {
        let pair = |first_ms, second_ms| Pair {
            what: String::new(),
            first: "ch05-antialiasing",
            second: "ch07 --like ch05".into(),
            rays: 11_611_362,
            first_median: Duration::from_millis(first_ms),
            second_median: Duration::from_millis(second_ms),
        };
        let (one, eight) = pair_speeds(&[pair(130, 29), pair(100, 50)]);
        // 11,611,362 rays / 0.130 s = 89.318 Mrays/s; / 0.029 s = 400.39.
        assert_eq!(one[0].0, 1.0);
        assert!((one[0].1 - 89.318).abs() < 1e-3, "{one:?}");
        assert!((eight[0].1 - 400.392).abs() < 1e-3, "{eight:?}");
        assert_eq!(eight[1].0, 2.0);
        assert!((eight[1].1 - 232.227).abs() < 1e-3, "{eight:?}");
    }

    #[test]
    fn the_pairs_figure_draws_both_lines_at_its_size() {
        let pair = |first, second, ms_one, ms_eight| Pair {
            what: String::new(),
            first,
            second,
            rays: 1_000_000,
            first_median: Duration::from_millis(ms_one),
            second_median: Duration::from_millis(ms_eight),
        };
        let pairs = [
            pair("ch01-ray-cast", "ch07 --like ch01".into(), 50, 12),
            pair("ch06-path-tracing", "ch08-eight-paths".into(), 60, 35),
        ];
        let figure = pairs_figure(&pairs);
        assert_eq!(figure.dimensions(), (900, 520));
        // Both series' colours are drawn.
        for k in [0, 2] {
            let colour = raylab_plot::colour::series_colour(k);
            assert!(
                figure.pixels().any(|p| p.0 == colour),
                "series {k} is not drawn"
            );
        }
    }

    #[test]
    fn the_machine_is_named_with_its_architecture_and_cores() {
        let line = machine();
        assert!(line.contains(std::env::consts::ARCH), "{line}");
        assert!(line.contains("core"), "{line}");
    }
}
