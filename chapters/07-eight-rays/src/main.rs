//! `cargo run --release -p ch07-eight-rays -- --help`
//!
//! `--like` is this chapter's own flag, read before the shared command line
//! sees the rest: it decides the chapter's defaults (`--max-depth`, `--spp`).
use std::process::ExitCode;

fn main() -> ExitCode {
    match ch07_eight_rays::like::take_like(std::env::args_os().collect()) {
        Ok((like, rest)) => raylab_cli::main_with_args(&ch07_eight_rays::chapter(like), rest),
        Err(message) => {
            eprintln!("{}: error: {message}", ch07_eight_rays::BINARY);
            ExitCode::from(2)
        }
    }
}
