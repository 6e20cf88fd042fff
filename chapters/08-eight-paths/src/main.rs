//! `cargo run --release -p ch08-eight-paths -- --help`
fn main() -> std::process::ExitCode {
    ch06_path_tracing::main(&ch08_eight_paths::PROGRAM)
}
