//! `cargo run --release -p ch07-eight-rays -- --help`
//!
//! `--like chNN-…` chooses which chapter's shading and defaults the waves
//! trace with (chapter 5's when it is not given); `--objects tree` finds
//! every hit through chapter 9's tree instead of the list.
use std::process::ExitCode;

use ch07_eight_rays::{BINARY, Like, chapter, chapter_through};

fn main() -> ExitCode {
    let command =
        raylab_like::command(&chapter(Like::AntiAliasing)).arg(ch09_many_spheres::objects::arg());
    raylab_cli::main_of(BINARY, command, std::env::args_os(), |matches| {
        let objects = ch09_many_spheres::objects::chosen(matches);
        raylab_like::run(matches, |like| chapter_through(like, objects))
    })
}
