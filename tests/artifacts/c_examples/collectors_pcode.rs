//! tests/c/collectors_pcode.c: cnc_rdpmacroinfo2 and cnc_rdpmacro through
//! the .so, compared with the simulator's P-code variable store.

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

/// The default profile with more P-code variables (#10000-#10199 and the
/// extended #20000-#20049) and a type for each range.
fn profile() -> Profile {
    let p = "[path.pmacros]\nranges = [[10000, 10099]]\nprotected = []\nv2_type = 0\nv1_type = 0\nv20_type = 0\n";
    assert!(
        DEFAULT_PROFILE.contains(p),
        "the default profile's [path.pmacros] moved"
    );
    let text = DEFAULT_PROFILE.replace(
        p,
        "[path.pmacros]\nranges = [[10000, 10199], [20000, 20049]]\nprotected = []\nv2_type = 2\nv1_type = 1\nv20_type = 3\n",
    );
    Profile::parse(&text).expect("profile")
}

#[test]
fn pcode_reads_follow_the_store() {
    let p = profile();
    let (kv, _sim) = run_c_test("collectors_pcode", p.clone());
    let pm = &p.paths[0].pmacros;
    assert_eq!(
        kv["pmacroinfo2"],
        format!("200,50,0,{},{},{}", pm.v1_type, pm.v2_type, pm.v20_type)
    );
    assert_eq!(kv["pmacroinfo2"], "200,50,0,1,2,3");
    for n in 10000..=10002 {
        let (v, d) = pm.vars.values.get(&n).copied().unwrap_or((0, -1));
        assert_eq!(kv[&format!("pmacro.{n}")], format!("{n},{v},{d}"));
    }
    // The profile's "12.5" and "-3"; #10002 vacant.
    assert_eq!(kv["pmacro.10000"], "10000,125,1");
    assert_eq!(kv["pmacro.10001"], "10001,-3,0");
    assert_eq!(kv["pmacro.10002"], "10002,0,-1");
    assert_eq!(kv["pmacro.absent"], fwlib32::ew::EW_NUMBER.to_string());
}
