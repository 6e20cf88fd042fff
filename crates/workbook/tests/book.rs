//! The book as a learner meets it: it builds, every listing is real code,
//! every figure it shows is one the programs make, and no link is broken.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use workbook::book::{
    LISTING_LINES, anchored, build, includes, links, pages, unfolded_listings_over,
};
use workbook::{Parts, Size, make_figures};

fn book_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../book")
}

#[test]
fn every_include_anchor_resolves_to_non_empty_code() {
    let src = book_dir().join("src");
    let code: Vec<_> = includes(&src)
        .into_iter()
        .filter(|i| !i.path.starts_with("figures/"))
        .collect();
    assert!(
        code.len() >= 20,
        "the chapters show their code: {} includes",
        code.len()
    );
    for include in code {
        let file = include.page.parent().unwrap().join(&include.path);
        let text = std::fs::read_to_string(&file)
            .unwrap_or_else(|e| panic!("{:?} includes {}: {e}", include.page, include.path));
        // Rust code is shown by anchor, a region that names what it holds;
        // a scene file may be shown whole.
        let Some(anchor) = include.anchor.as_deref() else {
            assert!(
                include.path.ends_with(".toml"),
                "{:?}: {} needs an anchor",
                include.page,
                include.path
            );
            assert!(
                !text.trim().is_empty(),
                "{:?}: {} is empty",
                include.page,
                include.path
            );
            continue;
        };
        let body = anchored(&text, anchor).unwrap_or_else(|| {
            panic!(
                "{:?}: no anchor '{anchor}' in {}",
                include.page, include.path
            )
        });
        assert!(
            !body.trim().is_empty(),
            "{:?}: anchor '{anchor}' in {} is empty",
            include.page,
            include.path
        );
    }
}

#[test]
fn no_internal_link_is_broken() {
    let src = book_dir().join("src");
    let pages_here: BTreeSet<String> = pages(&src)
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    let mut checked = 0;
    for (page, target) in links(&src) {
        let target = target.split_whitespace().next().unwrap_or_default();
        if target.starts_with("http") || target.starts_with('#') || target.starts_with("figures/") {
            continue;
        }
        let file = target.split('#').next().unwrap();
        assert!(
            pages_here.contains(file),
            "{page:?} links to {target}, which is not a page"
        );
        checked += 1;
    }
    assert!(checked >= 7, "the summary links every page: {checked}");
}

#[test]
fn the_book_builds_and_shows_only_figures_the_programs_make() {
    // A copy of the book, its figures made small, then built.
    let temp = tempfile::tempdir().unwrap();
    let book = temp.path().join("book");
    std::fs::create_dir_all(book.join("src")).unwrap();
    for file in workbook::book::BOOK_FILES {
        std::fs::copy(book_dir().join(file), book.join(file)).unwrap();
    }
    for page in pages(&book_dir().join("src")) {
        std::fs::copy(&page, book.join("src").join(page.file_name().unwrap())).unwrap();
    }
    // Code includes reach ../../src, ../../chapters, ../../crates, ../../scenes and
    // ../../.cargo: mirror them.
    for dir in ["src", "chapters", "crates", "scenes", ".cargo"] {
        copy_tree(&book_dir().join("..").join(dir), &temp.path().join(dir));
    }
    let figures = book.join("src/figures");
    let scenes = temp.path().join("scenes");
    let size = Size {
        width: 160,
        height: 120,
    };
    let made = make_figures(&figures, &scenes, size, true, &mut Parts::default()).unwrap();
    let made: BTreeSet<String> = made
        .iter()
        .map(|p| {
            p.strip_prefix(book.join("src"))
                .unwrap()
                .to_string_lossy()
                .into_owned()
        })
        .collect();

    let src = book.join("src");
    let mut shown = 0;
    for (page, target) in links(&src)
        .into_iter()
        .filter(|(_, t)| t.starts_with("figures/"))
    {
        let file = target.split_whitespace().next().unwrap();
        assert!(
            made.contains(file),
            "{page:?} shows {file}, which no program makes"
        );
        shown += 1;
    }
    for include in includes(&src)
        .into_iter()
        .filter(|i| i.path.starts_with("figures/"))
    {
        assert!(
            made.contains(&include.path),
            "{:?} includes {}, which no program makes",
            include.page,
            include.path
        );
    }
    assert!(shown >= 30, "the book shows the figures: {shown}");

    let index = build(&book).unwrap();
    assert!(index.exists());
    for page in pages(&src) {
        let name = page.file_stem().unwrap().to_string_lossy().into_owned();
        if name == "SUMMARY" {
            continue;
        }
        let html =
            std::fs::read_to_string(book.join("build").join(format!("{name}.html"))).unwrap();
        assert!(
            !html.contains("{{#include"),
            "{name}: an include was not resolved"
        );
    }
    let ch4 = std::fs::read_to_string(book.join("build/ch04-refraction.html")).unwrap();
    assert!(ch4.contains("send_refraction"), "chapter 4 shows its code");
    every_formula_is_mathml_and_no_page_needs_mathjax(&src, &book.join("build"));
    no_chapter_shows_a_long_listing_unfolded(&src, &book.join("build"));
}

/// A chapter's main text (the built page, every include resolved) shows
/// no listing longer than `LISTING_LINES` outside a `<details>` fold.
fn no_chapter_shows_a_long_listing_unfolded(src: &Path, build: &Path) {
    let mut chapters = 0;
    let mut long = Vec::new();
    for page in pages(src) {
        let name = page.file_stem().unwrap().to_string_lossy().into_owned();
        if !name.starts_with("ch") {
            continue;
        }
        chapters += 1;
        let html = std::fs::read_to_string(build.join(format!("{name}.html"))).unwrap();
        for (lines, first) in unfolded_listings_over(&html, LISTING_LINES) {
            long.push(format!("{name}: {lines} lines, from `{first}`"));
        }
    }
    assert_eq!(chapters, 10, "the ten chapters' pages");
    assert!(
        long.is_empty(),
        "listings longer than {LISTING_LINES} lines outside a fold:\n{}",
        long.join("\n")
    );
}

/// The book reads offline: each page that writes a formula holds MathML,
/// no raw TeX is left outside code, and no page loads MathJax.
fn every_formula_is_mathml_and_no_page_needs_mathjax(src: &Path, build: &Path) {
    let mut with_formulas = 0;
    for page in pages(src) {
        let name = page.file_stem().unwrap().to_string_lossy().into_owned();
        if name == "SUMMARY" {
            continue;
        }
        let markdown = std::fs::read_to_string(&page).unwrap();
        let html = std::fs::read_to_string(build.join(format!("{name}.html"))).unwrap();
        if markdown.contains(r"\\(") || markdown.contains(r"\\[") {
            with_formulas += 1;
            assert!(
                html.contains("<math"),
                "{name}: its formulas are not MathML"
            );
        }
        let prose = without(&html, &["pre", "code", "script", "annotation"]);
        for raw in [r"\(", r"\[", "$$"] {
            assert!(!prose.contains(raw), "{name}: raw TeX `{raw}` is left");
        }
        if let Some(at) = tex_command(&prose) {
            let context: String = prose[at.saturating_sub(40)..].chars().take(80).collect();
            panic!("{name}: a TeX command outside a formula: {context}");
        }
        assert!(
            !html.to_lowercase().contains("mathjax"),
            "{name}: the page still mentions MathJax"
        );
    }
    assert!(
        with_formulas >= 8,
        "the pages with formulas: {with_formulas}"
    );
}

/// The text with every `<tag …>…</tag>` of the given names cut out.
fn without(html: &str, tags: &[&str]) -> String {
    let mut text = html.to_owned();
    for tag in tags {
        let (open, close) = (format!("<{tag}"), format!("</{tag}>"));
        while let Some(start) = text.find(&open) {
            let end = text[start..]
                .find(&close)
                .map_or(text.len(), |e| start + e + close.len());
            text.replace_range(start..end, "");
        }
    }
    text
}

/// Where a backslash followed by a letter (`\cdot`) is, if anywhere.
fn tex_command(text: &str) -> Option<usize> {
    let bytes = text.as_bytes();
    (0..bytes.len().saturating_sub(1))
        .find(|&i| bytes[i] == b'\\' && bytes[i + 1].is_ascii_alphabetic())
}

#[test]
fn a_formula_that_does_not_convert_stops_the_build_naming_page_and_formula() {
    let temp = tempfile::tempdir().unwrap();
    let book = temp.path();
    std::fs::create_dir_all(book.join("src")).unwrap();
    std::fs::write(book.join("book.toml"), "[book]\ntitle = \"t\"\n").unwrap();
    std::fs::write(
        book.join("src/SUMMARY.md"),
        "# Summary\n\n- [Bad](bad.md)\n",
    )
    .unwrap();
    std::fs::write(
        book.join("src/bad.md"),
        "# Bad\n\nA good \\\\(x^2\\\\) and a bad \\\\(\\frac{a\\\\).\n",
    )
    .unwrap();
    let error = build(book).unwrap_err().to_string();
    assert!(error.contains("bad.md"), "{error}");
    assert!(error.contains(r"\frac{a"), "{error}");
}

fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap().flatten() {
        let path = entry.path();
        if path.is_dir() {
            copy_tree(&path, &to.join(entry.file_name()));
        } else if path.extension().is_some_and(|e| {
            ["rs", "toml", "wgsl", "frag", "glsl"].contains(&e.to_str().unwrap_or(""))
        }) {
            std::fs::copy(&path, to.join(entry.file_name())).unwrap();
        }
    }
}

/// Each ray-tree figure's paragraph, alt text and caption name the pixel
/// and the numbers of the probe the chapter's program prints at the
/// book's size (the main job checks the same against the files it wrote).
#[test]
fn the_text_around_every_ray_tree_agrees_with_its_probe() {
    let src = book_dir().join("src");
    let mut passages = 0;
    for page in pages(&src) {
        let text = std::fs::read_to_string(&page).unwrap();
        passages += workbook::claims::passages(&text).len();
    }
    assert!(passages >= 6, "the chapters' ray trees: {passages}");
    let wrong = workbook::claims::check_pages(&src, |dir| {
        workbook::claims::chapter_probe_text(dir, Size::DEFAULT).map(|text| text.unwrap())
    });
    assert!(wrong.is_empty(), "\n{}", wrong.join("\n"));
}
