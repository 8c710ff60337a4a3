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
    idle_as("class = \"30i\"")
}

/// [`idle`] with the `[cnc]` class line replaced by `class`.
fn idle_as(class: &str) -> Profile {
    let line = "class = \"30i\"";
    assert!(
        DEFAULT_PROFILE.contains(line),
        "the default profile's class moved"
    );
    let text = DEFAULT_PROFILE.replacen(line, class, 1);
    let cycle = "program = 1234           # O number in cycle (0 = idle)";
    let load = "servo_load = 18          # servo load meter, % (cnc_rdsvmeter)";
    assert!(
        DEFAULT_PROFILE.contains(cycle) && DEFAULT_PROFILE.contains(load),
        "the default profile's cycle or X axis moved"
    );
    let text = text
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
    channels_follow_the_servo_state(idle());
}

/// The same on a 16i (cnc_sdtsetchnl reads parameter 1023 with 0x000e,
/// 4-byte values, and refuses `cycle` -1 as a 30i would not).
#[test]
fn channels_read_the_servo_state_on_a_16i() {
    let p = idle_as("class = \"16i\"");
    assert_eq!(p.cnc.class, fwlib32::sim::profile::Class::Series16);
    channels_follow_the_servo_state(p);
}

/// The same on a Series 15 (the 16i class's parameter read, which no
/// Series 15 form of cnc_rdparam sends, answered as a 16i answers it).
#[test]
fn channels_read_the_servo_state_on_a_series_15() {
    let p = idle_as("class = \"16i\"\nkind = 2");
    assert_eq!(p.cnc.kind, 2);
    channels_follow_the_servo_state(p);
}

/// The servo parameter 1023 of `axis` (1-based) in the profile.
fn servo_axis_number(p: &Profile, axis: usize) -> i32 {
    let e = p.param.parameters.iter().find(|e| e.number == 1023);
    let e = e.expect("the profile sets parameter 1023");
    e.values[axis - 1]
}

fn channels_follow_the_servo_state(p: Profile) {
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
    // Y's servo axis number is even (its code goes negated, which the
    // simulator reads by magnitude), X's odd; Y's load is not 0.
    assert_eq!(servo_axis_number(&p, 2) % 2, 0);
    assert_eq!(servo_axis_number(&p, 1) % 2, 1);
    assert_ne!(figure(2, Datum::Load), 0);
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
    // The refused calls changed nothing; the channels set start sampling.
    assert_eq!(ints(&kv["refused_shot"]), set);
    assert_eq!(kv["start_set"], ok);
    // `cycle` -1: a 30i takes it, the 16i class refuses it (nothing set).
    let is16 = p.cnc.class == fwlib32::sim::profile::Class::Series16;
    let want = if is16 { EW_DATA } else { EW_OK };
    assert_eq!(kv["cycle_m1"], want.to_string());
}
