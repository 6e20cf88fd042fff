//! The entry points: a chapter program's whole `main`, and the `main` of
//! any program on the shared command line.

use std::ffi::OsString;
use std::process::ExitCode;

use clap::FromArgMatches;

use crate::error::{CliError, usage_line};
use crate::flags::Options;
use crate::program::Chapter;
use crate::report::print_report;
use crate::run::run;
use crate::watch;
use raylab::trace::Step;

/// A chapter program's whole `main`: parse, render, write, report.
/// Bad input gives one line on stderr and exit code 2.
pub fn main<S: Step>(chapter: &Chapter<S>) -> ExitCode {
    main_with_args(chapter, std::env::args_os())
}

/// [`main`] with the arguments given (the first is the program's name),
/// for a test or a program that hands its own arguments.
pub fn main_with_args<S: Step>(
    chapter: &Chapter<S>,
    args: impl IntoIterator<Item = impl Into<OsString> + Clone>,
) -> ExitCode {
    let command = Options::command(&chapter.program());
    main_of(chapter.binary, command, args, |matches| {
        let options =
            Options::from_arg_matches(matches).map_err(|e| CliError::Usage(usage_line(&e)))?;
        run_options(chapter, &options)
    })
}

/// What a chapter's program does once its options are parsed: render and
/// report, or render again on every save with `--watch`.
pub fn run_options<S: Step>(chapter: &Chapter<S>, options: &Options) -> Result<(), CliError> {
    if options.ray_tree.watch {
        return watch::watch(chapter, options);
    }
    let report = run(chapter, options)?;
    // Quiet or not: with --quiet the report is only what was asked for.
    print_report(chapter, options, &report);
    Ok(())
}

/// The `main` of every program on the shared command line, the Whitted
/// chapters' and the path tracers' alike: parse `args` with `command` (the
/// shared flags, and any of the program's own), hand the matches to `run`,
/// and [`exit`]. `--help` and `--version` print and stop; any other
/// parsing error is the one line of [`usage_line`] and exit code 2, like
/// every error `run` gives.
pub fn main_of(
    binary: &str,
    command: clap::Command,
    args: impl IntoIterator<Item = impl Into<OsString> + Clone>,
    run: impl FnOnce(&clap::ArgMatches) -> Result<(), CliError>,
) -> ExitCode {
    let matches = match command.try_get_matches_from(args) {
        Ok(matches) => matches,
        Err(e) => {
            if matches!(
                e.kind(),
                clap::error::ErrorKind::DisplayHelp | clap::error::ErrorKind::DisplayVersion
            ) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            return exit(binary, Err(CliError::Usage(usage_line(&e))));
        }
    };
    exit(binary, run(&matches))
}

/// The exit of every chapter program: success (a render written, or the end
/// of `--watch` by Ctrl-C), or one line on stderr and exit code 2.
pub fn exit(binary: &str, result: Result<(), CliError>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("{binary}: error: {error}");
            ExitCode::from(2)
        }
    }
}
