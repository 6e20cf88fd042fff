//! `cargo run --release -p ch09-many-spheres -- --help`
//!
//! Renders through the tree, as the chapter `--like` names does (chapter
//! 5 without it), or, with `generate-field N [--seed S]`, prints a scene
//! file of N random spheres instead.
fn main() -> std::process::ExitCode {
    ch09_many_spheres::program::main(std::env::args_os())
}
