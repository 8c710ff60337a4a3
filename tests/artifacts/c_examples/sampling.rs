//! tests/c/sampling.c: the servo data sampling functions (cnc_sdt*) through
//! the .so, compared with the simulator's servo state.

use super::run_c_test;
use fwlib32::ew::{EW_DATA, EW_NUMBER, EW_OK};
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::sim::profile::Datum;

/// The default profile with path 1 idle (no program in cycle: the servo
/// state stays as the profile puts it) and the X axis's motor turning.
fn idle() -> Profile {
    let cycle = "program = 1234           # O number in cycle (0 = idle)";
    let load = "servo_load = 18          # servo load meter, % (cnc_rdsvmeter)";
    assert!(
        DEFAULT_PROFILE.contains(cycle) && DEFAULT_PROFILE.contains(load),
        "the default profile's cycle or X axis moved"
    );
    let text = DEFAULT_PROFILE
        .replace(cycle, "program = 0")
        .replace(load, "servo_load = 18\nservo_speed = 1500");
    Profile::parse(&text).expect("profile")
}

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

/// The 0x5a filler of an element not written, as the C program prints it.
const FILL16: i64 = 0x5a5a;

#[test]
fn channels_read_the_servo_state_and_clear() {
    let p = idle();
    let path = &p.paths[0];
    let channels = &path.sample_channels;
    assert!(
        (1..=8).contains(&channels.len()),
        "the test expects 1..8 channels in the default profile"
    );
    // Each channel's figure of its axis, as the simulator models it.
    let mut want: Vec<i64> = channels
        .iter()
        .map(|c| {
            let a = &path.axes[usize::from(c.axis) - 1];
            let v = match c.datum {
                Datum::Speed => i64::from(a.servo_speed),
                Datum::Load => i64::from(a.servo_load),
                Datum::Current => {
                    let rated = a.rated_current.unwrap_or(10.0);
                    (rated * 10.0 * f64::from(a.servo_load) / 100.0).round() as i64
                }
                Datum::Other => 0,
            };
            i64::from(v as u16)
        })
        .collect();
    assert!(want.contains(&1500), "the X axis's speed is sampled");
    want.resize(8, 0);
    // Always 8 values written, the element after them untouched.
    want.push(FILL16);

    let (kv, _sim) = run_c_test("sampling", p.clone());
    let ok = EW_OK.to_string();
    assert_eq!(kv["shot.rc"], ok);
    assert_eq!(ints(&kv["shot"]), want);
    assert_eq!(kv["start"], ok);
    assert_eq!(kv["running.rc"], ok);
    assert_eq!(ints(&kv["running"]), want);
    assert_eq!(kv["cancel"], ok);
    assert_eq!(kv["restart"], ok);
    assert_eq!(kv["end"], ok);
    // Cleared: zeros, and nothing to start.
    assert_eq!(kv["clear"], ok);
    assert_eq!(kv["cleared.rc"], ok);
    let mut zeros = vec![0; 8];
    zeros.push(FILL16);
    assert_eq!(ints(&kv["cleared"]), zeros);
    assert_eq!(kv["start_cleared"], EW_DATA.to_string());
    assert_eq!(kv["end_cleared"], ok);
    assert_eq!(kv["null"], EW_DATA.to_string());

    // cnc_sdtsetchnl: channel 1 samples Y's figure of code 4, channel 2
    // X's of code 5 (the profile's `sample_code` list), channel 3 a
    // spindle (not modelled: 0).
    let datum = |code: i16| {
        let c = path.sample_codes.iter().find(|c| c.code == code);
        c.expect("the profile names codes 4 and 5").datum
    };
    let figure = |axis: usize, d: Datum| {
        let a = &path.axes[axis - 1];
        match d {
            Datum::Speed => i64::from(a.servo_speed as u16),
            Datum::Load => i64::from(a.servo_load as u16),
            _ => panic!("the test expects speed or load for codes 4 and 5"),
        }
    };
    let mut set = vec![figure(2, datum(4)), figure(1, datum(5)), 0];
    assert_eq!(set[1], 1500, "channel 2 samples the X axis's speed");
    set.resize(8, 0);
    set.push(FILL16);
    assert_eq!(kv["set"], ok);
    assert_eq!(ints(&kv["set_shot"]), set);
    for k in [
        "bad_type",
        "bad_spindle",
        "bad_chno",
        "bad_cycle",
        "null_chan",
    ] {
        assert_eq!(kv[k], EW_DATA.to_string(), "{k}");
    }
    assert_eq!(kv["bad_n"], EW_NUMBER.to_string());
    // The refused calls changed nothing.
    assert_eq!(ints(&kv["refused_shot"]), set);
}
