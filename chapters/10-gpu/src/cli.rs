//! The program: the shared command line, with `--like` and `--shader`,
//! and what runs when.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, FromArgMatches};
use raylab_cli::{CliError, CommonFlags, Program, usage_line};

use crate::BINARY;
use crate::gpu::Gpu;
use crate::like::Like;
use crate::run::{self, Error};
use crate::shader::{self, Source};

/// The program's name and defaults when it traces as `like`.
pub fn program(like: Like) -> Program {
    let defaults = like.defaults();
    Program {
        binary: BINARY,
        about: "Chapter 10, the lab as it ran: the tracer as a WGSL compute shader, one invocation \
                per pixel, reloaded on save with --watch. --like ch01-ray-cast … ch05-antialiasing \
                traces as that chapter does, with its defaults (default: ch05-antialiasing).",
        max_depth: defaults.max_depth,
        spp: defaults.spp,
    }
}

/// The flags only this chapter has. `--probe` and `--sweep` trace ray by
/// ray on the CPU, so this program, which traces on the GPU, has none.
#[derive(Args, Debug, Clone, PartialEq)]
pub struct GpuFlags {
    /// Trace with this WGSL file instead of the built-in tracer.wgsl (copy chapters/10-gpu/src/tracer.wgsl to start)
    #[arg(long, value_name = "FILE")]
    pub shader: Option<PathBuf>,

    /// Render again whenever the shader (--shader, or this chapter's src/tracer.wgsl) or the --scene file is saved, until Ctrl-C
    #[arg(long)]
    pub watch: bool,
}

/// The flags every program takes, with this chapter's defaults, and its own.
pub fn command() -> clap::Command {
    let command = CommonFlags::command(&program(Like::AntiAliasing)).arg(raylab_like::arg());
    GpuFlags::augment_args(command).after_help(format!(
        "Needs a Vulkan adapter (lavapipe runs it on the CPU). Set {}=1 to act as if there were none.",
        crate::gpu::NO_ADAPTER_VAR
    ))
}

/// The whole program: parse, check the shader, find the GPU, render (or
/// watch). Bad input gives one line on stderr and exit code 2.
pub fn main() -> ExitCode {
    raylab_cli::main_of(BINARY, command(), std::env::args_os(), |matches| {
        let usage = |e: clap::Error| CliError::Usage(usage_line(&e));
        let mut options = CommonFlags::from_arg_matches(matches).map_err(usage)?;
        let like = raylab_like::chosen(matches, &mut options.max_depth, &mut options.spp);
        let flags = GpuFlags::from_arg_matches(matches).map_err(usage)?;
        run_program(like, &options, &flags).map_err(|error| match error {
            Error::Cli(error) => error,
            other => CliError::Usage(other.to_string()),
        })
    })
}

fn run_program(like: Like, options: &CommonFlags, flags: &GpuFlags) -> Result<(), Error> {
    options.settings()?;
    // Everything the learner gave is read and checked before the GPU is
    // looked for: a broken shader or scene is reported on any machine.
    let scene = run::load_scene(options)?;
    let shader_file = flags.shader.clone().or_else(|| {
        let own = shader::chapter_source();
        (flags.watch && own.is_file()).then_some(own)
    });
    if flags.watch && shader_file.is_none() && options.scene.is_none() {
        return Err(Error::Usage(
            "--watch needs a file to watch: --shader FILE or --scene FILE".into(),
        ));
    }
    let source = match &shader_file {
        Some(path) => Source::read(path)?,
        None => Source::built_in(),
    };
    shader::check(&source)?;

    let gpu = Gpu::new()?;
    let tracer = gpu.compile(&source, options.max_depth)?;
    if flags.watch {
        return crate::watch::watch(&gpu, tracer, like, options, shader_file.as_deref());
    }
    let report = run::render(&gpu, &tracer, like, options, &scene)?;
    if !options.quiet {
        print!("{}", run::report_text(&report, &tracer, &gpu));
    }
    Ok(())
}
