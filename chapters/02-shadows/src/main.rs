//! `cargo run -p ch02-shadows -- --help`
fn main() -> std::process::ExitCode {
    raylab_cli::main(&ch02_shadows::CHAPTER)
}
