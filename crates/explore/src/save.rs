//! `w`: the frame as a PNG, and the chapter command that makes it again.

use std::path::{Path, PathBuf};

use raylab_cli::output::{save_png, save_text};

use crate::error::ExploreError;
use crate::state::Explorer;

/// What a save wrote and how to make it again.
#[derive(Clone, Debug, PartialEq)]
pub struct Saved {
    pub png: PathBuf,
    /// The scene file written beside it, unless this is the lab scene
    /// from the lab camera.
    pub scene: Option<PathBuf>,
    pub command: String,
}

/// Write the current frame (the scene only, no overlay) into `dir` as
/// `explore-NNN.png`, refined first if it is a Whitted preview, and, when
/// the camera has moved or the scene is a file's, the scene (seen from the
/// explorer's camera) as `explore-NNN.toml`.
pub fn save(explorer: &mut Explorer, dir: &Path) -> Result<Saved, ExploreError> {
    if !explorer.knobs.paths {
        // A still frame is the chapter's render; a preview is not.
        explorer.settle(1);
    }
    std::fs::create_dir_all(dir).map_err(|source| ExploreError::Folder {
        path: dir.to_owned(),
        source,
    })?;
    let name = (1..10_000)
        .map(|n| format!("explore-{n:03}"))
        .find(|n| !dir.join(format!("{n}.png")).exists())
        .ok_or(ExploreError::SavesFull)?;
    let png = dir.join(format!("{name}.png"));
    save_png(explorer.image(), &png)?;
    // The scene goes beside the image whenever it is not the lab's: a
    // scene file may change after the save, and the command must not.
    let text = match explorer.view.orbit() {
        Some(orbit) => Some(
            explorer
                .source()
                .with_camera(orbit.eye(), orbit.target, orbit.fov)?,
        ),
        None => explorer
            .source()
            .path
            .as_ref()
            .map(|_| explorer.source().text.clone()),
    };
    let scene = match text {
        Some(text) => {
            let path = dir.join(format!("{name}.toml"));
            save_text(&text, &path)?;
            Some(path)
        }
        None => None,
    };
    let scene_flag = scene
        .as_deref()
        .map(|p| format!(" --scene {}", p.display()))
        .unwrap_or_default();
    let command = command(explorer, &scene_flag, &png);
    Ok(Saved {
        png,
        scene,
        command,
    })
}

/// The chapter's command line for the same picture.
fn command(explorer: &Explorer, scene_flag: &str, png: &Path) -> String {
    let knobs = &explorer.knobs;
    let (width, height) = explorer.size();
    let out = png.with_extension("");
    let common = format!(
        "--width {width} --height {height} --max-depth {} --epsilon {}{scene_flag} --no-diagrams --out {}",
        knobs.max_depth,
        knobs.epsilon,
        out.display()
    );
    if knobs.paths {
        let (passes, _) = explorer.samples();
        let sun = knobs
            .sun_size
            .map(|d| format!(" --sun-size {d}"))
            .unwrap_or_default();
        format!(
            "cargo run --release -p {} -- --spp {passes} --pattern random --materials {}{sun} {common}   \
             # the same light from {passes} paths per pixel; the explorer's passes are seeded one by one, so not these bytes",
            knobs.binary(),
            knobs.materials.name()
        )
    } else {
        format!(
            "cargo run --release -p {} -- --spp {} {common}   # the same bytes",
            knobs.binary(),
            knobs.spp
        )
    }
}
