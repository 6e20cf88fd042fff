//! Scene files: the lab scene, or your own, in TOML.
//!
//! `scenes/lab.toml` is the lab scene of the lab model; `--scene FILE` renders any
//! other. Every number is checked when the file is read, and a file that
//! is not a valid scene gets one line that says where and why.

use std::io::Read;
use std::path::{Path, PathBuf};

use serde::Deserialize;

use raylab::Vec3;
use raylab::camera::Camera;
use raylab::light::{Sky, Sun};
use raylab::material::Material;
use raylab::plane::{Checker, Plane};
use raylab::scene::{Ground, Scene};
use raylab::sphere::Sphere;

/// The largest scene file read, in bytes.
pub const MAX_FILE_BYTES: u64 = 1024 * 1024;
/// The most spheres a scene may hold: each is tested by every ray.
pub const MAX_OBJECTS: usize = 10_000;
/// The largest coordinate or radius, in scene units: beyond it 32-bit
/// floats have too few digits left to tell neighbouring points apart.
pub const MAX_COORDINATE: f32 = 1e6;
/// The brightest sun or sky allowed: brighter light would overflow the
/// sums of a pixel's colour to infinity.
pub const MAX_RADIANCE: f32 = 1e6;

/// A scene file as written: the TOML tables, before any checking.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    /// How far shadow and secondary rays start from their surface; the
    /// lab's 1e-4 where the file does not say.
    epsilon: Option<f32>,
    camera: CameraSpec,
    sun: SunSpec,
    sky: SkySpec,
    ground: GroundSpec,
    #[serde(default)]
    sphere: Vec<SphereSpec>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraSpec {
    eye: [f32; 3],
    target: [f32; 3],
    up: [f32; 3],
    /// Vertical field of view, degrees.
    fov: f32,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SunSpec {
    direction: [f32; 3],
    brightness: f32,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SkySpec {
    horizon: [f32; 3],
    zenith: [f32; 3],
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct GroundSpec {
    point: [f32; 3],
    normal: [f32; 3],
    even: [f32; 3],
    odd: [f32; 3],
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SphereSpec {
    name: Option<String>,
    centre: [f32; 3],
    radius: f32,
    albedo: [f32; 3],
    #[serde(default)]
    reflection: f32,
    #[serde(default)]
    transmission: f32,
    #[serde(default = "air")]
    ior: f32,
}

fn air() -> f32 {
    1.0
}

/// Why a scene file was refused.
#[derive(Debug, thiserror::Error)]
pub enum SceneFileError {
    #[error("cannot read scene '{}': {source}", path.display())]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("scene '{}' is {bytes} bytes, more than the {MAX_FILE_BYTES} allowed", path.display())]
    TooLarge { path: PathBuf, bytes: u64 },
    #[error("{}:{line}:{column}: {message}", path.display())]
    Syntax {
        path: PathBuf,
        line: usize,
        column: usize,
        message: String,
    },
    /// A rule broken; the message names the object, e.g. "sphere 'glass': …".
    #[error("scene '{}': {message}", path.display())]
    Invalid { path: PathBuf, message: String },
    #[error("scene '{}' has {count} spheres, more than the {MAX_OBJECTS} allowed", path.display())]
    TooManyObjects { path: PathBuf, count: usize },
}

/// A scene file, read and checked.
#[derive(Clone, Debug)]
pub struct SceneDescription {
    pub scene: Scene,
    pub camera: Camera,
    /// The offset of shadow and secondary rays the file asks for, if any.
    pub epsilon: Option<f32>,
}

/// Read and check a scene file: the scene, and the camera that looks at it.
pub fn load(path: &Path) -> Result<(Scene, Camera), SceneFileError> {
    load_file(path).map(|d| (d.scene, d.camera))
}

/// Parse and check the text of a scene file; `path` is for messages only.
pub fn parse(text: &str, path: &Path) -> Result<(Scene, Camera), SceneFileError> {
    parse_file(text, path).map(|d| (d.scene, d.camera))
}

/// Read and check a scene file, with the offset it asks for.
pub fn load_file(path: &Path) -> Result<SceneDescription, SceneFileError> {
    let read_error = |source| SceneFileError::Read {
        path: path.to_owned(),
        source,
    };
    let file = std::fs::File::open(path).map_err(read_error)?;
    let mut text = String::new();
    // Read one byte past the limit, so that a larger file is seen to be one.
    file.take(MAX_FILE_BYTES + 1)
        .read_to_string(&mut text)
        .map_err(read_error)?;
    if text.len() as u64 > MAX_FILE_BYTES {
        let bytes = std::fs::metadata(path).map_or(text.len() as u64, |m| m.len());
        return Err(SceneFileError::TooLarge {
            path: path.to_owned(),
            bytes,
        });
    }
    parse_file(&text, path)
}

/// Parse and check the text of a scene file, with the offset it asks for.
pub fn parse_file(text: &str, path: &Path) -> Result<SceneDescription, SceneFileError> {
    let file: SceneFile = toml::from_str(text).map_err(|e| syntax_error(&e, text, path))?;
    if file.sphere.len() > MAX_OBJECTS {
        return Err(SceneFileError::TooManyObjects {
            path: path.to_owned(),
            count: file.sphere.len(),
        });
    }
    build(file).map_err(|message| SceneFileError::Invalid {
        path: path.to_owned(),
        message,
    })
}

/// Turn the checked-by-type file into a scene, checking every rule that
/// types cannot: finite numbers, directions that are not zero, materials
/// that do not create light. An error names the object, then the rule.
fn build(file: SceneFile) -> Result<SceneDescription, String> {
    let fail = |object: &str, rule: String| format!("{object}: {rule}");
    check_bounds(&file)?;
    if let Some(e) = file.epsilon
        && !(e.is_finite() && (0.0..=crate::limits::MAX_EPSILON).contains(&e))
    {
        return Err(format!(
            "epsilon is {e}, but it must be a number from 0 to {} (scene units)",
            crate::limits::MAX_EPSILON
        ));
    }
    let c = &file.camera;
    // A NaN or infinite eye or target fails here too: no view direction.
    let camera = Camera::look_at(c.eye.into(), c.target.into(), c.up.into(), c.fov)
        .map_err(|e| fail("camera", e.to_string()))?;

    let direction = unit("sun", "direction", file.sun.direction)?;
    let brightness = file.sun.brightness;
    if !(brightness.is_finite() && brightness >= 0.0) {
        return Err(fail(
            "sun",
            format!("brightness is {brightness}, but it must be a finite number of at least 0"),
        ));
    }
    for (key, colour) in [("horizon", file.sky.horizon), ("zenith", file.sky.zenith)] {
        if !colour.iter().all(|c| c.is_finite() && *c >= 0.0) {
            return Err(fail(
                "sky",
                format!("{key} {colour:?} must be finite and at least 0 in every channel"),
            ));
        }
    }
    let g = &file.ground;
    if !Vec3::from(g.point).is_finite() {
        return Err(fail("ground", "point must be finite".into()));
    }
    let ground = Ground {
        plane: Plane {
            point: g.point.into(),
            normal: unit("ground", "normal", g.normal)?,
        },
        checker: Checker {
            even: g.even.into(),
            odd: g.odd.into(),
        },
    };
    let sky = Sky {
        horizon: file.sky.horizon.into(),
        zenith: file.sky.zenith.into(),
    };
    let mut scene = Scene::new(
        ground,
        sky,
        Sun {
            direction,
            brightness,
        },
    )
    // The scene's own errors already name their object.
    .map_err(|e| e.to_string())?;

    for (n, s) in file.sphere.iter().enumerate() {
        let name = s
            .name
            .clone()
            .unwrap_or_else(|| format!("sphere {}", n + 1));
        let material = Material::new(s.albedo.into(), s.reflection, s.transmission, s.ior)
            .map_err(|e| fail(&format!("sphere '{name}'"), e.to_string()))?;
        let shape = Sphere {
            centre: s.centre.into(),
            radius: s.radius,
        };
        scene
            .add_sphere(&name, shape, material)
            .map_err(|e| e.to_string())?;
    }
    Ok(SceneDescription {
        scene,
        camera,
        epsilon: file.epsilon,
    })
}

/// Every coordinate and radius within [`MAX_COORDINATE`], every light
/// within [`MAX_RADIANCE`]. NaN passes here and is caught with its object.
fn check_bounds(file: &SceneFile) -> Result<(), String> {
    let too_far = |object: String, key: &str, values: &[f32]| {
        if values.iter().any(|v| v.abs() > MAX_COORDINATE) {
            Err(format!(
                "{object}: {key} {values:?} is beyond ±{MAX_COORDINATE}: keep scenes within a million units"
            ))
        } else {
            Ok(())
        }
    };
    let too_bright = |object: &str, key: &str, values: &[f32]| {
        if values.iter().any(|v| *v > MAX_RADIANCE) {
            Err(format!(
                "{object}: {key} {values:?} is brighter than the {MAX_RADIANCE} allowed"
            ))
        } else {
            Ok(())
        }
    };
    let c = &file.camera;
    too_far("camera".into(), "eye", &c.eye)?;
    too_far("camera".into(), "target", &c.target)?;
    too_far("ground".into(), "point", &file.ground.point)?;
    too_bright("sun", "brightness", &[file.sun.brightness])?;
    too_bright("sky", "horizon", &file.sky.horizon)?;
    too_bright("sky", "zenith", &file.sky.zenith)?;
    for (n, s) in file.sphere.iter().enumerate() {
        let name = || {
            format!(
                "sphere '{}'",
                s.name
                    .clone()
                    .unwrap_or_else(|| format!("sphere {}", n + 1))
            )
        };
        too_far(name(), "centre", &s.centre)?;
        too_far(name(), "radius", &[s.radius])?;
    }
    Ok(())
}

/// A direction from the file, normalised, or why it cannot be.
fn unit(object: &str, key: &str, v: [f32; 3]) -> Result<Vec3, String> {
    // `normalize`, as `Scene::lab` does, so that `lab.toml` gives the lab
    // scene to the last bit; the checks catch what it cannot normalise.
    let unit = Vec3::from(v).normalize();
    if unit.is_finite() && unit.is_normalized() {
        Ok(unit)
    } else {
        Err(format!(
            "{object}: {key} {v:?} must be finite and not zero: it is a direction"
        ))
    }
}

/// TOML's error as one line with its line and column; for an unknown key,
/// the nearest valid key.
fn syntax_error(error: &toml::de::Error, text: &str, path: &Path) -> SceneFileError {
    let (line, column) = error
        .span()
        .map_or((1, 1), |span| line_and_column(text, span.start));
    let message = error.message().trim().to_owned();
    let message = match unknown_key(&message) {
        Some((key, expected)) => match nearest(&key, &expected) {
            Some(near) => format!("unknown key `{key}`: did you mean `{near}`?"),
            None => format!(
                "unknown key `{key}`: expected one of {}",
                expected.join(", ")
            ),
        },
        None => message.lines().next().unwrap_or("invalid TOML").to_owned(),
    };
    SceneFileError::Syntax {
        path: path.to_owned(),
        line,
        column,
        message,
    }
}

fn line_and_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// serde's "unknown field `x`, expected one of `a`, `b`" as (x, [a, b]).
fn unknown_key(message: &str) -> Option<(String, Vec<String>)> {
    let rest = message.strip_prefix("unknown field `")?;
    let (key, rest) = rest.split_once('`')?;
    let expected = rest
        .split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_owned)
        .collect();
    Some((key.to_owned(), expected))
}

/// The valid key closest to a misspelt one, if any is close.
fn nearest(key: &str, expected: &[String]) -> Option<String> {
    expected
        .iter()
        .map(|e| (strsim::levenshtein(key, e), e))
        .filter(|(distance, e)| *distance <= (e.len() / 2).max(2))
        .min_by_key(|(distance, _)| *distance)
        .map(|(_, e)| e.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    const LAB: &str = include_str!("../../../scenes/lab.toml");

    fn error_of(text: &str) -> String {
        parse(text, Path::new("test.toml")).unwrap_err().to_string()
    }

    /// The lab scene with one line replaced.
    fn lab_with(from: &str, to: &str) -> String {
        assert!(LAB.contains(from), "{from}");
        LAB.replacen(from, to, 1)
    }

    #[test]
    fn lab_toml_is_the_lab_scene_exactly() {
        let (scene, camera) = parse(LAB, Path::new("scenes/lab.toml")).unwrap();
        assert_eq!(scene, Scene::lab());
        assert_eq!(camera, Camera::lab());
    }

    #[test]
    fn the_other_scenes_are_valid() {
        for text in [
            include_str!("../../../scenes/two-mirrors.toml"),
            include_str!("../../../scenes/water-and-glass.toml"),
            include_str!("../../../scenes/total-internal-reflection.toml"),
        ] {
            parse(text, Path::new("scene.toml")).unwrap();
        }
    }

    #[test]
    fn a_scene_file_may_set_its_epsilon_and_without_one_keeps_the_labs() {
        let path = Path::new("test.toml");
        assert_eq!(parse_file(LAB, path).unwrap().epsilon, None);
        let text = format!("epsilon = 2e-3\n{LAB}");
        assert_eq!(parse_file(&text, path).unwrap().epsilon, Some(2e-3));
        for bad in ["-1e-3", "0.5", "nan"] {
            let err = error_of(&format!("epsilon = {bad}\n{LAB}"));
            assert!(err.contains("epsilon is"), "{err}");
            assert!(err.contains("from 0 to 0.1"), "{err}");
        }
    }

    #[test]
    fn a_syntax_error_gives_its_line_and_column() {
        let err = error_of(&lab_with("radius = 0.5", "radius = 0.5.5"));
        assert!(err.starts_with("test.toml:28:"), "{err}");
    }

    #[test]
    fn an_unknown_key_names_the_nearest_valid_one() {
        let err = error_of(&lab_with("radius = 0.5", "radus = 0.5"));
        assert!(
            err.contains("unknown key `radus`: did you mean `radius`?"),
            "{err}"
        );
        assert!(err.starts_with("test.toml:28:"), "{err}");
        let err = error_of(&lab_with("[sun]", "[sunn]"));
        assert!(err.contains("`sunn`: did you mean `sun`?"), "{err}");
    }

    #[test]
    fn a_missing_key_is_named() {
        let err = error_of(&lab_with("fov = 45.0", ""));
        assert!(err.contains("missing field `fov`"), "{err}");
    }

    #[test]
    fn reflection_plus_transmission_above_one_names_the_sphere() {
        let err = error_of(&lab_with("reflection = 0.1", "reflection = 0.5"));
        assert!(
            err.contains("sphere 'glass': reflection + transmission is 0.5 + 0.7"),
            "{err}"
        );
    }

    #[test]
    fn a_radius_of_zero_or_less_names_the_sphere() {
        for radius in ["0.0", "-1.0"] {
            let err = error_of(&lab_with("radius = 0.25", &format!("radius = {radius}")));
            assert!(err.contains("sphere 'blue': radius is"), "{err}");
        }
    }

    #[test]
    fn a_transmitting_material_with_ior_below_one_is_refused() {
        let err = error_of(&lab_with("ior = 1.5", "ior = 0.8"));
        assert!(err.contains("sphere 'glass': ior is 0.8"), "{err}");
    }

    #[test]
    fn nan_and_infinite_numbers_are_refused() {
        let err = error_of(&lab_with(
            "centre = [0.0, 1.0, -1.5]",
            "centre = [nan, 1.0, -1.5]",
        ));
        assert!(
            err.contains("sphere 'red'") && err.contains("finite"),
            "{err}"
        );
        let err = error_of(&lab_with(
            "albedo = [0.9, 0.75, 0.2]",
            "albedo = [inf, 0.75, 0.2]",
        ));
        assert!(
            err.contains("sphere 'yellow'") && err.contains("finite"),
            "{err}"
        );
        let err = error_of(&lab_with("brightness = 25.0", "brightness = nan"));
        assert!(err.contains("sun: brightness is NaN"), "{err}");
    }

    #[test]
    fn a_camera_without_a_view_direction_is_refused() {
        let err = error_of(&lab_with(
            "target = [0.0, 0.6, 0.0]",
            "target = [0.0, 1.2, 4.5]",
        ));
        assert!(
            err.contains("camera: the camera's eye and target must be different"),
            "{err}"
        );
    }

    #[test]
    fn up_parallel_to_the_view_is_refused() {
        let err = error_of(&lab_with("up = [0.0, 1.0, 0.0]", "up = [0.0, -0.6, -4.5]"));
        assert!(err.contains("not parallel to the view direction"), "{err}");
    }

    #[test]
    fn a_field_of_view_outside_0_to_180_is_refused() {
        for fov in ["0.0", "180.0", "-10.0"] {
            let err = error_of(&lab_with("fov = 45.0", &format!("fov = {fov}")));
            assert!(err.contains("must be between 0° and 180°"), "{err}");
        }
    }

    #[test]
    fn a_zero_sun_direction_is_refused() {
        let err = error_of(&lab_with(
            "direction = [-1.0, 1.2, 0.8]",
            "direction = [0.0, 0.0, 0.0]",
        ));
        assert!(
            err.contains("sun: direction [0.0, 0.0, 0.0] must be finite and not zero"),
            "{err}"
        );
    }

    #[test]
    fn more_than_ten_thousand_spheres_are_refused() {
        let sphere =
            "\n[[sphere]]\ncentre = [0.0, 1.0, 0.0]\nradius = 1.0\nalbedo = [0.5, 0.5, 0.5]\n";
        let text = format!("{LAB}{}", sphere.repeat(MAX_OBJECTS));
        let err = error_of(&text);
        assert!(
            err.contains("has 10005 spheres, more than the 10000 allowed"),
            "{err}"
        );
    }

    #[test]
    fn a_file_over_one_mebibyte_is_refused_unread() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("huge.toml");
        std::fs::write(
            &path,
            format!("{LAB}\n# {}\n", "x".repeat(MAX_FILE_BYTES as usize)),
        )
        .unwrap();
        let err = load(&path).unwrap_err().to_string();
        assert!(err.contains("more than the 1048576 allowed"), "{err}");
        let err = load(&dir.path().join("missing.toml"))
            .unwrap_err()
            .to_string();
        assert!(err.starts_with("cannot read scene"), "{err}");
    }

    #[test]
    fn coordinates_and_lights_beyond_a_million_are_refused() {
        let err = error_of(&lab_with("radius = 1.0", "radius = 1e7"));
        assert!(
            err.contains("sphere 'red': radius [10000000.0] is beyond ±1000000"),
            "{err}"
        );
        let err = error_of(&lab_with("brightness = 25.0", "brightness = 1e30"));
        assert!(
            err.contains("sun: brightness") && err.contains("brighter than"),
            "{err}"
        );
    }

    #[test]
    fn a_ground_colour_above_one_names_the_ground_once() {
        let err = error_of(&lab_with(
            "even = [0.75, 0.75, 0.75]",
            "even = [1.5, 0.75, 0.75]",
        ));
        assert!(
            err.contains("scene 'test.toml': ground: albedo 1.5"),
            "{err}"
        );
        assert!(!err.contains("ground: ground"), "{err}");
    }

    #[test]
    fn an_unnamed_sphere_is_named_by_its_place() {
        let text = format!(
            "{LAB}\n[[sphere]]\ncentre = [0.0, 1.0, 0.0]\nradius = -2.0\nalbedo = [0.5, 0.5, 0.5]\n"
        );
        let err = error_of(&text);
        assert!(err.contains("sphere 'sphere 6': radius is -2"), "{err}");
    }
}
