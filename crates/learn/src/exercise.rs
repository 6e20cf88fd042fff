//! The exercises: each chapter's source with its new step blanked.
//!
//! A chapter marks what the learner writes with a pair of comments inside
//! the function's body, next to the book's own anchors:
//!
//! ```text
//! pub fn sun_factor(hit: &Hit, surface: &mut Surface) -> f32 {
//!     // ANCHOR: todo_sun_factor "Cast a feeler ray ..."
//!     ... the body ...
//!     // ANCHOR_END: todo_sun_factor
//! }
//! ```
//!
//! The exercise keeps everything else (signature, doc comment, tests) and
//! replaces the marked lines with `todo!("Cast a feeler ray ...")`. The
//! markers are mdBook anchors, so the book's listings, which include the
//! function around them, leave them out. The exercise is made from the
//! chapter's source every time it is needed, so it cannot drift from it.

use std::fmt;

/// One step of a chapter that can be done as an exercise: the chapter's
/// own step, taken by the chapter's number, or another region of it, taken
/// by its name (chapter 6's `cosine` and `nee`). Each is its chapter's
/// crate with only its regions blanked, standing on the reference for the
/// rest, as chapter 3's exercise stands on the reference chapters 1 and 2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Exercise {
    pub number: u8,
    /// The name `start` and `check` take besides the number: `None` for
    /// the chapter's own step, which the number names.
    pub name: Option<&'static str>,
    /// The regions of `step` the learner writes, by their marker names:
    /// the chapter's other regions stay as the chapter solves them.
    pub regions: &'static [&'static str],
    /// The chapter's folder, from the workspace's root.
    pub dir: &'static str,
    /// The chapter's package (and program) name.
    pub package: &'static str,
    /// What the learner writes, in a few words, for `learn list`.
    pub title: &'static str,
    /// The book's page for it, from the workspace's root.
    pub page: &'static str,
    /// The file of the chapter's crate that holds the step, from its folder.
    pub step: &'static str,
    /// Flags the check renders with besides its size (chapter 6: fewer
    /// paths than its default, so that the learner's debug build renders in
    /// seconds).
    pub flags: &'static [&'static str],
    /// `learn hint`'s first level: a nudge, what to think about.
    pub nudge: &'static str,
    /// Its second: the rule the code must follow.
    pub rule: &'static str,
    /// Its third: what to do, in a few lines (the recipe).
    pub hint: &'static str,
}

/// Every exercise, in the book's order.
pub const EXERCISES: [Exercise; 8] = [
    Exercise {
        number: 1,
        name: None,
        regions: &["local_light"],
        dir: "chapters/01-ray-cast",
        package: "ch01-ray-cast",
        title: "Lambert and the sun (`local_light`)",
        page: "book/src/ch01-ray-casting.md",
        step: "src/lib.rs",
        flags: &[],
        nudge: "How much sunlight a surface gets depends on how squarely it faces the sun.",
        rule: "Irradiance is k · brightness · cos θ, none for a surface facing away; a matte surface sends albedo / π of it back, and the ambient term comes on top.",
        hint: "`hit.facing_normal.dot(sun.direction)` is cos θ; clamp it at 0 so that a \
               surface facing away gets no sun. The irradiance is k · brightness · cos θ; a \
               Lambertian surface sends albedo / π of it back (std::f32::consts::PI), and the \
               ambient term albedo · AMBIENT comes on top. `hit.material.albedo()` is the colour.",
    },
    Exercise {
        number: 2,
        name: None,
        regions: &["sun_factor"],
        dir: "chapters/02-shadows",
        package: "ch02-shadows",
        title: "the shadow feeler (`sun_factor`)",
        page: "book/src/ch02-shadows.md",
        step: "src/lib.rs",
        flags: &[],
        nudge: "A point is in shadow when something lies between it and the sun: ask with a ray.",
        rule: "Cast a feeler from the hit point towards the sun and ask whether anything blocks it; start it a little way off the surface, or rounding makes the surface shadow itself (shadow acne).",
        hint: "The feeler's direction is `surface.scene().sun.direction`, and \
               `surface.trace_shadow_ray(ray)` says whether anything blocks it. Do not start it \
               at `hit.point` itself: rounding puts half of those starts just inside the surface, \
               which then shadows itself (speckled \"shadow acne\"). Start it \
               `surface.epsilon()` along the direction.",
    },
    Exercise {
        number: 3,
        name: None,
        regions: &["send_reflection"],
        dir: "chapters/03-reflection",
        package: "ch03-reflection",
        title: "sending the reflection (`send_reflection`)",
        page: "book/src/ch03-reflection.md",
        step: "src/lib.rs",
        flags: &[],
        nudge: "A mirror sends part of the light on: the tracer traces any ray you hand it, with its share.",
        rule: "A reflecting surface (r > 0) sends one Reflection ray of share r along the mirror direction, normalised and started epsilon off the surface.",
        hint: "`hit.material.reflection()` is r. `raylab::optics::reflect(d, n)` mirrors the \
               ray's direction about `hit.facing_normal`; normalise it, start the new ray \
               `surface.epsilon()` along it, and hand it to \
               `surface.send(RayKind::Reflection, ray, r)`: the tracer does the rest.",
    },
    Exercise {
        number: 4,
        name: None,
        regions: &["send_refraction"],
        dir: "chapters/04-refraction",
        package: "ch04-refraction",
        title: "sending the refraction (`send_refraction`)",
        page: "book/src/ch04-refraction.md",
        step: "src/lib.rs",
        flags: &[],
        nudge: "Glass sends its transmitted share on, bent at the surface or, past the critical angle, reflected back inside.",
        rule: "eta is n₁/n₂, the side the ray comes from over the side it goes into: 1/ior going in, ior coming out. Where refract finds no direction, the share goes along the mirror direction as a total internal reflection; every new ray starts epsilon along itself.",
        hint: "`hit.material.transmission()` is t and `hit.material.ior()` the index. Going in \
               (`hit.entering`) eta is 1/ior, coming out it is ior. \
               `raylab::optics::refract(d, hit.facing_normal, eta)` gives `None` past the \
               critical angle: then send the share t along `reflect(d, n)` as \
               `RayKind::TotalInternalReflection`. Normalise every new direction and start it \
               `surface.epsilon()` along itself.",
    },
    Exercise {
        number: 5,
        name: None,
        regions: &["lab_five"],
        dir: "chapters/05-antialiasing",
        package: "ch05-antialiasing",
        title: "the lab's five rays (`lab_five`)",
        page: "book/src/ch05-antialiasing.md",
        step: "src/lib.rs",
        flags: &[],
        nudge: "Five rays per pixel: its centre and the middle of each of its four quarters.",
        rule: "Offsets go from the pixel's top-left corner, the pixel 1 wide and 1 high, y down: the quarters' middles are 0.25 and 0.75 in. Their order matters to the last bit of the sum.",
        hint: "Offsets are measured from the pixel's top-left corner, with the pixel 1 wide and \
               1 high, x to the right and y down. The centre is (0.5, 0.5); each quarter is \
               0.5 wide, so its middle is 0.25 in from its sides: x and y are each 0.25 or \
               0.75. The order matters to the last bit of the sum: top left, top right, bottom \
               left, bottom right. The core averages the five colours in linear light for you.",
    },
    Exercise {
        number: 6,
        name: None,
        regions: &["choose_lobe"],
        dir: "chapters/06-path-tracing",
        package: "ch06-path-tracing",
        title: "the choice of lobe (`choose_lobe`)",
        page: "book/src/ch06-path-tracing.md",
        step: "src/integrator.rs",
        flags: CHAPTER_6_FLAGS,
        nudge: "A path picks one lobe at each bounce, at random, as often as that lobe's share of the light.",
        rule: "The shares are the mirror's r and the refraction's t (or s·F and s·(1 − F) with Fresnel), the rest diffuse; cut [0, 1) into those lengths and see where u falls. A surface that neither reflects nor transmits is diffuse.",
        hint: "A surface that neither reflects nor transmits (r + t = 0) is diffuse, whatever u \
               is. Otherwise the shares are (mirror, refraction) = (r, t), or, with \
               `Materials::Fresnel` on a material that transmits, (s·F, s·(1 − F)) with s = r + t \
               and F = `fresnel(d.dot(hit.facing_normal), eta(hit))`. Then cut [0, 1) in that \
               order: u below the mirror's share is the mirror, below mirror + refraction the \
               refraction, the rest diffuse. Any order of the three is right: the check compares \
               your image with the reference within the two images' own noise.",
    },
    Exercise {
        number: 6,
        name: Some("cosine"),
        regions: &["cosine_direction"],
        dir: "chapters/06-path-tracing",
        package: "ch06-path-tracing",
        title: "cosine directions (`cosine_direction`)",
        page: "book/src/ch06-path-tracing.md",
        step: "src/integrator.rs",
        flags: CHAPTER_6_FLAGS,
        nudge: "A diffuse bounce should send more paths near the normal, in proportion to cos θ.",
        rule: "The density is cos θ/π: a uniform point on the unit disc, lifted straight up onto the hemisphere, has it. The direction is built in the normal's frame and is a unit vector.",
        hint: "The density cos θ/π is what a uniform point on the unit disc becomes when it is \
               lifted straight up onto the hemisphere (Malley's method): draw x, y uniform in \
               [−1, 1) with `random.uniform()` until x² + y² < 1, then z = √(1 − x² − y²). Or \
               invert it directly: cos θ = √(1 − u₁), φ = 2π·u₂. `n.any_orthonormal_pair()` gives \
               t and b at right angles to n; the direction is x·t + y·b + z·n. Any correct \
               sampler passes, whatever numbers it draws.",
    },
    Exercise {
        number: 6,
        name: Some("nee"),
        regions: &["sun_next_event"],
        dir: "chapters/06-path-tracing",
        package: "ch06-path-tracing",
        title: "next-event estimation (`sun_next_event`)",
        page: "book/src/ch06-path-tracing.md",
        step: "src/integrator.rs",
        flags: CHAPTER_6_FLAGS,
        nudge: "Rather than wait for a path to hit the sun by chance, ask the sun directly at every diffuse hit.",
        rule: "The sun's light is the BRDF (albedo / π) times its irradiance times cos θ, when a shadow ray, started off the surface, reaches it; none when the sun is behind the surface.",
        hint: "`self.sun.draw(random)` is the direction to the sun (a point of its disc with \
               `--sun-size`); cos θ = `hit.facing_normal.dot(it)`. At or below 0 the sun is behind \
               the surface: Vec3::ZERO, and no ray. Otherwise count the shadow ray (`*rays += 1`), \
               start it `self.epsilon` along the direction (from `hit.point` itself the surface \
               shadows itself) and ask `self.objects.any_hit`: blocked, Vec3::ZERO; open, \
               `hit.material.albedo()` · FRAC_1_PI · `self.sun.irradiance` · cos θ.",
    },
];

/// The flags chapter 6's check renders with besides its size: enough paths
/// per pixel that a biased estimate stands out of the noise (at 16, a
/// uniform hemisphere sampler without its weight is barely caught, and
/// the noise's own tails come close to the bar), few enough that a debug
/// build renders in a second or two.
const CHAPTER_6_FLAGS: &[&str] = &["--spp=64"];

/// The exercise for chapter `number`'s own step, if there is one.
pub fn exercise(number: u8) -> Option<&'static Exercise> {
    EXERCISES
        .iter()
        .find(|e| e.number == number && e.name.is_none())
}

/// A chapter's exercise by its name (`cosine`), or its own step by its
/// number (`6`, `ch06`).
pub fn exercise_named(name: &str) -> Option<&'static Exercise> {
    if let Some(named) = EXERCISES.iter().find(|e| e.name == Some(name)) {
        return Some(named);
    }
    exercise(name.trim_start_matches("ch").parse().ok()?)
}

impl Exercise {
    /// The name `start` and `check` take: `2`, `cosine`.
    pub fn name(&self) -> String {
        self.name
            .map_or_else(|| self.number.to_string(), str::to_owned)
    }

    /// Whether its picture is path traced, and so judged against the
    /// reference within the two renders' own noise (a per-pixel z-test)
    /// rather than pixel by pixel: chapter 6.
    pub fn judged_statistically(&self) -> bool {
        self.number == 6
    }
}

/// One region of a chapter's source that the learner writes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Task {
    /// The function it belongs to, as its marker names it.
    pub name: String,
    /// The one-line task that becomes the `todo!`'s message.
    pub text: String,
}

/// A marker that does not pair up, or has no task.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("line {line}: {what}")]
pub struct MarkerError {
    pub line: usize,
    pub what: String,
}

/// A chapter's source split into what the learner gets and what they write.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Blanked {
    /// The exercise: the source with each marked region replaced by `todo!`.
    pub exercise: String,
    /// The solution: the source with the markers taken out and nothing else.
    pub solution: String,
    pub tasks: Vec<Task>,
}

const START: &str = "// ANCHOR: todo_";
const END: &str = "// ANCHOR_END: todo_";

/// Blank every marked region of `source` with `todo!("task")`.
pub fn blank(source: &str) -> Result<Blanked, MarkerError> {
    blank_regions(source, |_| true, todo)
}

/// Blank the marked regions of `source` that `take` picks by name; the
/// others keep their code, without their markers, as in the solution.
pub fn blank_only(source: &str, take: impl Fn(&str) -> bool) -> Result<Blanked, MarkerError> {
    blank_regions(source, take, todo)
}

/// Blank every marked region of `source` with what `stub` makes of the
/// marker's indent and the region's task: a language without `todo!`
/// (chapter 10's WGSL) gets a blank of its own.
pub fn blank_with(
    source: &str,
    stub: impl Fn(&str, &Task) -> String,
) -> Result<Blanked, MarkerError> {
    blank_regions(source, |_| true, stub)
}

/// Rust's blank: `todo!("task")` at the marker's indent.
fn todo(indent: &str, task: &Task) -> String {
    format!("{indent}todo!({:?})\n", task.text)
}

/// Blank the regions `take` picks with `stub`; keep the others' code.
fn blank_regions(
    source: &str,
    take: impl Fn(&str) -> bool,
    stub: impl Fn(&str, &Task) -> String,
) -> Result<Blanked, MarkerError> {
    let mut exercise = String::with_capacity(source.len());
    let mut solution = String::with_capacity(source.len());
    let mut tasks = Vec::new();
    let mut open: Option<(usize, Task)> = None;
    for (n, line) in source.lines().enumerate() {
        let number = n + 1;
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix(START) {
            if let Some((at, task)) = &open {
                return Err(error(
                    number,
                    format!("`{}` opened on line {at} is not closed", task.name),
                ));
            }
            let task = parse_start(rest).ok_or_else(|| {
                error(
                    number,
                    "a todo marker is `// ANCHOR: todo_NAME \"one-line task\"`".into(),
                )
            })?;
            if take(&task.name) {
                let indent = &line[..line.len() - trimmed.len()];
                exercise.push_str(&stub(indent, &task));
            }
            open = Some((number, task));
        } else if let Some(name) = trimmed.strip_prefix(END) {
            match open.take() {
                Some((_, task)) if task.name == name.trim() => tasks.push(task),
                _ => {
                    return Err(error(
                        number,
                        format!("`{}` is closed but not open", name.trim()),
                    ));
                }
            }
        } else {
            solution.push_str(line);
            solution.push('\n');
            if open.as_ref().is_none_or(|(_, task)| !take(&task.name)) {
                exercise.push_str(line);
                exercise.push('\n');
            }
        }
    }
    if let Some((at, task)) = open {
        return Err(error(at, format!("`{}` is never closed", task.name)));
    }
    Ok(Blanked {
        exercise,
        solution,
        tasks,
    })
}

/// `NAME "task"` → the task.
pub(crate) fn parse_start(rest: &str) -> Option<Task> {
    let (name, text) = rest.split_once(' ')?;
    let text = text.trim().strip_prefix('"')?.strip_suffix('"')?;
    (!name.is_empty() && !text.is_empty() && !text.contains('"')).then(|| Task {
        name: name.to_owned(),
        text: text.to_owned(),
    })
}

fn error(line: usize, what: String) -> MarkerError {
    MarkerError { line, what }
}

impl fmt::Display for Exercise {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.name {
            None => write!(f, "chapter {} ({})", self.number, self.package),
            Some(name) => write!(f, "chapter {}'s `{name}` ({})", self.number, self.package),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_hint_is_printed_without_runs_of_spaces() {
        for exercise in EXERCISES {
            assert!(
                !exercise.hint.contains("  ") && !exercise.hint.contains('\n'),
                "chapter {}'s hint has a run of spaces or a line break: {:?}",
                exercise.number,
                exercise.hint
            );
        }
    }

    const SOURCE: &str = "\
/// Doubles.
pub fn double(x: u32) -> u32 {
    // ANCHOR: todo_double \"Return twice x.\"
    // Why: because.
    x * 2
    // ANCHOR_END: todo_double
}
";

    #[test]
    fn a_marked_body_becomes_a_todo_with_its_task() {
        let blanked = blank(SOURCE).unwrap();
        assert_eq!(
            blanked.exercise,
            "/// Doubles.\npub fn double(x: u32) -> u32 {\n    todo!(\"Return twice x.\")\n}\n"
        );
        assert_eq!(
            blanked.tasks,
            [Task {
                name: "double".into(),
                text: "Return twice x.".into()
            }]
        );
    }

    #[test]
    fn the_solution_is_the_source_without_its_markers() {
        let blanked = blank(SOURCE).unwrap();
        assert_eq!(
            blanked.solution,
            "/// Doubles.\npub fn double(x: u32) -> u32 {\n    // Why: because.\n    x * 2\n}\n"
        );
    }

    #[test]
    fn an_unclosed_marker_is_an_error_that_names_its_line() {
        let source = "fn f() {\n    // ANCHOR: todo_f \"Do it.\"\n}\n";
        assert_eq!(blank(source).unwrap_err().line, 2);
    }

    #[test]
    fn a_marker_without_a_task_is_an_error() {
        let source = "fn f() {\n    // ANCHOR: todo_f\n    // ANCHOR_END: todo_f\n}\n";
        assert!(blank(source).is_err());
    }

    #[test]
    fn only_the_regions_picked_are_blanked_and_every_marker_goes() {
        let source = format!("{SOURCE}{}", SOURCE.replace("double", "twice"));
        let blanked = blank_only(&source, |name| name == "twice").unwrap();
        assert!(
            blanked
                .exercise
                .contains("    // Why: because.\n    x * 2\n")
        );
        assert!(blanked.exercise.contains("todo!(\"Return twice x.\")"));
        assert!(!blanked.exercise.contains("ANCHOR"), "{}", blanked.exercise);
        assert_eq!(blanked.tasks.len(), 2, "both are read");
    }

    #[test]
    fn every_region_of_a_chapter_is_one_exercise_and_every_exercise_names_its_regions() {
        let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
        for exercise in EXERCISES {
            let path = format!("{root}/{}/{}", exercise.dir, exercise.step);
            let source = std::fs::read_to_string(&path).unwrap();
            let blanked = blank(&source).unwrap_or_else(|e| panic!("{path}: {e}"));
            for task in &blanked.tasks {
                let owners = EXERCISES
                    .iter()
                    .filter(|e| e.dir == exercise.dir && e.regions.contains(&task.name.as_str()))
                    .count();
                assert_eq!(owners, 1, "{path}: region `{}`", task.name);
            }
            for region in exercise.regions {
                assert!(
                    blanked.tasks.iter().any(|t| t.name == *region),
                    "{exercise}: no region `{region}` in {path}"
                );
            }
        }
    }

    #[test]
    fn a_chapters_step_is_found_by_its_number_and_its_other_exercises_by_name() {
        assert_eq!(exercise_named("6").and_then(|e| e.name), None);
        assert_eq!(exercise_named("ch06").map(|e| e.number), Some(6));
        assert_eq!(
            exercise_named("nee").map(|e| e.regions),
            Some(&["sun_next_event"][..])
        );
        assert_eq!(
            exercise_named("cosine").map(Exercise::name),
            Some("cosine".into())
        );
        assert_eq!(exercise_named("lobe"), None);
    }
}
