//! The operation history, the operator message histories and alarm history
//! 5 through the C ABI against the simulator: the profile's entries, a
//! signal change the test itself made, bad ranges and short lengths.

mod sim;

use fwlib32::ew::*;
use fwlib32::sim::Profile;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::c_ushort;

fn ophis(h: c_ushort, s: u16, e: u16, length: u16) -> (i16, ODBHIS) {
    let mut b = ODBHIS::default();
    let r = unsafe { cnc_rdophistry(h, s, e, length, &mut b) };
    (r, b)
}

#[test]
fn operation_history_reads_the_profile_and_a_signal_written_here() {
    let (s, h) = sim::start_alloc(Profile::default());
    let (r, b) = ophis(h, 1, 5, 86);
    assert_eq!(r, EW_OK);
    assert_eq!((b.s_no, b.e_no), (1, 5));
    let d = |i: usize| b.data[i];
    unsafe {
        assert_eq!((d(0).rec_alm.rec_type, d(0).rec_alm.alm_no), (2, 1001));
        assert_eq!(d(0).rec_alm.alm_grp, 19);
        let g = d(1).rec_sgn;
        assert_eq!((g.rec_type, g.sig_no, g.sig_old, g.sig_new), (1, 43, 1, 5));
        assert_eq!((d(2).rec_mdi.rec_type, d(2).rec_mdi.key_code), (0, 0x52));
        let t = d(3).rec_time;
        assert_eq!((t.rec_type, t.hour, t.minute, t.second), (4, 13, 45, 30));
        let y = d(4).rec_date;
        assert_eq!((y.rec_type, y.year, y.month, y.day), (3, 24, 5, 17));
    }

    // A G-signal byte written through FOCAS is recorded, newest first,
    // after a date and a time stamp.
    let mut w = [0u8; 9];
    w[4..6].copy_from_slice(&10u16.to_le_bytes());
    w[6..8].copy_from_slice(&10u16.to_le_bytes());
    w[8] = 0x81;
    assert_eq!(unsafe { pmc_wrpmcrng(h, 9, w.as_mut_ptr().cast()) }, EW_OK);
    let (r, b) = ophis(h, 1, 3, 86);
    assert_eq!(r, EW_OK);
    unsafe {
        let g = b.data[0].rec_sgn;
        assert_eq!((g.rec_type, g.sig_no, g.sig_name), (1, 10, 0));
        assert_eq!((g.sig_old as u8, g.sig_new as u8), (0, 0x81));
        assert_eq!(b.data[1].rec_time.rec_type, 4);
        assert_eq!(b.data[2].rec_date.rec_type, 3);
    }

    // Bad range, short length: nothing written.
    assert_eq!(ophis(h, 3, 2, 86).0, EW_NUMBER);
    assert_eq!(ophis(h, 1, 5, 14).0, EW_LENGTH);
    assert_eq!(
        unsafe { cnc_rdophistry(h, 1, 5, 86, std::ptr::null_mut()) },
        EW_DATA
    );
    sim::free(h);
    drop(s);
}

#[test]
fn operator_message_histories_read_the_profile() {
    let (s, h) = sim::start_alloc(Profile::default());
    let mut b: ODBOMHIS2 = unsafe { std::mem::zeroed() };
    let r = unsafe { cnc_rdomhistry2(h, 1, 10, 2724, &mut b) };
    assert_eq!(r, EW_OK);
    // The message on display at power-on first, then the profile's two.
    assert_eq!((b.s_no, b.e_no), (1, 3));
    let m = b.opm_his[1];
    assert_eq!((m.om_no, m.year, m.month, m.day), (2002, 2024, 5, 17));
    assert_eq!(m.dsp_flg, 0);
    assert_eq!(b.opm_his[0].dsp_flg, 1);
    let text: String = m
        .ope_msg
        .iter()
        .take_while(|c| **c != 0)
        .map(|c| *c as u8 as char)
        .collect();
    assert_eq!(text, "TOOL 12 LIFE EXPIRED");
    assert_eq!(unsafe { cnc_rdomhistry2(h, 1, 10, 100, &mut b) }, EW_LENGTH);

    let mut one: [ODBOMHIS; 5] = unsafe { std::mem::zeroed() };
    let mut num: u16 = 5;
    assert_eq!(
        unsafe { cnc_rdomhistry(h, 1, &mut num, one.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 2);
    assert_eq!((one[0].om_no, one[0].year), (2002, 24));
    num = 0;
    assert_eq!(
        unsafe { cnc_rdomhistry(h, 1, &mut num, one.as_mut_ptr()) },
        EW_LENGTH
    );
    sim::free(h);
    drop(s);
}

#[test]
fn alarm_history_5_reads_the_ring_two_entries_an_exchange() {
    let (s, h) = sim::start_alloc(Profile::default());
    let mut b: Box<ODBAHIS5> = Box::new(unsafe { std::mem::zeroed() });
    let r = unsafe { cnc_rdalmhistry5(h, 1, 10, 5164, &mut *b) };
    assert_eq!(r, EW_OK);
    let want = &Profile::default().alarm_history.entries;
    assert_eq!(usize::from(b.e_no), want.len());
    let a = b.alm_his[1];
    assert_eq!((a.alm_no, a.alm_grp, a.axis_no), (500, 4, 3));
    assert_eq!((a.year, a.month, a.day, a.hour), (2024, 5, 16, 9));
    assert_eq!((a.pth_no, a.len_msg), (1, 18));
    assert_eq!(
        unsafe { cnc_rdalmhistry5(h, 0, 10, 5164, &mut *b) },
        EW_NUMBER
    );
    assert_eq!(
        unsafe { cnc_rdalmhistry5(h, 1, 10, 520, &mut *b) },
        EW_LENGTH
    );
    sim::free(h);
    drop(s);
}

#[test]
fn pitch_error_table_reads_the_profile_across_exchanges() {
    let (s, h) = sim::start_alloc(Profile::default());
    let p = Profile::default().pitch;
    let mut n = 0i16;
    assert_eq!(unsafe { cnc_rdpitchinfo(h, &mut n) }, EW_OK);
    assert_eq!(i32::from(n), p.size);
    // Points 0..=999: two exchanges (716 points each at most).
    let mut b = vec![0x55u8; 6 + 1000 + 8];
    let r = unsafe { cnc_rdpitchr(h, 0, 999, 1006, b.as_mut_ptr().cast()) };
    assert_eq!(r, EW_OK);
    assert_eq!(i16::from_le_bytes([b[4], b[5]]), 999);
    for (i, v) in p.values.iter().enumerate() {
        assert_eq!(b[6 + i] as i8, *v, "point {i}");
    }
    assert_eq!(b[6 + 1000], 0x55, "nothing past the points");
    assert_eq!(
        unsafe { cnc_rdpitchr(h, 0, 999, 100, b.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    assert_eq!(
        unsafe { cnc_rdpitchr(h, 5, 4, 100, b.as_mut_ptr().cast()) },
        EW_NUMBER
    );
    sim::free(h);
    drop(s);
}
