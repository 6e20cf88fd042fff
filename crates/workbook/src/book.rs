//! Building the book, and the checks that keep its text and code one.

use std::path::{Path, PathBuf};

use crate::JobError;

/// The files of `book/` beside its pages: the settings, and the styles and
/// scripts `book.toml` adds to every page (a copy of the book needs them).
pub const BOOK_FILES: [&str; 6] = [
    "book.toml",
    "math.css",
    "sliders.css",
    "sliders.js",
    "lab-in-browser.css",
    "lab-in-browser.js",
];

/// Build the book in `book_dir` (its `book.toml` names the output
/// folder); returns the path of its `index.html`.
pub fn build(book_dir: &Path) -> Result<PathBuf, JobError> {
    let mut book =
        mdbook_driver::MDBook::load(book_dir).map_err(|e| JobError::Book(format!("{e:#}")))?;
    // After mdBook's own preprocessors, so included text is converted too.
    book.with_preprocessor(crate::math::Formulas);
    book.build().map_err(|e| JobError::Book(format!("{e:#}")))?;
    Ok(book.build_dir_for("html").join("index.html"))
}

/// One `{{#include path}}` or `{{#include path:anchor}}` in a page.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Include {
    pub page: PathBuf,
    /// Relative to the page's folder.
    pub path: String,
    pub anchor: Option<String>,
}

/// Every include in the markdown pages under `src`.
pub fn includes(src: &Path) -> Vec<Include> {
    let mut found = Vec::new();
    for page in pages(src) {
        let text = std::fs::read_to_string(&page).unwrap_or_default();
        for piece in text.split("{{#include ").skip(1) {
            let Some(end) = piece.find("}}") else {
                continue;
            };
            let target = piece[..end].trim();
            let (path, anchor) = match target.split_once(':') {
                Some((path, anchor)) => (path, Some(anchor.to_owned())),
                None => (target, None),
            };
            found.push(Include {
                page: page.clone(),
                path: path.to_owned(),
                anchor,
            });
        }
    }
    found
}

/// The lines between `ANCHOR: name` and `ANCHOR_END: name` in `text`,
/// without the marker lines themselves (what mdBook shows).
pub fn anchored(text: &str, name: &str) -> Option<String> {
    let start = format!("ANCHOR: {name}");
    let end = format!("ANCHOR_END: {name}");
    let mut lines = text
        .lines()
        .skip_while(|l| !l.trim_start().ends_with(&start) || !l.contains("//"));
    lines.next()?;
    let body: Vec<&str> = lines.by_ref().take_while(|l| !l.contains(&end)).collect();
    let body = body
        .into_iter()
        .filter(|l| !l.contains("ANCHOR"))
        .collect::<Vec<_>>()
        .join("\n");
    Some(body)
}

/// Every `](target)` link in the pages under `src`, and every `src="…"`
/// of their HTML (the image sliders), with its page.
pub fn links(src: &Path) -> Vec<(PathBuf, String)> {
    let mut found = Vec::new();
    for page in pages(src) {
        let text = std::fs::read_to_string(&page).unwrap_or_default();
        for (open, close) in [("](", ')'), ("src=\"", '"')] {
            for piece in text.split(open).skip(1) {
                if let Some(end) = piece.find(close) {
                    found.push((page.clone(), piece[..end].to_owned()));
                }
            }
        }
    }
    found
}

/// The markdown pages directly under `src`, sorted.
pub fn pages(src: &Path) -> Vec<PathBuf> {
    let mut pages: Vec<PathBuf> = std::fs::read_dir(src)
        .map(|dir| {
            dir.flatten()
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|e| e == "md"))
                .collect()
        })
        .unwrap_or_default();
    pages.sort();
    pages
}

/// The longest listing a chapter's main text may show unfolded: a reader
/// takes in about a screen of code at once; a longer one goes in a
/// `<details>` fold or an appendix.
pub const LISTING_LINES: usize = 40;

/// Every code listing (`<pre>`) of a built page that is longer than `limit`
/// lines and not inside a `<details>` fold: its length and first line.
pub fn unfolded_listings_over(html: &str, limit: usize) -> Vec<(usize, String)> {
    let mut long = Vec::new();
    let mut folds = 0usize;
    let mut rest = html;
    loop {
        let next = ["<details", "</details>", "<pre"]
            .into_iter()
            .filter_map(|tag| rest.find(tag).map(|at| (at, tag)))
            .min();
        let Some((at, tag)) = next else {
            break;
        };
        rest = &rest[at + tag.len()..];
        match tag {
            "<details" => folds += 1,
            "</details>" => folds = folds.saturating_sub(1),
            _ => {
                let end = rest.find("</pre>").unwrap_or(rest.len());
                let code = text_of(&rest[..end]);
                rest = &rest[end..];
                let code = code.trim_end_matches('\n');
                let lines = code.lines().count();
                if folds == 0 && lines > limit {
                    let first = code.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
                    long.push((lines, first.trim().to_owned()));
                }
            }
        }
    }
    long
}

/// The text of an HTML fragment: its tags dropped (the first `>` ends the
/// `<pre>`'s own attributes), its entities left as they are.
fn text_of(fragment: &str) -> String {
    let fragment = fragment.split_once('>').map_or(fragment, |(_, body)| body);
    let mut text = String::with_capacity(fragment.len());
    let mut in_tag = false;
    for c in fragment.chars() {
        match c {
            '<' => in_tag = true,
            '>' if in_tag => in_tag = false,
            _ if !in_tag => text.push(c),
            _ => {}
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_listing_counts_only_outside_a_fold() {
        let code = |n: usize| {
            let lines: Vec<String> = (0..n).map(|i| format!("let x{i} = {i};")).collect();
            format!(
                "<pre><code class=\"language-rust\"><span>{}</span>\n</code></pre>",
                lines.join("\n")
            )
        };
        let page = format!(
            "<p>a</p>{}<details><summary>s</summary>{}</details>{}",
            code(41),
            code(90),
            code(40)
        );
        assert_eq!(
            unfolded_listings_over(&page, LISTING_LINES),
            [(41, "let x0 = 0;".to_owned())]
        );
        let nested = format!("<details><details></details>{}</details>", code(60));
        assert!(unfolded_listings_over(&nested, LISTING_LINES).is_empty());
    }

    #[test]
    fn an_anchor_gives_the_lines_between_its_markers() {
        let text = "a\n// ANCHOR: two\nb\nc\n// ANCHOR_END: two\nd\n";
        assert_eq!(anchored(text, "two").as_deref(), Some("b\nc"));
        assert_eq!(anchored(text, "three"), None);
    }
}
