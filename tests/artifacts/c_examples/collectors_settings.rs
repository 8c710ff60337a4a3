//! tests/c/collectors_settings.c: cnc_rdmacronum through the .so, compared
//! with the simulator's custom macro variable names (`[path.macros.names]`).

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

#[test]
fn macro_numbers_follow_the_names() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let (kv, _sim) = run_c_test("collectors_settings", p.clone());
    let names = &p.paths[0].macros.names;
    let ok = |n: &str| {
        let (num, attr) = names
            .get(n)
            .unwrap_or_else(|| panic!("the default profile names no {n}"));
        format!("0,{num},{attr}")
    };
    assert_eq!(kv["num.gauge1"], ok("GAUGE1"));
    assert_eq!(kv["num.gauge1"], "0,500,0");
    assert_eq!(kv["num.count"], ok("COUNT"));
    assert_eq!(kv["num.count"], "0,100,1");
    assert_eq!(kv["num.nul"], ok("GAUGE1"));
    assert_eq!(kv["num.length"], ok("GAUGE1"));
    // Not a name of the path: EW_DATA, the outputs untouched.
    let refused = format!("{},0,-1", fwlib32::ew::EW_DATA);
    assert_eq!(kv["num.prefix"], refused);
    assert_eq!(kv["num.absent"], refused);
    // No NUL in 64 bytes: EW_DATA from the library, nothing asked.
    assert_eq!(kv["num.long"], refused);
}
