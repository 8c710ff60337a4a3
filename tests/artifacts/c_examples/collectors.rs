//! tests/c/collectors.c: cnc_rdprgnumo8, cnc_rdspcss, cnc_rdtlinfo and
//! cnc_rdopnlsgnl through the .so, compared with the simulator's state.

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

/// The default profile with the software operator panel's F bytes set
/// (F73 mode, F75 switches, F76 handle / rapid, F77 handle axis, F78 feed
/// override, F79-F80 jog override).
fn profile() -> Profile {
    let f = "data = { 0 = [0x20] }";
    assert!(
        DEFAULT_PROFILE.contains(f),
        "the default profile's F area moved"
    );
    let text = DEFAULT_PROFILE.replace(
        f,
        "data = { 0 = [0x20], 73 = [0x01, 0x00, 0x3c, 0x12, 0x05, 0x9b, 0x64, 0x00] }",
    );
    Profile::parse(&text).expect("profile")
}

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

#[test]
fn collector_reads_follow_the_machine() {
    let p = profile();
    let (kv, _sim) = run_c_test("collectors", p.clone());
    let path = &p.paths[0];
    // The main program is the one in cycle; the running one is it or a
    // program it called.
    assert_eq!(kv["prgnumo8.mdata"], path.cycle.program.to_string());
    let running: i32 = kv["prgnumo8.data"].parse().unwrap();
    assert!(
        p.programs.iter().any(|q| q.number == running),
        "running program {running} is in memory"
    );
    let t = path.tool_life;
    assert_eq!(
        ints(&kv["tlinfo"]),
        [t.max_group, t.max_tool, t.max_minute, t.max_cycle].map(i64::from)
    );
    // No G96 in force: the surface speed is 0; the maximum spindle speed
    // is parameter 3772's.
    assert_eq!(kv["css.sspm"], "0");
    assert!(kv["css.smax"].parse::<i32>().unwrap() >= 0);
    // The panel's signals decoded from the F bytes as FANUC documents them.
    let f = ints(&kv["f73_80"]);
    assert_eq!(f, [0x01, 0x00, 0x3c, 0x12, 0x05, 0x9b, 0x64, 0x00]);
    let (f73, f75, f76, f77, f78) = (f[0], f[2], f[3], f[4], f[5]);
    let jog = (f[6] | f[7] << 8) as u16 as i16 as i64;
    let bit = |b: u32| (f75 >> b) & 1;
    assert_eq!(
        ints(&kv["panel"]),
        [
            0x1fff,
            f73 & 0x17,
            f77 & 0x0f,
            f76 & 0x03,
            (f76 >> 4) & 0x03,
            jog,
            f78,
            bit(2),
            bit(3),
            bit(4),
            bit(5),
            bit(6),
            bit(7)
        ]
    );
}
