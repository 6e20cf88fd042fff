//! `cargo run -p ch01-ray-cast -- --help`
fn main() -> std::process::ExitCode {
    raylab_cli::main(&ch01_ray_cast::CHAPTER)
}
