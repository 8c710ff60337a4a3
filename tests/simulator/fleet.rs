//! A fleet: many machines from one simulator (one tokio runtime), each
//! with its own port, state, program clock and CNC id, read through the
//! C API. The clock is frozen, so every answer is fixed. (tests/tools/sim_cli.rs
//! counts the threads of a large fleet.)

use fwlib32::ew::*;
use fwlib32::sim::{Fleet, FleetOptions, Profile};
use fwlib32::types::{ODBM, ODBSEQ};
use fwlib32::*;
use std::collections::BTreeSet;
use std::ffi::CString;
use std::os::raw::{c_ulong, c_ushort};
use std::time::Duration;

fn connect(port: u16) -> c_ushort {
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h = 0;
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), port, 5, &mut h) },
        EW_OK
    );
    h
}

fn cnc_id(h: c_ushort) -> [u32; 4] {
    let mut id = [0u32; 4];
    assert_eq!(
        unsafe { cnc_rdcncid(h, id.as_mut_ptr().cast::<c_ulong>()) },
        EW_OK
    );
    id
}

fn seq(h: c_ushort) -> i32 {
    let mut s = ODBSEQ::default();
    assert_eq!(unsafe { cnc_rdseqnum(h, &mut s) }, EW_OK);
    s.data
}

fn macro_var(h: c_ushort, n: i16) -> (i32, i16) {
    let mut m = ODBM::default();
    assert_eq!(unsafe { cnc_rdmacro(h, n, 10, &mut m) }, EW_OK);
    (m.mcr_val, m.dec_val)
}

#[test]
fn fifty_machines_answer_independently() {
    const N: usize = 50;
    let fleet = Fleet::start(
        &[Profile::default()],
        "127.0.0.1:0",
        FleetOptions {
            machines: Some(N),
            worker_threads: Some(2),
            ..FleetOptions::default()
        },
    )
    .expect("fleet");
    assert_eq!(fleet.len(), N);
    let ports: BTreeSet<u16> = (0..N).map(|i| fleet.port(i)).collect();
    assert_eq!(ports.len(), N, "a port each");

    fleet.set_elapsed(Duration::from_secs(100));
    let handles: Vec<c_ushort> = (0..N).map(|i| connect(fleet.port(i))).collect();
    for i in 0..N {
        assert_eq!(fleet.sessions(i), 1);
    }
    let base = Profile::default().cnc.cnc_id;
    let ids: Vec<[u32; 4]> = handles.iter().map(|&h| cnc_id(h)).collect();
    for (i, id) in ids.iter().enumerate() {
        assert_eq!(id[..3], base[..3]);
        assert_eq!(id[3], base[3] + i as u32, "machine {}", i + 1);
    }
    // Each machine's program is at its own block (its own phase and speed).
    let seqs: Vec<i32> = handles.iter().map(|&h| seq(h)).collect();
    let distinct: BTreeSet<i32> = seqs.iter().copied().collect();
    assert!(distinct.len() >= 5, "sequence numbers {seqs:?}");
    // A frozen clock: the same answers again.
    assert_eq!(handles.iter().map(|&h| seq(h)).collect::<Vec<_>>(), seqs);

    // State is per machine: a macro variable written on one is not on the others.
    let before: Vec<(i32, i16)> = handles.iter().map(|&h| macro_var(h, 500)).collect();
    assert_eq!(unsafe { cnc_wrmacro(handles[6], 500, 10, 4242, 1) }, EW_OK);
    for (i, &h) in handles.iter().enumerate() {
        let want = if i == 6 { (4242, 1) } else { before[i] };
        assert_eq!(macro_var(h, 500), want, "machine {}", i + 1);
    }
    for h in handles {
        assert_eq!(cnc_freelibhndl(h), EW_OK);
    }
}

#[test]
fn machines_cycle_through_the_profiles_or_take_their_own_counts() {
    let mill = Profile::default();
    let lathe = Profile::parse(
        "[cnc]\nclass = \"16i\"\ncnc_id = [1, 2, 3, 100]\n[fleet]\nmachines = 2\n\
         [[path]]\nmachine = \"lathe\"\n",
    )
    .unwrap();
    let fleet = Fleet::start(
        &[mill.clone(), lathe.clone()],
        "127.0.0.1:0",
        FleetOptions::default(),
    )
    .unwrap();
    // Without --fleet: 1 mill (its default count), then the lathe's 2.
    assert_eq!(fleet.len(), 3);
    let ids: Vec<u32> = (0..3).map(|i| cnc_id(connect(fleet.port(i)))[3]).collect();
    assert_eq!(ids, vec![mill.cnc.cnc_id[3], 101, 102]);
    let fleet = Fleet::start(
        &[mill, lathe],
        "127.0.0.1:0",
        FleetOptions {
            machines: Some(4),
            ..FleetOptions::default()
        },
    )
    .unwrap();
    let ids: Vec<u32> = (0..4).map(|i| cnc_id(connect(fleet.port(i)))[3]).collect();
    assert_eq!(ids[1], 101);
    assert_eq!(ids[3], 103);
}

#[test]
fn bad_fleets_are_refused() {
    let p = Profile::default();
    let opts = |n| FleetOptions {
        machines: Some(n),
        ..FleetOptions::default()
    };
    assert!(Fleet::start(std::slice::from_ref(&p), "127.0.0.1:0", opts(0)).is_err());
    let faulty = Profile::parse("[[path]]\n[[fault]]\nkind = \"off\"\nmachines = [3]\n").unwrap();
    let e = Fleet::start(&[faulty], "127.0.0.1:0", opts(2))
        .err()
        .expect("machine 3 of 2");
    assert!(e.to_string().contains("machine 3"), "{e}");
    assert!(Fleet::start(&[p], "127.0.0.1:65535", opts(2)).is_err());
}
