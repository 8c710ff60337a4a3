//! tests/c/collectors_axes.c: the axes, modes and settings long tail
//! through the .so, against the profile and the simulator's state.

use super::run_c_against;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::sim::{Profile, Simulator};
use std::time::Duration;

#[test]
fn axes_functions_follow_the_profile_and_state() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let path = &p.paths[0];
    assert!(path.axes.len() >= 3, "the default profile has X, Y, Z");
    // The clock stands: every read of the run sees one machine state.
    let sim = Simulator::start(p.clone(), "127.0.0.1:0").unwrap();
    sim.set_elapsed(Duration::from_secs(7));
    let kv = run_c_against("collectors_axes", &sim);

    // Each position with extra digits is the position cnc_absolute & co.
    // read (the double's digits at its decimal places), the axis's
    // decimals, and the same digits.
    for key in ["absolute", "machine", "relative", "distance"] {
        let plain: Vec<&str> = kv[&format!("{key}.plain")].split(',').collect();
        let want: Vec<String> = plain
            .iter()
            .zip(&path.axes)
            .map(|(v, a)| format!("{v};{};{v}", a.decimals))
            .collect();
        assert_eq!(kv[key], want.join("|"), "{key}");
    }
    assert_ne!(kv["absolute.plain"], "0,0,0", "positions to compare");

    let s = &path.sync_error;
    assert!(
        s.synchronous != 0 && s.rigid_tap != 0,
        "set in the default profile"
    );
    assert_eq!(kv["synerr"], format!("{},{}", s.synchronous, s.rigid_tap));
    let m = &path.measure;
    assert_ne!(m.enabled, m.center_enabled, "set in the default profile");
    assert_eq!(kv["measure"], format!("{},{}", m.enabled, m.center_enabled));
    let t = path.interference.tools;
    assert!(t[0] != 0 && t[1] != 0);
    assert_eq!(kv["interference"], format!("{},{}", t[0], t[1]));
    // The module configuration bytes, zeros after them (128 written).
    let c = &p.system.module_config;
    assert_eq!(c.len(), 8, "the default profile's");
    let mut want: Vec<String> = c.iter().map(i8::to_string).collect();
    want.push("0".into());
    assert_eq!(kv["mdlconfig"], format!("{};0", want.join(",")));

    // The free timer (it does not run) written, read back; negative
    // minutes refused (EW_DATA), the timer kept.
    assert_ne!(p.timers.free, 4321);
    assert_eq!(kv["timer.written"], "4321,12345");
    assert_eq!(kv["wrtimer.refused"], "5", "EW_DATA");
    assert_eq!(kv["timer.kept"], "4321,12345");
    let r = &path.rotation;
    assert!(r.mode != 0 && r.angle != 0 && r.center[0] != 0);
    assert_eq!(
        kv["rotation"],
        format!(
            "{};{},{};{},{};{}",
            r.mode, r.plane_axes[0], r.plane_axes[1], r.center[0], r.center[1], r.angle
        )
    );
}
