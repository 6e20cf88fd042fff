//! `cargo run --release -p ch09-many-spheres -- --help`
//!
//! Flags of its own, read before the shared command line sees the rest:
//! `--eight` (chapter 7's waves through the tree), `--paths` (chapter 8's
//! paths through the tree, with chapter 6's flags), and `--generate-field
//! N [--seed S]`, which prints a scene file instead of rendering.
//! `--like chNN-…` (which chapter's tracing and defaults) is one of the
//! shared command line's flags here, as in chapter 7.
use std::ffi::OsString;
use std::process::ExitCode;

use ch09_many_spheres::field::{MAX_FIELD, field};
use ch09_many_spheres::{BINARY, PATHS, chapter, chapter_eight};

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().collect();
    let like_given = args
        .iter()
        .any(|a| a.to_string_lossy().starts_with("--like"));
    let result = if args.iter().any(|a| {
        let a = a.to_string_lossy();
        a == "--generate-field" || a.starts_with("--generate-field=")
    }) {
        generate(&args[1..]).map(|text| {
            print!("{text}");
            ExitCode::SUCCESS
        })
    } else {
        let (eight, rest) = take_flag(args, "--eight");
        let (paths, rest) = take_flag(rest, "--paths");
        match (eight, paths) {
            (true, true) => Err("--eight and --paths cannot go together: give one".into()),
            (true, false) => Ok(raylab_like::main(chapter_eight, rest)),
            (false, true) if like_given => {
                Err("--like cannot go with --paths, which path-traces as chapter 6 does".into())
            }
            (false, true) => Ok(ch06_path_tracing::main_with_args(&PATHS, rest)),
            (false, false) => Ok(raylab_like::main(chapter, rest)),
        }
    };
    result.unwrap_or_else(|message| {
        eprintln!("{BINARY}: error: {message}");
        ExitCode::from(2)
    })
}

/// Take every `flag` out of the arguments; whether there was one.
fn take_flag(args: Vec<OsString>, flag: &str) -> (bool, Vec<OsString>) {
    let before = args.len();
    let rest: Vec<OsString> = args.into_iter().filter(|a| a != flag).collect();
    (rest.len() < before, rest)
}

/// `--generate-field N [--seed S]`: the scene file's text.
fn generate(args: &[OsString]) -> Result<String, String> {
    let (mut n, mut seed) = (None, 0u64);
    let mut args = args.iter().map(|a| a.to_string_lossy().into_owned());
    while let Some(arg) = args.next() {
        let (flag, inline) = match arg.split_once('=') {
            Some((f, v)) => (f.to_owned(), Some(v.to_owned())),
            None => (arg, None),
        };
        let mut value = || {
            inline
                .clone()
                .or_else(|| args.next())
                .ok_or(format!("{flag} needs a value"))
        };
        match flag.as_str() {
            "--generate-field" => {
                let text = value()?;
                n = Some(
                    text.parse::<usize>()
                        .ok()
                        .filter(|n| *n <= MAX_FIELD)
                        .ok_or(format!(
                            "--generate-field '{text}': give a whole number of spheres from 0 to {MAX_FIELD}"
                        ))?,
                );
            }
            "--seed" => {
                let text = value()?;
                seed = text.parse().map_err(|_| {
                    format!(
                        "--seed '{text}': give a whole number from 0 to {}",
                        u64::MAX
                    )
                })?;
            }
            other => {
                return Err(format!(
                    "'{other}' cannot go with --generate-field, which takes only --seed S"
                ));
            }
        }
    }
    let n = n.ok_or("--generate-field needs a number of spheres")?;
    Ok(field(n, seed))
}
