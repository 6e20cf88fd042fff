//! `cargo run -p ch02-shadows -- --help`
fn main() -> std::process::ExitCode {
    raylab::cli::main(&ch02_shadows::CHAPTER)
}
