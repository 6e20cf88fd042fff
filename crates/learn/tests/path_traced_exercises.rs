//! The author checks of chapter 6's exercises, whose picture is judged
//! within its noise: a correct answer that draws other random numbers than
//! the reference (the lobes in another order, another cosine sampler, two
//! numbers for a point sun) passes; a wrong one fails at its tests, with a
//! test that names it, and at its picture too, when the picture is judged
//! alone.
//!
//! They build in the author lab that `exercises.rs` uses (see there), so
//! each of them is an incremental build of an exercise compiled once.

use std::path::Path;
use std::sync::Mutex;
use std::time::Duration;

use learn::exercise::{Exercise, exercise_named};
use learn::lab::Lab;
use learn_check::check::{Limits, Verdict, check_picture_with, check_with};

mod author;
use author::author_lab;

static LOCK: Mutex<()> = Mutex::new(());

const SHORT: Limits = Limits {
    tests: Duration::from_secs(10),
    render: Duration::from_secs(20),
};

/// The exercise `name` laid afresh with `body` written where its `todo!`
/// is: the learner's answer.
fn answer(lab: &Lab, name: &str, body: &str) -> &'static Exercise {
    let exercise = exercise_named(name).unwrap();
    let folder = lab.folder(exercise);
    if folder.exists() {
        std::fs::remove_dir_all(&folder).unwrap();
    }
    lab.start(exercise, false).unwrap();
    let step = folder.join(exercise.step);
    let text = std::fs::read_to_string(&step).unwrap();
    let todo = text.find("todo!(").expect("the stub has its todo!");
    let line_start = text[..todo].rfind('\n').map_or(0, |i| i + 1);
    let line_end = todo + text[todo..].find('\n').unwrap() + 1;
    let answered = format!("{}{body}{}", &text[..line_start], &text[line_end..]);
    assert!(!answered.contains("todo!("), "one region to write");
    std::fs::write(&step, answered).unwrap();
    exercise
}

fn check(lab: &Lab, exercise: &Exercise) -> (Verdict, String) {
    let mut out = Vec::new();
    let verdict = check_with(lab, exercise, SHORT, &mut out);
    (verdict, String::from_utf8_lossy(&out).into_owned())
}

fn check_picture(lab: &Lab, exercise: &Exercise) -> (Verdict, String) {
    let mut out = Vec::new();
    let verdict = check_picture_with(lab, exercise, SHORT, &mut out);
    (verdict, String::from_utf8_lossy(&out).into_owned())
}

/// A wrong answer: its tests fail, `test` among them, and its picture,
/// judged alone, is further from the reference than the noise allows.
fn assert_caught(lab: &Lab, exercise: &Exercise, test: &str) {
    let (verdict, text) = check(lab, exercise);
    assert!(
        matches!(verdict, Verdict::TestsFail { failed, .. } if failed > 0),
        "{verdict:?}:\n{text}"
    );
    assert!(text.contains(&format!("✗ {test}")), "{text}");
    let (verdict, text) = check_picture(lab, exercise);
    println!("{exercise}, the picture alone: {verdict:?}");
    assert!(
        matches!(&verdict, Verdict::NoisyDiffers(a) if !a.passes()),
        "{verdict:?}:\n{text}"
    );
    assert!(text.contains("worst pixel ("), "{text}");
    assert!(text.contains("standard errors off"), "{text}");
    let dir = lab.folder(exercise).join("check");
    for name in ["learner.png", "reference.png", "z-map.png"] {
        assert!(dir.join(name).is_file(), "{name}");
    }
}

fn assert_passes(lab: &Lab, exercise: &Exercise) {
    let (verdict, text) = check(lab, exercise);
    println!("{text}");
    assert_eq!(verdict, Verdict::Passed, "{text}");
    assert!(text.contains("within the two renders' own noise"), "{text}");
    assert!(!text.contains("Likely mistake"), "{text}");
}

/// Chapter 6's lobe choice with the shares of `(mirror, refraction)` cut
/// from [0, 1) in the order `order` gives.
fn lobes(shares: &str, order: &str) -> String {
    format!(
        "        let (r, t) = (hit.material.reflection(), hit.material.transmission());
        if r + t <= 0.0 {{
            return Lobe::Diffuse;
        }}
        let (mirror, refraction) = match self.materials {{
            Materials::Fresnel if t > 0.0 => {{
                let s = r + t;
                let f = fresnel(d.dot(hit.facing_normal), eta(hit));
                (s * f, s * (1.0 - f))
            }}
            _ => {shares},
        }};
        let diffuse = 1.0 - mirror - refraction;
{order}"
    )
}

const DIFFUSE_FIRST: &str = "        if u < diffuse {
            Lobe::Diffuse
        } else if u < diffuse + refraction {
            Lobe::Refraction
        } else {
            Lobe::Mirror
        }
";

#[test]
fn any_correct_order_of_the_lobes_passes_chapter_6s_check() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = answer(&lab, "6", &lobes("(r, t)", DIFFUSE_FIRST));
    assert_passes(&lab, exercise);
}

#[test]
fn a_choice_of_lobe_with_the_mirror_and_refraction_shares_swapped_is_caught() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = answer(&lab, "6", &lobes("(t, r)", DIFFUSE_FIRST));
    assert_caught(&lab, exercise, "each lobe is chosen as often as its share");
}

/// A cosine sampler from two numbers, with `cos θ` as `cos_theta` makes it
/// from `u1`.
fn cosine_sampler(cos_theta: &str) -> String {
    format!(
        "    let (u1, u2) = (random.uniform(), random.uniform());
    let z: f32 = {cos_theta};
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (sin_phi, cos_phi) = (2.0 * std::f32::consts::PI * u2).sin_cos();
    let (t, b) = n.any_orthonormal_pair();
    (r * cos_phi * t + r * sin_phi * b + z * n).normalize()
"
    )
}

#[test]
fn a_cosine_sampler_that_inverts_the_density_directly_passes() {
    // P(cos θ ≤ c) = c² under cos θ/π: cos θ = √u, not Malley's disc.
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = answer(&lab, "cosine", &cosine_sampler("u1.sqrt()"));
    assert_passes(&lab, exercise);
}

#[test]
fn a_uniform_hemisphere_sampler_without_its_weight_is_caught() {
    // cos θ uniform: directions uniform on the hemisphere, density 1/2π,
    // which the path would have to weigh by 2 cos θ, and does not.
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = answer(&lab, "cosine", &cosine_sampler("u1"));
    assert_caught(
        &lab,
        exercise,
        "cosine directions have the mean cosine of two thirds",
    );
}

/// Next-event estimation with the sun's direction drawn by `to_sun` and
/// the shadow ray started at `origin`.
fn next_event(to_sun: &str, origin: &str) -> String {
    format!(
        "        let to_sun = {to_sun};
        let cos = hit.facing_normal.dot(to_sun);
        if cos > 0.0 {{
            *rays += 1;
            let shadow = Ray::new({origin}, to_sun);
            if !self.objects.any_hit(&shadow) {{
                return hit.material.albedo() * FRAC_1_PI * self.sun.irradiance * cos;
            }}
        }}
        Vec3::ZERO
"
    )
}

#[test]
fn next_event_estimation_that_draws_two_numbers_even_for_a_point_sun_passes() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let body = next_event(
        "self.sun.sample(random.uniform(), random.uniform())",
        "hit.point + to_sun * self.epsilon",
    );
    let exercise = answer(&lab, "nee", &body);
    assert_passes(&lab, exercise);
}

#[test]
fn a_shadow_ray_to_the_sun_started_on_the_surface_is_caught() {
    let _turn = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let lab = author_lab();
    let exercise = answer(
        &lab,
        "nee",
        &next_event("self.sun.draw(random)", "hit.point"),
    );
    assert_caught(
        &lab,
        exercise,
        "the shadow ray starts off the surface so a point rounded below the ground is still lit",
    );
}

#[test]
fn each_of_chapter_6s_exercises_blanks_only_its_own_region() {
    let dir = tempfile::tempdir().unwrap();
    let lab = Lab {
        dir: dir.path().to_owned(),
        ..author_lab()
    };
    for (name, function) in [
        ("6", "pub fn choose_lobe("),
        ("cosine", "pub fn cosine_direction("),
        ("nee", "pub fn sun_next_event("),
    ] {
        let exercise = exercise_named(name).unwrap();
        let files = lab.files(exercise, false).unwrap();
        let step = &files
            .iter()
            .find(|(p, _)| p == Path::new(exercise.step))
            .unwrap()
            .1;
        assert_eq!(step.matches("todo!(").count(), 1, "`{name}`");
        let todo = step.find("todo!(").unwrap();
        let owner = step[..todo].rfind("pub fn ").unwrap();
        assert!(
            step[owner..].starts_with(function),
            "`{name}` blanks {function}"
        );
        for (path, text) in &files {
            assert!(
                !text.contains("ANCHOR: todo_"),
                "`{name}`: {}",
                path.display()
            );
        }
    }
}
