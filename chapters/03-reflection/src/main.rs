//! `cargo run -p ch03-reflection -- --help`
fn main() -> std::process::ExitCode {
    raylab_cli::main(&ch03_reflection::CHAPTER)
}
