//! # learn: do the lab yourself
//!
//! The core's regions (`src/`, the track before chapter 1: [`core`], built
//! on the learner's copy as [`core_lab`] assembles it) and each chapter's
//! step as exercises, one path ([`path`]). `cargo run -p learn -- start 2`
//! lays chapter 2 with its shadow ray blanked into `my-lab/ch02/`;
//! `cargo run -p learn -- check 2` builds it, runs the chapter's tests on
//! it and compares its render with the reference chapter's; `watch 2`
//! checks again on every save. Chapter 10's shader is one more exercise
//! ([`shader`]): its three tasks blanked in `tracer.wgsl`. `hint` gives a
//! nudge, the rule, then the recipe; `mistakes` lists the catalogue of
//! known wrong answers ([`mistakes`]). See `cargo run -p learn -- --help`.
//!
//! This crate is small on purpose: it lists, lays out, hints and reads the
//! catalogue with a few small libraries (clap, serde, toml, thiserror), so
//! that on a fresh clone the first command answers in seconds. `check` and
//! `watch` need the tracer itself: they are the program of the workspace's
//! `learn-check` crate, which `learn` builds on first use and hands the
//! command to ([`checker`]).

pub mod checker;
pub mod core;
pub mod core_lab;
pub mod exercise;
pub mod lab;
pub mod limits;
pub mod mistakes;
pub mod path;
pub mod regions;
pub mod run;
pub mod shader;
