//! `cargo run --release -p ch06-path-tracing -- --help`
fn main() -> std::process::ExitCode {
    ch06_path_tracing::main(&ch06_path_tracing::PROGRAM)
}
