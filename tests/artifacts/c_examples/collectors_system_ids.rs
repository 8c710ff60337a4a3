//! tests/c/collectors_system_ids.c: the CNC's boards, software and drive
//! IDs through the .so, against the profile's `[system]` section.

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

#[test]
fn system_ids_follow_the_profile() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let sys = &p.system;
    assert!(
        sys.boards.len() >= 2 && sys.software.len() >= 2,
        "the default profile lists boards and software"
    );
    let (kv, _sim) = run_c_test("collectors_system_ids", p.clone());

    // cnc_rdsyshard: every board, then the second alone; past the end none.
    let board = |k: usize| {
        let b = &sys.boards[k];
        format!(
            "{},{},{},{},{},{},{},{}",
            b.id1, b.id2, b.group_id, b.hard_id, b.hard_num, b.slot_no, b.id1_format, b.id2_format
        )
    };
    let all: Vec<String> = (0..sys.boards.len()).map(board).collect();
    assert_eq!(
        kv["hard.all"],
        format!("{};{};untouched", all.len(), all.join("|"))
    );
    assert_eq!(kv["hard.second"], format!("1;{};untouched", board(1)));
    assert_eq!(kv["hard.past"], "0;;untouched");
    assert_eq!(kv["hard.none"], "2", "EW_LENGTH: no board asked for");

    // cnc_rdsyssoft3: every software and the total, then from the third.
    let soft = |k: usize| {
        let s = &sys.software[k];
        format!("{}:{:4}:{:4}:00", s.id, s.series, s.edition)
    };
    let n = sys.software.len();
    let all: Vec<String> = (0..n).map(soft).collect();
    assert_eq!(kv["soft.all"], format!("{n},{n};{}", all.join("|")));
    assert_eq!(
        kv["soft.last"],
        format!("{},{n};{}", n - 2, all[2..].join("|"))
    );
    assert_eq!(kv["soft.zero"], "3", "EW_NUMBER: s_no 0");

    // cnc_rdsyssoft3_str: the same software with their names.
    let named_soft = |k: usize| {
        let s = &sys.software[k];
        format!("{}:{}:{:4}:{:4}", s.id, s.name, s.series, s.edition)
    };
    assert!(
        sys.software
            .iter()
            .all(|s| !s.name.is_empty() && s.name.len() <= 12)
    );
    let all: Vec<String> = (0..n).map(named_soft).collect();
    assert_eq!(
        kv["softstr.all"],
        format!("{n},{n};{};untouched", all.join("|"))
    );
    assert_eq!(kv["softstr.second"], format!("1,{n};{};untouched", all[1]));

    // cnc_rdsyssoft / cnc_rdsyssoft2: the physical slots ascending, each
    // one's place in the profile's (logical) order, module and software ID,
    // and that software's series and edition (as cnc_rdsyssoft3 lists it);
    // then nothing (0xff, -1, -1, NULs); the named software's, the others
    // unset (empty).
    assert!(
        sys.slots.len() >= 2 && sys.slots.iter().any(|s| s.slot >= 0x80),
        "the default profile has slots in both banks"
    );
    let series = |id: i16| {
        let s = sys.software.iter().find(|s| s.id == id).expect("software");
        format!("{}:{}", s.series, s.edition)
    };
    let mut physical: Vec<_> = sys.slots.iter().collect();
    physical.sort_by_key(|s| s.slot);
    let slots: Vec<String> = physical
        .iter()
        .map(|s| {
            let logical = sys.slots.iter().position(|x| x.slot == s.slot).unwrap();
            format!(
                "{:02x}:{logical}:{}:{}:{}",
                s.slot,
                s.module_id,
                s.software,
                series(s.software)
            )
        })
        .collect();
    let named = |k: &str| sys.named.get(k).map_or(":".to_string(), |id| series(*id));
    let names = ["boot", "servo", "pmc", "ladder", "eth_boot"].map(named);
    assert!(
        names[..3].iter().all(|n| n.len() == 9),
        "named in the profile"
    );
    for key in ["syssoft", "syssoft2"] {
        assert_eq!(kv[key], slots.join("|"), "{key}");
        assert_eq!(kv[&format!("{key}.after")], "ff:-1:-1:0:0", "{key}");
        assert_eq!(kv[&format!("{key}.named")], names.join("|"), "{key}");
        assert_eq!(kv[&format!("{key}.inst")], sys.soft_inst.to_string());
    }
    assert_eq!(kv["syssoft2.embethe"], named("embEthe"));
    assert_eq!(
        kv["syssoft.same"], "1",
        "cnc_rdsyssoft2 begins as cnc_rdsyssoft"
    );
    assert_eq!(kv["syssoft.null"], fwlib32::ew::EW_DATA.to_string());

    // cnc_rdservoid / cnc_rdspindleid and the saved copies: the profile's
    // drives, each string cut to its field less the NUL.
    let drive = |d: &fwlib32::sim::profile::system::DriveId, lens: [usize; 8]| {
        let parts = [&d.motor, &d.sub, &d.amplifier, &d.power_supply];
        let texts = parts.iter().flat_map(|p| p.iter());
        (texts.zip(lens))
            .map(|(t, n)| t.chars().take(n - 1).collect::<String>())
            .collect::<Vec<_>>()
            .join("|")
    };
    const SERVO: [usize; 8] = [20, 10, 22, 9, 22, 12, 22, 12];
    const SPINDLE: [usize; 8] = [20, 10, 20, 10, 22, 12, 22, 12];
    assert!(sys.servo.len() >= 3 && !sys.spindle.is_empty());
    assert_eq!(kv["servo.2"], drive(&sys.servo[1], SERVO));
    assert_eq!(kv["fromservo.3"], drive(&sys.servo[2], SERVO));
    assert_eq!(kv["servo.none"], "3", "EW_NUMBER: axis 0");
    assert_eq!(kv["spindle.1"], drive(&sys.spindle[0], SPINDLE));
    assert_eq!(kv["fromspindle.1"], drive(&sys.spindle[0], SPINDLE));
    assert_eq!(kv["spindle.none"], "3", "EW_NUMBER: no spindle 9");
}
