//! `--scene FILE`, live: the file is read again after every save (as
//! `raylab_cli::watch` does for the chapters); a save that is not a valid
//! scene shows its one-line error and keeps the last good scene.

use std::path::{Path, PathBuf};
use std::time::Duration;

use raylab_cli::saves::{Saves, Watched};

use crate::error::ExploreError;
use crate::source::Loaded;
use crate::state::Explorer;

/// A watch on one scene file (the workbook's one file watch, which also
/// looks at the file where the file system sends no events).
pub struct SceneWatch {
    path: PathBuf,
    saves: Saves,
}

impl SceneWatch {
    pub fn new(path: &Path) -> Result<SceneWatch, ExploreError> {
        let saves =
            Saves::new(vec![Watched::File(path.to_owned())]).map_err(ExploreError::Watch)?;
        Ok(SceneWatch {
            path: path.to_owned(),
            saves,
        })
    }

    /// Read the file again if it was saved (and has been quiet since);
    /// whether the explorer changed. It does not wait: the window's
    /// event loop calls it between frames.
    pub fn poll(&mut self, explorer: &mut Explorer) -> bool {
        if self.saves.saved(Duration::ZERO).is_empty() {
            return false;
        }
        reload(explorer, &self.path);
        true
    }

    /// Whether a save is waiting out its debounce.
    pub fn pending(&self) -> bool {
        self.saves.pending()
    }
}

/// Read `path` into the explorer, or show why not and keep the scene.
pub fn reload(explorer: &mut Explorer, path: &Path) {
    match Loaded::file(path) {
        Ok(loaded) => explorer.replace_scene(loaded),
        Err(error) => explorer.set_status(format!("{error}; keeping the last good scene")),
    }
}
