//! # learn: do the lab yourself
//!
//! The core's regions (`src/`, the track before chapter 1: [`core`], built
//! on the learner's copy by [`core_lab`]) and each chapter's step as
//! exercises, one path ([`path`]). `cargo run -p learn -- start 2`
//! lays chapter 2 with its shadow ray blanked into `my-lab/ch02/`;
//! `cargo run -p learn -- check 2` builds it, runs the chapter's tests on
//! it and compares its render with the reference chapter's; `watch 2`
//! checks again on every save. Chapter 10's shader is one more exercise
//! ([`shader`], checked by [`shader_check`]): its three tasks blanked in
//! `tracer.wgsl`. See `cargo run -p learn -- --help`.

pub mod check;
pub mod compare;
pub mod core;
pub mod core_lab;
pub mod exercise;
pub mod lab;
pub mod mistakes;
pub mod noisy;
pub mod path;
pub mod regions;
pub mod run;
pub mod shader;
pub mod shader_check;
pub mod watch;
