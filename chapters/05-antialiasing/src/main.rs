//! `cargo run -p ch05-antialiasing -- --help`
fn main() -> std::process::ExitCode {
    raylab::cli::main(&ch05_antialiasing::CHAPTER)
}
