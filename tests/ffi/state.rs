//! One machine state: the answers about the same thing agree, all driven by
//! the running program on the simulator's settable clock (no sleeps):
//! cnc_modal follows the program's G codes and F, S, M, T as cnc_actf and
//! cnc_acts do; cnc_rdtimer counts on the simulator's clock and a feed hold
//! stops it without taking anything back; an inch machine reports its feed
//! in inch/min, a G95 program per revolution.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::Simulator;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::c_ushort;
use std::time::Duration;

const PROFILE: &str = sim::running_30i!(
    false,
    r#"
[path.modal]
g = [1, 2, 0]
aux = { 101 = 7, 103 = 999 }

[[path.axis]]
name = "X"
decimals = 3

[[path.spindle]]
name = "S1"
speed = 0

[timers]
operating = 10
cutting = 5

[[program]]
number = 1
text = """
O0001;
N10 G90 G00 X10.;
N20 G01 X20. F300 S1000 M03;
N30 G91 G02 X5. F200 T12;
N40 G00 X5.;
N50 M05;
N60 M30;
%
"""
"#
);

fn at(s: &Simulator, secs: f64) {
    s.set_elapsed(Duration::from_secs_f64(secs));
}

/// cnc_modal of one G group (type 0..) or other code (type 100..).
fn modal(h: c_ushort, kind: i16) -> i32 {
    let mut m = ODBMDL::default();
    assert_eq!(unsafe { cnc_modal(h, kind, 0, &mut m) }, EW_OK);
    unsafe {
        if kind < 100 {
            i32::from(m.modal.g_data as u8)
        } else {
            m.modal.aux.aux_data
        }
    }
}

fn actf(h: c_ushort) -> i32 {
    let mut a = ODBACT::default();
    assert_eq!(unsafe { cnc_actf(h, &mut a) }, EW_OK);
    a.data
}

fn acts(h: c_ushort) -> i32 {
    let mut a = ODBACT::default();
    assert_eq!(unsafe { cnc_acts(h, &mut a) }, EW_OK);
    a.data
}

/// cnc_rdtimer `kind` in milliseconds.
fn timer(h: c_ushort, kind: i16) -> i64 {
    let mut t = IODBTIME::default();
    assert_eq!(unsafe { cnc_rdtimer(h, kind, &mut t) }, EW_OK);
    i64::from(t.minute) * 60_000 + i64::from(t.msec)
}

#[test]
fn modal_codes_follow_the_running_program() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    // (group 01, group 02, group 03, F, S, M, T, D) and (actf, acts).
    let look = |h| {
        let codes = [0, 1, 2, 103, 107, 106, 108, 101].map(|k| modal(h, k));
        (codes, actf(h), acts(h))
    };
    at(&s, 0.5);
    let (c, f, _) = look(h);
    assert_eq!(c, [0, 2, 0, 999, 0, 0, 0, 7], "G00 G90, profile");
    assert!(f > 0, "a rapid move: the traverse speed");
    at(&s, 1.5);
    assert_eq!(look(h), ([1, 2, 0, 300, 1000, 3, 0, 7], 300, 1000));
    at(&s, 2.5);
    assert_eq!(look(h), ([2, 2, 1, 200, 1000, 3, 12, 7], 200, 1000));
    at(&s, 4.5);
    assert_eq!(look(h), ([0, 2, 1, 200, 1000, 5, 12, 7], 0, 0), "M05");
    at(&s, 30.0);
    let (c, f, _) = look(h);
    assert_eq!((c[0], c[5], f), (0, 30, 0), "ended at M30, the codes stay");
    // All groups at once (type -1) agree with the single reads.
    let mut m = ODBMDL::default();
    assert_eq!(unsafe { cnc_modal(h, -1, 0, &mut m) }, EW_OK);
    assert_eq!(unsafe { &m.modal.g_rdata[..3] }, &[0, 2, 1]);
    sim::free(h);
}

#[test]
fn timers_run_on_the_simulator_clock_and_a_hold_only_stops_them() {
    let hold = "\n[[event]]\nat = 1.5\nduration = 1.0\naction = \"feed_hold\"\n";
    let s = sim::start_toml(&format!("{PROFILE}{hold}"));
    let h = sim::alloc(&s);
    let (op0, cut0) = (10 * 60_000, 5 * 60_000);
    // (power-on, operating, cutting, cycle) past the profile's minutes.
    let all = |h| {
        (
            timer(h, 0),
            timer(h, 1) - op0,
            timer(h, 2) - cut0,
            timer(h, 3),
        )
    };
    at(&s, 1.5);
    assert_eq!(all(h), (1500, 1500, 500, 1500), "N20 G01");
    at(&s, 2.0);
    assert_eq!(all(h), (2000, 1500, 500, 1500), "held");
    at(&s, 3.0);
    assert_eq!(all(h), (3000, 2000, 1000, 2000), "N30 (G02) begins");
    at(&s, 5.0);
    assert_eq!(all(h), (5000, 4000, 2000, 4000), "N40 G00 is not cutting");
    at(&s, 100.0);
    assert_eq!(all(h), (100_000, 6000, 2000, 6000), "ended at M30");

    // A second run: the cycle time starts again, the others count on.
    assert_eq!(cnc_start(h), EW_OK);
    at(&s, 101.5);
    assert_eq!(all(h), (101_500, 7500, 2500, 1500));
    assert_eq!(cnc_reset(h), EW_OK);
    at(&s, 200.0);
    assert_eq!(all(h), (200_000, 7500, 2500, 1500), "reset: they stay");
    sim::free(h);
}

fn feed_unit(profile: &str) -> i16 {
    let s = sim::start_toml(profile);
    at(&s, 0.5);
    let h = sim::alloc(&s);
    let mut sp = ODBSPEED::default();
    assert_eq!(unsafe { cnc_rdspeed(h, 0, &mut sp) }, EW_OK);
    sim::free(h);
    sp.actf.unit
}

#[test]
fn an_inch_machine_reports_its_feed_in_inch_per_minute() {
    assert_eq!(feed_unit(PROFILE), 0, "mm/min");
    let inch = PROFILE.replace("decimals = 3", "decimals = 4\nunit = 1");
    assert_eq!(feed_unit(&inch), 1, "inch/min");
    // G95 in the program: feed per revolution (cnc_modal type 4 = 1).
    let g95 = |p: &str| p.replace("N10 G90 G00", "N10 G90 G95 G00");
    assert_eq!(feed_unit(&g95(PROFILE)), 3, "mm/rev");
    assert_eq!(feed_unit(&g95(&inch)), 4, "inch/rev");
    let s = sim::start_toml(&g95(PROFILE));
    at(&s, 0.5);
    let h = sim::alloc(&s);
    assert_eq!(modal(h, 4), 1);
    sim::free(h);
}

/// cnc_rdspcss: the S code follows the running program as cnc_modal's,
/// the maximum spindle speed is parameter 3772; no G96 surface speed.
#[test]
fn spindle_css_follows_the_program_and_parameter_3772() {
    let max = "\n[param]\n[[param.parameter]]\nnumber = 3772\nkind = \"2word\"\nvalues = [6000]\n";
    let s = sim::start_toml(&format!("{PROFILE}{max}"));
    let h = sim::alloc(&s);
    let css = |h| {
        let mut c = ODBCSS::default();
        assert_eq!(unsafe { cnc_rdspcss(h, &mut c) }, EW_OK);
        (c.srpm, c.sspm, c.smax)
    };
    at(&s, 0.5);
    assert_eq!(css(h), (0, 0, 6000), "no S yet");
    at(&s, 1.5);
    assert_eq!(css(h), (1000, 0, 6000), "N20 S1000");
    assert_eq!(css(h).0, modal(h, 107));
    assert_eq!(unsafe { cnc_rdspcss(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
}
