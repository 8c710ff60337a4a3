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

mod cabi;
mod sim;
mod toolchain;

use cabi::{Arg, Buf, Lib, Proto, all_prototypes, is_handle};
use fwlib32::ew::*;
use fwlib32::ffi::exports::{How, export};
use fwlib32::sim::Profile;
use std::collections::BTreeMap;
use std::time::Duration;

/// What a call gets in place of one argument.
#[derive(Debug, Clone, Copy)]
enum Bad {
    Null(usize),
    Handle(i64, &'static str),
    Int(usize, i64),
    Behind(usize, i64),
}

const HANDLE_TIMEOUT: i64 = 2;
/// The promise checked: no wait outlives the handle's timeout. A call that
/// makes n round trips (cnc_rdparam_ext over 32767 numbers makes ~1,500)
/// may wait n + 1 times (connecting, then each answer); the slack covers
/// scheduling on a loaded or emulated (qemu) machine, so only a hang fails.
fn bound(frames: u64) -> Duration {
    Duration::from_secs(HANDLE_TIMEOUT as u64) * (frames as u32 + 1) + Duration::from_secs(8)
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
    /// A fresh handle for the next call: the last may have freed this one,
    /// broken its connection or left an upload running.
    fn renew(&mut self) {
        let _ = self.lib.free(self.h);
        self.h = self.lib.alloc(self.sim.port(), HANDLE_TIMEOUT).unwrap();
    }

    /// Calls `p` with `bad` in place of one argument: the result code and
    /// whether every buffer is intact.
    /// The code, whether the buffers are intact, and the round trips sent.
    fn call(&mut self, p: &Proto, bad: Bad) -> (i16, bool, u64) {
        let mut args = Vec::new();
        for (i, a) in p.params.iter().enumerate() {
            args.push(if a.ptr {
                Arg::Ptr(match bad {
                    Bad::Null(k) if k == i => None,
                    Bad::Behind(k, v) if k == i => Some(Buf::new(Some(v))),
                    _ => Some(Buf::new(None)),
                })
            } else if is_handle(a) {
                Arg::Int(match bad {
                    Bad::Handle(h, _) => h,
                    _ => i64::from(self.h),
                })
            } else {
                Arg::Int(match bad {
                    Bad::Int(k, v) if k == i => v,
                    // A plausible small number elsewhere (1: a count, a
                    // number, a type), the port for a port.
                    _ if a.name.contains("port") => i64::from(self.sim.port()),
                    _ if a.name.contains("timeout") => HANDLE_TIMEOUT,
                    _ => 1,
                })
            });
        }
        if std::env::var_os("BAD_INPUT_TRACE").is_some() {
            eprintln!("{} {bad:?}", p.name);
        }
        let before = self.sim.data_frames();
        let (rc, intact, took) = self.lib.invoke(p, args);
        let frames = self.sim.data_frames() - before;
        assert!(
            took < bound(frames),
            "{} {bad:?} took {took:?} over {frames} round trips",
            p.name
        );
        (rc, intact, frames)
    }
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
    // cnc_startupprocess creates its log file by the bytes it is given
    // (names are bytes, not UTF-8): the counts behind a pointer name files,
    // which go to a scratch directory, not the working tree.
    std::env::set_current_dir(toolchain::scratch("bad-input-cwd")).expect("scratch directory");
    let lib = Lib::open();
    let sim = sim::start(Profile::default());
    let h = lib.alloc(sim.port(), HANDLE_TIMEOUT).unwrap();
    let mut bench = Bench { lib, sim, h };
    // A freed handle and one never issued (the table hands out small numbers).
    let freed = bench.lib.alloc(bench.sim.port(), HANDLE_TIMEOUT).unwrap();
    assert_eq!(bench.lib.free(freed), EW_OK);
    let never = 0x7ffe;

    let mut failures = Vec::new();
    let mut calls = 0;
    let mut not_on_ethernet = 0;
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
        let (base, _, sent) = bench.call(&p, Bad::Int(usize::MAX, 0));
        // A function no Ethernet library of FANUC's has answers its code on
        // a good handle, sending nothing.
        if let Some(How::NotOnEthernet { code, .. }) = how {
            if (base, sent) != (code, 0) {
                failures.push(format!(
                    "{}: {base} after {sent} round trips, not {code} and none",
                    p.name
                ));
            }
            not_on_ethernet += 1;
        }
        bench.renew();
        for bad in cases {
            let (rc, intact, _) = bench.call(&p, bad);
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
            // function has one, unless an argument check FANUC's library
            // makes first fails (the code the same arguments get with a
            // good handle).
            if let (
                Bad::Handle(_, which),
                Some(How::Written { .. } | How::Described | How::NotOnEthernet { .. }),
            ) = (bad, how)
                && rc != EW_HANDLE
                && (rc == EW_OK || rc != base)
            {
                failures.push(format!(
                    "{} with a {which} handle: {rc} (a good one: {base})",
                    p.name
                ));
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
    let _ = bench.lib.free(bench.h);
    println!("{calls} calls; codes by kind of bad argument:");
    for (k, c) in &codes {
        println!("  {k:28} {c:?}");
    }
    assert!(calls > 1000, "only {calls} calls");
    let absent = fwlib32::ffi::exports::EXPORTS
        .iter()
        .filter(|e| matches!(e.how, How::NotOnEthernet { .. }))
        .count();
    assert_eq!(
        not_on_ethernet, absent,
        "every function not on Ethernet called"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
