//! What `focas compat` needs of a program or library (ELF, read by the
//! `object` crate): its class and machine, the symbols it takes from other
//! libraries and those it defines, and the FOCAS names in its read-only
//! data (a program that loads the library with `dlopen` names its
//! functions there, as strings for `dlsym`). A truncated or malformed file
//! is an error, never a panic.

use object::elf;
use object::read::elf::{ElfFile, FileHeader, ProgramHeader};
use object::{Endianness, FileKind, Object, ObjectSection, ObjectSymbol, SectionKind};
use std::collections::BTreeSet;

/// What `focas compat` needs of an ELF file.
pub struct Binary {
    pub is_64: bool,
    /// As people name it: "x86-64", "aarch64" ...
    pub machine: String,
    /// Built for a machine this library is built for (64-bit x86-64, aarch64).
    pub loadable: bool,
    /// "program", "shared library", "object file".
    pub kind: &'static str,
    /// The symbols it uses from elsewhere (linked), sorted, without
    /// duplicates or version suffixes.
    pub undefined: Vec<String>,
    /// The symbols it defines, sorted, without duplicates.
    pub defined: Vec<String>,
    /// Its read-only data, where the strings of a program are.
    pub strings: Vec<u8>,
}

pub const NOT_ELF: &str = "not an ELF file (a program or shared library built for Linux)";

/// Reads an ELF file's class, machine, type, symbols and strings.
pub fn read(b: &[u8]) -> Result<Binary, String> {
    if b.len() < 4 || &b[..4] != b"\x7fELF" {
        return Err(NOT_ELF.into());
    }
    let bad = |e: object::Error| format!("a damaged ELF file: {e}");
    match FileKind::parse(b).map_err(bad)? {
        FileKind::Elf32 => of(&ElfFile::<elf::FileHeader32<Endianness>>::parse(b).map_err(bad)?),
        FileKind::Elf64 => of(&ElfFile::<elf::FileHeader64<Endianness>>::parse(b).map_err(bad)?),
        _ => Err(NOT_ELF.into()),
    }
}

fn of<H: FileHeader<Endian = Endianness>>(f: &ElfFile<'_, H>) -> Result<Binary, String> {
    let e = f.endian();
    let h = f.elf_header();
    if f.elf_section_table().is_empty() {
        return Err("no section headers (stripped of them): its symbols cannot be read".into());
    }
    let machine = h.e_machine(e);
    let interp = f
        .elf_program_headers()
        .iter()
        .any(|p| p.p_type(e) == elf::PT_INTERP);
    let kind = match (h.e_type(e), interp) {
        (elf::ET_REL, _) => "object file",
        (elf::ET_EXEC, _) | (elf::ET_DYN, true) => "program",
        (elf::ET_DYN, false) => "shared library",
        _ => "ELF file",
    };
    let (mut undefined, mut defined) = (Vec::new(), Vec::new());
    for s in f.symbols().chain(f.dynamic_symbols()) {
        let name = s
            .name()
            .map_err(|e| format!("a damaged symbol table: {e}"))?;
        let name = name.split('@').next().unwrap_or("");
        if name.is_empty() {
            continue;
        }
        if s.is_undefined() {
            undefined.push(name.to_string());
        } else {
            defined.push(name.to_string());
        }
    }
    for v in [&mut undefined, &mut defined] {
        v.sort();
        v.dedup();
    }
    let mut strings = Vec::new();
    for s in f.sections() {
        let data = matches!(
            s.kind(),
            SectionKind::ReadOnlyData
                | SectionKind::ReadOnlyString
                | SectionKind::ReadOnlyDataWithRel
                | SectionKind::Data
        );
        if data {
            strings.extend_from_slice(s.data().map_err(|e| format!("a damaged section: {e}"))?);
            strings.push(0);
        }
    }
    let is_64 = f.is_64();
    Ok(Binary {
        is_64,
        machine: machine_name(machine),
        // This library is built for x86-64 and aarch64 (64-bit Linux).
        loadable: is_64 && matches!(machine, elf::EM_X86_64 | elf::EM_AARCH64),
        kind,
        undefined,
        defined,
        strings,
    })
}

/// `e_machine` as people name it.
fn machine_name(m: u16) -> String {
    match m {
        elf::EM_386 => "x86".into(),
        elf::EM_MIPS => "MIPS".into(),
        elf::EM_PPC => "PowerPC".into(),
        elf::EM_PPC64 => "PowerPC 64".into(),
        elf::EM_ARM => "ARM".into(),
        elf::EM_X86_64 => "x86-64".into(),
        elf::EM_AARCH64 => "aarch64".into(),
        elf::EM_RISCV => "RISC-V".into(),
        m => format!("machine {m}"),
    }
}

/// The names `known` accepts in `text` (a source file, or a program's
/// strings): in each run of letters, digits and `_`, at each `cnc_`,
/// `pmc_` or `fwlib_`, the longest known name that starts there (Go lays
/// its strings end to end: `cnc_statinfocnc_rdparam` is two).
pub fn names_in(text: &[u8], known: impl Fn(&str) -> bool) -> BTreeSet<String> {
    const LONGEST: usize = 48;
    let word = |c: &u8| c.is_ascii_alphanumeric() || *c == b'_';
    let mut out = BTreeSet::new();
    for run in text.split(|c| !word(c)) {
        for at in 0..run.len() {
            let rest = &run[at..];
            if !(rest.starts_with(b"cnc_")
                || rest.starts_with(b"pmc_")
                || rest.starts_with(b"fwlib_"))
            {
                continue;
            }
            let rest = &rest[..rest.len().min(LONGEST)];
            // ASCII: every prefix is a str.
            let rest = std::str::from_utf8(rest).unwrap_or_default();
            if let Some(n) = (4..=rest.len())
                .rev()
                .map(|n| &rest[..n])
                .find(|n| known(n))
            {
                out.insert(n.to_string());
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn not_elf_or_damaged_is_an_error() {
        assert!(read(b"#!/bin/sh\necho hi\n").is_err());
        assert!(read(b"").is_err());
        // A 64-bit little-endian header cut short.
        let mut h = b"\x7fELF\x02\x01\x01".to_vec();
        h.resize(20, 0);
        assert!(read(&h).is_err());
        // Section headers pointing past the end.
        let mut h = b"\x7fELF\x02\x01\x01".to_vec();
        h.resize(64, 0);
        h[0x28..0x30].copy_from_slice(&1000u64.to_le_bytes());
        h[0x3A..0x3C].copy_from_slice(&64u16.to_le_bytes());
        h[0x3C..0x3E].copy_from_slice(&3u16.to_le_bytes());
        assert!(read(&h).is_err());
    }

    #[test]
    fn reads_this_test_binary() {
        let exe = std::env::current_exe().unwrap();
        let b = read(&std::fs::read(exe).unwrap()).unwrap();
        assert_eq!(b.is_64, cfg!(target_pointer_width = "64"));
        assert_eq!(b.kind, "program");
        // It calls into libc, and defines its own main.
        assert!(b.undefined.iter().any(|s| s == "malloc" || s == "free"));
        assert!(b.defined.iter().any(|s| s == "main"));
        // Its strings hold this test's.
        let n = names_in(&b.strings, |n| n == "cnc_looked_for_by_this_test");
        assert!(n.contains("cnc_looked_for_by_this_test"), "{n:?}");
    }

    #[test]
    fn names_in_text() {
        let known = |n: &str| ["cnc_statinfo", "cnc_rdparam", "cnc_rdparam3"].contains(&n);
        let n = names_in(
            b"x = lib.cnc_statinfo(h)\n\"cnc_rdparam3cnc_statinfo\" my_cnc_rdparamx cnc_nothing",
            known,
        );
        assert_eq!(
            n.into_iter().collect::<Vec<_>>(),
            ["cnc_rdparam", "cnc_rdparam3", "cnc_statinfo"]
        );
    }
}
