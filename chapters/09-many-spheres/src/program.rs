//! Chapter 9's command line: the shared one with `--like`, as every
//! program that traces as chapters 1–5 do, and `generate-field`, a
//! command of its own that writes a scene file instead of rendering.

use std::ffi::OsString;
use std::io::Write;
use std::process::ExitCode;

use clap::{Args, FromArgMatches};
use raylab_cli::{CliError, usage_line};

use crate::field::{MAX_FIELD, field};
use crate::{BINARY, Like, chapter};

/// The name of the command that prints a field of spheres.
pub const GENERATE_FIELD: &str = "generate-field";

/// `generate-field N [--seed S]`: a scene file of `N` random spheres.
#[derive(Args, Debug, Clone, Copy, PartialEq, Eq)]
pub struct FieldFlags {
    /// How many spheres, 0 to the most a scene file holds
    #[arg(value_name = "N", allow_negative_numbers = true,
          value_parser = clap::value_parser!(u64).range(0..=MAX_FIELD as u64))]
    pub spheres: u64,

    /// The seed that places them: the same N and seed give the same file
    #[arg(
        long,
        value_name = "S",
        default_value_t = 0,
        allow_negative_numbers = true
    )]
    pub seed: u64,
}

/// The program's whole command line: the shared flags with `--like`, and
/// `generate-field`, which takes none of them.
pub fn command() -> clap::Command {
    let field =
        FieldFlags::augment_args(clap::Command::new(GENERATE_FIELD).about(
            "Print a scene file of N random spheres on the lab's ground, placed by the seed",
        ));
    raylab_like::command(&chapter(Like::AntiAliasing))
        .subcommand(field)
        .args_conflicts_with_subcommands(true)
}

/// Chapter 9's `main`: render through the tree (as `--like` says), or
/// print a field of spheres. Bad input is one line and exit code 2.
pub fn main(args: impl IntoIterator<Item = impl Into<OsString> + Clone>) -> ExitCode {
    raylab_cli::main_of(BINARY, command(), args, |matches| {
        match matches.subcommand() {
            Some((GENERATE_FIELD, flags)) => {
                let flags = FieldFlags::from_arg_matches(flags)
                    .map_err(|e| CliError::Usage(usage_line(&e)))?;
                print_field(flags);
                Ok(())
            }
            _ => raylab_like::run(matches, chapter),
        }
    })
}

/// Print the field's scene file. A reader that stops reading is not an
/// error: what it read is whole lines of a scene file.
fn print_field(flags: FieldFlags) {
    let text = field(flags.spheres as usize, flags.seed);
    if let Err(error) = std::io::stdout().lock().write_all(text.as_bytes())
        && error.kind() != std::io::ErrorKind::BrokenPipe
    {
        eprintln!("{BINARY}: could not print the field: {error}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<clap::ArgMatches, String> {
        command()
            .try_get_matches_from(args)
            .map_err(|e| usage_line(&e))
    }

    fn field_flags(args: &[&str]) -> Result<FieldFlags, String> {
        let matches = parse(args)?;
        let (name, flags) = matches.subcommand().ok_or("no command")?;
        assert_eq!(name, GENERATE_FIELD);
        FieldFlags::from_arg_matches(flags).map_err(|e| usage_line(&e))
    }

    #[test]
    fn generate_field_takes_a_count_and_a_seed_that_defaults_to_zero() {
        assert_eq!(
            field_flags(&[BINARY, "generate-field", "500", "--seed", "1"]),
            Ok(FieldFlags {
                spheres: 500,
                seed: 1
            })
        );
        assert_eq!(
            field_flags(&[BINARY, "generate-field", "7"]),
            Ok(FieldFlags {
                spheres: 7,
                seed: 0
            })
        );
    }

    #[test]
    fn a_field_too_large_or_negative_or_missing_is_refused_in_one_line() {
        for bad in [
            &[BINARY, "generate-field", "1000001"][..],
            &[BINARY, "generate-field", "-3"],
            &[BINARY, "generate-field"],
            &[BINARY, "generate-field", "5", "--seed", "x"],
        ] {
            let err = field_flags(bad).unwrap_err();
            assert!(!err.contains('\n'), "{err}");
        }
        let too_many = field_flags(&[BINARY, "generate-field", &(MAX_FIELD + 1).to_string()]);
        assert!(too_many.unwrap_err().contains(&MAX_FIELD.to_string()));
    }

    #[test]
    fn render_flags_cannot_go_with_generate_field() {
        let err = parse(&[BINARY, "--width", "80", "generate-field", "5"]).unwrap_err();
        assert!(err.contains("generate-field"), "{err}");
        assert!(parse(&[BINARY, "generate-field", "5", "--width", "80"]).is_err());
    }

    #[test]
    fn without_a_command_it_renders_with_like() {
        let matches = parse(&[BINARY, "--like", "ch03", "--width", "80"]).unwrap();
        assert!(matches.subcommand().is_none());
        assert_eq!(
            matches.get_one::<Like>(raylab_like::ID),
            Some(&Like::Reflection)
        );
    }
}
