//! Where the scene came from: the lab, or a scene file; its text, to find
//! the camera's target (the orbit's centre) and to write the scene again
//! with another camera when a frame is saved.

use std::path::{Path, PathBuf};

use raylab::{Camera, Scene, Vec3};
use raylab_cli::scene_file;

use crate::error::ExploreError;

/// The lab scene's file, exactly the lab model's.
pub const LAB_TOML: &str = include_str!("../../../scenes/lab.toml");

/// A scene and the text it was read from.
#[derive(Clone, Debug)]
pub struct Source {
    /// `None` for the lab scene.
    pub path: Option<PathBuf>,
    pub text: String,
}

/// What a scene source holds: the scene, its camera and its target.
pub struct Loaded {
    pub scene: Scene,
    pub camera: Camera,
    pub target: Vec3,
    pub source: Source,
}

impl Loaded {
    /// The lab scene and camera.
    pub fn lab() -> Loaded {
        Loaded {
            scene: Scene::lab(),
            camera: Camera::lab(),
            target: Vec3::new(0.0, 0.6, 0.0),
            source: Source {
                path: None,
                text: LAB_TOML.to_owned(),
            },
        }
    }

    /// Read a scene file; the error is one line for the learner.
    pub fn file(path: &Path) -> Result<Loaded, ExploreError> {
        let text = std::fs::read_to_string(path).map_err(|source| ExploreError::ReadScene {
            path: path.to_owned(),
            source,
        })?;
        let (scene, camera) = scene_file::parse(&text, path)?;
        let target = camera_target(&text).unwrap_or(camera.eye + camera.forward() * 4.0);
        Ok(Loaded {
            scene,
            camera,
            target,
            source: Source {
                path: Some(path.to_owned()),
                text,
            },
        })
    }
}

/// The `[camera] target` of a scene file's text.
fn camera_target(text: &str) -> Option<Vec3> {
    let table: toml::Table = text.parse().ok()?;
    let target = table.get("camera")?.get("target")?.as_array()?;
    let n = |i: usize| {
        target
            .get(i)
            .and_then(|v| v.as_float().or(v.as_integer().map(|i| i as f64)))
    };
    Some(Vec3::new(n(0)? as f32, n(1)? as f32, n(2)? as f32))
}

impl Source {
    /// The same scene with its `[camera]` replaced: the file a chapter
    /// reads to see what the explorer's camera sees. `f32` values written
    /// as `f64` read back to the same `f32`, so the camera is rebuilt to
    /// the bit.
    pub fn with_camera(&self, eye: Vec3, target: Vec3, fov: f32) -> Result<String, ExploreError> {
        let mut table: toml::Table = self
            .text
            .parse()
            .map_err(|e: toml::de::Error| ExploreError::Rewrite(e.to_string()))?;
        let vector = |v: Vec3| {
            toml::Value::Array(
                [v.x, v.y, v.z]
                    .iter()
                    .map(|&c| toml::Value::Float(f64::from(c)))
                    .collect(),
            )
        };
        let mut camera = toml::Table::new();
        camera.insert("eye".into(), vector(eye));
        camera.insert("target".into(), vector(target));
        camera.insert("up".into(), vector(Vec3::Y));
        camera.insert("fov".into(), toml::Value::Float(f64::from(fov)));
        table.insert("camera".into(), toml::Value::Table(camera));
        let header =
            "# Written by raylab-explore: the scene as it was, seen from the explorer's camera.\n";
        toml::to_string(&table)
            .map(|body| format!("{header}{body}"))
            .map_err(|e| ExploreError::Rewrite(e.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lab_file_holds_the_lab_target() {
        assert_eq!(camera_target(LAB_TOML), Some(Vec3::new(0.0, 0.6, 0.0)));
    }

    #[test]
    fn a_scene_written_with_a_camera_reads_back_that_camera_to_the_bit() {
        let lab = Loaded::lab();
        let (eye, target, fov) = (Vec3::new(1.1, 2.3, 3.7), Vec3::new(0.1, 0.2, 0.3), 37.3);
        let text = lab.source.with_camera(eye, target, fov).unwrap();
        let (scene, camera) = scene_file::parse(&text, Path::new("x.toml")).unwrap();
        assert_eq!(camera, Camera::look_at(eye, target, Vec3::Y, fov).unwrap());
        assert_eq!(scene.spheres().len(), lab.scene.spheres().len());
    }
}
