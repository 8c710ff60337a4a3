//! 16i-class (open response frame version 2) forms of the functions whose
//! requests differ from the 30i class. The request bytes below were recorded
//! from FANUC's library (x86-64 libfwlib32 1.0.5) talking to our own fake CNC
//! answering the open with the v2_kind1 body of vectors/cnc_allclibhndl3.json
//! (our observation; see docs/protocol/classes.md "16i class").

use crate::sim;

use fwlib32::ew::*;
use fwlib32::proto::call::{Call, Ctx};
use fwlib32::proto::macros::{WriteMacros, to_base2};
use fwlib32::proto::open::CncClass;
use fwlib32::proto::packet::encode_request;
use fwlib32::proto::position::{AxisData, AxisDataCall, SpindleData, spdl};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_short, c_ushort};

fn cx16() -> Ctx {
    Ctx {
        class: CncClass::Series16 { kind: 1 },
        max_axes: 8,
        max_spindles: 4,
        ..Ctx::default()
    }
}

fn req<C: Call>(c: &C) -> String {
    let mut subs = c.request(&cx16());
    subs.iter_mut().for_each(|s| s.path = 1);
    encode_request(&subs)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

#[test]
fn request_bytes_recorded_from_fanuc() {
    // cnc_acts2(h, 1, ..)
    let acts2 = SpindleData {
        code: spdl::SPEED_ACT,
        sp_no: 1,
    };
    assert_eq!(
        req(&acts2),
        "0001001c0001000100400000000300000001000000000000000000000000"
    );
    // cnc_rdspload(h, 1, ..)
    let spload = SpindleData {
        code: spdl::LOAD_SERIAL,
        sp_no: 1,
    };
    assert_eq!(
        req(&spload),
        "0001001c0001000100400000000000000001000000000000000000000000"
    );
    // cnc_rdsvmeter(h, &8, ..)
    let sv = AxisDataCall {
        what: AxisData::Servo(vec![1]),
        limit: 8,
    };
    assert_eq!(
        req(&sv),
        "0002001c0001000100560000000100000000000000000000000000000000\
         001c0001000100890000000000000000000000000000000000000000"
    );
    // cnc_rdspmeter(h, 0 or -1, &8, ..): FANUC asks load and speed for either type.
    let sp = AxisDataCall {
        what: AxisData::Spindle(vec![spdl::LOAD_METER, spdl::SPEED_METER]),
        limit: 8,
    };
    assert_eq!(
        req(&sp),
        "0003001c00010001004000000004ffffffff000000000000000000000000\
         001c00010001004000000005ffffffff000000000000000000000000\
         001c00010001008a0000000000000000000000000000000000000000"
    );
    // cnc_wrmacro(h, 100, 10, 12345, 3) and (h, 100, 10, -1, 0)
    let w = WriteMacros {
        s: 100,
        values: vec![(12345, 3)],
    };
    assert_eq!(
        req(&w),
        "00010024000100010016000000640000006400000000000000000000000862c28f5c0002001b"
    );
    let w = WriteMacros {
        s: 100,
        values: vec![(-1, 0)],
    };
    assert_eq!(
        req(&w),
        "000100240001000100160000006400000064000000000000000000000008800000000002001f"
    );
}

#[test]
fn wrmacro_binary_records_as_fanuc() {
    // (mcr_val, dec_val) -> record words sent by FANUC's library (recorded).
    // Past dec 9 FANUC's library multiplies by its truncated 10^-9 and then
    // 10^(9 - rest) (docs/protocol/classes.md), so it loses a few units: 1 dec 10
    // is 0x6df37f63 where the exact value is 0x6df37f67.5.
    let cases: [((i32, i16), (u32, i16)); 28] = [
        ((1, 10), (0x6df37f63, 64)),
        ((-1, 10), (0x920c809a, 64)),
        ((3, 10), (0x52769f8b, 62)),
        ((i32::MAX, 10), (0x6df37f62, 33)),
        ((1, 20), (0x5e72842d, 97)),
        ((-1, 59), (0xbfb8f457, 226)),
        ((7, -10), (0x4131_4cf0, -6)),
        ((-7, -18), (0x9edb_0116, -32)),
        ((1, 127), (0x4551_15f7, 452)),
        ((1, -128), (0x49dd_23df, -395)),
        ((0, 3), (0, 3)),
        ((-12345, -9), (0xa62d_a548, -13)),
        ((-1, 1), (0x9999999a, 34)),
        ((12345, -9), (0x59d2_5ab7, -13)),
        ((12345, 3), (0x62c28f5c, 27)),
        ((1, 0), (0x40000000, 30)),
        ((-5, 1), (0x80000000, 32)),
        ((0, 0), (0, 0)),
        ((3, 0), (0x60000000, 29)),
        ((i32::MAX, 0), (0x7fffffff, 0)),
        ((7, 5), (0x49667b5f, 44)),
        ((1, 9), (0x44b82fa0, 60)),
        ((100, -2), (0x4e200000, 17)),
        ((-12345, 3), (0x9d3d70a4, 27)),
        ((-1, 0), (0x80000000, 31)),
        ((-3, 0), (0xa0000000, 29)),
        ((i32::MIN, 0), (0x80000000, 0)),
        ((-7, 5), (0xb69984a1, 44)),
    ];
    for ((v, d), (m, e)) in cases {
        assert_eq!(to_base2(v, d), (m as i32, e), "{v} dec {d}");
    }
}

const PROFILE: &str = r#"
[cnc]
class = "16i"
cnc_type = "16"
series = "B0H1"
version = "0020"
max_axes = 8
max_spindles = 4
[[path]]
axis = [{ name = "X", servo_load = 11 }, { name = "Y", servo_load = 22 }]
spindle = [{ name = "S1", speed = 3000, load = 25 }, { name = "S2", speed = 1500, load = 7 }]
"#;

#[test]
fn through_the_c_abi_against_a_16i_simulator() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);

    let mut a2 = ODBACT2::default();
    assert_eq!(unsafe { cnc_acts2(h, -1, &mut a2) }, EW_OK);
    assert_eq!(a2.datano, -1);
    assert_eq!(&a2.data[..2], &[3000, 1500]);

    let mut spn = ODBSPN::default();
    assert_eq!(unsafe { cnc_rdspload(h, 1, &mut spn) }, EW_OK);
    assert_eq!((spn.datano, spn.data[0]), (1, 25));

    // 16i: the count is the open body's maximum axes / spindles.
    let mut num: c_short = 8;
    let mut sv = [ODBSVLOAD::default(); 8];
    assert_eq!(
        unsafe { cnc_rdsvmeter(h, &mut num, sv.as_mut_ptr()) },
        EW_OK
    );
    assert!(num >= 2);
    assert_eq!((sv[0].svload.data, sv[0].svload.name as u8), (11, b'X'));
    assert_eq!((sv[1].svload.data, sv[1].svload.name as u8), (22, b'Y'));

    let mut num: c_short = 4;
    let mut spl = [ODBSPLOAD::default(); 4];
    assert_eq!(
        unsafe { cnc_rdspmeter(h, 0, &mut num, spl.as_mut_ptr()) },
        EW_OK
    );
    assert!(num >= 2);
    assert_eq!((spl[0].spload.data, spl[1].spload.data), (25, 7));

    // FANUC's library: EW_FUNC without traffic on a 16i-class CNC.
    let mut len: c_short = 8;
    let mut types: [c_short; 1] = [0];
    let mut ax = [ODBAXDT::default(); 8];
    assert_eq!(
        unsafe { cnc_rdaxisdata(h, 1, types.as_mut_ptr(), 1, &mut len, ax.as_mut_ptr()) },
        EW_FUNC
    );
    let mut his = ODBAHIS2::default();
    assert_eq!(
        unsafe { cnc_rdalmhistry2(h, 1, 1, 1024, &mut his) },
        EW_FUNC
    );

    // wrmacro sends a binary record; the value reads back unchanged.
    assert_eq!(unsafe { cnc_wrmacro(h, 100, 10, 12345, 3) }, EW_OK);
    let mut m = ODBM::default();
    assert_eq!(unsafe { cnc_rdmacro(h, 100, 10, &mut m) }, EW_OK);
    assert_eq!(
        f64::from(m.mcr_val) / 10f64.powi(i32::from(m.dec_val)),
        12.345
    );
    sim::free(h);
}

/// A 16i (kind 1) or a Series 15 (kind 2) with two axes and the display
/// parameters cnc_rdposition / cnc_rdspeed read; `aut` is the mode word.
fn display_profile(kind: u16, aut: i16) -> String {
    format!(
        r#"
[cnc]
class = "16i"
kind = {kind}
max_axes = 8
max_spindles = 4
[[path]]
feed = 1500
[path.status]
aut = {aut}
[path.modal]
g = [0, 0, 0, 0, 1]
[[path.axis]]
name = "X"
decimals = 3
absolute = 125000
machine = 125001
relative = 125002
distance = 7
unit = 1
[[path.axis]]
name = "Y"
decimals = 4
absolute = -42500
machine = -42501
relative = -42502
distance = -8
[[path.spindle]]
name = "S1"
speed = 3000
[param]
[[param.parameter]]
number = 3106
kind = "bit"
values = [0]
[[param.parameter]]
number = 3107
kind = "bit"
values = [8]
[[param.parameter]]
number = 3115
kind = "bit"
axis = true
values = [0, 2]
[[param.parameter]]
number = 9936
kind = "bit"
values = [0]
"#
    )
}

fn pos(h: c_ushort, t: c_short, n: c_short) -> (c_short, c_short, Vec<ODBPOS>) {
    let mut num = n;
    let mut p = vec![ODBPOS::default(); 8];
    let r = unsafe { cnc_rdposition(h, t, &mut num, p.as_mut_ptr()) };
    (r, num, p)
}

fn elem(e: &POSELM) -> (i32, i16, i16, i16, u8, u8) {
    (e.data, e.dec, e.unit, e.disp, e.name as u8, e.suff as u8)
}

#[test]
fn rdposition_and_rdspeed_16i_forms() {
    let s = sim::start_toml(&display_profile(1, 1));
    let h = sim::alloc(&s);
    // The count is the path's maximum axes (8), as FANUC's library reads
    // it; the simulator answers empty entries for the axes beyond the path's.
    let (r, num, p) = pos(h, -1, 8);
    assert_eq!((r, num), (EW_OK, 8));
    assert_eq!(elem(&p[0].abs), (125000, 3, 1, 1, b'X', 0));
    assert_eq!(elem(&p[0].mach), (125001, 3, 1, 1, b'X', 0));
    assert_eq!(elem(&p[0].rel), (125002, 3, 1, 1, b'X', 0));
    assert_eq!(elem(&p[0].dist), (7, 3, 1, 1, b'X', 0));
    // 3115 bit 1 hides all positions but the machine position.
    assert_eq!(elem(&p[1].abs), (-42500, 4, 0, 0, b'Y', 0));
    assert_eq!(elem(&p[1].mach), (-42501, 4, 0, 1, b'Y', 0));
    assert_eq!(elem(&p[1].dist), (-8, 4, 0, 0, b'Y', 0));
    assert_eq!(elem(&p[7].abs), (0, 0, 0, 1, 0, 0));
    // One type writes its elements only; the count limits the axes.
    let (r, num, p) = pos(h, 2, 1);
    assert_eq!((r, num), (EW_OK, 1));
    assert_eq!(elem(&p[0].rel), (125002, 3, 1, 1, b'X', 0));
    assert_eq!(p[0].abs, POSELM::default());
    assert_eq!(p[1], ODBPOS::default());
    // The 16i class checks *data_num before the type.
    assert_eq!(pos(h, 7, 0).0, EW_LENGTH);
    assert_eq!(pos(h, 7, 1).0, EW_ATTRIB);

    // Feed: inch (the first axis) + per revolution (3107 bit 3, G95).
    let mut sp = ODBSPEED::default();
    assert_eq!(unsafe { cnc_rdspeed(h, -1, &mut sp) }, EW_OK);
    let f = &sp.actf;
    assert_eq!((f.data, f.unit, f.disp, f.name as u8), (1500, 4, 1, b'F'));
    let a = &sp.acts;
    assert_eq!((a.data, a.unit, a.disp, a.name as u8), (3000, 2, 1, b'S'));
    sim::free(h);

    // In JOG mode FANUC's library does not take the distance to go.
    let s = sim::start_toml(&display_profile(1, 5));
    let h = sim::alloc(&s);
    let (r, _, p) = pos(h, 3, 2);
    assert_eq!(r, EW_OK);
    assert_eq!(elem(&p[0].dist), (0, -1, 1, 1, b'X', 0));
    sim::free(h);
}

#[test]
fn rdposition_and_rdspeed_series15_forms() {
    let s = sim::start_toml(&display_profile(2, 1));
    let h = sim::alloc(&s);
    // The count comes from 0x8c (the path's axes), the display words too.
    let (r, num, p) = pos(h, -1, 8);
    assert_eq!((r, num), (EW_OK, 2));
    assert_eq!(elem(&p[0].abs), (125000, 3, 1, 1, b'X', 0));
    assert_eq!(elem(&p[1].mach), (-42501, 4, 0, 1, b'Y', 0));
    assert_eq!(p[2], ODBPOS::default());
    let mut sp = ODBSPEED::default();
    assert_eq!(unsafe { cnc_rdspeed(h, -1, &mut sp) }, EW_OK);
    // No per-revolution form; the spindle named by 0x95's entry of 0x8a.
    assert_eq!((sp.actf.data, sp.actf.unit), (1500, 1));
    let a = &sp.acts;
    assert_eq!(
        (a.data, a.unit, a.disp, a.name as u8, a.suff as u8),
        (3000, 2, 1, b'S', b'1')
    );
    sim::free(h);
}
