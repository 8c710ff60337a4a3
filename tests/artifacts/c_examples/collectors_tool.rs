//! tests/c/collectors_tool.c: the tool life, tool offset and compensation
//! reads of family B and cnc_clrtofs through the .so, compared with the
//! simulator's state.

use super::run_c_test;
use fwlib32::ew::EW_ATTRIB;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::ODBTOFS;
use fwlib32::{cnc_allclibhndl3, cnc_freelibhndl, cnc_rdtofs};
use std::ffi::CString;

/// The default profile with group 1's second tool's H, D and information
/// apart, B-axis offsets, and G18 G41 D3 in effect (the profile's modal
/// codes, no program in cycle).
fn profile() -> Profile {
    let edits = [
        (
            "{ number = 11, length = 11, radius = 11, info = 0 }",
            "{ number = 11, length = 12, radius = 13, info = 2 }",
        ),
        ("b_axis = 0 ", "b_axis = 4 "),
        ("b_cancel = 0 ", "b_cancel = 9 "),
        ("g = [1, 0, 0, 0, 0, 1, 0, ", "g = [1, 1, 0, 0, 0, 1, 1, "),
        ("aux = { 101 = 1,", "aux = { 101 = 3,"),
        // No program in cycle: the modal codes are the profile's.
        ("program = 1234           #", "program = 0              #"),
    ];
    let mut text = DEFAULT_PROFILE.to_string();
    for (from, to) in edits {
        assert!(text.contains(from), "the default profile lacks {from}");
        text = text.replacen(from, to, 1);
    }
    Profile::parse(&text).expect("profile")
}

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

/// Offset 3's types 0..4 as cnc_rdtofsr reads them on a connection of its
/// own.
fn offset3(sim: &Simulator) -> Vec<i64> {
    let mut h = 0u16;
    let ip = CString::new("127.0.0.1").unwrap();
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), sim.port(), 10, &mut h) },
        0
    );
    let v = (0..4)
        .map(|t| {
            let mut o = ODBTOFS::default();
            assert_eq!(unsafe { cnc_rdtofs(h, 3, t, 8, &mut o) }, 0);
            i64::from(o.data)
        })
        .collect();
    assert_eq!(cnc_freelibhndl(h), 0);
    v
}

#[test]
fn tool_life_and_offset_reads_follow_the_machine() {
    let p = profile();
    let (kv, sim) = run_c_test("collectors_tool", p.clone());
    let path = &p.paths[0];
    let g1 = &path.tool_groups[0];
    let t = &g1.tools[1];
    let g = i64::from(g1.number);
    let (tno, h, d, inf) = (
        i64::from(t.number),
        i64::from(t.length),
        i64::from(t.radius),
        i64::from(t.info),
    );
    assert_eq!((h, d, inf), (12, 13, 2), "the profile's edits");
    // The 0x4f forms: type is the tool's number; the 0x4d forms: the use
    // number asked for.
    assert_eq!(ints(&kv["rd1length"]), [g, tno, h]);
    assert_eq!(ints(&kv["rd1radius"]), [g, tno, d]);
    assert_eq!(ints(&kv["t1info"]), [g, tno, inf]);
    assert_eq!(ints(&kv["rd2length"]), [g, 2, h]);
    assert_eq!(ints(&kv["rd2radius"]), [g, 2, d]);
    assert_eq!(ints(&kv["t2info"]), [g, 2, inf]);
    // dummy and type untouched.
    assert_eq!(ints(&kv["rd1tlifedat2"]), [g, 77, 88, tno, h, d, inf]);
    let g2 = &path.tool_groups[1];
    assert_eq!(g2.tools[0].number, 5);
    assert_eq!(ints(&kv["rdgrpid"]), [77, 5, i64::from(g2.number)]);

    let o = &path.offset;
    assert_eq!(kv["rdtofsenbl"], o.enable.to_string());
    assert_eq!(
        ints(&kv["rdtldata"]),
        [o.tl, o.decimals.into()].map(i64::from)
    );
    assert_ne!(o.tl, 0);
    // T, M and H in effect (the profile's modal codes), H's length
    // geometry.
    let aux = |k: &str| i64::from(path.modal.aux[k]);
    let hno = aux("104");
    let hm = i64::from(o.tool[hno as usize - 1][3]);
    assert_eq!(
        ints(&kv["rdtlmsinfo"]),
        [aux("108"), aux("106"), hm, o.decimals.into(), hno]
    );
    assert_eq!(
        ints(&kv["rdbtofsinfo"]),
        [o.memory, o.b_axis, o.b_cancel].map(i64::from)
    );
    assert_eq!((o.b_axis, o.b_cancel), (4, 9));
    // G18 G41 D3: the plane Z, X; the tool moving along Z is offset by D3's
    // radius (geometry + wear) along +X.
    let r = i64::from(o.tool[2][0] + o.tool[2][1]);
    assert_eq!(r, 7995);
    assert_eq!(ints(&kv["rdradofs"]), [1, 3, 1, 0, r]);
    assert_eq!(ints(&kv["rd3dtofs"]), [1, 1, 2, 3, r, 0, 0]);

    // cnc_clrtofs(1) cleared radius geometry only; type 9 refused, nothing
    // changed; the simulator holds what C read back.
    let before = [o.tool[2][0], o.tool[2][1], o.tool[2][3]].map(i64::from);
    assert_eq!(ints(&kv["before"]), before);
    assert_eq!(ints(&kv["after"]), [before[0], 0, before[2]]);
    assert_eq!(kv["clrtofs.refused"], EW_ATTRIB.to_string());
    assert_eq!(ints(&kv["refused"]), [before[0], 0, before[2]]);
    assert_eq!(kv["rdradofs.cleared"], o.tool[2][0].to_string());
    assert_eq!(
        offset3(&sim),
        [o.tool[2][0], 0, o.tool[2][2], o.tool[2][3]].map(i64::from)
    );
}
