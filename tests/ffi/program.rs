//! Program-area functions through the C ABI against the simulator: values
//! equal the profile's (or the running machine's), NULL pointers, bad
//! handles, bad types and lengths.
//!
//! Programs in memory through the C ABI against the simulator's program
//! store: what the oracle's single calls cannot show, that a change is seen
//! by the next directory read and upload, and that a refusal changes
//! nothing.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::run::StoredProgram;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_char, c_long, c_short, c_ulong, c_ushort};
use std::ptr::null_mut;

fn start(profile: &str) -> (Simulator, c_ushort) {
    let p = if profile.is_empty() {
        Profile::default()
    } else {
        Profile::parse(profile).expect("profile")
    };
    sim::start_alloc(p)
}

fn text(c: &[c_char]) -> String {
    let b: Vec<u8> = c
        .iter()
        .take_while(|x| **x != 0)
        .map(|x| *x as u8)
        .collect();
    String::from_utf8(b).unwrap()
}

/// One path running O1234 slowly (a block every 10^6 s: it stays put), an
/// 8-digit program stored too.
const RUNNING: &str = r#"
[[path]]
opmode = 3
[path.cycle]
program = 1234
block_seconds = 1000000.0
[[program]]
number = 1234
text = """
O1234 (TEST);
N10 G90 G54;
N20 G01 X10. F100;
N30 M30;
%
"""
"#;

const EIGHT_DIGITS: &str = r#"
[[path]]
[path.cycle]
program = 12345678
block_seconds = 1000000.0
[[program]]
number = 12345678
name = "//CNC_MEM/USER/LIBRARY/O12345678"
text = "O12345678;\nN1 M30;\n"
"#;

const IDLE: &str = r#"
[[path]]
"#;

#[test]
fn program_numbers_names_and_pointer() {
    let (_s, h) = start(RUNNING);
    let mut p = ODBPRO {
        dummy: [7, 7],
        ..ODBPRO::default()
    };
    assert_eq!(unsafe { cnc_rdprgnum(h, &mut p) }, EW_OK);
    assert_eq!((p.data, p.mdata), (1234, 1234));
    assert_eq!(p.dummy, [7, 7], "dummy untouched");

    let mut e = ODBEXEPRG::default();
    assert_eq!(unsafe { cnc_exeprgname(h, &mut e) }, EW_OK);
    assert_eq!((text(&e.name).as_str(), e.o_num), ("O1234", 1234));

    let mut full = [0x55 as c_char; 300];
    assert_eq!(unsafe { cnc_exeprgname2(h, full.as_mut_ptr()) }, EW_OK);
    assert_eq!(text(&full), "//CNC_MEM/USER/PATH1/O1234");
    assert!(full[26..256].iter().all(|c| *c == 0), "zero-filled to 256");
    assert!(full[256..].iter().all(|c| *c == 0x55), "nothing past 256");

    let (mut prog, mut blk): (c_long, c_long) = (0, 0);
    assert_eq!(unsafe { cnc_rdactpt(h, &mut prog, &mut blk) }, EW_OK);
    assert_eq!(prog as i32, 1234);

    let mut bc: c_long = 0;
    assert_eq!(unsafe { cnc_rdblkcount(h, &mut bc) }, EW_OK);
    assert!(bc as i32 >= 0);

    let mut seq = ODBSEQ::default();
    assert_eq!(unsafe { cnc_rdseqnum(h, &mut seq) }, EW_OK);
    let program = "O1234 (TEST);\nN10 G90 G54;\nN20 G01 X10. F100;\nN30 M30;\n%\n";
    assert!(
        seq.data == 0 || program.contains(&format!("N{} ", seq.data)),
        "sequence number {} is not one of the program's",
        seq.data
    );

    // The executing text: lines of the program, NUL-terminated.
    let mut buf = [0x55 as c_char; 256];
    let mut len: c_ushort = 200;
    let mut blknum: c_short = -1;
    assert_eq!(
        unsafe { cnc_rdexecprog(h, &mut len, &mut blknum, buf.as_mut_ptr()) },
        EW_OK
    );
    let t = text(&buf);
    assert_eq!(t.len(), len as usize);
    assert_eq!(buf[len as usize], 0);
    assert!(!t.is_empty());
    let lines: Vec<&str> = program.lines().collect();
    for l in t.lines().filter(|l| !l.is_empty()) {
        assert!(lines.iter().any(|p| p.starts_with(l)), "{l:?} not in O1234");
    }
    assert_eq!(blknum, blk as i32 as c_short, "same block as cnc_rdactpt");

    // A short buffer: never more than length - 1 characters and the NUL.
    let mut small = [0x55 as c_char; 16];
    let mut len: c_ushort = 8;
    assert_eq!(
        unsafe { cnc_rdexecprog(h, &mut len, &mut blknum, small.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(len, 7);
    assert_eq!(small[7], 0);
    assert!(small[8..].iter().all(|c| *c == 0x55));

    let mut mode: c_short = -1;
    assert_eq!(unsafe { cnc_rdopmode(h, &mut mode) }, EW_OK);
    assert_eq!(mode, 3);
    sim::free(h);
}

#[test]
fn program_numbers_keep_their_low_16_bits() {
    let (_s, h) = start(EIGHT_DIGITS);
    let mut p = ODBPRO::default();
    assert_eq!(unsafe { cnc_rdprgnum(h, &mut p) }, EW_OK);
    assert_eq!(p.data, 12345678u32 as u16 as i16);
    assert_eq!(p.mdata, 12345678u32 as u16 as i16);
    let mut e = ODBEXEPRG::default();
    assert_eq!(unsafe { cnc_exeprgname(h, &mut e) }, EW_OK);
    assert_eq!((text(&e.name).as_str(), e.o_num), ("O12345678", 12345678));
    let mut full = [0 as c_char; 256];
    assert_eq!(unsafe { cnc_exeprgname2(h, full.as_mut_ptr()) }, EW_OK);
    assert_eq!(text(&full), "//CNC_MEM/USER/LIBRARY/O12345678");
    sim::free(h);
}

/// cnc_rdprgnumo8 reads the 8-digit numbers whole, where cnc_rdprgnum
/// keeps their low 16 bits.
#[test]
fn eight_digit_program_numbers_read_whole() {
    let (_s, h) = start(EIGHT_DIGITS);
    let mut p = ODBPROO8 {
        dummy: [7, 7],
        ..ODBPROO8::default()
    };
    assert_eq!(unsafe { cnc_rdprgnumo8(h, &mut p) }, EW_OK);
    assert_eq!((p.data, p.mdata), (12345678, 12345678));
    assert_eq!(p.dummy, [7, 7], "dummy left as it was");
    assert_eq!(unsafe { cnc_rdprgnumo8(h, null_mut()) }, EW_DATA);
    sim::free(h);
    let (_s, h) = start(IDLE);
    assert_eq!(unsafe { cnc_rdprgnumo8(h, &mut p) }, EW_OK);
    assert_eq!((p.data, p.mdata), (0, 0));
    sim::free(h);
}

#[test]
fn an_idle_path_has_an_empty_executing_text() {
    let (_s, h) = start(IDLE);
    let mut p = ODBPRO::default();
    assert_eq!(unsafe { cnc_rdprgnum(h, &mut p) }, EW_OK);
    assert_eq!((p.data, p.mdata), (0, 0));
    let mut buf = [0x55 as c_char; 64];
    let mut len: c_ushort = 64;
    let mut blknum: c_short = 9;
    assert_eq!(
        unsafe { cnc_rdexecprog(h, &mut len, &mut blknum, buf.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!((len, blknum, buf[0]), (0, 0, 0));
    assert!(buf[1..].iter().all(|c| *c == 0x55));
    sim::free(h);
}

#[test]
fn modal_codes_equal_the_profile() {
    // Idle: a running program sets the codes it reaches (M06, M03 ...),
    // which state::modal_codes_follow_the_running_program checks.
    let mut prof = Profile::default();
    prof.paths[0].cycle.program = 0;
    let (_s, h) = sim::start_alloc(prof.clone());
    let m = &prof.paths[0].modal;
    let aux = |t: i32| m.aux.get(&t.to_string()).copied().unwrap_or(0);

    let mut o = ODBMDL::default();
    assert_eq!(unsafe { cnc_modal(h, 0, 0, &mut o) }, EW_OK);
    assert_eq!((o.datano, o.r#type), (0, 0));
    assert_eq!(unsafe { o.modal.g_data } as u8, m.g[0]);

    let mut o = ODBMDL::default();
    assert_eq!(unsafe { cnc_modal(h, 5, 1, &mut o) }, EW_OK);
    assert_eq!((o.datano, o.r#type), (5, 1));
    assert_eq!(unsafe { o.modal.g_data } as u8, m.g[5]);

    let mut o = ODBMDL::default();
    assert_eq!(unsafe { cnc_modal(h, -1, 0, &mut o) }, EW_OK);
    let g = unsafe { o.modal.g_rdata };
    for (i, c) in m.g.iter().enumerate() {
        assert_eq!(g[i] as u8, *c, "group {i}");
    }

    for t in 100..=126 {
        let mut o = ODBMDL::default();
        assert_eq!(unsafe { cnc_modal(h, t, 0, &mut o) }, EW_OK, "type {t}");
        assert_eq!(o.datano, t);
        assert_eq!(unsafe { o.modal.aux.aux_data }, aux(t as i32), "type {t}");
    }
    assert_eq!(aux(103), 1500, "the default profile's F");

    // −2: raux1[k] is type 100 + k.
    let mut o = ODBMDL::default();
    assert_eq!(unsafe { cnc_modal(h, -2, 0, &mut o) }, EW_OK);
    let r = unsafe { o.modal.raux1 };
    for (k, rec) in r.iter().enumerate() {
        assert_eq!(rec.aux_data, aux(100 + k as i32), "raux1[{k}]");
    }

    // −3: in the CNC's code order; raux2 has 32 places, 29 codes are sent.
    let mut o = ODBMDL::default();
    unsafe { o.modal.raux2[31].aux_data = 77 };
    assert_eq!(unsafe { cnc_modal(h, -3, 0, &mut o) }, EW_OK);
    let r = unsafe { o.modal.raux2 };
    assert_eq!(r[5].aux_data, aux(103), "code 5 is type 103");
    assert_eq!(r[31].aux_data, 77, "untouched past the records sent");

    // Types FANUC's library refuses locally, and a code the CNC lacks.
    let mut o = ODBMDL::default();
    for t in [127, 199, 400, -6] {
        assert_eq!(unsafe { cnc_modal(h, t, 0, &mut o) }, EW_NUMBER, "type {t}");
    }
    assert_eq!(unsafe { cnc_modal(h, 200, 0, &mut o) }, EW_NUMBER);
    assert_eq!(unsafe { cnc_modal(h, 99, 0, &mut o) }, EW_NUMBER);
    sim::free(h);
}

#[test]
fn timers_and_clock() {
    let (_s, h) = start("");
    let t = Profile::default().timers;
    let mut o = IODBTIME::default();
    assert_eq!(unsafe { cnc_rdtimer(h, 0, &mut o) }, EW_OK);
    assert!(o.minute >= t.power_on && (0..60_000).contains(&o.msec));
    assert_eq!(unsafe { cnc_rdtimer(h, 4, &mut o) }, EW_OK);
    assert_eq!((o.minute, o.msec), (t.free, 0));
    for k in 1..=3 {
        assert_eq!(unsafe { cnc_rdtimer(h, k, &mut o) }, EW_OK);
        assert!((0..60_000).contains(&o.msec));
    }
    assert_eq!(unsafe { cnc_rdtimer(h, 9, &mut o) }, EW_NUMBER);

    let mut c = IODBTIMER::default();
    assert_eq!(unsafe { cnc_gettimer(h, &mut c) }, EW_OK);
    let d = unsafe { c.data.date };
    assert!(d.year >= 2024 && (1..=12).contains(&d.month) && (1..=31).contains(&d.date));

    // settimer moves the CNC's clock; gettimer reads it back.
    let mut set = IODBTIMER {
        r#type: 0,
        dummy: 0,
        data: IODBTIMER_data {
            date: IODBTIMER_date {
                year: 2031,
                month: 2,
                date: 3,
            },
        },
    };
    assert_eq!(unsafe { cnc_settimer(h, &mut set) }, EW_OK);
    let mut c = IODBTIMER::default();
    assert_eq!(unsafe { cnc_gettimer(h, &mut c) }, EW_OK);
    let d = unsafe { c.data.date };
    assert_eq!((d.year, d.month), (2031, 2));
    assert!((3..=4).contains(&d.date), "midnight may pass");

    set.r#type = 1;
    set.data.time = IODBTIMER_time {
        hour: 12,
        minute: 34,
        second: 0,
    };
    assert_eq!(unsafe { cnc_settimer(h, &mut set) }, EW_OK);
    let mut c = IODBTIMER {
        r#type: 1,
        ..IODBTIMER::default()
    };
    assert_eq!(unsafe { cnc_gettimer(h, &mut c) }, EW_OK);
    let t = unsafe { c.data.time };
    assert_eq!((t.hour, t.minute), (12, 34));
    assert!(t.second < 30);

    // Invalid values: the CNC's EW_DATA; other types: EW_NUMBER without traffic.
    set.data.time.hour = 25;
    assert_eq!(unsafe { cnc_settimer(h, &mut set) }, EW_DATA);
    set.r#type = 2;
    assert_eq!(unsafe { cnc_settimer(h, &mut set) }, EW_NUMBER);
    let mut c = IODBTIMER {
        r#type: -1,
        ..IODBTIMER::default()
    };
    assert_eq!(unsafe { cnc_gettimer(h, &mut c) }, EW_NUMBER);
    sim::free(h);
}

#[test]
fn tool_life_groups() {
    let (_s, h) = start("");
    let prof = Profile::default();
    for g in &prof.paths[0].tool_groups {
        let mut n = ODBTLIFE3 {
            dummy: 99,
            ..ODBTLIFE3::default()
        };
        assert_eq!(
            unsafe { cnc_rdntool(h, g.number as c_short, &mut n) },
            EW_OK
        );
        assert_eq!(
            (n.datano as i32, n.data, n.dummy),
            (g.number, g.tools.len() as i32, 99)
        );
        for (i, tool) in g.tools.iter().enumerate() {
            let mut t = ODBTLIFE4::default();
            let u = i as c_short + 1;
            assert_eq!(
                unsafe { cnc_toolnum(h, g.number as c_short, u, &mut t) },
                EW_OK
            );
            assert_eq!(
                (t.datano as i32, t.r#type, t.data),
                (g.number, u, tool.number)
            );
        }
        let mut t = ODBTLIFE4::default();
        let past = g.tools.len() as c_short + 1;
        assert_eq!(
            unsafe { cnc_toolnum(h, g.number as c_short, past, &mut t) },
            EW_NUMBER
        );
    }
    let mut n = ODBTLIFE3::default();
    assert_eq!(unsafe { cnc_rdntool(h, 99, &mut n) }, EW_NUMBER);
    sim::free(h);
}

#[test]
fn null_pointers_bad_handles_and_lengths() {
    let (_s, h) = start("");
    let mut l: c_long = 0;
    let mut len: c_ushort = 10;
    let mut s: c_short = 0;
    let mut b = [0 as c_char; 16];
    unsafe {
        assert_eq!(cnc_rdprgnum(h, null_mut()), EW_DATA);
        assert_eq!(cnc_rdseqnum(h, null_mut()), EW_DATA);
        assert_eq!(cnc_rdblkcount(h, null_mut()), EW_DATA);
        assert_eq!(cnc_rdactpt(h, null_mut(), &mut l), EW_DATA);
        assert_eq!(cnc_rdactpt(h, &mut l, null_mut()), EW_DATA);
        assert_eq!(cnc_exeprgname(h, null_mut()), EW_DATA);
        assert_eq!(cnc_exeprgname2(h, null_mut()), EW_DATA);
        assert_eq!(
            cnc_rdexecprog(h, null_mut(), &mut s, b.as_mut_ptr()),
            EW_DATA
        );
        assert_eq!(
            cnc_rdexecprog(h, &mut len, null_mut(), b.as_mut_ptr()),
            EW_DATA
        );
        assert_eq!(cnc_rdexecprog(h, &mut len, &mut s, null_mut()), EW_DATA);
        assert_eq!(cnc_modal(h, 0, 0, null_mut()), EW_DATA);
        assert_eq!(cnc_rdtimer(h, 0, null_mut()), EW_DATA);
        assert_eq!(cnc_gettimer(h, null_mut()), EW_DATA);
        assert_eq!(cnc_settimer(h, null_mut()), EW_DATA);
        assert_eq!(cnc_rdopmode(h, null_mut()), EW_DATA);
        assert_eq!(cnc_toolnum(h, 1, 1, null_mut()), EW_DATA);
        assert_eq!(cnc_rdntool(h, 1, null_mut()), EW_DATA);
        // *length 0 is sent (FANUC's library): *blknum and *length 0 come
        // back, the buffer is not touched.
        let mut zero: c_ushort = 0;
        b[0] = 0x55;
        assert_eq!(cnc_rdexecprog(h, &mut zero, &mut s, b.as_mut_ptr()), EW_OK);
        assert_eq!((zero, b[0]), (0, 0x55));

        let bad = 0x7777;
        let mut p = ODBPRO::default();
        assert_eq!(cnc_rdprgnum(bad, &mut p), EW_HANDLE);
        assert_eq!(cnc_rdblkcount(bad, &mut l), EW_HANDLE);
        let mut m = ODBMDL::default();
        assert_eq!(cnc_modal(bad, 0, 0, &mut m), EW_HANDLE);
        let mut t = IODBTIME::default();
        assert_eq!(cnc_rdtimer(bad, 0, &mut t), EW_HANDLE);
        assert_eq!(cnc_rdopmode(bad, &mut s), EW_HANDLE);
    }
    sim::free(h);
}

// --- program directory (cnc_rdprogdir, cnc_rdprogdir3), self-contained ---

mod progdir {
    use fwlib32::ew::*;
    use fwlib32::sim::{Profile, Simulator};
    use fwlib32::types::*;
    use fwlib32::*;
    use std::ffi::CString;
    use std::os::raw::{c_long, c_short, c_ushort};
    use std::ptr::null_mut;

    fn start() -> (Simulator, Profile, c_ushort) {
        let p = Profile::default();
        let s = Simulator::start(p.clone(), "127.0.0.1:0").expect("simulator");
        let ip = CString::new("127.0.0.1").unwrap();
        let mut h: c_ushort = 0;
        assert_eq!(
            unsafe { cnc_allclibhndl3(ip.as_ptr(), s.port(), 5, &mut h) },
            EW_OK
        );
        (s, p, h)
    }

    /// (number, size, comment) of the profile's programs in number order.
    fn programs(p: &Profile) -> Vec<(i32, i32, String)> {
        let mut v: Vec<_> = p
            .programs
            .iter()
            .map(|s| (s.number, s.text.len() as i32, format!("({})", s.comment)))
            .collect();
        v.sort();
        v
    }

    fn dir3(
        h: c_ushort,
        t: c_short,
        top: i32,
        num: c_short,
    ) -> (c_short, i32, c_short, Vec<PRGDIR3>) {
        let fill = PRGDIR3 {
            number: -1,
            length: -1,
            page: -1,
            comment: [0x55; 52],
            mdate: PRGDIR3_date {
                year: -1,
                ..PRGDIR3_date::default()
            },
            cdate: PRGDIR3_date {
                year: -1,
                ..PRGDIR3_date::default()
            },
        };
        // One spare record past `num` to catch overruns.
        let mut b = vec![fill; num.max(0) as usize + 1];
        let (mut top, mut n) = (top, num);
        let r = unsafe {
            cnc_rdprogdir3(
                h,
                t,
                (&raw mut top).cast::<c_long>(),
                &mut n,
                b.as_mut_ptr(),
            )
        };
        assert_eq!(
            b.last().copied(),
            Some(fill),
            "wrote past *num_prog records"
        );
        b.pop();
        (r, top, n, b)
    }

    fn comment(c: &[std::os::raw::c_char]) -> String {
        c.iter()
            .take_while(|x| **x != 0)
            .map(|x| *x as u8 as char)
            .collect()
    }

    #[test]
    fn rdprogdir3_each_type_lists_the_profile_programs() {
        let (_s, p, h) = start();
        let want = programs(&p);
        assert!(want.len() >= 2);
        for t in 0..=2 {
            let (r, top, n, b) = dir3(h, t, 1, 10);
            assert_eq!(r, EW_OK, "type {t}");
            assert_eq!(n as usize, want.len());
            assert_eq!(top, want[0].0);
            for (rec, (num, len, com)) in b.iter().zip(&want) {
                assert_eq!(rec.number, *num);
                assert_eq!(rec.page, -1, "page is never written");
                assert_eq!(rec.cdate.year, -1, "cdate is never written");
                if t >= 1 {
                    assert_eq!(&comment(&rec.comment), com);
                } else {
                    assert_eq!(rec.comment, [0x55; 52]);
                }
                if t == 2 {
                    assert_eq!(rec.length, *len);
                } else {
                    assert_eq!(rec.length, -1);
                    assert_eq!(rec.mdate.year, -1);
                }
            }
            for rec in &b[want.len()..] {
                assert_eq!(rec.number, -1, "records past *num_prog untouched");
            }
        }
        // Modification dates of default.toml.
        let (_, _, _, b) = dir3(h, 2, 1, 10);
        let d = |r: &PRGDIR3| {
            (
                r.mdate.year,
                r.mdate.month,
                r.mdate.day,
                r.mdate.hour,
                r.mdate.minute,
                r.mdate.dummy,
            )
        };
        assert_eq!(d(&b[0]), (2023, 11, 2, 7, 30, 0));
        assert_eq!(d(&b[1]), (2024, 5, 17, 13, 45, 0));
        cnc_freelibhndl(h);
    }

    #[test]
    fn rdprogdir3_top_and_num() {
        let (_s, p, h) = start();
        let want = programs(&p);
        // num 1: only the first; then the next from the one after it.
        let (r, top, n, b) = dir3(h, 0, 0, 1);
        assert_eq!((r, top, n, b[0].number), (EW_OK, want[0].0, 1, want[0].0));
        let (r, top, n, b) = dir3(h, 0, want[0].0 + 1, 1);
        assert_eq!((r, top, n, b[0].number), (EW_OK, want[1].0, 1, want[1].0));
        // num far larger than the programs (several exchanges of 19).
        let (r, _, n, _) = dir3(h, 1, 1, 50);
        assert_eq!((r, n as usize), (EW_OK, want.len()));
        // Nothing from top on: *num_prog 0, *top_prog the number the
        // caller's first record held (-1 here), as FANUC's library.
        let (r, top, n, b) = dir3(h, 2, 99_999_999, 5);
        assert_eq!((r, top, n), (EW_OK, -1, 0));
        assert!(b.iter().all(|x| x.number == -1));
        // Local checks.
        assert_eq!(dir3(h, 3, 1, 5).0, EW_ATTRIB);
        assert_eq!(dir3(h, -1, 1, 5).0, EW_ATTRIB);
        assert_eq!(dir3(h, 0, 1, 0).0, EW_LENGTH);
        assert_eq!(dir3(h, 0, 1, -2).0, EW_LENGTH);
        cnc_freelibhndl(h);
    }

    fn dir(h: c_ushort, t: c_short, s: c_short, e: c_short, len: c_ushort) -> (c_short, Vec<u8>) {
        let mut b = vec![0xCCu8; len as usize + 16];
        let r = unsafe { cnc_rdprogdir(h, t, s, e, len, b.as_mut_ptr().cast()) };
        assert!(
            b[len as usize..].iter().all(|x| *x == 0xCC),
            "wrote past length"
        );
        let end = b.iter().rposition(|x| *x != 0xCC).map_or(0, |i| i + 1);
        b.truncate(end);
        (r, b)
    }

    #[test]
    fn rdprogdir_text_of_each_type() {
        let (_s, p, h) = start();
        let w = programs(&p);
        let t0: String = w
            .iter()
            .map(|(n, _, _)| format!("O{n}"))
            .collect::<String>()
            + "%";
        let t1 = format!(
            "%\n{}%",
            w.iter()
                .map(|(n, _, c)| format!("O{n}{c}\n"))
                .collect::<String>()
        );
        let t2: String = w
            .iter()
            .map(|(n, l, c)| format!("O{n}{c}{l}"))
            .collect::<String>()
            + "%";
        assert_eq!(dir(h, 0, 1, 9999, 256), (EW_OK, t0.clone().into_bytes()));
        assert_eq!(dir(h, 1, 1, 9999, 256), (EW_OK, t1.into_bytes()));
        assert_eq!(dir(h, 2, 1, 9999, 256), (EW_OK, t2.into_bytes()));
        // Range: only the first program.
        let first = format!("O{}%", w[0].0);
        assert_eq!(
            dir(h, 0, 1, w[0].0 as c_short, 256),
            (EW_OK, first.clone().into_bytes())
        );
        // None in range: "%".
        assert_eq!(dir(h, 1, 9000, 9999, 256), (EW_OK, b"%".to_vec()));
        // Too small: the entries that fit, "%", EW_LENGTH; never past length.
        let len = first.len() as c_ushort;
        assert_eq!(dir(h, 0, 1, 9999, len), (EW_LENGTH, first.into_bytes()));
        assert_eq!(dir(h, 0, 1, 9999, 1), (EW_LENGTH, b"%".to_vec()));
        // Local checks.
        assert_eq!(dir(h, 3, 1, 9999, 256), (EW_ATTRIB, vec![]));
        assert_eq!(dir(h, 0, 10, 9, 256), (EW_NUMBER, vec![]));
        assert_eq!(dir(h, 0, 1, 9999, 0), (EW_LENGTH, vec![]));
        cnc_freelibhndl(h);
    }

    #[test]
    fn progdir_null_pointers_and_bad_handle() {
        let (_s, _p, h) = start();
        let (mut top, mut n): (i32, c_short) = (1, 5);
        let mut b = [PRGDIR3::default(); 5];
        let tp = (&raw mut top).cast::<c_long>();
        unsafe {
            assert_eq!(
                cnc_rdprogdir3(h, 0, null_mut(), &mut n, b.as_mut_ptr()),
                EW_DATA
            );
            assert_eq!(
                cnc_rdprogdir3(h, 0, tp, null_mut(), b.as_mut_ptr()),
                EW_DATA
            );
            assert_eq!(cnc_rdprogdir3(h, 0, tp, &mut n, null_mut()), EW_DATA);
            assert_eq!(cnc_rdprogdir(h, 0, 1, 9999, 256, null_mut()), EW_DATA);
            assert_eq!(
                cnc_rdprogdir3(0x7777, 0, tp, &mut n, b.as_mut_ptr()),
                EW_HANDLE
            );
            let mut d = PRGDIR::default();
            assert_eq!(cnc_rdprogdir(0x7777, 0, 1, 9999, 256, &mut d), EW_HANDLE);
            cnc_freelibhndl(h);
        }
    }
}

/// The built-in profile with path 1 idle (no program in cycle, none
/// selected) and a protected O0500.
fn idle() -> Profile {
    let mut p = Profile::default();
    p.paths[0].cycle.program = 0;
    p.programs.push(StoredProgram {
        number: 500,
        text: "O0500 (KEEP);\nG04 X1.;\nM30;\n%\n".into(),
        protect: true,
        ..Default::default()
    });
    p
}

/// (number, size, comment) of every program, by cnc_rdprogdir3 type 2.
fn dir(h: c_ushort) -> Vec<(i32, i32, String)> {
    let mut buf = vec![PRGDIR3::default(); 20];
    let (mut top, mut num): (c_long, c_short) = (0, 20);
    assert_eq!(
        unsafe { cnc_rdprogdir3(h, 2, &mut top, &mut num, buf.as_mut_ptr()) },
        EW_OK
    );
    buf[..num as usize]
        .iter()
        .map(|d| {
            let c = d.comment.iter().take_while(|&&b| b != 0).map(|&b| b as u8);
            (d.number, d.length, String::from_utf8(c.collect()).unwrap())
        })
        .collect()
}

fn numbers(h: c_ushort) -> Vec<i32> {
    dir(h).into_iter().map(|d| d.0).collect()
}

/// The uploaded text of program `n`, or the error of its upload.
fn upload(h: c_ushort, n: i32) -> Result<String, c_short> {
    let r = cnc_upstart3(h, 0, n as c_long, n as c_long);
    if r != EW_OK {
        return Err(r);
    }
    let mut all = Vec::new();
    loop {
        let mut buf = vec![0u8; 1024];
        let mut len: c_long = 1024;
        match unsafe { cnc_upload3(h, &mut len, buf.as_mut_ptr().cast()) } {
            EW_OK => all.extend_from_slice(&buf[..len as usize]),
            EW_BUFFER => std::thread::yield_now(),
            EW_RESET => break,
            e => {
                cnc_upend3(h);
                return Err(e);
            }
        }
    }
    assert_eq!(cnc_upend3(h), EW_OK);
    Ok(String::from_utf8(all).unwrap())
}

fn proginfo(h: c_ushort) -> ODBNC_bin {
    let mut o = ODBNC::default();
    assert_eq!(unsafe { cnc_rdproginfo(h, 0, 12, &mut o) }, EW_OK);
    unsafe { o.u.bin }
}

#[test]
fn delete_removes_a_program_and_refusals_change_nothing() {
    let (_s, h) = sim::start_alloc(Profile::default());
    assert_eq!(numbers(h), vec![100, 1234]);
    assert_eq!(cnc_delete(h, 100), EW_OK);
    assert_eq!(numbers(h), vec![1234]);
    assert_eq!(upload(h, 100), Err(EW_DATA));
    assert_eq!(cnc_delete(h, 100), EW_DATA, "gone");
    // O1234 is executing (and the main program).
    assert_eq!(cnc_delete(h, 1234), EW_BUSY);
    assert_eq!(cnc_renameprog(h, 1234, 1), EW_BUSY);
    assert_eq!(cnc_search(h, 1234), EW_BUSY, "the path is running");
    assert_eq!(numbers(h), vec![1234]);
    assert!(upload(h, 1234).unwrap().contains("POCKET DEMO"));
}

#[test]
fn a_protected_program_stays() {
    let (_s, h) = sim::start_alloc(idle());
    let before = dir(h);
    assert_eq!(cnc_delete(h, 500), EW_PROT);
    assert_eq!(cnc_renameprog(h, 500, 501), EW_PROT);
    assert_eq!(cnc_delall(h), EW_OK);
    assert_eq!(numbers(h), vec![500], "delall leaves the protected program");
    assert_eq!(dir(h)[0], before[1]);
    assert!(upload(h, 500).unwrap().contains("O0500"));
}

#[test]
fn rename_and_copy_show_in_directory_and_upload() {
    let (_s, h) = sim::start_alloc(idle());
    assert_eq!(cnc_renameprog(h, 100, 200), EW_OK);
    assert_eq!(numbers(h), vec![200, 500, 1234]);
    assert_eq!(upload(h, 100), Err(EW_DATA));
    let text = upload(h, 200).unwrap();
    assert!(text.starts_with("%\nO0200 (WARM UP)\n"), "{text}");
    assert_eq!(cnc_renameprog(h, 200, 1234), EW_DATA, "number in use");
    assert_eq!(cnc_renameprog(h, 7, 8), EW_DATA, "no such program");

    assert_eq!(cnc_copyprog(h, 200, 300), EW_OK);
    assert_eq!(upload(h, 300).unwrap(), text.replace("O0200", "O0300"));
    assert_eq!(cnc_copyprog(h, 200, 300), EW_DATA, "number in use");
    assert_eq!(cnc_copyprog(h, 7, 301), EW_DATA, "no such program");
    assert_eq!(numbers(h), vec![200, 300, 500, 1234]);

    let mut d2 = vec![PRGDIR2::default(); 8];
    let (mut top, mut num): (c_short, c_short) = (250, 8);
    assert_eq!(
        unsafe { cnc_rdprogdir2(h, 2, &mut top, &mut num, d2.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!((top, num), (300, 3));
    assert_eq!(d2[0].length, dir(h)[1].1, "cnc_rdprogdir3's size");
}

#[test]
fn search_selects_the_main_program() {
    let (_s, h) = sim::start_alloc(idle());
    let prgnum = || {
        let mut p = ODBPRO::default();
        assert_eq!(unsafe { cnc_rdprgnum(h, &mut p) }, EW_OK);
        (p.data, p.mdata)
    };
    assert_eq!(prgnum(), (0, 0));
    assert_eq!(cnc_search(h, 7), EW_DATA);
    assert_eq!(cnc_search(h, 100), EW_OK);
    assert_eq!(prgnum(), (100, 100));
    let mut e = ODBEXEPRG::default();
    assert_eq!(unsafe { cnc_exeprgname(h, &mut e) }, EW_OK);
    assert_eq!(
        (e.o_num, e.name[..5].to_vec()),
        (100, b"O0100".map(|b| b as c_char).to_vec())
    );
    assert_eq!(cnc_delete(h, 100), EW_BUSY, "the main program");
    assert_eq!(cnc_delall(h), EW_OK);
    assert_eq!(numbers(h), vec![100, 500]);
}

#[test]
fn memory_information_follows_the_store() {
    let mut p = idle();
    let used: usize = p.programs.iter().map(|x| x.text.len()).sum();
    p.paths[0].memory.bytes = Some(used + 10);
    let (_s, h) = sim::start_alloc(p);
    let i = proginfo(h);
    assert_eq!((i.reg_prg, i.unreg_prg), (3, 397));
    assert_eq!((i.used_mem as usize, i.unused_mem), (used, 10));
    // Type 1: the same numbers as text.
    let mut o = ODBNC::default();
    assert_eq!(unsafe { cnc_rdproginfo(h, 1, 31, &mut o) }, EW_OK);
    let asc: Vec<u8> = unsafe { o.u.asc }.iter().map(|&b| b as u8).collect();
    let want = format!("%\n3\n397\n{used}\n10\n%\0");
    assert_eq!(&asc[..want.len()], want.as_bytes());
    // A copy that does not fit changes nothing.
    assert_eq!(cnc_copyprog(h, 100, 101), EW_OVRFLOW);
    assert_eq!(numbers(h), vec![100, 500, 1234]);
    assert_eq!(cnc_delete(h, 100), EW_OK);
    let i = proginfo(h);
    assert_eq!((i.reg_prg, i.unreg_prg), (2, 398));
}

#[test]
fn the_mdi_program_and_pointer_round_trip() {
    let (_s, h) = sim::start_alloc(idle());
    let mut text = *b"G91G28Z0;\nM30;\n%";
    let n = text.len() as c_short;
    assert_eq!(
        unsafe { cnc_wrmdiprog(h, n, text.as_mut_ptr().cast()) },
        EW_OK
    );
    let mut buf = [0 as c_char; 64];
    let mut len: c_short = 64;
    assert_eq!(
        unsafe { cnc_rdmdiprog(h, &mut len, buf.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(len, n);
    assert_eq!(
        buf[..len as usize]
            .iter()
            .map(|&b| b as u8)
            .collect::<Vec<_>>(),
        text
    );
    assert_eq!(cnc_wrmdipntr(h, 5), EW_OK);
    let mut p = ODBMDIP::default();
    assert_eq!(unsafe { cnc_rdmdipntr(h, &mut p) }, EW_OK);
    assert_eq!((p.mdipntr, p.crntpntr), (5, 5));
}

fn cs(s: &str) -> std::ffi::CString {
    std::ffi::CString::new(s).unwrap()
}

/// A one-name folder function on `name`.
fn on(
    f: unsafe extern "C" fn(c_ushort, *mut c_char) -> c_short,
    h: c_ushort,
    name: &str,
) -> c_short {
    unsafe { f(h, cs(name).as_ptr().cast_mut()) }
}

type Two = unsafe extern "C" fn(c_ushort, *mut c_char, *mut c_char) -> c_short;

fn two(f: Two, h: c_ushort, a: &str, b: &str) -> c_short {
    unsafe { f(h, cs(a).as_ptr().cast_mut(), cs(b).as_ptr().cast_mut()) }
}

fn subdirn(h: c_ushort, dir: &str) -> (c_short, c_short) {
    let mut n = ODBPDFNFIL::default();
    let r = unsafe { cnc_rdpdf_subdirn(h, cs(dir).as_ptr().cast_mut(), &mut n) };
    assert_eq!(r, EW_OK, "{dir}");
    (n.dir_num, n.file_num)
}

fn name256(f: impl FnOnce(*mut c_char) -> c_short) -> String {
    let mut b = [0 as c_char; 256];
    assert_eq!(f(b.as_mut_ptr()), EW_OK);
    let b: Vec<u8> = b
        .iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8)
        .collect();
    String::from_utf8(b).unwrap()
}

const P1: &str = "//CNC_MEM/USER/PATH1/";

#[test]
fn folders_hold_the_store() {
    let (_s, h) = sim::start_alloc(idle());
    let mut drv = ODBPDFDRV::default();
    assert_eq!(unsafe { cnc_rdpdf_drive(h, &mut drv) }, EW_OK);
    assert_eq!(drv.max_num, 1);
    assert_eq!(subdirn(h, "//CNC_MEM/USER/"), (2, 0), "LIBRARY and PATH1");
    assert_eq!(subdirn(h, P1), (0, 3));
    assert_eq!(on(cnc_pdf_add, h, "//CNC_MEM/USER/JOBS/"), EW_OK);
    assert_eq!(
        on(cnc_pdf_add, h, "//CNC_MEM/USER/JOBS/"),
        EW_DATA,
        "exists"
    );
    assert_eq!(
        on(cnc_pdf_add, h, "//CNC_MEM/NONE/X/"),
        EW_DATA,
        "no parent"
    );
    assert_eq!(subdirn(h, "//CNC_MEM/USER/"), (3, 0));
    assert_eq!(on(cnc_pdf_del, h, P1), EW_DATA, "the CNC's own folder");
    assert_eq!(on(cnc_pdf_del, h, "//CNC_MEM/USER/JOBS/"), EW_OK);
    // Programs: the path's store.
    assert_eq!(on(cnc_pdf_add, h, &format!("{P1}O0042")), EW_OK);
    assert_eq!(numbers(h), vec![42, 100, 500, 1234]);
    assert_eq!(on(cnc_pdf_del, h, &format!("{P1}O0500")), EW_PROT);
    assert_eq!(on(cnc_pdf_del, h, &format!("{P1}O0042")), EW_OK);
    assert_eq!(
        two(cnc_pdf_rename, h, &format!("{P1}O0100"), "O0200"),
        EW_OK
    );
    assert_eq!(
        two(cnc_pdf_copy, h, &format!("{P1}O0200"), P1),
        EW_DATA,
        "same number"
    );
    assert_eq!(
        two(
            cnc_pdf_copy,
            h,
            &format!("{P1}O0200"),
            &format!("{P1}O0300")
        ),
        EW_OK
    );
    assert_eq!(
        two(
            cnc_pdf_move,
            h,
            &format!("{P1}O0300"),
            &format!("{P1}O0400")
        ),
        EW_OK
    );
    assert_eq!(numbers(h), vec![200, 400, 500, 1234]);
    assert!(upload(h, 400).unwrap().starts_with("%\nO0400 (WARM UP)"));
    // Current folder and main program; a bare name is in the current folder.
    let cur = |k: c_short| name256(|b| unsafe { cnc_rdpdf_curdir(h, k, b) });
    assert_eq!(cur(1), P1);
    assert_eq!(on(cnc_pdf_slctmain, h, "O0400"), EW_OK);
    assert_eq!(
        name256(|b| unsafe { cnc_pdf_rdmain(h, b) }),
        format!("{P1}O0400")
    );
    let dir = cs("//CNC_MEM/USER/LIBRARY/");
    assert_eq!(
        unsafe { cnc_wrpdf_curdir(h, 2, dir.as_ptr().cast_mut()) },
        EW_OK
    );
    assert_eq!(
        (cur(1), cur(2)),
        (P1.to_string(), "//CNC_MEM/USER/LIBRARY/".to_string())
    );
    assert_eq!(
        unsafe { cnc_rdpdf_curdir(h, 3, [0 as c_char; 256].as_mut_ptr()) },
        EW_ATTRIB
    );
}

/// Lines `from..` (`lines` of them) of program `name`, by cnc_rdpdf_line.
fn read_lines(h: c_ushort, name: &str, from: u32, lines: u32) -> String {
    let mut buf = [0 as c_char; 512];
    let (mut ll, mut dl): (c_ulong, c_ulong) = (lines as c_ulong, 512);
    let p = cs(name);
    let r = unsafe {
        cnc_rdpdf_line(
            h,
            p.as_ptr().cast_mut(),
            from as c_ulong,
            buf.as_mut_ptr(),
            &mut ll,
            &mut dl,
        )
    };
    assert_eq!(r, EW_OK);
    buf[..dl as usize]
        .iter()
        .map(|&c| c as u8 as char)
        .collect()
}

#[test]
fn lines_of_a_program_are_edited_in_place() {
    let (_s, h) = sim::start_alloc(idle());
    let o100 = format!("{P1}O0100");
    assert_eq!(
        read_lines(h, &o100, 2, 2),
        "N10 G91 G28 Z0.;\nN20 M03 S1000;\n"
    );
    let mut add = *b"N15 G04 X1.;\n";
    let p = cs(&o100);
    let r = unsafe {
        cnc_wrpdf_line(
            h,
            p.as_ptr().cast_mut(),
            2,
            add.as_mut_ptr().cast(),
            add.len() as c_ulong,
        )
    };
    assert_eq!(r, EW_OK);
    assert_eq!(
        read_lines(h, &o100, 2, 3),
        "N10 G91 G28 Z0.;\nN15 G04 X1.;\nN20 M03 S1000;\n"
    );
    assert_eq!(
        unsafe { cnc_pdf_delline(h, p.as_ptr().cast_mut(), 3, 1) },
        EW_OK
    );
    assert!(
        upload(h, 100).unwrap().contains("Z0.\nN20 M03"),
        "the upload sees the edit"
    );
    let keep = cs(&format!("{P1}O0500"));
    assert_eq!(
        unsafe { cnc_pdf_delline(h, keep.as_ptr().cast_mut(), 1, 1) },
        EW_PROT
    );
    // Execution pointer on a program, then delete all (the protected one stays).
    let mut blk: c_long = 3;
    assert_eq!(
        unsafe { cnc_pdf_wractpt(h, p.as_ptr().cast_mut(), 0, &mut blk) },
        EW_OK
    );
    assert_eq!(blk, 3);
    let dir = cs(P1);
    assert_eq!(
        unsafe { cnc_pdf_delall(h, 1, dir.as_ptr().cast_mut()) },
        EW_OK
    );
    assert_eq!(numbers(h), vec![500]);
}

#[test]
fn directory_lists_show_folders_and_programs() {
    let (_s, h) = sim::start_alloc(idle());
    let mut inp: IDBPDFADIR = unsafe { std::mem::zeroed() };
    for (d, c) in inp.path.iter_mut().zip(P1.bytes()) {
        *d = c as c_char;
    }
    let mut out: [ODBPDFADIR; 8] = unsafe { std::mem::zeroed() };
    let mut n: c_short = 8;
    assert_eq!(
        unsafe { cnc_rdpdf_alldir(h, &mut n, &mut inp, out.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(n, 3);
    let name = |d: &[c_char]| -> String {
        d.iter()
            .take_while(|&&c| c != 0)
            .map(|&c| c as u8 as char)
            .collect()
    };
    let got: Vec<(c_short, String, i32)> = out[..3]
        .iter()
        .map(|e| (e.data_kind, name(&e.d_f), e.size))
        .collect();
    assert_eq!(
        got.iter().map(|g| g.1.as_str()).collect::<Vec<_>>(),
        ["O0100", "O0500", "O1234"]
    );
    assert_eq!(got[0].2, dir(h)[0].1, "the size cnc_rdprogdir3 reports");
    assert_eq!(name(&out[0].comment), "(WARM UP)");

    let mut sin: IDBPDFSDIR = unsafe { std::mem::zeroed() };
    for (d, c) in sin.path.iter_mut().zip("//CNC_MEM/USER/".bytes()) {
        *d = c as c_char;
    }
    assert_eq!(on(cnc_pdf_add, h, "//CNC_MEM/USER/JOBS/"), EW_OK);
    let mut sub: [ODBPDFSDIR; 8] = unsafe { std::mem::zeroed() };
    let mut n: c_short = 8;
    assert_eq!(
        unsafe { cnc_rdpdf_subdir(h, &mut n, &mut sin, sub.as_mut_ptr()) },
        EW_OK
    );
    let names: Vec<String> = sub[..n as usize].iter().map(|s| name(&s.d_f)).collect();
    assert_eq!(names, ["LIBRARY", "PATH1", "JOBS"]);
    let mut n: c_short = 0;
    assert_eq!(
        unsafe { cnc_rdpdf_subdir(h, &mut n, &mut sin, sub.as_mut_ptr()) },
        EW_LENGTH
    );
}
