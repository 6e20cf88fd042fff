//! # raylab-cli: the lab bench every chapter stands on
//!
//! What turns a chapter's [`Step`](raylab::trace::Step) into a program a learner runs: the
//! command line every chapter binary shares, writing files, scene files,
//! `--watch`, the probe's text, and the figures of a render (depth and ray
//! heat maps, the ray-tree diagram, the depth sweep). The tracer itself is
//! the core crate `raylab`; the drawing is `raylab-plot`'s.

//!
//! The crate root only names the parts and re-exports what the chapters
//! use, as ripgrep's `flags/mod.rs` does: what a program is
//! ([`program`]), its flags ([`flags`]), what it accepts ([`limits`]), its
//! errors ([`error`]), one run ([`run`](mod@run)), what the run tells the learner
//! ([`report`]), and the entry points ([`entry`]).

pub mod diagrams;
pub mod entry;
pub mod error;
pub mod flags;
pub mod limits;
pub mod output;
pub mod probe_text;
pub mod program;
pub mod report;
pub mod run;
pub mod saves;
pub mod scene_file;
pub mod watch;

pub use entry::{exit, main, main_of, main_with_args, run_options};
pub use error::{CliError, usage_line};
pub use flags::{CommonFlags, Options, RayTreeFlags, check_pixel_count};
pub use limits::{DEFAULT_EPSILON, MAX_EPSILON, MAX_PIXELS, MAX_SIDE};
pub use program::{Chapter, Program, Renderer};
pub use report::{Report, print_report};
pub use run::{SWEEP_SPP, prepare_out_dir, progress_bar, run};
