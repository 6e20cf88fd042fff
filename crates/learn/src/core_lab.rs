//! The learner's core: `my-lab/core/src/`, and the workspace the check
//! builds it in, `my-lab/.core-build/`.
//!
//! `learn start sphere` copies the core's `sphere.rs` into
//! `my-lab/core/src/` with its regions blanked and their marker lines
//! kept. The check then assembles a whole core in `.core-build/raylab/`:
//! the reference's files, with the learner's regions in place of the
//! reference's for the exercise being checked and every one they passed,
//! so that an exercise is judged with everything the learner has proved
//! and nothing they have not written yet. The same workspace holds the
//! command line (`raylab-cli`) and chapters 1 to 4 as packages whose
//! sources are the workspace's own files, read where they are, and whose
//! `raylab` is the assembled one: that is how the learner's core replaces
//! the workspace's for their builds, while the workspace itself never
//! changes. Only files whose text changed are written, so a check after a
//! one-line edit recompiles the core and, incrementally, what stands on it.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::core::{CoreExercise, owner};
use crate::lab::{Lab, LabError, Started, inline_spec, read, rust_files, write_new};
use crate::regions::{blank_keeping_markers, splice};

/// The chapters the build workspace holds, by folder and package.
const CHAPTERS: [(&str, &str); 4] = [
    ("chapters/01-ray-cast", "ch01-ray-cast"),
    ("chapters/02-shadows", "ch02-shadows"),
    ("chapters/03-reflection", "ch03-reflection"),
    ("chapters/04-refraction", "ch04-refraction"),
];

/// The program name of chapter `number` built on the learner's core.
pub fn program_name(number: u8) -> Option<String> {
    let (_, package) = CHAPTERS.get(usize::from(number).checked_sub(1)?)?;
    Some(format!("my-core-{package}"))
}

/// The package name of chapter `number`.
pub fn package_name(number: u8) -> Option<&'static str> {
    Some(CHAPTERS.get(usize::from(number).checked_sub(1)?)?.1)
}

impl Lab {
    /// The learner's core sources, `my-lab/core/src/`.
    pub fn core_src(&self) -> PathBuf {
        self.dir.join("core").join("src")
    }

    /// The workspace the check assembles and builds the learner's core in.
    pub fn core_build(&self) -> PathBuf {
        self.dir.join(".core-build")
    }

    /// Where the check of a core exercise writes its images.
    pub fn core_check_dir(&self, exercise: &CoreExercise) -> PathBuf {
        self.dir.join("core").join("check").join(exercise.name)
    }

    /// Whether the learner has the files of `exercise`.
    pub fn core_started(&self, exercise: &CoreExercise) -> bool {
        exercise
            .files
            .iter()
            .all(|file| self.core_src().join(file).is_file())
    }

    /// Lay the exercise's files into `my-lab/core/src/`: blanked, markers
    /// kept, or (for the author checks) as the reference has them. A file
    /// already there is never touched.
    pub fn start_core(&self, exercise: &CoreExercise, solved: bool) -> Result<Started, LabError> {
        let mut started = Started {
            folder: self.core_src(),
            written: Vec::new(),
            kept: Vec::new(),
        };
        for file in exercise.files {
            let reference_path = self.root.join("src").join(file);
            let reference = read(&reference_path)?;
            let text = if solved {
                reference
            } else {
                blank_keeping_markers(&reference).map_err(|source| LabError::Marker {
                    path: reference_path.clone(),
                    source,
                })?
            };
            let name = PathBuf::from(file);
            if write_new(&self.core_src().join(file), &text)? {
                started.written.push(name);
            } else {
                started.kept.push(name);
            }
        }
        Ok(started)
    }

    /// Write the build workspace for checking `exercise`, the learner's
    /// regions of it and of the exercises in `passed` spliced into the
    /// reference core.
    pub fn assemble_core(
        &self,
        exercise: &CoreExercise,
        passed: &BTreeSet<String>,
    ) -> Result<(), LabError> {
        let build = self.core_build();
        let take = |region: &str| {
            owner(region).is_some_and(|o| o.name == exercise.name || passed.contains(o.name))
        };
        let src = self.root.join("src");
        for file in rust_files(&src, Path::new(""))? {
            let reference = read(&src.join(&file))?;
            let mine = self.core_src().join(&file);
            let text = if mine.is_file() {
                splice(&reference, &read(&mine)?, take).map_err(|e| LabError::Manifest {
                    path: mine.clone(),
                    what: e.to_string(),
                })?
            } else {
                reference
            };
            write_if_changed(&build.join("raylab/src").join(&file), &text)?;
        }
        for (path, text) in self.core_manifests()? {
            write_if_changed(&build.join(path), &text)?;
        }
        // The workspace's own lock file, so that the build uses exactly
        // the same versions, without the network; cargo keeps it after.
        let lock = read(&self.root.join("Cargo.lock"))?;
        write_new(&build.join("Cargo.lock"), &lock)?;
        Ok(())
    }

    /// The build workspace's manifests: its root, the core, the command
    /// line and the chapters.
    fn core_manifests(&self) -> Result<Vec<(PathBuf, String)>, LabError> {
        let root_path = self.root.join("Cargo.toml");
        let root: toml::Table = crate::lab::parse_toml(&root_path)?;
        let shared = root
            .get("workspace")
            .and_then(|w| w.get("dependencies"))
            .and_then(|d| d.as_table())
            .ok_or_else(|| LabError::Manifest {
                path: root_path.clone(),
                what: "no [workspace.dependencies]".into(),
            })?;
        // A package of the build workspace is found by its name.
        let local: Vec<&str> = ["raylab", "raylab-cli"]
            .into_iter()
            .chain(CHAPTERS.iter().map(|(_, package)| *package))
            .collect();
        let deps = |manifest: &toml::Table| -> String {
            let mut text = String::from("[dependencies]\n");
            let table = manifest.get("dependencies").and_then(|d| d.as_table());
            for (name, spec) in table.into_iter().flatten() {
                let line = if local.contains(&name.as_str()) {
                    format!("{{ path = {:?} }}", format!("../{name}"))
                } else {
                    let spec = if spec.get("workspace").and_then(|w| w.as_bool()) == Some(true) {
                        shared.get(name).unwrap_or(spec)
                    } else {
                        spec
                    };
                    absolute_paths(spec, &self.root)
                };
                text.push_str(&format!("{name} = {line}\n"));
            }
            text
        };
        let package = |name: &str| {
            format!(
                "[package]\nname = \"{name}\"\nversion = \"{}\"\nedition = \"2024\"\npublish = false\n\n",
                self.version
            )
        };
        let mut manifests = Vec::new();
        let header = "# Made by `learn check` for a core exercise: the learner's core, and the\n\
                      # workspace's command line and chapters built on it. Rewritten by every check.\n";
        manifests.push((
            PathBuf::from("raylab/Cargo.toml"),
            format!("{header}{}{}", package("raylab"), deps(&root)),
        ));
        let cli_path = self.root.join("crates/cli/Cargo.toml");
        let cli = crate::lab::parse_toml(&cli_path)?;
        manifests.push((
            PathBuf::from("raylab-cli/Cargo.toml"),
            format!(
                "{header}{}[lib]\nname = \"raylab_cli\"\npath = {:?}\ntest = false\ndoctest = false\n\n{}",
                package("raylab-cli"),
                self.root.join("crates/cli/src/lib.rs").display().to_string(),
                deps(&cli)
            ),
        ));
        for (dir, name) in CHAPTERS {
            let chapter = crate::lab::parse_toml(&self.root.join(dir).join("Cargo.toml"))?;
            let src = self.root.join(dir).join("src");
            manifests.push((
                PathBuf::from(name).join("Cargo.toml"),
                format!(
                    "{header}{}[lib]\npath = {:?}\ntest = false\ndoctest = false\n\n\
                     [[bin]]\nname = \"my-core-{name}\"\npath = {:?}\ntest = false\n\n{}",
                    package(name),
                    src.join("lib.rs").display().to_string(),
                    src.join("main.rs").display().to_string(),
                    deps(&chapter)
                ),
            ));
        }
        let members: Vec<String> = local.iter().map(|m| format!("{m:?}")).collect();
        manifests.push((
            PathBuf::from("Cargo.toml"),
            format!(
                "{header}[workspace]\nresolver = \"3\"\nmembers = [{}]\n\n\
                 # Quick to compile after an edit; the libraries under it as the\n\
                 # workspace builds them.\n{}",
                members.join(", "),
                crate::lab::dev_profile(&root, "opt-level = 0\ndebug = false\n"),
            ),
        ));
        Ok(manifests)
    }
}

/// A dependency's spec as one inline TOML value, its `path` made absolute
/// from the workspace's root.
fn absolute_paths(spec: &toml::Value, root: &Path) -> String {
    inline_spec(spec, |path| {
        let path = root.join(path);
        let path = path.canonicalize().unwrap_or(path);
        path.display().to_string()
    })
}

/// Write `text` to `path` unless it holds exactly that already: a file
/// written again, even unchanged, would make cargo rebuild it.
fn write_if_changed(path: &Path, text: &str) -> Result<(), LabError> {
    if std::fs::read_to_string(path).is_ok_and(|old| old == text) {
        return Ok(());
    }
    let fail = |source| LabError::Write {
        path: path.to_owned(),
        source,
    };
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(fail)?;
    }
    std::fs::write(path, text).map_err(fail)
}
