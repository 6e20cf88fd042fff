//! `learn watch NAME`: check again after every save.
//!
//! The files are watched as every `--watch` of the workbook watches them
//! (`raylab_cli::saves`): by file events, and by looking twice a second
//! where the file system sends none.

use std::io::Write;
use std::sync::atomic::Ordering;
use std::time::Duration;

use raylab_cli::saves::{Saves, Watched, ctrl_c};

use learn::lab::Lab;
use learn::path::Item;

use crate::check::check;
use crate::core_check::check_core;
use crate::shader_check::check_shader;
use crate::verdict::Verdict;
use learn::limits::Limits;

/// Check, then check again after every save, until Ctrl-C.
pub fn watch(lab: &Lab, item: Item, out: &mut dyn Write) -> Result<(), String> {
    let (folder, check) = match item {
        Item::Core(core) => (
            lab.dir.join("core"),
            Box::new(move |out: &mut dyn Write| check_core(lab, core, Limits::DEFAULT, out))
                as Box<dyn Fn(&mut dyn Write) -> Verdict>,
        ),
        Item::Chapter(chapter) => (
            lab.folder(chapter),
            Box::new(move |out: &mut dyn Write| check(lab, chapter, out))
                as Box<dyn Fn(&mut dyn Write) -> Verdict>,
        ),
        // The shader is in my-lab/ch10/src/, as a chapter's sources are.
        Item::Shader => (
            lab.shader_folder(),
            Box::new(move |out: &mut dyn Write| check_shader(lab, Limits::DEFAULT, out))
                as Box<dyn Fn(&mut dyn Write) -> Verdict>,
        ),
    };
    let verdict = check(out);
    if verdict == Verdict::NoExercise {
        return Err("nothing to watch".into());
    }
    let stop = ctrl_c();
    let mut saves = Saves::new(vec![
        Watched::Tree(folder.join("src")),
        Watched::File(folder.join("Cargo.toml")),
    ])?;
    let _ = writeln!(
        out,
        "watching {}/src: save to check again (Ctrl-C to stop)",
        folder.display()
    );
    while !stop.load(Ordering::SeqCst) {
        if saves.saved(Duration::from_millis(20)).is_empty() {
            continue;
        }
        let _ = writeln!(out, "\n— saved: checking again —");
        check(out);
        let _ = out.flush();
    }
    let _ = writeln!(out, "stopped watching");
    Ok(())
}
