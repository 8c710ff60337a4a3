//! `focas compat FILE`: will a program (or a library) built for FANUC's
//! FOCAS library work with this one? The FOCAS functions it uses, each
//! looked up in the table of this library's exports (`fwlib32::ffi::exports`,
//! written by build.rs from the same sources as the exports, and read by
//! COMPATIBILITY.md too) and in the list of FANUC's functions
//! (tools/compat/fanuc-functions.txt). Of a program or library (ELF): its
//! undefined `cnc_*`, `pmc_*` and `fwlib_*` symbols (linked), and the
//! FOCAS names in its strings (a program that loads the library with
//! `dlopen` looks its functions up by name: only mentioned, not linked).
//! Of a source file (C, C++, C#, Java, Python, Go, Rust ...): the FOCAS
//! names it contains.

use crate::binary;
use crate::out::{Fail, Table, json_line, print};
use fwlib32::ffi::exports::{EXPORTS, How, export};
use serde_json::json;
use std::path::Path;

/// FANUC's `cnc_*`/`pmc_*` functions: `name linux` or `name -` lines.
const FANUC: &str = include_str!("../../../tools/compat/fanuc-functions.txt");

/// (declared by FANUC's header, exported by FANUC's Linux library).
fn fanuc(name: &str) -> (bool, bool) {
    FANUC
        .lines()
        .filter(|l| !l.starts_with('#'))
        .find_map(|l| {
            let mut w = l.split_whitespace();
            (w.next() == Some(name)).then(|| (true, w.next() == Some("linux")))
        })
        .unwrap_or((false, false))
}

fn focas_symbol(s: &str) -> bool {
    s.starts_with("cnc_") || s.starts_with("pmc_") || s.starts_with("fwlib_")
}

/// A FOCAS function's name: one of FANUC's header or one of ours.
fn known(name: &str) -> bool {
    static KNOWN: std::sync::OnceLock<std::collections::HashSet<&'static str>> =
        std::sync::OnceLock::new();
    KNOWN
        .get_or_init(|| {
            let fanuc = FANUC
                .lines()
                .filter(|l| !l.starts_with('#'))
                .filter_map(|l| l.split_whitespace().next());
            fanuc.chain(EXPORTS.iter().map(|e| e.name)).collect()
        })
        .contains(name)
}

/// The language of a source file, by its extension.
fn language(path: &Path) -> Option<&'static str> {
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    Some(match ext.as_str() {
        "c" | "h" => "C",
        "cpp" | "cc" | "cxx" | "hpp" | "hh" | "hxx" => "C++",
        "cs" => "C#",
        "vb" => "Visual Basic",
        "java" => "Java",
        "kt" => "Kotlin",
        "py" | "pyw" => "Python",
        "go" => "Go",
        "rs" => "Rust",
        "js" | "mjs" | "ts" => "JavaScript",
        _ => return None,
    })
}

/// One function the file uses.
struct Used {
    name: String,
    /// Linked (an undefined symbol), else only named (a string, a source).
    linked: bool,
    how: Option<How>,
    fanuc_header: bool,
    fanuc_linux: bool,
}

impl Used {
    fn status(&self) -> &'static str {
        match self.how {
            None => "missing",
            Some(How::NotOnEthernet { .. }) => "not_on_ethernet",
            Some(_) => "supported",
        }
    }

    fn status_text(&self) -> &'static str {
        match self.how {
            None => "MISSING",
            Some(How::NotOnEthernet { ew, .. }) => ew,
            Some(_) => "supported",
        }
    }

    fn how_key(&self) -> Option<&'static str> {
        match self.how? {
            How::Written { .. } => Some("implemented"),
            How::Described => Some("described"),
            How::Extension => Some("extension"),
            How::NotOnEthernet { .. } => None,
        }
    }

    fn notes(&self) -> String {
        match self.how {
            Some(How::Written { .. } | How::Described) => "implemented".into(),
            Some(How::Extension) => "fwlib32-rs extension (fwlib32_ext.h)".into(),
            Some(How::NotOnEthernet { code, ew }) if ew == "EW_VERSION" => {
                format!("answers {ew} ({code}) without a request, as FANUC's Ethernet library does")
            }
            Some(How::NotOnEthernet { code, ew }) => {
                format!("answers {ew} ({code}) without a request: HSSB only")
            }
            None => match (self.fanuc_header, self.fanuc_linux) {
                (true, true) => "not in this library (FANUC's Linux library has it)".into(),
                (true, false) => "not in this library (declared by FANUC's header; not in \
                                   FANUC's Linux library either)"
                    .into(),
                (false, _) => "not in this library (not a function of FANUC's header)".into(),
            },
        }
    }
}

/// What the file is, and the FOCAS functions in it.
struct Found {
    /// "x86-64 program", "32-bit ARM shared library", "Python source".
    what: String,
    machine: Option<String>,
    bits: Option<u8>,
    loadable: bool,
    source: Option<&'static str>,
    used: Vec<Used>,
    /// FOCAS functions it defines itself (a FOCAS library?).
    defines: usize,
}

fn used(name: &str, linked: bool) -> Used {
    let (fanuc_header, fanuc_linux) = fanuc(name);
    Used {
        name: name.to_string(),
        linked,
        how: export(name).map(|e| e.how),
        fanuc_header,
        fanuc_linux,
    }
}

fn find(path: &Path, bytes: &[u8]) -> Result<Found, String> {
    if let Some(lang) = language(path).filter(|_| !bytes.starts_with(b"\x7fELF")) {
        let names = binary::names_in(bytes, known);
        return Ok(Found {
            what: format!("{lang} source"),
            machine: None,
            bits: None,
            loadable: true,
            source: Some(lang),
            used: names.iter().map(|n| used(n, false)).collect(),
            defines: 0,
        });
    }
    let b = binary::read(bytes).map_err(|e| {
        if e == binary::NOT_ELF {
            format!("{e} nor a source file (.c, .cs, .java, .py, .go ...)")
        } else {
            e
        }
    })?;
    let linked: Vec<&String> = b.undefined.iter().filter(|s| focas_symbol(s)).collect();
    // Names in its strings, less those it links or defines.
    let mentioned: Vec<String> = binary::names_in(&b.strings, known)
        .into_iter()
        .filter(|n| b.undefined.binary_search(n).is_err() && b.defined.binary_search(n).is_err())
        .collect();
    let mut all: Vec<Used> = linked.iter().map(|n| used(n, true)).collect();
    all.extend(mentioned.iter().map(|n| used(n, false)));
    Ok(Found {
        what: if b.is_64 {
            format!("{} {}", b.machine, b.kind)
        } else {
            format!("32-bit {} {}", b.machine, b.kind)
        },
        machine: Some(b.machine),
        bits: Some(if b.is_64 { 64 } else { 32 }),
        loadable: b.loadable,
        source: None,
        used: all,
        defines: b.defined.iter().filter(|s| focas_symbol(s)).count(),
    })
}

fn plural(n: usize) -> &'static str {
    if n == 1 { "" } else { "s" }
}

/// Prints the report; returns how many problems it found: the functions
/// missing, and one more when the file cannot load this library at all (a
/// 32-bit program, another architecture).
pub fn run(path: &Path, json: bool) -> Result<usize, Fail> {
    let bytes = std::fs::read(path).map_err(|e| Fail::Other(format!("{}: {e}", path.display())))?;
    let f = find(path, &bytes).map_err(|e| Fail::Other(format!("{}: {e}", path.display())))?;
    let used = &f.used;
    let count = |s: &str| used.iter().filter(|u| u.status() == s).count();
    let (supported, absent, missing) = (
        count("supported"),
        count("not_on_ethernet"),
        count("missing"),
    );
    let problems = missing + usize::from(!f.loadable);
    if json {
        let functions: Vec<_> = used
            .iter()
            .map(|u| {
                let (code, ew) = match u.how {
                    Some(How::NotOnEthernet { code, ew }) => (Some(code), Some(ew)),
                    _ => (None, None),
                };
                json!({
                    "name": u.name,
                    "linked": u.linked,
                    "status": u.status(),
                    "how": u.how_key(),
                    "code": code,
                    "ew": ew,
                    "fanuc_header": u.fanuc_header,
                    "fanuc_linux": u.fanuc_linux,
                })
            })
            .collect();
        json_line(&json!({
            "file": path.display().to_string(),
            "source": f.source,
            "machine": f.machine,
            "bits": f.bits,
            "loadable": f.loadable,
            "functions": functions,
            "supported": supported,
            "not_on_ethernet": absent,
            "missing": missing,
            "defines": f.defines,
        }))?;
        return Ok(problems);
    }
    let (linked, named): (Vec<&Used>, Vec<&Used>) = used.iter().partition(|u| u.linked);
    let what = &f.what;
    let head = match (f.source, named.len()) {
        (Some(_), n) => format!("{n} FOCAS function{} named", plural(n)),
        (None, 0) => format!(
            "{} FOCAS function{} used",
            linked.len(),
            plural(linked.len())
        ),
        (None, n) => format!(
            "{} FOCAS function{} linked, {n} named in its strings",
            linked.len(),
            plural(linked.len())
        ),
    };
    let mut text = format!("{}: {what}, {head}\n", path.display());
    if !f.loadable {
        text.push_str(&format!(
            "note: a {what} cannot load this library, which is built for 64-bit x86-64 and \
             aarch64 Linux: rebuild the program for one of them against this library's \
             fwlib32.h\n"
        ));
    }
    if used.is_empty() && f.defines > 0 {
        text.push_str(&format!(
            "note: it defines {} FOCAS functions itself (a FOCAS library?): check the \
             programs that use it instead\n",
            f.defines
        ));
    }
    let table = |list: &[&Used]| {
        let mut t = Table::new(&[false, false, false]);
        t.row(["function", "status", "notes"]);
        for u in list {
            t.row([u.name.clone(), u.status_text().to_string(), u.notes()]);
        }
        t.render()
    };
    if !linked.is_empty() {
        text.push_str(&table(&linked));
    }
    if !named.is_empty() {
        if f.source.is_none() {
            text.push_str(
                "named in its strings, not linked: a program that loads the library itself \
                 (dlopen) looks these up by name; they are only mentioned, so it may or may \
                 not call them:\n",
            );
        }
        text.push_str(&table(&named));
    }
    text.push_str(&format!(
        "{supported} supported, {absent} not on Ethernet (answered without a request, as by \
         FANUC's Ethernet library), {missing} missing\n"
    ));
    if linked.iter().any(|u| u.how.is_none()) {
        text.push_str(
            "a missing function stops the program when it is called (\"symbol lookup error\"; \
             at start-up if the program was linked with -z now)\n",
        );
    }
    if named.iter().any(|u| u.how.is_none()) {
        text.push_str(match f.source {
            Some(_) => "a missing function fails where the program looks it up or calls it\n",
            None => {
                "a missing function named in its strings: looking it up (dlsym) finds \
                     nothing, and the program goes on as it is written to\n"
            }
        });
    }
    print(&text)?;
    Ok(problems)
}
