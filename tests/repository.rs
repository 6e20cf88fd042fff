//! Tests of the repository as a learner receives it: what its files may say.

use std::path::{Path, PathBuf};

/// Folders that hold what the programs write or what was fetched, not what
/// the repository ships.
const GENERATED: [&str; 6] = [
    ".git",
    "target",
    "out",
    "my-lab",
    "book/build",
    "book/src/figures",
];

/// Every file the repository ships, below `dir`.
fn shipped_files(root: &Path, dir: &Path, files: &mut Vec<PathBuf>) {
    let entries = std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    for entry in entries {
        let path = entry.expect("a folder entry").path();
        let relative = path.strip_prefix(root).expect("below the root");
        // npm's packages, wherever `npm ci` put them (tests/browser/).
        let fetched = path.file_name().is_some_and(|n| n == "node_modules");
        if fetched || GENERATED.iter().any(|g| relative == Path::new(g)) {
            continue;
        }
        if path.is_dir() {
            shipped_files(root, &path, files);
        } else {
            files.push(path);
        }
    }
}

#[test]
fn no_file_names_the_lab_model_by_a_file_the_learner_does_not_have() {
    // Spelt in two halves, so that this file does not name it either.
    let name = concat!("LAB", ".md");
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the workspace");
    let mut files = Vec::new();
    shipped_files(root, root, &mut files);
    assert!(files.len() > 100, "found only {} files", files.len());
    let naming: Vec<String> = files
        .iter()
        .filter(|f| {
            std::fs::read(f)
                .ok()
                .and_then(|bytes| String::from_utf8(bytes).ok())
                .is_some_and(|text| text.contains(name))
        })
        .map(|f| {
            f.strip_prefix(root)
                .expect("below the root")
                .display()
                .to_string()
        })
        .collect();
    assert!(
        naming.is_empty(),
        "these files name {name}, which is not in the repository (say \"the lab model\", the book's appendix): {}",
        naming.join(", ")
    );
}

#[test]
fn every_crate_of_the_workspace_takes_the_workspace_lints() {
    // `[lints] workspace = true` is how a crate forbids `unsafe` with the
    // rest: a crate without it would make "safe Rust throughout" untrue.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the workspace");
    let mut manifests = vec![root.join("Cargo.toml"), root.join("tests/Cargo.toml")];
    for folder in ["chapters", "crates"] {
        let entries = std::fs::read_dir(root.join(folder)).expect("a folder of crates");
        for entry in entries {
            let manifest = entry.expect("a folder entry").path().join("Cargo.toml");
            if manifest.is_file() {
                manifests.push(manifest);
            }
        }
    }
    assert!(
        manifests.len() > 15,
        "found only {} crates",
        manifests.len()
    );
    let without: Vec<String> = manifests
        .iter()
        .filter(|m| {
            let text = std::fs::read_to_string(m).expect("a readable manifest");
            !text.contains("[lints]\nworkspace = true")
        })
        .map(|m| {
            m.strip_prefix(root)
                .expect("below the root")
                .display()
                .to_string()
        })
        .collect();
    assert!(
        without.is_empty(),
        "these crates do not take the workspace's lints (add `[lints]` with `workspace = true`): {}",
        without.join(", ")
    );
}
