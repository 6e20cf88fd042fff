//! No import cycle between modules: in every crate of the workspace, the
//! top-level modules (the crate root's `mod`s) depend on each other as a
//! tree of layers, never in a ring. A ring (`state` uses `overlay`, which
//! uses `tree3d`, which uses `state`) means none of them can be read, or
//! tested, without the others.
//!
//! The test reads the source, not the compiler's view of it: it follows
//! `mod NAME;` to the module files, and in every file it resolves the
//! paths that can name a sibling module, `crate::…`, `super::…` and
//! `self::…` (in `use` lines and in code, groups `{…}` included), after
//! taking out comments and string literals. A name the crate root
//! re-exports (`pub use scene_file::SceneFileError;`) counts as a use of
//! the module it comes from. The crate root itself is not a node: it
//! declares and re-exports every module by nature.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// One crate's modules and what each uses: top-level module → the other
/// top-level modules its files name.
type Graph = BTreeMap<String, BTreeSet<String>>;

/// Rust source with comments, string literals and character literals
/// blanked out (each replaced by a space), so that a path written in a
/// doc comment or a message is not taken for a use.
fn code_only(source: &str) -> String {
    let chars: Vec<char> = source.chars().collect();
    let mut out = String::with_capacity(source.len());
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
            out.push(' ');
        } else if c == '/' && next == Some('*') {
            // Block comments nest in Rust.
            let mut depth = 0;
            while i < chars.len() {
                if chars[i] == '/' && chars.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if chars[i] == '*' && chars.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            out.push(' ');
        } else if c == 'r' && (next == Some('"') || next == Some('#')) && raw_start(&chars, i) {
            // A raw string: r"…", r#"…"#, br"…", and so on.
            let hashes = chars[i + 1..].iter().take_while(|&&h| h == '#').count();
            if chars.get(i + 1 + hashes) != Some(&'"') {
                out.push(c);
                i += 1;
                continue;
            }
            i += 2 + hashes;
            let closing: Vec<char> = std::iter::once('"')
                .chain(std::iter::repeat_n('#', hashes))
                .collect();
            while i < chars.len() && !chars[i..].starts_with(&closing) {
                i += 1;
            }
            i += closing.len();
            out.push(' ');
        } else if c == '"' {
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                i += if chars[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            out.push(' ');
        } else if c == '\'' {
            // A character literal ('a', '\n', '\u{2026}'), or a lifetime ('a).
            if next == Some('\\') {
                // Past the quote, the backslash and the escaped character.
                i += 3;
                while i < chars.len() && chars[i] != '\'' {
                    i += 1;
                }
                i += 1;
                out.push(' ');
            } else if chars.get(i + 2) == Some(&'\'') {
                i += 3;
                out.push(' ');
            } else {
                out.push(c);
                i += 1;
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Whether the `r` at `i` starts a raw string (`r"`, `br"`), not ends a
/// word (`for"` cannot occur, but `bar` must not start one).
fn raw_start(chars: &[char], i: usize) -> bool {
    let before = |k: usize| k > 0 && is_ident(chars[k - 1]);
    !before(i) || (chars[i - 1] == 'b' && !before(i - 1))
}

/// The tokens of code: identifiers, `::`, and single punctuation.
fn tokens(code: &str) -> Vec<String> {
    let chars: Vec<char> = code.chars().collect();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if is_ident(c) || c == '$' {
            let start = i;
            i += 1;
            while i < chars.len() && is_ident(chars[i]) {
                i += 1;
            }
            tokens.push(chars[start..i].iter().collect());
        } else if c == ':' && chars.get(i + 1) == Some(&':') {
            tokens.push("::".into());
            i += 2;
        } else {
            tokens.push(c.to_string());
            i += 1;
        }
    }
    tokens
}

/// A path as written from `start` (which holds `crate`, `super` or
/// `self`): its segments, and for a group (`a::{b::C, d}`) each item's
/// first segment after the group. Returns the segments before any group,
/// the groups' first segments, and where the path ends.
fn read_path(tokens: &[String], start: usize) -> (Vec<String>, Vec<String>, usize) {
    // `$crate` in a macro is the crate it is defined in.
    let mut segments = vec![tokens[start].trim_start_matches('$').to_owned()];
    let mut i = start + 1;
    let mut group_heads = Vec::new();
    while i + 1 < tokens.len() && tokens[i] == "::" {
        let next = &tokens[i + 1];
        if next == "{" {
            // Each item of the group starts after `{` or a `,` at depth 1.
            let mut depth = 0;
            let mut j = i + 1;
            let mut expect_head = true;
            while j < tokens.len() {
                match tokens[j].as_str() {
                    "{" => {
                        depth += 1;
                        expect_head = depth == 1;
                    }
                    "}" => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    "," if depth == 1 => expect_head = true,
                    token if expect_head && depth == 1 => {
                        group_heads.push(token.to_owned());
                        expect_head = false;
                    }
                    _ => {}
                }
                j += 1;
            }
            return (segments, group_heads, j);
        }
        if !next.chars().all(is_ident) {
            break;
        }
        segments.push(next.clone());
        i += 2;
    }
    (segments, group_heads, i)
}

/// A crate's module tree as read from its root file: every module file,
/// with its module path (`["diagrams", "sweep"]`; the root is `[]`).
fn module_files(root_file: &Path) -> Result<Vec<(Vec<String>, PathBuf)>, String> {
    let mut files = vec![(Vec::new(), root_file.to_owned())];
    let mut k = 0;
    while k < files.len() {
        let (path, file) = files[k].clone();
        k += 1;
        let source = std::fs::read_to_string(&file)
            .map_err(|e| format!("cannot read {}: {e}", file.display()))?;
        // A non-root file `a.rs` keeps its children in `a/`; `mod.rs`,
        // `lib.rs` and `main.rs` keep theirs beside them.
        let stem = file.file_stem().and_then(|s| s.to_str()).unwrap_or("");
        let dir = file.parent().expect("a file in a folder");
        let child_dir = if path.is_empty() || stem == "mod" {
            dir.to_owned()
        } else {
            dir.join(stem)
        };
        for (inline, name) in declared_modules(&code_only(&source)) {
            let mut folder = child_dir.clone();
            folder.extend(&inline);
            let candidates = [
                folder.join(format!("{name}.rs")),
                folder.join(&name).join("mod.rs"),
            ];
            let found = candidates.iter().find(|c| c.is_file()).ok_or_else(|| {
                format!(
                    "{}: `mod {name};` has no file ({} or {})",
                    file.display(),
                    candidates[0].display(),
                    candidates[1].display()
                )
            })?;
            let mut child = path.clone();
            child.extend(inline);
            child.push(name);
            files.push((child, found.clone()));
        }
    }
    Ok(files)
}

/// The `mod NAME;` declarations of a file, each with the inline modules
/// (`mod a { mod b; }`) it sits in.
fn declared_modules(code: &str) -> Vec<(Vec<String>, String)> {
    let mut found = Vec::new();
    walk(code, |inline, tokens, i| {
        if tokens[i] == "mod" && tokens.get(i + 2).is_some_and(|t| t == ";") {
            found.push((inline.to_vec(), tokens[i + 1].clone()));
        }
    });
    found
}

/// Visit every token of `code` with the inline modules it sits in.
fn walk(code: &str, mut visit: impl FnMut(&[String], &[String], usize)) {
    let tokens = tokens(code);
    // The inline modules open here, each with the brace depth inside it.
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0;
    let mut i = 0;
    while i < tokens.len() {
        match tokens[i].as_str() {
            "{" => depth += 1,
            "}" => {
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
                depth -= 1;
            }
            "mod" if tokens.get(i + 2).is_some_and(|t| t == "{") => {
                inline.push((tokens[i + 1].clone(), depth + 1));
            }
            _ => {}
        }
        let names: Vec<String> = inline.iter().map(|(n, _)| n.clone()).collect();
        visit(&names, &tokens, i);
        i += 1;
    }
}

/// The names the crate root brings into its own scope from its modules
/// (`pub use flags::{CommonFlags, Options};`, `use run::run;`): name →
/// the top-level module it comes from.
fn root_imports(code: &str, modules: &BTreeSet<String>) -> BTreeMap<String, String> {
    let tokens = tokens(code);
    let mut imports = BTreeMap::new();
    let mut depth = 0;
    for i in 0..tokens.len() {
        match tokens[i].as_str() {
            "{" => depth += 1,
            "}" => depth -= 1,
            "use" if depth == 0 => {
                let mut j = i + 1;
                if tokens.get(j).is_some_and(|t| t == "crate" || t == "self") {
                    j += 2;
                }
                let Some(module) = tokens.get(j).filter(|t| modules.contains(*t)) else {
                    continue;
                };
                // Every name the statement ends in: the last segment of
                // each item, or its `as` name.
                let end = (j..tokens.len())
                    .find(|&k| tokens[k] == ";")
                    .unwrap_or(tokens.len());
                for k in j..end {
                    let token = &tokens[k];
                    let ends_item = tokens
                        .get(k + 1)
                        .is_some_and(|t| t == "," || t == "}" || t == ";");
                    if ends_item && token.chars().all(is_ident) && token != "self" {
                        imports.insert(token.clone(), module.clone());
                    }
                }
            }
            _ => {}
        }
    }
    imports
}

/// The module graph of the crate whose root file is `root_file`.
fn module_graph(root_file: &Path) -> Result<Graph, String> {
    let files = module_files(root_file)?;
    let top: BTreeSet<String> = files
        .iter()
        .filter(|(path, _)| path.len() == 1)
        .map(|(path, _)| path[0].clone())
        .collect();
    let root_code = code_only(&std::fs::read_to_string(root_file).map_err(|e| e.to_string())?);
    let imports = root_imports(&root_code, &top);
    let mut graph: Graph = top.iter().map(|m| (m.clone(), BTreeSet::new())).collect();
    for (path, file) in &files {
        let source = std::fs::read_to_string(file).map_err(|e| e.to_string())?;
        walk(&code_only(&source), |inline, tokens, i| {
            let start = tokens[i].trim_start_matches('$');
            if !matches!(start, "crate" | "super" | "self")
                || tokens.get(i + 1).is_none_or(|t| t != "::")
                || (i > 0 && tokens[i - 1] == "::")
            {
                return;
            }
            let mut here: Vec<String> = path.iter().chain(inline).cloned().collect();
            let Some(from) = here.first().cloned() else {
                return; // the crate root: not a node
            };
            let (segments, group_heads, _) = read_path(tokens, i);
            let mut rest = segments.iter().peekable();
            match rest.next().map(String::as_str) {
                Some("crate") => here.clear(),
                Some("super") => {
                    here.pop();
                }
                _ => {} // self
            }
            while rest.next_if(|s| *s == "super").is_some() {
                here.pop();
            }
            let heads: Vec<&String> = match (here.first(), rest.next()) {
                (Some(module), _) => vec![module],
                (None, Some(name)) => vec![name],
                (None, None) => group_heads.iter().collect(),
            };
            for head in heads {
                let to = if top.contains(head) {
                    Some(head)
                } else {
                    imports.get(head)
                };
                if let Some(to) = to.filter(|to| **to != from) {
                    graph.entry(from.clone()).or_default().insert(to.clone());
                }
            }
        });
    }
    Ok(graph)
}

/// Every ring of modules in `graph`, each as `a → b → a`: the strongly
/// connected components of more than one module, by Tarjan's algorithm,
/// each shown as one cycle through it.
fn cycles(graph: &Graph) -> Vec<String> {
    struct Search<'g> {
        graph: &'g Graph,
        index: BTreeMap<&'g str, usize>,
        low: BTreeMap<&'g str, usize>,
        stack: Vec<&'g str>,
        on_stack: BTreeSet<&'g str>,
        components: Vec<Vec<&'g str>>,
    }
    impl<'g> Search<'g> {
        fn visit(&mut self, node: &'g str) {
            let n = self.index.len();
            self.index.insert(node, n);
            self.low.insert(node, n);
            self.stack.push(node);
            self.on_stack.insert(node);
            for next in self.graph.get(node).into_iter().flatten() {
                let next = next.as_str();
                if !self.index.contains_key(next) {
                    self.visit(next);
                    let low = self.low[node].min(self.low[next]);
                    self.low.insert(node, low);
                } else if self.on_stack.contains(next) {
                    let low = self.low[node].min(self.index[next]);
                    self.low.insert(node, low);
                }
            }
            if self.low[node] == self.index[node] {
                let mut component = Vec::new();
                while let Some(top) = self.stack.pop() {
                    self.on_stack.remove(top);
                    component.push(top);
                    if top == node {
                        break;
                    }
                }
                self.components.push(component);
            }
        }
    }
    let mut search = Search {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        components: Vec::new(),
    };
    for node in graph.keys() {
        if !search.index.contains_key(node.as_str()) {
            search.visit(node);
        }
    }
    search
        .components
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|mut component| {
            component.sort();
            let ring = ring(graph, &component);
            // The ring shown may not pass through every module of the knot.
            if ring.matches(" → ").count() < component.len() {
                format!("{ring} (all of {} reach each other)", component.join(", "))
            } else {
                ring
            }
        })
        .collect()
}

/// One cycle through the modules of `component`, as `a → b → … → a`.
fn ring(graph: &Graph, component: &[&str]) -> String {
    let inside: BTreeSet<&str> = component.iter().copied().collect();
    let start = *inside.first().expect("a component has a module");
    // Breadth first from `start` back to it, inside the component.
    let mut came_from: BTreeMap<&str, &str> = BTreeMap::new();
    let mut queue = std::collections::VecDeque::from([start]);
    while let Some(node) = queue.pop_front() {
        for next in graph.get(node).into_iter().flatten() {
            let next = next.as_str();
            if next == start {
                let mut path = vec![start, node];
                let mut at = node;
                while at != start {
                    at = came_from[at];
                    path.push(at);
                }
                path.reverse();
                return path.join(" → ");
            }
            if inside.contains(next) && !came_from.contains_key(next) {
                came_from.insert(next, node);
                queue.push_back(next);
            }
        }
    }
    unreachable!("a strongly connected component has a cycle through each module")
}

/// The root files of every crate in the workspace: each package's library
/// and programs.
fn crate_roots(workspace: &Path) -> Vec<PathBuf> {
    let mut packages = vec![workspace.to_owned()];
    for group in ["chapters", "crates"] {
        let mut members: Vec<PathBuf> = std::fs::read_dir(workspace.join(group))
            .expect("the workspace's folders")
            .map(|e| e.expect("a folder entry").path())
            .filter(|p| p.join("Cargo.toml").is_file())
            .collect();
        members.sort();
        packages.extend(members);
    }
    let mut roots = vec![workspace.join("tests/lib.rs")];
    for package in packages {
        let src = package.join("src");
        roots.extend(
            [src.join("lib.rs"), src.join("main.rs")]
                .into_iter()
                .filter(|f| f.is_file()),
        );
        if let Ok(bins) = std::fs::read_dir(src.join("bin")) {
            for bin in bins {
                let bin = bin.expect("a folder entry").path();
                let main = if bin.is_dir() {
                    bin.join("main.rs")
                } else {
                    bin
                };
                roots.push(main);
            }
        }
    }
    roots
}

#[test]
fn no_crate_in_the_workspace_has_a_cycle_of_modules() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the workspace");
    let mut rings = Vec::new();
    let mut modules = 0;
    let mut uses = 0;
    let roots = crate_roots(workspace);
    for root in &roots {
        let graph = module_graph(root).unwrap_or_else(|e| panic!("{e}"));
        modules += graph.len();
        uses += graph.values().map(BTreeSet::len).sum::<usize>();
        let shown = root.strip_prefix(workspace).unwrap_or(root).display();
        rings.extend(cycles(&graph).into_iter().map(|c| format!("{shown}: {c}")));
    }
    // Not an empty pass: the workspace has dozens of crates and hundreds of
    // modules that use each other.
    assert!(roots.len() > 20, "found only {} crate roots", roots.len());
    assert!(
        modules > 100 && uses > 100,
        "{modules} modules, {uses} uses"
    );
    assert!(rings.is_empty(), "modules in a ring:\n{}", rings.join("\n"));
}

#[test]
fn the_command_lines_modules_are_read_as_they_use_each_other() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the workspace");
    let graph = module_graph(&workspace.join("crates/cli/src/lib.rs")).unwrap();
    // `use crate::error::CliError;` in flags.rs, `use super::kind_colour;`
    // `crate::limits::MAX_EPSILON` in scene_file.rs's code, `use
    // crate::output::…` in diagrams/sweep.rs, and a name the root
    // re-exports (`crate::CliError` would count as `error`).
    assert!(graph["flags"].contains("error"), "{graph:?}");
    assert!(graph["scene_file"].contains("limits"), "{graph:?}");
    assert!(graph["diagrams"].contains("output"), "{graph:?}");
    assert!(graph["run"].contains("diagrams"), "{graph:?}");
    assert!(!graph["limits"].contains("flags"), "{graph:?}");
}

/// A crate of `files` (path → source) in a temporary folder.
fn tiny_crate(files: &[(&str, &str)]) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    for (path, source) in files {
        let path = dir.path().join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, source).unwrap();
    }
    let root = dir.path().join("src/lib.rs");
    (dir, root)
}

#[test]
fn a_ring_of_three_modules_is_found_and_named() {
    let (_dir, root) = tiny_crate(&[
        ("src/lib.rs", "mod a;\nmod b;\nmod c;\n"),
        ("src/a.rs", "use crate::b::B;\npub fn g() {}\n"),
        ("src/b.rs", "use super::c::C;\npub struct B;\n"),
        ("src/c.rs", "pub struct C;\nfn f() { crate::a::g() }\n"),
    ]);
    let graph = module_graph(&root).unwrap();
    assert_eq!(cycles(&graph), ["a → b → c → a"]);
}

#[test]
fn layers_that_only_use_downwards_have_no_ring() {
    let (_dir, root) = tiny_crate(&[
        ("src/lib.rs", "mod a;\nmod b;\nmod c;\npub use c::C;\n"),
        ("src/a.rs", "use crate::{b::B, C};\n"),
        // The same names in a comment, a string and a doc line are not uses.
        (
            "src/b.rs",
            "//! Uses crate::a::g.\npub struct B(crate::C);\nconst S: &str = \"crate::a\";\n/* super::a */\n",
        ),
        ("src/c.rs", "pub struct C;\n"),
    ]);
    let graph = module_graph(&root).unwrap();
    assert_eq!(graph["a"], BTreeSet::from(["b".into(), "c".into()]));
    assert_eq!(graph["b"], BTreeSet::from(["c".into()]));
    assert!(cycles(&graph).is_empty(), "{graph:?}");
}

#[test]
fn a_name_the_root_re_exports_counts_as_its_modules() {
    let (_dir, root) = tiny_crate(&[
        (
            "src/lib.rs",
            "mod a;\nmod b;\npub use a::{A, helpers::Tool as Kit};\n",
        ),
        (
            "src/a.rs",
            "pub struct A;\npub mod helpers { pub struct Tool; }\nfn f(_: crate::b::B) {}\n",
        ),
        ("src/b.rs", "pub struct B;\nfn g(_: crate::Kit) {}\n"),
    ]);
    let graph = module_graph(&root).unwrap();
    assert_eq!(cycles(&graph), ["a → b → a"]);
}

#[test]
fn super_inside_an_inline_test_module_is_its_own_file() {
    // In `a/x.rs`, `super::y` is `a::y`; inside its inline `mod tests`,
    // `super::super::y` is the same module: neither names the sibling `y`.
    let (_dir, root) = tiny_crate(&[
        ("src/lib.rs", "mod a;\nmod y;\n"),
        ("src/a/mod.rs", "mod x;\nmod y;\n"),
        (
            "src/a/x.rs",
            "use super::y::Y;\n#[cfg(test)]\nmod tests {\n    use super::super::y::Y;\n}\n",
        ),
        ("src/a/y.rs", "pub struct Y;\n"),
        ("src/y.rs", "use crate::a::Z;\n"),
    ]);
    let graph = module_graph(&root).unwrap();
    assert!(graph["a"].is_empty(), "{graph:?}");
    assert!(cycles(&graph).is_empty());
}
