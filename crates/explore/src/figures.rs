//! The book's screenshots of the explorer, made without a window through
//! the same state and scripts the window runs.

use std::path::{Path, PathBuf};

use raylab::probe::ProbeTarget;

use crate::driver::{Driver, Messages, run_headless};
use crate::error::ExploreError;
use crate::script;
use crate::source::Loaded;
use crate::state::Explorer;

/// The screenshots' size: the explorer's default window.
const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;

/// The glass ball's centre pixel in the lab camera, for the probes.
fn glass_pixel() -> (u32, u32) {
    let lab = Loaded::lab();
    ProbeTarget::centre_of("glass")
        .pixel(&lab.scene, &lab.camera, WIDTH, HEIGHT)
        .unwrap_or((WIDTH / 2, HEIGHT / 2))
}

/// Each figure: its file name and the script that makes it.
pub fn scripts() -> Vec<(&'static str, String)> {
    let (gx, gy) = glass_pixel();
    vec![
        ("explorer-ch05.png", "settle".into()),
        ("explorer-help.png", "key:? settle".into()),
        ("explorer-ch01.png", "key:1 settle".into()),
        ("explorer-acne.png", "key:2 key:e settle".into()),
        (
            "explorer-ch03-depth-1.png",
            format!("key:3 {}settle", "key:down ".repeat(9)),
        ),
        ("explorer-tree.png", format!("key:4 click:{gx},{gy} settle")),
        (
            "explorer-tree-side.png",
            format!("key:4 click:{gx},{gy} drag:320,240,560,200 settle"),
        ),
        // 64 paths per pixel: one step down from chapter 6's 256.
        ("explorer-paths.png", "key:6 key:R settle".into()),
        ("explorer-sun-20.png", "key:6 key:R keys:]]] settle".into()),
        // Without a GPU adapter, the frame shows the line that says so.
        ("explorer-gpu.png", "key:g settle".into()),
    ]
}

/// Write the book's screenshots of the explorer into `dir`; the paths written.
pub fn write_book_figures(dir: &Path) -> Result<Vec<PathBuf>, ExploreError> {
    std::fs::create_dir_all(dir).map_err(|source| ExploreError::Folder {
        path: dir.to_owned(),
        source,
    })?;
    let mut written = Vec::new();
    for (name, text) in scripts() {
        let path = dir.join(name);
        let steps = script::parse(&text)?;
        let mut explorer = Explorer::new(Loaded::lab(), WIDTH, HEIGHT);
        let mut driver = Driver::new(steps, dir.to_owned());
        run_headless(&mut explorer, &mut driver, 0, Some(&path), Messages::Drop)?;
        written.push(path);
    }
    Ok(written)
}
