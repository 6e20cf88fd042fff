//! `cargo run -p ch10-gpu -- --help`
//!
//! `--like` is this chapter's own flag, read before the shared command line
//! sees the rest: it decides the chapter's defaults (`--max-depth`, `--spp`).
fn main() -> std::process::ExitCode {
    ch10_gpu::cli::main()
}
