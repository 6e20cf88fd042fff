//! The marked regions of a source file, for the core's exercises: a file
//! handed out with its regions blanked *and its markers kept*, and the
//! learner's regions spliced back into the reference.
//!
//! A chapter's exercise is the chapter's whole crate, all of it the
//! learner's. The core's exercises share files (`optics.rs` holds both
//! `reflect` and `refract`), and a learner may write them in any order, so
//! the core the check builds takes from the learner only the regions of
//! the exercise being checked and of those already passed, and the
//! reference's for the rest. The marker lines are how it finds them.

use crate::exercise::{MarkerError, Task};

const START: &str = "// ANCHOR: todo_";
const END: &str = "// ANCHOR_END: todo_";

/// A source cut at its markers: text outside any region, and regions.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Piece {
    Text(String),
    Region {
        task: Task,
        /// The opening marker line, the body, the closing marker line.
        open: String,
        body: String,
        close: String,
    },
}

fn cut(source: &str) -> Result<Vec<Piece>, MarkerError> {
    let mut pieces = Vec::new();
    let mut text = String::new();
    let mut open: Option<(usize, Task, String, String)> = None;
    for (n, line) in source.lines().enumerate() {
        let number = n + 1;
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix(START) {
            if let Some((at, task, ..)) = &open {
                return Err(MarkerError {
                    line: number,
                    what: format!("`{}` opened on line {at} is not closed", task.name),
                });
            }
            let task = crate::exercise::parse_start(rest).ok_or_else(|| MarkerError {
                line: number,
                what: "a todo marker is `// ANCHOR: todo_NAME \"one-line task\"`".into(),
            })?;
            pieces.push(Piece::Text(std::mem::take(&mut text)));
            open = Some((number, task, format!("{line}\n"), String::new()));
        } else if let Some(name) = trimmed.strip_prefix(END) {
            match open.take() {
                Some((_, task, first, body)) if task.name == name.trim() => {
                    pieces.push(Piece::Region {
                        task,
                        open: first,
                        body,
                        close: format!("{line}\n"),
                    });
                }
                _ => {
                    return Err(MarkerError {
                        line: number,
                        what: format!("`{}` is closed but not open", name.trim()),
                    });
                }
            }
        } else if let Some((.., body)) = &mut open {
            body.push_str(line);
            body.push('\n');
        } else {
            text.push_str(line);
            text.push('\n');
        }
    }
    if let Some((at, task, ..)) = open {
        return Err(MarkerError {
            line: at,
            what: format!("`{}` is never closed", task.name),
        });
    }
    pieces.push(Piece::Text(text));
    Ok(pieces)
}

/// The names of the regions of `source`, in order.
pub fn region_names(source: &str) -> Result<Vec<String>, MarkerError> {
    Ok(cut(source)?
        .into_iter()
        .filter_map(|piece| match piece {
            Piece::Region { task, .. } => Some(task.name),
            Piece::Text(_) => None,
        })
        .collect())
}

/// `source` with every region's body replaced by `todo!("task")`, its
/// marker lines kept so that the check can find the learner's code.
pub fn blank_keeping_markers(source: &str) -> Result<String, MarkerError> {
    let mut out = String::with_capacity(source.len());
    for piece in cut(source)? {
        match piece {
            Piece::Text(text) => out.push_str(&text),
            Piece::Region {
                task, open, close, ..
            } => {
                let indent = &open[..open.len() - open.trim_start().len()];
                out.push_str(&open);
                out.push_str(&format!("{indent}todo!({:?})\n", task.text));
                out.push_str(&close);
            }
        }
    }
    Ok(out)
}

/// Why a learner's file cannot be spliced.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SpliceError {
    #[error("{0}")]
    Marker(MarkerError),
    #[error(
        "the marker lines of `{0}` are gone: put `// ANCHOR: todo_{0} …` and `// ANCHOR_END: todo_{0}` back around your code (the check takes it from between them)"
    )]
    Missing(String),
}

/// The reference `source` with the bodies of the regions `take` picks
/// replaced by the learner's. When `take` picks every region of the file,
/// the learner's whole file is used, whatever else they changed in it.
pub fn splice(
    reference: &str,
    learner: &str,
    take: impl Fn(&str) -> bool,
) -> Result<String, SpliceError> {
    let pieces = cut(reference).map_err(SpliceError::Marker)?;
    let regions: Vec<&Task> = pieces
        .iter()
        .filter_map(|p| match p {
            Piece::Region { task, .. } => Some(task),
            Piece::Text(_) => None,
        })
        .collect();
    if regions.iter().all(|task| take(&task.name)) {
        return Ok(learner.to_owned());
    }
    let theirs = cut(learner).map_err(SpliceError::Marker)?;
    let mut out = String::with_capacity(reference.len());
    for piece in &pieces {
        match piece {
            Piece::Text(text) => out.push_str(text),
            Piece::Region {
                task,
                open,
                body,
                close,
            } => {
                out.push_str(open);
                if take(&task.name) {
                    let mine = theirs.iter().find_map(|p| match p {
                        Piece::Region { task: t, body, .. } if t.name == task.name => Some(body),
                        _ => None,
                    });
                    out.push_str(mine.ok_or_else(|| SpliceError::Missing(task.name.clone()))?);
                } else {
                    out.push_str(body);
                }
                out.push_str(close);
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const REFERENCE: &str = "\
fn a() -> u32 {
    // ANCHOR: todo_a \"Return 1.\"
    1
    // ANCHOR_END: todo_a
}
fn b() -> u32 {
    // ANCHOR: todo_b \"Return 2.\"
    2
    // ANCHOR_END: todo_b
}
";

    #[test]
    fn a_blanked_file_keeps_its_markers_around_each_todo() {
        let blanked = blank_keeping_markers(REFERENCE).unwrap();
        assert!(blanked.contains(
            "    // ANCHOR: todo_a \"Return 1.\"\n    todo!(\"Return 1.\")\n    // ANCHOR_END: todo_a\n"
        ));
        assert_eq!(region_names(&blanked).unwrap(), ["a", "b"]);
    }

    #[test]
    fn only_the_regions_taken_come_from_the_learner() {
        let learner = REFERENCE
            .replace("    1\n", "    10\n")
            .replace("    2\n", "    20\n");
        let spliced = splice(REFERENCE, &learner, |name| name == "b").unwrap();
        assert!(
            spliced.contains("    1\n") && spliced.contains("    20\n"),
            "{spliced}"
        );
    }

    #[test]
    fn when_every_region_is_taken_the_learners_whole_file_is_used() {
        let learner = format!("use std::f32::consts::PI;\n{REFERENCE}");
        assert_eq!(splice(REFERENCE, &learner, |_| true).unwrap(), learner);
    }

    #[test]
    fn a_region_whose_markers_the_learner_removed_is_named() {
        let learner = "fn a() -> u32 { 10 }\nfn b() -> u32 { 2 }\n";
        assert_eq!(
            splice(REFERENCE, learner, |name| name == "a"),
            Err(SpliceError::Missing("a".into()))
        );
    }
}
