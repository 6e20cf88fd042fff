//! Property tests: whatever text or numbers a scene file holds, nothing
//! panics, and a scene that is accepted renders without a NaN or infinite
//! pixel. `PROPTEST_CASES=10000 cargo test -p raylab-tests --test robustness`
//! runs them longer.

use std::path::Path;

use proptest::prelude::*;
use proptest::test_runner::FileFailurePersistence;
use raylab::NoProgress;
use raylab::{Keep, Sampling, Settings, render};
use raylab_cli::scene_file::parse;

/// Floats of every kind: ordinary, zero, tiny, huge, negative, NaN, infinite.
fn wild() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => -3.0f32..3.0,
        1 => Just(0.0f32),
        1 => 1e-30f32..1e-20,
        1 => 1e5f32..1e30,
        1 => -1e30f32..-1e5,
        1 => any::<f32>(),
        1 => prop_oneof![Just(f32::NAN), Just(f32::INFINITY), Just(f32::NEG_INFINITY)],
    ]
}

/// A float as TOML writes it.
fn toml(v: f32) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{v:?}")
    }
}

/// A coordinate: usually ordinary, sometimes wild.
fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![40 => -3.0f32..3.0, 1 => wild()]
}

fn vec3() -> impl Strategy<Value = String> {
    (coordinate(), coordinate(), coordinate())
        .prop_map(|(x, y, z)| format!("[{}, {}, {}]", toml(x), toml(y), toml(z)))
}

/// Colours and shares mostly in range, sometimes not.
fn unit() -> impl Strategy<Value = f32> {
    prop_oneof![40 => 0.0f32..1.0, 1 => wild()]
}

/// A share of the light for reflection or transmission: two of them
/// usually sum to at most 1.
fn share() -> impl Strategy<Value = f32> {
    prop_oneof![40 => 0.0f32..0.5, 1 => wild()]
}

fn colour() -> impl Strategy<Value = String> {
    (unit(), unit(), unit())
        .prop_map(|(r, g, b)| format!("[{}, {}, {}]", toml(r), toml(g), toml(b)))
}

/// A scene file with every table present and wild numbers in it.
fn wild_scene() -> impl Strategy<Value = String> {
    let camera = (
        vec3(),
        vec3(),
        vec3(),
        prop_oneof![20 => 10.0f32..120.0, 1 => wild()],
    );
    let sphere = (
        vec3(),
        prop_oneof![20 => 0.1f32..2.0, 1 => wild()],
        colour(),
        share(),
        share(),
        prop_oneof![20 => 1.0f32..2.5, 1 => wild()],
    );
    (camera, vec3(), prop_oneof![20 => 0.0f32..100.0, 1 => wild()], colour(), colour(), vec3(), vec3(), prop::collection::vec(sphere, 0..6)).prop_map(
        |((eye, target, up, fov), sun, brightness, horizon, zenith, point, normal, spheres)| {
            let mut text = format!(
                "[camera]\neye = {eye}\ntarget = {target}\nup = {up}\nfov = {}\n\
                 [sun]\ndirection = {sun}\nbrightness = {}\n\
                 [sky]\nhorizon = {horizon}\nzenith = {zenith}\n\
                 [ground]\npoint = {point}\nnormal = {normal}\neven = [0.75, 0.75, 0.75]\nodd = [0.25, 0.25, 0.25]\n",
                toml(fov),
                toml(brightness.abs()),
            );
            for (centre, radius, albedo, r, t, ior) in spheres {
                text += &format!(
                    "[[sphere]]\ncentre = {centre}\nradius = {}\nalbedo = {albedo}\nreflection = {}\ntransmission = {}\nior = {}\n",
                    toml(radius),
                    toml(r),
                    toml(t),
                    toml(ior)
                );
            }
            text
        },
    )
}

#[test]
fn most_wild_scenes_are_accepted_so_the_render_check_runs() {
    // Without this, a generator that produced only invalid scenes would
    // make the render property pass without rendering anything.
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let accepted = (0..400)
        .filter(|_| {
            let text = wild_scene().new_tree(&mut runner).unwrap().current();
            parse(&text, Path::new("wild.toml")).is_ok()
        })
        .count();
    assert!(
        accepted > 40 && accepted < 360,
        "{accepted} of 400 accepted"
    );
}

proptest! {
    // A failing case is kept beside this test (tests run in their package's
    // folder), in `tests/proptest-regressions/`, and tried first next time.
    #![proptest_config(ProptestConfig {
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(
            "proptest-regressions/robustness.txt",
        ))),
        ..ProptestConfig::default()
    })]

    #[test]
    fn any_text_is_parsed_or_refused_without_panicking(text in ".{0,400}") {
        let _ = parse(&text, Path::new("fuzz.toml"));
    }

    #[test]
    fn any_bytes_near_a_real_scene_are_parsed_or_refused(cut in 0usize..1200, insert in ".{0,8}") {
        // The lab scene, cut somewhere and with a few characters inserted.
        let lab = include_str!("../scenes/lab.toml");
        let at = lab.char_indices().map(|(i, _)| i).nth(cut % lab.chars().count()).unwrap_or(0);
        let text = format!("{}{insert}{}", &lab[..at], &lab[at..]);
        let _ = parse(&text, Path::new("fuzz.toml"));
    }

    #[test]
    fn a_wild_scene_is_refused_or_renders_without_nan(text in wild_scene()) {
        if let Ok((scene, camera)) = parse(&text, Path::new("wild.toml")) {
            for (max_depth, epsilon) in [(10, 1e-4), (6, 0.0)] {
                let settings = Settings { width: 8, height: 6, max_depth, epsilon, sampling: Sampling::LAB_FIVE };
                let rendered = render(&scene, &camera, &ch04_refraction::Refraction, &settings, Keep::ALL, &NoProgress);
                prop_assert_eq!(rendered.non_finite, 0, "a pixel was NaN or infinite: {}", text);
                prop_assert!(rendered.linear_image().is_finite());
            }
        }
    }
}
