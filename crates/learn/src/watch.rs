//! `learn watch NAME`: check again after every save.
//!
//! File events come from the operating system (notify, as the chapters'
//! `--watch` uses). Some file systems never send them (network shares,
//! some containers and virtual machines), so the watch first makes sure
//! that one arrives, and otherwise looks at the files twice a second.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant, SystemTime};

use notify::{RecursiveMode, Watcher};

use crate::check::{Limits, Verdict, check, check_core};
use crate::lab::Lab;
use crate::path::Item;
use crate::shader_check::check_shader;

/// How long the files must stay quiet before the check: editors often
/// save in several steps (truncate, write, rename).
const DEBOUNCE: Duration = Duration::from_millis(100);
/// How often the files are looked at when no events arrive.
const POLL: Duration = Duration::from_millis(500);
/// How long to wait for the test event before falling back to polling.
const EVENT_PROBE: Duration = Duration::from_secs(2);
/// The file written once to see whether events arrive.
const PROBE_FILE: &str = ".learn-watch-probe";

/// Check, then check again after every save, until Ctrl-C.
pub fn watch(lab: &Lab, item: Item, out: &mut dyn Write) -> Result<(), String> {
    let (folder, check) = match item {
        Item::Core(core) => (
            lab.dir.join("core"),
            Box::new(move |out: &mut dyn Write| check_core(lab, core, Limits::DEFAULT, out))
                as Box<dyn Fn(&mut dyn Write) -> Verdict>,
        ),
        Item::Chapter(chapter) => (
            lab.folder(chapter),
            Box::new(move |out: &mut dyn Write| check(lab, chapter, out))
                as Box<dyn Fn(&mut dyn Write) -> Verdict>,
        ),
        // The shader is in my-lab/ch10/src/, as a chapter's sources are.
        Item::Shader => (
            lab.shader_folder(),
            Box::new(move |out: &mut dyn Write| check_shader(lab, Limits::DEFAULT, out))
                as Box<dyn Fn(&mut dyn Write) -> Verdict>,
        ),
    };
    let verdict = check(out);
    if verdict == Verdict::NoExercise {
        return Err("nothing to watch".into());
    }
    let stop = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&stop);
    let _ = ctrlc::set_handler(move || flag.store(true, Ordering::SeqCst));

    let (tx, rx) = mpsc::channel::<PathBuf>();
    let watcher = events(&folder, tx);
    let mut polling = watcher.is_none();
    if let Some(_watcher) = &watcher
        && !events_arrive(&folder, &rx)
    {
        polling = true;
    }
    if polling {
        let _ = writeln!(
            out,
            "watching {}/src by looking every {} ms: this file system sends no file events (Ctrl-C to stop)",
            folder.display(),
            POLL.as_millis()
        );
    } else {
        let _ = writeln!(
            out,
            "watching {}/src: save to check again (Ctrl-C to stop)",
            folder.display()
        );
    }
    let mut last_seen = fingerprint(&folder);
    let mut changed_at: Option<Instant> = None;
    while !stop.load(Ordering::SeqCst) {
        if polling {
            std::thread::sleep(POLL);
            let now = fingerprint(&folder);
            if now != last_seen {
                last_seen = now;
                changed_at = Some(Instant::now() - DEBOUNCE);
            }
        } else if let Ok(path) = rx.recv_timeout(Duration::from_millis(20))
            && is_source(&folder, &path)
        {
            changed_at = Some(Instant::now());
        }
        if changed_at.is_some_and(|t| t.elapsed() >= DEBOUNCE) {
            changed_at = None;
            let _ = writeln!(out, "\n— saved: checking again —");
            check(out);
            let _ = out.flush();
        }
    }
    let _ = writeln!(out, "stopped watching");
    drop(watcher);
    Ok(())
}

/// A watcher that sends the path of every changed file, if one can be made.
fn events(folder: &Path, tx: mpsc::Sender<PathBuf>) -> Option<notify::RecommendedWatcher> {
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
    watcher.watch(folder, RecursiveMode::Recursive).ok()?;
    Some(watcher)
}

/// Write and remove one file, and see whether its event comes back.
fn events_arrive(folder: &Path, rx: &mpsc::Receiver<PathBuf>) -> bool {
    let probe = folder.join(PROBE_FILE);
    if std::fs::write(&probe, b"learn watch: are file events delivered here?\n").is_err() {
        return false;
    }
    let start = Instant::now();
    let mut seen = false;
    while start.elapsed() < EVENT_PROBE {
        if let Ok(path) = rx.recv_timeout(Duration::from_millis(20))
            && path.file_name() == Some(PROBE_FILE.as_ref())
        {
            seen = true;
            break;
        }
    }
    let _ = std::fs::remove_file(&probe);
    // Let the removal's own events pass, then forget them.
    std::thread::sleep(Duration::from_millis(50));
    while rx.try_recv().is_ok() {}
    seen
}

/// Whether a changed path is the learner's source (not the check's images).
fn is_source(folder: &Path, path: &Path) -> bool {
    let Ok(inside) = path.strip_prefix(folder) else {
        // Some back ends report canonical paths.
        return folder
            .canonicalize()
            .ok()
            .is_some_and(|f| path.starts_with(f.join("src")) || path == f.join("Cargo.toml"));
    };
    inside.starts_with("src") || inside == Path::new("Cargo.toml")
}

/// The size and modification time of every source file, for polling.
fn fingerprint(folder: &Path) -> Vec<(PathBuf, u64, Option<SystemTime>)> {
    let mut files = Vec::new();
    let mut stack = vec![folder.join("src")];
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let Ok(meta) = entry.metadata() else { continue };
            if meta.is_dir() {
                stack.push(path);
            } else {
                files.push((path, meta.len(), meta.modified().ok()));
            }
        }
    }
    if let Ok(meta) = std::fs::metadata(folder.join("Cargo.toml")) {
        files.push((folder.join("Cargo.toml"), meta.len(), meta.modified().ok()));
    }
    files.sort();
    files
}
