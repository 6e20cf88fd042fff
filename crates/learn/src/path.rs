//! The whole path, from the empty skeleton to chapter 10's shader: the
//! core's exercises and the chapters' steps in one order, each with the
//! name `start`, `check`, `watch` and `hint` take.

use crate::core::{CoreExercise, core_exercise};
use crate::exercise::{Exercise, exercise_named};
use crate::lab::{Lab, LabRecord};
use crate::shader;

/// One exercise of the path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Item {
    /// A region of the core (`src/`), by name: `sphere`.
    Core(&'static CoreExercise),
    /// A chapter's step, by number (`2`), or another of its regions, by
    /// name (`nee`).
    Chapter(&'static Exercise),
    /// Chapter 10's shader with the lab's three tasks blanked: `shader`.
    Shader,
}

/// The path, by name: each core piece just before the first chapter that
/// shows it in a picture, so that a learner who starts from the empty
/// skeleton sees their tracer grow chapter by chapter; the shader last,
/// where chapter 10 stands.
pub const PATH: [&str; 18] = [
    "ray", "camera", "sphere", "plane", "sky", "1", "srgb", "2", "reflect", "3", "refract", "4",
    "stack", "5", "6", "cosine", "nee", "shader",
];

/// The exercise called `name`: a core exercise's name, a chapter's
/// number (chapter 10's is the shader), or the name of a chapter's other
/// exercise.
pub fn find(name: &str) -> Option<Item> {
    if let Some(core) = core_exercise(name) {
        return Some(Item::Core(core));
    }
    if name == shader::NAME || name.trim_start_matches("ch").parse() == Ok(shader::CHAPTER) {
        return Some(Item::Shader);
    }
    exercise_named(name).map(Item::Chapter)
}

/// Every exercise, in the path's order.
pub fn items() -> impl Iterator<Item = Item> {
    PATH.iter().filter_map(|name| find(name))
}

/// The exercise to do after `name`: the first after it on the path that
/// is not passed yet.
pub fn next_after(name: &str, progress: &LabRecord) -> Option<Item> {
    items()
        .skip_while(|item| item.name() != name)
        .skip(1)
        .find(|item| !item.passed(progress))
}

/// The line a pass ends with: the next exercise and the command that
/// starts it, or the end of the path.
pub fn next_line(name: &str, progress: &LabRecord) -> String {
    match next_after(name, progress) {
        Some(item) => format!(
            "Next: `{}`, {}: cargo run -p learn -- start {}",
            item.name(),
            item.title(),
            item.name()
        ),
        None => "That was the last exercise not yet passed: the whole path is done \
                 (`cargo run -p learn -- list`)."
            .to_owned(),
    }
}

/// The names, as the error messages list them.
pub fn names() -> String {
    PATH.join(", ")
}

impl Item {
    /// The name `start` and `check` take.
    pub fn name(&self) -> String {
        match self {
            Item::Core(core) => core.name.to_owned(),
            Item::Chapter(chapter) => chapter.name(),
            Item::Shader => shader::NAME.to_owned(),
        }
    }

    /// What it builds, in a few words.
    pub fn title(&self) -> String {
        match self {
            Item::Core(core) => format!("core: {}", core.title),
            Item::Chapter(chapter) => format!("chapter {}: {}", chapter.number, chapter.title),
            Item::Shader => format!("chapter {}: {}", shader::CHAPTER, shader::TITLE),
        }
    }

    /// Its hints, in the order `learn hint` gives them: a nudge (what to
    /// think about), the rule (what the code must do), the recipe (how).
    pub fn hints(&self) -> [&'static str; 3] {
        match self {
            Item::Core(core) => [core.nudge, core.rule, core.hint],
            Item::Chapter(chapter) => [chapter.nudge, chapter.rule, chapter.hint],
            Item::Shader => [shader::NUDGE, shader::RULE, shader::HINT],
        }
    }

    /// The book's page for it, from the workspace's root.
    pub fn page(&self) -> &'static str {
        match self {
            Item::Core(core) => core.page(),
            Item::Chapter(chapter) => chapter.page,
            Item::Shader => shader::PAGE,
        }
    }

    pub fn passed(&self, progress: &LabRecord) -> bool {
        match self {
            Item::Core(core) => progress.core.contains(core.name),
            Item::Chapter(chapter) => match chapter.name {
                None => progress.passed.contains(&chapter.number),
                Some(name) => progress.named.contains(name),
            },
            Item::Shader => progress.passed.contains(&shader::CHAPTER),
        }
    }

    pub fn started(&self, lab: &Lab) -> bool {
        match self {
            Item::Core(core) => lab.core_started(core),
            Item::Chapter(chapter) => lab.folder(chapter).join("src/lib.rs").is_file(),
            Item::Shader => lab.shader_started(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::CORE_EXERCISES;
    use crate::exercise::EXERCISES;

    #[test]
    fn after_a_pass_the_next_exercise_is_the_first_later_one_not_passed() {
        let mut progress = LabRecord::default();
        assert_eq!(
            next_after("ray", &progress).map(|i| i.name()),
            Some("camera".into())
        );
        progress.core.insert("camera".into());
        assert_eq!(
            next_after("ray", &progress).map(|i| i.name()),
            Some("sphere".into())
        );
        assert_eq!(next_after("shader", &progress), None);
        assert!(next_line("sky", &progress).ends_with("cargo run -p learn -- start 1"));
    }

    #[test]
    fn every_exercise_has_three_levels_of_hint_each_one_line() {
        for item in items() {
            for hint in item.hints() {
                assert!(!hint.is_empty() && !hint.contains("  ") && !hint.contains('\n'));
            }
        }
    }

    #[test]
    fn the_path_holds_every_exercise_once() {
        let all = items().count();
        assert_eq!(all, PATH.len());
        assert_eq!(all, CORE_EXERCISES.len() + EXERCISES.len() + 1);
    }

    #[test]
    fn a_chapter_is_found_by_its_number_and_a_core_exercise_by_its_name() {
        assert_eq!(find("2").map(|i| i.name()), Some("2".into()));
        assert_eq!(find("ch02").map(|i| i.name()), Some("2".into()));
        assert_eq!(find("refract").map(|i| i.name()), Some("refract".into()));
        assert_eq!(find("shader"), Some(Item::Shader));
        assert_eq!(find("10"), Some(Item::Shader));
        assert_eq!(find("nee").map(|i| i.name()), Some("nee".into()));
        assert_eq!(find("9"), None);
        assert_eq!(find("spheres"), None);
    }
}
