//! Machine data (issue 11) through the C ABI against the simulator:
//! cnc_rdopmsg3 (the profile's operator messages and the message a running
//! program's `#3006` shows).
//!
//! Machine information through the C ABI against the simulator: each answer
//! equals the profile (values other than the built-in ones, so a constant
//! could not pass), NULL outputs and bad handles fail before any traffic.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_short, c_ushort};
use std::time::Duration;

/// cnc_rdopmsg3: (code, messages written, the records).
fn opmsg3(h: c_ushort, kind: c_short, num: c_short) -> (i16, c_short, Vec<OPMSG3>) {
    let mut b = vec![OPMSG3::default(); 16];
    let mut n = num;
    let r = unsafe { cnc_rdopmsg3(h, kind, &mut n, b.as_mut_ptr()) };
    (r, n, b)
}

fn text(m: &OPMSG3) -> String {
    let b: Vec<u8> = m
        .data
        .iter()
        .map(|c| *c as u8)
        .take_while(|c| *c != 0)
        .collect();
    String::from_utf8_lossy(&b).into_owned()
}

/// The built-in profile with a `#3006` message block before M05 (block 11:
/// 5.5 s into each pass at 0.5 s a block), on the 30i or the 16i class.
fn message_profile(class16: bool) -> String {
    let t = DEFAULT_PROFILE.replacen("N120 M05;", "N115 #3006=7(CHECK TOOL 1);\nN120 M05;", 1);
    if class16 {
        t.replacen("class = \"30i\"", "class = \"16i\"\nkind = 1", 1)
    } else {
        t
    }
}

#[test]
fn operator_messages_3_read_the_profile_and_a_running_macro_message() {
    for class16 in [false, true] {
        let s = sim::start_toml(&message_profile(class16));
        let h = sim::alloc(&s);
        s.set_elapsed(Duration::from_secs(1));
        // The profile's message (type 0).
        let (r, n, b) = opmsg3(h, 0, 5);
        assert_eq!((r, n), (EW_OK, 1), "16i class: {class16}");
        assert_eq!((b[0].datano, b[0].r#type, b[0].char_num), (2001, 0, 20));
        assert_eq!(text(&b[0]), "CHECK COOLANT NOZZLE");
        // No macro message yet: the 30i answers none, the 16i its
        // "no message" record (number -1).
        let (r, n, b) = opmsg3(h, 4, 5);
        assert_eq!(r, EW_OK);
        if class16 {
            assert_eq!((n, b[0].datano), (1, -1));
        } else {
            assert_eq!(n, 0);
        }

        // The program passes `#3006=7(CHECK TOOL 1)`: its message shows.
        s.set_elapsed(Duration::from_secs_f64(6.2));
        let (r, n, b) = opmsg3(h, 4, 5);
        assert_eq!((r, n), (EW_OK, 1));
        assert_eq!((b[0].datano, b[0].r#type, b[0].char_num), (7, 4, 12));
        assert_eq!(text(&b[0]), "CHECK TOOL 1");
        if !class16 {
            // Every type (-1): the profile's and the macro message, in
            // exchanges of five (12 asked: three exchanges).
            let (r, n, b) = opmsg3(h, -1, 12);
            assert_eq!((r, n), (EW_OK, 2));
            assert_eq!((b[0].datano, b[1].datano), (2001, 7));
            // Still there in the next pass (until a program shows another).
            s.set_elapsed(Duration::from_secs_f64(7.6));
            assert_eq!(opmsg3(h, -1, 5).1, 2);
            // One asked for: the first.
            let (r, n, b) = opmsg3(h, -1, 1);
            assert_eq!((r, n, b[0].datano), (EW_OK, 1, 2001));
        }

        // Local checks: num ≤ 0 EW_LENGTH, NULL EW_DATA.
        assert_eq!(opmsg3(h, 0, 0).0, EW_LENGTH);
        assert_eq!(opmsg3(h, 0, -1).0, EW_LENGTH);
        let mut n: c_short = 5;
        assert_eq!(
            unsafe { cnc_rdopmsg3(h, 0, &mut n, std::ptr::null_mut()) },
            EW_DATA
        );
        // A type the CNC does not know: its EW_ATTRIB.
        assert_eq!(opmsg3(h, 5, 5).0, EW_ATTRIB);
        sim::free(h);
        drop(s);
    }
}

#[test]
fn control_signals_read_the_pmc_and_the_running_spindle() {
    let s = sim::start_toml(DEFAULT_PROFILE);
    let h = sim::alloc(&s);
    s.set_elapsed(Duration::from_secs(1));
    // Input signals: G070..G073 of the first spindle, as the test writes them.
    let mut w = [0u8; 12];
    w[4..6].copy_from_slice(&70u16.to_le_bytes());
    w[6..8].copy_from_slice(&73u16.to_le_bytes());
    w[8..12].copy_from_slice(&[0x81, 0x02, 0x40, 0x10]);
    assert_eq!(unsafe { pmc_wrpmcrng(h, 12, w.as_mut_ptr().cast()) }, EW_OK);
    let mut di = [0xccu8; 8];
    assert_eq!(unsafe { cnc_rdctrldi(h, di.as_mut_ptr().cast()) }, EW_OK);
    assert_eq!(
        di,
        [0x81, 0x02, 0x40, 0x10, 0xcc, 0xcc, 0xcc, 0xcc],
        "the struct only"
    );

    // Output signals: the spindle turns at S12000 (SARA, bit 3) ...
    let mut o = ODBSPDO::default();
    assert_eq!(unsafe { cnc_rdctrldo(h, &mut o) }, EW_OK);
    assert_eq!(o.sgnl1 as u8 & 0x0b, 0x08);
    // ... and stands after the program's M05 (SSTA, bit 1).
    s.set_elapsed(Duration::from_secs_f64(6.2));
    assert_eq!(unsafe { cnc_rdctrldo(h, &mut o) }, EW_OK);
    assert_eq!(o.sgnl1 as u8 & 0x0b, 0x02);

    assert_eq!(unsafe { cnc_rdctrldi(h, std::ptr::null_mut()) }, EW_DATA);
    assert_eq!(unsafe { cnc_rdctrldo(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
    drop(s);
}

fn prstr(h: c_ushort) -> (i16, ODBPRS) {
    let mut p = ODBPRS::default();
    let r = unsafe { cnc_rdprstrinfo(h, &mut p) };
    (r, p)
}

fn absolute_x(h: c_ushort) -> i32 {
    let mut a = ODBAXIS {
        dummy: 0,
        r#type: 0,
        data: [0; 32],
    };
    assert_eq!(unsafe { cnc_absolute(h, 1, 8, &mut a) }, EW_OK);
    a.data[0]
}

#[test]
fn program_restart_information_follows_a_reset_made_here() {
    let s = sim::start_toml(DEFAULT_PROFILE);
    let h = sim::alloc(&s);
    // The program runs; nothing interrupted it yet: no restart data.
    s.set_elapsed(Duration::from_secs(1));
    let (r, p) = prstr(h);
    assert_eq!((r, p.data_info), (EW_OK, [0; 5]));
    assert!(p.dest.iter().chain(&p.dist).all(|v| *v == 0));

    // A reset at N70 (block 7, X moving to 50 mm at F1500): the block, the
    // modal M03, T1, S12000 (no B code) and where the axes stopped.
    s.set_elapsed(Duration::from_secs_f64(3.2));
    assert_eq!(cnc_reset(h), EW_OK);
    let x = absolute_x(h);
    assert!(x > 0 && x < 50_000, "X stopped on its way: {x}");
    let (r, p) = prstr(h);
    assert_eq!((r, p.data_info), (EW_OK, [1, 1, 1, 1, 0]));
    assert_eq!(
        (p.rstr_bc, p.rstr_m[0], p.rstr_t[0], p.rstr_s),
        (7, 3, 1, 12000)
    );
    assert_eq!((p.dest[0], p.dist[0]), (x, 0));

    // Started again from the top: the distance back to the restart point.
    assert_eq!(cnc_start(h), EW_OK);
    s.set_elapsed(Duration::from_secs_f64(5.0));
    let now = absolute_x(h);
    let (r, p) = prstr(h);
    assert_eq!(r, EW_OK);
    assert_eq!((p.dest[0], p.dist[0]), (x, x - now));
    assert_ne!(p.dist[0], 0);

    assert_eq!(unsafe { cnc_rdprstrinfo(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
    drop(s);
}

#[test]
fn ether_info_is_the_profiles_board() {
    for (board, device) in [(2i16, 1i16), (0, 0)] {
        let text = fwlib32::sim::profile::DEFAULT_PROFILE
            .replacen("ether_type = 1", &format!("ether_type = {board}"), 1)
            .replacen("ether_device = 0", &format!("ether_device = {device}"), 1);
        let (_s, h) = sim::start_alloc(Profile::parse(&text).unwrap());
        let (mut t, mut d) = (-1i16, -1i16);
        assert_eq!(unsafe { cnc_rdetherinfo(h, &mut t, &mut d) }, EW_OK);
        assert_eq!((t, d), (board, device));
        assert_eq!(
            unsafe { cnc_rdetherinfo(h, std::ptr::null_mut(), &mut d) },
            EW_DATA
        );
        assert_eq!(
            unsafe { cnc_rdetherinfo(h, &mut t, std::ptr::null_mut()) },
            EW_DATA
        );
        assert_eq!(cnc_freelibhndl(h), EW_OK);
        assert_eq!(unsafe { cnc_rdetherinfo(h, &mut t, &mut d) }, EW_HANDLE);
    }
}

/// A two-axis machine running O0001 one block a second: N10 rapid to X10
/// (10 mm in 1 s), N20 X20 at F300 (10 mm), N30 Y+5, N40 a dwell.
const RUNNING: &str = sim::running_30i!(
    true,
    r#"
[path.offset]
memory = 1
enable = 0
tool = [[10, 20], [30, 40], [50, 60]]

[[path.tool_group]]
number = 1
life = 100
count = 5
tool = [{ number = 11, length = 1, radius = 1 }]

[[path.tool_group]]
number = 7
life = 10
count = 0
tool = [{ number = 12, length = 2, radius = 2 }]

[[path.axis]]
name = "X"
decimals = 3
servo_load = 30
loop_gain = 2500
lead = 5.0

[[path.axis]]
name = "Y"
decimals = 3
servo_load = 12

[[program]]
number = 1
text = """
O0001 (TEST);
N10 G90 G00 X10. Y0.;
N20 G01 X20. F300;
N30 G91 Y5.;
N40 G04 X1.;
N50 M30;
%
"""
"#
);

fn servo(h: u16, f: unsafe extern "C" fn(u16, *mut std::os::raw::c_long) -> i16) -> [i32; 2] {
    let mut v = [-1i32; 32];
    assert_eq!(unsafe { f(h, v.as_mut_ptr().cast()) }, EW_OK);
    assert!(
        v[2..].iter().all(|x| *x == -1),
        "one value per axis of the path"
    );
    [v[0], v[1]]
}

#[test]
fn servo_figures_follow_the_running_program() {
    let s = sim::start_toml(RUNNING);
    let h = sim::alloc(&s);
    assert_eq!(servo(h, cnc_rdloopgain), [2500, 3000], "profile, else 3000");

    // N10: X moves 10 mm in 1 s = 600 mm/min; over a 5 mm lead 120 rpm.
    s.set_elapsed(std::time::Duration::from_secs_f64(0.5));
    assert_eq!(servo(h, cnc_rdsrvspeed), [120, 0]);
    // N30: Y moves 5 mm in 1 s over the default 10 mm lead: 30 rpm.
    s.set_elapsed(std::time::Duration::from_secs_f64(2.5));
    assert_eq!(servo(h, cnc_rdsrvspeed), [0, 30]);
    let current = || {
        let mut cur = [-1i16; 32];
        assert_eq!(unsafe { cnc_rdcurrent(h, cur.as_mut_ptr()) }, EW_OK);
        assert!(cur[2..].iter().all(|x| *x == -1));
        [cur[0], cur[1]]
    };
    assert_eq!(
        current(),
        [30, 12],
        "the profile's loads while the path moves"
    );
    // N40: the dwell, nothing turns; a third of the load at rest.
    s.set_elapsed(std::time::Duration::from_secs_f64(3.5));
    assert_eq!(servo(h, cnc_rdsrvspeed), [0, 0]);
    assert_eq!(current(), [10, 4]);

    for f in [cnc_rdloopgain, cnc_rdsrvspeed] {
        assert_eq!(unsafe { f(h, std::ptr::null_mut()) }, EW_DATA);
    }
    assert_eq!(unsafe { cnc_rdcurrent(h, std::ptr::null_mut()) }, EW_DATA);
}

#[test]
fn offset_and_tool_life_sizes_are_the_profiles() {
    let s = sim::start_toml(RUNNING);
    let h = sim::alloc(&s);
    let mut i = fwlib32::types::ODBTLINF2::default();
    assert_eq!(unsafe { cnc_rdtofsinfo2(h, &mut i) }, EW_OK);
    assert_eq!((i.ofs_type, i.use_no, i.ofs_enable), (1, 3, 0));
    let mut g = fwlib32::types::ODBTLIFE2::default();
    assert_eq!(unsafe { cnc_rdngrp(h, &mut g) }, EW_OK);
    assert_eq!(g.data, 2);
    assert_eq!(unsafe { cnc_rdngrp(h, std::ptr::null_mut()) }, EW_DATA);
    assert_eq!(unsafe { cnc_rdtofsinfo2(h, std::ptr::null_mut()) }, EW_DATA);
}

#[test]
fn machining_times_are_the_runs_completed_then_the_profiles() {
    let text = RUNNING.replacen(
        "[path.status]",
        "proc_times = [[77, 1, 2, 3], [78, 0, 59, 59]]\n[path.status]",
        1,
    );
    let s = sim::start_toml(&text);
    let h = sim::alloc(&s);
    let read = || {
        let mut t = fwlib32::types::ODBPTIME::default();
        assert_eq!(unsafe { cnc_rdproctime(h, &mut t) }, EW_OK);
        let d = &t.data[..t.num as usize];
        d.iter()
            .map(|x| (x.prg_no, x.hour, x.minute as u8, x.second as u8))
            .collect::<Vec<_>>()
    };
    // Before the first run ends: the profile's earlier runs.
    s.set_elapsed(std::time::Duration::from_secs_f64(2.0));
    assert_eq!(read(), [(77, 1, 2, 3), (78, 0, 59, 59)]);
    // O0001 is 5 blocks of 1 s: after 4 runs, four 5-second runs first, at most 10.
    s.set_elapsed(std::time::Duration::from_secs_f64(24.5));
    let r = read();
    assert_eq!(r.len(), 6);
    assert!(r[..4].iter().all(|x| *x == (1, 0, 0, 5)), "{r:?}");
    assert_eq!(r[4], (77, 1, 2, 3));
    s.set_elapsed(std::time::Duration::from_secs_f64(600.0));
    assert_eq!(read(), vec![(1, 0, 0, 5); 10]);
    assert_eq!(unsafe { cnc_rdproctime(h, std::ptr::null_mut()) }, EW_DATA);
}

#[test]
fn serial_spindle_ratios_are_the_profiles() {
    let text = fwlib32::sim::profile::DEFAULT_PROFILE
        .replacen("max_rpm_ratio = 12000", "max_rpm_ratio = 9000", 1)
        .replacen("gear_ratio = 2", "gear_ratio = 3", 1);
    let (_s, h) = sim::start_alloc(Profile::parse(&text).unwrap());
    for (f, want) in [
        (cnc_rdspmaxrpm as unsafe extern "C" fn(_, _, _) -> _, 9000),
        (cnc_rdspgear, 3),
    ] {
        let mut o = fwlib32::types::ODBSPN::default();
        assert_eq!(unsafe { f(h, -1, &mut o) }, EW_OK);
        assert_eq!((o.datano, o.data[0]), (-1, want));
        let mut o = fwlib32::types::ODBSPN::default();
        assert_eq!(unsafe { f(h, 1, &mut o) }, EW_OK);
        assert_eq!((o.datano, o.data[0]), (1, want));
        assert_eq!(unsafe { f(h, 2, &mut o) }, EW_NUMBER, "one spindle");
        assert_eq!(unsafe { f(h, 9, &mut o) }, EW_NUMBER);
        assert_eq!(unsafe { f(h, 1, std::ptr::null_mut()) }, EW_DATA);
    }
}

#[test]
fn sysinfo_ex_is_the_open_response() {
    // Two paths: a 3-axis mill with a spindle, a 2-axis lathe without.
    let text = format!(
        "{}\n[[path]]\nmachine = \"lathe\"\n[[path.axis]]\nname = \"X\"\n[[path.axis]]\nname = \"Z\"\n",
        fwlib32::sim::profile::DEFAULT_PROFILE
    );
    let (_s, h) = sim::start_alloc(Profile::parse(&text).unwrap());
    let mut x: fwlib32::types::ODBSYSEX = unsafe { std::mem::zeroed() };
    x.reserved = [-1, -1];
    x.path[14].reserved = -1;
    assert_eq!(unsafe { cnc_sysinfo_ex(h, &mut x) }, EW_OK);
    assert_eq!((x.max_axis, x.max_spdl, x.max_path), (32, 8, 2));
    assert_eq!(
        (x.ctrl_axis, x.ctrl_srvo, x.ctrl_spdl, x.ctrl_path),
        (5, 5, 1, 2)
    );
    assert_eq!((x.max_mchn, x.ctrl_mchn, x.reserved), (1, 1, [-1, -1]));
    let p = |k: usize| {
        let p = x.path[k];
        (
            p.system.to_le_bytes(),
            p.group,
            p.ctrl_axis,
            p.ctrl_spdl,
            p.mchn_no,
        )
    };
    assert_eq!(p(0), (*b"M ", 1, 3, 1, 1));
    assert_eq!(p(1), (*b"T ", 1, 2, 0, 1));
    assert_eq!(p(2), ([0, 0], 0, 0, 0, 0));
    assert_eq!(
        x.path[14].reserved, -1,
        "the reserved words are not written"
    );
    assert_eq!(unsafe { cnc_sysinfo_ex(h, std::ptr::null_mut()) }, EW_DATA);
}

#[test]
fn operation_history_records_the_alarms_the_machine_raises() {
    // The built-in profile raises alarm 500 at 30 s, then every 60 s.
    let s = sim::start(Profile::default());
    let h = sim::alloc(&s);
    let count = || {
        let mut n = 0xffffu16;
        assert_eq!(unsafe { cnc_rdophisno(h, &mut n) }, EW_OK);
        n
    };
    // The profile's five records; cleared, the alarm at 31 s comes with a
    // date and a time record.
    assert_eq!(count(), 5);
    assert_eq!(cnc_clearophis(h, 0), EW_OK);
    s.set_elapsed(std::time::Duration::from_secs(10));
    assert_eq!(count(), 0);
    s.set_elapsed(std::time::Duration::from_secs(31));
    assert_eq!(count(), 3);
    // Stopped: the alarm at 90 s is not recorded; started again, the one at
    // 150 s is (with a time record on a new second of the clock, a date
    // record on a new day).
    assert_eq!(cnc_stopophis(h), EW_OK);
    s.set_elapsed(std::time::Duration::from_secs(91));
    assert_eq!(count(), 3);
    assert_eq!(cnc_startophis(h), EW_OK);
    s.set_elapsed(std::time::Duration::from_secs(151));
    assert!((4..=6).contains(&count()));
    assert_eq!(cnc_clearophis(h, 0), EW_OK);
    assert_eq!(count(), 0);
    assert_eq!(unsafe { cnc_rdophisno(h, std::ptr::null_mut()) }, EW_DATA);
}

#[test]
fn operator_message_history_holds_the_messages_shown() {
    let text = fwlib32::sim::profile::DEFAULT_PROFILE.replacen(
        "capacity = 50\n[[operator_message_history.entry]]",
        "capacity = 20\nchars = 128\n[[operator_message_history.entry]]",
        1,
    );
    let (_s, h) = sim::start_alloc(Profile::parse(&text).unwrap());
    let mut n = 0u16;
    assert_eq!(unsafe { cnc_rdomhisno(h, &mut n) }, EW_OK);
    assert_eq!(
        n, 3,
        "the message on display at power-on, the profile's two"
    );
    let mut i = fwlib32::types::ODBOMIF::default();
    assert_eq!(unsafe { cnc_rdomhisinfo(h, &mut i) }, EW_OK);
    assert_eq!((i.om_max, i.om_sum, i.om_char), (20, 3, 128));
    assert_eq!(cnc_stopomhis(h), EW_OK);
    assert_eq!(cnc_startomhis(h), EW_OK);
    assert_eq!(cnc_clearomhis(h), EW_OK);
    assert_eq!(unsafe { cnc_rdomhisno(h, &mut n) }, EW_OK);
    assert_eq!(n, 0);
    assert_eq!(unsafe { cnc_rdomhisinfo(h, std::ptr::null_mut()) }, EW_DATA);
}

#[test]
fn servo_and_spindle_figures_follow_the_profile_and_the_motion() {
    let text = fwlib32::sim::profile::DEFAULT_PROFILE.replacen(
        "alarm = 0                # spindle",
        "alarm = 7                # spindle",
        1,
    );
    let p = Profile::parse(&text).unwrap();
    let (_s, h) = sim::start_alloc(p.clone());
    let mut alm = [0x55i8; 8];
    assert_eq!(unsafe { cnc_rdspdlalm(h, alm.as_mut_ptr().cast()) }, EW_OK);
    assert_eq!(alm[0], 7);
    assert_eq!(alm[1], 0x55, "one byte per spindle");

    let read = |f: unsafe extern "C" fn(u16, i16, i16, *mut ODBAXIS) -> i16, axis: i16| {
        let mut b = ODBAXIS::default();
        assert_eq!(unsafe { f(h, axis, 4 + 4 * 32, &mut b) }, EW_OK);
        assert_eq!(b.r#type, axis);
        b.data
    };
    assert_eq!(read(cnc_skip, 1)[0], p.paths[0].axes[0].skip);
    // Delays follow the motor speed: zero for an axis at rest.
    let speed = {
        let mut v = [0i32; 32];
        assert_eq!(unsafe { cnc_rdsrvspeed(h, v.as_mut_ptr().cast()) }, EW_OK);
        v
    };
    let (srv, acc) = (read(cnc_srvdelay, -1), read(cnc_accdecdly, -1));
    for k in 0..p.paths[0].axes.len() {
        assert_eq!(srv[k] == 0, speed[k] == 0, "axis {k}");
        assert_eq!(acc[k] == 0, speed[k] == 0, "axis {k}");
    }
    let mut b = ODBAXIS::default();
    assert_eq!(unsafe { cnc_srvdelay(h, -1, 8, &mut b) }, EW_LENGTH);
    assert_eq!(unsafe { cnc_skip(h, 33, 8, &mut b) }, EW_ATTRIB);
}
