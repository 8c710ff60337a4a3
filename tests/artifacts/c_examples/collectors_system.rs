//! tests/c/collectors_system.c: the long-tail system functions (family A)
//! through the .so, against the profile and the simulator's state.

use super::{run_c_against, run_c_test};
use fwlib32::sim::Profile;
use fwlib32::sim::Simulator;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::sim::profile::system::DriveId;
use std::time::Duration;

/// A drive's strings in the *2 layout's order (parts, software, power
/// modules), each cut to its field less the NUL; fields past the profile's
/// strings empty.
fn drive2(d: &DriveId, lens: &[usize]) -> String {
    let parts = [&d.motor, &d.sub, &d.amplifier, &d.power_supply];
    let texts = parts.into_iter().flat_map(|p| p.iter());
    let texts = texts.chain(&d.software).chain(d.modules.iter().flatten());
    let mut out: Vec<String> = texts
        .zip(lens)
        .map(|(t, n)| t.chars().take(n - 1).collect())
        .collect();
    out.resize(lens.len(), String::new());
    out.join("|")
}

#[test]
fn system_functions_follow_the_profile_and_state() {
    let mut p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    // Three additional work coordinate systems (G54.1 P1..P3) past G59.
    let work = &mut p.paths[0].offset.work;
    assert_eq!(work.len(), 7, "the default profile: external, G54..G59");
    let row = work[1].clone();
    work.extend([row.clone(), row.clone(), row]);
    let sys = &p.system;
    let (kv, _sim) = run_c_test("collectors_system", p.clone());

    // cnc_rdservoid2 / cnc_rdspindleid2 and the saved copies.
    const SERVO2: [usize; 14] = [20, 10, 22, 9, 22, 12, 22, 12, 9, 9, 22, 9, 22, 9];
    const SPINDLE2: [usize; 9] = [20, 10, 20, 10, 22, 12, 22, 12, 9];
    assert!(sys.servo.len() >= 3 && !sys.spindle.is_empty());
    assert!(
        sys.servo[0].software.len() == 2 && !sys.servo[0].modules[0][0].is_empty(),
        "the default profile's servo drives have software and a power module"
    );
    assert_eq!(kv["servo2.1"], drive2(&sys.servo[0], &SERVO2));
    assert_eq!(kv["fromservo2.3"], drive2(&sys.servo[2], &SERVO2));
    assert_eq!(kv["servo2.none"], "3", "EW_NUMBER: axis 0");
    assert!(!sys.spindle[0].software.is_empty());
    assert_eq!(kv["spindle2.1"], drive2(&sys.spindle[0], &SPINDLE2));
    assert_eq!(kv["fromspindle2.1"], drive2(&sys.spindle[0], &SPINDLE2));
    assert_eq!(kv["spindle2.none"], "3", "EW_NUMBER: no spindle 9");

    // The model, the display language (changed; a code past 15 refused,
    // the language kept).
    assert_eq!(kv["model"], sys.model.to_string());
    assert_eq!(kv["language"], sys.language.to_string());
    assert_ne!(sys.language, 2);
    assert_eq!(kv["language.changed"], "2");
    assert_eq!(kv["chglang.refused"], "5", "EW_DATA");
    assert_eq!(kv["language.kept"], "2");

    // The operation and protection levels.
    assert_eq!(kv["ope_lvl"], sys.operation_level.to_string());
    let [rd, wt] = sys.protection[1];
    assert_ne!([rd, wt], [2, 3]);
    assert_eq!(kv["prt_lvl.1"], format!("{rd},{wt}"));
    assert_eq!(kv["prt_lvl.1.set"], "2,3");
    assert_eq!(kv["wrprt_lvl.refused"], "5", "EW_DATA: level 8");
    assert_eq!(kv["prt_lvl.1.kept"], "2,3");
    assert_eq!(kv["prt_lvl.none"], "3", "EW_NUMBER: no data kind 99");

    // The menu switches: the low four bits from the write, the rest kept.
    assert_eq!(kv["menu"], sys.menu_switch.to_string());
    assert_eq!(kv["menu.set"], (sys.menu_switch & !0x0f | 0x0a).to_string());

    // The counts.
    assert_eq!(kv["coordnum"], "3");
    assert_eq!(kv["axisnum.0"], p.paths[0].axes.len().to_string());
    assert_eq!(kv["axisnum.1"], p.paths[0].spindles.len().to_string());

    // The canned cycle in force: the path's `fixed_cycle`.
    let f = &p.paths[0].fixed_cycle;
    assert!(
        f.mode != 0 && f.z_point != 0 && f.cut != 0,
        "set in the default profile"
    );
    assert_eq!(
        kv["fixcycle"],
        format!(
            "{};{},{};{};{},{},{};{},{};{};{},{}",
            f.mode,
            f.plane_axes[0],
            f.plane_axes[1],
            f.drill_axis,
            f.initial,
            f.r_point,
            f.z_point,
            f.repeats[0],
            f.repeats[1],
            f.cut,
            f.shift[0],
            f.shift[1]
        )
    );

    // The cursor: busy while the program runs; N70 of the main program
    // found, N75 (not in it) refused and the cursor kept; the top.
    assert_eq!(p.paths[0].status.run, 3, "the default profile runs");
    let main = p
        .programs
        .iter()
        .find(|g| g.number == p.paths[0].cycle.program);
    let text = &main.expect("the main program").text;
    assert!(text.contains("N70 ") && !text.contains("N75 "));
    assert_eq!(kv["seqsrch.running"], "-1", "EW_BUSY");
    assert_eq!(kv["seq.searched"], "70");
    assert_eq!(kv["seqsrch.missing"], "5", "EW_DATA");
    assert_eq!(kv["seq.kept"], "70");
    assert_eq!(kv["seq.rewound"], "0");
}

/// cnc_rdrepeatval: the running program's completed runs, none at the
/// start, more once the clock has run far.
#[test]
fn repeats_follow_the_running_program() {
    // A simulator each: the program resets its path.
    let at = |secs| {
        let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
        let sim = Simulator::start(p, "127.0.0.1:0").expect("simulator");
        sim.set_elapsed(Duration::from_secs(secs));
        run_c_against("collectors_system", &sim)
    };
    assert_eq!(at(0)["repeat"], "0");
    let later = at(100_000);
    let n: i64 = later["repeat"].parse().expect("a number");
    assert!(n > 0, "runs completed after 100000 s: {n}");
}
