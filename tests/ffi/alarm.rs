//! Alarm-area functions through the C ABI against the simulator: the
//! profile's active alarms and operator messages read back through
//! cnc_alarm/alarm2/rdalmmsg/rdalmmsg2/rdalminfo/rdopmsg; NULL pointers,
//! bad handles and lengths; nothing written past the caller's buffer.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_char, c_long, c_short, c_ushort};
use std::ptr::null_mut;

const ALARMS: &str = r#"
[[path]]
[[path.alarm]]
number = 1001
type = 19
message = "COOLANT LEVEL LOW"
[[path.alarm]]
number = 500
type = 4
axis = 1
message = "OVER TRAVEL +X"
[[path.alarm]]
number = 70001
type = 3
message = "A MESSAGE LONGER THAN THIRTY-TWO CHARACTERS, UP TO SIXTY-FOUR"
[[path.opmsg]]
number = 2001
type = 0
text = "DOOR OPEN !"
"#;

struct Want {
    number: i32,
    kind: i16,
    axis: i16,
    message: &'static str,
}

const WANT: [Want; 3] = [
    Want {
        number: 1001,
        kind: 19,
        axis: 0,
        message: "COOLANT LEVEL LOW",
    },
    Want {
        number: 500,
        kind: 4,
        axis: 1,
        message: "OVER TRAVEL +X",
    },
    Want {
        number: 70001,
        kind: 3,
        axis: 0,
        message: "A MESSAGE LONGER THAN THIRTY-TWO CHARACTERS, UP TO SIXTY-FOUR",
    },
];

fn start(profile: &str) -> (Simulator, c_ushort) {
    sim::start_alloc(Profile::parse(profile).expect("profile"))
}

fn text(c: &[c_char], n: usize) -> String {
    c[..n].iter().map(|x| *x as u8 as char).collect()
}

#[test]
fn alarm_bits() {
    let (_s, h) = start(ALARMS);
    let bits: u32 = 1 << 19 | 1 << 4 | 1 << 3;
    let mut l: c_long = -1;
    assert_eq!(unsafe { cnc_alarm2(h, &mut l) }, EW_OK);
    assert_eq!(l as u32, bits);
    let mut a = ODBALM {
        dummy: [5, 5],
        data: 0,
    };
    assert_eq!(unsafe { cnc_alarm(h, &mut a) }, EW_OK);
    assert_eq!(a.data, bits as u16 as i16, "low 16 bits");
    assert_eq!(a.dummy, [5, 5]);
    sim::free(h);
}

#[test]
fn alarm_messages() {
    let (_s, h) = start(ALARMS);
    let mut recs = [ODBALMMSG::default(); 4];
    let mut num: c_short = 4;
    assert_eq!(
        unsafe { cnc_rdalmmsg(h, -1, &mut num, recs.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 3);
    for (r, w) in recs.iter().zip(&WANT) {
        assert_eq!((r.alm_no, r.r#type, r.axis), (w.number, w.kind, w.axis));
        let n = w.message.len().min(32);
        assert_eq!(r.msg_len as usize, n);
        assert_eq!(text(&r.alm_msg, n), w.message[..n]);
    }

    // Only alarms of one type; at most *num records.
    let mut num: c_short = 4;
    assert_eq!(
        unsafe { cnc_rdalmmsg(h, 4, &mut num, recs.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!((num, recs[0].alm_no), (1, 500));
    let mut two = [ODBALMMSG::default(); 3];
    two[2].alm_no = 42;
    let mut num: c_short = 2;
    assert_eq!(
        unsafe { cnc_rdalmmsg(h, -1, &mut num, two.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 2);
    assert_eq!(two[2].alm_no, 42, "nothing past *num records");

    let mut recs2 = [ODBALMMSG2::default(); 3];
    let mut num: c_short = 3;
    assert_eq!(
        unsafe { cnc_rdalmmsg2(h, -1, &mut num, recs2.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 3);
    let w = &WANT[2];
    assert_eq!(recs2[2].msg_len as usize, w.message.len());
    assert_eq!(text(&recs2[2].alm_msg, w.message.len()), w.message);
    sim::free(h);
}

#[test]
fn alarm_info() {
    let (_s, h) = start(ALARMS);
    // Type 0: axis and number; −1 after the last record.
    let mut a = ALMINFO::default();
    assert_eq!(
        unsafe { cnc_rdalminfo(h, 0, -1, std::mem::size_of::<ALMINFO>() as c_short, &mut a) },
        EW_OK
    );
    let r = unsafe { a.u.alm1 };
    for (x, w) in r.alm.iter().zip(&WANT) {
        assert_eq!(
            (x.axis, x.alm_no),
            (i32::from(w.axis), w.number as u16 as i16)
        );
    }
    assert_eq!(r.alm[3].axis, -1, "end mark after 3 records");

    // Type 1: with messages.
    let mut a = ALMINFO::default();
    assert_eq!(unsafe { cnc_rdalminfo(h, 1, -1, 204, &mut a) }, EW_OK);
    let r = unsafe { a.u.alm2 };
    for (x, w) in r.alm.iter().zip(&WANT) {
        let n = w.message.len().min(32);
        assert_eq!(x.alm_no, w.number as u16 as i16);
        assert_eq!(
            (x.msg_len as usize, text(&x.alm_msg, n)),
            (n, w.message[..n].to_string())
        );
    }
    assert_eq!(r.alm[3].axis, -1);

    // A 12-byte buffer holds one type-0 record and the end mark: nothing more written.
    let mut b = [0xccu8; 64];
    assert_eq!(
        unsafe { cnc_rdalminfo(h, 0, -1, 12, b.as_mut_ptr().cast()) },
        EW_OK
    );
    assert_eq!(&b[4..6], &1001i16.to_le_bytes());
    assert_eq!(&b[8..12], &(-1i32).to_le_bytes());
    assert!(b[12..].iter().all(|x| *x == 0xcc));

    // Type 1 in 43 bytes: no room for one record: EW_LENGTH before any
    // traffic, nothing written (FANUC's library).
    let mut b = [0xccu8; 64];
    assert_eq!(
        unsafe { cnc_rdalminfo(h, 1, -1, 43, b.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    assert!(b.iter().all(|x| *x == 0xcc));

    let mut a = ALMINFO::default();
    assert_eq!(unsafe { cnc_rdalminfo(h, 0, -1, 4, &mut a) }, EW_LENGTH);
    sim::free(h);
}

#[test]
fn no_alarms() {
    let (_s, h) = start("[[path]]\n");
    let mut l: c_long = -1;
    assert_eq!(unsafe { cnc_alarm2(h, &mut l) }, EW_OK);
    assert_eq!(l as u32, 0);
    let mut recs = [ODBALMMSG::default(); 2];
    recs[0].alm_no = 9;
    let mut num: c_short = 2;
    assert_eq!(
        unsafe { cnc_rdalmmsg(h, -1, &mut num, recs.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!((num, recs[0].alm_no), (0, 9));
    let mut a = ALMINFO::default();
    unsafe { a.u.alm1.alm[0].axis = 7 };
    assert_eq!(unsafe { cnc_rdalminfo(h, 0, -1, 44, &mut a) }, EW_OK);
    assert_eq!(unsafe { a.u.alm1.alm[0].axis }, -1);
    sim::free(h);
}

#[test]
fn operator_messages() {
    let (_s, h) = start(ALARMS);
    let mut m = OPMSG::default();
    m.data.fill(0x55);
    assert_eq!(unsafe { cnc_rdopmsg(h, 0, 262, &mut m) }, EW_OK);
    assert_eq!((m.datano, m.r#type, m.char_num), (2001, 0, 11));
    assert_eq!(text(&m.data, 11), "DOOR OPEN !");
    assert!(m.data[11..].iter().all(|c| *c == 0), "zero-filled");

    // Only type 0 (FANUC's library refuses the others before any traffic).
    assert_eq!(unsafe { cnc_rdopmsg(h, 2, 262, &mut m) }, EW_ATTRIB);
    assert_eq!(unsafe { cnc_rdopmsg(h, -1, 1310, &mut m) }, EW_ATTRIB);

    // Always the 262 bytes of OPMSG, whatever `length` (at least 262).
    let mut b = [0xccu8; 300];
    assert_eq!(
        unsafe { cnc_rdopmsg(h, 0, 1000, b.as_mut_ptr().cast()) },
        EW_OK
    );
    assert_eq!(&b[6..17], b"DOOR OPEN !");
    assert!(b[17..262].iter().all(|x| *x == 0));
    assert!(b[262..].iter().all(|x| *x == 0xcc));

    assert_eq!(unsafe { cnc_rdopmsg(h, 0, 10, &mut m) }, EW_LENGTH);
    assert_eq!(unsafe { cnc_rdopmsg(h, 0, 5, &mut m) }, EW_LENGTH);
    sim::free(h);
}

#[test]
fn null_pointers_and_bad_handles() {
    let (_s, h) = start(ALARMS);
    let mut num: c_short = 1;
    let mut m = ODBALMMSG::default();
    let mut m2 = ODBALMMSG2::default();
    unsafe {
        assert_eq!(cnc_alarm(h, null_mut()), EW_DATA);
        assert_eq!(cnc_alarm2(h, null_mut()), EW_DATA);
        assert_eq!(cnc_rdalmmsg(h, -1, null_mut(), &mut m), EW_DATA);
        assert_eq!(cnc_rdalmmsg(h, -1, &mut num, null_mut()), EW_DATA);
        assert_eq!(cnc_rdalmmsg2(h, -1, null_mut(), &mut m2), EW_DATA);
        assert_eq!(cnc_rdalmmsg2(h, -1, &mut num, null_mut()), EW_DATA);
        assert_eq!(cnc_rdalminfo(h, 0, -1, 44, null_mut()), EW_DATA);
        assert_eq!(cnc_rdopmsg(h, 0, 262, null_mut()), EW_DATA);

        let bad = 0x7777;
        let mut a = ODBALM::default();
        assert_eq!(cnc_alarm(bad, &mut a), EW_HANDLE);
        assert_eq!(cnc_rdalmmsg(bad, -1, &mut num, &mut m), EW_HANDLE);
        let mut i = ALMINFO::default();
        assert_eq!(cnc_rdalminfo(bad, 0, -1, 44, &mut i), EW_HANDLE);
        let mut o = OPMSG::default();
        assert_eq!(cnc_rdopmsg(bad, 0, 262, &mut o), EW_HANDLE);
    }
    sim::free(h);
}
