//! `--scene FILE`, live: the file is read again after every save (as
//! `raylab_cli::watch` does for the chapters); a save that is not a valid
//! scene shows its one-line error and keeps the last good scene.

use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use notify::{RecursiveMode, Watcher};

use crate::source::Loaded;
use crate::state::Explorer;

/// How long the file must stay quiet before it is read: editors often
/// save in several steps (truncate, write, rename).
const DEBOUNCE: Duration = Duration::from_millis(150);

/// A watch on one scene file.
pub struct SceneWatch {
    path: PathBuf,
    name: std::ffi::OsString,
    events: mpsc::Receiver<notify::Result<notify::Event>>,
    changed_at: Option<Instant>,
    // Kept alive for as long as the watch: dropping it ends the watch.
    _watcher: notify::RecommendedWatcher,
}

impl SceneWatch {
    /// Watch the folder, not the file: an editor that saves by renaming a
    /// new file over the old one (or a file deleted and made again) would
    /// end a watch on the file itself.
    pub fn new(path: &Path) -> Result<SceneWatch, String> {
        let name = path
            .file_name()
            .ok_or_else(|| format!("'{}' is not a file", path.display()))?
            .to_owned();
        let folder = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_owned(),
            _ => PathBuf::from("."),
        };
        let (tx, events) = mpsc::channel();
        let fail = |e: notify::Error| format!("cannot watch the scene file: {e}");
        let mut watcher = notify::recommended_watcher(move |event| {
            let _ = tx.send(event);
        })
        .map_err(fail)?;
        watcher
            .watch(&folder, RecursiveMode::NonRecursive)
            .map_err(fail)?;
        Ok(SceneWatch {
            path: path.to_owned(),
            name,
            events,
            changed_at: None,
            _watcher: watcher,
        })
    }

    /// Read the file again if it was saved (and has been quiet since);
    /// whether the explorer changed.
    pub fn poll(&mut self, explorer: &mut Explorer) -> bool {
        while let Ok(event) = self.events.try_recv() {
            if let Ok(event) = event
                && !event.kind.is_access()
                && event
                    .paths
                    .iter()
                    .any(|p| p.file_name() == Some(self.name.as_os_str()))
            {
                self.changed_at = Some(Instant::now());
            }
        }
        if self.changed_at.is_none_or(|t| t.elapsed() < DEBOUNCE) {
            return false;
        }
        self.changed_at = None;
        reload(explorer, &self.path);
        true
    }

    /// Whether a save is waiting out its debounce.
    pub fn pending(&self) -> bool {
        self.changed_at.is_some()
    }
}

/// Read `path` into the explorer, or show why not and keep the scene.
pub fn reload(explorer: &mut Explorer, path: &Path) {
    match Loaded::file(path) {
        Ok(loaded) => explorer.replace_scene(loaded),
        Err(error) => explorer.set_status(format!("{error}; keeping the last good scene")),
    }
}
