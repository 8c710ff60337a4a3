//! tests/c/collectors_history_timers.c: the history counts, the real-time
//! macro counts and the panel's *2 functions through the .so; each write
//! read back from C and checked in the simulator (through a second
//! connection).

use super::run_c_test;
use fwlib32::native::{Cnc, PmcArea};
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use std::time::Duration;

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

#[test]
fn history_timer_and_panel_functions_follow_the_machine() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let (kv, sim) = run_c_test("collectors_history_timers", p.clone());
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(10)).unwrap();

    // The *3 counts are the older functions' (the machine may have added
    // alarms to the profile's history since it started).
    let alm = ints(&kv["almhisno"]);
    assert_eq!(alm[0], alm[1]);
    assert!(alm[1] >= p.alarm_history.entries.len() as i64);
    assert!(
        !p.alarm_history.entries.is_empty(),
        "set in the default profile"
    );
    let op = ints(&kv["ophisno"]);
    assert_eq!(op[0], op[1]);
    assert!(op[1] >= p.operation_history.entries.len() as i64);

    // cnc_rdhissgnl: the first 20 of the operation history's signals, as
    // cnc_rdhissgnl3 reads them.
    assert_eq!(kv["hissgnl.same"], "1");
    let s0 = &p.operation_history.signals[0];
    assert_eq!(
        kv["hissgnl.first"],
        format!("1,{},{},{};20", s0.number, s0.group, s0.mask)
    );

    // cnc_getmacaddress: the profile's digits, then the NUL; the 14th byte
    // untouched.
    assert_eq!(p.cnc.mac_address.len(), 12, "the default profile's");
    assert_eq!(kv["mac"], format!("{};85", p.cnc.mac_address));

    // The real-time macro variables: the path's [path.rt_macros].
    let rt = &p.paths[0].rt_macros;
    assert!(
        rt.volatile != 0 && rt.nonvolatile != 0,
        "set in the default profile"
    );
    assert_eq!(
        ints(&kv["rtmr"]),
        [i64::from(rt.volatile), i64::from(rt.nonvolatile)]
    );

    // cnc_wropnlgnrl2: switches 1 and 3 on, 2 and 4 off, then 8 on; both
    // reads and F0072 agree (cnc_rdopnlgnrl2 sign-extends the byte, as
    // FANUC's library does).
    assert_eq!(ints(&kv["gnrl2"]), [0xff, i64::from(0x85u8 as i8), 0x85]);
    let f72: Vec<u8> = cnc.pmc(PmcArea::F, 72..=72).unwrap();
    assert_eq!(f72, [0x85]);

    // cnc_rdopnlgsname2: the profile's names (unnamed ones empty);
    // cnc_wropnlgsname2 renamed switches 2 and 12 alone, 8 characters;
    // cnc_rdopnlgsname reads the same first names.
    let names = &p.operator_panel.switch_names;
    let name = |k: usize| names.get(k).cloned().unwrap_or_default();
    assert!(
        names.len() >= 3 && names.len() < 11,
        "the default profile's"
    );
    assert_eq!(
        kv["gsname2.before"],
        format!("-1;{}", [0, 1, 2, 3, 4, 15].map(name).join("|"))
    );
    assert_eq!(
        kv["gsname2.after"],
        format!("{}|TABLEAIR|{}||MIST", name(0), name(2))
    );
    assert_eq!(kv["gsname.after"], format!("{}|TABLEAIR", name(0)));
}
