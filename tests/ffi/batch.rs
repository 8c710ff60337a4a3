//! Call batching (fwlib32_ext.h): every batchable function, batched, gives
//! the outputs and return code of the same call made alone against the
//! same CNC state; many calls go in few frames; what may not join a batch
//! is refused without traffic; the default frame limits are the largest
//! FANUC's library was recorded sending.

use crate::cases;
use crate::probe;
use crate::profiles;
use crate::sim;
use crate::toolchain;

use fwlib32::client::batch::default_limits;
use fwlib32::ew::*;
use fwlib32::proto::open::CncClass;
use fwlib32::sim::Simulator;
use fwlib32::types::*;
use fwlib32::*;
use probe::{Answer, Probe};
use std::collections::BTreeSet;
use std::os::raw::{c_long, c_short};
use std::path::PathBuf;
use std::time::Duration;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Without the fields a batch adds (r0.., the queued calls' codes).
fn own_fields(fields: &[(String, i64)]) -> Vec<(String, i64)> {
    fields
        .iter()
        .filter(|(k, _)| !(k.starts_with('r') && k[1..].parse::<u32>().is_ok()))
        .cloned()
        .collect()
}

/// Words that are no call on a connected handle.
const NOT_ON_A_HANDLE: &[&str] = &[
    "alloc",
    "alloc4",
    "allclibhdl3",
    "allclibhndl",
    "free",
    "exitprocess",
    "startup",
    "resetconnect",
    "thread_alloc",
    "thread_free",
    "thread_statinfo",
    "slot",
    "seth",
];

/// Every probe word, on each class, with its generated argument lists:
/// queued in a batch (fwlib_batch_begin, the call, fwlib_batch_end), then
/// called alone, on a simulator whose clock stands still. A call the batch
/// took gives the same return code, in-out counts and buffers as alone; one
/// it refused answered EW_REJECT at once. The functions it took are the
/// README's batchable list.
#[test]
fn every_batchable_call_batched_equals_the_call_alone() {
    let lib = toolchain::cdylib();
    let probe_dir = toolchain::scratch("batch-probe"); // removed when the test ends
    let probe_exe = probe::build(&root(), &probe_dir);
    let words = cases::words();
    let (mut took, mut refused) = (BTreeSet::new(), BTreeSet::new());
    let mut differ = Vec::new();
    // One simulator (clock standing still) and probe per profile.
    let mut running = std::collections::BTreeMap::new();
    for class in ["v3", "v2", "s15"] {
        for w in &words {
            if !w.setup.is_empty()
                || NOT_ON_A_HANDLE.contains(&w.word)
                || w.word.starts_with("fwlib_")
            {
                continue;
            }
            let function = cases::function(w.word);
            let profile = cases::class_profile(w.word, class);
            let (_, p) = running.entry(profile).or_insert_with(|| {
                let s = Simulator::start(profiles::profile(profile), "127.0.0.1:0").unwrap();
                s.set_elapsed(Duration::from_millis(2500));
                let mut p = Probe::spawn(toolchain::target_command(&probe_exe), &lib, s.port());
                assert!(matches!(p.call("alloc 10"), Answer::Done { ret: 0, .. }));
                (s, p)
            });
            for (_, args) in cases::arg_lists(w) {
                let cmd = if args.is_empty() {
                    w.word.to_string()
                } else {
                    format!("{} {args}", w.word)
                };
                assert!(matches!(
                    p.call("fwlib_batch_begin"),
                    Answer::Done { ret: 0, .. }
                ));
                let queued = p.call(&cmd);
                let end = p.call("fwlib_batch_end");
                let Answer::Done { ret: qret, .. } = queued else {
                    differ.push(format!("{profile} `{cmd}` queued: {queued:?}"));
                    continue;
                };
                let Answer::Done {
                    ret: 0,
                    fields: ef,
                    b0: eb0,
                    b1: eb1,
                } = &end
                else {
                    differ.push(format!("{profile} `{cmd}`: fwlib_batch_end {end:?}"));
                    continue;
                };
                let code = ef.iter().find(|(k, _)| k == "r0").map(|(_, v)| *v);
                if code.is_none() && qret == i64::from(EW_REJECT) {
                    refused.insert(function.clone());
                    continue;
                }
                let alone = p.call(&cmd);
                let Answer::Done {
                    ret,
                    fields,
                    b0,
                    b1,
                } = &alone
                else {
                    differ.push(format!("{profile} `{cmd}` alone: {alone:?}"));
                    continue;
                };
                if code.is_some() || qret == 0 {
                    took.insert(function.clone());
                }
                let same = match code {
                    // Queued: its code and outputs come at the batch's end.
                    Some(code) => {
                        qret == 0
                            && code == *ret
                            && own_fields(ef) == own_fields(fields)
                            && eb0 == b0
                            && eb1 == b1
                    }
                    // Answered at once, as alone: a local check refused it,
                    // or its answer is local (cnc_getdtailerr ...).
                    None => qret == *ret,
                };
                if !same {
                    differ.push(format!("{profile} `{cmd}`:\n  queued  {queued:?}\n  end     {end:?}\n  alone   {alone:?}"));
                }
            }
        }
    }
    for (_, (_, p)) in running {
        p.finish();
    }
    assert!(
        differ.is_empty(),
        "{} differ:\n{}",
        differ.len(),
        differ.join("\n")
    );
    let both: Vec<_> = took.intersection(&refused).collect();
    assert!(both.is_empty(), "taken and refused: {both:?}");
    assert!(refused.contains("cnc_wrparam") && refused.contains("cnc_rdparar"));
    // docs/functions.md names the hand-written ones; the described reads are all in.
    let described: BTreeSet<String> = fwlib32::spec::FUNCS
        .iter()
        .filter(|f| f.outs().next().is_some())
        .map(|f| f.name.to_string())
        .collect();
    let readme = std::fs::read_to_string(root().join("docs/functions.md")).unwrap();
    let listed = readme
        .split("(src/spec/table/) and ")
        .nth(1)
        .and_then(|t| t.split(" (src/ffi").next())
        .expect("docs/functions.md: the batchable list");
    let listed: BTreeSet<String> = listed
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|w| w.starts_with("cnc_") || w.starts_with("pmc_"))
        .map(str::to_string)
        .collect();
    let hand: BTreeSet<String> = took.difference(&described).cloned().collect();
    assert_eq!(
        listed, hand,
        "docs/functions.md's batchable list vs the functions a batch took"
    );
    assert!(
        took.len() >= 60,
        "only {} functions taken: {took:?}",
        took.len()
    );
}

fn statinfo(h: u16) -> (i16, ODBST) {
    let mut st = ODBST::default();
    (unsafe { cnc_statinfo(h, &mut st) }, st)
}

/// 20 cnc_statinfo calls (3 subpackets each) in one batch: 4 frames of at
/// most 16 subpackets on a 30i, and each output as read alone.
#[test]
fn many_calls_go_in_few_frames() {
    let s = sim::start(profiles::profile("v3"));
    s.set_elapsed(Duration::from_millis(2500));
    let h = sim::alloc(&s);
    let alone: Vec<(i16, ODBST)> = (0..20).map(|_| statinfo(h)).collect();
    let mut out = vec![ODBST::default(); 20];
    let before = s.data_frames();
    assert_eq!(fwlib_batch_begin(h), EW_OK);
    assert_eq!(fwlib_batch_begin(h), EW_BUSY);
    for o in out.iter_mut() {
        assert_eq!(unsafe { cnc_statinfo(h, o) }, EW_OK);
    }
    assert_eq!(s.data_frames(), before, "nothing sent while queueing");
    let mut codes = [0x7fff_i16; 20];
    assert_eq!(
        unsafe { fwlib_batch_end(h, codes.as_mut_ptr(), 19) },
        EW_LENGTH
    );
    assert_eq!(unsafe { fwlib_batch_end(h, codes.as_mut_ptr(), 20) }, EW_OK);
    // 5 calls (15 subpackets) a frame of at most 16.
    assert_eq!(s.data_frames() - before, 4);
    assert_eq!(codes, [EW_OK; 20]);
    for (a, b) in alone.iter().zip(&out) {
        assert_eq!(format!("{:?}", a.1), format!("{b:?}"));
    }
    // Smaller limits: more frames; a call larger than them goes alone.
    assert_eq!(fwlib_batch_limits(h, 2, 4000), EW_OK);
    assert_eq!(fwlib_batch_limits(h, 0, 4000), EW_LENGTH);
    assert_eq!(fwlib_batch_begin(h), EW_OK);
    for o in out.iter_mut().take(3) {
        assert_eq!(unsafe { cnc_statinfo(h, o) }, EW_OK);
    }
    let before = s.data_frames();
    assert_eq!(unsafe { fwlib_batch_end(h, codes.as_mut_ptr(), 3) }, EW_OK);
    assert_eq!(s.data_frames() - before, 3);
    assert_eq!(
        unsafe { fwlib_batch_end(h, codes.as_mut_ptr(), 3) },
        EW_FUNC,
        "no batch"
    );
    sim::free(h);
}

/// While a handle batches, calls that cannot join return EW_REJECT without
/// traffic; local errors of batchable calls come at once; another handle
/// is not affected.
#[test]
fn what_cannot_join_is_refused_without_traffic() {
    let s = sim::start(profiles::profile("v3w"));
    s.set_elapsed(Duration::from_millis(2500));
    let h = sim::alloc(&s);
    let other = sim::alloc(&s);
    assert_eq!(fwlib_batch_begin(h), EW_OK);
    let before = s.data_frames();
    let mut p = IODBPSD::default();
    // A write, a transfer, a read that needs an earlier answer, a path change.
    assert_eq!(unsafe { cnc_wrparam(h, 8, &mut p) }, EW_REJECT);
    assert_eq!(cnc_upstart3(h, 0, 1, 1), EW_REJECT);
    assert_eq!(cnc_dwnstart3(h, 0), EW_REJECT);
    assert_eq!(cnc_setpath(h, 1), EW_REJECT);
    let mut len: c_short = 0;
    assert_eq!(
        unsafe { cnc_rdprogdir2(h, 0, &mut len, &mut len, std::ptr::null_mut()) },
        EW_REJECT
    );
    // A batchable call's local check, at once.
    let null = unsafe { cnc_statinfo(other, std::ptr::null_mut()) };
    assert_ne!(null, EW_OK);
    assert_eq!(unsafe { cnc_statinfo(h, std::ptr::null_mut()) }, null);
    // The other handle goes on.
    assert_eq!(statinfo(other).0, EW_OK);
    assert_eq!(
        s.data_frames() - before,
        1,
        "the other handle's statinfo only"
    );
    let mut blk: c_long = 0;
    assert_eq!(unsafe { cnc_rdblkcount(h, &mut blk) }, EW_OK);
    let mut codes = [0_i16; 1];
    assert_eq!(unsafe { fwlib_batch_end(h, codes.as_mut_ptr(), 1) }, EW_OK);
    assert_eq!(codes, [EW_OK]);
    // Freed in the middle of a batch: its calls are dropped with it.
    assert_eq!(fwlib_batch_begin(other), EW_OK);
    assert_eq!(unsafe { cnc_rdblkcount(other, &mut blk) }, EW_OK);
    sim::free(other);
    sim::free(h);
}

/// The default limits are the largest frames FANUC's library was recorded
/// sending for each class (tests/vectors).
#[test]
fn default_limits_are_the_largest_recorded() {
    let mut most = std::collections::BTreeMap::<&str, (usize, usize)>::new();
    for e in std::fs::read_dir(root().join("tests/vectors")).unwrap() {
        let text = std::fs::read_to_string(e.unwrap().path()).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        for case in v["cases"].as_array().into_iter().flatten() {
            let class = match case["profile"].as_str().unwrap_or("") {
                p if p.starts_with("s15") => "s15",
                p if p.starts_with("v2") => "16i",
                _ => "30i",
            };
            for call in case["calls"].as_array().into_iter().flatten() {
                for f in call["frames"].as_array().into_iter().flatten() {
                    let hex = f["hex"].as_str().unwrap_or("");
                    if f["dir"] != "req" || hex.len() < 24 || &hex[12..16] != "2101" {
                        continue;
                    }
                    let body = (hex.len() - 20) / 2;
                    let subs = usize::from_str_radix(&hex[20..24], 16).unwrap();
                    let m = most.entry(class).or_default();
                    *m = (m.0.max(subs), m.1.max(body));
                }
            }
        }
    }
    let lim = |c| {
        let l = default_limits(c);
        (l.subpackets, l.body)
    };
    assert_eq!(most["30i"], lim(CncClass::Series30));
    assert_eq!(most["16i"], lim(CncClass::Series16 { kind: 1 }));
    assert_eq!(most["s15"], lim(CncClass::Series16 { kind: 2 }));
}
