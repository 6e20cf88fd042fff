//! The workbook's main job: render every chapter with its defaults and
//! every figure of the book, then build the book.
//!
//! `cargo run --release -p workbook`, from the workspace's root.

use std::path::Path;
use std::process::{Command, ExitCode};

use workbook::{JobError, Parts, Size, book, claims, make_figures};

fn run() -> Result<(), JobError> {
    let book_dir = Path::new("book");
    let mut parts = Parts::default();
    make_figures(
        &book_dir.join("src/figures"),
        Path::new("scenes"),
        Size::DEFAULT,
        false,
        &mut parts,
    )?;
    // The hand-written text around each ray-tree figure agrees with the
    // probe.txt it was made with, before the book is built from both.
    let figures = book_dir.join("src/figures");
    let wrong = claims::check_pages(&book_dir.join("src"), |dir| {
        std::fs::read_to_string(figures.join(dir).join("probe.txt")).ok()
    });
    if !wrong.is_empty() {
        return Err(JobError::Book(format!(
            "a page disagrees with its probe:\n  {}",
            wrong.join("\n  ")
        )));
    }
    let index = parts.time("the book", || book::build(book_dir))?;
    print!("{}", parts.summary());
    println!(
        "book: open {} (or run `mdbook serve book`)",
        index.display()
    );
    Ok(())
}

/// Chapter 10's speed table asks the Vulkan loader for an adapter, and on
/// a machine with no per-user runtime folder (a container, a login over
/// ssh) the window system's library prints two `error:` lines that are no
/// error of the job. Such a run starts itself again with a private folder,
/// as `.ci/run` gives the tests one; `None` when the folder is fine.
fn with_private_runtime_folder() -> Option<ExitCode> {
    const VAR: &str = "XDG_RUNTIME_DIR";
    if std::env::var_os(VAR).is_some_and(|dir| Path::new(&dir).is_dir()) {
        return None;
    }
    // Made with mode 0700, as the folder must be; removed when dropped.
    let folder = tempfile::tempdir().ok()?;
    let program = std::env::current_exe().ok()?;
    let status = Command::new(program)
        .args(std::env::args_os().skip(1))
        .env(VAR, folder.path())
        .status()
        .ok()?;
    Some(match status.code() {
        Some(code) => ExitCode::from(u8::try_from(code).unwrap_or(2)),
        None => ExitCode::from(2),
    })
}

fn main() -> ExitCode {
    if let Some(code) = with_private_runtime_folder() {
        return code;
    }
    if !Path::new("book/book.toml").exists() {
        eprintln!(
            "workbook: error: no book/book.toml here: run it from the workspace's root folder"
        );
        return ExitCode::from(2);
    }
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("workbook: error: {error}");
            ExitCode::from(2)
        }
    }
}
