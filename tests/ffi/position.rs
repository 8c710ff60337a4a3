//! The position area through the C ABI against the simulator: every
//! function reads back the profile's values; all-axes answers carry
//! max-axes records; length, NULL, handle and number checks.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::mem::{offset_of, size_of};
use std::os::raw::{c_short, c_ushort};

/// An idle machine (no program in cycle): values stay as configured.
fn profile(max_axes: u16) -> String {
    format!(
        r#"
[cnc]
max_axes = {max_axes}

[[path]]
feed = 1234

[[path.axis]]
name = "X"
decimals = 3
absolute = 1000
machine = 2000
relative = 3000
distance = 4000
servo_load = 11

[[path.axis]]
name = "Y"
decimals = 3
absolute = -1001
machine = -2001
relative = -3001
distance = -4001
servo_load = 22
input_figures = 4
output_figures = 2

[[path.axis]]
name = "B"
suffix = "1"
decimals = 4
unit = 2
absolute = 900000
machine = 900001
relative = 900002
distance = 900003
servo_load = 33

[[path.spindle]]
name = "S1"
speed = 3000
load = 25

[[path.spindle]]
name = "S2"
speed = 1500
load = 7

[[path.alarm]]
number = 500
type = 4
message = "OVER TRAVEL"

[[path.alarm]]
number = 1001
type = 19
message = "COOLANT"
"#
    )
}

struct Cnc {
    _sim: Simulator,
    h: c_ushort,
    p: Profile,
}

impl Drop for Cnc {
    fn drop(&mut self) {
        cnc_freelibhndl(self.h);
    }
}

fn start(text: &str) -> Cnc {
    let p = Profile::parse(text).expect("profile");
    let (s, h) = sim::start_alloc(p.clone());
    Cnc { _sim: s, h, p }
}

const FILL: u8 = 0xCC;

/// A buffer pre-filled with 0xCC, read as `T` fields at byte offsets.
struct Buf(Vec<u8>);

impl Buf {
    fn new(n: usize) -> Buf {
        Buf(vec![FILL; n])
    }
    fn ptr<T>(&mut self) -> *mut T {
        self.0.as_mut_ptr().cast()
    }
    fn i32(&self, off: usize) -> i32 {
        i32::from_le_bytes(self.0[off..off + 4].try_into().unwrap())
    }
    fn i16(&self, off: usize) -> i16 {
        i16::from_le_bytes(self.0[off..off + 2].try_into().unwrap())
    }
    fn untouched(&self, range: std::ops::Range<usize>) -> bool {
        self.0[range].iter().all(|b| *b == FILL)
    }
}

fn low16(v: i32) -> i32 {
    i32::from(v as i16)
}

fn alarm_bits(p: &Profile) -> i32 {
    p.paths[0].alarms.iter().fold(0u32, |b, a| b | 1 << a.kind) as i32
}

#[test]
fn names_read_back() {
    let c = start(&profile(32));
    let mut num: c_short = 8;
    let mut names = [ODBAXISNAME::default(); 8];
    assert_eq!(
        unsafe { cnc_rdaxisname(c.h, &mut num, names.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 3);
    let got: Vec<(u8, u8)> = names[..3]
        .iter()
        .map(|n| (n.name as u8, n.suff as u8))
        .collect();
    assert_eq!(got, [(b'X', 0), (b'Y', 0), (b'B', b'1')]);

    // Fewer slots than axes: only those are written.
    let mut num: c_short = 2;
    let mut b = Buf::new(16);
    assert_eq!(unsafe { cnc_rdaxisname(c.h, &mut num, b.ptr()) }, EW_OK);
    assert_eq!(num, 2);
    assert!(b.untouched(4..16));

    let mut num: c_short = 4;
    let mut sp = [ODBSPDLNAME::default(); 4];
    assert_eq!(
        unsafe { cnc_rdspdlname(c.h, &mut num, sp.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 2);
    assert_eq!(
        [sp[1].name as u8, sp[1].suff1 as u8, sp[1].suff2 as u8],
        [b'S', b'2', 0]
    );
}

#[test]
fn positions_read_back() {
    let c = start(&profile(32));
    let axes = &c.p.paths[0].axes;
    type F = unsafe extern "C" fn(c_ushort, c_short, c_short, *mut ODBAXIS) -> c_short;
    type Pick = fn(&fwlib32::sim::profile::Axis) -> i32;
    let fns: [(F, Pick); 6] = [
        (cnc_absolute, |a| a.absolute),
        (cnc_absolute2, |a| a.absolute),
        (cnc_machine, |a| a.machine),
        (cnc_relative, |a| a.relative),
        (cnc_relative2, |a| a.relative),
        (cnc_distance, |a| a.distance),
    ];
    for (f, pick) in fns {
        // One axis: 8 bytes written (dummy untouched).
        for (i, a) in axes.iter().enumerate() {
            let mut b = Buf::new(64);
            let axis = i as c_short + 1;
            assert_eq!(unsafe { f(c.h, axis, 8, b.ptr()) }, EW_OK);
            assert_eq!(b.i16(2), axis);
            assert_eq!(b.i32(4), pick(a));
            assert!(b.untouched(0..2) && b.untouched(8..64));
        }
        // All axes: max-axes values, unused ones zero.
        let mut o = ODBAXIS::default();
        assert_eq!(
            unsafe { f(c.h, -1, size_of::<ODBAXIS>() as c_short, &mut o) },
            EW_OK
        );
        assert_eq!(o.r#type, -1);
        let want: Vec<i32> = axes
            .iter()
            .map(pick)
            .chain(std::iter::repeat(0))
            .take(32)
            .collect();
        assert_eq!(o.data.to_vec(), want);
        // Length checks before traffic; bad axis from the CNC.
        assert_eq!(unsafe { f(c.h, 1, 7, &mut o) }, EW_LENGTH);
        assert_eq!(unsafe { f(c.h, -1, 131, &mut o) }, EW_LENGTH);
        assert_eq!(unsafe { f(c.h, 4, 8, &mut o) }, EW_ATTRIB);
        assert_eq!(unsafe { f(c.h, 0, 8, &mut o) }, EW_ATTRIB);
        assert_eq!(unsafe { f(c.h, 1, 8, std::ptr::null_mut()) }, EW_DATA);
        assert_eq!(unsafe { f(0, 1, 8, &mut o) }, EW_HANDLE);
    }
}

#[test]
fn dynamic2_one_axis_and_all_axes() {
    let c = start(&profile(32));
    let p = &c.p.paths[0];
    let bits = alarm_bits(&c.p);
    let pos = offset_of!(ODBDY2, pos);

    for (i, a) in p.axes.iter().enumerate() {
        let mut b = Buf::new(600);
        let axis = i as c_short + 1;
        assert_eq!(unsafe { cnc_rddynamic2(c.h, axis, 44, b.ptr()) }, EW_OK);
        assert!(b.untouched(0..2), "dummy untouched");
        assert_eq!(b.i16(2), axis);
        assert_eq!(b.i32(4), low16(bits));
        assert_eq!(b.i32(8), 0, "idle: no program");
        assert_eq!(b.i32(20), p.feed);
        assert_eq!(b.i32(24), p.spindles[0].speed);
        let got: Vec<i32> = (0..4).map(|k| b.i32(pos + 4 * k)).collect();
        assert_eq!(got, [a.absolute, a.machine, a.relative, a.distance]);
        assert!(b.untouched(44..600), "nothing past 44 bytes");
    }

    let mut d = ODBDY2::default();
    assert_eq!(unsafe { cnc_rddynamic2(c.h, -1, 540, &mut d) }, EW_OK);
    assert_eq!((d.axis, d.actf, d.acts), (-1, p.feed, p.spindles[0].speed));
    let f = unsafe { d.pos.faxis };
    let col = |pick: fn(&fwlib32::sim::profile::Axis) -> i32| -> Vec<i32> {
        p.axes
            .iter()
            .map(pick)
            .chain(std::iter::repeat(0))
            .take(32)
            .collect()
    };
    assert_eq!(f.absolute.to_vec(), col(|a| a.absolute));
    assert_eq!(f.machine.to_vec(), col(|a| a.machine));
    assert_eq!(f.relative.to_vec(), col(|a| a.relative));
    assert_eq!(f.distance.to_vec(), col(|a| a.distance));

    // ODBDY: shorts for alarm and program numbers.
    let mut b = Buf::new(600);
    assert_eq!(unsafe { cnc_rddynamic(c.h, 2, 40, b.ptr()) }, EW_OK);
    assert_eq!(b.i16(4), bits as i16);
    assert!(b.untouched(10..12), "padding untouched");
    assert_eq!(b.i32(16), p.feed);
    assert_eq!(b.i32(24), p.axes[1].absolute);
    assert!(b.untouched(40..600));

    // Length checks (no traffic) and NULL / handle.
    assert_eq!(unsafe { cnc_rddynamic2(c.h, 1, 43, &mut d) }, EW_LENGTH);
    assert_eq!(unsafe { cnc_rddynamic2(c.h, -1, 539, &mut d) }, EW_LENGTH);
    let mut dy = ODBDY::default();
    assert_eq!(unsafe { cnc_rddynamic(c.h, 1, 39, &mut dy) }, EW_LENGTH);
    assert_eq!(unsafe { cnc_rddynamic(c.h, -1, 535, &mut dy) }, EW_LENGTH);
    assert_eq!(
        unsafe { cnc_rddynamic2(c.h, 1, 44, std::ptr::null_mut()) },
        EW_DATA
    );
    assert_eq!(unsafe { cnc_rddynamic2(0, 1, 44, &mut d) }, EW_HANDLE);
    assert_eq!(unsafe { cnc_rddynamic2(c.h, 9, 44, &mut d) }, EW_ATTRIB);
}

#[test]
fn all_axes_with_fewer_max_axes() {
    let c = start(&profile(4));
    let p = &c.p.paths[0];
    // 4 records: 3 axes and a zero; the other 28 slots untouched.
    let mut b = Buf::new(540);
    assert_eq!(unsafe { cnc_rddynamic2(c.h, -1, 540, b.ptr()) }, EW_OK);
    let pos = offset_of!(ODBDY2, pos);
    for k in 0..4 {
        let base = pos + 128 * k;
        assert_eq!(b.i32(base), [1000, 2000, 3000, 4000][k]);
        assert_eq!(b.i32(base + 12), 0, "unused 4th axis");
        assert!(b.untouched(base + 16..base + 128));
    }
    assert_eq!(b.i32(pos + 8), p.axes[2].absolute);

    // ODBAXIS: length must hold max_axes values.
    let mut b = Buf::new(200);
    assert_eq!(unsafe { cnc_machine(c.h, -1, 19, b.ptr()) }, EW_LENGTH);
    assert_eq!(unsafe { cnc_machine(c.h, -1, 20, b.ptr()) }, EW_OK);
    assert_eq!(b.i32(4 + 8), p.axes[2].machine);
    assert_eq!(b.i32(4 + 12), 0);
    assert!(b.untouched(20..200));
}

#[test]
fn feed_speed_and_loads() {
    let c = start(&profile(32));
    let p = &c.p.paths[0];

    let mut a = ODBACT::default();
    assert_eq!(unsafe { cnc_actf(c.h, &mut a) }, EW_OK);
    assert_eq!(a.data, p.feed);
    assert_eq!(unsafe { cnc_acts(c.h, &mut a) }, EW_OK);
    assert_eq!(a.data, p.spindles[0].speed);
    assert_eq!(unsafe { cnc_actf(c.h, std::ptr::null_mut()) }, EW_DATA);

    let mut a2 = ODBACT2::default();
    assert_eq!(unsafe { cnc_acts2(c.h, -1, &mut a2) }, EW_OK);
    assert_eq!(a2.datano, -1);
    assert_eq!(&a2.data[..2], &[3000, 1500]);
    assert_eq!(unsafe { cnc_acts2(c.h, 2, &mut a2) }, EW_OK);
    assert_eq!((a2.datano, a2.data[0]), (2, 1500));
    assert_eq!(unsafe { cnc_acts2(c.h, 3, &mut a2) }, EW_NUMBER);

    let mut sp = ODBSPEED::default();
    assert_eq!(unsafe { cnc_rdspeed(c.h, -1, &mut sp) }, EW_OK);
    assert_eq!(
        (sp.actf.data, sp.actf.unit, sp.actf.name as u8),
        (p.feed, 0, b'F')
    );
    assert_eq!(
        (
            sp.acts.data,
            sp.acts.unit,
            sp.acts.disp,
            sp.acts.name as u8,
            sp.acts.suff as u8
        ),
        (3000, 2, 1, b'S', b'1')
    );
    assert_eq!(unsafe { cnc_rdspeed(c.h, 2, &mut sp) }, EW_ATTRIB);

    let mut num: c_short = 8;
    let mut sv = [ODBSVLOAD::default(); 8];
    assert_eq!(
        unsafe { cnc_rdsvmeter(c.h, &mut num, sv.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 3);
    let loads: Vec<(i32, u8)> = sv[..3]
        .iter()
        .map(|s| (s.svload.data, s.svload.name as u8))
        .collect();
    assert_eq!(loads, [(11, b'X'), (22, b'Y'), (33, b'B')]);

    let mut num: c_short = 4;
    let mut spl = [ODBSPLOAD::default(); 4];
    assert_eq!(
        unsafe { cnc_rdspmeter(c.h, -1, &mut num, spl.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 2);
    assert_eq!(
        [
            spl[0].spload.data,
            spl[0].spspeed.data,
            spl[1].spload.data,
            spl[1].spspeed.data
        ],
        [25, 3000, 7, 1500]
    );
    assert_eq!((spl[0].spload.unit, spl[0].spspeed.unit), (0, 1));
    assert_eq!(
        unsafe { cnc_rdspmeter(c.h, 2, &mut num, spl.as_mut_ptr()) },
        EW_ATTRIB
    );

    let mut spn = ODBSPN::default();
    assert_eq!(unsafe { cnc_rdspload(c.h, 1, &mut spn) }, EW_OK);
    assert_eq!((spn.datano, spn.data[0]), (1, 25));
    assert_eq!(unsafe { cnc_rdspload(c.h, 9, &mut spn) }, EW_NUMBER);
    assert_eq!(unsafe { cnc_rdspload(c.h, 3, &mut spn) }, EW_NUMBER);
}

#[test]
fn axis_data_and_position() {
    let c = start(&profile(32));
    let p = &c.p.paths[0];
    let mut types: [c_short; 4] = [0, 1, 2, 3];
    let mut len: c_short = 8;
    let mut ax = [ODBAXDT::default(); 32];
    assert_eq!(
        unsafe { cnc_rdaxisdata(c.h, 1, types.as_mut_ptr(), 4, &mut len, ax.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(len, 3);
    // Type-major: record (type k, axis i) at k * 8 + i.
    let b = &ax[8 + 2];
    assert_eq!(
        (b.name[0] as u8, b.name[1] as u8, b.data, b.dec, b.unit),
        (b'B', b'1', p.axes[2].machine, 4, 2)
    );
    assert_eq!(ax[3 * 8].data, p.axes[0].distance);

    let mut t: [c_short; 1] = [0];
    let mut len: c_short = 8;
    assert_eq!(
        unsafe { cnc_rdaxisdata(c.h, 2, t.as_mut_ptr(), 1, &mut len, ax.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!((len, ax[1].data, ax[1].unit), (3, 22, 8));
    let mut t: [c_short; 2] = [0, 1];
    let mut len: c_short = 4;
    assert_eq!(
        unsafe { cnc_rdaxisdata(c.h, 3, t.as_mut_ptr(), 2, &mut len, ax.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!((len, ax[1].data, ax[4 + 1].data), (2, 7, 1500));
    assert_eq!(
        unsafe { cnc_rdaxisdata(c.h, 7, t.as_mut_ptr(), 2, &mut len, ax.as_mut_ptr()) },
        EW_NUMBER
    );

    let mut num: c_short = 8;
    let mut ps = [ODBPOS::default(); 8];
    assert_eq!(
        unsafe { cnc_rdposition(c.h, -1, &mut num, ps.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 3);
    for (o, a) in ps.iter().zip(&p.axes) {
        assert_eq!(
            [o.abs.data, o.mach.data, o.rel.data, o.dist.data],
            [a.absolute, a.machine, a.relative, a.distance]
        );
        assert_eq!(
            (o.abs.dec, o.abs.unit, o.abs.name as u8),
            (a.decimals, a.unit, a.name.as_bytes()[0])
        );
    }
    // One type: only its slot.
    let mut num: c_short = 3;
    let mut b = Buf::new(3 * 48);
    assert_eq!(unsafe { cnc_rdposition(c.h, 1, &mut num, b.ptr()) }, EW_OK);
    assert_eq!(b.i32(48 + 12), p.axes[1].machine);
    assert!(b.untouched(0..12) && b.untouched(24..48));
}

#[test]
fn figures() {
    let c = start(&profile(32));
    let mut valid: c_short = 0;
    let (mut fin, mut fout) = ([0 as c_short; 32], [0 as c_short; 32]);
    assert_eq!(
        unsafe { cnc_getfigure(c.h, 0, &mut valid, fin.as_mut_ptr(), fout.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(valid, 3);
    assert_eq!((&fin[..3], &fout[..3]), (&[3, 4, 4][..], &[3, 2, 4][..]));
    assert_eq!(
        unsafe { cnc_getfigure(c.h, 0, &mut valid, std::ptr::null_mut(), fout.as_mut_ptr()) },
        EW_DATA
    );
}

#[test]
fn spindle_meters_need_the_spindle_word() {
    // A machine without spindles: the open response's spindle word is 0.
    let text = profile(32);
    let text = text.split("[[path.spindle]]").next().unwrap().to_string();
    let c = start(&text);
    let mut num: c_short = 4;
    let mut spl = [ODBSPLOAD::default(); 4];
    assert_eq!(
        unsafe { cnc_rdspmeter(c.h, -1, &mut num, spl.as_mut_ptr()) },
        EW_NOOPT
    );
    assert_eq!(num, 4, "untouched");
    let mut a = ODBACT::default();
    assert_eq!(unsafe { cnc_acts(c.h, &mut a) }, EW_OK);
    assert_eq!(a.data, 0);
}

/// cnc_rdaxisdata with `types` into a 0xCC-filled buffer of `room` records
/// per type: (code, *len out, buffer).
fn axisdata(
    h: c_ushort,
    cls: c_short,
    types: &[c_short],
    room: c_short,
) -> (c_short, c_short, Vec<u8>) {
    let mut t = types.to_vec();
    let mut len = room;
    let mut b = vec![FILL; size_of::<ODBAXDT>() * (types.len().max(1) * room.max(1) as usize)];
    let r = unsafe {
        cnc_rdaxisdata(
            h,
            cls,
            t.as_mut_ptr(),
            types.len() as c_short,
            &mut len,
            b.as_mut_ptr().cast(),
        )
    };
    (r, len, b)
}

/// ODBAXDT record `k` of a buffer: (name bytes, data, dec, unit, flag).
fn axdt(b: &[u8], k: usize) -> ([u8; 4], i32, i16, i16, i16) {
    let r = &b[16 * k..16 * k + 16];
    let i16_at = |o: usize| i16::from_le_bytes([r[o], r[o + 1]]);
    (
        [r[0], r[1], r[2], r[3]],
        i32::from_le_bytes([r[4], r[5], r[6], r[7]]),
        i16_at(8),
        i16_at(10),
        i16_at(12),
    )
}

/// Classes 4 and 5 and class-1 types 4..17 (FANUC's library's tables, see
/// docs/protocol/position.md), and FANUC's local checks: *len < 1 → EW_LENGTH, num outside
/// 1..4 → EW_ATTRIB, class outside 1..5 → EW_NUMBER, unknown type →
/// EW_ATTRIB.
#[test]
fn axis_data_classes_4_5_and_more_position_types() {
    let text = profile(32);
    let c = start(&text);
    let p = &c.p.paths[0];
    // Class 1 types 4, 5, 17 (codes 11, 12, 39: the simulator answers 0)
    // and 0: names and units as the other non-machine types.
    let (r, len, b) = axisdata(c.h, 1, &[4, 5, 17, 0], 4);
    assert_eq!((r, len), (EW_OK, 3));
    for k in 0..3 {
        let (name, data, _, unit, _) = axdt(&b, 4 * k + 2);
        assert_eq!((name[0], data, unit), (b'B', 0, 2), "type index {k}");
    }
    assert_eq!(axdt(&b, 12 + 2).1, p.axes[2].absolute);
    assert_eq!(axisdata(c.h, 1, &[18], 4).0, EW_ATTRIB);
    assert_eq!(axisdata(c.h, 1, &[-1], 4).0, EW_ATTRIB);

    // Class 5: always one item; type 0 feed 'F' (2 name bytes), unit from
    // 0x88[3]; type 1 the first spindle's speed and name, unit 5, flag 1;
    // type 2 'F', flag 2.
    let (r, len, b) = axisdata(c.h, 5, &[0, 1, 2], 2);
    assert_eq!((r, len), (EW_OK, 1));
    assert_eq!(axdt(&b, 0), ([b'F', 0, FILL, FILL], p.feed, 0, 3, 0));
    let (name, data, dec, unit, flag) = axdt(&b, 2);
    assert_eq!(
        (&name[..2], data, dec, unit, flag),
        (&b"S1"[..], p.spindles[0].speed, 0, 5, 1)
    );
    assert_eq!(axdt(&b, 4), ([b'F', 0, FILL, FILL], 0, 0, 0, 2));
    assert!(b[16..32].iter().all(|&x| x == FILL), "item 1 untouched");
    assert_eq!(axisdata(c.h, 5, &[3], 2).0, EW_ATTRIB);

    // Local checks, FANUC's order.
    assert_eq!(axisdata(c.h, 1, &[0], 0).0, EW_LENGTH);
    assert_eq!(axisdata(c.h, 6, &[0], 0).0, EW_LENGTH);
    assert_eq!(axisdata(c.h, 1, &[0; 5], 4).0, EW_ATTRIB);
    assert_eq!(axisdata(c.h, 6, &[0; 5], 4).0, EW_ATTRIB);
    assert_eq!(axisdata(c.h, 1, &[], 4).0, EW_ATTRIB);
    assert_eq!(axisdata(c.h, 0, &[0], 4).0, EW_NUMBER);
    assert_eq!(axisdata(c.h, 6, &[0], 4).0, EW_NUMBER);

    // Class 3 types 2..4 (0x40 codes 3, 7, 6): speed, 0, 0 with their units.
    let (r, len, b) = axisdata(c.h, 3, &[2, 3, 4], 4);
    assert_eq!((r, len), (EW_OK, 2));
    assert_eq!(axdt(&b, 1).1, p.spindles[1].speed);
    assert_eq!((axdt(&b, 4).3, axdt(&b, 8).3), (5, 8));
    assert_eq!(axisdata(c.h, 3, &[5], 4).0, EW_ATTRIB);

    // Class 4 asks 0x40[code, 1] for as many items as 0xa4[3] (the
    // simulator: the path's spindles), so a one-spindle machine answers.
    let one = text.replacen(
        "[[path.spindle]]\nname = \"S2\"\nspeed = 1500\nload = 7\n",
        "",
        1,
    );
    assert_ne!(one, text);
    let c1 = start(&one);
    let (r, len, b) = axisdata(c1.h, 4, &[0, 1], 4);
    assert_eq!((r, len), (EW_OK, 1));
    assert_eq!(axdt(&b, 0), (*b"S1\0\0", 25, 0, 8, 0));
    assert_eq!(axdt(&b, 4), (*b"S1\0\0", 3000, 0, 5, 0));
    assert_eq!(axisdata(c1.h, 4, &[5], 4).0, EW_ATTRIB);
    // Two spindles: 0xa4[3] = 2 but 0x40[code, 1] one record → EW_PROTOCOL
    // (FANUC's library copies a stale record).
    assert_eq!(axisdata(c.h, 4, &[0], 4).0, EW_PROTOCOL);
}
