//! Calling the exported C functions as the headers declare them, without
//! naming any: the prototypes of include/fwlib32.h and fwlib32_ext.h
//! parsed, each function looked up in the built library (dlopen) and
//! called with integer-class arguments (the C calling conventions pass
//! integers and pointers alike; the parser refuses floating-point ones).
//! Shared by tests/bad_input.rs and tests/robust/hostile.rs; the test crate
//! declares `mod toolchain;`.

#![allow(dead_code)]

use std::ffi::CString;
use std::time::{Duration, Instant};

/// One argument of a prototype.
#[derive(Debug, Clone)]
pub struct Param {
    pub name: String,
    /// The C type without the name, e.g. "unsigned short", "short *".
    pub ty: String,
    pub ptr: bool,
}

#[derive(Debug, Clone)]
pub struct Proto {
    pub name: String,
    pub params: Vec<Param>,
    /// The comment before the prototype.
    pub doc: String,
}

impl Proto {
    /// The header says `param` may be NULL.
    pub fn null_ok(&self, param: &str) -> bool {
        self.doc.contains(&format!("`{param}` must be NULL or"))
    }
}

/// The prototypes of a header: `short name(type a, type *b);`, possibly over
/// several lines.
pub fn prototypes(text: &str) -> Vec<Proto> {
    let mut out = Vec::new();
    let mut lines = text.lines();
    let mut doc = String::new();
    while let Some(l) = lines.next() {
        if l.starts_with("/*") {
            doc.clear();
        }
        doc.push_str(l);
        doc.push('\n');
        if l.starts_with(' ') || l.starts_with('#') || l.starts_with('/') || !l.contains('(') {
            continue;
        }
        let (head, _) = l.split_once('(').unwrap();
        let Some(name) = head.split_whitespace().last() else {
            continue;
        };
        if !(name.starts_with("cnc_") || name.starts_with("pmc_") || name.starts_with("fwlib_")) {
            continue;
        }
        let mut decl = l.to_string();
        while !decl.contains(");") {
            decl.push(' ');
            decl.push_str(lines.next().expect("prototype ends").trim());
        }
        let inner = decl.split_once('(').unwrap().1.rsplit_once(')').unwrap().0;
        let params = inner
            .split(',')
            .map(str::trim)
            .filter(|p| !p.is_empty() && *p != "void")
            .map(|p| {
                assert!(
                    !p.contains("float") && !p.contains("double") || p.contains('*'),
                    "{name}: a floating-point argument ({p}) needs its own calling convention"
                );
                let ptr = p.contains('*');
                let split = p.rfind([' ', '*']).unwrap();
                Param {
                    name: p[split + 1..].to_string(),
                    ty: p[..=split].trim().to_string(),
                    ptr,
                }
            })
            .collect();
        out.push(Proto {
            name: name.to_string(),
            params,
            doc: std::mem::take(&mut doc),
        });
    }
    out
}

/// Up to 8 integer-class arguments: a function taking fewer ignores the
/// rest (the caller owns them in every C calling convention).
pub type Fn8 = unsafe extern "C" fn(i64, i64, i64, i64, i64, i64, i64, i64) -> i16;

pub struct Lib {
    handle: *mut libc::c_void,
}

impl Lib {
    pub fn open() -> Lib {
        let path = CString::new(crate::toolchain::cdylib().to_str().unwrap()).unwrap();
        let handle = unsafe { libc::dlopen(path.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL) };
        assert!(!handle.is_null(), "dlopen {:?}", path);
        Lib { handle }
    }
    pub fn get(&self, name: &str) -> Fn8 {
        let c = CString::new(name).unwrap();
        let p = unsafe { libc::dlsym(self.handle, c.as_ptr()) };
        assert!(!p.is_null(), "{name} is declared but not exported");
        unsafe { std::mem::transmute::<*mut libc::c_void, Fn8>(p) }
    }
}

/// The memory behind a pointer argument: room for the largest count a
/// `short` can say of the largest record (mapped lazily: only the pages
/// the library touches cost anything), then a guard.
pub const ROOM: usize = 16 << 20;
pub const GUARD: usize = 4096;
pub const FILL: u8 = 0xA5;

/// A pointer argument's memory: ROOM bytes (zeros, or a count in the first
/// bytes) and a guard after them.
pub struct Buf(pub *mut u8);

impl Buf {
    pub fn new(count: Option<i64>) -> Buf {
        let p = unsafe {
            libc::mmap(
                std::ptr::null_mut(),
                ROOM + GUARD,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS | libc::MAP_NORESERVE,
                -1,
                0,
            )
        };
        assert_ne!(p, libc::MAP_FAILED);
        let p = p.cast::<u8>();
        unsafe { std::ptr::write_bytes(p.add(ROOM), FILL, GUARD) };
        if let Some(c) = count {
            // The same number read as a short, a long or a 64-bit long
            // (little-endian: the low bytes first).
            unsafe { std::ptr::copy_nonoverlapping(c.to_le_bytes().as_ptr(), p, 8) };
        }
        Buf(p)
    }
    pub fn intact(&self) -> bool {
        let guard = unsafe { std::slice::from_raw_parts(self.0.add(ROOM), GUARD) };
        guard.iter().all(|b| *b == FILL)
    }
}

impl Drop for Buf {
    fn drop(&mut self) {
        unsafe { libc::munmap(self.0.cast(), ROOM + GUARD) };
    }
}

pub fn all_prototypes() -> Vec<Proto> {
    let mut protos = prototypes(&crate::toolchain::header_text());
    let ext = std::fs::read_to_string(crate::toolchain::ext_header_path()).unwrap();
    protos.extend(prototypes(&ext));
    protos
}

/// What goes in one argument.
pub enum Arg {
    Int(i64),
    /// A buffer (see [`Buf`]), or NULL.
    Ptr(Option<Buf>),
}

impl Lib {
    /// Calls `p` with `args` (one per parameter): its code, whether every
    /// buffer's guard is intact, and how long it took.
    pub fn invoke(&self, p: &Proto, args: Vec<Arg>) -> (i16, bool, Duration) {
        assert_eq!(args.len(), p.params.len(), "{}", p.name);
        let f = self.get(&p.name);
        let mut words = [0i64; 8];
        for (w, a) in words.iter_mut().zip(&args) {
            *w = match a {
                Arg::Int(v) => *v,
                Arg::Ptr(b) => b.as_ref().map_or(0, |b| b.0 as i64),
            };
        }
        let t = Instant::now();
        let rc = unsafe {
            f(
                words[0], words[1], words[2], words[3], words[4], words[5], words[6], words[7],
            )
        };
        let took = t.elapsed();
        let intact = args.iter().all(|a| match a {
            Arg::Ptr(Some(b)) => b.intact(),
            _ => true,
        });
        (rc, intact, took)
    }

    /// `cnc_allclibhndl3` to 127.0.0.1:`port` through this library.
    pub fn alloc(&self, port: u16, timeout: i64) -> Result<u16, i16> {
        let ip = CString::new("127.0.0.1").unwrap();
        let mut h: u16 = 0;
        let rc = unsafe {
            self.get("cnc_allclibhndl3")(
                ip.as_ptr() as i64,
                i64::from(port),
                timeout,
                &mut h as *mut u16 as i64,
                0,
                0,
                0,
                0,
            )
        };
        if rc == 0 { Ok(h) } else { Err(rc) }
    }

    pub fn free(&self, h: u16) -> i16 {
        unsafe { self.get("cnc_freelibhndl")(i64::from(h), 0, 0, 0, 0, 0, 0, 0) }
    }
}

/// The library handle argument.
pub fn is_handle(p: &Param) -> bool {
    p.name == "FlibHndl"
}

/// A function answering one code on every call, sending and writing
/// nothing: one FANUC's header declares and none of its Ethernet libraries
/// has (src/spec/table/absent/: EW_VERSION; tests/bad_input.rs and
/// tests/ffi/absent.rs check it), or a described one with an `answers`
/// check (pmc_rdmsg: EW_FUNC, as FANUC's Linux library). It never reaches
/// the CNC, so the sweeps of the CNC's answers leave it out.
pub fn fixed_answer(name: &str) -> bool {
    let absent = fwlib32::spec::table::absent::ROWS.iter().copied().flatten();
    absent.clone().any(|(n, _)| *n == name)
        || (fwlib32::spec::FUNCS.iter()).any(|f| f.name == name && f.answers().is_some())
}

/// Functions that end or change the handle's session (free it, drop its
/// connections, start an upload, change its path or timeout) are left to
/// their own tests; every other function taking a handle is swept.
pub const SESSION: &[&str] = &[
    "cnc_freelibhndl",
    "cnc_resetconnect",
    "cnc_upstart",
    "cnc_upstart3",
    "cnc_upstart4",
    "cnc_setpath",
    "cnc_settimeout",
    "fwlib_set_reconnect",
    // A batch queues the handle's calls; a transfer holds connection 1;
    // deleting every program leaves the program functions nothing.
    "fwlib_batch_begin",
    "fwlib_batch_end",
    "fwlib_batch_limits",
    "cnc_dwnstart",
    "cnc_dwnstart3",
    "cnc_dwnstart4",
    "cnc_dncstart",
    "cnc_dncstart2",
    "cnc_delall",
    "cnc_pdf_delall",
    // Transfer data and ends: nothing to do without a start.
    "cnc_download",
    "cnc_download3",
    "cnc_download4",
    "cnc_dwnend",
    "cnc_dwnend3",
    "cnc_dwnend4",
    "cnc_dnc",
    "cnc_dnc2",
    "cnc_dncend",
    "cnc_dncend2",
    "cnc_upload",
    "cnc_upload3",
    "cnc_upload4",
    "cnc_cupload",
    "cnc_upend",
    "cnc_upend3",
    "cnc_upend4",
];
