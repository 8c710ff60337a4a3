//! Tool and work offsets and tool life through the C ABI against the
//! simulator: reads equal the profile, writes read back (the write encoder
//! is the read decoder reversed), protection, NULL pointers, bad lengths.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_short, c_ushort};

fn default() -> (Simulator, c_ushort) {
    sim::start_alloc(Profile::default())
}

fn rdtofs(h: c_ushort, n: c_short, t: c_short) -> Result<i32, c_short> {
    let mut o = ODBTOFS::default();
    match unsafe { cnc_rdtofs(h, n, t, 8, &mut o) } {
        EW_OK => {
            assert_eq!((o.datano, o.r#type), (n, t));
            Ok(o.data)
        }
        e => Err(e),
    }
}

fn rdzofs_all(h: c_ushort, n: c_short) -> Result<IODBZOFS, c_short> {
    let mut z = IODBZOFS::default();
    match unsafe { cnc_rdzofs(h, n, -1, 132, &mut z) } {
        EW_OK => Ok(z),
        e => Err(e),
    }
}

#[test]
fn tool_offsets_read_the_profile() {
    let (_s, h) = default();
    let p = Profile::default();
    let tool = &p.paths[0].offset.tool;
    for (i, row) in tool.iter().enumerate() {
        for (t, v) in row.iter().enumerate() {
            assert_eq!(rdtofs(h, i as c_short + 1, t as c_short), Ok(*v));
        }
    }
    let mut info = ODBTLINF::default();
    assert_eq!(unsafe { cnc_rdtofsinfo(h, &mut info) }, EW_OK);
    assert_eq!(info.use_no as usize, tool.len());
    assert_eq!(info.ofs_type, p.paths[0].offset.memory);

    // A range of one type, and all types of each offset (type -1).
    let mut r: IODBTO = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { cnc_rdtofsr(h, 1, 3, 3, 8 + 3 * 4, &mut r) }, EW_OK);
    assert_eq!((r.datano_s, r.r#type, r.datano_e), (1, 3, 3));
    let m = unsafe { r.u.m_ofs };
    assert_eq!(&m[..3], &[tool[0][3], tool[1][3], tool[2][3]]);
    let mut r: IODBTO = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { cnc_rdtofsr(h, 1, -1, 2, 188, &mut r) }, EW_OK);
    let all: Vec<i32> = tool[..2].iter().flatten().copied().collect();
    assert_eq!(unsafe { &r.u.m_ofs_c[..8] }, &all[..]);
    sim::free(h);
}

#[test]
fn tool_offset_write_then_read_every_type() {
    let (_s, h) = default();
    // Radius wear/geometry (0/1) and length wear/geometry (2/3).
    for (n, t, v) in [(1, 0, -25), (1, 1, 5012), (2, 2, -333), (2, 3, 150_001)] {
        assert_eq!(unsafe { cnc_wrtofs(h, n, t, 8, v) }, EW_OK);
        assert_eq!(rdtofs(h, n, t), Ok(v as i32));
    }
    // Other types of the same offset are unchanged.
    let p = Profile::default();
    assert_eq!(rdtofs(h, 1, 2), Ok(p.paths[0].offset.tool[0][2]));
    // A `long` is sent as its low 32 bits.
    assert_eq!(unsafe { cnc_wrtofs(h, 3, 3, 8, 0x1_0000_0007) }, EW_OK);
    assert_eq!(rdtofs(h, 3, 3), Ok(7));
    sim::free(h);
}

#[test]
fn tool_offset_protection() {
    let (_s, h) = default();
    let before = rdtofs(h, 1, 1).unwrap();
    unsafe {
        // Unknown numbers, wrong types: the CNC refuses, nothing changes.
        assert_eq!(cnc_wrtofs(h, 0, 1, 8, 1), EW_NUMBER);
        assert_eq!(cnc_wrtofs(h, 99, 1, 8, 1), EW_NUMBER);
        assert_eq!(cnc_wrtofs(h, 1, 4, 8, 1), EW_ATTRIB);
        assert_eq!(cnc_wrtofs(h, 1, -1, 8, 1), EW_ATTRIB);
        // Bad length: refused before any traffic.
        assert_eq!(cnc_wrtofs(h, 1, 1, 7, 1), EW_LENGTH);
        let mut o = ODBTOFS::default();
        assert_eq!(cnc_rdtofs(h, 1, 1, 7, &mut o), EW_LENGTH);
        assert_eq!(cnc_rdtofs(h, 99, 1, 8, &mut o), EW_NUMBER);
        assert_eq!(cnc_rdtofs(h, 1, 9, 8, &mut o), EW_ATTRIB);
        assert_eq!(o, ODBTOFS::default(), "nothing written on errors");
        assert_eq!(cnc_rdtofs(h, 1, 1, 8, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rdtofsinfo(h, std::ptr::null_mut()), EW_DATA);
        let mut r: IODBTO = std::mem::zeroed();
        assert_eq!(cnc_rdtofsr(h, 1, 0, 3, 19, &mut r), EW_LENGTH);
        assert_eq!(cnc_rdtofsr(h, 3, 0, 1, 100, &mut r), EW_NUMBER);
        assert_eq!(cnc_rdtofsr(h, 1, 0, 3, 100, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rdtofs(0, 1, 1, 8, &mut o), EW_HANDLE);
        assert_eq!(cnc_wrtofs(0, 1, 1, 8, 1), EW_HANDLE);
    }
    assert_eq!(rdtofs(h, 1, 1), Ok(before));
    sim::free(h);
}

#[test]
fn work_offsets_read_the_profile() {
    let (_s, h) = default();
    let p = Profile::default();
    let work = &p.paths[0].offset.work;
    for (n, row) in work.iter().enumerate() {
        let z = rdzofs_all(h, n as c_short).unwrap();
        assert_eq!((z.datano, z.r#type), (n as c_short, -1));
        assert_eq!(&z.data[..3], &row[..]);
        assert!(
            z.data[3..].iter().all(|v| *v == 0),
            "axes beyond the machine's read 0"
        );
        for (a, v) in row.iter().enumerate() {
            let mut z = IODBZOFS::default();
            assert_eq!(
                unsafe { cnc_rdzofs(h, n as c_short, a as c_short + 1, 8, &mut z) },
                EW_OK
            );
            assert_eq!(
                (z.datano, z.r#type, z.data[0]),
                (n as c_short, a as c_short + 1, *v)
            );
        }
    }
    let mut no: c_short = 0;
    assert_eq!(unsafe { cnc_rdzofsinfo(h, &mut no) }, EW_OK);
    assert_eq!(no as usize, work.len() - 1);

    // A range, all axes: 32 values per offset; datano_e from the answer.
    let mut r: IODBZOR = unsafe { std::mem::zeroed() };
    assert_eq!(
        unsafe { cnc_rdzofsr(h, 1, -1, 2, 8 + 2 * 128, &mut r) },
        EW_OK
    );
    assert_eq!((r.datano_s, r.r#type, r.datano_e), (1, -1, 2));
    assert_eq!(&r.data[..3], &work[1][..]);
    assert_eq!(&r.data[32..35], &work[2][..]);
    // One axis of G54..G59.
    let mut r: IODBZOR = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { cnc_rdzofsr(h, 1, 2, 6, 8 + 6 * 4, &mut r) }, EW_OK);
    let ys: Vec<i32> = work[1..7].iter().map(|w| w[1]).collect();
    assert_eq!(&r.data[..6], &ys[..]);
    assert_eq!(r.datano_e, 6);
    sim::free(h);
}

#[test]
fn work_offset_write_then_read_per_axis_and_all_axes() {
    let (_s, h) = default();
    // Per axis.
    for (n, a, v) in [(1, 1, -100_000), (1, 3, 12_345), (0, 2, -7)] {
        let mut z = IODBZOFS {
            datano: n,
            r#type: a,
            ..IODBZOFS::default()
        };
        z.data[0] = v;
        assert_eq!(unsafe { cnc_wrzofs(h, 8, &mut z) }, EW_OK);
        let mut back = IODBZOFS::default();
        assert_eq!(unsafe { cnc_rdzofs(h, n, a, 8, &mut back) }, EW_OK);
        assert_eq!(back.data[0], v);
    }
    // All axes: the machine's three take the values.
    let mut z = IODBZOFS {
        datano: 4,
        r#type: -1,
        ..IODBZOFS::default()
    };
    z.data[..3].copy_from_slice(&[111, -222, 333]);
    assert_eq!(unsafe { cnc_wrzofs(h, 132, &mut z) }, EW_OK);
    let back = rdzofs_all(h, 4).unwrap();
    assert_eq!(&back.data[..3], &[111, -222, 333]);
    // G54's Y kept its profile value next to the written X and Z.
    let p = Profile::default();
    let g54 = rdzofs_all(h, 1).unwrap();
    assert_eq!(
        &g54.data[..3],
        &[-100_000, p.paths[0].offset.work[1][1], 12_345]
    );
    sim::free(h);
}

#[test]
fn work_offset_protection() {
    let (_s, h) = default();
    let before = rdzofs_all(h, 1).unwrap();
    unsafe {
        let mut z = IODBZOFS {
            datano: 1,
            r#type: 1,
            ..IODBZOFS::default()
        };
        z.data = [9; 32];
        // Lengths: refused before traffic.
        assert_eq!(cnc_wrzofs(h, 7, &mut z), EW_LENGTH);
        z.r#type = -1;
        assert_eq!(cnc_wrzofs(h, 131, &mut z), EW_LENGTH);
        z.r#type = -2;
        assert_eq!(cnc_wrzofs(h, 131, &mut z), EW_LENGTH);
        // Axis beyond the CNC's: local; beyond the machine's: the CNC's.
        z.r#type = 33;
        assert_eq!(cnc_wrzofs(h, 8, &mut z), EW_ATTRIB);
        z.r#type = 4;
        assert_eq!(cnc_wrzofs(h, 8, &mut z), EW_ATTRIB);
        z.r#type = 0;
        assert_eq!(cnc_wrzofs(h, 8, &mut z), EW_ATTRIB);
        // Unknown number.
        z.r#type = 1;
        z.datano = 7;
        assert_eq!(cnc_wrzofs(h, 8, &mut z), EW_NUMBER);
        z.datano = -1;
        assert_eq!(cnc_wrzofs(h, 8, &mut z), EW_NUMBER);
        assert_eq!(cnc_wrzofs(h, 8, std::ptr::null_mut()), EW_DATA);

        let mut o = IODBZOFS::default();
        assert_eq!(cnc_rdzofs(h, 1, 1, 7, &mut o), EW_LENGTH);
        assert_eq!(cnc_rdzofs(h, 1, -1, 131, &mut o), EW_LENGTH);
        assert_eq!(cnc_rdzofs(h, 1, 33, 8, &mut o), EW_ATTRIB);
        assert_eq!(cnc_rdzofs(h, 1, 1, 8, std::ptr::null_mut()), EW_DATA);
        assert_eq!(o, IODBZOFS::default(), "nothing written on local errors");
        // The CNC's error: the header and a zero first value are written
        // (as FANUC's library).
        assert_eq!(cnc_rdzofs(h, 9, 1, 8, &mut o), EW_NUMBER);
        assert_eq!((o.datano, o.r#type, o.data[0]), (9, 1, 0));
        let mut r: IODBZOR = std::mem::zeroed();
        assert_eq!(cnc_rdzofsr(h, 3, 1, 1, 100, &mut r), EW_NUMBER);
        // More values than `length` holds: EW_LENGTH after the exchange, nothing written.
        assert_eq!(cnc_rdzofsr(h, 1, 1, 6, 8 + 5 * 4, &mut r), EW_LENGTH);
        assert_eq!(r.datano_s, 0);
        assert_eq!(cnc_rdzofsinfo(h, std::ptr::null_mut()), EW_DATA);
    }
    let after = rdzofs_all(h, 1).unwrap();
    assert_eq!(after, before, "rejected writes change nothing");
    sim::free(h);
}

#[test]
fn tool_life_groups() {
    let (_s, h) = default();
    let p = Profile::default();
    let g = &p.paths[0].tool_groups[0];
    let mut l = ODBTLIFE3 {
        dummy: 77,
        ..ODBTLIFE3::default()
    };
    assert_eq!(unsafe { cnc_rdlife(h, g.number as c_short, &mut l) }, EW_OK);
    assert_eq!(
        (l.datano, l.dummy, l.data),
        (g.number as c_short, 77, g.life)
    );
    assert_eq!(
        unsafe { cnc_rdcount(h, g.number as c_short, &mut l) },
        EW_OK
    );
    assert_eq!(l.data, g.count);

    let mut t = ODBTG::default();
    let len = std::mem::size_of::<ODBTG>() as c_short;
    assert_eq!(
        unsafe { cnc_rdtoolgrp(h, g.number as c_short, len, &mut t) },
        EW_OK
    );
    assert_eq!(
        (t.grp_num, t.ntool, t.life, t.count),
        (g.number as c_short, g.tools.len() as i32, g.life, g.count)
    );
    for (i, x) in g.tools.iter().enumerate() {
        let d = t.data[i];
        assert_eq!(
            (d.tuse_num, d.tool_num, d.length_num, d.radius_num, d.tinfo),
            (i as i32 + 1, x.number, x.length, x.radius, x.info)
        );
    }
    unsafe {
        assert_eq!(cnc_rdlife(h, 99, &mut l), EW_NUMBER);
        assert_eq!(cnc_rdcount(h, 1, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rdtoolgrp(h, 1, 19, &mut t), EW_LENGTH);
        // Room for the head and one tool, the group has two: EW_LENGTH
        // with the head written, as FANUC's library writes it.
        let mut t = ODBTG::default();
        assert_eq!(cnc_rdtoolgrp(h, 1, 40, &mut t), EW_LENGTH);
        assert_eq!(t.grp_num, 1);
        assert_eq!(t.ntool, 2);
        assert_eq!(t.data[0].tool_num, 0);
        // A punch-press function: a mill refuses it without traffic.
        let mut c = IODBTLCTL::default();
        assert_eq!(cnc_rdtlctldata(h, &mut c), EW_FUNC);
        assert_eq!(cnc_rdtlctldata(h, std::ptr::null_mut()), EW_DATA);
    }
    sim::free(h);
}

/// cnc_deltlifedt and cnc_deltlifegrp change the tool life table the reads
/// answer from; a refused delete (absent group or tool) changes nothing.
#[test]
fn tool_life_deletes_change_the_table() {
    let (_s, h) = default();
    let p = Profile::default();
    let g = &p.paths[0].tool_groups[0];
    let n = g.number as c_short;
    let (mut groups, mut t) = (ODBTLIFE2::default(), ODBTLIFE3::default());
    unsafe {
        assert_eq!(
            cnc_deltlifedt(h, n, g.tools.len() as c_short + 1),
            EW_NUMBER
        );
        assert_eq!(cnc_deltlifegrp(h, 9999), EW_NUMBER);
        assert_eq!(cnc_rdntool(h, n, &mut t), EW_OK);
        assert_eq!(t.data, g.tools.len() as i32);
        assert_eq!(cnc_deltlifedt(h, n, 1), EW_OK);
        assert_eq!(cnc_rdntool(h, n, &mut t), EW_OK);
        assert_eq!(t.data, g.tools.len() as i32 - 1);
        // The second tool moved up to use number 1.
        let mut one = ODBTLIFE4::default();
        assert_eq!(cnc_toolnum(h, n, 1, &mut one), EW_OK);
        assert_eq!(one.data, g.tools[1].number);
        assert_eq!(cnc_deltlifegrp(h, n), EW_OK);
        assert_eq!(cnc_rdntool(h, n, &mut t), EW_NUMBER);
        assert_eq!(cnc_deltlifegrp(h, n), EW_NUMBER);
        assert_eq!(cnc_rdngrp(h, &mut groups), EW_OK);
        assert_eq!(groups.data, p.paths[0].tool_groups.len() as i32 - 1);
    }
    sim::free(h);
}

/// cnc_instlifedt inserts a tool the reads then see; a refused insert
/// (absent group, use number past the end, tool number 0) changes nothing.
#[test]
fn tool_life_insert_changes_the_table() {
    let (_s, h) = default();
    let p = Profile::default();
    let g = &p.paths[0].tool_groups[1];
    let n = g.number as c_short;
    let ntool = |h| {
        let mut t = ODBTLIFE3::default();
        assert_eq!(unsafe { cnc_rdntool(h, n, &mut t) }, EW_OK);
        t.data
    };
    let mut t = IDBITD {
        datano: n,
        r#type: g.tools.len() as c_short + 2,
        data: 77,
    };
    unsafe {
        assert_eq!(cnc_instlifedt(h, &mut t), EW_NUMBER);
        t.r#type = 1;
        t.data = 0;
        assert_eq!(cnc_instlifedt(h, &mut t), EW_DATA);
        t.datano = 9999;
        t.data = 77;
        assert_eq!(cnc_instlifedt(h, &mut t), EW_NUMBER);
        assert_eq!(ntool(h), g.tools.len() as i32);
        t.datano = n;
        assert_eq!(cnc_instlifedt(h, &mut t), EW_OK);
        assert_eq!(cnc_instlifedt(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(ntool(h), g.tools.len() as i32 + 1);
        let mut one = ODBTLIFE4::default();
        assert_eq!(cnc_toolnum(h, n, 1, &mut one), EW_OK);
        assert_eq!(one.data, 77);
        assert_eq!(cnc_toolnum(h, n, 2, &mut one), EW_OK);
        assert_eq!(one.data, g.tools[0].number);
        let mut l = ODBTLIFE5::default();
        assert_eq!(cnc_rdgrpid2(h, 77, &mut l), EW_OK);
        assert_eq!(l.data, g.number);
    }
    sim::free(h);
}

/// cnc_rdgrpid2 finds each profile tool's group, writes the tool number
/// back into `type`, leaves `dummy`; a deleted tool is no longer found.
#[test]
fn group_of_a_tool() {
    let (_s, h) = default();
    let p = Profile::default();
    for g in &p.paths[0].tool_groups {
        for t in &g.tools {
            let mut l = ODBTLIFE5 {
                dummy: 77,
                ..ODBTLIFE5::default()
            };
            assert_eq!(unsafe { cnc_rdgrpid2(h, t.number.into(), &mut l) }, EW_OK);
            assert_eq!((l.dummy, l.r#type, l.data), (77, t.number, g.number));
        }
    }
    let g = &p.paths[0].tool_groups[1];
    let mut l = ODBTLIFE5::default();
    unsafe {
        assert_eq!(
            cnc_rdgrpid2(h, g.tools[0].number.into(), std::ptr::null_mut()),
            EW_DATA
        );
        assert_eq!(cnc_deltlifedt(h, g.number as c_short, 1), EW_OK);
        assert_eq!(cnc_rdgrpid2(h, g.tools[0].number.into(), &mut l), EW_NUMBER);
    }
    sim::free(h);
}

/// cnc_rdwkcdshft reads the profile's shift; cnc_wrwkcdshft changes it (one
/// axis, all axes); a refused write (short length, bad axis) changes nothing.
#[test]
fn work_coordinate_shift_write_then_read() {
    let (_s, h) = default();
    let p = Profile::default();
    let shift = &p.paths[0].offset.shift;
    let read = |axis: c_short| {
        let mut w = IODBWCSF::default();
        let len = std::mem::size_of::<IODBWCSF>() as c_short;
        let r = unsafe { cnc_rdwkcdshft(h, axis, len, &mut w) };
        (r, w)
    };
    let (r, w) = read(2);
    assert_eq!((r, w.r#type, w.data[0]), (EW_OK, 2, shift[1]));
    let (r, w) = read(-1);
    assert_eq!((r, w.r#type, &w.data[..3]), (EW_OK, -1, &shift[..3]));
    let mut w = IODBWCSF {
        datano: 0,
        r#type: 2,
        ..IODBWCSF::default()
    };
    w.data[0] = 4321;
    unsafe {
        assert_eq!(cnc_wrwkcdshft(h, 4, &mut w), EW_LENGTH);
        assert_eq!(read(2).1.data[0], shift[1]);
        assert_eq!(cnc_wrwkcdshft(h, 8, &mut w), EW_OK);
        assert_eq!(read(2).1.data[0], 4321);
        w.r#type = 33;
        assert_eq!(cnc_wrwkcdshft(h, 8, &mut w), EW_ATTRIB);
        w.r#type = -1;
        w.data[..3].copy_from_slice(&[7, 8, 9]);
        assert_eq!(cnc_wrwkcdshft(h, 132, &mut w), EW_OK);
        assert_eq!(&read(-1).1.data[..3], &[7, 8, 9]);
        let mut one = IODBWCSF::default();
        assert_eq!(cnc_rdwkcdshft(h, 1, 7, &mut one), EW_LENGTH);
        assert_eq!(one, IODBWCSF::default());
        assert_eq!(cnc_rdwkcdshft(h, 33, 8, &mut one), EW_ATTRIB);
        assert_eq!(cnc_rdwkcdshft(h, 1, 8, std::ptr::null_mut()), EW_DATA);
    }
    sim::free(h);
}

#[test]
fn profile_validation() {
    let bad = "[[path]]\n[[path.axis]]\nname = \"X\"\n[path.offset]\ntool = [[1, 2], [3]]\n";
    assert!(Profile::parse(bad).is_err());
    let bad = "[[path]]\n[[path.axis]]\nname = \"X\"\n[path.offset]\nwork = [[1, 2]]\n";
    assert!(Profile::parse(bad).is_err());
}

/// Group 0 is the group in use (the simulator's first); the group number
/// written is the one the CNC answered, as FANUC's library writes it.
#[test]
fn tool_life_group_numbers_come_from_the_answer() {
    let p = Profile::default();
    let first = p.paths[0].tool_groups[0].number as i16;
    let (_s, h) = sim::start_alloc(p);
    let mut l = ODBTLIFE3::default();
    assert_eq!(unsafe { cnc_rdlife(h, 0, &mut l) }, EW_OK);
    assert_eq!(l.datano, first);
    let mut c = ODBTLIFE3::default();
    assert_eq!(unsafe { cnc_rdcount(h, 0, &mut c) }, EW_OK);
    assert_eq!(c.datano, first);
    sim::free(h);
}

/// A profile whose tool offsets have 21 types (0..20), values 1000·type +
/// number, so types 9 and 20 exist.
fn wide_tool_profile() -> Profile {
    let mut p = Profile::default();
    p.paths[0].offset.tool = (1..=4)
        .map(|n| (0..21).map(|t| 1000 * t + n).collect())
        .collect();
    p
}

/// cnc_rdtofsr types 9 and 20 are 2-byte values packed from offset 8, with
/// FANUC's per-type length table (2 bytes per number for 9/20, 8 for -2,
/// 16 for -3, 12 for -5, 20 for -6, 4 otherwise); nothing past `length`.
#[test]
fn tool_offsets_2_byte_types_and_length_table() {
    let (_s, h) = sim::start_alloc(wide_tool_profile());
    for t in [9, 20] {
        let mut b = [0xCCu8; 32];
        let r = unsafe { cnc_rdtofsr(h, 1, t, 4, 8 + 2 * 4, b.as_mut_ptr().cast()) };
        assert_eq!(r, EW_OK, "type {t}");
        let mut want = vec![1, 0, t as u8, 0, 4, 0, 0xCC, 0xCC];
        for n in 1..=4i32 {
            want.extend_from_slice(&((1000 * i32::from(t) + n) as i16).to_le_bytes());
        }
        want.resize(32, 0xCC);
        assert_eq!(b, want[..], "type {t}");
        // One byte short of 8 + 2·4: refused before traffic.
        let r = unsafe { cnc_rdtofsr(h, 1, t, 4, 15, b.as_mut_ptr().cast()) };
        assert_eq!(r, EW_LENGTH);
    }
    // 4-byte types are unchanged: 8 + 4·n.
    let mut b = [0xCCu8; 32];
    assert_eq!(
        unsafe { cnc_rdtofsr(h, 1, 8, 2, 15, b.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    assert_eq!(
        unsafe { cnc_rdtofsr(h, 1, 8, 2, 16, b.as_mut_ptr().cast()) },
        EW_OK
    );
    assert_eq!(
        &b[8..16],
        [&8001i32.to_le_bytes()[..], &8002i32.to_le_bytes()].concat()
    );
    assert_eq!(b[16..], [0xCC; 16]);
    // The "all" types' table: one byte short is refused locally (the
    // simulator answers -2..-6 with EW_ATTRIB, so enough room reaches it).
    for (t, k) in [(-2, 8), (-3, 16), (-4, 8), (-5, 12), (-6, 20)] {
        let mut b = vec![0xCCu8; 8 + 2 * k];
        let p = b.as_mut_ptr().cast();
        let short = (8 + 2 * k - 1) as c_short;
        assert_eq!(
            unsafe { cnc_rdtofsr(h, 1, t, 2, short, p) },
            EW_LENGTH,
            "{t}"
        );
        assert_eq!(
            unsafe { cnc_rdtofsr(h, 1, t, 2, short + 1, p) },
            EW_ATTRIB,
            "{t}"
        );
        assert!(b.iter().all(|&x| x == 0xCC));
    }
    // Type -1 (all 21 types of each number, 4 bytes each) with room for 8 +
    // 4·n: only the values that fit are written.
    let mut b = [0xCCu8; 40];
    assert_eq!(
        unsafe { cnc_rdtofsr(h, 1, -1, 2, 16, b.as_mut_ptr().cast()) },
        EW_OK
    );
    assert_eq!(
        &b[8..16],
        [&1i32.to_le_bytes()[..], &1001i32.to_le_bytes()].concat()
    );
    assert_eq!(b[16..], [0xCC; 24]);
    sim::free(h);
}

/// Every negative axis is "all axes" for cnc_rdzofs / cnc_wrzofs /
/// cnc_rdzofsr, as in FANUC's library: -2 needs the all-axes length
/// (4 + 4·max_axes) and is then sent as it is. The simulator treats only -1
/// as all axes and answers -2 with EW_ATTRIB, which shows the request went
/// out instead of the old local EW_LENGTH.
#[test]
fn work_offsets_negative_axes_are_all_axes() {
    let (_s, h) = default();
    unsafe {
        let mut z = IODBZOFS {
            datano: 1,
            r#type: -2,
            ..IODBZOFS::default()
        };
        assert_eq!(cnc_wrzofs(h, 131, &mut z), EW_LENGTH);
        assert_eq!(cnc_wrzofs(h, 132, &mut z), EW_ATTRIB);
        z.r#type = -3;
        assert_eq!(cnc_wrzofs(h, 132, &mut z), EW_ATTRIB);
        let mut o = IODBZOFS::default();
        assert_eq!(cnc_rdzofs(h, 1, -2, 131, &mut o), EW_LENGTH);
        assert_eq!(o, IODBZOFS::default());
        // The CNC's EW_ATTRIB: header written, as by FANUC's library.
        assert_eq!(cnc_rdzofs(h, 1, -2, 132, &mut o), EW_ATTRIB);
        assert_eq!((o.datano, o.r#type), (1, -2));
        let mut r: IODBZOR = std::mem::zeroed();
        assert_eq!(cnc_rdzofsr(h, 1, -2, 2, 300, &mut r), EW_ATTRIB);
    }
    sim::free(h);
}

/// cnc_rdzofsr axis -1: whole groups of max_axes values, datano_e from the
/// groups received; the length check (after the exchange) counts 8 + 4 ·
/// values, and a length one byte short writes nothing.
#[test]
fn work_offsets_all_axes_range_groups_and_length() {
    let (_s, h) = default();
    let mut b = vec![0xCCu8; 8 + 2 * 128 + 16];
    let p = b.as_mut_ptr().cast();
    assert_eq!(
        unsafe { cnc_rdzofsr(h, 1, -1, 2, 8 + 2 * 128 - 1, p) },
        EW_LENGTH
    );
    assert!(b.iter().all(|&x| x == 0xCC));
    assert_eq!(unsafe { cnc_rdzofsr(h, 1, -1, 2, 8 + 2 * 128, p) }, EW_OK);
    assert_eq!(&b[..8], [1, 0, 0xff, 0xff, 2, 0, 0xCC, 0xCC]);
    assert_eq!(&b[8..12], (-325400i32).to_le_bytes());
    assert_eq!(&b[8 + 128..8 + 132], (-125000i32).to_le_bytes());
    assert_eq!(b[8 + 256..], [0xCC; 16]);
    sim::free(h);
}

/// cnc_rdzofsr reads all axes 5 numbers a request (179 value records at
/// most), as FANUC's library: each answer is checked against `length` and
/// written before the next, the header only at the end; the CNC's
/// EW_NUMBER on a later request (the range runs past the table) ends the
/// read with what the earlier ones got.
#[test]
fn work_offsets_range_in_pieces() {
    let (_s, h) = default();
    let g = |n: usize| 8 + 128 * n;
    let mut b = vec![0xCCu8; g(7)];
    let p = b.as_mut_ptr().cast();
    // G54..G59: the first piece (5 numbers) fits, the second does not.
    assert_eq!(
        unsafe { cnc_rdzofsr(h, 1, -1, 6, (g(6) - 1) as c_short, p) },
        EW_LENGTH
    );
    assert_eq!(&b[..8], [0xCC; 8], "no header on EW_LENGTH");
    assert_eq!(&b[8..12], (-325400i32).to_le_bytes());
    assert_eq!(b[g(5)..], [0xCC; 128 * 2]);
    assert_eq!(
        unsafe { cnc_rdzofsr(h, 1, -1, 6, g(6) as c_short, p) },
        EW_OK
    );
    assert_eq!(&b[..8], [1, 0, 0xff, 0xff, 6, 0, 0xCC, 0xCC]);
    assert_eq!(b[g(6)..], [0xCC; 128]);
    // 1..20: [1, 5] is read, [6, 10] is past the table: datano_e 5.
    let mut b = vec![0xCCu8; 2000];
    let p = b.as_mut_ptr().cast();
    assert_eq!(unsafe { cnc_rdzofsr(h, 1, -1, 20, 2000, p) }, EW_OK);
    assert_eq!(&b[..8], [1, 0, 0xff, 0xff, 5, 0, 0xCC, 0xCC]);
    assert_eq!(b[g(5)..], [0xCC; 2000 - 8 - 128 * 5]);
    // The first request past the table: the CNC's code, nothing written.
    let mut b = vec![0xCCu8; 2000];
    let p = b.as_mut_ptr().cast();
    assert_eq!(unsafe { cnc_rdzofsr(h, 7, -1, 20, 2000, p) }, EW_NUMBER);
    assert!(b.iter().all(|&x| x == 0xCC));
    sim::free(h);
}
