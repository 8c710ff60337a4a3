//! tests/c/collectors_panel_system.c: the operator panel and system
//! functions through the .so; each write read back from C and checked in
//! the simulator (through a second connection).

use super::run_c_test;
use fwlib32::native::{Cnc, PmcArea};
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use std::time::Duration;

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

#[test]
fn panel_and_system_follow_the_machine() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let (kv, sim) = run_c_test("collectors_panel_system", p.clone());
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(10)).unwrap();

    // cnc_wropnlsgnl: what C wrote reads back (spindle override not
    // used), then the feed override alone; the refused write left it.
    assert_eq!(
        ints(&kv["panel.all"]),
        [1, 2, 3, 1, 0x1234, 100, 0, 1, 0, 1, 0, 1, 0]
    );
    assert_eq!(kv["panel.refused"], "5", "EW_DATA");
    assert_eq!(
        ints(&kv["panel.feed"]),
        [1, 2, 3, 1, 0x1234, 120, 0, 1, 0, 1, 0, 1, 0]
    );
    // The simulator's F bytes: F73 mode, F75 switches, F76 handle and
    // rapid, F77 handle axis, F78 feed override, F79-F80 jog override.
    let f: Vec<u8> = cnc.pmc(PmcArea::F, 73..=80).unwrap();
    assert_eq!(f, [0x01, 0x00, 0x54, 0x13, 0x02, 120, 0x34, 0x12]);

    // cnc_wropnlgnrl: switches 1 and 3 on, 2 and 4 off, then 8 on; F0072.
    assert_eq!(kv["gnrl.type_after"], "15", "type's low byte left");
    assert_eq!(ints(&kv["gnrl"]), [0xff, 0x85]);
    let f72: Vec<u8> = cnc.pmc(PmcArea::F, 72..=72).unwrap();
    assert_eq!(f72, [0x85]);

    // cnc_rdopnlgsname: the profile's switch names (unnamed ones empty);
    // cnc_wropnlgsname renamed switch 2 alone, 8 characters.
    let names = &p.operator_panel.switch_names;
    let name = |k: usize| names.get(k).cloned().unwrap_or_default();
    assert_eq!(
        kv["gsname.before"],
        (0..5).map(name).collect::<Vec<_>>().join("|")
    );
    assert_eq!(
        kv["gsname.after"],
        format!("{}|TABLEAIR|{}", name(0), name(2))
    );

    // cnc_rdsetnum: the profile's parameters up to [param] setting_max.
    let set: Vec<i32> = (p.param.parameters.iter())
        .map(|e| e.number)
        .filter(|n| *n <= p.param.setting_max)
        .collect();
    assert!(set.len() >= 2, "the default profile has setting parameters");
    assert_eq!(
        kv["setnum"],
        format!("{},{},{}", set[0], set[set.len() - 1], set.len())
    );
}
