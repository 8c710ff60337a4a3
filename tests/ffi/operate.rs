//! Operating the simulated machine through the C ABI: cnc_reset stops the
//! running program where it is and clears the reset-clearable alarms,
//! cnc_clralm clears one type, cnc_start runs the main program once from
//! that moment. The simulator's clock is set (no sleeps).

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_long, c_ushort};
use std::time::Duration;

const PROFILE: &str = sim::running_30i!(
    true,
    r#"
[[path.axis]]
name = "X"
decimals = 3

[[path.alarm]]
number = 100
type = 3
message = "PARAMETER WRITE ENABLE"

[[path.alarm]]
number = 401
type = 6
message = "SERVO V-READY OFF"

[[program]]
number = 1
text = """
O0001 (TEST);
N10 G90 G00 X10.;
N20 G01 X20. F300;
N30 M30;
%
"""
"#
);

fn at(s: &Simulator, secs: f64) {
    s.set_elapsed(Duration::from_secs_f64(secs));
}

fn run_state(h: c_ushort) -> i16 {
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    st.run
}

fn x(h: c_ushort) -> i32 {
    let mut a = ODBAXIS::default();
    assert_eq!(unsafe { cnc_absolute(h, 1, 8, &mut a) }, EW_OK);
    a.data[0]
}

fn alarm_bits(h: c_ushort) -> c_long {
    let mut bits: c_long = 0;
    assert_eq!(unsafe { cnc_alarm2(h, &mut bits) }, EW_OK);
    bits & 0xffff_ffff
}

fn blocks(h: c_ushort) -> c_long {
    let mut n: c_long = 0;
    assert_eq!(unsafe { cnc_rdblkcount(h, &mut n) }, EW_OK);
    n
}

#[test]
fn reset_stops_the_program_where_it_is_and_start_runs_it_again() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    at(&s, 1.5);
    assert_eq!((run_state(h), x(h)), (3, 15000), "half-way through N20");
    assert_eq!(cnc_start(h), EW_REJECT, "alarms are active");
    assert_eq!(cnc_reset(h), EW_OK);
    assert_eq!((run_state(h), x(h)), (0, 15000), "stopped where it was");
    assert_eq!(alarm_bits(h), 1 << 6, "PS cleared, the servo alarm stays");
    at(&s, 30.0);
    assert_eq!((run_state(h), x(h)), (0, 15000), "and stays there");
    let before = blocks(h);

    assert_eq!(cnc_start(h), EW_REJECT, "the servo alarm is still active");
    assert_eq!(cnc_clralm(h, 6), EW_OK);
    assert_eq!(alarm_bits(h), 0);
    assert_eq!(cnc_start(h), EW_OK);
    assert_eq!(run_state(h), 3);
    at(&s, 30.5);
    assert_eq!(x(h), 12500, "N10 G00 X10. from 15.000, half-way");
    at(&s, 31.5);
    assert_eq!(x(h), 15000, "N20 from 10.000 to 20.000, half-way");
    at(&s, 40.0);
    assert_eq!((run_state(h), x(h)), (0, 20000), "ran once to M30");
    assert_eq!(blocks(h), before + 3, "the counter goes on");
    assert_eq!(cnc_start(h), EW_OK, "a finished program starts again");
    assert_eq!(run_state(h), 3);
    sim::free(h);
}

#[test]
fn start_needs_memory_mode() {
    let s = sim::start_toml(
        &PROFILE
            .replace("aut = 1", "aut = 0")
            .replace("type = 3", "type = 2"),
    );
    let h = sim::alloc(&s);
    assert_eq!(cnc_reset(h), EW_OK);
    assert_eq!(cnc_clralm(h, 6), EW_OK);
    assert_eq!(cnc_start(h), EW_REJECT, "MDI mode");
    assert_eq!(run_state(h), 0);
    // cnc_reset2 needs the FOCAS option: the default profile has it.
    assert_eq!(cnc_reset2(h), EW_OK);
    sim::free(h);
}

#[test]
fn the_profiles_machine_without_the_option_refuses_reset2_locally() {
    let p = Profile::parse(&PROFILE.replace("class = \"30i\"", "class = \"30i\"\noption = 0"))
        .expect("profile");
    let s = sim::start(p);
    let h = sim::alloc(&s);
    assert_eq!(cnc_reset2(h), EW_NOOPT);
    assert_eq!(cnc_reset(h), EW_OK);
    sim::free(h);
}

/// cnc_dnc2 of `text`.
fn dnc2(h: c_ushort, text: &str) -> i16 {
    let mut len = text.len() as c_long;
    unsafe { cnc_dnc2(h, &mut len, text.as_ptr().cast_mut().cast()) }
}

fn motion(h: c_ushort) -> i16 {
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    st.motion
}

/// Polls until `f` holds (5 s at most): DNC data frames have no answer, so
/// the simulator may take them after a data request of connection 2.
fn eventually(mut f: impl FnMut() -> bool) {
    let until = std::time::Instant::now() + Duration::from_secs(5);
    while !f() {
        assert!(std::time::Instant::now() < until, "never happened");
        std::thread::yield_now();
    }
}

/// cnc_rdtimer 1, 2, 3 (operating, cutting, cycle) in milliseconds.
fn timers(h: c_ushort) -> [i64; 3] {
    [1, 2, 3].map(|k| {
        let mut t = IODBTIME::default();
        assert_eq!(unsafe { cnc_rdtimer(h, k, &mut t) }, EW_OK);
        i64::from(t.minute) * 60_000 + i64::from(t.msec)
    })
}

#[test]
fn a_dnc_program_runs_while_it_arrives() {
    // An idle machine; its alarms cleared.
    let idle = PROFILE
        .replace("program = 1\n", "program = 0\n")
        .replace("run = 3", "run = 0");
    let s = sim::start_toml(&idle);
    let h = sim::alloc(&s);
    assert_eq!(cnc_reset(h), EW_OK);
    assert_eq!(cnc_clralm(h, 6), EW_OK);
    at(&s, 10.0);
    assert_eq!(run_state(h), 0);
    assert_eq!(unsafe { cnc_dncstart2(h, std::ptr::null_mut()) }, EW_OK);
    assert_eq!(
        dnc2(h, "%\nO0077 (DNC)\nN10 G91 G01 X1. F100\nN20 X"),
        EW_OK
    );
    eventually(|| run_state(h) == 3);
    at(&s, 10.5);
    assert_eq!(x(h), 500);
    at(&s, 20.0);
    assert_eq!(
        (run_state(h), motion(h), x(h)),
        (3, 0, 1000),
        "waiting for data"
    );
    assert_eq!(
        timers(h),
        [10_000, 1000, 10_000],
        "waiting is operating time"
    );
    assert_eq!(dnc2(h, "2.\nM30\n%"), EW_OK);
    eventually(|| motion(h) == 1);
    at(&s, 20.5);
    assert_eq!(
        (motion(h), x(h)),
        (1, 2000),
        "N20 X2. goes on from where it waited"
    );
    assert_eq!(timers(h), [10_500, 1500, 10_500]);
    assert_eq!(cnc_dncend2(h, -1), EW_OK);
    at(&s, 30.0);
    assert_eq!((run_state(h), x(h)), (0, 3000), "ran to M30 once");
    assert_eq!(timers(h), [12_000, 2000, 12_000], "from 10 s to 22 s");
    sim::free(h);
}
