//! tests/c/collectors_magazine.c: the magazine and tool management family
//! through the .so, compared with the simulator's tool life state; the
//! writes (cnc_wrmagazine, cnc_wrtool, and the paging cnc_regmagazine,
//! cnc_delmagazine, cnc_regtool, cnc_regtool_f2) read back from C (cnc_rdmagazine,
//! cnc_rdtool) and checked in the simulator (through a second connection).

use super::run_c_test;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::IODBTLMNG;
use fwlib32::{cnc_allclibhndl3, cnc_freelibhndl, cnc_rdtool};
use std::ffi::CString;

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

/// The default profile, idle, with limits and a third tool in group 1
/// that no other profile value repeats, which is the T code in effect.
fn profile() -> Profile {
    let limits = "max_group = 128\nmax_tool = 16\n";
    let tools = "  { number = 11, length = 11, radius = 11, info = 0 },\n";
    let (cycle, t) = ("program = 1234 ", "108 = 1 }");
    assert!(
        [limits, tools, cycle, t]
            .iter()
            .all(|s| DEFAULT_PROFILE.contains(s)),
        "the default profile's tool life section, cycle or modal T moved"
    );
    let text = DEFAULT_PROFILE
        .replacen(limits, "max_group = 77\nmax_tool = 9\n", 1)
        .replacen(cycle, "program = 0 ", 1)
        .replacen(t, "108 = 23 }", 1)
        .replacen(
            tools,
            &format!("{tools}  {{ number = 23, length = 31, radius = 42, info = 6 }},\n"),
            1,
        );
    Profile::parse(&text).expect("profile")
}

#[test]
fn magazine_and_tool_data_follow_the_machine() {
    let p = profile();
    let (kv, sim) = run_c_test("collectors_magazine", p.clone());
    let path = &p.paths[0];
    assert_eq!(kv["maxgrp"], path.tool_life.max_group.to_string());
    assert_eq!(kv["maxtool"], path.tool_life.max_tool.to_string());
    // Idle: the group holding the profile's modal T (tool 23, group 1) is
    // next, in use and selected.
    assert_eq!(ints(&kv["usegrp"]), [1, 1, 1]);
    for g in path.tool_groups.iter().filter(|g| g.number <= 2) {
        for (k, t) in g.tools.iter().enumerate() {
            let n = k as i64 + 1;
            let want = |ty: i64| {
                vec![
                    i64::from(g.number),
                    ty,
                    i64::from(t.number),
                    i64::from(t.length),
                    i64::from(t.radius),
                    i64::from(t.info),
                ]
            };
            // cnc_rd1tlifedata leaves `type` untouched (0 before the call).
            assert_eq!(ints(&kv[&format!("rd1.{}.{n}", g.number)]), want(0));
            assert_eq!(ints(&kv[&format!("rd2.{}.{n}", g.number)]), want(n));
        }
        // Past the last tool: EW_NUMBER (3) from both.
        assert_eq!(
            kv[&format!("tools{}", g.number)],
            format!("{},3", g.tools.len())
        );
    }
    assert_eq!(path.tool_groups[0].tools.len(), 3);

    // cnc_wrmagazine: data number 2 went to magazine 2 pot 5; 999 was
    // refused (EW_NUMBER) and changed nothing; then data number 1 took
    // that pot and data number 2 left the magazine.
    let t = &path.managed_tools;
    assert_eq!((t[0].magazine, t[0].pot), (1, 1), "the profile's pots");
    assert_eq!(ints(&kv["mag.tool2"]), [2, 5]);
    assert_eq!(kv["mag.refused"], "3");
    assert_eq!(ints(&kv["mag.tool1"]), [1, 1]);
    assert_eq!(ints(&kv["mag.moved1"]), [2, 5]);
    assert_eq!(ints(&kv["mag.moved2"]), [0, 0]);

    // cnc_wrtool: what C wrote reads back (rest = life - counter); the
    // refused writes (life status 9: EW_DATA; data number 0: EW_NUMBER
    // before traffic) changed nothing.
    assert_eq!(
        ints(&kv["tool2"]),
        [4711, 7, 250, 243, 1, 21, -4, 2200, 333, 3, 9, -5, 20]
    );
    assert_eq!(kv["tool.refused"], "5");
    assert_eq!(kv["tool.refused_no"], "3");
    assert_eq!(ints(&kv["tool2.after"]), [4711, 1]);
    assert_eq!(managed(&sim, 2), (4711, 7, 250, 21, -4));

    // cnc_rdmagazine, 130 pots (two exchanges): magazine 2 pot 5 holds
    // data number 1, magazine 3 pot 9 data number 2 (where the writes above
    // put them), magazine 4's pots none; `*num` 0: EW_NUMBER, untouched.
    assert_eq!(ints(&kv["rdmag"]), [130, 2, 5, 1, 2, 0]);
    assert_eq!(ints(&kv["rdmag.num0"]), [3, 0]);
    // cnc_regmagazine: both pots registered, read back; the taken pot was
    // refused (EW_DATA, `*num` 0) and changed nothing.
    assert_eq!(kv["regmag"], "2");
    assert_eq!(ints(&kv["regmag.back"]), [2, 1, 0, 0]);
    assert_eq!(ints(&kv["regmag.refused"]), [5, 0]);
    assert_eq!(kv["regmag.after"], "2");
    // 150 pots in one call (118, then 32): data number 1 ends in the last.
    assert_eq!(ints(&kv["regmag.paged"]), [6, 150]);
    // cnc_delmagazine: both pots emptied; a pot 0 refused (EW_NUMBER).
    assert_eq!(kv["delmag"], "2");
    assert_eq!(ints(&kv["delmag.back"]), [0, 0]);
    assert_eq!(kv["delmag.refused"], "3");
    // cnc_regtool: data numbers 3..12 added (9, then 1 per exchange) and
    // read back; 20 (past the end) refused by the CNC, 0 before traffic
    // (EW_NUMBER both), nothing changed.
    assert_eq!(kv["regtool"], "10");
    assert_eq!(ints(&kv["regtool.back"]), [10, 100, 109, 59, 9, 10, 10]);
    assert_eq!(ints(&kv["regtool.refused"]), [3, 0]);
    assert_eq!(ints(&kv["regtool.refused0"]), [3, 1]);
    // The simulator's state, through a second connection: after the
    // writes above (data number 1 to magazine 2 pot 5, cnc_wrtool's 2 to
    // magazine 3 pot 9, both registered elsewhere), the pots deleted, the
    // tools registered.
    assert_eq!(pots(&sim), [(0, 0), (0, 0)]);
    assert_eq!(managed(&sim, 12), (109, 9, 59, 10, 0));
    // cnc_regtool_f2: data numbers 13..19 added (6, then 1), read back.
    assert_eq!(kv["regtool_f2"], "7");
    assert_eq!(ints(&kv["regtool_f2.back"]), [7, 200, 206, 2006]);
    assert_eq!(tool_count(&sim), 19);
    assert_eq!(managed(&sim, 19), (206, 0, 70, 0, 0));
}

/// How many entries the simulator's tool management data holds: the
/// number cnc_rdtool reads from data number 1 asking for 40.
fn tool_count(sim: &Simulator) -> i16 {
    let mut h = 0u16;
    let ip = CString::new("127.0.0.1").unwrap();
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), sim.port(), 10, &mut h) },
        0
    );
    let mut t = [IODBTLMNG::default(); 40];
    let mut num = 40i16;
    let rc = unsafe { cnc_rdtool(h, 1, &mut num, t.as_mut_ptr()) };
    assert_eq!(cnc_freelibhndl(h), 0);
    assert!(rc == 0 || rc == 3, "cnc_rdtool: {rc}");
    num
}

/// T code, life counter, life, H and D codes of tool management data
/// `n`, read by cnc_rdtool on a connection of its own.
fn managed(sim: &Simulator, n: i16) -> (i32, i32, i32, i16, i16) {
    let mut h = 0u16;
    let ip = CString::new("127.0.0.1").unwrap();
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), sim.port(), 10, &mut h) },
        0
    );
    let mut t = IODBTLMNG::default();
    let mut num = 1i16;
    assert_eq!(unsafe { cnc_rdtool(h, n, &mut num, &mut t) }, 0);
    assert_eq!(cnc_freelibhndl(h), 0);
    (t.T_code, t.life_count, t.max_life, t.H_code, t.D_code)
}

/// Magazine and pot of tool management data 1 and 2, read by cnc_rdtool
/// on a connection of its own.
fn pots(sim: &Simulator) -> Vec<(i16, i16)> {
    let mut h = 0u16;
    let ip = CString::new("127.0.0.1").unwrap();
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), sim.port(), 10, &mut h) },
        0
    );
    let v = (1..=2)
        .map(|n| {
            let mut t = IODBTLMNG::default();
            let mut num = 1i16;
            assert_eq!(unsafe { cnc_rdtool(h, n, &mut num, &mut t) }, 0);
            (t.magazine, t.pot)
        })
        .collect();
    assert_eq!(cnc_freelibhndl(h), 0);
    v
}
