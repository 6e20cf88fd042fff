//! The workbook's main job: render every chapter with its defaults and
//! every figure of the book, then build the book.
//!
//! `cargo run --release -p workbook`, from the workspace's root.

use std::path::Path;
use std::process::ExitCode;

use workbook::{JobError, Size, book, claims, make_figures};

fn run() -> Result<(), JobError> {
    let book_dir = Path::new("book");
    make_figures(
        &book_dir.join("src/figures"),
        Path::new("scenes"),
        Size::DEFAULT,
        false,
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
    let index = book::build(book_dir)?;
    println!(
        "book: open {} (or run `mdbook serve book`)",
        index.display()
    );
    Ok(())
}

fn main() -> ExitCode {
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
