//! # learn-check: the checker `learn` builds on first use
//!
//! `cargo run -p learn -- check 2` (and `watch 2`) runs this crate's
//! program, `learn-check`, which `learn` builds the first time a check is
//! asked for (see `learn::checker`). It holds everything of `learn` that
//! needs the tracer: building the learner's exercise ([`build`]), running
//! its tests ([`test_run`]), rendering it small and comparing the render
//! with the reference chapter's ([`picture`], [`compare`], [`noisy`]),
//! saying how a picture differs ([`picture::report`]), and naming the
//! catalogue's mistake a failure matches ([`fingerprints`], [`diagnose`]).
//! Each stage answers a [`verdict::Verdict`]. A chapter's step is checked by
//! [`check`], a core exercise by [`core_check`], the shader by
//! [`shader_check`]; [`watch`] checks again on every save. The stages in
//! order, without the diagnosis, are [`chapter_stages`] and
//! [`core_stages`]: the catalogue checks its own mistakes through them, so
//! the diagnosis and the checks that call it use each other through no
//! ring of modules.
//!
//! Why a program of its own: the reference renders need the core and
//! chapters 1 to 6, the command line and the image library, about 120
//! crates, none of which `list`, `start`, `hint` or `mistakes`
//! need. In `learn` itself they were compiled before the learner saw the
//! list of exercises; here they are compiled once, when the first check
//! needs them, after a note that says what and how long.

pub mod build;
pub mod chapter_stages;
pub mod check;
pub mod compare;
pub mod core_check;
pub mod core_stages;
pub mod diagnose;
pub mod fingerprints;
pub mod noisy;
pub mod picture;
pub mod shader_check;
pub mod test_run;
pub mod verdict;
pub mod watch;
