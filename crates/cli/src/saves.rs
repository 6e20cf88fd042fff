//! Knowing when a file was saved: the one file watch of the workbook,
//! used by every `--watch` (the chapters', chapter 10's), `learn watch`
//! and the explorer.
//!
//! File events come from the operating system (notify). Some file systems
//! never send them (network shares, some containers and virtual machines),
//! so the files are also looked at twice a second: a save is seen either
//! way, at once where events arrive. Editors often save in several steps
//! (truncate, write, rename), so a save counts once the file has been
//! quiet for a moment.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock, mpsc};
use std::time::{Duration, Instant, SystemTime};

use notify::{RecursiveMode, Watcher};

/// How long the files must stay quiet before a save counts.
pub const DEBOUNCE: Duration = Duration::from_millis(150);
/// How often the files are looked at, for saves no event reports.
pub const POLL: Duration = Duration::from_millis(500);
/// Set to `off` to ignore file events and rely on looking alone, as on a
/// file system that sends none (the tests use it).
pub const EVENTS_VAR: &str = "RAYLAB_FILE_EVENTS";

/// What to watch: one file, or every file below a folder.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Watched {
    File(PathBuf),
    Tree(PathBuf),
}

impl Watched {
    /// The folder the operating system is asked to watch: a file's own
    /// folder, so that an editor that saves by renaming a new file over
    /// the old one does not end the watch.
    fn folder(&self) -> PathBuf {
        match self {
            Watched::Tree(folder) => folder.clone(),
            Watched::File(file) => match file.parent() {
                Some(p) if !p.as_os_str().is_empty() => p.to_owned(),
                _ => PathBuf::from("."),
            },
        }
    }

    /// Whether a path an event names is (inside) this.
    fn covers(&self, path: &Path) -> bool {
        let canonical = |p: &Path| p.canonicalize().unwrap_or_else(|_| p.to_owned());
        match self {
            Watched::Tree(folder) => {
                path.starts_with(folder) || path.starts_with(canonical(folder))
            }
            // Some back ends report canonical paths, and a file renamed
            // over may not exist any more: compare names, then folders.
            Watched::File(file) => {
                path.file_name() == file.file_name()
                    && path
                        .parent()
                        .is_some_and(|p| canonical(p) == canonical(&self.folder()))
            }
        }
    }

    /// The size and modification time of every file, to compare.
    fn fingerprint(&self) -> Vec<(PathBuf, u64, Option<SystemTime>)> {
        let mut files = Vec::new();
        let mut stack = vec![match self {
            Watched::File(file) => file.clone(),
            Watched::Tree(folder) => folder.clone(),
        }];
        while let Some(path) = stack.pop() {
            let Ok(meta) = std::fs::metadata(&path) else {
                continue;
            };
            if meta.is_dir() {
                if let Ok(entries) = std::fs::read_dir(&path) {
                    stack.extend(entries.flatten().map(|e| e.path()));
                }
            } else {
                files.push((path, meta.len(), meta.modified().ok()));
            }
        }
        files.sort();
        files
    }
}

/// A watch on some files: [`Saves::saved`] says which were saved.
pub struct Saves {
    watched: Vec<Watched>,
    events: mpsc::Receiver<PathBuf>,
    // Kept for as long as the watch: dropping it ends the events.
    _watcher: Option<notify::RecommendedWatcher>,
    seen: Vec<Vec<(PathBuf, u64, Option<SystemTime>)>>,
    changed_at: Vec<Option<Instant>>,
    looked_at: Instant,
}

impl Saves {
    /// Watch these files and folders. Without file events it still works,
    /// by looking; an error only when there is nothing to watch.
    pub fn new(watched: Vec<Watched>) -> Result<Saves, String> {
        if let Some(missing) = watched.iter().find(|w| !w.folder().is_dir()) {
            return Err(format!("no folder '{}'", missing.folder().display()));
        }
        let (tx, events) = mpsc::channel();
        let off = std::env::var_os(EVENTS_VAR).is_some_and(|v| v == "off");
        let watcher = if off { None } else { events_of(&watched, tx) };
        Ok(Saves {
            seen: watched.iter().map(Watched::fingerprint).collect(),
            changed_at: vec![None; watched.len()],
            watched,
            events,
            _watcher: watcher,
            looked_at: Instant::now(),
        })
    }

    /// Wait up to `wait` for news, then the indices (into what was
    /// watched) of the files saved and quiet since; empty if none.
    pub fn saved(&mut self, wait: Duration) -> Vec<usize> {
        match self.events.recv_timeout(wait) {
            Ok(path) => {
                self.note(&path);
                while let Ok(path) = self.events.try_recv() {
                    self.note(&path);
                }
            }
            Err(mpsc::RecvTimeoutError::Timeout) => {}
            // No watcher (file events off, or none to be had): looking alone.
            Err(mpsc::RecvTimeoutError::Disconnected) => std::thread::sleep(wait),
        }
        if self.looked_at.elapsed() >= POLL {
            self.looked_at = Instant::now();
            for (i, watched) in self.watched.iter().enumerate() {
                // Only what no event reported: a save seen by both counts once.
                if self.changed_at[i].is_none() && watched.fingerprint() != self.seen[i] {
                    self.changed_at[i] = Some(Instant::now() - DEBOUNCE);
                }
            }
        }
        let mut saved = Vec::new();
        for i in 0..self.watched.len() {
            if self.changed_at[i].is_some_and(|t| t.elapsed() >= DEBOUNCE) {
                self.changed_at[i] = None;
                self.seen[i] = self.watched[i].fingerprint();
                saved.push(i);
            }
        }
        saved
    }

    /// Whether a save is waiting out its quiet moment.
    pub fn pending(&self) -> bool {
        self.changed_at.iter().any(Option::is_some)
    }

    fn note(&mut self, path: &Path) {
        for (i, watched) in self.watched.iter().enumerate() {
            if watched.covers(path) {
                self.changed_at[i] = Some(Instant::now());
            }
        }
    }
}

/// A watcher that sends the path of every changed file, if one can be made.
fn events_of(watched: &[Watched], tx: mpsc::Sender<PathBuf>) -> Option<notify::RecommendedWatcher> {
    let mut watcher = notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
        if let Ok(event) = event
            && !event.kind.is_access()
        {
            for path in event.paths {
                let _ = tx.send(path);
            }
        }
    })
    .ok()?;
    let mut folders: Vec<(PathBuf, RecursiveMode)> = watched
        .iter()
        .map(|w| match w {
            Watched::File(_) => (w.folder(), RecursiveMode::NonRecursive),
            Watched::Tree(folder) => (folder.clone(), RecursiveMode::Recursive),
        })
        .collect();
    folders.sort_by(|a, b| a.0.cmp(&b.0));
    folders.dedup_by(|a, b| a.0 == b.0);
    for (folder, mode) in folders {
        watcher.watch(&folder, mode).ok()?;
    }
    Some(watcher)
}

/// The one Ctrl-C flag of the process: set once Ctrl-C is pressed. A
/// watch loop stops between renders; files are written atomically, so
/// even a Ctrl-C during a render leaves no half-written file.
pub fn ctrl_c() -> Arc<AtomicBool> {
    static FLAG: OnceLock<Arc<AtomicBool>> = OnceLock::new();
    Arc::clone(FLAG.get_or_init(|| {
        let flag = Arc::new(AtomicBool::new(false));
        let set = Arc::clone(&flag);
        let _ = ctrlc::set_handler(move || set.store(true, Ordering::SeqCst));
        flag
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wait_for_save(saves: &mut Saves) -> Vec<usize> {
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(5) {
            let saved = saves.saved(Duration::from_millis(20));
            if !saved.is_empty() {
                return saved;
            }
        }
        Vec::new()
    }

    #[test]
    fn a_save_is_seen_once_and_names_the_file_saved() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.toml"), dir.path().join("b.toml"));
        std::fs::write(&a, "one").unwrap();
        std::fs::write(&b, "one").unwrap();
        let mut saves = Saves::new(vec![Watched::File(a.clone()), Watched::File(b)]).unwrap();
        std::fs::write(&a, "two, longer").unwrap();
        assert_eq!(wait_for_save(&mut saves), [0]);
        // Looked at again after the event: the same save is not counted twice.
        std::thread::sleep(POLL + DEBOUNCE);
        assert!(saves.saved(Duration::from_millis(20)).is_empty());
        assert!(!saves.pending());
    }

    #[test]
    fn a_file_saved_below_a_watched_folder_is_a_save_of_that_folder() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir(dir.path().join("src")).unwrap();
        let mut saves = Saves::new(vec![Watched::Tree(dir.path().join("src"))]).unwrap();
        std::fs::write(dir.path().join("src/lib.rs"), "fn main() {}").unwrap();
        assert_eq!(wait_for_save(&mut saves), [0]);
    }

    #[test]
    fn nothing_saved_is_nothing_seen() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.toml");
        std::fs::write(&file, "one").unwrap();
        let mut saves = Saves::new(vec![Watched::File(file)]).unwrap();
        std::thread::sleep(POLL);
        assert!(saves.saved(Duration::from_millis(200)).is_empty());
    }

    #[test]
    fn a_folder_that_is_not_there_cannot_be_watched() {
        let err = Saves::new(vec![Watched::File("no/such/folder/a.toml".into())])
            .err()
            .expect("an error");
        assert!(err.contains("no folder"), "{err}");
    }
}
