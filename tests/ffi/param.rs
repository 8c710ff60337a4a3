//! Parameters and diagnosis data through the C ABI against the simulator:
//! every type read, write-then-read round trips, the CNC's write protection,
//! local checks, and a 16i-class CNC.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::sim::{Machine, Profile};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_char, c_short, c_ushort};

/// The default profile with some text replaced.
fn profile(edits: &[(&str, &str)]) -> Profile {
    let mut t = DEFAULT_PROFILE.to_string();
    for (a, b) in edits {
        assert!(t.contains(a), "default profile lacks {a:?}");
        t = t.replacen(a, b, 1);
    }
    Profile::parse(&t).expect("profile")
}

/// Parameter write enable on, MDI mode.
const WRITABLE: &[(&str, &str)] = &[
    ("param_write_enable = false", "param_write_enable = true"),
    ("aut = 1 ", "aut = 0 "),
];

const S16: &[(&str, &str)] = &[
    ("class = \"30i\"", "class = \"16i\""),
    ("max_axes = 32", "max_axes = 8"),
    ("param_write_enable = false", "param_write_enable = true"),
    ("aut = 1 ", "aut = 0 "),
];

fn rd(h: c_ushort, number: c_short, axis: c_short, length: c_short) -> (c_short, IODBPSD) {
    let mut b = IODBPSD::default();
    let r = unsafe { cnc_rdparam(h, number, axis, length, &mut b) };
    (r, b)
}

fn rd_ok(h: c_ushort, number: c_short, axis: c_short) -> IODBPSD {
    let (r, b) = rd(h, number, axis, 260);
    assert_eq!(r, EW_OK, "cnc_rdparam({number}, {axis})");
    assert_eq!(b.datano, number);
    assert_eq!(b.r#type, axis);
    b
}

fn dg_ok(h: c_ushort, number: c_short, axis: c_short) -> ODBDGN {
    let mut b = ODBDGN::default();
    assert_eq!(
        unsafe { cnc_diagnoss(h, number, axis, 260, &mut b) },
        EW_OK,
        "cnc_diagnoss({number}, {axis})"
    );
    assert_eq!((b.datano, b.r#type), (number, axis));
    let mut c = ODBDGN::default();
    assert_eq!(unsafe { cnc_rddiag(h, number, axis, 260, &mut c) }, EW_OK);
    assert_eq!(unsafe { c.u.ldatas }, unsafe { b.u.ldatas });
    b
}

fn wr(h: c_ushort, length: c_short, mut b: IODBPSD) -> c_short {
    unsafe { cnc_wrparam(h, length, &mut b) }
}

fn psd(number: c_short, axis: c_short, set: impl FnOnce(&mut IODBPSD_u)) -> IODBPSD {
    let mut b = IODBPSD {
        datano: number,
        r#type: axis,
        ..IODBPSD::default()
    };
    set(&mut b.u);
    b
}

#[test]
fn every_type_reads_as_the_profile_says() {
    let (_s, h) = sim::start_alloc(Profile::default());
    unsafe {
        assert_eq!(rd_ok(h, 0, 0).u.cdata, 0b10); // bit
        assert_eq!(rd_ok(h, 20, 0).u.cdata, 4); // byte
        assert_eq!(rd_ok(h, 1825, 2).u.idata, 3000); // word, one axis
        assert_eq!(rd_ok(h, 6711, 0).u.ldata, 1234); // 2-word
        let r = rd_ok(h, 1320, 1).u.rdata; // real
        assert_eq!((r.prm_val, r.dec_val), (800000, 3));
        // All axes: max_axes (32) values, axes beyond the path's three read 0.
        let a = rd_ok(h, 1005, -1).u.cdatas;
        assert_eq!(&a[..4], &[1, 1, 1, 0]);
        let a = rd_ok(h, 1825, -1).u.idatas;
        assert_eq!(&a[..4], &[3000, 3000, 3000, 0]);
        let a = rd_ok(h, 1321, -1).u.rdatas;
        assert_eq!(
            a[..3]
                .iter()
                .map(|r| (r.prm_val, r.dec_val))
                .collect::<Vec<_>>(),
            [(-5000, 3), (-5000, 3), (-500000, 3)]
        );
        assert_eq!(rd_ok(h, 1020, 3).u.cdata, 90);

        assert_eq!(dg_ok(h, 308, 2).u.cdata, 36); // byte
        assert_eq!(dg_ok(h, 411, 3).u.idata, 35); // word
        assert_eq!(dg_ok(h, 752, 1).u.ldata, 298); // 2-word
        assert_eq!(&dg_ok(h, 300, -1).u.ldatas[..4], &[12, -8, 3, 0]);
        assert_eq!(dg_ok(h, 1000, 0).u.cdata, 0); // bit
        let r = dg_ok(h, 4901, 0).u.rdata; // real
        assert_eq!((r.dgn_val, r.dec_val), (235, 1));
    }
}

#[test]
fn read_errors() {
    let (_s, h) = sim::start_alloc(Profile::default());
    assert_eq!(rd(h, 9999, 0, 8).0, EW_NUMBER);
    let mut b = ODBDGN::default();
    assert_eq!(unsafe { cnc_diagnoss(h, 9999, 0, 8, &mut b) }, EW_NUMBER);
    // An axis parameter needs an axis; a non-axis one none; axes beyond the path's.
    assert_eq!(rd(h, 1825, 0, 8).0, EW_ATTRIB);
    assert_eq!(rd(h, 6711, 1, 8).0, EW_ATTRIB);
    assert_eq!(rd(h, 1825, 4, 8).0, EW_ATTRIB);
    // Length below 4 + one value: EW_LENGTH after the exchange, header written.
    let (r, b) = rd(h, 6711, 0, 7);
    assert_eq!(r, EW_LENGTH);
    assert_eq!((b.datano, b.r#type), (6711, 0));
    assert_eq!(rd(h, 1320, 1, 11).0, EW_LENGTH);
    assert_eq!(rd(h, 20, 0, 5).0, EW_OK);
    // NULL pointers, bad handle.
    unsafe {
        assert_eq!(cnc_rdparam(h, 6711, 0, 8, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_diagnoss(h, 300, 1, 8, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rddiag(h, 300, 1, 8, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_wrparam(h, 8, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rdparainfo(h, 0, 1, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rddiaginfo(h, 0, 1, std::ptr::null_mut()), EW_DATA);
        let mut b = IODBPSD::default();
        assert_eq!(cnc_rdparam(0x7fff, 6711, 0, 8, &mut b), EW_HANDLE);
    }
}

#[test]
fn writes_read_back_for_every_type() {
    let (_s, h) = sim::start_alloc(profile(WRITABLE));
    // bit: all eight bits (0x81 reads back as the same char).
    assert_eq!(
        wr(h, 5, psd(1001, 0, |u| u.cdata = 0x81u8 as c_char)),
        EW_OK
    );
    assert_eq!(unsafe { rd_ok(h, 1001, 0).u.cdata } as u8, 0x81);
    // byte, negative
    assert_eq!(wr(h, 5, psd(20, 0, |u| u.cdata = -5i8 as c_char)), EW_OK);
    assert_eq!(unsafe { rd_ok(h, 20, 0).u.cdata }, -5i8 as c_char);
    // word, one axis; the other axes keep theirs
    assert_eq!(wr(h, 6, psd(1825, 2, |u| u.idata = -1234)), EW_OK);
    assert_eq!(
        &unsafe { rd_ok(h, 1825, -1).u.idatas }[..3],
        &[3000, -1234, 3000]
    );
    // 2-word
    assert_eq!(wr(h, 8, psd(6711, 0, |u| u.ldata = 987654321)), EW_OK);
    assert_eq!(unsafe { rd_ok(h, 6711, 0).u.ldata }, 987654321);
    // real, same decimals and other decimals (converted to the parameter's)
    let real = |v, d| {
        psd(1320, 1, move |u| {
            u.rdata = REALPRM {
                prm_val: v,
                dec_val: d,
            }
        })
    };
    assert_eq!(wr(h, 12, real(123456, 3)), EW_OK);
    let r = unsafe { rd_ok(h, 1320, 1).u.rdata };
    assert_eq!((r.prm_val, r.dec_val), (123456, 3));
    assert_eq!(wr(h, 12, real(654, 1)), EW_OK);
    let r = unsafe { rd_ok(h, 1320, 1).u.rdata };
    assert_eq!((r.prm_val, r.dec_val), (65400, 3));
    // a real that cannot be held with the parameter's decimals: EW_DATA, unchanged
    assert_eq!(wr(h, 12, real(1, 4)), EW_DATA);
    assert_eq!(unsafe { rd_ok(h, 1320, 1).u.rdata.prm_val }, 65400);
    // all axes at once: one value per axis of the CNC (max_axes) in the input
    let mut all = psd(1005, -1, |_| {});
    unsafe { all.u.cdatas[..3].copy_from_slice(&[7, 8, 9]) };
    assert_eq!(wr(h, 4 + 32, all), EW_OK);
    assert_eq!(&unsafe { rd_ok(h, 1005, -1).u.cdatas }[..4], &[7, 8, 9, 0]);
    let mut all = psd(1321, -1, |_| {});
    unsafe {
        for (i, r) in all.u.rdatas[..3].iter_mut().enumerate() {
            *r = REALPRM {
                prm_val: -(i as i32 + 1) * 1000,
                dec_val: 3,
            };
        }
    }
    assert_eq!(wr(h, 4 + 8 * 32, all), EW_OK);
    let r = unsafe { rd_ok(h, 1321, -1).u.rdatas };
    assert_eq!(
        r[..3].iter().map(|r| r.prm_val).collect::<Vec<_>>(),
        [-1000, -2000, -3000]
    );
}

#[test]
fn protection_refuses_and_changes_nothing() {
    let part = |h| unsafe { rd_ok(h, 6711, 0).u.ldata };
    let count = |v| psd(6711, 0, move |u| u.ldata = v);

    // Parameter write enable off (the default profile): EW_PASSWD.
    let (s, h) = sim::start_alloc(profile(&[("aut = 1 ", "aut = 0 ")]));
    assert_eq!(wr(h, 8, count(1)), EW_PASSWD);
    assert_eq!(part(h), 1234);
    drop(s);
    // Enabled, but not in MDI mode: EW_PASSWD.
    let (s, h) = sim::start_alloc(profile(&[(
        "param_write_enable = false",
        "param_write_enable = true",
    )]));
    assert_eq!(wr(h, 8, count(1)), EW_PASSWD);
    assert_eq!(part(h), 1234);
    drop(s);

    let (_s, h) = sim::start_alloc(profile(WRITABLE));
    // Unknown number: the attribute read answers EW_NUMBER, nothing is written.
    assert_eq!(wr(h, 8, psd(9999, 0, |u| u.ldata = 1)), EW_NUMBER);
    // Length not 4 + the type's size: EW_LENGTH before the write.
    assert_eq!(wr(h, 6, count(1)), EW_LENGTH);
    assert_eq!(wr(h, 12, count(1)), EW_LENGTH);
    assert_eq!(part(h), 1234);
    // Axis word wrong for the parameter: EW_ATTRIB.
    assert_eq!(wr(h, 8, psd(6711, 1, |u| u.ldata = 1)), EW_ATTRIB);
    assert_eq!(wr(h, 6, psd(1825, 0, |u| u.idata = 1)), EW_ATTRIB);
    assert_eq!(wr(h, 6, psd(1825, 4, |u| u.idata = 1)), EW_ATTRIB);
    assert_eq!(part(h), 1234);
    assert_eq!(
        &unsafe { rd_ok(h, 1825, -1).u.idatas }[..3],
        &[3000, 3000, 3000]
    );
    // Read-only: EW_PROT.
    assert_eq!(wr(h, 5, psd(1020, 1, |u| u.cdata = 65)), EW_PROT);
    assert_eq!(unsafe { rd_ok(h, 1020, 1).u.cdata }, 88);
    // And a good write still works afterwards.
    assert_eq!(wr(h, 8, count(1)), EW_OK);
    assert_eq!(part(h), 1);
}

#[test]
fn info_lists() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let mut b = ODBPARAIF::default();
    assert_eq!(unsafe { cnc_rdparainfo(h, 6711, 3, &mut b) }, EW_OK);
    assert_eq!((b.info_no, b.prev_no, b.next_no), (3, 6710, 6750));
    let got: Vec<_> = b.info[..3].iter().map(|e| (e.prm_no, e.prm_type)).collect();
    assert_eq!(got, [(6711, 3), (6712, 3), (6713, 3)]);
    // The adapter's use: one entry, type & 3.
    assert_eq!(unsafe { cnc_rdparainfo(h, 20, 1, &mut b) }, EW_OK);
    assert_eq!(
        (b.info_no, b.info[0].prm_no, b.info[0].prm_type & 3),
        (1, 20, 1)
    );
    // Axis parameters have bit 8; a start between numbers gives the next one.
    assert_eq!(unsafe { cnc_rdparainfo(h, 1800, 1, &mut b) }, EW_OK);
    assert_eq!((b.info[0].prm_no, b.info[0].prm_type), (1825, 0x102));
    // Never more than read_no entries.
    assert_eq!(unsafe { cnc_rdparainfo(h, 0, 2, &mut b) }, EW_OK);
    assert_eq!(b.info_no, 2);
    assert_eq!(unsafe { cnc_rdparainfo(h, 30000, 1, &mut b) }, EW_NUMBER);

    let mut d = ODBDIAGIF::default();
    assert_eq!(unsafe { cnc_rddiaginfo(h, 411, 2, &mut d) }, EW_OK);
    assert_eq!((d.info_no, d.prev_no, d.next_no), (2, 308, 1000));
    let got: Vec<_> = d.info[..2]
        .iter()
        .map(|e| (e.diag_no, e.diag_type))
        .collect();
    assert_eq!(got, [(411, 0x102), (752, 0x103)]);
}

#[test]
fn series_16i() {
    let (_s, h) = sim::start_alloc(profile(S16));
    unsafe {
        assert_eq!(rd_ok(h, 6711, 0).u.ldata, 1234);
        assert_eq!(rd_ok(h, 20, 0).u.cdata, 4);
        assert_eq!(
            &rd_ok(h, 1825, -1).u.idatas[..9],
            &[3000, 3000, 3000, 0, 0, 0, 0, 0, 0]
        );
        assert_eq!(dg_ok(h, 411, 3).u.idata, 35);
        assert_eq!(&dg_ok(h, 300, -1).u.ldatas[..4], &[12, -8, 3, 0]);
    }
    assert_eq!(wr(h, 8, psd(6711, 0, |u| u.ldata = -77)), EW_OK);
    assert_eq!(unsafe { rd_ok(h, 6711, 0).u.ldata }, -77);
    assert_eq!(wr(h, 6, psd(1825, 3, |u| u.idata = 2500)), EW_OK);
    assert_eq!(unsafe { rd_ok(h, 1825, 3).u.idata }, 2500);
    assert_eq!(wr(h, 5, psd(1020, 1, |u| u.cdata = 65)), EW_PROT);
    let mut b = ODBPARAIF::default();
    assert_eq!(unsafe { cnc_rdparainfo(h, 6711, 1, &mut b) }, EW_OK);
    assert_eq!(
        (b.info_no, b.info[0].prm_no, b.info[0].prm_type),
        (1, 6711, 3)
    );
}

#[test]
fn the_machine_sets_parameters_itself() {
    let mut m = Machine::new(Profile::default());
    assert_eq!(m.param_value(6711, 0), Some(1234));
    assert!(m.set_param_value(6711, 0, 1235));
    assert_eq!(m.param_value(6711, 0), Some(1235));
    assert!(m.set_param_value(1825, 2, 100));
    assert_eq!(m.param_value(1825, 2), Some(100));
    assert!(!m.set_param_value(9999, 0, 1));
    m.set_param_write_enable(true);
    assert!(m.profile.param.param_write_enable);
}

#[test]
fn ext_reads_and_number_ranges() {
    let (_s, h) = sim::start_alloc(Profile::default());
    // 32-bit numbers (FANUC's x86-64 library reads `long *` 4 bytes apart);
    // 10 numbers = two exchanges of 8 and 2; 9999 does not exist.
    let mut nos: Vec<i32> = vec![6711, 1320, 9999, 20, 0, 1001, 1005, 1020, 1420, 6712];
    let mut out = vec![IODBPRM::default(); nos.len()];
    let r = unsafe { cnc_rdparam_ext(h, nos.as_mut_ptr().cast(), 10, out.as_mut_ptr()) };
    assert_eq!(r, EW_OK);
    assert_eq!((out[0].datano, out[0].r#type, out[0].axis), (6711, 3, 0));
    assert_eq!(
        out[0].data[0],
        IODBPRM_data {
            prm_val: 1234,
            dec_val: 0
        }
    );
    assert_eq!((out[1].datano, out[1].r#type, out[1].axis), (1320, 4, 3));
    let d: Vec<_> = out[1].data[..4]
        .iter()
        .map(|d| (d.prm_val, d.dec_val))
        .collect();
    assert_eq!(d, [(800000, 3), (500000, 3), (0, 3), (0, 3)]);
    assert_eq!((out[2].datano, out[2].r#type), (9999, -1));
    assert_eq!((out[9].datano, out[9].data[0].prm_val), (6712, 56789));

    let mut nos: Vec<i32> = vec![411, 4901];
    let r = unsafe { cnc_rddiag_ext(h, nos.as_mut_ptr().cast(), 2, out.as_mut_ptr()) };
    assert_eq!(r, EW_OK);
    assert_eq!((out[0].datano, out[0].r#type, out[0].axis), (411, 1, 3));
    assert_eq!(out[0].data[2].prm_val, 35);
    assert_eq!(
        (
            out[1].r#type,
            out[1].data[0].prm_val,
            out[1].data[0].dec_val
        ),
        (5, 235, 1)
    );

    let p = Profile::default();
    let mut n = ODBPARANUM::default();
    assert_eq!(unsafe { cnc_rdparanum(h, &mut n) }, EW_OK);
    let all = &p.param.parameters;
    assert_eq!(
        (n.para_min, n.para_max, n.total_no),
        (
            all[0].number as u16,
            all[all.len() - 1].number as u16,
            all.len() as u16
        )
    );
    let mut d = ODBDIAGNUM::default();
    assert_eq!(unsafe { cnc_rddiagnum(h, &mut d) }, EW_OK);
    assert_eq!((d.diag_min, d.diag_max), (300, 5202));
    unsafe {
        assert_eq!(cnc_rdparanum(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rddiagnum(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(
            cnc_rdparam_ext(h, std::ptr::null_mut(), 1, out.as_mut_ptr()),
            EW_DATA
        );
    }
}

// --- cnc_rdparar / cnc_wrparas ---

/// cnc_rdparar into a buffer of `len` bytes followed by 16 guard bytes
/// (all 0xCC before the call): (return, *e_number, *length, buffer);
/// `*s_number` must come back as `s_out` (the first number read).
fn rdr_s(
    h: c_ushort,
    s: c_short,
    s_out: c_short,
    axis: c_short,
    e: c_short,
    len: c_short,
) -> (c_short, c_short, c_short, Vec<u8>) {
    let mut buf = vec![0xccu8; len.max(0) as usize + 16];
    let (mut s_no, mut e_no, mut length) = (s, e, len);
    let r = unsafe {
        cnc_rdparar(
            h,
            &mut s_no,
            axis,
            &mut e_no,
            &mut length,
            buf.as_mut_ptr().cast(),
        )
    };
    assert_eq!(s_no, s_out, "*s_number");
    assert!(
        buf[len.max(0) as usize..].iter().all(|b| *b == 0xcc),
        "written past *length"
    );
    (r, e_no, length, buf)
}

/// A packed record: number, type word, value bytes (before padding).
#[derive(Debug, PartialEq)]
struct Rec {
    number: i16,
    typ: u16,
    data: Vec<u8>,
}

fn size_of(typ: u16) -> usize {
    [1, 1, 2, 4, 8][(typ >> 8) as usize]
}

/// Splits `used` bytes of cnc_rdparar output into records (max_axes 32).
/// cnc_rdparar where `*s_number` stays (an error, or `s` exists).
fn rdr(
    h: c_ushort,
    s: c_short,
    axis: c_short,
    e: c_short,
    len: c_short,
) -> (c_short, c_short, c_short, Vec<u8>) {
    rdr_s(h, s, s, axis, e, len)
}

fn records(buf: &[u8]) -> Vec<Rec> {
    let mut out = Vec::new();
    let mut at = 0;
    while at < buf.len() {
        let number = i16::from_le_bytes([buf[at], buf[at + 1]]);
        let typ = u16::from_le_bytes([buf[at + 2], buf[at + 3]]);
        let n = if typ & 0xff == 0xff { 32 } else { 1 };
        let end = at + 4 + n * size_of(typ);
        out.push(Rec {
            number,
            typ,
            data: buf[at + 4..end].to_vec(),
        });
        at = (end + 3) & !3;
    }
    out
}

fn rec(number: i16, ptype: u8, axis: i8, data: &[u8]) -> Vec<u8> {
    let mut b = number.to_le_bytes().to_vec();
    b.push(axis as u8);
    b.push(ptype);
    b.extend_from_slice(data);
    while !b.len().is_multiple_of(4) {
        b.push(0);
    }
    b
}

fn real(v: i32, d: i32) -> Vec<u8> {
    [v.to_le_bytes(), d.to_le_bytes()].concat()
}

fn wrs(h: c_ushort, recs: &[Vec<u8>]) -> c_short {
    let mut b = recs.concat();
    unsafe { cnc_wrparas(h, b.len() as c_short, b.as_mut_ptr().cast()) }
}

#[test]
fn rdparar_reads_ranges() {
    let (_s, h) = sim::start_alloc(Profile::default());
    // 6700..6760: twelve parameters, answers of five, five and two;
    // padding is not written.
    let (r, e, len, buf) = rdr(h, 6700, 0, 6760, 200);
    assert_eq!(r, EW_OK);
    assert_eq!((e, len), (6758, 96));
    assert!(buf[96..].iter().all(|b| *b == 0xcc));
    let got = records(&buf[..96]);
    let numbers: Vec<i16> = got.iter().map(|r| r.number).collect();
    assert_eq!(
        numbers,
        [
            6700, 6710, 6711, 6712, 6713, 6750, 6751, 6752, 6753, 6754, 6757, 6758
        ]
    );
    assert_eq!(
        got[0],
        Rec {
            number: 6700,
            typ: 0x0000,
            data: vec![0]
        }
    );
    assert_eq!(
        got[1],
        Rec {
            number: 6710,
            typ: 0x0200,
            data: 30i16.to_le_bytes().to_vec()
        }
    );
    assert_eq!(
        got[2],
        Rec {
            number: 6711,
            typ: 0x0300,
            data: 1234i32.to_le_bytes().to_vec()
        }
    );
    assert_eq!(
        &buf[5..8],
        &[0xcc; 3],
        "padding of the bit record untouched"
    );
    assert_eq!(
        &buf[14..16],
        &[0xcc; 2],
        "padding of the word record untouched"
    );

    // Axis 0 over axis parameters: those answer all axes (type word 0x..ff).
    // *s_number becomes the first number read. (Up to 1022: parameter 1023,
    // the servo axis numbers, would not fit.)
    let (r, e, len, buf) = rdr_s(h, 1000, 1001, 0, 1022, 100);
    assert_eq!((r, e, len), (EW_OK, 1020, 8 + 36 + 36));
    let got = records(&buf[..80]);
    assert_eq!(
        got[0],
        Rec {
            number: 1001,
            typ: 0x0000,
            data: vec![0]
        }
    );
    assert_eq!((got[1].number, got[1].typ), (1005, 0x00ff));
    assert_eq!(&got[1].data[..4], &[1, 1, 1, 0]);
    assert_eq!((got[2].number, got[2].typ), (1020, 0x01ff));
    assert_eq!(&got[2].data[..4], &[88, 89, 90, 0]);

    // Reals of one axis: value and decimals.
    let (r, e, len, buf) = rdr(h, 1320, 2, 1420, 100);
    assert_eq!((r, e, len), (EW_OK, 1420, 36));
    let got = records(&buf[..36]);
    assert_eq!(
        got[0],
        Rec {
            number: 1320,
            typ: 0x0402,
            data: real(500000, 3)
        }
    );
    assert_eq!(
        got[1],
        Rec {
            number: 1321,
            typ: 0x0402,
            data: real(-5000, 3)
        }
    );
    assert_eq!(
        got[2],
        Rec {
            number: 1420,
            typ: 0x0402,
            data: real(48000, 0)
        }
    );

    // All axes: every parameter with max_axes values.
    let (r, e, len, buf) = rdr(h, 1320, -1, 1321, 600);
    assert_eq!((r, e, len), (EW_OK, 1321, 2 * (4 + 256)));
    let got = records(&buf[..520]);
    assert_eq!(got[1].typ, 0x04ff);
    assert_eq!(&got[1].data[16..24], &real(-500000, 3)[..]);
    assert_eq!(&got[1].data[24..32], &real(0, 3)[..]);

    // One number (the request cnc_rdparam sends).
    let (r, e, len, buf) = rdr(h, 6711, 0, 6711, 8);
    assert_eq!((r, e, len), (EW_OK, 6711, 8));
    assert_eq!(records(&buf[..8])[0].data, 1234i32.to_le_bytes());
}

#[test]
fn rdparar_errors() {
    let (_s, h) = sim::start_alloc(Profile::default());
    // Start above end: EW_NUMBER without traffic; nothing written.
    let (r, e, len, buf) = rdr(h, 6711, 0, 6700, 100);
    assert_eq!((r, e, len), (EW_NUMBER, 6700, 100));
    assert!(buf.iter().all(|b| *b == 0xcc));
    // No parameter in the range.
    assert_eq!(rdr(h, 2, 0, 19, 100).0, EW_NUMBER);
    // An axis beyond the path's.
    assert_eq!(rdr(h, 1000, 4, 1030, 100).0, EW_ATTRIB);
    // Too small: the records that fit stay, and the next one's header if it
    // fits whole; *length and *e_number unchanged; never past *length.
    let (r, e, len, buf) = rdr(h, 6710, 0, 6713, 12);
    assert_eq!((r, e, len), (EW_LENGTH, 6713, 12));
    assert_eq!(&buf[..4], &[0x36, 0x1a, 0x00, 0x02]);
    assert_eq!(&buf[8..12], &[0x37, 0x1a, 0x00, 0x03]);
    let (r, _, _, buf) = rdr(h, 6710, 0, 6713, 10);
    assert_eq!(r, EW_LENGTH);
    assert_eq!(&buf[8..10], &[0xcc, 0xcc]);
    // A record fits only with its padding (FANUC's library: a word record
    // in 6 bytes is EW_LENGTH with only its header written); *s_number stays.
    let (r, _, _, buf) = rdr(h, 6701, 0, 6713, 6);
    assert_eq!(r, EW_LENGTH);
    assert_eq!(&buf[..6], &[0x36, 0x1a, 0x00, 0x02, 0xcc, 0xcc]);
    let (r, _, _, buf) = rdr(h, 6710, 0, 6713, 0);
    assert_eq!(r, EW_LENGTH);
    assert!(buf.iter().all(|b| *b == 0xcc));
    // NULL pointers, bad handle.
    let (mut s, mut e, mut l) = (6700 as c_short, 6760 as c_short, 100 as c_short);
    let mut buf = [0u8; 100];
    let p = buf.as_mut_ptr().cast();
    let null = std::ptr::null_mut();
    unsafe {
        assert_eq!(cnc_rdparar(h, null, 0, &mut e, &mut l, p), EW_DATA);
        assert_eq!(cnc_rdparar(h, &mut s, 0, null, &mut l, p), EW_DATA);
        assert_eq!(cnc_rdparar(h, &mut s, 0, &mut e, null, p), EW_DATA);
        assert_eq!(
            cnc_rdparar(h, &mut s, 0, &mut e, &mut l, null.cast()),
            EW_DATA
        );
        assert_eq!(cnc_rdparar(0x7fff, &mut s, 0, &mut e, &mut l, p), EW_HANDLE);
        assert_eq!(cnc_wrparas(h, 8, null.cast()), EW_DATA);
        assert_eq!(cnc_wrparas(0x7fff, 8, p), EW_HANDLE);
    }
}

#[test]
fn wrparas_writes_every_type_and_reads_back() {
    let (_s, h) = sim::start_alloc(profile(WRITABLE));
    let mut bits = vec![0u8; 32];
    bits[..3].copy_from_slice(&[7, 8, 9]);
    // Six records: two exchanges (5 + 1).
    let recs = [
        rec(1001, 0, 0, &[0x81]),
        rec(20, 1, 0, &[(-5i8) as u8]),
        rec(1825, 2, 2, &(-1234i16).to_le_bytes()),
        rec(6711, 3, 0, &987654321i32.to_le_bytes()),
        rec(1320, 4, 1, &real(654, 1)),
        rec(1005, 0, -1, &bits),
    ];
    assert_eq!(wrs(h, &recs), EW_OK);
    unsafe {
        assert_eq!(rd_ok(h, 1001, 0).u.cdata as u8, 0x81);
        assert_eq!(rd_ok(h, 20, 0).u.cdata, -5i8 as c_char);
        assert_eq!(&rd_ok(h, 1825, -1).u.idatas[..3], &[3000, -1234, 3000]);
        assert_eq!(rd_ok(h, 6711, 0).u.ldata, 987654321);
        let r = rd_ok(h, 1320, 1).u.rdata;
        assert_eq!((r.prm_val, r.dec_val), (65400, 3)); // converted to the parameter's decimals
        assert_eq!(&rd_ok(h, 1005, -1).u.cdatas[..4], &[7, 8, 9, 0]);
    }
    // What cnc_rdparar reads, cnc_wrparas writes back unchanged.
    let (r, _, len, mut buf) = rdr(h, 6710, 0, 6713, 100);
    assert_eq!(r, EW_OK);
    assert_eq!(
        unsafe { cnc_wrparas(h, len, buf.as_mut_ptr().cast()) },
        EW_OK
    );
    let (_, _, len2, buf2) = rdr(h, 6710, 0, 6713, 100);
    assert_eq!(&buf2[..len2 as usize], &buf[..len as usize]);
    // length 0 writes nothing.
    assert_eq!(unsafe { cnc_wrparas(h, 0, buf.as_mut_ptr().cast()) }, EW_OK);
}

#[test]
fn wrparas_protection_and_local_checks() {
    let part = |h| unsafe { rd_ok(h, 6711, 0).u.ldata };
    let count = |v: i32| rec(6711, 3, 0, &v.to_le_bytes());

    // Parameter write enable off: EW_PASSWD, nothing written.
    let (s, h) = sim::start_alloc(profile(&[("aut = 1 ", "aut = 0 ")]));
    assert_eq!(wrs(h, &[count(1), rec(20, 1, 0, &[9])]), EW_PASSWD);
    assert_eq!(part(h), 1234);
    assert_eq!(unsafe { rd_ok(h, 20, 0).u.cdata }, 4);
    drop(s);

    let (_s, h) = sim::start_alloc(profile(WRITABLE));
    // One refused record in an exchange: the simulator checks every record
    // of the subpacket first and applies none (a real CNC writes the ones
    // before the refused one).
    assert_eq!(wrs(h, &[count(1), rec(1020, 1, 1, &[65])]), EW_PROT);
    assert_eq!(wrs(h, &[count(1), rec(9999, 3, 0, &[0; 4])]), EW_NUMBER);
    assert_eq!(wrs(h, &[count(1), rec(20, 2, 0, &[1, 0])]), EW_ATTRIB); // wrong type
    assert_eq!(wrs(h, &[count(1), rec(1825, 2, 0, &[1, 0])]), EW_ATTRIB); // axis needed
    assert_eq!(part(h), 1234);
    assert_eq!(unsafe { rd_ok(h, 1020, 1).u.cdata }, 88);
    // Exchanges before the refused one stay written: five go in the first.
    let five: Vec<_> = (0..5).map(|_| count(77)).collect();
    assert_eq!(
        wrs(h, &[five, vec![rec(1020, 1, 1, &[65])]].concat()),
        EW_PROT
    );
    assert_eq!(part(h), 77);

    // Local checks, no traffic: a record longer than length, an unknown type.
    let mut b = count(5);
    for l in 1..8 {
        assert_eq!(
            unsafe { cnc_wrparas(h, l, b.as_mut_ptr().cast()) },
            EW_LENGTH,
            "length {l}"
        );
    }
    let mut two = [count(6), count(7)].concat();
    assert_eq!(
        unsafe { cnc_wrparas(h, 12, two.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    // A record of an unknown type is its 4-byte header alone (as FANUC's
    // library reads it): the next 4 bytes are a bit record needing 5.
    let mut bad = rec(6711, 5, 0, &[0; 4]);
    assert_eq!(
        unsafe { cnc_wrparas(h, 8, bad.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    assert_eq!(part(h), 77);
}

#[test]
fn rdparar_wrparas_series_16i() {
    // The 16i word blocks (0x000e / 0x000f) carry what the 30i record
    // blocks (0x008d / 0x008e) carry: the same packed records on both.
    let s30: &[(&str, &str)] = &[
        ("max_axes = 32", "max_axes = 8"),
        ("param_write_enable = false", "param_write_enable = true"),
        ("aut = 1 ", "aut = 0 "),
    ];
    let (_a, h30) = sim::start_alloc(profile(s30));
    let (_b, h16) = sim::start_alloc(profile(S16));
    for (s, axis, e, ok) in [
        (6700, 0, 6760, true),
        (1001, -1, 1500, true),
        (1320, 1, 1330, true),
        (0, 0, 9999, true),
    ] {
        // Room for the whole built-in table.
        let a = rdr(h30, s, axis, e, 1000);
        assert_eq!(a, rdr(h16, s, axis, e, 1000), "{s}..{e} axis {axis}");
        assert_eq!(a.0 == EW_OK, ok, "{s}..{e} axis {axis}: {}", a.0);
    }
    // Writes: two 0x000f blocks of 8 + 4 · 8 bytes in one exchange.
    let count = |v: i32| rec(6711, 3, 0, &v.to_le_bytes());
    let seven = rec(6712, 3, 0, &7i32.to_le_bytes());
    assert_eq!(wrs(h16, &[count(42), seven]), EW_OK);
    assert_eq!(unsafe { rd_ok(h16, 6711, 0).u.ldata }, 42);
    assert_eq!(unsafe { rd_ok(h16, 6712, 0).u.ldata }, 7);
}

/// A non-axis parameter read for all axes (cnc_rdparam(h, 6711, -1, 8, ..),
/// as MTConnect adapters read the part counter): the simulator answers it as
/// a non-axis parameter (axis word 0, one value), which FANUC's library and
/// ours read as one value, so length 8 is enough.
#[test]
fn non_axis_parameter_read_with_all_axes() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let (r, b) = rd(h, 6711, -1, 8);
    assert_eq!(r, EW_OK);
    assert_eq!((b.datano, b.r#type), (6711, 0));
    assert_eq!(
        unsafe { (b.u.ldata, rd_ok(h, 6711, 0).u.ldata) },
        (1234, 1234)
    );
    // A diagnosis item the same way.
    let mut d = ODBDGN::default();
    assert_eq!(unsafe { cnc_diagnoss(h, 1000, -1, 5, &mut d) }, EW_OK);
    assert_eq!((d.datano, d.r#type), (1000, 0));
    // An axis parameter read for all axes needs room for every axis.
    assert_eq!(rd(h, 1825, -1, 8).0, EW_LENGTH);
    sim::free(h);
}

#[test]
fn rdparainfo3_lists_the_parameter_table_with_its_neighbours() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let mut b = [fwlib32::types::ODBPARAIF2::default(); 4];
    let (mut num, mut prev, mut next) = (4i16, 0i16, 0i16);
    let r = unsafe { cnc_rdparainfo3(h, 1320, &mut num, &mut prev, &mut next, b.as_mut_ptr()) };
    assert_eq!(r, EW_OK);
    assert_eq!(num, 4);
    assert_eq!((b[0].prm_no, b[0].size, b[0].array), (1320, 4, 2));
    assert!(prev < 1320 && next > b[3].prm_no);
    num = 0;
    let r = unsafe { cnc_rdparainfo3(h, 1320, &mut num, &mut prev, &mut next, b.as_mut_ptr()) };
    assert_eq!(r, EW_LENGTH);
}
