//! `focas compat FILE`: will a program (or a library) built for FANUC's
//! FOCAS library work with this one? Its undefined `cnc_*`, `pmc_*` and
//! `fwlib_*` symbols, each looked up in the table of this library's exports
//! (`fwlib32::ffi::exports`, written by build.rs from the same sources as
//! the exports, and read by COMPATIBILITY.md too) and in the list of FANUC's
//! functions (tools/compat/fanuc-functions.txt).

use crate::elf;
use crate::out::{Fail, Table, json_line, print};
use fwlib32::ffi::exports::{How, export};
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

/// One function the file uses.
struct Used {
    name: String,
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
            Some(How::Written { .. }) => "implemented".into(),
            Some(How::Described) => "implemented (described as data)".into(),
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

/// Prints the report; returns how many problems it found: the functions
/// missing, and one more when the file cannot load this library at all (a
/// 32-bit program, another architecture).
pub fn run(path: &Path, json: bool) -> Result<usize, Fail> {
    let bytes = std::fs::read(path).map_err(|e| Fail::Other(format!("{}: {e}", path.display())))?;
    let elf = elf::read(&bytes).map_err(|e| Fail::Other(format!("{}: {e}", path.display())))?;
    let used: Vec<Used> = elf
        .undefined
        .iter()
        .filter(|s| focas_symbol(s))
        .map(|name| {
            let (fanuc_header, fanuc_linux) = fanuc(name);
            Used {
                name: name.clone(),
                how: export(name).map(|e| e.how),
                fanuc_header,
                fanuc_linux,
            }
        })
        .collect();
    let count = |s: &str| used.iter().filter(|u| u.status() == s).count();
    let (supported, absent, missing) = (
        count("supported"),
        count("not_on_ethernet"),
        count("missing"),
    );
    let defines = elf.defined.iter().filter(|s| focas_symbol(s)).count();
    let machine = elf::machine_name(elf.machine);
    let bits = if elf.is_64 { 64 } else { 32 };
    // This library is built for x86-64 and aarch64 (64-bit Linux).
    let loadable = elf.is_64 && matches!(elf.machine, 62 | 183);
    let kind = match (elf.kind, elf.interp) {
        (1, _) => "object file",
        (2, _) | (3, true) => "program",
        (3, false) => "shared library",
        _ => "ELF file",
    };
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
            "machine": machine,
            "bits": bits,
            "loadable": loadable,
            "functions": functions,
            "supported": supported,
            "not_on_ethernet": absent,
            "missing": missing,
            "defines": defines,
        }))?;
        return Ok(missing + usize::from(!loadable));
    }
    let what = if elf.is_64 {
        format!("{machine} {kind}")
    } else {
        format!("32-bit {machine} {kind}")
    };
    let mut text = format!(
        "{}: {what}, {} FOCAS function{} used\n",
        path.display(),
        used.len(),
        if used.len() == 1 { "" } else { "s" }
    );
    if !loadable {
        text.push_str(&format!(
            "note: a {what} cannot load this library, which is built for 64-bit x86-64 and \
             aarch64 Linux: rebuild the program for one of them against this library's \
             fwlib32.h\n"
        ));
    }
    if used.is_empty() && defines > 0 {
        text.push_str(&format!(
            "note: it defines {defines} FOCAS functions itself (a FOCAS library?): check the \
             programs that use it instead\n"
        ));
    }
    if !used.is_empty() {
        let mut t = Table::new(&[false, false, false]);
        t.row(["function", "status", "notes"]);
        for u in &used {
            t.row([u.name.clone(), u.status_text().to_string(), u.notes()]);
        }
        text.push_str(&t.render());
    }
    text.push_str(&format!(
        "{supported} supported, {absent} not on Ethernet (answered without a request, as by \
         FANUC's Ethernet library), {missing} missing\n"
    ));
    if missing > 0 {
        text.push_str(
            "a missing function stops the program when it is called (\"symbol lookup error\"; \
             at start-up if the program was linked with -z now)\n",
        );
    }
    print(&text)?;
    Ok(missing + usize::from(!loadable))
}
