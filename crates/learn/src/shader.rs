//! Chapter 10's exercise: the shader with the lab's three tasks blanked,
//! as the 2016 student had them: the shadow feeler, the reflection push
//! and the refraction push, in `trace_ray` of `tracer.wgsl`.
//!
//! The regions are marked in the shader as the chapters mark their steps
//! (`// ANCHOR: todo_NAME "task"` … `// ANCHOR_END: todo_NAME`). WGSL has
//! no `todo!`, so a blanked region becomes a comment, `// TODO: task`: the
//! shader still compiles and renders, visibly wrong (no feeler, no
//! shadows; no push, no mirror or glass), which is what the check's
//! pictures then show.

use std::path::PathBuf;

use crate::exercise::{Blanked, MarkerError, Task, blank_with};
use crate::lab::{Lab, LabError, Started, read, write_new};

/// The name `start`, `check`, `watch` and `hint` take.
pub const NAME: &str = "shader";

/// The chapter it belongs to, as `progress.toml` records its pass.
pub const CHAPTER: u8 = 10;

/// The reference shader, from the workspace's root.
pub const SOURCE: &str = "chapters/10-gpu/src/tracer.wgsl";

/// The learner's copy, from their exercise's folder (`my-lab/ch10/`): in
/// `src/`, as in the chapter, where `watch` looks for saves.
pub const FILE: &str = "src/tracer.wgsl";

/// The program that renders with it.
pub const PACKAGE: &str = "ch10-gpu";

/// The book's page for it, from the workspace's root.
pub const PAGE: &str = "book/src/ch10-gpu.md";

/// What the learner writes, for `learn list`.
pub const TITLE: &str = "the shader's feeler, reflection and refraction";

/// `learn hint`'s first level: a nudge.
pub const NUDGE: &str = "The shader's three gaps are the CPU chapters' three steps, in WGSL: the \
     feeler (chapter 2), the reflection push (chapter 3) and the refraction push (chapter 4).";

/// Its second: the rules.
pub const RULE: &str = "Every new ray starts `params.epsilon` along its direction; a push's \
     weight is its share alone (`push` multiplies in the parent's); eta is 1/ior going in and ior \
     coming out, and WGSL's `refract` returns all zeros past the critical angle.";

/// Its third: what to do (the recipe), for `learn hint`.
pub const HINT: &str = "Three regions of `trace_ray` in my-lab/ch10/src/tracer.wgsl, each a \
     `// TODO:` where the lab's code was: as handed out the shader compiles and renders, with no \
     shadows (no feeler), and mirror and glass showing only their own colour (no push). The \
     feeler: start it `params.epsilon` along `params.to_sun` from `hit.point` (from the point \
     itself, rounding puts half the starts inside the surface: shadow acne), count it \
     (`count(work, SHADOW)`, `work.rays += 1u`) and set k = SUN_IN_SHADOW when `any_hit` finds \
     anything. A push fills `reflected` or `transmitted` with `Pending(start, d, share, 0u, KIND)` \
     (the weight is the share, r or t: `push` multiplies in the parent's) and takes the share off \
     `kept`. Reflection: d = normalize(reflect(ray.direction, hit.facing_normal)). Refraction: eta \
     = 1/ior going in (`hit.entering`), ior coming out; WGSL's `refract` returns all zeros past \
     the critical angle: then send t along the mirror direction as TOTAL_INTERNAL, else along \
     normalize(bent) as REFRACTED. Every new ray starts `params.epsilon` along its direction.";

/// One picture of the check: the shader traced like a chapter, compared
/// with that chapter's own render. Each chapter adds one task's effect to
/// the one before, so the first picture that differs names the task.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stage {
    /// The chapter traced like (`--like`) and compared with.
    pub chapter: u8,
    pub package: &'static str,
    /// What that chapter's picture adds, in a few words.
    pub shows: &'static str,
    /// The region it judges, by its marker name.
    pub region: &'static str,
    /// That region's task, in a few words.
    pub task: &'static str,
    /// A scene file (from the workspace's root) instead of the lab scene.
    pub scene: Option<&'static str>,
}

/// The check's pictures, in order: chapter 2 judges the feeler (its
/// shadows), chapter 3 the reflection push (the mirror), chapter 4 the
/// refraction push (the glass), and chapter 4 again, under water, its
/// total internal reflection: a ray that enters a sphere is never totally
/// reflected inside it, so the lab scene has none to judge. Chapter 4
/// alone shows all three tasks, but a mismatch there could be any of
/// them; chapter 5 adds only where a pixel's rays go, which the program
/// decides, not the shader's tasks.
pub const STAGES: [Stage; 4] = [
    Stage {
        chapter: 2,
        package: "ch02-shadows",
        shows: "the shadows",
        region: "shadow_feeler",
        task: "the feeler",
        scene: None,
    },
    Stage {
        chapter: 3,
        package: "ch03-reflection",
        shows: "the mirror's reflections",
        region: "reflection",
        task: "the reflection push",
        scene: None,
    },
    Stage {
        chapter: 4,
        package: "ch04-refraction",
        shows: "the glass's refraction",
        region: "refraction",
        task: "the refraction push",
        scene: None,
    },
    Stage {
        chapter: 4,
        package: "ch04-refraction",
        shows: "total internal reflection (Snell's window, seen from under water)",
        region: "refraction",
        task: "the refraction push past the critical angle",
        scene: Some("scenes/total-internal-reflection.toml"),
    },
];

impl Stage {
    /// How the check names it: `like ch02-shadows`, and the scene if it
    /// is not the lab's.
    pub fn label(&self) -> String {
        match self.scene {
            Some(scene) => format!("like {} on {scene}", self.package),
            None => format!("like {}", self.package),
        }
    }
}

/// The shader with its regions blanked: the body of each replaced by one
/// comment line, `// TODO: task`, at the marker's indent.
pub fn blank_shader(source: &str) -> Result<Blanked, MarkerError> {
    blank_with(source, |indent, task: &Task| {
        format!("{indent}// TODO: {}\n", task.text)
    })
}

impl Lab {
    /// The shader exercise's folder, `my-lab/ch10/`.
    pub fn shader_folder(&self) -> PathBuf {
        self.dir.join(format!("ch{CHAPTER:02}"))
    }

    /// The learner's shader, `my-lab/ch10/src/tracer.wgsl`.
    pub fn shader_file(&self) -> PathBuf {
        self.shader_folder().join(FILE)
    }

    /// The reference shader, the chapter's own.
    pub fn shader_reference(&self) -> PathBuf {
        self.root.join(SOURCE)
    }

    /// Where the check writes its renders and images.
    pub fn shader_check_dir(&self) -> PathBuf {
        self.shader_folder().join("check")
    }

    pub fn shader_started(&self) -> bool {
        self.shader_file().is_file()
    }

    /// The reference shader, blanked (or, for the author checks, solved:
    /// the markers taken out and nothing else), and its tasks.
    pub fn shader_text(&self, solved: bool) -> Result<(String, Vec<Task>), LabError> {
        let path = self.shader_reference();
        let blanked =
            blank_shader(&read(&path)?).map_err(|source| LabError::Marker { path, source })?;
        let text = if solved {
            blanked.solution
        } else {
            blanked.exercise
        };
        Ok((text, blanked.tasks))
    }

    /// Lay the shader into `my-lab/ch10/src/`; a file already there is
    /// never touched.
    pub fn start_shader(&self, solved: bool) -> Result<Started, LabError> {
        let (text, _) = self.shader_text(solved)?;
        let mut started = Started {
            folder: self.shader_folder(),
            written: Vec::new(),
            kept: Vec::new(),
        };
        if write_new(&self.shader_file(), &text)? {
            started.written.push(PathBuf::from(FILE));
        } else {
            started.kept.push(PathBuf::from(FILE));
        }
        Ok(started)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reference() -> String {
        let path = format!("{}/../../{SOURCE}", env!("CARGO_MANIFEST_DIR"));
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
    }

    #[test]
    fn the_shader_marks_one_region_for_each_stage_of_the_check() {
        let blanked = blank_shader(&reference()).unwrap();
        let names: Vec<&str> = blanked.tasks.iter().map(|t| t.name.as_str()).collect();
        let stages: Vec<&str> = STAGES.iter().map(|s| s.region).collect();
        assert_eq!(names.len(), 3);
        for stage in &STAGES {
            if let Some(scene) = stage.scene {
                let path = format!("{}/../../{scene}", env!("CARGO_MANIFEST_DIR"));
                assert!(std::path::Path::new(&path).is_file(), "{path}");
            }
        }
        for stage in stages {
            assert!(names.contains(&stage), "{names:?}");
        }
    }

    #[test]
    fn a_blanked_region_is_a_todo_comment_at_the_markers_indent() {
        let blanked = blank_shader(&reference()).unwrap();
        for task in &blanked.tasks {
            let line = format!("        // TODO: {}\n", task.text);
            assert!(blanked.exercise.contains(&line), "{line}");
        }
        assert!(!blanked.exercise.contains("ANCHOR: todo_"));
        assert!(!blanked.exercise.contains("any_hit(feeler"));
    }

    #[test]
    fn the_hint_is_printed_without_runs_of_spaces() {
        assert!(!HINT.contains("  ") && !HINT.contains('\n'), "{HINT:?}");
    }
}
