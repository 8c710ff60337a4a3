//! The running machine: the live state as a function of the time since the
//! simulator started, checked with synthetic instants (Machine::advance_to)
//! and through the C ABI against a simulator whose clock is set
//! (Simulator::set_elapsed). No sleeps, no timed assertions.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Machine, Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::c_ushort;
use std::time::Duration;

const BASE: &str = sim::running_30i!(
    true,
    r#"
[[path.axis]]
name = "X"
decimals = 3
absolute = 0
machine = 100000
relative = 0

[[path.axis]]
name = "Y"
decimals = 3
absolute = 0
machine = 0
relative = 7000

[[path.spindle]]
name = "S"
speed = 0

[[program]]
number = 1
text = """
O0001 (TEST);
N10 G90 G00 X10. Y0.;
N20 G01 X20. F300 S1000 M03;
N30 G91 Y5.;
N40 G04 X1.;
(A COMMENT LINE);
N50 M05 M30;
%
"""

[[program]]
number = 2
text = """
O0002;
N10 G91 G01 X1. F100;
N20 M30;
%
"""
"#
);

fn profile(extra: &str) -> Profile {
    Profile::parse(&format!("{BASE}\n{extra}")).expect("profile")
}

fn at(m: &mut Machine, secs: f64) {
    let t = m.started + Duration::from_secs_f64(secs);
    m.advance_to(t);
}

fn xy(m: &Machine) -> (i32, i32) {
    let a = &m.profile.paths[0].axes;
    (a[0].absolute, a[1].absolute)
}

#[test]
fn axes_interpolate_between_block_end_points() {
    let mut m = Machine::new(profile(""));
    at(&mut m, 0.5);
    let a = &m.profile.paths[0].axes;
    // N10 G00 X10.: half-way from 0 to 10.000 mm.
    assert_eq!(a[0].absolute, 5000);
    assert_eq!(
        a[0].machine, 105000,
        "machine = absolute + the profile's offset"
    );
    assert_eq!(a[0].relative, 5000);
    assert_eq!(a[0].distance, 5000, "remaining distance to the block end");
    assert_eq!((a[1].absolute, a[1].relative), (0, 7000));
    let r = &m.run[0];
    assert_eq!((r.seq, r.block, r.block_count), (10, 1, 0));
    assert_eq!(r.feed, 600, "G00: 10 mm in one second");
    let s = m.profile.paths[0].status;
    assert_eq!((s.run, s.motion), (3, 1));

    at(&mut m, 1.25);
    assert_eq!(xy(&m), (12500, 0));
    assert_eq!(m.profile.paths[0].axes[0].distance, 7500);
    let r = &m.run[0];
    assert_eq!((r.seq, r.block, r.block_count), (20, 2, 1));
    assert_eq!(r.feed, 300, "G01: the modal F");
    assert_eq!(r.spindle_speed, 1000);
    assert_eq!(m.profile.paths[0].spindles[0].speed, 1000);
    assert!(
        r.exec_text
            .starts_with("N20 G01 X20. F300 S1000 M03;\nN30 G91 Y5.;")
    );

    // N30 G91 Y5.: incremental.
    at(&mut m, 2.5);
    assert_eq!(xy(&m), (20000, 2500));
    assert_eq!(m.run[0].feed, 300);

    // N40 G04: a dwell, X is its time, not a move.
    at(&mut m, 3.5);
    assert_eq!(xy(&m), (20000, 5000));
    assert_eq!(m.profile.paths[0].status.motion, 2);
    assert_eq!(m.run[0].feed, 0);
    assert_eq!(m.profile.paths[0].axes[0].distance, 0);

    // The comment line is a block too; then N50 M05 M30.
    at(&mut m, 4.5);
    assert_eq!((m.run[0].seq, m.run[0].block), (40, 5));
    at(&mut m, 5.5);
    let r = &m.run[0];
    assert_eq!((r.seq, r.block, r.parts), (50, 6, 0));
    assert_eq!(r.spindle_speed, 0, "M05");
    assert_eq!(m.profile.paths[0].status.motion, 0);
}

#[test]
fn the_program_repeats_and_counts_parts() {
    let mut m = Machine::new(profile(""));
    // Pass 2 (6 blocks a pass), N10 again: from (20, 5) to (10, 0) absolute.
    at(&mut m, 6.25);
    let r = &m.run[0];
    assert_eq!((r.seq, r.parts, r.block_count), (10, 1, 6));
    assert_eq!(xy(&m), (17500, 3750));
    assert_eq!(
        r.spindle_speed, 0,
        "M05 from the previous pass holds until M03"
    );
    at(&mut m, 6.0 * 100.0 + 1.5);
    let r = &m.run[0];
    assert_eq!((r.seq, r.parts, r.block_count), (20, 100, 601));
    assert_eq!(xy(&m), (15000, 0));
}

#[test]
fn incremental_programs_drift_pass_after_pass() {
    let mut p = profile("");
    p.paths[0].cycle.program = 2;
    let mut m = Machine::new(p);
    at(&mut m, 6.5); // pass 3 (2 blocks a pass), N10 half done
    assert_eq!(xy(&m).0, 3500);
    assert_eq!(m.run[0].parts, 3);
}

#[test]
fn a_program_that_does_not_repeat_ends() {
    let mut p = profile("");
    p.paths[0].cycle.repeat = false;
    let mut m = Machine::new(p);
    at(&mut m, 1000.0);
    let r = &m.run[0];
    assert!(r.finished);
    assert_eq!((r.seq, r.parts, r.block_count), (50, 1, 6));
    assert_eq!(xy(&m), (20000, 5000));
    let s = m.profile.paths[0].status;
    assert_eq!((s.run, s.motion), (0, 0));
}

#[test]
fn state_is_a_function_of_elapsed_time() {
    let extra = r#"
[[event]]
at = 1.5
every = 10.0
duration = 1.0
action = "feed_hold"
"#;
    let snap = |m: &Machine| {
        let r = &m.run[0];
        (
            xy(m),
            r.seq,
            r.block_count,
            r.parts,
            r.feed,
            m.profile.paths[0].status.run,
        )
    };
    let mut a = Machine::new(profile(extra));
    let mut b = Machine::new(profile(extra));
    for t in [0.0, 3.3, 17.2, 55.9, 123.4] {
        at(&mut a, t);
    }
    at(&mut a, 42.0);
    at(&mut b, 42.0);
    assert_eq!(snap(&a), snap(&b));
    at(&mut a, 7.25);
    at(&mut b, 7.25);
    assert_eq!(snap(&a), snap(&b));
}

#[test]
fn feed_hold_stops_motion_and_the_program_clock() {
    let mut m = Machine::new(profile(
        r#"
[[event]]
at = 1.5
duration = 1.0
action = "feed_hold"
"#,
    ));
    at(&mut m, 2.0);
    assert_eq!(xy(&m), (15000, 0), "frozen where the hold began");
    let s = m.profile.paths[0].status;
    assert_eq!((s.run, s.motion), (2, 0));
    assert!(m.run[0].held);
    assert_eq!(m.run[0].feed, 0);
    at(&mut m, 2.75); // 1.75 s of program time
    assert_eq!(xy(&m), (17500, 0));
    assert_eq!(m.profile.paths[0].status.run, 3);
}

#[test]
fn events_raise_and_clear_alarms_mode_and_emergency() {
    let mut m = Machine::new(profile(
        r#"
[[event]]
at = 10.0
every = 20.0
duration = 5.0
action = "alarm"
alarm = { number = 1001, type = 19, message = "COOLANT LEVEL LOW" }

[[event]]
at = 3.0
action = "mode"
value = 5

[[event]]
at = 50.0
duration = 2.0
action = "emergency"
"#,
    ));
    at(&mut m, 1.0);
    assert!(m.run[0].alarms.is_empty());
    let s = m.profile.paths[0].status;
    assert_eq!((s.alarm, s.aut, s.emergency), (0, 1, 0));
    at(&mut m, 12.0);
    assert_eq!(m.run[0].alarms.len(), 1);
    assert_eq!(m.run[0].alarms[0].number, 1001);
    assert_eq!(m.run[0].alarms[0].message, "COOLANT LEVEL LOW");
    let s = m.profile.paths[0].status;
    assert_eq!((s.alarm, s.aut), (1, 5));
    at(&mut m, 16.0);
    assert!(m.run[0].alarms.is_empty());
    assert_eq!(m.profile.paths[0].status.alarm, 0);
    at(&mut m, 31.0);
    assert_eq!(m.profile.paths[0].status.alarm, 1);
    at(&mut m, 51.0);
    let s = m.profile.paths[0].status;
    assert_eq!((s.emergency, s.run, s.motion), (1, 0, 0));
    assert_eq!(m.run[0].spindle_speed, 0);
    at(&mut m, 52.5);
    assert_eq!(m.profile.paths[0].status.emergency, 0);
}

#[test]
fn profile_alarms_stay_active() {
    let mut m = Machine::new(profile(
        r#"
[[path.alarm]]
number = 500
type = 4
axis = 1
message = "OVER TRAVEL +X"
"#,
    ));
    at(&mut m, 3.0);
    assert_eq!(m.run[0].alarms.len(), 1);
    assert_eq!(m.profile.paths[0].status.alarm, 1);
}

#[test]
fn invalid_running_sections_are_refused() {
    for (extra, needle) in [
        ("", "names no [[program]]"),
        ("[[event]]\naction = \"explode\"", "action must be one of"),
        (
            "[[event]]\naction = \"feed_hold\"\npath = 3",
            "path 3 does not exist",
        ),
        ("[[event]]\naction = \"alarm\"", "needs alarm"),
        ("[[event]]\naction = \"mode\"\nat = -1.0", "at must be"),
    ] {
        let mut text = BASE.to_string();
        if extra.is_empty() {
            text = text.replace("program = 1\n", "program = 77\n");
        }
        let e = Profile::parse(&format!("{text}\n{extra}")).expect_err(needle);
        assert!(e.to_string().contains(needle), "{e} lacks {needle:?}");
    }
    let text = BASE.replace("block_seconds = 1.0", "block_seconds = 0.0");
    assert!(Profile::parse(&text).is_err());
}

#[test]
fn the_default_profile_runs() {
    let mut m = Machine::new(Profile::default());
    at(&mut m, 0.1);
    assert_eq!(m.run[0].program, 1234);
    assert_eq!(m.run[0].seq, 10);
    at(&mut m, 31.0);
    assert_eq!(
        m.profile.paths[0].status.alarm, 1,
        "the coolant alarm at 30 s"
    );
    at(&mut m, 41.0);
    assert_eq!(m.profile.paths[0].status.alarm, 0);
}

// Through the C ABI: cnc_statinfo sees the machine at the simulator's clock.

fn status(h: c_ushort) -> ODBST {
    let mut o = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut o) }, EW_OK);
    o
}

#[test]
fn status_changes_with_the_simulator_clock() {
    let s = Simulator::start(
        profile(
            r#"
[[event]]
at = 10.0
duration = 5.0
action = "feed_hold"

[[event]]
at = 20.0
duration = 5.0
action = "alarm"
alarm = { number = 1001, type = 19, message = "COOLANT LEVEL LOW" }
"#,
        ),
        "127.0.0.1:0",
    )
    .expect("simulator");
    s.set_elapsed(Duration::from_secs_f64(0.5));
    let h = sim::alloc(&s);
    let o = status(h);
    assert_eq!((o.run, o.motion, o.alarm), (3, 1, 0));
    s.set_elapsed(Duration::from_secs(12));
    let o = status(h);
    assert_eq!((o.run, o.motion), (2, 0), "feed hold");
    s.set_elapsed(Duration::from_secs(21));
    let o = status(h);
    assert_eq!((o.run, o.alarm), (3, 1));
    s.set_elapsed(Duration::from_secs(26));
    assert_eq!(status(h).alarm, 0);
    s.set_elapsed(Duration::from_secs(12));
    assert_eq!(status(h).run, 2, "the same time gives the same state");
    sim::free(h);
}

fn rdparam_long(h: c_ushort, number: i16) -> i32 {
    let mut p = std::mem::MaybeUninit::<IODBPSD>::zeroed();
    assert_eq!(
        unsafe { cnc_rdparam(h, number, 0, 8, p.as_mut_ptr()) },
        EW_OK
    );
    unsafe { p.assume_init().u.ldata }
}

fn history_count(h: c_ushort) -> u16 {
    let mut n: c_ushort = 0;
    assert_eq!(unsafe { cnc_rdalmhisno(h, &mut n) }, EW_OK);
    n
}

/// What the running program drives beyond status and positions: feed and
/// spindle readings, the part counter (parameter 6711) and the alarm history.
#[test]
fn feed_parts_and_alarm_history_follow_the_program() {
    let extra = r#"
[[event]]
at = 20.0
duration = 5.0
action = "alarm"
alarm = { number = 500, type = 4, axis = 1, message = "OVER TRAVEL ( SOFT 1 ) +X" }

[param]
[[param.parameter]]
number = 6711
kind = "2word"
values = [100]
"#;
    let s = sim::start(profile(extra));
    s.set_elapsed(Duration::from_secs_f64(1.5)); // N20 G01 X20. F300 S1000 M03
    let h = sim::alloc(&s);
    let mut f = ODBACT::default();
    assert_eq!(unsafe { cnc_actf(h, &mut f) }, EW_OK);
    assert_eq!(f.data, 300, "programmed feed while cutting");
    let mut sp = ODBACT::default();
    assert_eq!(unsafe { cnc_acts(h, &mut sp) }, EW_OK);
    assert_eq!(sp.data, 1000, "S1000 M03");
    let parts0 = rdparam_long(h, 6711);
    assert_eq!(parts0, 100);
    let hist0 = history_count(h);

    s.set_elapsed(Duration::from_secs(21));
    assert_eq!(
        history_count(h),
        hist0 + 1,
        "the raised alarm is in the history"
    );
    let mut m = Machine::new(profile(extra));
    at(&mut m, 21.0);
    let made = m.run[0].parts as i32;
    assert!(made > 0);
    assert_eq!(rdparam_long(h, 6711), 100 + made, "one count per M30");
    s.set_elapsed(Duration::from_secs(21));
    assert_eq!(rdparam_long(h, 6711), 100 + made, "counted once");
    sim::free(h);
}

/// rdaxisdata class 2 through the C ABI: type 0 the servo load (%), type 2
/// the servo current (A, one decimal: the load's share of the rated
/// current), both following the motion.
#[test]
fn servo_load_and_current_follow_the_motion() {
    let text = BASE.replacen(
        "machine = 100000\nrelative = 0\n",
        "machine = 100000\nrelative = 0\nservo_load = 30\nrated_current = 20.0\n",
        1,
    );
    assert_ne!(text, BASE);
    let s = sim::start(Profile::parse(&text).expect("profile"));
    let h = sim::alloc(&s);
    let read = || {
        let mut t: [i16; 2] = [0, 2];
        let mut len: i16 = 4;
        let mut ax = [ODBAXDT::default(); 8];
        assert_eq!(
            unsafe { cnc_rdaxisdata(h, 2, t.as_mut_ptr(), 2, &mut len, ax.as_mut_ptr()) },
            EW_OK
        );
        assert_eq!(len, 2);
        let (load, cur) = (ax[0], ax[4]);
        assert_eq!((load.name[0] as u8, load.unit, load.dec), (b'X', 8, 0));
        assert_eq!((cur.name[0] as u8, cur.unit, cur.dec), (b'X', 9, 1));
        (load.data, cur.data)
    };
    s.set_elapsed(Duration::from_secs_f64(1.5)); // N20 G01 X20.: moving
    assert_eq!(read(), (30, 60), "30 % of 20 A = 6.0 A");
    s.set_elapsed(Duration::from_secs_f64(3.5)); // N40 G04: at rest
    assert_eq!(read(), (10, 20), "a third of the load at rest");
    sim::free(h);
}
