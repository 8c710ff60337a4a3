//! tests/c/collectors_tool_axis.c: the tool_axis family (position
//! deviations, spindles, commanded values, tool tip, magazine, set zone)
//! through the .so, compared with the simulator's state.

use super::run_c_against;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::sim::{Profile, Simulator};
use std::collections::HashMap;
use std::time::Duration;

/// The default profile (its program running) with a second spindle.
fn profile() -> Profile {
    let s1 = "pulses_per_rev = 4096 ";
    assert!(
        DEFAULT_PROFILE.contains(s1),
        "the default profile's spindle moved"
    );
    let text = DEFAULT_PROFILE.replacen(
        s1,
        "pulses_per_rev = 4096\n\n[[path.spindle]]\nname = \"S2\"\nspeed = 1500\nloop_gain = 2000\npulses_per_rev = 1024\n#",
        1,
    );
    Profile::parse(&text).expect("profile")
}

/// tests/c/collectors_tool_axis.c run against a simulator of `p` whose
/// clock stands at `at` (every read of a run sees one machine state).
fn run_at(p: &Profile, at: Duration) -> HashMap<String, String> {
    let sim = Simulator::start(p.clone(), "127.0.0.1:0").unwrap();
    sim.set_elapsed(at);
    run_c_against("collectors_tool_axis", &sim)
}

fn ints(v: &str) -> Vec<i64> {
    v.split(',').map(|x| x.parse().unwrap()).collect()
}

#[test]
fn tool_axis_reads_follow_the_machine() {
    let p = profile();
    let path = &p.paths[0];
    let z = path.axes.iter().position(|a| a.name == "Z").unwrap();
    let mut z_moved = false;
    for ms in [500, 1500, 2500, 4000, 6000] {
        let kv = run_at(&p, Duration::from_millis(ms));
        // The 30i class counts the path's spindles.
        assert_eq!(kv["nspdl"], path.spindles.len().to_string());
        // Each spindle's position deviation: its actual speed (cnc_acts2)
        // in position coder pulses per second over its position loop gain.
        let speeds = ints(&kv["speeds"]);
        let want: Vec<i64> = (path.spindles.iter().zip(&speeds))
            .map(|(s, v)| {
                let pulses = *v as f64 / 60.0 * f64::from(s.pulses_per_rev.unwrap_or(4096));
                (pulses / (f64::from(s.loop_gain.unwrap_or(3000)) / 100.0)).round() as i64
            })
            .collect();
        assert_eq!(speeds[1], 1500, "spindle S2 of the profile turns");
        assert_eq!(want[1], 1280);
        assert_eq!(ints(&kv["poserrs"]), want, "at {ms} ms");
        // Spindles 1 and 2 alone.
        assert_eq!(ints(&kv["poserrs2"]), want[..2], "at {ms} ms");
        // The Z axis's deviation is its servo delay (cnc_srvdelay).
        let delay = ints(&kv["srvdelay"])[z];
        assert_eq!(kv["poserrz"], delay.to_string(), "at {ms} ms");
        z_moved |= delay != 0;
        // The values in force: each address's value is cnc_modal's for it.
        let n: usize = kv["ncmd"].parse().unwrap();
        assert!(n >= 3, "F, S and T at least ({n})");
        let mut letters = String::new();
        for i in 0..n {
            let rec: Vec<&str> = kv[&format!("cmd{i}")].split(',').collect();
            letters.push_str(rec[0]);
            assert_eq!(&rec[1..4], ["1", "0", rec[5]], "cmd{i} at {ms} ms");
            assert_eq!(rec[4], "0");
        }
        assert!(
            letters.contains('F') && letters.contains('S') && letters.contains('T'),
            "{letters}"
        );
        let f: Vec<&str> = kv["cmdF"].split(',').collect();
        assert_eq!(f[..2], ["1", "F"]);
        let i = letters.find('F').unwrap();
        assert_eq!(f[2], kv[&format!("cmd{i}")].split(',').nth(3).unwrap());
        assert_eq!(kv["cmd_short"], "2,1", "EW_LENGTH, the count kept");
    }
    assert!(z_moved, "the program moves Z at one of the instants");
}
