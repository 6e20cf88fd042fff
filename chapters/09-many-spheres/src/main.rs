//! `cargo run --release -p ch09-many-spheres -- --help`
//!
//! Two flags of its own, read before the shared command line sees the
//! rest: `--like chNN-…` (which chapter's tracing and defaults), and
//! `--generate-field N [--seed S]`, which prints a scene file instead of
//! rendering.
use std::ffi::OsString;
use std::process::ExitCode;

use ch09_many_spheres::field::{MAX_FIELD, field};
use ch09_many_spheres::{BINARY, chapter, like::take_like};

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().collect();
    let result = if args.iter().any(|a| {
        let a = a.to_string_lossy();
        a == "--generate-field" || a.starts_with("--generate-field=")
    }) {
        generate(&args[1..]).map(|text| {
            print!("{text}");
            ExitCode::SUCCESS
        })
    } else {
        take_like(args).map(|(like, rest)| raylab_cli::main_with_args(&chapter(like), rest))
    };
    result.unwrap_or_else(|message| {
        eprintln!("{BINARY}: error: {message}");
        ExitCode::from(2)
    })
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
