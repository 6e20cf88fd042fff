//! `cargo run --release -p ch08-eight-paths -- --help`
//!
//! Chapter 6's command line, and `--objects tree`: every hit found through
//! chapter 9's tree instead of the list.
use ch06_path_tracing::run;
use ch08_eight_paths::{PROGRAM, program_through};
use ch09_many_spheres::objects;

fn main() -> std::process::ExitCode {
    let binary = PROGRAM.program.binary;
    let command = run::command(&PROGRAM.program).arg(objects::arg());
    raylab_cli::main_of(binary, command, std::env::args_os(), |matches| {
        run::run_matches(&program_through(objects::chosen(matches)), matches)
    })
}
