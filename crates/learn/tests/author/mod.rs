//! The author lab the checks of `learn`'s own tests run in: a lab of the
//! workspace's exercises in `target/learn-author-checks/`, shared by the
//! test files that build exercises (one at a time: see their `LOCK`).

use std::path::{Path, PathBuf};

use learn::lab::Lab;

/// The workspace's root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("crates/learn/ is inside the workspace")
        .to_owned()
}

/// The author lab, beside the learner's (`my-lab/`), never in it.
pub fn author_lab() -> Lab {
    let root = root();
    Lab {
        dir: root.join("target").join("learn-author-checks"),
        version: "0.1.0-author-checks".to_owned(),
        ..Lab::in_workspace(&root)
    }
}
