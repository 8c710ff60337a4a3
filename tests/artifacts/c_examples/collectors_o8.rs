//! tests/c/collectors_o8.c: cnc_rddynamico8, cnc_rdprogdiro8,
//! cnc_rdprogdir2o8, cnc_rdmdiprgstat and cnc_rdmultipieceno through the
//! .so, compared with the simulator's state (a program with an 8-digit
//! number in cycle and in memory; the MDI program the C test writes).

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

/// The 8-digit number the default profile's program 1234 becomes.
const O8: i32 = 12345678;

/// The default profile with program 1234 renumbered O8 and in cycle, its
/// first block (no motion) lasting the whole test: the axes stay where the
/// profile puts them; multiple-piece machining number 37.
fn profile() -> Profile {
    let mut text = DEFAULT_PROFILE.to_string();
    for (from, to) in [
        ("program = 1234 ", format!("program = {O8} ")),
        ("number = 1234\n", format!("number = {O8}\n")),
        ("O1234 (POCKET DEMO);", format!("O{O8} (POCKET DEMO);")),
        (
            "block_seconds = 0.5 ",
            "block_seconds = 100000 ".to_string(),
        ),
        ("multi_piece = 0 ", "multi_piece = 37 ".to_string()),
    ] {
        assert_eq!(
            text.matches(from).count(),
            1,
            "the default profile's {from:?} moved"
        );
        text = text.replacen(from, &to, 1);
    }
    Profile::parse(&text).expect("profile")
}

#[test]
fn eight_digit_program_reads_follow_the_machine() {
    let p = profile();
    let (kv, _sim) = run_c_test("collectors_o8", p.clone());
    let path = &p.paths[0];
    assert_eq!(path.cycle.program, O8);
    // cnc_rddynamico8 keeps the low 16 bits of the program numbers,
    // sign-extended, as FANUC's library (and cnc_rddynamic2) does.
    let low16 = i32::from(O8 as i16).to_string();
    assert_eq!(kv["dyo8.prgmnum"], low16);
    assert_eq!(kv["dyo8.prgnum"], low16);
    assert_eq!(kv["dy2.prgmnum"], low16);
    assert_eq!(kv["dyo8.axis"], "-1");
    assert_eq!(kv["dyo8.alarm"], "0");
    let col = |f: fn(&fwlib32::sim::profile::Axis) -> i32| {
        path.axes
            .iter()
            .take(3)
            .map(|a| f(a).to_string())
            .collect::<Vec<_>>()
            .join(",")
    };
    assert_eq!(kv["dyo8.absolute"], col(|a| a.absolute));
    assert_eq!(kv["dyo8.machine"], col(|a| a.machine));
    assert_eq!(kv["dyo8_2.axis"], "2");
    assert_eq!(kv["dyo8_2.absolute"], path.axes[1].absolute.to_string());
    // All axes need the whole ODBDYO8 (540 bytes): EW_LENGTH (2) before traffic.
    assert_eq!(kv["dyo8.short_length"], "2");
    // The directory between two 8-digit numbers: the programs in memory, in order.
    let mut numbers: Vec<i32> = p.programs.iter().map(|q| q.number).collect();
    numbers.sort();
    let text: String = numbers.iter().map(|n| format!("O{n}")).collect();
    assert_eq!(kv["diro8"], format!("{text}%"));
    assert_eq!(kv["diro8_high"], format!("O{O8}%"));
    // datano_s after datano_e: EW_NUMBER (3).
    assert_eq!(kv["diro8.reversed"], "3");
    // From 200 on: the one 8-digit program, its comment and size.
    assert_eq!(kv["dir2o8.num"], "1");
    assert_eq!(kv["dir2o8.top"], O8.to_string());
    let q = p.programs.iter().find(|q| q.number == O8).unwrap();
    let rec: Vec<&str> = kv["dir2o8.0"].splitn(3, ',').collect();
    assert_eq!(rec[0], O8.to_string());
    assert!(rec[1].parse::<i32>().unwrap() > 0, "size {}", rec[1]);
    assert_eq!(rec[2], format!("({})", q.comment));
    // No MDI program, then one (MDI_EXIST 2) from its top (MDI_START_TOP
    // 4), then with its pointer moved.
    assert_eq!(kv["mdistat.none"], "0");
    assert_eq!(kv["mdistat.top"], "6");
    assert_eq!(kv["mdistat.pointer"], "2");
    assert_eq!(kv["multipiece"], path.cycle.multi_piece.to_string());
    assert_eq!(path.cycle.multi_piece, 37);
}
