//! The learner's lab: `my-lab/chNN/`, one small crate per exercise, and
//! the progress file.
//!
//! Each exercise is a copy of its chapter's crate with the step blanked,
//! and is its own workspace: its `Cargo.toml` depends on the finished core
//! and earlier chapters by path, so chapter 3's exercise stands on the
//! reference chapters 1 and 2. All exercises build into the workspace's
//! own target folder (`target/`), so the libraries the workspace has
//! compiled already (image, rayon, clap …) are used as they are, the core
//! is compiled for the exercises once, and each check recompiles only the
//! learner's few lines.

use std::collections::{BTreeMap, BTreeSet};
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::exercise::{Exercise, blank_only};

/// Where a lab lives: the workspace it builds against, the learner's
/// folder, and the target folder the exercises share.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lab {
    /// The raylab workspace's root (the folder with its `Cargo.toml`).
    pub root: PathBuf,
    /// The learner's folder, `my-lab/` by default.
    pub dir: PathBuf,
    /// The target folder every exercise builds into.
    pub target: PathBuf,
    /// The exercises' package version. Cargo tells two builds of a package
    /// apart by its name and version, not by its folder: two labs that
    /// build into one target folder (the learner's and the author checks
    /// of `cargo test`) must differ here, or a check in one could find the
    /// other's build up to date and run it instead of its own.
    pub version: String,
}

/// Why the lab could not do what was asked; one line each.
#[derive(Debug, thiserror::Error)]
pub enum LabError {
    #[error("cannot read {}: {source}", path.display())]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("cannot write {}: {source}", path.display())]
    Write {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{}: a todo marker is broken, {source}", path.display())]
    Marker {
        path: PathBuf,
        source: crate::exercise::MarkerError,
    },
    #[error("{}: {what}", path.display())]
    Manifest { path: PathBuf, what: String },
}

/// The workspace's root: the folder at or above `here` that holds
/// `crates/learn/Cargo.toml` and `chapters/`, so that the lab is the
/// learner's checkout wherever in it they are.
pub fn workspace_root(here: &Path) -> Option<PathBuf> {
    here.ancestors()
        .find(|dir| dir.join("crates/learn/Cargo.toml").is_file() && dir.join("chapters").is_dir())
        .map(Path::to_owned)
}

/// What `start` did with each file of the exercise.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Started {
    pub folder: PathBuf,
    pub written: Vec<PathBuf>,
    /// Files that were there already and were left as they were.
    pub kept: Vec<PathBuf>,
}

impl Lab {
    /// The lab of the workspace at `root`: `root/my-lab`, building into the
    /// workspace's target folder.
    pub fn in_workspace(root: &Path) -> Lab {
        // Where cargo builds the workspace: `target/`, unless
        // CARGO_TARGET_DIR says otherwise (relative to the root then).
        let target = std::env::var_os("CARGO_TARGET_DIR")
            .filter(|dir| !dir.is_empty())
            .map_or_else(|| root.join("target"), |dir| root.join(dir));
        Lab {
            root: root.to_owned(),
            dir: root.join("my-lab"),
            target,
            version: "0.1.0".to_owned(),
        }
    }

    /// The folder of one exercise, e.g. `my-lab/ch02`, `my-lab/ch06-nee`.
    pub fn folder(&self, exercise: &Exercise) -> PathBuf {
        match exercise.name {
            None => self.dir.join(format!("ch{:02}", exercise.number)),
            Some(name) => self.dir.join(format!("ch{:02}-{name}", exercise.number)),
        }
    }

    /// The package version of one exercise's crate: a chapter's named
    /// exercises are the chapter's package too, and each must be a build
    /// of its own (see [`Lab::version`]).
    fn package_version(&self, exercise: &Exercise) -> String {
        match exercise.name {
            None => self.version.clone(),
            Some(name) if self.version.contains('-') => format!("{}.{name}", self.version),
            Some(name) => format!("{}-{name}", self.version),
        }
    }

    /// The learner's program, `my-ch06-path-tracing` or, for a named
    /// exercise, `my-ch06-path-tracing-nee`: never the chapter's own.
    pub fn program_name(&self, exercise: &Exercise) -> String {
        match exercise.name {
            None => format!("my-{}", exercise.package),
            Some(name) => format!("my-{}-{name}", exercise.package),
        }
    }

    /// The chapter's own source, the reference solution.
    pub fn reference_source(&self, exercise: &Exercise) -> PathBuf {
        self.root.join(exercise.dir).join(exercise.step)
    }

    /// The files of an exercise, as `start` writes them: with the step
    /// blanked, or (for the author checks) solved as the chapter solves it.
    pub fn files(
        &self,
        exercise: &Exercise,
        solved: bool,
    ) -> Result<Vec<(PathBuf, String)>, LabError> {
        let chapter = self.root.join(exercise.dir);
        // Only the exercise's regions are blanked, in the step and in
        // every other file; the chapter's other regions stay solved.
        let blanked = |path: &Path| {
            blank_only(&read(path)?, |region| {
                !solved && exercise.regions.contains(&region)
            })
            .map(|b| b.exercise)
            .map_err(|source| LabError::Marker {
                path: path.to_owned(),
                source,
            })
        };
        let step = blanked(&chapter.join(exercise.step))?;
        let manifest = self.manifest(exercise)?;
        let lock = read(&self.root.join("Cargo.lock"))?;
        let mut files = vec![
            (PathBuf::from("Cargo.toml"), manifest),
            // The workspace's own lock file, so that the exercise builds
            // with exactly the same versions, without the network.
            (PathBuf::from("Cargo.lock"), lock),
            (PathBuf::from(exercise.step), step),
        ];
        // The rest of the chapter's sources as they are (chapter 6's
        // integrator has its render loop, sun and caustics beside it, and
        // its eight-lane tracer in a folder of its own).
        let src = chapter.join("src");
        for name in rust_files(&src, Path::new(""))? {
            let file = PathBuf::from("src").join(&name);
            if file != Path::new(exercise.step) {
                files.push((file, blanked(&src.join(&name))?));
            }
        }
        Ok(files)
    }

    /// Lay the exercise into its folder. A file that is already there is
    /// never touched: the learner's work is theirs.
    pub fn start(&self, exercise: &Exercise, solved: bool) -> Result<Started, LabError> {
        let folder = self.folder(exercise);
        let mut started = Started {
            folder: folder.clone(),
            written: Vec::new(),
            kept: Vec::new(),
        };
        for (name, text) in self.files(exercise, solved)? {
            let path = folder.join(&name);
            if write_new(&path, &text)? {
                started.written.push(name);
            } else {
                started.kept.push(name);
            }
        }
        Ok(started)
    }

    /// The exercise's `Cargo.toml`: the chapter's package, with its
    /// dependencies resolved from the workspace to paths, and the
    /// workspace's build profile (the core optimised, the learner's crate
    /// quick to compile).
    fn manifest(&self, exercise: &Exercise) -> Result<String, LabError> {
        let chapter_path = self.root.join(exercise.dir).join("Cargo.toml");
        let chapter: toml::Table = parse_toml(&chapter_path)?;
        let root_path = self.root.join("Cargo.toml");
        let root: toml::Table = parse_toml(&root_path)?;
        let bad = |path: &Path, what: &str| LabError::Manifest {
            path: path.to_owned(),
            what: what.to_owned(),
        };
        let shared = root
            .get("workspace")
            .and_then(|w| w.get("dependencies"))
            .and_then(|d| d.as_table())
            .ok_or_else(|| bad(&root_path, "no [workspace.dependencies]"))?;
        let deps = chapter
            .get("dependencies")
            .and_then(|d| d.as_table())
            .ok_or_else(|| bad(&chapter_path, "no [dependencies]"))?;
        let mut text = format!(
            "# Your exercise for {exercise}, made by `cargo run -p learn -- start {}`.\n\
             # Its own workspace, built against the finished core and earlier chapters.\n\
             [package]\nname = \"{package}\"\nversion = \"{version}\"\nedition = \"2024\"\npublish = false\n\n\
             # Your program is `{program}`, so that it never takes the place of the\n\
             # chapter's own `{package}` in the shared target folder.\n\
             [[bin]]\nname = \"{program}\"\npath = \"src/main.rs\"\n\n\
             [dependencies]\n",
            exercise.name(),
            package = exercise.package,
            program = self.program_name(exercise),
            version = self.package_version(exercise),
        );
        // The chapter's own unit tests come with its sources, so the
        // libraries they use come along too.
        let dev_deps = chapter.get("dev-dependencies").and_then(|d| d.as_table());
        let sections = [("", Some(deps)), ("\n[dev-dependencies]\n", dev_deps)];
        for (header, deps) in sections {
            let Some(deps) = deps else { continue };
            text.push_str(header);
            for (name, spec) in deps {
                let spec = if spec.get("workspace").and_then(|w| w.as_bool()) == Some(true) {
                    shared.get(name).ok_or_else(|| {
                        bad(&root_path, &format!("no workspace dependency `{name}`"))
                    })?
                } else {
                    spec
                };
                text.push_str(&format!("{name} = {}\n", self.resolve(exercise, spec)));
            }
        }
        text.push_str("\n[workspace]\n\n");
        text.push_str(&dev_profile(&root, "opt-level = 1\n"));
        Ok(text)
    }

    /// A dependency's spec as one inline TOML value, with its `path` seen
    /// from the exercise's folder: relative inside the workspace (so that
    /// the workspace can move), absolute for a lab elsewhere.
    fn resolve(&self, exercise: &Exercise, spec: &toml::Value) -> String {
        inline_spec(spec, |path| {
            self.path_from_exercise(exercise, Path::new(path))
        })
    }

    /// `path` (from the root) as the exercise's `Cargo.toml` should name it.
    fn path_from_exercise(&self, exercise: &Exercise, path: &Path) -> String {
        let folder = self.folder(exercise);
        let target = self.root.join(path);
        let target = target.canonicalize().unwrap_or(target);
        match folder.strip_prefix(&self.root) {
            Ok(inside) => {
                let up = "../".repeat(inside.components().count());
                let rest = path.to_string_lossy();
                match rest.as_ref() {
                    "." | "" => up.trim_end_matches('/').to_owned(),
                    rest => format!("{up}{}", rest.trim_start_matches("./")),
                }
            }
            Err(_) => target.to_string_lossy().into_owned(),
        }
    }

    /// Where the progress is kept.
    pub fn progress_path(&self) -> PathBuf {
        self.dir.join("progress.toml")
    }

    /// The chapters passed so far.
    pub fn progress(&self) -> LabRecord {
        std::fs::read_to_string(self.progress_path())
            .ok()
            .and_then(|text| toml::from_str(&text).ok())
            .unwrap_or_default()
    }

    /// Record that chapter `number` passed its check.
    pub fn record_pass(&self, number: u8) -> Result<(), LabError> {
        let mut progress = self.progress();
        if progress.passed.insert(number) {
            self.save_progress(&progress)?;
        }
        Ok(())
    }

    /// Record that a chapter's exercise passed: its own step by number, a
    /// named one by name.
    pub fn record_exercise_pass(&self, exercise: &Exercise) -> Result<(), LabError> {
        let Some(name) = exercise.name else {
            return self.record_pass(exercise.number);
        };
        let mut progress = self.progress();
        if progress.named.insert(name.to_owned()) {
            self.save_progress(&progress)?;
        }
        Ok(())
    }

    /// Record that `learn hint` gave level `level` of exercise `name`.
    pub fn record_hint(&self, name: &str, level: u8) -> Result<(), LabError> {
        let mut progress = self.progress();
        if progress.hints.insert(name.to_owned(), level) != Some(level) {
            self.save_progress(&progress)?;
        }
        Ok(())
    }

    /// Record that the core exercise `name` passed its check.
    pub fn record_core_pass(&self, name: &str) -> Result<(), LabError> {
        let mut progress = self.progress();
        if progress.core.insert(name.to_owned()) {
            self.save_progress(&progress)?;
        }
        Ok(())
    }

    fn save_progress(&self, progress: &LabRecord) -> Result<(), LabError> {
        let text = toml::to_string(progress).expect("sets of numbers and names serialise");
        let text = format!(
            "# Chapters (`passed`), their named exercises (`named`) and core exercises\n\
             # (`core`) whose check passed, and the last level of hint asked for (`hints`)\n\
             # (`cargo run -p learn -- list`).\n{text}"
        );
        write_atomically(&self.progress_path(), &text)
    }
}

/// The packages whose build settings a lab copies from the workspace's
/// `[profile.dev.package]`: every library (`*`), and the procedural macros
/// and their parser, which every lab's graph holds (through the command
/// line). Not the whole table: cargo warns about each entry that names a
/// package the lab does not have (the GPU stack, the book's builder), and
/// those warnings would stand above a learner's compile errors.
pub const LAB_PROFILE: [&str; 9] = [
    "*",
    "syn",
    "proc-macro2",
    "quote",
    "serde_derive",
    "clap_derive",
    "thiserror-impl",
    "zerocopy-derive",
    "paste",
];

/// A lab's `[profile.dev]`: `own` for its own crates (the learner's), and
/// the workspace's settings for the libraries under them ([`LAB_PROFILE`]),
/// copied from its `Cargo.toml` (`root`): the libraries the workspace has
/// compiled are then the very builds the lab needs, never compiled a second
/// time with other settings.
pub(crate) fn dev_profile(root: &toml::Table, own: &str) -> String {
    let mut text = format!("[profile.dev]\n{own}\n");
    let packages = root
        .get("profile")
        .and_then(|p| p.get("dev"))
        .and_then(|d| d.get("package"))
        .and_then(|p| p.as_table());
    for (name, settings) in packages.into_iter().flatten() {
        let Some(settings) = settings.as_table() else {
            continue;
        };
        if !LAB_PROFILE.contains(&name.as_str()) {
            continue;
        }
        text.push_str(&format!(
            "[profile.dev.package.{}]\n",
            toml::Value::String(name.clone())
        ));
        for (key, value) in settings {
            text.push_str(&format!("{key} = {value}\n"));
        }
        text.push('\n');
    }
    text
}

/// A dependency's spec as one inline TOML value, its `path` (if it has
/// one) rewritten by `path`.
pub(crate) fn inline_spec(spec: &toml::Value, path: impl Fn(&str) -> String) -> String {
    let Some(table) = spec.as_table() else {
        return spec.to_string();
    };
    let fields: Vec<String> = table
        .iter()
        .map(|(key, value)| match (key.as_str(), value.as_str()) {
            ("path", Some(old)) => format!("path = {}", toml::Value::String(path(old))),
            _ => format!("{key} = {value}"),
        })
        .collect();
    format!("{{ {} }}", fields.join(", "))
}

/// The record of what the learner has done (the checks passed, the hints
/// given), kept in `my-lab/progress.toml`. Not a render's progress (the
/// core's `raylab::render::Progress`).
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct LabRecord {
    #[serde(default)]
    pub passed: BTreeSet<u8>,
    /// The chapters' named exercises passed (`cosine`).
    #[serde(default, skip_serializing_if = "BTreeSet::is_empty")]
    pub named: BTreeSet<String>,
    /// The core exercises passed, by name.
    #[serde(default)]
    pub core: BTreeSet<String>,
    /// The last level of hint (1 to 3) `learn hint` gave, by exercise.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub hints: BTreeMap<String, u8>,
}

pub(crate) fn read(path: &Path) -> Result<String, LabError> {
    std::fs::read_to_string(path).map_err(|source| LabError::Read {
        path: path.to_owned(),
        source,
    })
}

pub(crate) fn parse_toml(path: &Path) -> Result<toml::Table, LabError> {
    read(path)?
        .parse()
        .map_err(|e: toml::de::Error| LabError::Manifest {
            path: path.to_owned(),
            what: e.message().to_owned(),
        })
}

/// Write `text` to `path` only if no file is there; `false` if one was.
/// `create_new` makes the test and the creation one step, so not even a
/// file saved at the same moment is overwritten.
pub(crate) fn write_new(path: &Path, text: &str) -> Result<bool, LabError> {
    let fail = |source| LabError::Write {
        path: path.to_owned(),
        source,
    };
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(fail)?;
    }
    match std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
    {
        Ok(mut file) => {
            file.write_all(text.as_bytes()).map_err(fail)?;
            Ok(true)
        }
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Ok(false),
        Err(e) => Err(fail(e)),
    }
}

/// Write through a temporary file in the same folder, then rename it over
/// `path`: a reader sees the old file or the new one, never half of one.
fn write_atomically(path: &Path, text: &str) -> Result<(), LabError> {
    let fail = |source| LabError::Write {
        path: path.to_owned(),
        source,
    };
    let parent = path.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(parent).map_err(fail)?;
    let tmp = path.with_extension("toml.tmp");
    std::fs::write(&tmp, text).map_err(fail)?;
    std::fs::rename(&tmp, path).map_err(fail)
}
/// The `.rs` files under `dir/under`, as paths relative to `dir`, in
/// sorted order, those of subfolders included.
pub(crate) fn rust_files(dir: &Path, under: &Path) -> Result<Vec<PathBuf>, LabError> {
    let folder = dir.join(under);
    let mut entries: Vec<_> = std::fs::read_dir(&folder)
        .map_err(|source| LabError::Read {
            path: folder.clone(),
            source,
        })?
        .filter_map(|entry| entry.ok())
        .collect();
    entries.sort_by_key(|e| e.file_name());
    let mut files = Vec::new();
    for entry in entries {
        let name = under.join(entry.file_name());
        if entry.file_type().is_ok_and(|t| t.is_dir()) {
            files.extend(rust_files(dir, &name)?);
        } else if name.to_string_lossy().ends_with(".rs") {
            files.push(name);
        }
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_labs_profile_keeps_its_own_level_and_the_workspaces_settings_for_every_library() {
        let root: toml::Table = "[profile.dev]\nopt-level = 1\n\n\
             [profile.dev.package.\"*\"]\nopt-level = 3\ndebug = false\n\n\
             [profile.dev.package]\nsyn = { opt-level = 0 }\nwgpu = { opt-level = 0 }\n"
            .parse()
            .unwrap();
        let text = dev_profile(&root, "opt-level = 0\n");
        let lab: toml::Table = text.parse().unwrap();
        let dev = &lab["profile"]["dev"];
        assert_eq!(dev["opt-level"].as_integer(), Some(0), "{text}");
        assert_eq!(dev["package"]["*"]["opt-level"].as_integer(), Some(3));
        assert_eq!(dev["package"]["*"]["debug"].as_bool(), Some(false));
        assert_eq!(dev["package"]["syn"]["opt-level"].as_integer(), Some(0));
        assert!(
            dev["package"].get("wgpu").is_none(),
            "no lab has the GPU stack"
        );
    }

    #[test]
    fn every_package_a_lab_takes_the_settings_of_is_in_the_workspaces_profile() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../Cargo.toml");
        let root = parse_toml(&root).unwrap();
        let lab: toml::Table = dev_profile(&root, "").parse().unwrap();
        let copied = lab["profile"]["dev"]["package"].as_table().unwrap();
        for name in LAB_PROFILE {
            assert!(copied.contains_key(name), "{name}");
        }
    }

    #[test]
    fn the_workspace_root_is_found_from_any_folder_inside_it() {
        let here = Path::new(env!("CARGO_MANIFEST_DIR"));
        let root = workspace_root(&here.join("src")).unwrap();
        assert!(root.join("chapters").is_dir() && root.join("crates/learn").is_dir());
        assert_eq!(workspace_root(Path::new("/")), None);
    }
}
