//! tests/c/collectors_pmcctl.c: the long-tail PMC control functions
//! (family C: control data groups, ladders, backup memory) through the .so, against the profile and the simulator's
//! state (a second connection reads what the first wrote).

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

#[test]
fn pmc_control_functions_follow_the_profile_and_state() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let [u1, u2] = [&p.pmc.info[0], &p.pmc.info[1]];
    assert_ne!(u1.control_group, 25, "the default profile's is another");
    assert_ne!(u1.exrelay_group, 9, "the default profile's is another");
    assert_ne!(u1.control_group, u2.control_group, "unit 2 has its own");
    let (kv, _sim) = run_c_test("collectors_pmcctl", p.clone());

    // pmc_rdcntlgrp / pmc_wrcntlgrp: 2001 refused (EW_DATA), 25 kept.
    assert_eq!(kv["cntlgrp"], u1.control_group.to_string());
    assert_eq!(kv["cntlgrp.set"], "25");
    assert_eq!(kv["wrcntlgrp.refused"], "5", "EW_DATA");
    assert_eq!(kv["cntlgrp.kept"], "25");

    // pmc_rdcntl_exrelay_grp / pmc_wrcntl_exrelay_grp: -1 refused.
    assert_eq!(kv["exrelay"], u1.exrelay_group.to_string());
    assert_eq!(kv["exrelay.set"], "9");
    assert_eq!(kv["wrexrelay.refused"], "5", "EW_DATA");

    // The machine's state, through another connection; unit 2 unchanged.
    assert_eq!(kv["cntlgrp.other"], "25");
    assert_eq!(kv["exrelay.other"], "9");
    assert_eq!(kv["cntlgrp.unit2"], u2.control_group.to_string());
    assert_eq!(kv["exrelay.unit2"], u2.exrelay_group.to_string());

    // pmc_kpmsiz: 4 bytes written (on LP64 the `unsigned long`'s high half
    // keeps the caller's bytes); pmc_get_number_of_ladder; per unit.
    assert_ne!(u1.kpm_size, u2.kpm_size, "the default profile's differ");
    assert_ne!(u1.ladders, u2.ladders, "the default profile's differ");
    assert_eq!(kv["kpmsiz.low"], u1.kpm_size.to_string());
    if std::mem::size_of::<std::ffi::c_ulong>() == 8 {
        assert_eq!(kv["kpmsiz.high"], 0xeeee_eeee_u32.to_string());
    }
    assert_eq!(kv["ladders"], u1.ladders.to_string());
    assert_eq!(kv["kpmsiz.unit2"], u2.kpm_size.to_string());
    assert_eq!(kv["ladders.unit2"], u2.ladders.to_string());
}
