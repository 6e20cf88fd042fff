//! The core as exercises: the track beside chapters 1, 3 and 4, in which a
//! learner writes the tracer the chapters stand on (`src/`), from the point along
//! a ray to the ray stack.
//!
//! Each exercise is one or more regions of the real core, marked as the
//! chapters' steps are (`// ANCHOR: todo_NAME "task"` …
//! `// ANCHOR_END: todo_NAME`), judged first by the core's own unit tests
//! of those regions and then by a picture: a chapter rendered with the
//! learner's core (see [`crate::core_lab`]) against the reference.

/// One exercise of the core track.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CoreExercise {
    /// The name `start`, `check`, `watch` and `hint` take.
    pub name: &'static str,
    /// What it builds, for `list`.
    pub title: &'static str,
    /// The regions the learner writes, by their marker names.
    pub regions: &'static [&'static str],
    /// The core's files that hold them, from `src/`.
    pub files: &'static [&'static str],
    /// The core's unit tests that judge it: names or the start of names,
    /// as `cargo test` filters them.
    pub tests: &'static [&'static str],
    /// The chapter whose render, made with the learner's core, is compared
    /// with the reference: the first that needs every region.
    pub chapter: u8,
    /// `learn hint`'s first level: a nudge, what to think about.
    pub nudge: &'static str,
    /// Its second: the rule the code must follow.
    pub rule: &'static str,
    /// Its third: what to do, in a few lines (the recipe).
    pub hint: &'static str,
}

impl CoreExercise {
    /// The chapter whose "Do it yourself" teaches it: the first that needs
    /// it, which for the stack is chapter 3 (mirrors), though its check
    /// renders chapter 4, the first to send two rays from one hit.
    pub fn page(&self) -> &'static str {
        match self.name {
            "reflect" | "stack" => "book/src/ch03-reflection.md",
            "refract" => "book/src/ch04-refraction.md",
            _ => "book/src/ch01-ray-casting.md",
        }
    }
}

/// The core track, in the order the book takes it.
pub const CORE_EXERCISES: [CoreExercise; 9] = [
    CoreExercise {
        name: "ray",
        title: "the point along a ray",
        regions: &["ray_at"],
        files: &["ray.rs"],
        tests: &["ray::tests::"],
        chapter: 1,
        nudge: "A ray is a starting point and a direction: where is it after it has gone a distance t?",
        rule: "The point at distance t is the origin moved t times the (unit) direction.",
        hint: "A ray is a point that moves: at distance t it has gone t times its unit \
               direction from its origin. `Vec3` adds and scales as you would write it on paper.",
    },
    CoreExercise {
        name: "camera",
        title: "the camera's ray through a pixel",
        regions: &["camera_ray"],
        files: &["camera.rs"],
        tests: &["camera::tests::"],
        chapter: 1,
        nudge: "Each pixel's ray starts at the eye and passes through that pixel's point on an image plane one unit in front of the camera.",
        rule: "The plane reaches ±h up and down and ±h·a to the sides (h = `self.half_height`, a = width / height); row 0 is the top and column 0 the left; the direction is a unit vector.",
        hint: "The image plane is at distance 1 along `self.forward`; it is 2·h high and \
               2·h·a wide (h = `self.half_height`, a = width / height). Pixel column i + sx \
               maps to x from −h·a (left) to +h·a (right); row j + sy to y from +h (row 0, the \
               top) to −h (the bottom). The direction is forward + x·right + y·up, normalised \
               (`Ray::new` insists on unit directions); the ray starts at `self.eye`.",
    },
    CoreExercise {
        name: "sphere",
        title: "ray–sphere: both roots, the inside case",
        regions: &["sphere"],
        files: &["sphere.rs"],
        tests: &["sphere::tests::"],
        chapter: 1,
        nudge: "Put the ray's point o + t·d into the sphere's equation |p − c|² = R²: it becomes a quadratic in t.",
        rule: "The quadratic has up to two roots; the hit is the nearest one ahead of the ray (t > 0), which is the far one when the ray starts inside the sphere.",
        hint: "With oc = origin − centre, b = dot(oc, d) and q = dot(oc, oc) − R², the hits are \
               the roots of t² + 2bt + q = 0: t = −b ∓ √(b² − q). A negative b² − q means no \
               hit. Try the near root first; if it is not ahead of the ray (≤ 0) the ray starts \
               inside the sphere (the glass!) and the far root is the hit, if it is ahead.",
    },
    CoreExercise {
        name: "plane",
        title: "ray–plane and the checker",
        regions: &["plane", "checker"],
        files: &["plane.rs"],
        tests: &["plane::tests::"],
        chapter: 1,
        nudge: "A point p is on the plane when dot(p − p0, n) = 0; the checker's colour depends only on which unit square x and z fall in.",
        rule: "Solve dot(o + t·d − p0, n) = 0 for t: a ray parallel to the plane never meets it, and only t > 0 is ahead, from either side. A square's parity is that of floor(x) + floor(z): floors, not truncation.",
        hint: "Plane: with denom = dot(d, n), a ray with |denom| < 1e-8 runs parallel and never \
               meets it; else t = dot(p0 − o, n) / denom, a hit only when t > 0 (from either \
               side). Checker: s = floor(x) + floor(z) is a whole number; its parity picks the \
               colour. `as i32` truncates towards zero and would merge the squares either side \
               of 0: use `floor`, then `(s as i64) & 1`.",
    },
    CoreExercise {
        name: "sky",
        title: "the sky",
        regions: &["sky"],
        files: &["light.rs"],
        tests: &["light::tests::"],
        chapter: 1,
        nudge: "The sky's colour depends only on how high the direction looks.",
        rule: "Blend from the horizon colour to the zenith colour by the square root of the direction's height, held to [0, 1].",
        hint: "Only the direction's height d.y matters. Clamp it to [0, 1] (below the horizon the \
               sky stays the horizon colour), take its square root t, and blend: (1 − t) · \
               horizon + t · zenith.",
    },
    CoreExercise {
        name: "srgb",
        title: "sRGB encoding, halves rounded away from zero",
        regions: &["srgb_curve", "srgb_encode", "srgb_quantise"],
        files: &["srgb.rs"],
        tests: &["srgb::tests::"],
        chapter: 1,
        nudge: "A screen's levels are not linear in light: the light is encoded with the sRGB curve before it is rounded to a level 0 to 255.",
        rule: "The curve is linear near black and a 1/2.4 power above 0.0031308; a NaN is 0, values are clamped to [0, 1], and halves round away from zero.",
        hint: "Three small functions. `linear_to_srgb`: 12.92 · c up to 0.0031308, else 1.055 · \
               c^(1/2.4) − 0.055 (`powf`). `encode_channel`: a NaN becomes 0, then clamp to \
               [0, 1], encode, quantise. `quantise`: (255 · v).round() as u8; `f32::round` \
               rounds halves away from zero, as the lab model asks (`round_ties_even` would not).",
    },
    CoreExercise {
        name: "reflect",
        title: "reflect",
        regions: &["reflect"],
        files: &["optics.rs"],
        tests: &["optics::tests::reflecting_"],
        chapter: 3,
        nudge: "A mirror keeps the part of the direction along the surface and turns round the part along the normal.",
        rule: "With n a unit normal, the part of d along n is dot(d, n) · n; the rest is d minus that.",
        hint: "Split d into its part along n, dot(d, n) · n, and the rest. A mirror keeps the \
               rest and flips the part along n: d − 2 · dot(d, n) · n.",
    },
    CoreExercise {
        name: "refract",
        title: "refract, with total internal reflection",
        regions: &["refract"],
        files: &["optics.rs"],
        tests: &[
            "optics::tests::refracting_",
            "optics::tests::entering_glass",
            "optics::tests::leaving_glass",
        ],
        chapter: 4,
        nudge: "Snell's law, n₁ sin θ₁ = n₂ sin θ₂ with eta = n₁/n₂, gives the bent direction; past some angle it has no answer.",
        rule: "The refracted direction's cos² is k = 1 − eta² · (1 − cos² θᵢ): a negative k is total internal reflection, where no direction exists at all (`None`); otherwise the answer is a unit vector.",
        hint: "GLSL's refract: cos_i = dot(n, i) (negative, i points into the surface), \
               k = 1 − eta² · (1 − cos_i²) is cos² of the refracted angle. If k < 0 Snell's law \
               has no answer: return None (total internal reflection; the chapter sends the \
               light along the mirror instead). Else eta · i − (eta · cos_i + √k) · n.",
    },
    CoreExercise {
        name: "stack",
        title: "the ray stack: push, pop, weights, depth, the budget",
        regions: &["stack_push", "stack_pop", "trace"],
        files: &["stack.rs", "trace.rs"],
        tests: &["stack::tests::", "trace::tests::"],
        chapter: 4,
        nudge: "The tracer keeps the rays it still has to trace on a stack: the last one pushed is the next one traced.",
        rule: "Each ray's weight is its parent's weight times its share; a ray at max_depth sends nothing on, and nothing more is pushed once the ray budget is spent.",
        hint: "push: assert that len < STACK_CAPACITY, store at rays[len], count it. pop: None \
               when empty, else uncount and return rays[len]. trace: push the primary ray \
               (RayKind::Primary, weight 1, depth 1, no parent), then pop until empty; count each \
               ray (`self.count(&mut traced, &pending)`). No hit: \
               `self.add(&mut traced, &pending, None, weight · sky)`. A hit: \
               `self.surface.reset()`, local = `self.step.shade(…)`, add weight · kept · local, \
               count the feelers (`self.count_shadow_rays`); then, below max_depth and if any were sent, stop with \
               `over_budget` at RAY_BUDGET rays, else push each `self.surface.sent()` ray with \
               weight · share, depth + 1 and the parent `self.add` returned.",
    },
];

/// The core exercise called `name`, if there is one.
pub fn core_exercise(name: &str) -> Option<&'static CoreExercise> {
    CORE_EXERCISES.iter().find(|e| e.name == name)
}

/// The core exercise a region belongs to.
pub fn owner(region: &str) -> Option<&'static CoreExercise> {
    CORE_EXERCISES.iter().find(|e| e.regions.contains(&region))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::regions::region_names;

    fn core_source(file: &str) -> String {
        let path = format!("{}/../../src/{file}", env!("CARGO_MANIFEST_DIR"));
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
    }

    #[test]
    fn every_region_of_an_exercise_is_marked_in_its_files() {
        for exercise in &CORE_EXERCISES {
            let mut marked = Vec::new();
            for file in exercise.files {
                marked.extend(region_names(&core_source(file)).unwrap());
            }
            for region in exercise.regions {
                assert!(
                    marked.iter().any(|m| m == region),
                    "`{}`: no region `{region}` in {:?}",
                    exercise.name,
                    exercise.files
                );
            }
        }
    }

    #[test]
    fn every_region_marked_in_the_core_belongs_to_one_exercise() {
        let src = concat!(env!("CARGO_MANIFEST_DIR"), "/../../src");
        let files =
            crate::lab::rust_files(std::path::Path::new(src), std::path::Path::new("")).unwrap();
        for file in files {
            let name = file.to_string_lossy().into_owned();
            for region in region_names(&core_source(&name)).unwrap() {
                let owners = CORE_EXERCISES
                    .iter()
                    .filter(|e| e.regions.contains(&region.as_str()))
                    .count();
                assert_eq!(owners, 1, "region `{region}` of src/{name}");
                let exercise = owner(&region).unwrap();
                assert!(
                    exercise.files.contains(&name.as_str()),
                    "`{}` lists its files",
                    exercise.name
                );
            }
        }
    }

    #[test]
    fn every_hint_is_printed_without_runs_of_spaces() {
        for exercise in &CORE_EXERCISES {
            assert!(
                !exercise.hint.contains("  ") && !exercise.hint.contains('\n'),
                "{}",
                exercise.name
            );
        }
    }
}
