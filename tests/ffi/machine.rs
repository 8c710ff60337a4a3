//! Machine data (issue 11) through the C ABI against the simulator:
//! cnc_rdopmsg3 (the profile's operator messages and the message a running
//! program's `#3006` shows).

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::profile::DEFAULT_PROFILE;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_short, c_ushort};
use std::time::Duration;

/// cnc_rdopmsg3: (code, messages written, the records).
fn opmsg3(h: c_ushort, kind: c_short, num: c_short) -> (i16, c_short, Vec<OPMSG3>) {
    let mut b = vec![OPMSG3::default(); 16];
    let mut n = num;
    let r = unsafe { cnc_rdopmsg3(h, kind, &mut n, b.as_mut_ptr()) };
    (r, n, b)
}

fn text(m: &OPMSG3) -> String {
    let b: Vec<u8> = m
        .data
        .iter()
        .map(|c| *c as u8)
        .take_while(|c| *c != 0)
        .collect();
    String::from_utf8_lossy(&b).into_owned()
}

/// The built-in profile with a `#3006` message block before M05 (block 11:
/// 5.5 s into each pass at 0.5 s a block), on the 30i or the 16i class.
fn message_profile(class16: bool) -> String {
    let t = DEFAULT_PROFILE.replacen("N120 M05;", "N115 #3006=7(CHECK TOOL 1);\nN120 M05;", 1);
    if class16 {
        t.replacen("class = \"30i\"", "class = \"16i\"\nkind = 1", 1)
    } else {
        t
    }
}

#[test]
fn operator_messages_3_read_the_profile_and_a_running_macro_message() {
    for class16 in [false, true] {
        let s = sim::start_toml(&message_profile(class16));
        let h = sim::alloc(&s);
        s.set_elapsed(Duration::from_secs(1));
        // The profile's message (type 0).
        let (r, n, b) = opmsg3(h, 0, 5);
        assert_eq!((r, n), (EW_OK, 1), "16i class: {class16}");
        assert_eq!((b[0].datano, b[0].r#type, b[0].char_num), (2001, 0, 20));
        assert_eq!(text(&b[0]), "CHECK COOLANT NOZZLE");
        // No macro message yet: the 30i answers none, the 16i its
        // "no message" record (number -1).
        let (r, n, b) = opmsg3(h, 4, 5);
        assert_eq!(r, EW_OK);
        if class16 {
            assert_eq!((n, b[0].datano), (1, -1));
        } else {
            assert_eq!(n, 0);
        }

        // The program passes `#3006=7(CHECK TOOL 1)`: its message shows.
        s.set_elapsed(Duration::from_secs_f64(6.2));
        let (r, n, b) = opmsg3(h, 4, 5);
        assert_eq!((r, n), (EW_OK, 1));
        assert_eq!((b[0].datano, b[0].r#type, b[0].char_num), (7, 4, 12));
        assert_eq!(text(&b[0]), "CHECK TOOL 1");
        if !class16 {
            // Every type (-1): the profile's and the macro message, in
            // exchanges of five (12 asked: three exchanges).
            let (r, n, b) = opmsg3(h, -1, 12);
            assert_eq!((r, n), (EW_OK, 2));
            assert_eq!((b[0].datano, b[1].datano), (2001, 7));
            // Still there in the next pass (until a program shows another).
            s.set_elapsed(Duration::from_secs_f64(7.6));
            assert_eq!(opmsg3(h, -1, 5).1, 2);
            // One asked for: the first.
            let (r, n, b) = opmsg3(h, -1, 1);
            assert_eq!((r, n, b[0].datano), (EW_OK, 1, 2001));
        }

        // Local checks: num ≤ 0 EW_LENGTH, NULL EW_DATA.
        assert_eq!(opmsg3(h, 0, 0).0, EW_LENGTH);
        assert_eq!(opmsg3(h, 0, -1).0, EW_LENGTH);
        let mut n: c_short = 5;
        assert_eq!(
            unsafe { cnc_rdopmsg3(h, 0, &mut n, std::ptr::null_mut()) },
            EW_DATA
        );
        // A type the CNC does not know: its EW_ATTRIB.
        assert_eq!(opmsg3(h, 5, 5).0, EW_ATTRIB);
        sim::free(h);
        drop(s);
    }
}

#[test]
fn control_signals_read_the_pmc_and_the_running_spindle() {
    let s = sim::start_toml(DEFAULT_PROFILE);
    let h = sim::alloc(&s);
    s.set_elapsed(Duration::from_secs(1));
    // Input signals: G070..G073 of the first spindle, as the test writes them.
    let mut w = [0u8; 12];
    w[4..6].copy_from_slice(&70u16.to_le_bytes());
    w[6..8].copy_from_slice(&73u16.to_le_bytes());
    w[8..12].copy_from_slice(&[0x81, 0x02, 0x40, 0x10]);
    assert_eq!(unsafe { pmc_wrpmcrng(h, 12, w.as_mut_ptr().cast()) }, EW_OK);
    let mut di = [0xccu8; 8];
    assert_eq!(unsafe { cnc_rdctrldi(h, di.as_mut_ptr().cast()) }, EW_OK);
    assert_eq!(
        di,
        [0x81, 0x02, 0x40, 0x10, 0xcc, 0xcc, 0xcc, 0xcc],
        "the struct only"
    );

    // Output signals: the spindle turns at S12000 (SARA, bit 3) ...
    let mut o = ODBSPDO::default();
    assert_eq!(unsafe { cnc_rdctrldo(h, &mut o) }, EW_OK);
    assert_eq!(o.sgnl1 as u8 & 0x0b, 0x08);
    // ... and stands after the program's M05 (SSTA, bit 1).
    s.set_elapsed(Duration::from_secs_f64(6.2));
    assert_eq!(unsafe { cnc_rdctrldo(h, &mut o) }, EW_OK);
    assert_eq!(o.sgnl1 as u8 & 0x0b, 0x02);

    assert_eq!(unsafe { cnc_rdctrldi(h, std::ptr::null_mut()) }, EW_DATA);
    assert_eq!(unsafe { cnc_rdctrldo(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
    drop(s);
}

fn prstr(h: c_ushort) -> (i16, ODBPRS) {
    let mut p = ODBPRS::default();
    let r = unsafe { cnc_rdprstrinfo(h, &mut p) };
    (r, p)
}

fn absolute_x(h: c_ushort) -> i32 {
    let mut a = ODBAXIS {
        dummy: 0,
        r#type: 0,
        data: [0; 32],
    };
    assert_eq!(unsafe { cnc_absolute(h, 1, 8, &mut a) }, EW_OK);
    a.data[0]
}

#[test]
fn program_restart_information_follows_a_reset_made_here() {
    let s = sim::start_toml(DEFAULT_PROFILE);
    let h = sim::alloc(&s);
    // The program runs; nothing interrupted it yet: no restart data.
    s.set_elapsed(Duration::from_secs(1));
    let (r, p) = prstr(h);
    assert_eq!((r, p.data_info), (EW_OK, [0; 5]));
    assert!(p.dest.iter().chain(&p.dist).all(|v| *v == 0));

    // A reset at N70 (block 7, X moving to 50 mm at F1500): the block, the
    // modal M03, T1, S12000 (no B code) and where the axes stopped.
    s.set_elapsed(Duration::from_secs_f64(3.2));
    assert_eq!(cnc_reset(h), EW_OK);
    let x = absolute_x(h);
    assert!(x > 0 && x < 50_000, "X stopped on its way: {x}");
    let (r, p) = prstr(h);
    assert_eq!((r, p.data_info), (EW_OK, [1, 1, 1, 1, 0]));
    assert_eq!(
        (p.rstr_bc, p.rstr_m[0], p.rstr_t[0], p.rstr_s),
        (7, 3, 1, 12000)
    );
    assert_eq!((p.dest[0], p.dist[0]), (x, 0));

    // Started again from the top: the distance back to the restart point.
    assert_eq!(cnc_start(h), EW_OK);
    s.set_elapsed(Duration::from_secs_f64(5.0));
    let now = absolute_x(h);
    let (r, p) = prstr(h);
    assert_eq!(r, EW_OK);
    assert_eq!((p.dest[0], p.dist[0]), (x, x - now));
    assert_ne!(p.dist[0], 0);

    assert_eq!(unsafe { cnc_rdprstrinfo(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
    drop(s);
}
