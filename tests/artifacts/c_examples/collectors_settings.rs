//! tests/c/collectors_settings.c: cnc_rdmacronum, cnc_rdset, cnc_rdsetr and cnc_wrset
//! through the .so, compared with the simulator's custom macro variable
//! names (`[path.macros.names]`) and its setting data (the parameters up to
//! `[param] setting_max`), each write checked in the simulator.

use super::run_c_test;
use fwlib32::native::Cnc;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use std::time::Duration;

#[test]
fn macro_numbers_follow_the_names() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let (kv, _sim) = run_c_test("collectors_settings", p.clone());
    let names = &p.paths[0].macros.names;
    let ok = |n: &str| {
        let (num, attr) = names
            .get(n)
            .unwrap_or_else(|| panic!("the default profile names no {n}"));
        format!("0,{num},{attr}")
    };
    assert_eq!(kv["num.gauge1"], ok("GAUGE1"));
    assert_eq!(kv["num.gauge1"], "0,500,0");
    assert_eq!(kv["num.count"], ok("COUNT"));
    assert_eq!(kv["num.count"], "0,100,1");
    assert_eq!(kv["num.nul"], ok("GAUGE1"));
    assert_eq!(kv["num.length"], ok("GAUGE1"));
    // Not a name of the path: EW_DATA, the outputs untouched.
    let refused = format!("{},0,-1", fwlib32::ew::EW_DATA);
    assert_eq!(kv["num.prefix"], refused);
    assert_eq!(kv["num.absent"], refused);
    // No NUL in 64 bytes: EW_DATA from the library, nothing asked.
    assert_eq!(kv["num.long"], refused);
}

/// The default profile, writable: parameter write enable on, MDI mode.
fn writable(text: &str) -> Profile {
    let mut p = Profile::parse(text).expect("profile");
    p.param.param_write_enable = true;
    p.paths[0].status.aut = 0;
    p
}

/// The setting's value in the profile (its first).
fn setting(p: &Profile, number: i32) -> i32 {
    let e = p.param.parameters.iter().find(|e| e.number == number);
    let e = e.unwrap_or_else(|| panic!("the default profile has no parameter {number}"));
    assert!(number <= p.param.setting_max, "{number} is no setting");
    e.values[0]
}

fn settings_follow_the_machine(p: Profile) {
    let (kv, sim) = run_c_test("collectors_settings", p.clone());
    let (s20, s0) = (setting(&p, 20), setting(&p, 0));
    assert_ne!(s20, 9, "the write must change the setting");
    // rc, datano, type (no axis), the byte value.
    assert_eq!(kv["set.read20"], format!("0,20,0,{s20}"));
    assert_eq!(kv["set.read0"], format!("0,0,0,{s0}"));
    // Room for the header only: EW_LENGTH, datano and type written, the
    // value left (0xcc).
    assert_eq!(kv["set.short"], "2,20,0,-52");
    // 1001 is a parameter past `setting_max`: EW_NUMBER, nothing written.
    assert!(1001 > p.param.setting_max);
    assert_eq!(kv["set.absent"], "3,-13108,-13108,-52");
    // The write from C, read back from C as a setting and as the parameter.
    assert_eq!(kv["set.write"], "0");
    assert_eq!(kv["set.after"], "0,20,0,9");
    assert_eq!(kv["set.param"], "0,9");
    // Refused writes: a wrong length (EW_LENGTH), a parameter that is not
    // a setting (the CNC's EW_NUMBER); neither changed anything.
    assert_eq!(kv["set.badlength"], "2");
    assert_eq!(kv["set.notsetting"], "3");
    assert_eq!(kv["set.kept"], "0,20,0,9");
    // cnc_rdsetr: the settings as packed records (number, type word
    // `(type << 8) | axis`: 0 bit, 1 byte), the write's value among them.
    let settings: Vec<&fwlib32::sim::profile::param::Entry> = (p.param.parameters.iter())
        .filter(|e| e.number <= p.param.setting_max)
        .collect();
    assert_eq!(
        settings.iter().map(|e| e.number).collect::<Vec<_>>(),
        [0, 20]
    );
    assert_eq!(kv["setr.all"], format!("0,0,20,16,0:0:{s0},20:256:9"));
    // Room for the first record only: EW_LENGTH, the first record written
    // (the line prints no record for an error), the shorts kept.
    assert_eq!(kv["setr.room"], "2,0,99,10");
    assert_eq!(
        kv["setr.backwards"],
        format!("{},20,0,100", fwlib32::ew::EW_NUMBER)
    );
    // The simulator's state, through a connection of its own.
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(10)).unwrap();
    assert_eq!(cnc.param::<i32>(20, None).unwrap(), 9);
    let before = p.param.parameters.iter().find(|e| e.number == 1001);
    assert_eq!(
        cnc.param::<fwlib32::native::Value>(1001, None)
            .unwrap()
            .to_string(),
        format!("{:08b}", before.map_or(-1, |e| e.values[0]))
    );
}

#[test]
fn settings_follow_the_machine_on_a_30i() {
    settings_follow_the_machine(writable(DEFAULT_PROFILE));
}

/// The same on a 16i (the setting commands 0x0029 / 0x002a, word values).
#[test]
fn settings_follow_the_machine_on_a_16i() {
    let text = DEFAULT_PROFILE.replacen("class = \"30i\"", "class = \"16i\"", 1);
    assert_ne!(text, DEFAULT_PROFILE, "the default profile's class moved");
    let p = writable(&text);
    assert_eq!(p.cnc.class, fwlib32::sim::profile::Class::Series16);
    settings_follow_the_machine(p);
}
