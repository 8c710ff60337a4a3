//! tests/c/collectors_3dhandle.c: cnc_rd3dtooltip through the .so,
//! compared with the simulator's state.

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

/// The default profile with path 1 idle (no program in cycle): the axes
/// stay where the profile puts them.
fn idle() -> Profile {
    let cycle = "program = 1234           # O number in cycle (0 = idle)";
    assert!(
        DEFAULT_PROFILE.contains(cycle),
        "the default profile's cycle moved"
    );
    Profile::parse(&DEFAULT_PROFILE.replace(cycle, "program = 0")).expect("profile")
}

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

/// The 0x5a filler of an element not written, as the C program prints it.
const FILL16: i64 = 0x5a5a;
const FILL32: i64 = 0x5a5a_5a5a;

#[test]
fn tool_tip_follows_the_axes_and_needs_the_option() {
    let p = idle();
    let axes = &p.paths[0].axes;
    assert!(
        !axes.is_empty() && axes.len() < 5,
        "the test expects 1..4 axes"
    );
    let (kv, _sim) = run_c_test("collectors_3dhandle", p.clone());
    assert_eq!(kv["rc"], "0");
    let n = axes.len();
    let mut want_axes: Vec<i64> = (1..=n as i64).collect();
    want_axes.resize(5, FILL16);
    assert_eq!(ints(&kv["axes"]), want_axes);
    let mut want_data: Vec<i64> = axes.iter().map(|a| i64::from(a.absolute)).collect();
    want_data.resize(5, FILL32);
    assert_eq!(ints(&kv["data"]), want_data);
    assert_eq!(kv["null"], fwlib32::ew::EW_DATA.to_string());

    // Without the FOCAS option: EW_NOOPT, nothing written. (One test: the
    // two runs share the C program's build.)
    let mut p = idle();
    p.cnc.option = 0;
    let (kv, sim) = run_c_test("collectors_3dhandle", p);
    assert_eq!(kv["rc"], fwlib32::ew::EW_NOOPT.to_string());
    assert_eq!(ints(&kv["axes"]), [FILL16; 5]);
    assert_eq!(ints(&kv["data"]), [FILL32; 5]);
    drop(sim);
}
