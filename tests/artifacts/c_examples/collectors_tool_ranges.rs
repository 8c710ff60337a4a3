//! tests/c/collectors_tool_ranges.c: the tool life group reads by range
//! and by count, the offsets' ranges and the tool data writes through the
//! .so, compared with the simulator's state.

use super::run_c_test;
use fwlib32::ew::{EW_ATTRIB, EW_DATA, EW_LENGTH, EW_NUMBER};
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

/// The default profile with group 2's life used up (its tools to be
/// exchanged) and group 2 given an optional group number.
fn profile() -> Profile {
    let edits = [
        ("count = 498", "count = 500"),
        ("count_type = 0\n", "count_type = 0\noptional = 202\n"),
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

#[test]
fn tool_life_ranges_offset_ranges_and_tool_writes_follow_the_machine() {
    let p = profile();
    let (kv, _sim) = run_c_test("collectors_tool_ranges", p.clone());
    let path = &p.paths[0];
    let (g1, g2) = (&path.tool_groups[0], &path.tool_groups[1]);
    let n = |g: &fwlib32::sim::profile::offset::ToolGroupProfile| g.tools.len() as i64;
    assert_eq!(
        ints(&kv["rdtoolrng"]),
        [
            1,
            2,
            n(g1),
            g1.life.into(),
            g1.count.into(),
            n(g2),
            g2.life.into(),
            g2.count.into()
        ]
    );
    assert_eq!(kv["rdtoolrng.short"], EW_LENGTH.to_string());
    assert_eq!(
        ints(&kv["rdusetlno"]),
        [1, 2, g1.using.into(), g2.using.into()]
    );
    assert_eq!(g1.using, 2);

    let tools = |g: &fwlib32::sim::profile::offset::ToolGroupProfile| {
        let mut v = vec![n(g)];
        for t in &g.tools {
            v.extend([t.number, t.length, t.radius, t.info].map(i64::from));
        }
        v
    };
    assert_eq!(ints(&kv["rdtltool"]), tools(g1));
    let t = &g1.tools[0];
    assert_eq!(
        ints(&kv["rdtltool.one"]),
        [1, t.number, t.length, t.radius, t.info].map(i64::from)
    );
    assert_eq!(kv["rdtltool.zero"], EW_LENGTH.to_string());

    // Group 2's counter reached its life: it alone is to be exchanged.
    assert!(g2.count >= g2.life && g1.count < g1.life);
    assert_eq!(
        ints(&kv["rdexchgtgrp"]),
        [1, g2.number.into(), g2.optional.into()]
    );
    assert_eq!(g2.optional, 202);

    let o = &path.offset;
    let lim = [o.limits[0], o.limits[1], o.limit_status].map(i64::from);
    assert_ne!(lim[1], 0);
    for k in ["tofs_rnge", "zofs_rnge", "wksft_rnge"] {
        assert_eq!(ints(&kv[k]), lim, "{k}");
    }
    assert_eq!(kv["tofs_rnge.type"], EW_ATTRIB.to_string());
    assert_eq!(kv["tofs_rnge.number"], EW_NUMBER.to_string());
    assert_eq!(kv["zofs_rnge.axis"], EW_ATTRIB.to_string());

    // The fixture offset in effect, all axes and axis 2.
    let f = usize::try_from(o.fixture_active - 1).unwrap();
    let row = &o.fixture[f];
    let fx = |k: usize| i64::from(row[k]);
    let act = i64::from(o.fixture_active);
    assert_eq!(ints(&kv["rdactfixofs"]), [act, -1, fx(0), fx(1), fx(2)]);
    assert_eq!(ints(&kv["rdactfixofs.axis"]), [act, 2, fx(1)]);
    assert_ne!(fx(1), 0);

    // The path's three axes' volumetric compensation; the last two words
    // untouched (0x55 bytes).
    let untouched = i64::from(0x5555_5555_i32);
    let v = |k: usize| i64::from(o.volumetric[k]);
    assert_eq!(
        ints(&kv["rdvolccomp"]),
        [v(0), v(1), v(2), untouched, untouched]
    );
    assert_ne!(v(1), 0);

    // Group 1's second tool rewritten and read back; the refused writes
    // changed nothing.
    let mut want = tools(g1);
    want[5..9].copy_from_slice(&[21, 22, 23, 4]);
    assert_eq!(ints(&kv["written"]), want);
    assert_eq!(kv["wr1tlifedata.group"], EW_NUMBER.to_string());
    assert_eq!(kv["wr1tlifedata.tool"], EW_NUMBER.to_string());
    assert_eq!(kv["wr1tlifedata.number"], EW_DATA.to_string());
    assert_eq!(ints(&kv["refused"]), want);
    let mut want2 = tools(g2);
    want2[1..5].copy_from_slice(&[31, 32, 33, 1]);
    assert_eq!(ints(&kv["written2"]), want2);
}
