//! `cargo run -p ch05-antialiasing -- --help`
fn main() -> std::process::ExitCode {
    raylab_cli::main(&ch05_antialiasing::CHAPTER)
}
