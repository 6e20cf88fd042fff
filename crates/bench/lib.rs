//! Benchmarks live in `benches/`; run them with `cargo bench -p raylab-bench`.
//! This package is outside the workspace's default members so that
//! `cargo test` does not build criterion.
