//! No import cycles between the crate's modules (docs/architecture.md, "the map"): the
//! `crate::`, `super::` and `self::` paths of every module under `src/` (the app's folders
//! included) are drawn as edges, and the graph must have no cycle.
//!
//! An edge from module `a` to module `b` counts between the two children of their nearest
//! common ancestor that hold them (`raster::render -> budget` is `raster -> budget` at the
//! top level); a module using its own ancestor or descendant is containment, not an edge.
//! A path through a `pub use` re-export is followed to the module that defines the name.
//! Comments, strings and `#[cfg(test)]` modules are left out.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

type Module = Vec<String>;

/// The source of `text` without comments, string and character literals, and without the
/// `#[cfg(test)]` modules from the first one on.
fn code_only(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < b.len() {
        let rest = &text[i..];
        if rest.starts_with("//") {
            i += rest.find('\n').unwrap_or(rest.len());
        } else if rest.starts_with("/*") {
            let mut depth = 0;
            while i < b.len() {
                if text[i..].starts_with("/*") {
                    depth += 1;
                    i += 2;
                } else if text[i..].starts_with("*/") {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if let Some(hashes) = raw_string_start(rest) {
            let close = format!("\"{}", "#".repeat(hashes));
            let open = hashes + 2;
            i += open
                + rest[open..]
                    .find(&close)
                    .map_or(rest.len() - open, |k| k + close.len());
            out.push_str("\"\"");
        } else if b[i] == b'"' {
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if b[i] == b'\'' && (rest.get(1..2) == Some("\\") || rest.get(2..3) == Some("'")) {
            // A character literal ('x', '\n', '\''); a lifetime has no closing quote.
            i += 1;
            while i < b.len() && b[i] != b'\'' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
        } else {
            let c = rest.chars().next().expect("a character");
            out.push(c);
            i += c.len_utf8();
        }
    }
    match out.find("#[cfg(test)]") {
        Some(k)
            if out[k..]
                .trim_start_matches("#[cfg(test)]")
                .trim_start()
                .starts_with("mod ") =>
        {
            out.truncate(k);
            out
        }
        _ => out,
    }
}

/// `Some(number of #)` when `s` starts a raw string `r"`, `r#"`, ...
fn raw_string_start(s: &str) -> Option<usize> {
    let t = s.strip_prefix('r')?;
    let hashes = t.len() - t.trim_start_matches('#').len();
    t[hashes..].starts_with('"').then_some(hashes)
}

/// The paths a `use` tree names, braces expanded: `a::{b, c::{d, e}}` -> `a::b`, `a::c::d`,
/// `a::c::e` (aliases dropped).
fn expand(tree: &str) -> Vec<String> {
    let tree: String = tree.split_whitespace().collect::<Vec<_>>().join(" ");
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or_default();
        return vec![path.replace(' ', "")];
    };
    let mut depth = 0;
    let mut close = tree.len();
    for (k, c) in tree.char_indices().skip(open) {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    close = k;
                    break;
                }
            }
            _ => {}
        }
    }
    let (prefix, inner) = (&tree[..open], &tree[open + 1..close]);
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (k, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..k]);
                start = k + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.trim().is_empty())
        .flat_map(|p| expand(&format!("{prefix}{}", p.trim())))
        .map(|p| p.trim_end_matches("::self").to_string())
        .collect()
}

/// Every module under `dir`, by path from the crate root, with its code.
fn modules(root: &Path, dir: &Path, out: &mut BTreeMap<Module, (bool, String)>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("read src")
        .map(|e| e.expect("entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            modules(root, &path, out);
            continue;
        }
        if path.extension().and_then(|e| e.to_str()) != Some("rs") {
            continue;
        }
        let rel = path.strip_prefix(root).expect("under src");
        let mut m: Module = rel
            .with_extension("")
            .iter()
            .map(|s| s.to_string_lossy().into_owned())
            .collect();
        let is_dir_module = matches!(m.last().map(String::as_str), Some("mod" | "lib" | "main"));
        if is_dir_module {
            m.pop();
        }
        let text = std::fs::read_to_string(&path).expect("read a source file");
        out.insert(m, (is_dir_module, code_only(&text)));
    }
}

/// The module a path names from module `from` (a directory module when `dir`), and the rest of
/// the path after it. `None` for paths outside the crate.
fn resolve(
    mods: &BTreeMap<Module, (bool, String)>,
    from: &Module,
    dir: bool,
    path: &str,
) -> Option<(Module, Vec<String>)> {
    let segs: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
    let mut full: Module = match segs.first()? {
        &"crate" => Vec::new(),
        &"self" | &"super" => {
            // `self` of a file module is itself; `super` goes one level up from it.
            let mut base = from.clone();
            let _ = dir;
            for s in &segs {
                match *s {
                    "self" => {}
                    "super" => {
                        base.pop();
                    }
                    _ => break,
                }
            }
            base
        }
        _ => return None,
    };
    full.extend(
        segs.iter()
            .skip_while(|s| matches!(**s, "crate" | "self" | "super"))
            .map(|s| s.to_string()),
    );
    (0..=full.len())
        .rev()
        .find(|&k| mods.contains_key(&full[..k]))
        .map(|k| (full[..k].to_vec(), full[k..].to_vec()))
}

/// The paths a module's code names: its `use` trees and inline `crate::`, `super::` and
/// `self::` paths. Each with whether it is a `pub` re-export.
fn paths(code: &str) -> Vec<(String, bool)> {
    let mut out = Vec::new();
    let words: Vec<(usize, &str)> = code
        .match_indices(|c: char| !(c.is_alphanumeric() || c == '_'))
        .scan(0, |start, (k, sep)| {
            let word = (*start, &code[*start..k]);
            *start = k + sep.len();
            Some(word)
        })
        .collect();
    for (k, w) in &words {
        if *w == "use" {
            let end = code[*k..].find(';').map_or(code.len(), |e| k + e);
            let tree = &code[k + 3..end];
            let before = code[..*k].trim_end();
            let public =
                before.ends_with("pub") || before.ends_with(')') && before.contains("pub(");
            out.extend(expand(tree).into_iter().map(|p| (p, public)));
        }
    }
    for start in ["crate::", "super::", "self::"] {
        for (k, _) in code.match_indices(start) {
            let prev = code[..k].chars().next_back();
            if prev.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let end = code[k..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |e| k + e);
            out.push((code[k..end].trim_end_matches(':').to_string(), false));
        }
    }
    out
}

/// The edges between sibling modules, each with the file-level edges behind it.
fn sibling_edges() -> BTreeMap<(Module, Module), BTreeSet<String>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut mods = BTreeMap::new();
    modules(&root, &root, &mut mods);
    let mut raw: BTreeMap<Module, Vec<(Module, Vec<String>, bool)>> = BTreeMap::new();
    let mut reexports: BTreeMap<Module, BTreeMap<String, Module>> = BTreeMap::new();
    for (m, (dir, code)) in &mods {
        for (path, public) in paths(code) {
            if let Some((target, rest)) = resolve(&mods, m, *dir, &path) {
                if public && let Some(name) = rest.last() {
                    reexports
                        .entry(m.clone())
                        .or_default()
                        .insert(name.clone(), target.clone());
                }
                raw.entry(m.clone())
                    .or_default()
                    .push((target, rest, public));
            }
        }
    }
    let name = |m: &Module| {
        if m.is_empty() {
            "crate".to_string()
        } else {
            m.join("::")
        }
    };
    let mut edges: BTreeMap<(Module, Module), BTreeSet<String>> = BTreeMap::new();
    for (m, targets) in &raw {
        for (target, rest, _) in targets {
            let mut t = target.clone();
            for _ in 0..10 {
                match rest.first().and_then(|r| reexports.get(&t)?.get(r)) {
                    Some(next) if *next != t => t = next.clone(),
                    _ => break,
                }
            }
            if t.starts_with(m) || m.starts_with(&t) {
                continue;
            }
            let common = m.iter().zip(&t).take_while(|(a, b)| a == b).count();
            let (a, b) = (m[..=common].to_vec(), t[..=common].to_vec());
            edges
                .entry((a, b))
                .or_default()
                .insert(format!("{} -> {}", name(m), name(&t)));
        }
    }
    edges
}

#[test]
fn every_module_imports_one_way() {
    let edges = sibling_edges();
    assert!(
        edges.len() > 100,
        "only {} edges found: the scan is broken",
        edges.len()
    );
    // A known edge, as a check that the scan sees what it should.
    assert!(
        edges.contains_key(&(vec!["raster".to_string()], vec!["budget".to_string()])),
        "raster -> budget not found"
    );
    let app = |m: &str| vec!["app".to_string(), m.to_string()];
    assert!(
        edges.contains_key(&(app("panels"), app("document"))),
        "app::panels -> app::document not found: the app's folders are not scanned"
    );
    let mut graph: BTreeMap<&Module, Vec<&Module>> = BTreeMap::new();
    for (a, b) in edges.keys() {
        graph.entry(a).or_default().push(b);
    }
    // Depth-first search for a back edge; a cycle is reported with the edges behind it.
    let mut state: BTreeMap<&Module, u8> = BTreeMap::new();
    let mut cycles = Vec::new();
    fn visit<'g>(
        v: &'g Module,
        graph: &BTreeMap<&'g Module, Vec<&'g Module>>,
        state: &mut BTreeMap<&'g Module, u8>,
        stack: &mut Vec<&'g Module>,
        cycles: &mut Vec<Vec<&'g Module>>,
    ) {
        state.insert(v, 1);
        stack.push(v);
        for &w in graph.get(v).map(Vec::as_slice).unwrap_or_default() {
            match state.get(w) {
                None => visit(w, graph, state, stack, cycles),
                Some(1) => {
                    let from = stack.iter().position(|&s| s == w).unwrap_or_default();
                    cycles.push(stack[from..].to_vec());
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(v, 2);
    }
    for &v in graph.keys() {
        if !state.contains_key(v) {
            visit(v, &graph, &mut state, &mut Vec::new(), &mut cycles);
        }
    }
    let described: Vec<String> = cycles
        .iter()
        .map(|c| {
            let mut lines = Vec::new();
            for (k, a) in c.iter().enumerate() {
                let b = c[(k + 1) % c.len()];
                let why = &edges[&((*a).clone(), b.clone())];
                lines.push(format!(
                    "  {} -> {} ({})",
                    a.join("::"),
                    b.join("::"),
                    why.iter().cloned().collect::<Vec<_>>().join(", ")
                ));
            }
            lines.join("\n")
        })
        .collect();
    assert!(
        cycles.is_empty(),
        "import cycles:\n{}",
        described.join("\n\n")
    );
}
