//! Layering of src/: the file-level module dependency graph has no cycle,
//! so each module depends only on modules below it.
//!
//! The graph is read from the source text, without rustc: every `use` tree
//! and every `crate::…`, `super::…`, `self::…` path (and, in a file that
//! declares child modules, `child::…`) is mapped to the file that defines
//! it, following `pub use` re-exports (`super::Machine` is sim/machine.rs)
//! and `#[macro_export]` macros (`crate::log_at!` is client/log.rs).
//! A `pub use` is a dependency only if the file's own code uses the name
//! too: `pub use alarm::*` in types/mod.rs is a façade, so types::alarm may
//! use `super::LONG`. `#[cfg(test)]` items are left out. `cargo test --test artifacts layers:: -- --nocapture`
//! prints the graph.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module's path from the crate root ("" is the crate root).
type Module = String;

fn join(a: &str, b: &str) -> String {
    if a.is_empty() {
        b.to_string()
    } else {
        format!("{a}::{b}")
    }
}

fn is_ident(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// The text with comments, string and char literals blanked (same length,
/// newlines kept), so braces and paths can be found by scanning.
fn strip(src: &str) -> Vec<u8> {
    let s = src.as_bytes();
    let mut out = s.to_vec();
    let blank = |out: &mut Vec<u8>, from: usize, to: usize| {
        for c in &mut out[from..to.min(s.len())] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    };
    let mut i = 0;
    while i < s.len() {
        let rest = &s[i..];
        if rest.starts_with(b"//") {
            let end = rest
                .iter()
                .position(|&c| c == b'\n')
                .map_or(s.len(), |p| i + p);
            blank(&mut out, i, end);
            i = end;
        } else if rest.starts_with(b"/*") {
            let (mut depth, mut j) = (0, i);
            while j < s.len() {
                if s[j..].starts_with(b"/*") {
                    depth += 1;
                    j += 2;
                } else if s[j..].starts_with(b"*/") {
                    depth -= 1;
                    j += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    j += 1;
                }
            }
            blank(&mut out, i, j);
            i = j;
        } else if (rest.starts_with(b"r\"") || rest.starts_with(b"r#") || rest.starts_with(b"br"))
            && (i == 0 || !is_ident(s[i - 1]))
        {
            // Raw string: r"…", r#"…"#, br"…".
            let mut j = i + if rest[0] == b'b' { 2 } else { 1 };
            let hashes = s[j..].iter().take_while(|&&c| c == b'#').count();
            j += hashes;
            if s.get(j) != Some(&b'"') {
                i += 1;
                continue;
            }
            let close: Vec<u8> = std::iter::once(b'"')
                .chain(std::iter::repeat_n(b'#', hashes))
                .collect();
            let end = s[j + 1..]
                .windows(close.len())
                .position(|w| w == close.as_slice())
                .map_or(s.len(), |p| j + 1 + p + close.len());
            blank(&mut out, i, end);
            i = end;
        } else if rest[0] == b'"' {
            let mut j = i + 1;
            while j < s.len() && s[j] != b'"' {
                j += if s[j] == b'\\' { 2 } else { 1 };
            }
            blank(&mut out, i, j + 1);
            i = j + 1;
        } else if rest[0] == b'\'' {
            // A char literal ('x', '\n', '\u{..}'), or a lifetime ('a).
            if rest.get(1) == Some(&b'\\') {
                let end = s[i + 2..]
                    .iter()
                    .position(|&c| c == b'\'')
                    .map_or(s.len(), |p| i + 3 + p);
                blank(&mut out, i, end);
                i = end;
            } else if let Some(len) = std::str::from_utf8(&rest[1..rest.len().min(6)])
                .ok()
                .or_else(|| std::str::from_utf8(&rest[1..rest.len().min(2)]).ok())
                .and_then(|t| t.chars().next())
                .map(char::len_utf8)
                .filter(|&l| rest.get(1 + l) == Some(&b'\''))
            {
                blank(&mut out, i, i + 2 + len);
                i += 2 + len;
            } else {
                i += 1;
            }
        } else {
            i += 1;
        }
    }
    out
}

/// Index just past the item starting at `i`: its `;`, or its `{ … }` block.
fn item_end(s: &[u8], mut i: usize) -> usize {
    let mut depth = 0usize;
    while i < s.len() {
        match s[i] {
            b';' if depth == 0 => return i + 1,
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
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

/// Blanks every `#[cfg(test)]` item (test-only code may use anything).
fn drop_test_items(s: &mut [u8]) {
    const ATTR: &[u8] = b"#[cfg(test)]";
    while let Some(at) = s.windows(ATTR.len()).position(|w| w == ATTR) {
        let end = item_end(s, at + ATTR.len());
        for c in &mut s[at..end] {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    }
}

fn word_at(s: &[u8], i: usize, w: &[u8]) -> bool {
    // Not a raw identifier (`r#use`, a field named after the keyword).
    s[i..].starts_with(w)
        && (i == 0 || !is_ident(s[i - 1]) && s[i - 1] != b'#')
        && s.get(i + w.len()).is_none_or(|&c| !is_ident(c))
}

fn ident_at(s: &[u8], i: usize) -> &str {
    let n = s[i..].iter().take_while(|&&c| is_ident(c)).count();
    std::str::from_utf8(&s[i..i + n]).unwrap()
}

fn skip_ws(s: &[u8], mut i: usize) -> usize {
    while i < s.len() && s[i].is_ascii_whitespace() {
        i += 1;
    }
    i
}

/// Expands a `use` tree (`a::{b, c::{d as e, self}, f::*}`) into
/// (path, name it is bound to) pairs; a glob's name is "*".
fn expand(tree: &str, prefix: &[String], out: &mut Vec<(Vec<String>, String)>) {
    let tree = tree.trim();
    if tree.is_empty() {
        return;
    }
    // Split at the first top-level `{`.
    if let Some(open) = tree.find('{') {
        let head: Vec<String> = tree[..open]
            .split("::")
            .map(str::trim)
            .filter(|x| !x.is_empty())
            .map(String::from)
            .collect();
        let close = tree.rfind('}').unwrap_or(tree.len());
        let inner = &tree[open + 1..close];
        let mut p = prefix.to_vec();
        p.extend(head);
        let (mut depth, mut start) = (0, 0);
        for (k, c) in inner.char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    expand(&inner[start..k], &p, out);
                    start = k + 1;
                }
                _ => {}
            }
        }
        expand(&inner[start..], &p, out);
        return;
    }
    let (path, alias) = match tree.split_once(" as ") {
        Some((p, a)) => (p.trim(), Some(a.trim().to_string())),
        None => (tree, None),
    };
    let mut p = prefix.to_vec();
    p.extend(path.split("::").map(|x| x.trim().to_string()));
    if p.last().is_some_and(|l| l == "self") {
        p.pop();
    }
    let name = alias.unwrap_or_else(|| p.last().cloned().unwrap_or_default());
    out.push((p, name));
}

/// One reference found in a file: from which (possibly inline) module.
struct Ref {
    scope: Module,
    path: Vec<String>,
    /// `pub use`: binds `name` in `scope` to `path`.
    reexport: Option<String>,
    /// A `pub use` whose name the file's own code does not use (a glob, or
    /// a name only passed on): namespace plumbing, not a dependency.
    facade: bool,
}

struct File {
    module: Module,
    text: Vec<u8>,
    children: BTreeSet<String>,
    refs: Vec<Ref>,
}

fn module_of(src: &Path, file: &Path) -> Module {
    let rel = file.strip_prefix(src).unwrap();
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_str().unwrap().trim_end_matches(".rs").to_string())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts.join("::")
}

fn scan(module: Module, src: &str) -> File {
    let mut s = strip(src);
    drop_test_items(&mut s);
    let mut children = BTreeSet::new();
    let mut refs = Vec::new();
    // Inline modules: (name, brace depth inside them).
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut pending_mod: Option<String> = None;
    let mut uses = Vec::new();
    let mut depth = 0;
    let mut i = 0;
    let scope_of =
        |inline: &[(String, usize)]| inline.iter().fold(module.clone(), |m, (n, _)| join(&m, n));
    while i < s.len() {
        match s[i] {
            b'{' => {
                depth += 1;
                if let Some(n) = pending_mod.take() {
                    inline.push((n, depth));
                }
                i += 1;
                continue;
            }
            b'}' => {
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
                depth -= 1;
                i += 1;
                continue;
            }
            _ => {}
        }
        if !is_ident(s[i]) || (i > 0 && (is_ident(s[i - 1]) || s[i - 1] == b':')) {
            i += 1;
            continue;
        }
        if word_at(&s, i, b"mod") {
            let j = skip_ws(&s, i + 3);
            let name = ident_at(&s, j).to_string();
            let k = skip_ws(&s, j + name.len());
            if s.get(k) == Some(&b';') {
                if inline.is_empty() {
                    children.insert(name);
                }
            } else {
                pending_mod = Some(name);
            }
            i = k;
            continue;
        }
        if word_at(&s, i, b"use") {
            let end = i + s[i..].iter().position(|&c| c == b';').unwrap();
            let tree = std::str::from_utf8(&s[i + 3..end]).unwrap();
            let before = std::str::from_utf8(&s[i.saturating_sub(20)..i])
                .unwrap()
                .trim_end();
            let is_pub = ["pub", "pub(crate)", "pub(super)"]
                .iter()
                .any(|v| before.ends_with(v));
            let mut leaves = Vec::new();
            expand(tree, &[], &mut leaves);
            for (path, name) in leaves {
                refs.push(Ref {
                    scope: scope_of(&inline),
                    path,
                    reexport: is_pub.then_some(name),
                    facade: false,
                });
            }
            uses.push((i, end + 1));
            i = end + 1;
            continue;
        }
        // A path: ident(::ident)*, optionally a macro call.
        let mut path = Vec::new();
        let mut j = i;
        loop {
            let id = ident_at(&s, j);
            path.push(id.to_string());
            j += id.len();
            if s[j..].starts_with(b"::") && s.get(j + 2).is_some_and(|&c| is_ident(c)) {
                j += 2;
            } else {
                break;
            }
        }
        let first = path[0].as_str();
        let relative = matches!(first, "crate" | "super" | "self")
            || (inline.is_empty() && path.len() > 1 && children.contains(first));
        if relative && path.len() > 1 {
            refs.push(Ref {
                scope: scope_of(&inline),
                path,
                reexport: None,
                facade: false,
            });
        }
        i = j;
    }
    let mut code = s.clone();
    for (a, b) in uses {
        code[a..b].fill(b' ');
    }
    for r in &mut refs {
        if let Some(name) = &r.reexport {
            r.facade = name == "*" || !(0..code.len()).any(|k| word_at(&code, k, name.as_bytes()));
        }
    }
    File {
        module,
        text: s,
        children,
        refs,
    }
}

/// Makes a path absolute (from the crate root), as seen from `scope`.
fn absolute(scope: &str, path: &[String], children: &BTreeSet<String>) -> Option<Vec<String>> {
    let mut m: Vec<String> = if scope.is_empty() {
        Vec::new()
    } else {
        scope.split("::").map(String::from).collect()
    };
    let mut rest = path;
    match path.first().map(String::as_str) {
        Some("crate") => {
            m.clear();
            rest = &path[1..];
        }
        Some("super" | "self") => {
            while let Some(seg) = rest.first() {
                match seg.as_str() {
                    "super" => {
                        m.pop();
                    }
                    "self" => {}
                    _ => break,
                }
                rest = &rest[1..];
            }
        }
        Some(first) if children.contains(first) => {}
        _ => return None, // another crate
    }
    m.extend(rest.iter().cloned());
    Some(m)
}

struct Crate {
    files: BTreeMap<Module, File>,
    /// `pub use` bindings: (module, name) -> absolute path.
    reexports: BTreeMap<(Module, String), Vec<String>>,
    /// `#[macro_export]` macros: name -> defining module.
    macros: BTreeMap<String, Module>,
}

impl Crate {
    fn load(src: &Path) -> Crate {
        let mut files = BTreeMap::new();
        let mut stack = vec![src.to_path_buf()];
        while let Some(dir) = stack.pop() {
            for e in std::fs::read_dir(&dir).unwrap() {
                let p = e.unwrap().path();
                if p.is_dir() {
                    if p.file_name().unwrap() != "bin" {
                        stack.push(p);
                    }
                } else if p.extension().is_some_and(|x| x == "rs") {
                    let module = module_of(src, &p);
                    let text = std::fs::read_to_string(&p).unwrap();
                    files.insert(module.clone(), scan(module, &text));
                }
            }
        }
        let mut reexports = BTreeMap::new();
        let mut macros = BTreeMap::new();
        for f in files.values() {
            for r in &f.refs {
                if let (Some(name), Some(abs)) =
                    (&r.reexport, absolute(&r.scope, &r.path, &f.children))
                {
                    reexports.insert((r.scope.clone(), name.clone()), abs);
                }
            }
            let t = String::from_utf8_lossy(&f.text);
            for part in t.split("#[macro_export]").skip(1) {
                if let Some(rest) = part.trim_start().strip_prefix("macro_rules!") {
                    let name = rest
                        .trim_start()
                        .split(|c: char| !c.is_alphanumeric() && c != '_');
                    macros.insert(
                        name.into_iter().next().unwrap().to_string(),
                        f.module.clone(),
                    );
                }
            }
        }
        Crate {
            files,
            reexports,
            macros,
        }
    }

    /// Whether `module`'s file defines an item called `name`.
    fn defines(&self, module: &str, name: &str) -> bool {
        let Some(f) = self.files.get(module) else {
            return false;
        };
        let t = String::from_utf8_lossy(&f.text);
        [
            "fn", "struct", "enum", "const", "static", "type", "trait", "mod", "union",
        ]
        .iter()
        .any(|kw| {
            t.match_indices(&format!("{kw} {name}")).any(|(k, _)| {
                t.as_bytes()
                    .get(k + kw.len() + 1 + name.len())
                    .is_none_or(|&c| !is_ident(c))
            })
        })
    }

    /// The file-level module an absolute path lands in.
    fn resolve(&self, path: &[String]) -> Module {
        let mut path = path.to_vec();
        let mut cur = String::new();
        let mut k = 0;
        for _ in 0..32 {
            if k == path.len() {
                return cur;
            }
            let seg = &path[k];
            let next = join(&cur, seg);
            if self.files.contains_key(&next) {
                cur = next;
                k += 1;
                continue;
            }
            if let Some(target) = self.reexports.get(&(cur.clone(), seg.clone())) {
                let mut p = target.clone();
                p.extend_from_slice(&path[k + 1..]);
                (path, cur, k) = (p, String::new(), 0);
                continue;
            }
            if cur.is_empty()
                && let Some(m) = self.macros.get(seg)
            {
                return m.clone();
            }
            if !self.defines(&cur, seg) {
                // A glob re-export (`pub use a::*`) that brings `seg` in.
                let glob = self.reexports.iter().find_map(|((m, n), target)| {
                    (*m == cur && n == "*" && self.defines(&self.resolve(target), seg))
                        .then(|| target.clone())
                });
                if let Some(mut p) = glob {
                    p.extend_from_slice(&path[k..]);
                    (path, cur, k) = (p, String::new(), 0);
                    continue;
                }
            }
            return cur;
        }
        cur
    }

    /// module -> modules it refers to (file level, without itself).
    fn graph(&self) -> BTreeMap<Module, BTreeSet<Module>> {
        let mut g: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
        for f in self.files.values() {
            let deps = g.entry(f.module.clone()).or_default();
            for r in f.refs.iter().filter(|r| !r.facade) {
                if let Some(abs) = absolute(&r.scope, &r.path, &f.children) {
                    let to = self.resolve(&abs);
                    if to != f.module {
                        deps.insert(to);
                    }
                }
            }
        }
        g
    }
}

/// The strongly connected components with more than one module, each
/// shown as one cycle through it.
fn cycles(g: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<Vec<Module>> {
    let reach = |from: &Module| {
        let mut seen = BTreeSet::new();
        let mut todo = vec![from.clone()];
        while let Some(m) = todo.pop() {
            for n in g.get(&m).into_iter().flatten() {
                if seen.insert(n.clone()) {
                    todo.push(n.clone());
                }
            }
        }
        seen
    };
    let reach: BTreeMap<&Module, BTreeSet<Module>> = g.keys().map(|m| (m, reach(m))).collect();
    let mut done = BTreeSet::new();
    let mut out = Vec::new();
    for m in g.keys() {
        if done.contains(m) || !reach[m].contains(m) {
            continue;
        }
        let scc: BTreeSet<&Module> = g
            .keys()
            .filter(|n| reach[m].contains(*n) && reach[*n].contains(m))
            .collect();
        done.extend(scc.iter().cloned().cloned());
        // Shortest way back to m (breadth first, inside the component).
        let mut prev: BTreeMap<&Module, &Module> = BTreeMap::new();
        let mut queue = std::collections::VecDeque::from([m]);
        'bfs: while let Some(a) = queue.pop_front() {
            for b in &g[a] {
                if b == m {
                    // m -> … -> a -> m, read backwards from a.
                    let mut back = vec![m.clone()];
                    let mut x = a;
                    while x != m {
                        back.push(x.clone());
                        x = prev[x];
                    }
                    back.push(m.clone());
                    back.reverse();
                    out.push(back);
                    break 'bfs;
                }
                if scc.contains(b) && !prev.contains_key(b) && b != m {
                    prev.insert(b, a);
                    queue.push_back(b);
                }
            }
        }
    }
    out
}

fn name(m: &str) -> &str {
    if m.is_empty() { "crate" } else { m }
}

fn src() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Issue 23: a file past a few hundred lines splits by meaning.
const MOST_LINES: usize = 600;

#[test]
fn no_source_file_is_past_600_lines() {
    fn walk(dir: &Path, out: &mut Vec<(usize, PathBuf)>) {
        for e in std::fs::read_dir(dir).expect("read src") {
            let p = e.expect("entry").path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let text = std::fs::read_to_string(&p).expect("read a source file");
                out.push((text.lines().count(), p));
            }
        }
    }
    let mut files = Vec::new();
    walk(&src(), &mut files);
    assert!(files.len() > 100, "only {} files under src/", files.len());
    files.sort();
    let long: Vec<String> = files
        .iter()
        .filter(|(n, _)| *n > MOST_LINES)
        .map(|(n, p)| format!("{} ({n} lines)", p.display()))
        .collect();
    println!("longest: {:?}", files.last());
    assert!(
        long.is_empty(),
        "past {MOST_LINES} lines (split by meaning):\n  {}",
        long.join("\n  ")
    );
}

#[test]
fn src_module_graph_has_no_cycle() {
    let c = Crate::load(&src());
    let g = c.graph();
    for (m, deps) in &g {
        let deps: Vec<&str> = deps.iter().map(|d| name(d)).collect();
        println!("{} -> {}", name(m), deps.join(", "));
    }
    // The scanner sees what it should (a broken one would find no cycle either).
    for (from, to) in [
        ("client::pair", "client::conn"),
        ("client::conn", "client::log"),
        ("sim", "sim::server"),
        ("sim::param", "sim::machine"),
        ("sim::session", "sim::service"),
        ("ffi::handle", "client::pair"),
    ] {
        assert!(g[from].contains(to), "the scanner misses {from} -> {to}");
    }
    let found = cycles(&g);
    let shown: Vec<String> = found
        .iter()
        .map(|c| c.iter().map(|m| name(m)).collect::<Vec<_>>().join(" -> "))
        .collect();
    assert!(
        found.is_empty(),
        "module import cycles in src/:\n  {}",
        shown.join("\n  ")
    );
}

#[test]
fn the_scanner_follows_reexports_and_skips_test_code() {
    let lib = scan(String::new(), "pub mod a;\npub mod b;\npub use a::Thing;\n");
    let a = scan(
        "a".into(),
        "use crate::b::{self as bee, x::{Y, Z}};\n// use crate::c;\nfn f() { let s = \"crate::c::x\"; crate::log!(s); }\n#[cfg(test)]\nmod tests { use crate::c::Q; }\n",
    );
    let b = scan(
        "b".into(),
        "pub struct Y; fn g() -> super::Thing { todo!() }\n",
    );
    let c = Crate {
        reexports: [(
            ("".to_string(), "Thing".to_string()),
            vec!["a".into(), "Thing".into()],
        )]
        .into(),
        files: [lib, a, b]
            .into_iter()
            .map(|f| (f.module.clone(), f))
            .collect(),
        macros: [("log".to_string(), "b".to_string())].into(),
    };
    let g = c.graph();
    assert_eq!(g["a"], BTreeSet::from(["b".to_string()]));
    assert_eq!(g["b"], BTreeSet::from(["a".to_string()]));
    assert_eq!(
        cycles(&g),
        vec![vec!["a".to_string(), "b".into(), "a".into()]]
    );
}
