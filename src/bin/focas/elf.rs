//! Just enough of ELF to list a program's or library's symbols: the header,
//! the section headers and the symbol tables (`.dynsym`, `.symtab`), for
//! 32- and 64-bit files of either byte order. Every offset is checked
//! against the file: a truncated or malformed file is an error, never a panic.

/// What `focas compat` needs of an ELF file.
pub struct Elf {
    /// ELFCLASS64.
    pub is_64: bool,
    /// `e_machine`.
    pub machine: u16,
    /// `e_type`: 1 relocatable, 2 executable, 3 shared object or PIE.
    pub kind: u16,
    /// It names a program interpreter (PT_INTERP): a program, not a library.
    pub interp: bool,
    /// Names of the undefined symbols (the functions and data it uses from
    /// elsewhere), sorted, without duplicates or version suffixes.
    pub undefined: Vec<String>,
    /// Names of the symbols it defines, sorted, without duplicates.
    pub defined: Vec<String>,
}

const SHT_SYMTAB: u32 = 2;
const SHT_DYNSYM: u32 = 11;
const SHN_UNDEF: u16 = 0;

struct Reader<'a> {
    b: &'a [u8],
    le: bool,
}

impl Reader<'_> {
    fn bytes(&self, at: u64, n: u64) -> Result<&[u8], String> {
        let end = at
            .checked_add(n)
            .filter(|e| *e <= self.b.len() as u64)
            .ok_or_else(|| {
                format!(
                    "truncated: needs bytes {at}..{} of {}",
                    at + n,
                    self.b.len()
                )
            })?;
        Ok(&self.b[at as usize..end as usize])
    }
    fn u16(&self, at: u64) -> Result<u16, String> {
        let b: [u8; 2] = self.bytes(at, 2)?.try_into().unwrap();
        Ok(if self.le {
            u16::from_le_bytes(b)
        } else {
            u16::from_be_bytes(b)
        })
    }
    fn u32(&self, at: u64) -> Result<u32, String> {
        let b: [u8; 4] = self.bytes(at, 4)?.try_into().unwrap();
        Ok(if self.le {
            u32::from_le_bytes(b)
        } else {
            u32::from_be_bytes(b)
        })
    }
    fn u64(&self, at: u64) -> Result<u64, String> {
        let b: [u8; 8] = self.bytes(at, 8)?.try_into().unwrap();
        Ok(if self.le {
            u64::from_le_bytes(b)
        } else {
            u64::from_be_bytes(b)
        })
    }
    /// The NUL-terminated string at `at` (within `limit`).
    fn cstr(&self, at: u64, limit: u64) -> Result<String, String> {
        let limit = limit.min(self.b.len() as u64);
        if at >= limit {
            return Err(format!("string offset {at} outside its table"));
        }
        let s = &self.b[at as usize..limit as usize];
        let end = s.iter().position(|c| *c == 0).unwrap_or(s.len());
        Ok(String::from_utf8_lossy(&s[..end]).into_owned())
    }
}

/// One section header's fields we use.
struct Section {
    kind: u32,
    offset: u64,
    size: u64,
    link: u32,
    entsize: u64,
}

/// Reads an ELF file's class, machine, type and symbols.
pub fn read(b: &[u8]) -> Result<Elf, String> {
    if b.len() < 16 || &b[..4] != b"\x7fELF" {
        return Err("not an ELF file (a program or shared library built for Linux)".into());
    }
    let is_64 = match b[4] {
        1 => false,
        2 => true,
        c => return Err(format!("unknown ELF class {c}")),
    };
    let le = match b[5] {
        1 => true,
        2 => false,
        d => return Err(format!("unknown ELF byte order {d}")),
    };
    let r = Reader { b, le };
    let kind = r.u16(16)?;
    let machine = r.u16(18)?;
    // e_phoff, e_phentsize, e_phnum: is there a PT_INTERP (3)?
    let (phoff, at) = if is_64 {
        (r.u64(0x20)?, 0x36)
    } else {
        (u64::from(r.u32(0x1C)?), 0x2A)
    };
    let (phentsize, phnum) = (u64::from(r.u16(at)?), u64::from(r.u16(at + 2)?));
    let mut interp = false;
    if phoff != 0 && phentsize >= 4 {
        for i in 0..phnum {
            let h = phoff
                .checked_add(i * phentsize)
                .ok_or("program headers past the end")?;
            interp |= r.u32(h)? == 3;
        }
    }
    // e_shoff, e_shentsize, e_shnum, e_shstrndx.
    let (shoff, at) = if is_64 {
        (r.u64(0x28)?, 0x3A)
    } else {
        (u64::from(r.u32(0x20)?), 0x2E)
    };
    let shentsize = u64::from(r.u16(at)?);
    let mut shnum = u64::from(r.u16(at + 2)?);
    if shoff == 0 {
        return Err("no section headers (stripped of them): its symbols cannot be read".into());
    }
    let min_entsize = if is_64 { 64 } else { 40 };
    if shentsize < min_entsize {
        return Err(format!("section header size {shentsize} too small"));
    }
    let section = |i: u64| -> Result<Section, String> {
        let h = shoff
            .checked_add(i * shentsize)
            .ok_or("section headers past the end")?;
        r.bytes(h, shentsize)?;
        Ok(if is_64 {
            Section {
                kind: r.u32(h + 4)?,
                offset: r.u64(h + 24)?,
                size: r.u64(h + 32)?,
                link: r.u32(h + 40)?,
                entsize: r.u64(h + 56)?,
            }
        } else {
            Section {
                kind: r.u32(h + 4)?,
                offset: r.u32(h + 16)?.into(),
                size: r.u32(h + 20)?.into(),
                link: r.u32(h + 24)?,
                entsize: r.u32(h + 36)?.into(),
            }
        })
    };
    if shnum == 0 {
        // More sections than e_shnum holds: the count is section 0's size.
        shnum = section(0)?.size;
    }
    if shnum > b.len() as u64 / shentsize {
        return Err(format!("{shnum} section headers do not fit in the file"));
    }
    let sym_size = if is_64 { 24 } else { 16 };
    let (mut undefined, mut defined) = (Vec::new(), Vec::new());
    for i in 0..shnum {
        let s = section(i)?;
        if s.kind != SHT_SYMTAB && s.kind != SHT_DYNSYM {
            continue;
        }
        if s.entsize != 0 && s.entsize < sym_size {
            return Err(format!("symbol size {} too small", s.entsize));
        }
        let entsize = if s.entsize == 0 { sym_size } else { s.entsize };
        let strtab = section(u64::from(s.link))?;
        r.bytes(s.offset, s.size)?;
        r.bytes(strtab.offset, strtab.size)?;
        // Entry 0 is the null symbol.
        for k in 1..s.size / entsize {
            let e = s.offset + k * entsize;
            let name_at = u64::from(r.u32(e)?);
            let shndx = if is_64 { r.u16(e + 6)? } else { r.u16(e + 14)? };
            if name_at == 0 {
                continue;
            }
            let name = r.cstr(strtab.offset + name_at, strtab.offset + strtab.size)?;
            let name = name.split('@').next().unwrap_or("").to_string();
            if shndx == SHN_UNDEF {
                undefined.push(name);
            } else {
                defined.push(name);
            }
        }
    }
    for v in [&mut undefined, &mut defined] {
        v.sort();
        v.dedup();
    }
    Ok(Elf {
        is_64,
        machine,
        kind,
        interp,
        undefined,
        defined,
    })
}

/// `e_machine` as people name it.
pub fn machine_name(m: u16) -> String {
    match m {
        3 => "x86".into(),
        8 => "MIPS".into(),
        20 => "PowerPC".into(),
        21 => "PowerPC 64".into(),
        40 => "ARM".into(),
        62 => "x86-64".into(),
        183 => "aarch64".into(),
        243 => "RISC-V".into(),
        m => format!("machine {m}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn not_elf_or_truncated_is_an_error() {
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
        let elf = read(&std::fs::read(exe).unwrap()).unwrap();
        assert_eq!(elf.is_64, cfg!(target_pointer_width = "64"));
        assert!(elf.interp);
        // It calls into libc, and defines its own main.
        assert!(elf.undefined.iter().any(|s| s == "malloc" || s == "free"));
        assert!(elf.defined.iter().any(|s| s == "main"));
    }
}
