//! The bad-C-input matrix over every exported function, generated from the
//! headers (include/fwlib32.h, include/fwlib32_ext.h): nothing here names a
//! function, so a new export is covered as soon as it is declared. Each
//! function is looked up in the built library (dlopen) and called with:
//!
//! * NULL for each pointer argument in turn (the others pointing to large
//!   zeroed buffers);
//! * handle 0, a freed handle and a never-issued handle;
//! * negative and huge values for each integer argument, and behind each
//!   pointer argument (`short *num`, `long *length` ...).
//!
//! Every call must come back within the handle's timeout with a known
//! EW_* code, never EW_UNEXP (a panic caught at the C boundary), and write
//! nothing past the buffers. A handle, a NULL or a count the library can
//! check locally gets its code; the handle checks are exact (EW_HANDLE).
//!
//! The calls go to a simulator; every argument is passed in an integer
//! register or stack slot, as the C calling convention passes integers and
//! pointers (the headers have no floating-point or struct arguments: the
//! parser refuses them).

mod sim;
mod toolchain;

use fwlib32::ew::*;
use fwlib32::ffi::exports::{How, export};
use fwlib32::sim::Profile;
use std::collections::BTreeMap;
use std::ffi::CString;
use std::time::{Duration, Instant};

/// One argument of a prototype.
#[derive(Debug, Clone)]
struct Param {
    name: String,
    /// The C type without the name, e.g. "unsigned short", "short *".
    ty: String,
    ptr: bool,
}

#[derive(Debug, Clone)]
struct Proto {
    name: String,
    params: Vec<Param>,
    /// The comment before the prototype.
    doc: String,
}

impl Proto {
    /// The header says `param` may be NULL.
    fn null_ok(&self, param: &str) -> bool {
        self.doc.contains(&format!("`{param}` must be NULL or"))
    }
}

/// The prototypes of a header: `short name(type a, type *b);`, possibly over
/// several lines.
fn prototypes(text: &str) -> Vec<Proto> {
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
type Fn8 = unsafe extern "C" fn(i64, i64, i64, i64, i64, i64, i64, i64) -> i16;

struct Lib {
    handle: *mut libc::c_void,
}

impl Lib {
    fn open() -> Lib {
        let path = CString::new(toolchain::cdylib().to_str().unwrap()).unwrap();
        let handle = unsafe { libc::dlopen(path.as_ptr(), libc::RTLD_NOW | libc::RTLD_LOCAL) };
        assert!(!handle.is_null(), "dlopen {:?}", path);
        Lib { handle }
    }
    fn get(&self, name: &str) -> Fn8 {
        let c = CString::new(name).unwrap();
        let p = unsafe { libc::dlsym(self.handle, c.as_ptr()) };
        assert!(!p.is_null(), "{name} is declared but not exported");
        unsafe { std::mem::transmute::<*mut libc::c_void, Fn8>(p) }
    }
}

/// The memory behind a pointer argument: room for the largest count a
/// `short` can say of the largest record (mapped lazily: only the pages
/// the library touches cost anything), then a guard.
const ROOM: usize = 16 << 20;
const GUARD: usize = 4096;
const FILL: u8 = 0xA5;

/// A pointer argument's memory: ROOM bytes (zeros, or a count in the first
/// bytes) and a guard after them.
struct Buf(*mut u8);

impl Buf {
    fn new(count: Option<i64>) -> Buf {
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
    fn intact(&self) -> bool {
        let guard = unsafe { std::slice::from_raw_parts(self.0.add(ROOM), GUARD) };
        guard.iter().all(|b| *b == FILL)
    }
}

impl Drop for Buf {
    fn drop(&mut self) {
        unsafe { libc::munmap(self.0.cast(), ROOM + GUARD) };
    }
}

/// What a call gets in place of one argument.
#[derive(Debug, Clone, Copy)]
enum Bad {
    Null(usize),
    Handle(i64, &'static str),
    Int(usize, i64),
    Behind(usize, i64),
}

const HANDLE_TIMEOUT: i64 = 2;
const BOUND: Duration = Duration::from_secs(HANDLE_TIMEOUT as u64 + 8);

fn is_handle(p: &Param) -> bool {
    p.name == "FlibHndl"
}

/// The values an integer argument of type `ty` is tried with.
fn bad_ints(ty: &str) -> &'static [i64] {
    match ty {
        "unsigned short" => &[0xffff, 0x8000],
        "short" | "signed short" => &[-1, -32768, 32767],
        "char" | "unsigned char" => &[-1, 0x7f],
        _ => &[-1, i32::MIN as i64, i32::MAX as i64, i64::MAX],
    }
}

/// Known result codes: the EW_* codes of fwlib32.h.
fn known(rc: i16) -> bool {
    (-17..=18).contains(&rc) && rc != EW_UNEXP
}

struct Bench {
    lib: Lib,
    sim: fwlib32::sim::Simulator,
    h: u16,
}

impl Bench {
    fn alloc(lib: &Lib, port: u16) -> u16 {
        let ip = CString::new("127.0.0.1").unwrap();
        let mut h: u16 = 0;
        let rc = unsafe {
            lib.get("cnc_allclibhndl3")(
                ip.as_ptr() as i64,
                i64::from(port),
                HANDLE_TIMEOUT,
                &mut h as *mut u16 as i64,
                0,
                0,
                0,
                0,
            )
        };
        assert_eq!(rc, EW_OK, "cnc_allclibhndl3");
        h
    }

    fn free(&self, h: u16) -> i16 {
        unsafe { self.lib.get("cnc_freelibhndl")(i64::from(h), 0, 0, 0, 0, 0, 0, 0) }
    }

    /// A fresh handle for the next call: the last may have freed this one,
    /// broken its connection or left an upload running.
    fn renew(&mut self) {
        let _ = self.free(self.h);
        self.h = Bench::alloc(&self.lib, self.sim.port());
    }

    /// Calls `p` with `bad` in place of one argument: the result code and
    /// whether every buffer is intact.
    fn call(&mut self, p: &Proto, bad: Bad) -> (i16, bool) {
        let f = self.lib.get(&p.name);
        let mut bufs: Vec<Option<Buf>> = Vec::new();
        let mut args = [0i64; 8];
        for (i, a) in p.params.iter().enumerate() {
            let v = if a.ptr {
                let b = match bad {
                    Bad::Null(k) if k == i => None,
                    Bad::Behind(k, v) if k == i => Some(Buf::new(Some(v))),
                    _ => Some(Buf::new(None)),
                };
                let v = b.as_ref().map_or(0, |b| b.0 as i64);
                bufs.push(b);
                v
            } else if is_handle(a) {
                match bad {
                    Bad::Handle(h, _) => h,
                    _ => i64::from(self.h),
                }
            } else {
                match bad {
                    Bad::Int(k, v) if k == i => v,
                    // A plausible small number elsewhere (1: a count, a
                    // number, a type), the port for a port.
                    _ if a.name.contains("port") => i64::from(self.sim.port()),
                    _ if a.name.contains("timeout") => HANDLE_TIMEOUT,
                    _ => 1,
                }
            };
            args[i] = v;
        }
        if std::env::var_os("BAD_INPUT_TRACE").is_some() {
            eprintln!("{} {bad:?}", p.name);
        }
        let t = Instant::now();
        let rc = unsafe {
            f(
                args[0], args[1], args[2], args[3], args[4], args[5], args[6], args[7],
            )
        };
        assert!(
            t.elapsed() < BOUND,
            "{} {bad:?} took {:?}",
            p.name,
            t.elapsed()
        );
        let intact = bufs.iter().flatten().all(Buf::intact);
        (rc, intact)
    }
}

fn all_prototypes() -> Vec<Proto> {
    let mut protos = prototypes(&toolchain::header_text());
    let ext = std::fs::read_to_string(toolchain::ext_header_path()).unwrap();
    protos.extend(prototypes(&ext));
    protos
}

#[test]
fn the_parser_reads_every_declared_function() {
    let protos = all_prototypes();
    let names: std::collections::BTreeSet<_> = protos.iter().map(|p| p.name.clone()).collect();
    let declared = toolchain::header_functions(&toolchain::header_text());
    assert!(
        declared.is_subset(&names),
        "{:?}",
        declared.difference(&names)
    );
    for p in &protos {
        assert!(p.params.len() <= 8, "{}: more than 8 arguments", p.name);
        assert!(
            export(&p.name).is_some(),
            "{} is declared, not exported",
            p.name
        );
    }
    // Every export is declared, so the matrix covers every export.
    for e in fwlib32::ffi::exports::EXPORTS {
        assert!(
            names.contains(e.name),
            "{} is exported, not declared",
            e.name
        );
    }
}

#[test]
fn every_export_survives_bad_arguments() {
    let lib = Lib::open();
    let sim = sim::start(Profile::default());
    let h = Bench::alloc(&lib, sim.port());
    let mut bench = Bench { lib, sim, h };
    // A freed handle and one never issued (the table hands out small numbers).
    let freed = Bench::alloc(&bench.lib, bench.sim.port());
    assert_eq!(bench.free(freed), EW_OK);
    let never = 0x7ffe;

    let mut failures = Vec::new();
    let mut calls = 0;
    let mut codes: BTreeMap<&str, BTreeMap<i16, usize>> = BTreeMap::new();
    for p in all_prototypes() {
        let how = export(&p.name).map(|e| e.how);
        let has_handle = p.params.iter().any(is_handle);
        let mut cases = Vec::new();
        for (i, a) in p.params.iter().enumerate() {
            if a.ptr {
                cases.push(Bad::Null(i));
                for v in [-1i64, 0x7fff, 0x7fff_ffff, -0x8000] {
                    cases.push(Bad::Behind(i, v));
                }
            } else if is_handle(a) {
                cases.push(Bad::Handle(0, "0"));
                cases.push(Bad::Handle(i64::from(freed), "freed"));
                cases.push(Bad::Handle(never, "never issued"));
            } else {
                for v in bad_ints(&a.ty) {
                    cases.push(Bad::Int(i, *v));
                }
            }
        }
        // The arguments as they are in every case but the bad one.
        let (base, _) = bench.call(&p, Bad::Int(usize::MAX, 0));
        bench.renew();
        for bad in cases {
            let (rc, intact) = bench.call(&p, bad);
            calls += 1;
            let kind = match bad {
                Bad::Null(_) => "NULL",
                Bad::Handle(..) => "bad handle",
                Bad::Int(..) => "bad integer",
                Bad::Behind(..) => "bad count behind a pointer",
            };
            *codes.entry(kind).or_default().entry(rc).or_default() += 1;
            if !known(rc) {
                failures.push(format!("{} {bad:?}: {rc} (not a clear EW_* code)", p.name));
            }
            if !intact {
                failures.push(format!("{} {bad:?}: wrote past a buffer", p.name));
            }
            // A handle that does not exist is EW_HANDLE wherever the
            // function checks handles (all but those FANUC's Ethernet
            // library lacks, which answer their code at once).
            // function checks handles (all but those FANUC's Ethernet
            // library lacks, which answer their code at once), unless an
            // argument check FANUC's library makes first fails (the code
            // the same arguments get with a good handle).
            if let (Bad::Handle(_, which), Some(How::Written { .. } | How::Described)) = (bad, how)
            {
                if rc != EW_HANDLE && (rc == EW_OK || rc != base) {
                    failures.push(format!(
                        "{} with a {which} handle: {rc} (a good one: {base})",
                        p.name
                    ));
                }
            }
            // A NULL the header does not allow is refused.
            if let (Bad::Null(i), EW_OK, true) = (bad, rc, has_handle)
                && !p.null_ok(&p.params[i].name)
            {
                failures.push(format!(
                    "{}: EW_OK with NULL for {}",
                    p.name, p.params[i].name
                ));
            }
            if std::env::var_os("BAD_INPUT_TRACE").is_some() {
                println!("{} {bad:?} -> {rc}", p.name);
            }
            bench.renew();
        }
    }
    let _ = bench.free(bench.h);
    println!("{calls} calls; codes by kind of bad argument:");
    for (k, c) in &codes {
        println!("  {k:28} {c:?}");
    }
    assert!(calls > 1000, "only {calls} calls");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
