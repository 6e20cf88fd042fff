//! `learn-check <check|watch> NAME`: the program `cargo run -p learn --
//! check NAME` and `watch NAME` run, once `learn` has built it. `learn`
//! has already found the exercise and seen that it is started; this says
//! the same things itself when it is run on its own.

use std::io::Write;
use std::process::ExitCode;

use learn::lab::{Lab, workspace_root};
use learn::path::{self, Item};
use learn_check::check::{Limits, Verdict, check};
use learn_check::core_check::check_core;
use learn_check::shader_check::check_shader;

/// Why the command could not run: one line, exit code 2.
fn usage(line: &str) -> ExitCode {
    eprintln!("learn-check: error: {line}");
    ExitCode::from(2)
}

/// 0 for a pass, 1 for work still to do, 2 for a check that could not run.
fn exit_for(verdict: &Verdict) -> ExitCode {
    match verdict {
        Verdict::Passed => ExitCode::SUCCESS,
        Verdict::NoExercise | Verdict::Broken(_) => ExitCode::from(2),
        _ => ExitCode::from(1),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [command, name] = args.as_slice() else {
        return usage(
            "say `check NAME` or `watch NAME`; a learner runs it as `cargo run -p learn -- check NAME`",
        );
    };
    let Some(item) = path::find(name) else {
        return usage(&format!(
            "there is no exercise `{name}`: the exercises are {}",
            path::names()
        ));
    };
    let Some(root) = std::env::current_dir()
        .ok()
        .and_then(|here| workspace_root(&here))
    else {
        return usage("run it inside the raylab workspace: `cargo run -p learn -- check NAME`");
    };
    let lab = Lab::in_workspace(&root);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    match command.as_str() {
        "check" => {
            let verdict = match item {
                Item::Core(core) => check_core(&lab, core, Limits::DEFAULT, &mut out),
                Item::Chapter(chapter) => check(&lab, chapter, &mut out),
                Item::Shader => check_shader(&lab, Limits::DEFAULT, &mut out),
            };
            let _ = out.flush();
            exit_for(&verdict)
        }
        "watch" => match learn_check::watch::watch(&lab, item, &mut out) {
            Ok(()) => ExitCode::SUCCESS,
            Err(why) => usage(&why),
        },
        other => usage(&format!(
            "no command `{other}`: say `check NAME` or `watch NAME`"
        )),
    }
}
