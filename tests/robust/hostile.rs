//! A hostile CNC. A server answers every request with what the simulator
//! would answer, then mutates it: payloads truncated, extended, bytes
//! flipped, replaced by random bytes, error codes set, subpackets dropped.
//! The framing stays valid, so every mutation reaches the decoders. Every
//! read function of the library, called many times against it, must return
//! an EW_* code (never EW_UNEXP, the code of a caught panic), never write
//! past the caller's buffer, and come back within the timeout. The mutations
//! come from a fixed seed: a failure replays.
//!
//! Two call lists: [`PROBES`], read functions with the arguments a caller
//! would pass, and every exported function of the headers (tests/cabi),
//! its arguments found against a plain simulator, so that a new export is
//! covered without a line here.

use crate::cabi;
use crate::guard;
use crate::sim;

use fwlib32::ew::*;
use fwlib32::proto::frame::{Frame, ftype};
use fwlib32::proto::packet::{RespSub, decode_request, encode_response};
use fwlib32::sim::service::CncService;
use fwlib32::sim::{Machine, Profile};
use fwlib32::types::*;
use fwlib32::*;
use parking_lot::Mutex;
use std::io::Write;
use std::net::TcpStream;
use std::os::raw::{c_long, c_short, c_ulong, c_ushort};
use std::sync::Arc;

/// xorshift64*: small, seedable, good enough for mutations.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn bytes(&mut self, n: usize) -> Vec<u8> {
        (0..n).map(|_| self.next() as u8).collect()
    }
}

/// The answer to one subpacket, mutated or not.
fn mutate(rng: &mut Rng, mut r: RespSub) -> Option<RespSub> {
    let n = r.payload.len();
    match rng.below(10) {
        0 | 1 => {}
        2 | 3 => r.payload.truncate(rng.below(n.max(1))),
        4 => {
            for _ in 0..1 + rng.below(4) {
                if n > 0 {
                    let i = rng.below(n);
                    r.payload[i] ^= rng.next() as u8 | 1;
                }
            }
        }
        5 => {
            // A count or length word made huge or negative.
            if n >= 4 {
                let i = rng.below(n / 4) * 4;
                let v: [u8; 4] = match rng.below(3) {
                    0 => [0x7f, 0xff, 0xff, 0xff],
                    1 => [0xff, 0xff, 0xff, 0xff],
                    _ => [0x80, 0, 0, 0],
                };
                r.payload[i..i + 4].copy_from_slice(&v);
            }
        }
        6 => {
            let len = rng.below(700);
            r.payload = rng.bytes(len);
        }
        7 => {
            let len = rng.below(300);
            r.payload.extend(rng.bytes(len));
        }
        8 => {
            r.error = [1, 2, 3, 4, 5, 6, 7, 8, 10, 13, 17, -1][rng.below(12)];
            r.payload.clear();
        }
        _ => return None,
    }
    Some(r)
}

/// Serves one connection: the open and the start-up frames (sysinfo, and
/// the 16i class's option probe) as the simulator answers them, then
/// mutated answers.
fn serve(mut s: TcpStream, machine: Arc<Mutex<Machine>>, seed: u64) {
    let mut rng = Rng(seed | 1);
    let mut frames = Frames::new();
    let version = machine.lock().open_body().frame_version();
    let startup_frames = if version <= 2 { 2 } else { 1 };
    let mut data_frames = 0;
    while let Some(frame) = frames.read(&mut s) {
        let reply = match frame.ftype {
            ftype::OPEN_REQ => Frame::new(
                version,
                ftype::OPEN_RESP,
                machine.lock().open_body().to_bytes(),
            ),
            ftype::CLOSE_REQ => {
                let _ = s.write_all(&Frame::new(version, ftype::CLOSE_RESP, vec![]).encode());
                return;
            }
            ftype::DATA_REQ => {
                let Ok(subs) = decode_request(&frame.body) else {
                    return;
                };
                data_frames += 1;
                let mut m = machine.lock();
                let mut resp: Vec<RespSub> = subs.iter().map(|q| m.answer(q)).collect();
                if data_frames > startup_frames {
                    resp = resp
                        .into_iter()
                        .filter_map(|r| mutate(&mut rng, r))
                        .collect();
                    if resp.is_empty() {
                        resp.push(m.answer(&subs[0]));
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
}

fn hostile_cnc(profile: Profile, seed: u64) -> u16 {
    let machine = Arc::new(Mutex::new(Machine::new(profile)));
    listen(move |i, c| {
        let m = machine.clone();
        std::thread::spawn(move || serve(c, m, seed.wrapping_add(i as u64 * 7919)));
        true
    })
}

use guard::*;

type Probe = (&'static str, fn(c_ushort) -> (c_short, Vec<Out>));

fn one(n: usize, f: impl FnOnce(&mut Out) -> c_short) -> (c_short, Vec<Out>) {
    let mut o = Out::new(n);
    let r = f(&mut o);
    (r, vec![o])
}

fn size<T>() -> usize {
    std::mem::size_of::<T>()
}

/// Every read function with a plausible call, the output sized as a caller
/// sizes it.
const PROBES: &[Probe] = &[
    ("cnc_statinfo", |h| {
        one(size::<ODBST>(), |o| unsafe { cnc_statinfo(h, o.p()) })
    }),
    ("cnc_statinfo2", |h| {
        one(size::<ODBST2>(), |o| unsafe { cnc_statinfo2(h, o.p()) })
    }),
    ("cnc_rdcncid", |h| {
        one(16, |o| unsafe { cnc_rdcncid(h, o.p::<c_ulong>()) })
    }),
    ("cnc_rdaxisname", |h| {
        let mut n: c_short = 32;
        one(size::<ODBAXISNAME>() * 32, |o| unsafe {
            cnc_rdaxisname(h, &mut n, o.p())
        })
    }),
    ("cnc_rdspdlname", |h| {
        let mut n: c_short = 8;
        one(size::<ODBSPDLNAME>() * 8, |o| unsafe {
            cnc_rdspdlname(h, &mut n, o.p())
        })
    }),
    ("cnc_rddynamic2 all", |h| {
        one(size::<ODBDY2>(), |o| unsafe {
            cnc_rddynamic2(h, ALL_AXES, size::<ODBDY2>() as c_short, o.p())
        })
    }),
    ("cnc_rddynamic2 one", |h| {
        one(44, |o| unsafe { cnc_rddynamic2(h, 1, 44, o.p()) })
    }),
    ("cnc_rddynamic", |h| {
        one(size::<ODBDY>(), |o| unsafe {
            cnc_rddynamic(h, ALL_AXES, size::<ODBDY>() as c_short, o.p())
        })
    }),
    ("cnc_actf", |h| {
        one(size::<ODBACT>(), |o| unsafe { cnc_actf(h, o.p()) })
    }),
    ("cnc_acts", |h| {
        one(size::<ODBACT>(), |o| unsafe { cnc_acts(h, o.p()) })
    }),
    ("cnc_acts2", |h| {
        one(size::<ODBACT2>(), |o| unsafe {
            cnc_acts2(h, ALL_SPINDLES, o.p())
        })
    }),
    ("cnc_rdspeed", |h| {
        one(size::<ODBSPEED>(), |o| unsafe { cnc_rdspeed(h, -1, o.p()) })
    }),
    ("cnc_rdspmeter", |h| {
        let mut n: c_short = 8;
        one(size::<ODBSPLOAD>() * 8, |o| unsafe {
            cnc_rdspmeter(h, -1, &mut n, o.p())
        })
    }),
    ("cnc_rdsvmeter", |h| {
        let mut n: c_short = 32;
        one(size::<ODBSVLOAD>() * 32, |o| unsafe {
            cnc_rdsvmeter(h, &mut n, o.p())
        })
    }),
    ("cnc_rdspload", |h| {
        one(size::<ODBSPN>(), |o| unsafe { cnc_rdspload(h, -1, o.p()) })
    }),
    ("cnc_rdposition", |h| {
        let mut n: c_short = 32;
        one(size::<ODBPOS>() * 32, |o| unsafe {
            cnc_rdposition(h, -1, &mut n, o.p())
        })
    }),
    ("cnc_rdaxisdata", |h| {
        let types: [c_short; 4] = [0, 1, 2, 3];
        let mut len: c_short = 32;
        one(size::<ODBAXDT>() * 4 * 32, |o| unsafe {
            cnc_rdaxisdata(h, 1, types.as_ptr().cast_mut(), 4, &mut len, o.p())
        })
    }),
    ("cnc_absolute", |h| {
        one(size::<ODBAXIS>(), |o| unsafe {
            cnc_absolute(h, ALL_AXES, size::<ODBAXIS>() as c_short, o.p())
        })
    }),
    ("cnc_machine", |h| {
        one(8, |o| unsafe { cnc_machine(h, 1, 8, o.p()) })
    }),
    ("cnc_relative2", |h| {
        one(size::<ODBAXIS>(), |o| unsafe {
            cnc_relative2(h, ALL_AXES, size::<ODBAXIS>() as c_short, o.p())
        })
    }),
    ("cnc_distance", |h| {
        one(size::<ODBAXIS>(), |o| unsafe {
            cnc_distance(h, ALL_AXES, size::<ODBAXIS>() as c_short, o.p())
        })
    }),
    ("cnc_getfigure", |h| {
        let mut n: c_short = 0;
        let mut a = Out::new(64);
        let mut b = Out::new(64);
        let r = unsafe { cnc_getfigure(h, 0, &mut n, a.p(), b.p()) };
        (r, vec![a, b])
    }),
    ("cnc_rdprgnum", |h| {
        one(size::<ODBPRO>(), |o| unsafe { cnc_rdprgnum(h, o.p()) })
    }),
    ("cnc_rdseqnum", |h| {
        one(size::<ODBSEQ>(), |o| unsafe { cnc_rdseqnum(h, o.p()) })
    }),
    ("cnc_rdblkcount", |h| {
        one(4, |o| unsafe { cnc_rdblkcount(h, o.p::<c_long>()) })
    }),
    ("cnc_rdactpt", |h| {
        let mut a = Out::new(4);
        let mut b = Out::new(4);
        let r = unsafe { cnc_rdactpt(h, a.p::<c_long>(), b.p::<c_long>()) };
        (r, vec![a, b])
    }),
    ("cnc_exeprgname", |h| {
        one(size::<ODBEXEPRG>(), |o| unsafe { cnc_exeprgname(h, o.p()) })
    }),
    ("cnc_exeprgname2", |h| {
        one(256, |o| unsafe { cnc_exeprgname2(h, o.p()) })
    }),
    ("cnc_rdexecprog", |h| {
        let mut len: c_ushort = 256;
        let mut blk: c_short = 0;
        one(256, |o| unsafe {
            cnc_rdexecprog(h, &mut len, &mut blk, o.p())
        })
    }),
    ("cnc_modal all", |h| {
        one(size::<ODBMDL>(), |o| unsafe { cnc_modal(h, -1, 0, o.p()) })
    }),
    ("cnc_modal aux", |h| {
        one(size::<ODBMDL>(), |o| unsafe { cnc_modal(h, -2, 0, o.p()) })
    }),
    ("cnc_modal 103", |h| {
        one(size::<ODBMDL>(), |o| unsafe { cnc_modal(h, 103, 1, o.p()) })
    }),
    ("cnc_alarm", |h| {
        one(size::<ODBALM>(), |o| unsafe { cnc_alarm(h, o.p()) })
    }),
    ("cnc_alarm2", |h| {
        one(4, |o| unsafe { cnc_alarm2(h, o.p::<c_long>()) })
    }),
    ("cnc_rdalmmsg", |h| {
        let mut n: c_short = 10;
        one(size::<ODBALMMSG>() * 10, |o| unsafe {
            cnc_rdalmmsg(h, -1, &mut n, o.p())
        })
    }),
    ("cnc_rdalmmsg2", |h| {
        let mut n: c_short = 10;
        one(size::<ODBALMMSG2>() * 10, |o| unsafe {
            cnc_rdalmmsg2(h, -1, &mut n, o.p())
        })
    }),
    ("cnc_rdalminfo", |h| {
        one(size::<ALMINFO>(), |o| unsafe {
            cnc_rdalminfo(h, 1, -1, size::<ALMINFO>() as c_short, o.p())
        })
    }),
    ("cnc_rdopmsg", |h| {
        one(size::<OPMSG>(), |o| unsafe {
            cnc_rdopmsg(h, 0, size::<OPMSG>() as c_short, o.p())
        })
    }),
    ("cnc_toolnum", |h| {
        one(size::<ODBTLIFE4>(), |o| unsafe {
            cnc_toolnum(h, 0, 0, o.p())
        })
    }),
    ("cnc_rdntool", |h| {
        one(size::<ODBTLIFE3>(), |o| unsafe { cnc_rdntool(h, 0, o.p()) })
    }),
    ("cnc_rdtimer", |h| {
        one(size::<IODBTIME>(), |o| unsafe { cnc_rdtimer(h, 0, o.p()) })
    }),
    ("cnc_rdparam", |h| {
        one(size::<IODBPSD>(), |o| unsafe {
            cnc_rdparam(h, 1320, -1, size::<IODBPSD>() as c_short, o.p())
        })
    }),
    ("cnc_diagnoss", |h| {
        one(size::<ODBDGN>(), |o| unsafe {
            cnc_diagnoss(h, 301, -1, size::<ODBDGN>() as c_short, o.p())
        })
    }),
    ("cnc_rdparainfo", |h| {
        one(size::<ODBPARAIF>(), |o| unsafe {
            cnc_rdparainfo(h, 6711, 10, o.p())
        })
    }),
    ("cnc_rddiaginfo", |h| {
        one(size::<ODBDIAGIF>(), |o| unsafe {
            cnc_rddiaginfo(h, 300, 10, o.p())
        })
    }),
    ("cnc_rdparam_ext", |h| {
        let nums: [i32; 2] = [1320, 6711];
        one(size::<IODBPRM>() * 2, |o| unsafe {
            cnc_rdparam_ext(h, nums.as_ptr().cast_mut().cast(), 2, o.p())
        })
    }),
    ("cnc_rdparar", |h| {
        let (mut s, mut e, mut len): (c_short, c_short, c_short) = (6700, 6760, 600);
        one(600, |o| unsafe {
            cnc_rdparar(h, &mut s, -1, &mut e, &mut len, o.p())
        })
    }),
    ("cnc_rdmacro", |h| {
        one(size::<ODBM>(), |o| unsafe {
            cnc_rdmacro(h, 500, 10, o.p())
        })
    }),
    ("cnc_rdmacror", |h| {
        let n = 8 + 8 * 5;
        one(n, |o| unsafe {
            cnc_rdmacror(h, 500, 504, n as c_short, o.p())
        })
    }),
    ("cnc_rdmacror2", |h| {
        let mut n: c_ulong = 5;
        one(8 * 5, |o| unsafe { cnc_rdmacror2(h, 500, &mut n, o.p()) })
    }),
    ("pmc_rdpmcrng", |h| {
        one(8 + 40, |o| unsafe {
            pmc_rdpmcrng(h, 9, 1, 0, 39, 8 + 40, o.p())
        })
    }),
    ("pmc_rdpmcinfo", |h| {
        one(size::<ODBPMCINF>(), |o| unsafe {
            pmc_rdpmcinfo(h, -1, o.p())
        })
    }),
    ("cnc_rdtofs", |h| {
        one(size::<ODBTOFS>(), |o| unsafe {
            cnc_rdtofs(h, 1, 0, 8, o.p())
        })
    }),
    ("cnc_rdtofsr", |h| {
        let n = 8 + 4 * 4 * 3;
        one(n, |o| unsafe {
            cnc_rdtofsr(h, 1, 0, 3, n as c_short, o.p())
        })
    }),
    ("cnc_rdzofs", |h| {
        one(size::<IODBZOFS>(), |o| unsafe {
            cnc_rdzofs(h, 1, -1, size::<IODBZOFS>() as c_short, o.p())
        })
    }),
    ("cnc_rdzofsr", |h| {
        let n = 6 + 4 * 32 * 3;
        one(n, |o| unsafe {
            cnc_rdzofsr(h, 0, -1, 2, n as c_short, o.p())
        })
    }),
    ("cnc_rdalmhistry", |h| {
        one(size::<ODBAHIS>(), |o| unsafe {
            cnc_rdalmhistry(h, 1, 10, size::<ODBAHIS>() as c_ushort, o.p())
        })
    }),
    ("cnc_rdalmhistry2", |h| {
        one(size::<ODBAHIS2>(), |o| unsafe {
            cnc_rdalmhistry2(h, 1, 10, size::<ODBAHIS2>() as c_ushort, o.p())
        })
    }),
    ("cnc_rdlife", |h| {
        one(size::<ODBTLIFE3>(), |o| unsafe { cnc_rdlife(h, 1, o.p()) })
    }),
    ("cnc_rdtoolgrp", |h| {
        one(size::<ODBTG>(), |o| unsafe {
            cnc_rdtoolgrp(h, 1, size::<ODBTG>() as c_short, o.p())
        })
    }),
    ("cnc_rdgrpinfo", |h| {
        one(size::<IODBTGI>(), |o| unsafe {
            cnc_rdgrpinfo(h, 1, 5, size::<IODBTGI>() as c_short, o.p())
        })
    }),
    ("cnc_rdtlusegrp", |h| {
        one(size::<ODBUSEGRP>(), |o| unsafe { cnc_rdtlusegrp(h, o.p()) })
    }),
    ("cnc_rdtool", |h| {
        let mut n: c_short = 3;
        one(size::<IODBTLMNG>() * 3, |o| unsafe {
            cnc_rdtool(h, 1, &mut n, o.p())
        })
    }),
    ("cnc_rdprogdir3", |h| {
        let (mut top, mut num): (c_long, c_short) = (0, 3);
        one(size::<PRGDIR3>() * 3, |o| unsafe {
            cnc_rdprogdir3(h, 2, &mut top, &mut num, o.p())
        })
    }),
    ("cnc_rdprogdir", |h| {
        one(256, |o| unsafe { cnc_rdprogdir(h, 2, 0, 9999, 256, o.p()) })
    }),
    // --- machine information, servo, tool life sizes ---
    ("cnc_rdetherinfo", |h| {
        let mut a = Out::new(2);
        let mut b = Out::new(2);
        let r = unsafe { cnc_rdetherinfo(h, a.p(), b.p()) };
        (r, vec![a, b])
    }),
    ("cnc_rdproctime", |h| {
        one(size::<ODBPTIME>(), |o| unsafe { cnc_rdproctime(h, o.p()) })
    }),
    ("cnc_rdloopgain", |h| {
        one(4 * MAX_AXIS, |o| unsafe {
            cnc_rdloopgain(h, o.p::<c_long>())
        })
    }),
    ("cnc_rdsrvspeed", |h| {
        one(4 * MAX_AXIS, |o| unsafe {
            cnc_rdsrvspeed(h, o.p::<c_long>())
        })
    }),
    ("cnc_rdcurrent", |h| {
        one(2 * MAX_AXIS, |o| unsafe { cnc_rdcurrent(h, o.p()) })
    }),
    ("cnc_rdspmaxrpm", |h| {
        one(size::<ODBSPN>(), |o| unsafe {
            cnc_rdspmaxrpm(h, -1, o.p())
        })
    }),
    ("cnc_rdspgear", |h| {
        one(size::<ODBSPN>(), |o| unsafe { cnc_rdspgear(h, -1, o.p()) })
    }),
    ("cnc_rdtofsinfo2", |h| {
        one(size::<ODBTLINF2>(), |o| unsafe {
            cnc_rdtofsinfo2(h, o.p())
        })
    }),
    ("pmc_get_number_of_pmc", |h| {
        one(4, |o| unsafe { pmc_get_number_of_pmc(h, o.p::<c_long>()) })
    }),
    ("pmc_get_pmc_unit_types", |h| {
        let mut count = Out::new(4);
        unsafe { count.p::<i32>().write_unaligned(4) };
        let mut types = Out::new(16);
        let r = unsafe { pmc_get_pmc_unit_types(h, types.p::<c_long>(), count.p::<c_long>()) };
        (r, vec![types, count])
    }),
    ("cnc_rdngrp", |h| {
        one(size::<ODBTLIFE2>(), |o| unsafe { cnc_rdngrp(h, o.p()) })
    }),
];

fn run_against(profile: Profile, seed: u64) {
    let port = hostile_cnc(profile, seed);
    let mut h = sim::connect(port);
    let mut codes = std::collections::BTreeMap::<&str, std::collections::BTreeSet<c_short>>::new();
    for round in 0..40 {
        for (name, probe) in PROBES {
            let (r, outs) = probe(h);
            assert_ne!(
                r, EW_UNEXP,
                "{name} (round {round}) panicked inside the library"
            );
            for (i, o) in outs.iter().enumerate() {
                assert!(o.intact(), "{name} (round {round}) wrote past output {i}");
            }
            codes.entry(name).or_default().insert(r);
            if r == EW_SOCKET {
                let _ = cnc_freelibhndl(h);
                // The hostile CNC may mutate the start-up answers too: a
                // refused start-up is fine, a few attempts get through.
                h = (0..20)
                    .find_map(|_| sim::try_connect(port).ok())
                    .expect("a reconnect to the hostile CNC succeeds");
            }
        }
    }
    sim::free(h);
    for (name, c) in &codes {
        println!("{name:20} {c:?}");
    }
    // The mutations reached the decoders: most functions saw both success
    // and an error (many read a short answer as FANUC's library does, so
    // the error is not always EW_PROTOCOL), and some saw EW_PROTOCOL.
    let both = codes
        .values()
        .filter(|c| c.contains(&EW_OK) && c.iter().any(|r| *r != EW_OK))
        .count();
    assert!(
        codes.values().any(|c| c.contains(&EW_PROTOCOL)),
        "no mutation reached a decoder's length checks: {codes:?}"
    );
    assert!(both * 2 > PROBES.len(), "mutations too mild: {codes:?}");
}

#[test]
fn a_hostile_30i_gets_codes_never_panics_or_overruns() {
    run_against(Profile::default(), 0x5eed_f0ca);
}

#[test]
fn a_hostile_16i_gets_codes_never_panics_or_overruns() {
    let text =
        fwlib32::sim::profile::DEFAULT_PROFILE.replacen("class = \"30i\"", "class = \"16i\"", 1);
    let p = Profile::parse(&text).expect("16i profile");
    run_against(p, 0x1615_eed0);
}

/// The arguments a header-driven call gets: integers `int`, those named
/// like a length `length`, a count `behind` in each pointed-to buffer.
#[derive(Debug, Clone, Copy)]
struct Recipe {
    int: i64,
    length: i64,
    behind: i64,
}

const RECIPES: [Recipe; 8] = [
    Recipe {
        int: 1,
        length: 4096,
        behind: 0,
    },
    Recipe {
        int: 1,
        length: 4096,
        behind: 4,
    },
    Recipe {
        int: 0,
        length: 4096,
        behind: 4,
    },
    Recipe {
        int: -1,
        length: 4096,
        behind: 4,
    },
    Recipe {
        int: 500,
        length: 10,
        behind: 4,
    },
    Recipe {
        int: 1320,
        length: 8,
        behind: 1,
    },
    Recipe {
        int: 1,
        length: 256,
        behind: 256,
    },
    Recipe {
        int: 0,
        length: 0,
        behind: 0,
    },
];

fn recipe_args(p: &cabi::Proto, h: c_ushort, r: Recipe) -> Vec<cabi::Arg> {
    p.params
        .iter()
        .map(|a| {
            if a.ptr {
                cabi::Arg::Ptr(Some(cabi::Buf::new(Some(r.behind))))
            } else if cabi::is_handle(a) {
                cabi::Arg::Int(i64::from(h))
            } else if a.name.contains("len") {
                cabi::Arg::Int(r.length)
            } else {
                cabi::Arg::Int(r.int)
            }
        })
        .collect()
}

/// `min_percent`: of the functions swept, how many at least must accept
/// some arguments on a plain simulator (the 16i class lacks many).
fn sweep_against(profile: Profile, seed: u64, min_percent: usize) {
    let lib = cabi::Lib::open();
    // The arguments: the first recipe each function accepts on a plain simulator.
    let plain = sim::start(profile.clone());
    let h = lib.alloc(plain.port(), 5).expect("a handle");
    let mut calls = Vec::new();
    for p in cabi::all_prototypes() {
        if !p.params.iter().any(cabi::is_handle)
            || cabi::SESSION.contains(&p.name.as_str())
            || cabi::fixed_answer(&p.name)
        {
            continue;
        }
        let r = RECIPES
            .iter()
            .copied()
            .find(|r| lib.invoke(&p, recipe_args(&p, h, *r)).0 == EW_OK);
        calls.push((p, r));
    }
    let _ = lib.free(h);
    let accepted = calls.iter().filter(|(_, r)| r.is_some()).count();
    if std::env::var_os("HOSTILE_LIST").is_some() {
        for (p, _) in calls.iter().filter(|(_, r)| r.is_none()) {
            println!("no arguments accepted: {}", p.name);
        }
    }
    println!(
        "{accepted} of {} functions found arguments they accept",
        calls.len()
    );
    assert!(
        accepted * 100 >= calls.len() * min_percent,
        "too few functions reach the CNC"
    );

    let port = hostile_cnc(profile, seed);
    let connect = || {
        (0..20)
            .find_map(|_| lib.alloc(port, 5).ok())
            .expect("a connection to the hostile CNC")
    };
    let mut h = connect();
    let mut codes =
        std::collections::BTreeMap::<String, std::collections::BTreeSet<c_short>>::new();
    for round in 0..20 {
        for (p, r) in &calls {
            let r = r.unwrap_or(RECIPES[0]);
            let (rc, intact, took) = lib.invoke(p, recipe_args(p, h, r));
            let what = format!("{} {r:?} (round {round})", p.name);
            assert_ne!(rc, EW_UNEXP, "{what} panicked inside the library");
            assert!((-17..=18).contains(&rc), "{what}: {rc}");
            assert!(intact, "{what} wrote past a buffer");
            assert!(
                took < std::time::Duration::from_secs(15),
                "{what} took {took:?}"
            );
            codes.entry(p.name.clone()).or_default().insert(rc);
            if rc == EW_SOCKET {
                let _ = lib.free(h);
                h = connect();
            }
        }
    }
    let _ = lib.free(h);
    let both = codes
        .values()
        .filter(|c| c.contains(&EW_OK) && c.iter().any(|r| *r != EW_OK))
        .count();
    println!(
        "{both} of {} functions saw both success and an error",
        codes.len()
    );
    assert!(both * 2 > accepted, "mutations too mild: {codes:?}");
}

#[test]
fn every_export_against_a_hostile_30i() {
    sweep_against(Profile::default(), 0x5eed_0e30, 70);
}

#[test]
fn every_export_against_a_hostile_16i() {
    let text =
        fwlib32::sim::profile::DEFAULT_PROFILE.replacen("class = \"30i\"", "class = \"16i\"", 1);
    sweep_against(Profile::parse(&text).expect("16i profile"), 0x5eed_0e16, 40);
}
