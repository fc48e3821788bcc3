//! Invariants of `ARCHITECTURE.md` that a test can check.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable source dir") {
        let path = entry.expect("dir entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn pure_modules_import_no_tokio_axum_or_wgpu() {
    // The CPU references: the world function, authored regions, the subsurface and the volume
    // stages. They run anywhere (tests, exports, other hosts) and stay free of the service.
    for (dir, min_files) in [
        ("src/terrain", 5),
        ("src/authoring", 4),
        ("src/subsurface", 3),
        ("src/volume", 2),
        ("src/ptex", 4),
        ("src/edits.rs", 1),
    ] {
        let mut files = Vec::new();
        let path = root().join(dir);
        if path.is_file() {
            files.push(path);
        } else {
            rust_files(&path, &mut files);
        }
        assert!(files.len() >= min_files, "{dir} has its modules");
        for f in files {
            // Code only: docs may name the GPU twin or the service that uses the module.
            let text = strip_comments_and_literals(&std::fs::read_to_string(&f).expect("readable"));
            for banned in ["tokio::", "axum::", "wgpu::"] {
                assert!(!text.contains(banned), "{} mentions {banned}", f.display());
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Layers: top-level modules of `src/` form a DAG in the order of ARCHITECTURE.md.
// ---------------------------------------------------------------------------------------------

/// The marker lines around the layer table in `ARCHITECTURE.md`, the one place the order is
/// written.
const LAYERS_BEGIN: &str = "<!-- layers: begin -->";
const LAYERS_END: &str = "<!-- layers: end -->";

/// The layer order of `ARCHITECTURE.md`, bottom first: each numbered line of the marked block is
/// one layer, and the names in backticks before its ` — ` are its top-level modules (`main` is
/// `src/main.rs`, the binary).
fn layer_table() -> Vec<Vec<String>> {
    let doc = std::fs::read_to_string(root().join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let start = doc
        .find(LAYERS_BEGIN)
        .expect("ARCHITECTURE.md has the layers: begin marker");
    let end = doc
        .find(LAYERS_END)
        .expect("ARCHITECTURE.md has the layers: end marker");
    let mut layers = Vec::new();
    for line in doc[start + LAYERS_BEGIN.len()..end].lines() {
        let line = line.trim();
        let Some((number, rest)) = line.split_once(". ") else {
            continue;
        };
        if number.is_empty() || !number.chars().all(|c| c.is_ascii_digit()) {
            continue;
        }
        let names = rest.split(" — ").next().unwrap_or(rest);
        let modules: Vec<String> = names
            .split('`')
            .skip(1)
            .step_by(2)
            .map(str::to_string)
            .collect();
        assert!(!modules.is_empty(), "layer line without modules: {line}");
        layers.push(modules);
    }
    assert!(
        layers.len() >= 2,
        "the layer table of ARCHITECTURE.md has layers"
    );
    layers
}

/// Module name → layer index (0 is the bottom), checking that no module is listed twice.
fn layer_index(layers: &[Vec<String>]) -> BTreeMap<String, usize> {
    let mut index = BTreeMap::new();
    for (i, layer) in layers.iter().enumerate() {
        for m in layer {
            assert!(index.insert(m.clone(), i).is_none(), "{m} is in two layers");
        }
    }
    index
}

/// Replaces comments, string literals and character literals by spaces (newlines kept, so line
/// numbers stay right): what is left is code, and a path in it is a real path.
fn strip_comments_and_literals(src: &str) -> String {
    let c: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(src.len());
    let blank = |out: &mut String, ch: char| out.push(if ch == '\n' { '\n' } else { ' ' });
    let ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut i = 0;
    while i < c.len() {
        let prev_ident = i > 0 && ident(c[i - 1]);
        if c[i] == '/' && c.get(i + 1) == Some(&'/') {
            while i < c.len() && c[i] != '\n' {
                i += 1;
                out.push(' ');
            }
        } else if c[i] == '/' && c.get(i + 1) == Some(&'*') {
            // Block comments nest in Rust.
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
        } else if !prev_ident && (c[i] == 'r' || (c[i] == 'b' && c.get(i + 1) == Some(&'r'))) {
            // A raw string `r#"…"#` (or `br…`), else an identifier starting with r or b.
            let mut j = i + if c[i] == 'b' { 2 } else { 1 };
            let mut hashes = 0;
            while c.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if c.get(j) != Some(&'"') {
                out.push(c[i]);
                i += 1;
                continue;
            }
            out.extend(std::iter::repeat_n(' ', j + 1 - i));
            i = j + 1;
            while i < c.len() {
                if c[i] == '"' && (1..=hashes).all(|k| c.get(i + k) == Some(&'#')) {
                    out.extend(std::iter::repeat_n(' ', hashes + 1));
                    i += hashes + 1;
                    break;
                }
                blank(&mut out, c[i]);
                i += 1;
            }
        } else if c[i] == '"' {
            out.push(' ');
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' {
                    out.push(' ');
                    i += 1;
                }
                if i < c.len() {
                    blank(&mut out, c[i]);
                    i += 1;
                }
            }
            out.push(' ');
            i += 1;
        } else if c[i] == '\'' && (c.get(i + 1) == Some(&'\\') || c.get(i + 2) == Some(&'\'')) {
            // A character literal ('x', '\n', '\u{…}'); a lone quote is a lifetime or a label.
            out.push(' ');
            i += 1;
            while i < c.len() && c[i] != '\'' {
                if c[i] == '\\' {
                    out.push(' ');
                    i += 1;
                }
                out.push(' ');
                i += 1;
            }
            out.push(' ');
            i += 1;
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

/// A token of stripped code: an identifier, `::` or one punctuation character, with its line.
#[derive(Debug, Clone, PartialEq)]
struct Token {
    text: String,
    line: usize,
}

/// Splits stripped code into identifiers, `::` and single punctuation characters.
fn tokens(code: &str) -> Vec<Token> {
    let mut out = Vec::new();
    for (n, line) in code.lines().enumerate() {
        let c: Vec<char> = line.chars().collect();
        let mut i = 0;
        while i < c.len() {
            let start = i;
            if c[i].is_alphanumeric() || c[i] == '_' {
                while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                    i += 1;
                }
            } else if c[i] == ':' && c.get(i + 1) == Some(&':') {
                i += 2;
            } else if c[i].is_whitespace() {
                i += 1;
                continue;
            } else {
                i += 1;
            }
            out.push(Token {
                text: c[start..i].iter().collect(),
                line: n + 1,
            });
        }
    }
    out
}

/// A file's module path: `src/a/b.rs` and `src/a/b/mod.rs` are `["a", "b"]`; `src/main.rs` is
/// `["main"]`, the binary.
fn module_path(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .iter()
        .skip(1)
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().expect("a file name");
    let stem = last.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        parts.push(stem.to_string());
    }
    parts
}

/// One path in a file that leaves its top-level module.
#[derive(Debug, Clone)]
struct Reference {
    line: usize,
    /// The path as written, from `crate`, `strata` or the first `super` to its end.
    path: String,
    /// The top-level module it names.
    target: String,
}

/// The path that starts at `tokens[at]`, as written: segments joined by `::`, a `{…}` group after
/// a `::` kept whole.
fn path_text(tokens: &[Token], at: usize) -> String {
    let is_segment = |t: &str| t == "*" || t.chars().all(|c| c.is_alphanumeric() || c == '_');
    let mut text = String::new();
    let mut i = at;
    while let Some(t) = tokens.get(i) {
        let after_colons = i > at && tokens[i - 1].text == "::";
        if i > at && !after_colons && t.text != "::" {
            break;
        }
        if after_colons && t.text == "{" {
            let mut depth = 0;
            for t in &tokens[i..] {
                text.push_str(&t.text);
                match t.text.as_str() {
                    "{" => depth += 1,
                    "}" => depth -= 1,
                    "," => text.push(' '),
                    _ => {}
                }
                if depth == 0 {
                    break;
                }
            }
            break;
        }
        if t.text != "::" && !is_segment(&t.text) {
            break;
        }
        text.push_str(&t.text);
        i += 1;
    }
    text
}

/// The top-level modules a path names from the crate root, `tokens[at]` being the segment after
/// the root's `::`: the segment itself, or the first segment of each item of a `{…}` group.
fn first_segments(tokens: &[Token], at: usize) -> Vec<String> {
    match tokens.get(at).map(|t| t.text.as_str()) {
        Some("{") => {
            let mut names = Vec::new();
            let mut depth = 0;
            let mut item_start = true;
            for t in &tokens[at..] {
                match t.text.as_str() {
                    "{" => depth += 1,
                    "}" => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    "," if depth == 1 => item_start = true,
                    name if depth == 1 && item_start => {
                        if name != "self" {
                            names.push(name.to_string());
                        }
                        item_start = false;
                    }
                    _ => {}
                }
            }
            names
        }
        Some(name) if name != "*" => vec![name.to_string()],
        _ => Vec::new(),
    }
}

/// Every path in a file that names a top-level module other than the file's own: `crate::…`
/// (in `use` items, `use crate::{a::X, b::Y}` groups, expressions, types and `#[cfg(test)]` code
/// alike), `super::…` chains that climb to the crate root, and `strata::…` in the binary.
fn references(rel: &Path, code: &str) -> Vec<Reference> {
    let file_module = module_path(rel);
    let own = file_module.first().cloned().unwrap_or_default();
    let is_binary = file_module == ["main"];
    let toks = tokens(code);
    let mut out = Vec::new();
    // Inline `mod name { … }` blocks: the name and the brace depth inside the block.
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < toks.len() {
        let t = toks[i].text.as_str();
        let next = toks.get(i + 1).map(|t| t.text.as_str());
        match t {
            "{" => depth += 1,
            "}" => {
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
                depth = depth.saturating_sub(1);
            }
            "mod" if toks.get(i + 2).is_some_and(|t| t.text == "{") => {
                inline.push((toks[i + 1].text.clone(), depth + 1));
            }
            _ => {}
        }
        let after_colon = i > 0 && toks[i - 1].text == "::";
        let root_segment = if after_colon || next != Some("::") {
            None
        } else if t == "crate" || (is_binary && t == "strata") {
            Some(i + 2)
        } else if t == "super" {
            // Climb: the file's module, the inline modules around this point, one `super` each.
            let mut here = file_module.len() + inline.len();
            let mut j = i;
            while toks.get(j).is_some_and(|t| t.text == "super")
                && toks.get(j + 1).is_some_and(|t| t.text == "::")
            {
                here = here.saturating_sub(1);
                j += 2;
            }
            (here == 0).then_some(j)
        } else {
            None
        };
        if let Some(at) = root_segment {
            let path = path_text(&toks, i);
            for target in first_segments(&toks, at) {
                if target != own && target != "self" {
                    out.push(Reference {
                        line: toks[i].line,
                        path: path.clone(),
                        target,
                    });
                }
            }
        }
        i += 1;
    }
    out
}

/// Every reference of every file of `src/` (but `lib.rs`, which only declares the modules), with
/// the file's path relative to the repository root and its top-level module.
fn all_references() -> Vec<(PathBuf, String, Reference)> {
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    files.sort();
    let mut out = Vec::new();
    for f in files {
        let rel = f
            .strip_prefix(root())
            .expect("under the root")
            .to_path_buf();
        if rel == Path::new("src/lib.rs") {
            continue;
        }
        let code = strip_comments_and_literals(&std::fs::read_to_string(&f).expect("readable"));
        let own = module_path(&rel)[0].clone();
        for r in references(&rel, &code) {
            out.push((rel.clone(), own.clone(), r));
        }
    }
    out
}

/// The top-level modules `src/lib.rs` declares, plus `main`, the binary.
fn declared_modules() -> BTreeSet<String> {
    let lib = strip_comments_and_literals(
        &std::fs::read_to_string(root().join("src/lib.rs")).expect("src/lib.rs"),
    );
    let toks = tokens(&lib);
    let mut out: BTreeSet<String> = toks
        .windows(3)
        .filter(|w| w[0].text == "mod" && w[2].text == ";")
        .map(|w| w[1].text.clone())
        .collect();
    out.insert("main".to_string());
    out
}

/// A cycle in the module graph, as the list of modules along it, if there is one.
fn find_cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        match state.get(m) {
            Some(2) => return None,
            Some(1) => {
                let from = stack.iter().position(|s| s == m).expect("on the stack");
                let mut cycle = stack[from..].to_vec();
                cycle.push(m.to_string());
                return Some(cycle);
            }
            _ => {}
        }
        state.insert(m.to_string(), 1);
        stack.push(m.to_string());
        for n in edges.get(m).into_iter().flatten() {
            if let Some(c) = visit(n, edges, state, stack) {
                return Some(c);
            }
        }
        stack.pop();
        state.insert(m.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for m in edges.keys() {
        if let Some(c) = visit(m, edges, &mut state, &mut Vec::new()) {
            return Some(c);
        }
    }
    None
}

#[test]
fn every_module_has_a_layer() {
    let layers = layer_index(&layer_table());
    let declared = declared_modules();
    let listed: BTreeSet<String> = layers.keys().cloned().collect();
    assert_eq!(
        declared, listed,
        "the layer table of ARCHITECTURE.md lists exactly the top-level modules of src/lib.rs \
         (and `main`)"
    );
}

#[test]
fn top_level_modules_import_only_lower_layers() {
    let table = layer_table();
    let layers = layer_index(&table);
    let mut wrong = Vec::new();
    for (file, from, r) in all_references() {
        let (Some(&lf), Some(&lt)) = (layers.get(&from), layers.get(&r.target)) else {
            wrong.push(format!(
                "{}:{}: `{}` — {from} → {} (a module missing from the layer table)",
                file.display(),
                r.line,
                r.path,
                r.target
            ));
            continue;
        };
        if lt >= lf {
            wrong.push(format!(
                "{}:{}: `{}` — `{from}` (layer {}: {}) may not import `{}` (layer {}: {})",
                file.display(),
                r.line,
                r.path,
                lf + 1,
                table[lf].join(", "),
                r.target,
                lt + 1,
                table[lt].join(", "),
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "{} import(s) against the layer order of ARCHITECTURE.md (a module imports only modules \
         of lower layers):\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

#[test]
fn top_level_modules_form_a_dag() {
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut example: BTreeMap<(String, String), String> = BTreeMap::new();
    for (file, from, r) in all_references() {
        edges
            .entry(from.clone())
            .or_default()
            .insert(r.target.clone());
        example
            .entry((from, r.target))
            .or_insert_with(|| format!("{}:{}: `{}`", file.display(), r.line, r.path));
    }
    if let Some(cycle) = find_cycle(&edges) {
        let steps: Vec<String> = cycle
            .windows(2)
            .map(|w| {
                format!(
                    "  {} → {}: {}",
                    w[0],
                    w[1],
                    example[&(w[0].clone(), w[1].clone())]
                )
            })
            .collect();
        panic!(
            "top-level modules import each other in a cycle:\n{}",
            steps.join("\n")
        );
    }
}

#[test]
fn the_scanner_sees_real_paths_only() {
    let code = strip_comments_and_literals(
        "use crate::{terrain::hash, scene::{Element, Rect}};\n\
         // use crate::server::AppState;\n\
         /* crate::gpu /* nested */ crate::stream */\n\
         let s = \"crate::store\"; let r = r#\"crate::cli \"quoted\"\"#; let c = '\"';\n\
         fn f<'a>(x: &'a crate::encode::Glb) -> crate::volume::Chunk { todo!() }\n\
         mod tests { use super::super::super::export::X; use super::Y; }\n\
         pub(crate) fn g() { super::cache::hit(); }\n",
    );
    let refs = references(Path::new("src/authoring/grid.rs"), &code);
    let got: Vec<(usize, &str)> = refs.iter().map(|r| (r.line, r.target.as_str())).collect();
    assert_eq!(
        got,
        [
            (1, "terrain"),
            (1, "scene"),
            (5, "encode"),
            (5, "volume"),
            (6, "export")
        ],
        "{refs:?}"
    );
    assert_eq!(
        refs[0].path,
        "crate::{terrain::hash, scene::{Element, Rect}}"
    );
    assert_eq!(refs[3].path, "crate::volume::Chunk");
    // A struct literal or block after a path is not part of it.
    let refs = references(
        Path::new("src/edits.rs"),
        "let r = crate::scene::Rect { min, max };",
    );
    assert_eq!(refs[0].path, "crate::scene::Rect");
    // In a top-level file, one `super` reaches the root.
    let refs = references(Path::new("src/edits.rs"), "fn f() { super::volume::x(); }");
    assert_eq!(refs.len(), 1);
    assert_eq!(refs[0].target, "volume");
    // The binary names the library `strata`.
    let refs = references(Path::new("src/main.rs"), "fn main() { strata::cli::run() }");
    assert_eq!(refs[0].target, "cli");
}
