//! No module cycle inside a crate: for each library crate of the workspace, the graph of its
//! top-level modules (an edge `a -> b` when a source file of `a` names `crate::b`, a root
//! re-export of `b` such as `crate::Rational`, or `b` through `super::`) has no cycle beyond
//! the ones listed in [`KNOWN`]. Test code (`#[cfg(test)]` items and the files they declare)
//! and comments are not part of the graph.
//!
//! Hand-written rather than taken from a crate: the dependency tools (`cargo-modules`) are
//! separate programs that need the compiler's analysis; reading `crate::` and `super::` paths
//! from the sources is enough for this check and runs in milliseconds.

use std::collections::{BTreeMap, BTreeSet, VecDeque};
use std::path::{Path, PathBuf};

/// The cycles that remain, per crate, with the edges that close them. A cycle not contained in
/// one of these fails the test; an entry that is no longer a cycle fails it too (remove it).
/// None remains.
const KNOWN: &[(&str, &[&str])] = &[];

/// The library crates: name and source directory (relative to the workspace root).
const CRATES: &[(&str, &str)] = &[
    ("core", "core/src"),
    ("exact", "exact/src"),
    ("float", "float/src"),
    ("exactcheck", "src"),
];

/// Rust source with comments removed and the contents of string and character literals
/// blanked (so that neither a `//` nor a `{` inside them is read as code).
fn code_only(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < c.len() {
        match c[i] {
            '/' if c.get(i + 1) == Some(&'/') => {
                while i < c.len() && c[i] != '\n' {
                    i += 1;
                }
            }
            '/' if c.get(i + 1) == Some(&'*') => {
                let mut depth = 0;
                while i < c.len() {
                    if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                        depth += 1;
                        i += 2;
                    } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                        depth -= 1;
                        i += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        i += 1;
                    }
                }
            }
            'r' if (c.get(i + 1) == Some(&'"') || c.get(i + 1) == Some(&'#'))
                && !c[..i]
                    .last()
                    .is_some_and(|p| p.is_alphanumeric() || *p == '_') =>
            {
                let mut j = i + 1;
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
                j += 1;
                loop {
                    if j >= c.len() {
                        break;
                    }
                    if c[j] == '"' && (0..hashes).all(|k| c.get(j + 1 + k) == Some(&'#')) {
                        j += 1 + hashes;
                        break;
                    }
                    j += 1;
                }
                out.push_str("\"\"");
                i = j;
            }
            '"' => {
                i += 1;
                while i < c.len() && c[i] != '"' {
                    if c[i] == '\\' {
                        i += 1;
                    }
                    i += 1;
                }
                i += 1;
                out.push_str("\"\"");
            }
            '\'' => {
                // A character literal (`'x'`, `'\n'`, `'{'`), else a lifetime (`'a`).
                if c.get(i + 1) == Some(&'\\') {
                    i += 2;
                    while i < c.len() && c[i] != '\'' {
                        i += 1;
                    }
                    i += 1;
                    out.push_str("' '");
                } else if c.get(i + 2) == Some(&'\'') {
                    i += 3;
                    out.push_str("' '");
                } else {
                    out.push('\'');
                    i += 1;
                }
            }
            ch => {
                out.push(ch);
                i += 1;
            }
        }
    }
    out
}

fn is_ident(ch: char) -> bool {
    ch.is_alphanumeric() || ch == '_'
}

/// The end (exclusive) of the item starting at `from`: its `;` at depth 0, or the `}` closing
/// its first `{`.
fn item_end(s: &[char], from: usize) -> usize {
    let mut depth = 0usize;
    let mut i = from;
    while i < s.len() {
        match s[i] {
            ';' if depth == 0 => return i + 1,
            '{' => depth += 1,
            '}' => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return i + 1;
                }
            }
            _ => {}
        }
        i += 1;
    }
    s.len()
}

/// The code with its `#[cfg(test)]` items removed, and the names of the modules those items
/// declare as files (`#[cfg(test)] mod tests;`).
fn without_tests(code: &str) -> (String, Vec<String>) {
    let s: Vec<char> = code.chars().collect();
    let attr: Vec<char> = "#[cfg(test)]".chars().collect();
    let mut out = String::new();
    let mut test_files = Vec::new();
    let mut i = 0;
    while i < s.len() {
        if s[i..].starts_with(&attr) {
            let end = item_end(&s, i + attr.len());
            let item: String = s[i + attr.len()..end].iter().collect();
            let words: Vec<&str> = item
                .split(|ch: char| !is_ident(ch) && ch != ';')
                .filter(|w| !w.is_empty())
                .collect();
            if let Some(k) = words.iter().position(|w| *w == "mod") {
                if let Some(name) = words.get(k + 1) {
                    if let Some(name) = name.strip_suffix(';') {
                        test_files.push(name.to_string());
                    }
                }
            }
            i = end;
        } else {
            out.push(s[i]);
            i += 1;
        }
    }
    (out, test_files)
}

/// The top-level modules a file's code names: `crate::NAME` (or a root re-export of NAME's
/// item), `crate::{NAME, ...}` and `super::...::NAME` resolving to the crate root.
fn referenced(code: &str, depth: usize, reexports: &BTreeMap<String, String>) -> BTreeSet<String> {
    let s: Vec<char> = code.chars().collect();
    let mut found = BTreeSet::new();
    let ident_at = |mut j: usize| {
        while j < s.len() && s[j].is_whitespace() {
            j += 1;
        }
        let start = j;
        while j < s.len() && is_ident(s[j]) {
            j += 1;
        }
        (s[start..j].iter().collect::<String>(), j)
    };
    let starts = |i: usize, word: &str| {
        let w: Vec<char> = word.chars().collect();
        s[i..].starts_with(&w) && (i == 0 || !is_ident(s[i - 1]))
    };
    // Inline modules (`mod NAME { ... }`): a `super::` inside one climbs out of it first.
    let mut inline: Vec<(usize, usize)> = Vec::new();
    for k in 0..s.len() {
        if starts(k, "mod ") {
            let (_, after) = ident_at(k + "mod ".len());
            let mut j = after;
            while j < s.len() && s[j].is_whitespace() {
                j += 1;
            }
            if s.get(j) == Some(&'{') {
                inline.push((j, item_end(&s, j)));
            }
        }
    }
    let mut i = 0;
    while i < s.len() {
        if starts(i, "crate::") {
            let mut j = i + "crate::".len();
            while j < s.len() && s[j].is_whitespace() {
                j += 1;
            }
            if s.get(j) == Some(&'{') {
                // The first segment of every item of the group.
                let end = item_end(&s, j);
                let group: String = s[j + 1..end.saturating_sub(1)].iter().collect();
                let mut depth = 0;
                let mut item = String::new();
                for ch in group.chars().chain(std::iter::once(',')) {
                    match ch {
                        '{' => depth += 1,
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            let first: String =
                                item.trim().chars().take_while(|c| is_ident(*c)).collect();
                            found.insert(first);
                            item.clear();
                            continue;
                        }
                        _ => {}
                    }
                    item.push(ch);
                }
                i = end;
            } else {
                let (name, end) = ident_at(j);
                found.insert(name);
                i = end;
            }
        } else if starts(i, "super::") {
            let mut n = 0;
            let mut j = i;
            while s[j..].starts_with(&['s', 'u', 'p', 'e', 'r', ':', ':']) {
                n += 1;
                j += "super::".len();
            }
            let nested = inline.iter().filter(|(a, b)| *a < i && i < *b).count();
            if n == depth + nested {
                let (name, end) = ident_at(j);
                found.insert(name);
                j = end;
            }
            i = j;
        } else {
            i += 1;
        }
    }
    found
        .into_iter()
        .map(|n| reexports.get(&n).cloned().unwrap_or(n))
        .collect()
}

/// The `.rs` files under `dir`, recursively.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Module graph of a crate: top-level module -> (module it names -> a file naming it).
type Graph = BTreeMap<String, BTreeMap<String, String>>;

fn crate_graph(src: &Path) -> Graph {
    let root = std::fs::read_to_string(src.join("lib.rs")).expect("the crate root");
    let (root_code, _) = without_tests(&code_only(&root));
    // Top-level modules (`mod NAME;`) and the root's re-exports (`pub use NAME::{A, b::C};`).
    let mut modules = BTreeSet::new();
    let mut reexports = BTreeMap::new();
    for stmt in root_code.split(';') {
        let words: Vec<&str> = stmt.split_whitespace().collect();
        if let Some(k) = words.iter().position(|w| *w == "mod") {
            if let Some(name) = words.get(k + 1) {
                modules.insert(name.to_string());
            }
        }
        if let Some(rest) = stmt.trim().strip_prefix("pub use ") {
            if let Some((module, items)) = rest.split_once("::") {
                for item in items.split([',', '{', '}']) {
                    let item = item.trim();
                    let name = item.rsplit([' ', ':']).next().unwrap_or("");
                    if !name.is_empty() && name != "self" {
                        reexports.insert(name.to_string(), module.trim().to_string());
                    }
                }
            }
        }
    }
    reexports.retain(|name, _| !modules.contains(name));
    let mut graph: Graph = modules
        .iter()
        .map(|m| (m.clone(), BTreeMap::new()))
        .collect();
    let mut files = Vec::new();
    for m in &modules {
        files.push(src.join(format!("{m}.rs")));
        rust_files(&src.join(m), &mut files);
    }
    // Test-only files: declared by a `#[cfg(test)] mod NAME;` of their parent.
    let mut test_only: BTreeSet<PathBuf> = BTreeSet::new();
    let mut code = BTreeMap::new();
    files.sort();
    for f in files.iter().filter(|f| f.is_file()) {
        let text = std::fs::read_to_string(f).expect("a source file");
        let (c, tests) = without_tests(&code_only(&text));
        let dir = if f.file_name().is_some_and(|n| n == "mod.rs") {
            f.parent().expect("a directory").to_path_buf()
        } else {
            f.with_extension("")
        };
        for t in tests {
            test_only.insert(dir.join(format!("{t}.rs")));
            test_only.insert(dir.join(&t));
        }
        let whole_file_test = c.contains("#![cfg(test)]");
        code.insert(f.clone(), (c, whole_file_test));
    }
    for (f, (c, whole_file_test)) in &code {
        if *whole_file_test || test_only.iter().any(|t| f.starts_with(t)) {
            continue;
        }
        let rel = f.strip_prefix(src).expect("inside the crate");
        let mut segs: Vec<String> = rel
            .with_extension("")
            .iter()
            .map(|s| s.to_string_lossy().into_owned())
            .collect();
        if segs.last().is_some_and(|s| s == "mod") {
            segs.pop();
        }
        let module = segs[0].clone();
        for target in referenced(c, segs.len(), &reexports) {
            if target != module && modules.contains(&target) {
                graph
                    .get_mut(&module)
                    .expect("a module")
                    .entry(target)
                    .or_insert_with(|| rel.display().to_string());
            }
        }
    }
    graph
}

/// The strongly connected components of more than one module (Tarjan).
fn cycles(graph: &Graph) -> Vec<BTreeSet<String>> {
    struct State<'a> {
        graph: &'a Graph,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        found: Vec<BTreeSet<String>>,
    }
    fn visit<'a>(st: &mut State<'a>, v: &'a str) {
        let n = st.index.len();
        st.index.insert(v, n);
        st.low.insert(v, n);
        st.stack.push(v);
        for w in st.graph[v].keys() {
            let w = w.as_str();
            if !st.index.contains_key(w) {
                visit(st, w);
                let lw = st.low[w];
                let lv = st.low.get_mut(v).expect("visited");
                *lv = (*lv).min(lw);
            } else if st.stack.contains(&w) {
                let iw = st.index[w];
                let lv = st.low.get_mut(v).expect("visited");
                *lv = (*lv).min(iw);
            }
        }
        if st.low[v] == st.index[v] {
            let mut comp = BTreeSet::new();
            while let Some(w) = st.stack.pop() {
                comp.insert(w.to_string());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                st.found.push(comp);
            }
        }
    }
    let mut st = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in graph.keys() {
        if !st.index.contains_key(v.as_str()) {
            visit(&mut st, v);
        }
    }
    st.found
}

/// One shortest cycle through the first module of `comp`, each step with the file that makes
/// it: `a -> b (a/x.rs) -> a (b.rs)`.
fn describe(graph: &Graph, comp: &BTreeSet<String>) -> String {
    let start = comp.iter().next().expect("non-empty");
    let mut prev: BTreeMap<&str, &str> = BTreeMap::new();
    let mut queue = VecDeque::from([start.as_str()]);
    'search: while let Some(v) = queue.pop_front() {
        for w in graph[v].keys().filter(|w| comp.contains(*w)) {
            if w == start {
                prev.insert(start, v);
                break 'search;
            }
            if !prev.contains_key(w.as_str()) {
                prev.insert(w, v);
                queue.push_back(w);
            }
        }
    }
    let mut path = vec![start.as_str()];
    let mut at = prev[start.as_str()];
    while at != start {
        path.push(at);
        at = prev[at];
    }
    path.push(start);
    path.reverse();
    let mut text = path[0].to_string();
    for pair in path.windows(2) {
        text += &format!(" -> {} ({})", pair[1], graph[pair[0]][pair[1]]);
    }
    format!("{text} [all modules of the cycle: {comp:?}]")
}

#[test]
fn no_module_cycle_inside_a_crate() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut problems = Vec::new();
    for (name, dir) in CRATES {
        let graph = crate_graph(&workspace.join(dir));
        assert!(
            graph.len() > 3,
            "{name}: the modules of {dir} were not found"
        );
        let known: Vec<BTreeSet<String>> = KNOWN
            .iter()
            .filter(|(c, _)| c == name)
            .map(|(_, m)| m.iter().map(|s| s.to_string()).collect())
            .collect();
        let found = cycles(&graph);
        for comp in &found {
            if !known.iter().any(|k| comp.is_subset(k)) {
                problems.push(format!(
                    "crate {name}: module cycle {}",
                    describe(&graph, comp)
                ));
            }
        }
        for k in &known {
            if !found.iter().any(|comp| comp.intersection(k).count() > 1) {
                problems.push(format!(
                    "crate {name}: the listed cycle {k:?} is gone: remove it from KNOWN"
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The reader finds a cycle made of each kind of path, and none in test code or comments.
#[test]
fn the_reader_sees_crate_super_and_reexport_paths_only_in_code() {
    let dir = std::env::temp_dir().join(format!("exactcheck-cycles-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("b")).unwrap();
    let write = |p: &str, t: &str| std::fs::write(dir.join(p), t).unwrap();
    write(
        "lib.rs",
        "pub mod a;\npub mod b;\npub mod c;\npub mod d;\npub use c::Thing;\n",
    );
    // a -> b through a group, b -> a through `super::super` from a file below b.
    write("a.rs", "use crate::{b::X, d};\n// crate::c in a comment\n");
    write("b/mod.rs", "mod inner;\n#[cfg(test)]\nmod tests;\n");
    write("b/inner.rs", "fn f() { super::super::a::g() }\n");
    write("b/tests.rs", "use crate::c;\n");
    // c -> d by a path (`super::a` in c's inline module is c's own `a`); d -> c only through the
    // root re-export, and in a string and a test.
    write(
        "c.rs",
        "fn f() -> crate::d::Y { todo!() }\nconst S: &str = \"crate::a\";\nmod inner {\n    use super::a;\n}\n",
    );
    write(
        "d.rs",
        "fn f(_: crate::Thing) {}\n#[cfg(test)]\nmod tests { use crate::a; fn x() { let _ = '{'; } }\n",
    );
    let graph = crate_graph(&dir);
    let edges = |m: &str| graph[m].keys().cloned().collect::<Vec<_>>();
    assert_eq!(edges("a"), ["b", "d"]);
    assert_eq!(edges("b"), ["a"]);
    assert_eq!(edges("c"), ["d"]);
    assert_eq!(edges("d"), ["c"]);
    let mut found = cycles(&graph);
    found.sort();
    assert_eq!(found.len(), 2, "{found:?}");
    let text = describe(&graph, &found[0]);
    assert_eq!(
        text,
        r#"a -> b (a.rs) -> a (b/inner.rs) [all modules of the cycle: {"a", "b"}]"#
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
