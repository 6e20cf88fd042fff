//! `cargo run --release -p ch07-eight-rays -- --help`
//!
//! `--like chNN-…` chooses which chapter's shading and defaults the waves
//! trace with (chapter 5's when it is not given).
use std::process::ExitCode;

fn main() -> ExitCode {
    raylab_like::main(ch07_eight_rays::chapter, std::env::args_os())
}
