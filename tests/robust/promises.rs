//! The header's promises, checked: each export's `# Safety` text says how
//! much memory behind each pointer the library may touch ("a writable
//! ODBST", "64 writable bytes", "`length` writable bytes", "`*num` writable
//! ODBPOS"). Every export taking a handle is called, with every argument
//! recipe the simulator accepts (all axes, counts up to 32, lengths up to
//! 4096), against the simulator and against a CNC answering more records
//! than any maximum (every payload repeated), with each pointer's promised
//! size placed right before an inaccessible page (mmap + PROT_NONE): one
//! byte touched past the promise is a fault, which ends the test naming the
//! call. Texts this test cannot read are listed; the few allowed are below.

use crate::cabi;
use crate::guard;
use crate::toolchain;

use fwlib32::ew::*;
use fwlib32::proto::frame::{Frame, ftype};
use fwlib32::proto::packet::{RespSub, decode_request, encode_response};
use fwlib32::sim::service::CncService;
use fwlib32::sim::{Machine, Profile};
use guard::{Frames, listen};
use parking_lot::Mutex;
use std::collections::BTreeMap;
use std::io::Write;
use std::process::Command;
use std::sync::Arc;

const PAGE: usize = 4096;

/// The call in progress, for the fault handler.
static CURRENT: std::sync::Mutex<[u8; 200]> = std::sync::Mutex::new([0; 200]);
static mut CURRENT_COPY: [u8; 200] = [0; 200];

extern "C" fn on_fault(_: libc::c_int) {
    let head = b"\npromises: touched memory past its Safety text: ";
    unsafe {
        libc::write(2, head.as_ptr().cast(), head.len());
        let p = std::ptr::addr_of!(CURRENT_COPY).cast::<u8>();
        let n = (0..200).take_while(|i| *p.add(*i) != 0).count();
        libc::write(2, p.cast(), n);
        libc::write(2, b"\n".as_ptr().cast(), 1);
        libc::_exit(101);
    }
}

/// Names the next call for the fault handler (SIGSEGV / SIGBUS end the
/// process with its name).
fn naming(what: &str) {
    let mut c = CURRENT.lock().unwrap();
    *c = [0; 200];
    let n = what.len().min(199);
    c[..n].copy_from_slice(&what.as_bytes()[..n]);
    unsafe { std::ptr::addr_of_mut!(CURRENT_COPY).write(*c) };
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| unsafe {
        let h = on_fault as extern "C" fn(libc::c_int) as libc::sighandler_t;
        libc::signal(libc::SIGSEGV, h);
        libc::signal(libc::SIGBUS, h);
    });
}

/// `n` bytes ending right before a page nothing may touch.
struct Fence {
    base: *mut u8,
    len: usize,
    n: usize,
}

impl Fence {
    fn new(n: usize, content: &[u8]) -> Fence {
        let rw = n.div_ceil(PAGE).max(1) * PAGE;
        let len = rw + PAGE;
        let base = unsafe {
            libc::mmap(
                std::ptr::null_mut(),
                len,
                libc::PROT_READ | libc::PROT_WRITE,
                libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
                -1,
                0,
            )
        };
        assert_ne!(base, libc::MAP_FAILED);
        let base = base.cast::<u8>();
        assert_eq!(
            unsafe { libc::mprotect(base.add(rw).cast(), PAGE, libc::PROT_NONE) },
            0
        );
        let f = Fence { base, len, n };
        let k = content.len().min(n);
        unsafe { std::ptr::copy_nonoverlapping(content.as_ptr(), f.ptr(), k) };
        f
    }
    fn ptr(&self) -> *mut u8 {
        unsafe { self.base.add(self.len - PAGE - self.n) }
    }
}

impl Drop for Fence {
    fn drop(&mut self) {
        unsafe { libc::munmap(self.base.cast(), self.len) };
    }
}

/// How much a pointer's text promises.
#[derive(Debug, Clone)]
enum Promise {
    Bytes(usize),
    /// The value of this integer argument times a size, and at least
    /// the last ("`x` must point to `length` readable bytes ..., and at least 4").
    Arg(String, usize, usize),
    /// Records of `size` bytes, as many as the count in pointer `count`.
    Counted(String, usize),
}

/// The Safety section of a prototype's comment, as one line.
fn safety(doc: &str) -> String {
    let s = doc.split("# Safety").nth(1).unwrap_or("");
    let s = s.split("*/").next().unwrap_or(s);
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The size of the type named by the words at the start of `w`
/// ("unsigned shorts", "ODBPOS", "doubles", "4-byte elements", "PRGDIR2 records").
fn type_size(w: &[&str], sizes: &BTreeMap<String, usize>) -> Option<usize> {
    // An array type is quoted as code: `char[62]`.
    let first = w
        .first()?
        .trim_end_matches(['.', ',', ';'])
        .trim_matches('`');
    if first == "unsigned" {
        let t = w
            .get(1)?
            .trim_end_matches(['.', ',', ';'])
            .trim_end_matches('s');
        return sizes.get(&format!("unsigned {t}")).copied();
    }
    if let Some(n) = first.strip_suffix("-byte") {
        return n.parse().ok();
    }
    if first == "doubles" || first == "double" {
        return Some(8);
    }
    sizes
        .get(first)
        .or_else(|| sizes.get(first.trim_end_matches('s')))
        .copied()
}

/// The promise for pointer `name` among `pointers`, if the text says it in
/// a form read here: `name` (possibly in a list of names sharing the
/// predicate) followed by "[must] [be NULL or] [point to|have|to] " and
/// "a [readable and] writable T", "N [writable] bytes", "writable Ts",
/// "`arg` writable bytes|T", "`*count` [writable] T".
fn promise(
    text: &str,
    name: &str,
    pointers: &[String],
    sizes: &BTreeMap<String, usize>,
) -> Option<Promise> {
    if text.contains(&format!("`{name}` must point to a writable"))
        && text.contains("with room for")
    {
        return None;
    }
    let words: Vec<&str> = text.split_whitespace().collect();
    let is_ptr = |w: &str| {
        let n = w.trim_matches(|c: char| c == ',' || c == ';' || c == '.');
        n.starts_with('`') && n.ends_with('`') && pointers.iter().any(|p| *p == n[1..n.len() - 1])
    };
    let at = words
        .iter()
        .position(|w| w.trim_end_matches([',', ';', '.']).eq(&format!("`{name}`")))?;
    // Skip the rest of a list of names: `a`, `b` and `c` ...
    let mut i = at + 1;
    while i < words.len() && (is_ptr(words[i]) || words[i] == "and") {
        i += 1;
    }
    let mut w = &words[i.min(words.len())..];
    for skip in [
        &["must"][..],
        &["be", "NULL", "or"],
        &["point", "to"],
        &["have"],
        &["to"],
    ] {
        if w.starts_with(skip) {
            w = &w[skip.len()..];
        }
    }
    fn drop_rw<'a, 'b>(mut w: &'b [&'a str]) -> &'b [&'a str] {
        while matches!(w.first(), Some(&"readable" | &"writable" | &"and")) {
            w = &w[1..];
        }
        w
    }
    if w.first() == Some(&"a") {
        w = &w[1..];
    }
    let w = drop_rw(w);
    let first = w.first()?.trim_end_matches([',', ';', '.']);
    let rest = drop_rw(&w[1..]);
    let bytes = rest.first().is_some_and(|x| x.starts_with("bytes"));
    let sized = |rest: &[&str]| {
        if bytes {
            Some(1)
        } else {
            type_size(rest, sizes)
        }
    };
    if let Some(inner) = first.strip_prefix("`*").and_then(|x| x.strip_suffix('`')) {
        return sized(rest).map(|s| Promise::Counted(inner.to_string(), s));
    }
    if let Some(arg) = first.strip_prefix('`').and_then(|x| x.strip_suffix('`')) {
        let at_least = text
            .split_once(&format!("`{name}` must point to `{arg}`"))
            .and_then(|(_, t)| t.split(['.', ';']).next())
            .and_then(|t| t.split_once("at least "))
            .and_then(|(_, n)| n.split_whitespace().next()?.parse().ok())
            .unwrap_or(0);
        return sized(rest).map(|s| Promise::Arg(arg.to_string(), s, at_least));
    }
    if let Ok(n) = first.parse::<usize>() {
        return sized(rest).map(|s| Promise::Bytes(n * s));
    }
    type_size(w, sizes).map(Promise::Bytes)
}

/// sizeof of every struct of the header and of the scalar types, from the C compiler.
fn sizes() -> BTreeMap<String, usize> {
    let header = toolchain::header_text();
    let mut body = String::new();
    for (kind, name) in toolchain::header_typedefs(&header) {
        body.push_str(&format!(
            "    printf(\"{name} %zu\\n\", sizeof({kind} {name}));\n"
        ));
    }
    for t in ["short", "long", "char"] {
        body.push_str(&format!("    printf(\"{t} %zu\\n\", sizeof({t}));\n"));
    }
    let c = format!(
        "#include <stdio.h>\n#include \"fwlib32.h\"\nint main(void)\n{{\n{body}    return 0;\n}}\n"
    );
    let dir = toolchain::scratch("promises-sizes");
    let (src, exe) = (dir.join("sizes.c"), dir.join("sizes"));
    std::fs::write(&src, c).unwrap();
    toolchain::run(
        Command::new(toolchain::cc())
            .args(["-std=c99", "-o"])
            .arg(&exe)
            .arg("-I")
            .arg(toolchain::header_path().parent().unwrap())
            .arg(&src),
    );
    let out = toolchain::run(&mut toolchain::target_command(&exe));
    let mut m: BTreeMap<String, usize> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .filter_map(|l| {
            let (n, s) = l.split_once(' ')?;
            Some((n.to_string(), s.parse().ok()?))
        })
        .collect();
    m.insert("unsigned short".into(), 2);
    m.insert("unsigned long".into(), m["long"]);
    m.insert("char[62]".into(), 62);
    m
}

/// A CNC that answers what the simulator answers, every payload repeated
/// (`repeat`) until it would pass 1400 bytes in the frame: more records
/// than any maximum.
fn cnc(profile: Profile, repeat: bool) -> u16 {
    let machine = Arc::new(Mutex::new(Machine::new(profile)));
    listen(move |_, mut s| {
        let m = machine.clone();
        std::thread::spawn(move || {
            let mut frames = Frames::new();
            let version = m.lock().open_body().frame_version();
            let startup = if version <= 2 { 2 } else { 1 };
            let mut data = 0;
            while let Some(f) = frames.read(&mut s) {
                let reply = match f.ftype {
                    ftype::OPEN_REQ => {
                        Frame::new(version, ftype::OPEN_RESP, m.lock().open_body().to_bytes())
                    }
                    ftype::CLOSE_REQ => {
                        let _ =
                            s.write_all(&Frame::new(version, ftype::CLOSE_RESP, vec![]).encode());
                        return;
                    }
                    ftype::DATA_REQ => {
                        let Ok(subs) = decode_request(&f.body) else {
                            return;
                        };
                        data += 1;
                        let mut resp: Vec<RespSub> =
                            subs.iter().map(|q| m.lock().answer(q)).collect();
                        if repeat && data > startup {
                            let room = 1400 / resp.len().max(1);
                            for r in &mut resp {
                                let one = r.payload.clone();
                                while !one.is_empty() && r.payload.len() + one.len() <= room {
                                    r.payload.extend_from_slice(&one);
                                }
                            }
                        }
                        Frame::new(version, ftype::DATA_RESP, encode_response(&resp))
                    }
                    _ => continue,
                };
                if s.write_all(&reply.encode()).is_err() {
                    return;
                }
            }
        });
        true
    })
}

/// Argument recipes: integers, lengths, the count in each counted pointer.
const RECIPES: [(i64, i64, i64); 9] = [
    (-1, 4096, 32),
    (1, 4096, 32),
    (0, 4096, 32),
    (1, 4096, 8),
    (500, 10, 4),
    (1320, 8, 1),
    (1, 256, 256),
    (2, 4096, 32),
    (1, 0, 0),
];

/// Pointers whose text says something this test does not size (strings,
/// sizes computed from several arguments): they get 16 MiB.
const UNSIZED_OK: &[&str] = &[
    "ip", "prgname", "logfile", "fname", "path", "from", "to", "drv_name", "dir_name", "types",
    "grpinfo", "diag_no", "prm_no", "type",
    // cnc_rdaxisdata: `num * *len` ODBAXDT; cnc_rdparainfo / cnc_rddiaginfo:
    // a struct "with room for `read_no` entries".
    "axdata", "paraif", "diagif",
];

/// A parameter's name (`item)[62]` of `char (*item)[62]`: item).
fn name_of(p: &str) -> String {
    p.split(')').next().unwrap_or(p).to_string()
}

fn args_for(
    p: &cabi::Proto,
    h: u16,
    (int, length, count): (i64, i64, i64),
    promises: &BTreeMap<String, Option<Promise>>,
) -> (Vec<i64>, Vec<Option<Fence>>, Vec<cabi::Buf>) {
    let ints: BTreeMap<&str, i64> = p
        .params
        .iter()
        .filter(|a| !a.ptr)
        .map(|a| {
            let v = if cabi::is_handle(a) {
                i64::from(h)
            } else if a.name.contains("len") {
                length
            } else {
                int
            };
            (a.name.as_str(), v)
        })
        .collect();
    let (mut words, mut fences, mut big) = (Vec::new(), Vec::new(), Vec::new());
    for a in &p.params {
        if !a.ptr {
            words.push(ints[a.name.as_str()]);
            continue;
        }
        let n = match promises.get(&name_of(&a.name)).cloned().flatten() {
            Some(Promise::Bytes(n)) => Some(n),
            Some(Promise::Arg(x, size, min)) => ints
                .get(x.as_str())
                .map(|v| ((*v).max(0) as usize * size).max(min)),
            Some(Promise::Counted(c, size)) => {
                // The count a counted pointer holds; what a `long` count says.
                let _ = c;
                Some(count as usize * size)
            }
            None => None,
        };
        match n {
            Some(n) => {
                let f = Fence::new(n, &count.to_le_bytes());
                words.push(f.ptr() as i64);
                fences.push(Some(f));
            }
            None => {
                let b = cabi::Buf::new(Some(count));
                words.push(b.0 as i64);
                big.push(b);
            }
        }
    }
    (words, fences, big)
}

fn call(lib: &cabi::Lib, p: &cabi::Proto, words: &[i64]) -> i16 {
    let f = lib.get(&p.name);
    let mut w = [0i64; 8];
    w[..words.len()].copy_from_slice(words);
    unsafe { f(w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]) }
}

fn check(profile: Profile) {
    static SIZES: std::sync::OnceLock<BTreeMap<String, usize>> = std::sync::OnceLock::new();
    let sizes = SIZES.get_or_init(sizes);
    let lib = cabi::Lib::open();
    let mut unread = Vec::new();
    let mut calls = Vec::new();
    for p in cabi::all_prototypes() {
        let handle = p.params.iter().any(|a| cabi::is_handle(a) && !a.ptr);
        if !handle || cabi::SESSION.contains(&p.name.as_str()) || cabi::fixed_answer(&p.name) {
            continue;
        }
        let text = safety(&p.doc);
        let pointers: Vec<String> = p
            .params
            .iter()
            .filter(|a| a.ptr)
            .map(|a| name_of(&a.name))
            .collect();
        let promises: BTreeMap<String, Option<Promise>> = pointers
            .iter()
            .map(|n| (n.clone(), promise(&text, n, &pointers, sizes)))
            .collect();
        for (n, pr) in &promises {
            if pr.is_none()
                && !UNSIZED_OK.contains(&n.as_str())
                && !text.contains("Nothing is written")
            {
                unread.push(format!("{}: `{n}`: {text}", p.name));
            }
        }
        calls.push((p, promises));
    }
    assert!(
        unread.is_empty(),
        "Safety texts this test cannot size (say `NAME` must point to N writable bytes / a writable TYPE / `LENGTH` writable bytes / `*COUNT` writable TYPE):\n{}",
        unread.join("\n")
    );
    let mut checked = 0;
    for repeat in [false, true] {
        let port = cnc(profile.clone(), repeat);
        let h = lib.alloc(port, 5).expect("a handle");
        for (p, promises) in &calls {
            if promises.values().all(Option::is_none) {
                continue;
            }
            for r in RECIPES {
                naming(&format!("{} {r:?} repeat={repeat}", p.name));
                let (words, _fences, _big) = args_for(p, h, r, promises);
                let rc = call(&lib, p, &words);
                assert_ne!(rc, EW_UNEXP, "{} {r:?}", p.name);
                if rc == EW_OK {
                    checked += 1;
                }
            }
        }
        let _ = lib.free(h);
    }
    println!("{checked} calls answered EW_OK within their promises");
    assert!(checked > 200, "too few calls succeeded: {checked}");
}

#[test]
fn every_export_stays_within_its_safety_text_30i() {
    check(Profile::default());
}

#[test]
fn every_export_stays_within_its_safety_text_16i() {
    let text =
        fwlib32::sim::profile::DEFAULT_PROFILE.replacen("class = \"30i\"", "class = \"16i\"", 1);
    check(Profile::parse(&text).expect("16i profile"));
}
