//! Tool life groups through the C ABI against the simulator: cnc_rdgrpinfo
//! reads the profile's `[[path.tool_group]]` table, cnc_wrgrpinfo changes it
//! (a refused write changes nothing), cnc_rdtlusegrp follows the T code the
//! running program set.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::mem::size_of;
use std::os::raw::{c_char, c_short, c_ushort};
use std::time::Duration;

const LEN: c_short = size_of::<IODBTGI>() as c_short;

fn rdgrpinfo(h: c_ushort, s: c_short, e: c_short) -> Result<IODBTGI, c_short> {
    let mut g = IODBTGI::default();
    match unsafe { cnc_rdgrpinfo(h, s, e, LEN, &mut g) } {
        EW_OK => Ok(g),
        r => Err(r),
    }
}

fn rdtlusegrp(h: c_ushort) -> Result<ODBUSEGRP, c_short> {
    let mut u = ODBUSEGRP::default();
    match unsafe { cnc_rdtlusegrp(h, &mut u) } {
        EW_OK => Ok(u),
        r => Err(r),
    }
}

#[test]
fn group_information_reads_the_profile() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let p = Profile::default();
    let groups = &p.paths[0].tool_groups;
    assert!(groups.len() >= 2);
    let g = rdgrpinfo(h, 1, 99).expect("rdgrpinfo");
    assert_eq!((g.s_grp, g.e_grp), (1, groups.len() as c_short));
    for (d, x) in g.data.iter().zip(groups) {
        assert_eq!(
            (d.n_tool, d.count_value, d.counter, d.count_type),
            (x.tools.len() as i32, x.life, x.count, x.count_type)
        );
    }
    // One group; the head of a range answer counts only what the CNC sent.
    let g = rdgrpinfo(h, 2, 2).expect("group 2");
    assert_eq!(
        (g.s_grp, g.e_grp, g.data[0].counter),
        (2, 2, groups[1].count)
    );
    unsafe {
        let mut g = IODBTGI::default();
        // FANUC's local checks: no traffic.
        assert_eq!(cnc_rdgrpinfo(h, 0, 2, LEN, &mut g), EW_NUMBER);
        assert_eq!(cnc_rdgrpinfo(h, 2, 1, LEN, &mut g), EW_NUMBER);
        // Room for the head and one group; two answered.
        assert_eq!(cnc_rdgrpinfo(h, 1, 2, 8 + 16, &mut g), EW_LENGTH);
        assert_eq!(g, IODBTGI::default(), "nothing written");
        assert_eq!(cnc_rdgrpinfo(h, 1, 2, 8 + 32, &mut g), EW_OK);
        // Past the table: the CNC's EW_NUMBER.
        assert_eq!(cnc_rdgrpinfo(h, 9, 12, LEN, &mut g), EW_NUMBER);
        assert_eq!(cnc_rdgrpinfo(h, 1, 2, LEN, std::ptr::null_mut()), EW_DATA);
    }
    sim::free(h);
}

#[test]
fn a_group_write_reads_back_and_a_refused_one_changes_nothing() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let before = rdgrpinfo(h, 1, 2).expect("rdgrpinfo");
    let mut w = before;
    w.data[0].count_value = 150;
    w.data[0].counter = 10;
    w.data[0].count_type = 0;
    w.data[1].counter = 0;
    w.data[1].n_tool = 9; // not sent: the tools stay
    assert_eq!(unsafe { cnc_wrgrpinfo(h, 8 + 32, &mut w) }, EW_OK);
    let after = rdgrpinfo(h, 1, 2).expect("read back");
    assert_eq!(
        (after.data[0].count_value, after.data[0].counter),
        (150, 10)
    );
    assert_eq!(after.data[0].count_type, 0);
    assert_eq!(after.data[1].counter, 0);
    assert_eq!(after.data[1].n_tool, before.data[1].n_tool);
    // The same group's life as cnc_rdlife / cnc_rdcount read it.
    let mut l = ODBTLIFE3::default();
    assert_eq!(unsafe { cnc_rdcount(h, 1, &mut l) }, EW_OK);
    assert_eq!(l.data, 10);

    unsafe {
        // A counter type the CNC refuses, a group it lacks: nothing changes.
        let mut bad = after;
        bad.data[0].counter = 99;
        bad.data[1].count_type = 7;
        assert_eq!(cnc_wrgrpinfo(h, 8 + 32, &mut bad), EW_DATA);
        let mut absent = after;
        absent.s_grp = 2;
        absent.e_grp = 3;
        assert_eq!(cnc_wrgrpinfo(h, 8 + 32, &mut absent), EW_NUMBER);
        // FANUC's local checks.
        assert_eq!(cnc_wrgrpinfo(h, 8 + 16, &mut bad), EW_LENGTH);
        let mut rev = after;
        rev.e_grp = 0;
        assert_eq!(cnc_wrgrpinfo(h, 8 + 32, &mut rev), EW_NUMBER);
    }
    assert_eq!(rdgrpinfo(h, 1, 2), Ok(after));
    sim::free(h);
}

const RUNNING: &str = r#"
[cnc]
class = "30i"

[[path]]
[path.status]
aut = 1
run = 3
motion = 1

[path.cycle]
program = 1
block_seconds = 1.0
repeat = false

[path.modal]
aux = { 108 = 1 }

[[path.axis]]
name = "X"
decimals = 3

[[path.tool_group]]
number = 1
life = 100
count = 3
optional = 11
tool = [{ number = 1, length = 1, radius = 1 }]

[[path.tool_group]]
number = 2
life = 200
count = 4
count_type = 1
optional = 12
tool = [{ number = 5, length = 5, radius = 5 }]

[[program]]
number = 1
text = """
O0001;
N10 G91 G01 X1. F100;
N20 T5 M06;
N30 G91 G01 X1. F100;
N40 G91 G01 X1. F100;
N50 M30;
%
"""
"#;

#[test]
fn the_group_in_use_follows_the_running_program() {
    for class in ["30i", "16i"] {
        let text = RUNNING.replace("\"30i\"", &format!("\"{class}\""));
        let s = Simulator::start(Profile::parse(&text).expect("profile"), "127.0.0.1:0")
            .expect("simulator");
        s.set_elapsed(Duration::from_secs_f64(0.5)); // N10: the profile's T1
        let h = sim::alloc(&s);
        let u = rdtlusegrp(h).expect("rdtlusegrp");
        assert_eq!((u.next, u.r#use, u.slct), (1, 1, 1), "{class}");
        assert_eq!((u.opt_next, u.opt_use, u.opt_slct), (11, 11, 11), "{class}");
        s.set_elapsed(Duration::from_secs_f64(2.5)); // after N20 T5 M06
        let u = rdtlusegrp(h).expect("rdtlusegrp");
        assert_eq!((u.next, u.r#use, u.slct), (2, 2, 2), "{class}");
        assert_eq!((u.opt_next, u.opt_use, u.opt_slct), (12, 12, 12), "{class}");
        assert_eq!(unsafe { cnc_rdtlusegrp(h, std::ptr::null_mut()) }, EW_DATA);
        sim::free(h);
    }
}

#[test]
fn tool_management_data_reads_the_profile_and_the_groups_written() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let p = Profile::default();
    let tools = &p.paths[0].managed_tools;
    assert!(tools.len() >= 2);
    let mut t = [IODBTLMNG::default(); 4];
    let mut num: c_short = 4;
    // Two exchanges' worth asked, the table ends after its entries: the
    // CNC's EW_NUMBER with the entries read so far.
    assert_eq!(
        unsafe { cnc_rdtool(h, 1, &mut num, t.as_mut_ptr()) },
        EW_NUMBER
    );
    assert_eq!(num as usize, tools.len());
    for (x, m) in t.iter().zip(tools) {
        assert_eq!(
            (x.T_code, x.H_code, x.D_code, x.magazine, x.pot),
            (
                m.number,
                m.length as i16,
                m.radius as i16,
                m.magazine as i16,
                m.pot as i16
            )
        );
        assert_eq!(
            (x.spindle_speed, x.feedrate, x.grp),
            (m.spindle_speed, m.feedrate, m.group as i16)
        );
        assert_eq!(x.rest_life, x.max_life - x.life_count);
    }
    // Without a group: the entry's own life; in one: the group's.
    let (own, grouped) = (&t[1], &t[0]);
    assert_eq!(
        (own.life_count, own.max_life),
        (tools[1].life_count, tools[1].max_life)
    );
    assert_eq!(own.custom1, tools[1].custom[0]);
    let g = &p.paths[0].tool_groups[0];
    assert_eq!((grouped.life_count, grouped.max_life), (g.count, g.life));

    // cnc_wrgrpinfo changes the group: the managed tool in it follows.
    let mut w = rdgrpinfo(h, g.number as c_short, g.number as c_short).expect("group");
    w.data[0].counter = 1;
    w.data[0].count_value = 40;
    assert_eq!(unsafe { cnc_wrgrpinfo(h, 8 + 16, &mut w) }, EW_OK);
    let mut one = IODBTLMNG::default();
    let mut num: c_short = 1;
    assert_eq!(unsafe { cnc_rdtool(h, 1, &mut num, &mut one) }, EW_OK);
    assert_eq!(
        (num, one.life_count, one.max_life, one.rest_life),
        (1, 1, 40, 39)
    );

    unsafe {
        // FANUC's local checks: no traffic.
        let mut num: c_short = 1;
        assert_eq!(cnc_rdtool(h, 0, &mut num, &mut one), EW_NUMBER);
        assert_eq!(num, 1, "untouched");
        num = -1;
        assert_eq!(cnc_rdtool(h, 1, &mut num, &mut one), EW_OK);
        assert_eq!(num, 0);
        assert_eq!(cnc_rdtool(h, 1, std::ptr::null_mut(), &mut one), EW_DATA);
    }
    sim::free(h);
}

const PUNCH: &str = r#"
[cnc]
class = "30i"

[[path]]
machine = "punch"

[[path.axis]]
name = "X"
decimals = 3

[[path.punch_tool]]
number = 1
x_offset = 1500
turret = 1
punch_count = 1234
life = 50000
size_i = 10000

[[path.punch_tool]]
number = 12
turret = 2
radius = 25000
radius_angle = 45000
angle = 90000
decimals = 4
angle_decimals = 2
"#;

#[test]
fn punch_press_tool_data_reads_the_profile_and_a_mill_refuses_it() {
    for class in ["30i", "16i"] {
        let text = PUNCH.replace("\"30i\"", &format!("\"{class}\""));
        let p = Profile::parse(&text).expect("profile");
        let tools = p.paths[0].punch_tools.clone();
        let s = Simulator::start(p, "127.0.0.1:0").expect("simulator");
        let h = sim::alloc(&s);
        let mut t = [IODBTLDT::default(); 3];
        let mut num: c_short = 3;
        assert_eq!(
            unsafe { cnc_rdtooldata(h, 1, &mut num, t.as_mut_ptr()) },
            EW_OK
        );
        assert_eq!(num as usize, tools.len(), "{class}");
        for (x, m) in t.iter().zip(&tools) {
            assert_eq!(
                (
                    x.tool_no,
                    x.x_axis_ofs,
                    x.turret_pos,
                    x.punch_count,
                    x.tool_life
                ),
                (m.number, m.x_offset, m.turret, m.punch_count, m.life)
            );
            assert_eq!(
                (x.m_tl_radius, x.m_tl_angle, x.tl_size_i, x.tl_angle),
                (m.radius, m.radius_angle, m.size_i, m.angle)
            );
            // The 16i class's record has no decimals.
            let dec = if class == "30i" {
                m.decimals as c_char
            } else {
                0
            };
            assert_eq!((x.x_axis_dec, x.tl_size_j_dec), (dec, dec), "{class}");
        }
        let mut one = IODBTLDT::default();
        let mut num: c_short = 1;
        assert_eq!(unsafe { cnc_rdtooldata(h, 2, &mut num, &mut one) }, EW_OK);
        assert_eq!((num, one.tool_no), (1, tools[1].number));
        num = 0;
        assert_eq!(
            unsafe { cnc_rdtooldata(h, 1, &mut num, &mut one) },
            EW_LENGTH
        );
        num = 1;
        assert_eq!(
            unsafe { cnc_rdtooldata(h, 9, &mut num, &mut one) },
            EW_NUMBER
        );

        let mut info = ODBPTLINF::default();
        assert_eq!(unsafe { cnc_rdtoolinfo(h, &mut info) }, EW_OK);
        assert_eq!(
            (info.tld_max, info.tld_size[0]),
            (tools.len() as i16, tools.len() as i16)
        );
        sim::free(h);
    }

    // A mill: EW_FUNC without traffic, the count untouched.
    let (_s, h) = sim::start_alloc(Profile::default());
    let mut one = IODBTLDT::default();
    let mut num: c_short = 1;
    let mut info = ODBPTLINF::default();
    unsafe {
        assert_eq!(cnc_rdtooldata(h, 1, &mut num, &mut one), EW_FUNC);
        assert_eq!(num, 1);
        assert_eq!(cnc_rdtoolinfo(h, &mut info), EW_FUNC);
        assert_eq!(cnc_rdtoolinfo(h, std::ptr::null_mut()), EW_DATA);
    }
    sim::free(h);
}

/// cnc_rdtlinfo reads the profile's `[path.tool_life]` limits on the 30i
/// class (its own command) and on the 16i class and Series 15 (cnc_rdngrp's
/// command, the limits after the group count, which cnc_rdngrp still reads).
#[test]
fn tool_life_limits_read_the_profile_on_every_class() {
    for class in [
        "class = \"30i\"",
        "class = \"16i\"",
        "class = \"16i\"\nkind = 2",
    ] {
        let p = format!(
            "[cnc]\n{class}\n[[path]]\n[path.tool_life]\nmax_group = 64\nmax_tool = 8\n\
             max_minute = 4300\nmax_cycle = 9999\n[[path.tool_group]]\nnumber = 1\n\
             [[path.tool_group]]\nnumber = 2\n"
        );
        let (_s, h) = sim::start_alloc(Profile::parse(&p).expect("profile"));
        let mut t = ODBTLINFO::default();
        assert_eq!(unsafe { cnc_rdtlinfo(h, &mut t) }, EW_OK, "{class}");
        assert_eq!(
            (t.max_group, t.max_tool, t.max_minute, t.max_cycle),
            (64, 8, 4300, 9999),
            "{class}"
        );
        let mut g = ODBTLIFE2::default();
        assert_eq!(unsafe { cnc_rdngrp(h, &mut g) }, EW_OK, "{class}");
        assert_eq!(g.data, 2, "{class}");
        assert_eq!(unsafe { cnc_rdtlinfo(h, std::ptr::null_mut()) }, EW_DATA);
        sim::free(h);
    }
}
