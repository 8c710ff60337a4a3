//! tests/c/collectors_programs_macros.c: the 8-digit program functions
//! (cnc_searcho8, cnc_deleteo8, cnc_rdmdipntro8) and the P-code macro
//! variables (cnc_rdpmacroinfo) through the .so, compared with the
//! simulator's program store afterwards and the profile.

use super::run_c_test;
use fwlib32::native::Cnc;
use fwlib32::sim::Profile;
use std::time::Duration;

/// An idle path (nothing running, so a program can be selected) with
/// 8-digit programs, 50 P-code variables and 10 extended ones.
const PROFILE: &str = r#"
[[path]]
[path.pmacros]
ranges = [[10000, 10049], [20000, 20009]]
v2_type = 1
[[program]]
number = 12345678
text = "O12345678;\nN1 M30;\n"
[[program]]
number = 87654321
text = "O87654321;\nN1 M30;\n"
[[program]]
number = 1234
text = "O1234;\nN1 M30;\n"
"#;

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

#[test]
fn eight_digit_programs_follow_the_store() {
    let p = Profile::parse(PROFILE).expect("profile");
    let (kv, sim) = run_c_test("collectors_programs_macros", p);
    let (data, ok) = (fwlib32::ew::EW_DATA.to_string(), "0");
    assert_eq!(kv["searched.mdata"], "12345678");
    assert_eq!(kv["search_missing"], data);
    assert_eq!(
        kv["after_missing.mdata"], "12345678",
        "a refused search changes nothing"
    );
    assert_ne!(kv["search_missing"], ok);
    assert_eq!(kv["delete_again"], data);
    assert_eq!(kv["search_deleted"], data);
    assert_eq!(ints(&kv["mdipntro8"]), [0, 4321, 0, 4321]);
    assert_eq!(ints(&kv["pmacroinfo"]), [50, 10, 1]);
    // The store as another client sees it: 87654321 is gone, the others stay.
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5)).unwrap();
    let numbers: Vec<u32> = cnc.programs().unwrap().iter().map(|e| e.number).collect();
    assert_eq!(numbers, [1234, 12345678]);
}
