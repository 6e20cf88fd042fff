//! The book's formulas, turned from TeX into MathML when the book is built.
//!
//! The pages write formulas as mdBook's MathJax would read them, `\\( … \\)`
//! inline and `\\[ … \\]` on their own line. MathJax would fetch a script
//! from the network when the page is opened; this preprocessor instead
//! writes each formula as MathML into the page, which every current browser
//! draws by itself. A formula that does not convert stops the build with
//! the page and the formula named, so no page ever shows raw TeX.

use std::ops::Range;

use mdbook_driver::book::{Book, BookItem};
use mdbook_preprocessor::errors::{Error, Result};
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};
use pulldown_cmark::{Event, Options, Parser, Tag};
use pulldown_latex::config::DisplayMode;
use pulldown_latex::{RenderConfig, Storage};

/// The mdBook preprocessor that writes every formula as MathML.
pub struct Formulas;

impl Preprocessor for Formulas {
    fn name(&self) -> &str {
        "raylab-formulas"
    }

    fn run(&self, _ctx: &PreprocessorContext, mut book: Book) -> Result<Book> {
        let mut failure = None;
        book.for_each_mut(|item| {
            let BookItem::Chapter(chapter) = item else {
                return;
            };
            if failure.is_some() {
                return;
            }
            match to_mathml(&chapter.content) {
                Ok(page) => chapter.content = page,
                Err(error) => {
                    let page = chapter
                        .source_path
                        .as_ref()
                        .map_or(chapter.name.clone(), |p| p.display().to_string());
                    failure = Some(Error::msg(format!("{page}: {error}")));
                }
            }
        });
        match failure {
            Some(error) => Err(error),
            None => Ok(book),
        }
    }

    fn supports_renderer(&self, renderer: &str) -> Result<bool> {
        Ok(renderer == "html")
    }
}

/// A formula that could not be turned into MathML.
#[derive(Debug, PartialEq, Eq, thiserror::Error)]
pub enum FormulaError {
    #[error("the formula `{tex}` does not convert to MathML: {reason}")]
    Convert { tex: String, reason: String },
    #[error("a formula opened with `{open}` near `{start}` is never closed with `{close}`")]
    Unclosed {
        open: &'static str,
        close: &'static str,
        start: String,
    },
}

/// The two kinds of formula, as the markdown source spells their
/// delimiters (a markdown `\\` is one backslash on the page).
const DELIMITERS: [(&str, &str, DisplayMode); 2] = [
    (r"\\(", r"\\)", DisplayMode::Inline),
    (r"\\[", r"\\]", DisplayMode::Block),
];

/// A markdown page with every formula outside code written as MathML.
pub fn to_mathml(page: &str) -> std::result::Result<String, FormulaError> {
    let code = code_ranges(page);
    let in_code = |at: usize| code.iter().any(|r| r.contains(&at));
    let mut out = String::with_capacity(page.len());
    let mut rest = 0;
    while let Some((start, (open, close, mode))) = next_opening(page, rest, &in_code) {
        let body_start = start + open.len();
        let Some(length) = page[body_start..].find(close) else {
            return Err(FormulaError::Unclosed {
                open,
                close,
                start: page[start..].chars().take(40).collect(),
            });
        };
        let end = body_start + length;
        let tex = unescape_markdown(&page[body_start..end]);
        out.push_str(&page[rest..start]);
        out.push_str(&formula(&tex, mode)?);
        rest = end + close.len();
    }
    out.push_str(&page[rest..]);
    Ok(out)
}

/// The first formula delimiter at or after `from` that is not inside code.
fn next_opening(
    page: &str,
    mut from: usize,
    in_code: &impl Fn(usize) -> bool,
) -> Option<(usize, (&'static str, &'static str, DisplayMode))> {
    loop {
        let (at, delimiter) = DELIMITERS
            .iter()
            .filter_map(|d| page[from..].find(d.0).map(|i| (from + i, *d)))
            .min_by_key(|(at, _)| *at)?;
        if !in_code(at) {
            return Some((at, delimiter));
        }
        from = at + delimiter.0.len();
    }
}

/// The byte ranges of the page that are code (fenced, indented or inline),
/// found the way mdBook's own markdown parser finds them.
fn code_ranges(page: &str) -> Vec<Range<usize>> {
    let mut ranges = Vec::new();
    for (event, range) in Parser::new_ext(page, Options::all()).into_offset_iter() {
        match event {
            Event::Code(_) | Event::Start(Tag::CodeBlock(_)) => ranges.push(range),
            Event::Html(_) | Event::InlineHtml(_) => ranges.push(range),
            _ => {}
        }
    }
    ranges
}

/// The TeX the author meant: markdown turns `\` before punctuation into
/// the punctuation alone, so `\\,` in the page is TeX's thin space `\,`.
fn unescape_markdown(text: &str) -> String {
    let mut tex = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match chars.peek() {
            Some(&next) if c == '\\' && next.is_ascii_punctuation() => {
                tex.push(next);
                chars.next();
            }
            _ => tex.push(c),
        }
    }
    tex
}

/// One formula as a single line of MathML that markdown leaves alone.
fn formula(tex: &str, mode: DisplayMode) -> std::result::Result<String, FormulaError> {
    let fail = |reason: String| FormulaError::Convert {
        tex: tex.trim().to_owned(),
        reason,
    };
    let storage = Storage::new();
    let events: Vec<_> = pulldown_latex::Parser::new(tex, &storage)
        .collect::<std::result::Result<_, _>>()
        .map_err(|e| fail(e.to_string()))?;
    let config = RenderConfig {
        display_mode: mode,
        // The TeX kept beside the MathML: screen readers and copy-paste.
        annotation: Some(tex.trim()),
        ..RenderConfig::default()
    };
    let mut mathml = String::new();
    pulldown_latex::push_mathml(
        &mut mathml,
        events.into_iter().map(Ok::<_, std::convert::Infallible>),
        config,
    )
    .map_err(|e| fail(e.to_string()))?;
    Ok(shield_from_markdown(&mathml))
}

/// Write every punctuation mark between tags as a character reference, so
/// that markdown reads no `*`, `_`, `|` or `\` of a formula as its own (a
/// `|` would split a table's cell), and put it all on one line.
fn shield_from_markdown(mathml: &str) -> String {
    let mut out = String::with_capacity(mathml.len() * 2);
    let mut in_tag = false;
    let mut chars = mathml.chars();
    while let Some(c) = chars.next() {
        match c {
            '<' => {
                in_tag = true;
                out.push(c);
            }
            '>' if in_tag => {
                in_tag = false;
                out.push(c);
            }
            '\n' => out.push(' '),
            _ if in_tag => out.push(c),
            '&' => {
                // An entity the writer made (`&amp;`): copy it whole.
                out.push(c);
                for e in chars.by_ref() {
                    out.push(e);
                    if e == ';' {
                        break;
                    }
                }
            }
            _ if c.is_ascii_punctuation() => out.push_str(&format!("&#{};", c as u32)),
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_inline_formula_becomes_inline_mathml() {
        let page = to_mathml(r"where \\(\eta = 1/1.5\\) holds").unwrap();
        assert!(page.starts_with("where <math"), "{page}");
        assert!(page.ends_with("</math> holds"), "{page}");
        assert!(!page.contains(r"\\("), "{page}");
        assert!(page.contains("η"), "{page}");
    }

    #[test]
    fn a_display_formula_becomes_a_block() {
        let page = to_mathml("text\n\n\\\\[ x = \\frac{a}{b} \\\\]\n\nmore").unwrap();
        assert!(page.contains(r#"display="block""#), "{page}");
        assert!(page.contains("<mfrac>"), "{page}");
    }

    #[test]
    fn formulas_inside_code_are_left_as_written() {
        let page = "`\\\\(x\\\\)` and\n\n```text\n\\\\[ y \\\\]\n```\n";
        assert_eq!(to_mathml(page).unwrap(), page);
    }

    #[test]
    fn a_markdown_escape_inside_a_formula_is_the_tex_the_author_meant() {
        assert_eq!(unescape_markdown(r"a\\, b \mathbf n"), r"a\, b \mathbf n");
    }

    #[test]
    fn a_bar_inside_a_formula_does_not_split_a_table_cell() {
        let page = to_mathml(r"| \\(\lvert x \rvert\\) | b |").unwrap();
        assert_eq!(
            page.matches('|').count(),
            3,
            "only the table's own bars: {page}"
        );
        assert_eq!(page.matches("&#124;").count(), 2, "{page}");
    }

    #[test]
    fn a_formula_that_does_not_convert_is_named_in_the_error() {
        let error = to_mathml(r"see \\(\frac{a\\) here").unwrap_err();
        assert!(error.to_string().contains(r"\frac{a"), "{error}");
        let error = to_mathml(r"see \\(\nosuchcommand x\\) here").unwrap_err();
        assert!(error.to_string().contains(r"\nosuchcommand"), "{error}");
    }

    #[test]
    fn a_quad_between_the_five_points_leaves_no_escaped_entity_in_the_page() {
        // pulldown-latex writes `\ ` (a backslash space) as an escaped
        // `&amp;nbsp;`, which the page showed as the text "&nbsp;" in chapter
        // 5's list of points; `\quad` is a real MathML space.
        let page = to_mathml(r"\\[ (0.5, 0.5),\quad (0.25, 0.25) \\]").unwrap();
        assert!(!page.contains("nbsp"), "{page}");
        let text = include_str!("../../../book/src/ch05-antialiasing.md");
        assert!(!text.contains(r",\ ("), "chapter 5 uses \\ ; use \\quad");
    }

    #[test]
    fn an_unclosed_formula_is_an_error() {
        let error = to_mathml(r"see \\(x here").unwrap_err();
        assert!(matches!(error, FormulaError::Unclosed { .. }), "{error}");
    }
}
