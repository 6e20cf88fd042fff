//! The shader's source, and naga's verdict on it before the GPU sees it.
//!
//! wgpu checks a shader too, but its error arrives as a block of text
//! about a pipeline. naga, the WGSL compiler inside wgpu, says where: so
//! the program parses and validates the file itself first, and a mistake
//! is one line, `tracer.wgsl:57:12: …`, that an editor can jump to.

use std::path::{Path, PathBuf};

use wgpu::naga;

/// The chapter's own tracer, built into the program.
pub const BUILT_IN: &str = include_str!("tracer.wgsl");

/// The name the built-in tracer goes by in messages.
pub const BUILT_IN_NAME: &str = "tracer.wgsl";

/// The chapter's source file, which `--watch` reloads when no `--shader`
/// is given (it exists where the workspace was built).
pub fn chapter_source() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src/tracer.wgsl")
}

/// A shader's text and the name its messages give it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Source {
    pub name: String,
    pub text: String,
}

impl Source {
    /// The tracer built into the program.
    pub fn built_in() -> Source {
        Source {
            name: BUILT_IN_NAME.into(),
            text: BUILT_IN.into(),
        }
    }

    /// A learner's shader file, named in messages as it was given.
    pub fn read(path: &Path) -> Result<Source, ShaderError> {
        let text = std::fs::read_to_string(path).map_err(|e| ShaderError::Read {
            path: path.to_owned(),
            message: e.to_string(),
        })?;
        Ok(Source {
            name: path.display().to_string(),
            text,
        })
    }
}

/// The start of the line of `tracer.wgsl` that sizes the ray stack.
pub const STACK_SIZE_LINE: &str = "const STACK_SIZE: u32 = ";

impl Source {
    /// The source with its ray stack sized for `max_depth`: the number on
    /// the line that starts with [`STACK_SIZE_LINE`] replaced, the lines
    /// left where they were (so naga's line numbers still fit the file).
    /// A shader without that line is used as it is.
    pub fn with_stack_size(&self, max_depth: u32) -> Source {
        let text = self
            .text
            .split_inclusive('\n')
            .map(|line| {
                if line.trim_start().starts_with(STACK_SIZE_LINE) {
                    let end = if line.ends_with('\n') { "\n" } else { "" };
                    format!("{STACK_SIZE_LINE}{max_depth}u;{end}")
                } else {
                    line.to_owned()
                }
            })
            .collect();
        Source {
            name: self.name.clone(),
            text,
        }
    }
}

/// Why a shader cannot be used; each is one line.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ShaderError {
    #[error("cannot read shader '{}': {message}", path.display())]
    Read { path: PathBuf, message: String },
    /// naga's message, at a line and column (1-based) of the file.
    #[error("{file}:{line}:{column}: {message}")]
    At {
        file: String,
        line: u32,
        column: u32,
        message: String,
    },
    /// naga's message where it names no place in the file.
    #[error("{file}: {message}")]
    Whole { file: String, message: String },
}

/// Parse and validate WGSL as wgpu would, and say where it is wrong.
pub fn check(source: &Source) -> Result<naga::Module, ShaderError> {
    let module = naga::front::wgsl::parse_str(&source.text).map_err(|error| {
        let message = error.message().to_owned();
        at(source, error.location(&source.text), message)
    })?;
    let mut validator = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    );
    validator.validate(&module).map_err(|error| {
        let message = one_line(error.as_inner());
        at(source, error.location(&source.text), message)
    })?;
    Ok(module)
}

fn at(source: &Source, location: Option<naga::SourceLocation>, message: String) -> ShaderError {
    let file = source.name.clone();
    match location {
        Some(place) => ShaderError::At {
            file,
            line: place.line_number,
            column: place.line_position,
            message,
        },
        None => ShaderError::Whole { file, message },
    }
}

/// An error and the errors it wraps, on one line: naga's validation
/// errors nest ("Function 'trace' is invalid: …: the cause").
fn one_line(error: &dyn std::error::Error) -> String {
    let mut text = error.to_string();
    let mut cause = error.source();
    while let Some(inner) = cause {
        text.push_str(": ");
        text.push_str(&inner.to_string());
        cause = inner.source();
    }
    text.replace('\n', " ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn named(text: &str) -> Source {
        Source {
            name: "tracer.wgsl".into(),
            text: text.into(),
        }
    }

    #[test]
    fn the_built_in_tracer_is_valid_wgsl() {
        check(&Source::built_in()).unwrap();
    }

    #[test]
    fn the_stack_is_sized_for_the_depth_on_its_own_line() {
        let built_in = Source::built_in();
        let sized = built_in.with_stack_size(10);
        assert!(sized.text.contains("\nconst STACK_SIZE: u32 = 10u;\n"));
        assert_eq!(sized.text.lines().count(), built_in.text.lines().count());
        check(&sized).unwrap();
        let max = raylab::stack::MAX_DEPTH_LIMIT;
        assert!(built_in.text.contains(&format!("{STACK_SIZE_LINE}{max}u;")));
    }

    #[test]
    fn an_unknown_name_is_reported_at_its_line_and_column() {
        let text = "fn f() -> f32 {\n    return 1.0;\n}\nfn g() -> f32 {\n    return foo;\n}\n";
        let error = check(&named(text)).unwrap_err();
        let ShaderError::At { line, column, .. } = &error else {
            panic!("{error}");
        };
        assert_eq!((*line, *column), (5, 12), "{error}");
        assert!(
            error.to_string().starts_with("tracer.wgsl:5:12: "),
            "{error}"
        );
        assert!(error.to_string().contains("foo"), "{error}");
    }

    #[test]
    fn a_function_that_can_end_without_returning_is_caught_by_the_validator() {
        // Parses, but one path through `f` returns nothing.
        let text = "fn f(x: f32) -> f32 {\n    if x > 0.0 {\n        return 1.0;\n    }\n}\n";
        let error = check(&named(text)).unwrap_err();
        assert!(error.to_string().starts_with("tracer.wgsl:"), "{error}");
        assert!(!error.to_string().contains('\n'));
    }
}
