//! `cargo run -p ch04-refraction -- --help`
fn main() -> std::process::ExitCode {
    raylab_cli::main(&ch04_refraction::CHAPTER)
}
