//! Custom macro variables through the C ABI against the simulator: values
//! with decimal places, negative and vacant variables written and read
//! back, protection (a rejected write changes nothing), local checks, and
//! the 16i class.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::Profile;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_long, c_short, c_ushort};

const PROFILE: &str = r#"
[cnc]
class = "30i"

[[path]]
machine = "mill"

[path.macros]
ranges = [[100, 199], [500, 999]]
protected = [[990, 999]]

[path.macros.values]
100 = "12.345"
150 = "-7"
995 = "3.25"
"#;

/// cnc_rdmacro → (return, mcr_val, dec_val).
fn rd(h: c_ushort, n: c_short) -> (c_short, i32, i16) {
    let mut m = ODBM::default();
    let r = unsafe { cnc_rdmacro(h, n, 10, &mut m) };
    if r == EW_OK {
        assert_eq!(m.datano, n);
    }
    (r, m.mcr_val, m.dec_val)
}

fn wr(h: c_ushort, n: c_short, v: c_long, d: c_short) -> c_short {
    unsafe { cnc_wrmacro(h, n, 10, v, d) }
}

#[test]
fn profile_values_read_back() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    assert_eq!(rd(h, 100), (EW_OK, 12345, 3));
    assert_eq!(rd(h, 150), (EW_OK, -7, 0));
    assert_eq!(rd(h, 101), (EW_OK, 0, -1), "vacant");
    assert_eq!(rd(h, 995), (EW_OK, 325, 2));
    sim::free(h);
}

#[test]
fn default_profile_has_the_adapter_macro() {
    let s = sim::start(Profile::default());
    let h = sim::alloc(&s);
    // The MTConnect adapter reads #500 with length sizeof(ODBM).
    let mut m = ODBM::default();
    let len = std::mem::size_of::<ODBM>() as c_short;
    assert_eq!(unsafe { cnc_rdmacro(h, 500, len, &mut m) }, EW_OK);
    assert_eq!((m.datano, m.mcr_val, m.dec_val), (500, 25400, 3));
    assert_eq!(rd(h, 501), (EW_OK, -125, 3));
    sim::free(h);
}

#[test]
fn written_values_read_back() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    for (n, v, d) in [
        (100, 123456, 3),
        (101, -25, 1),
        (102, 0, 0),
        (500, i32::MAX, 9),
        (501, i32::MIN, 0),
        (999 - 10, -1, 4),
    ] {
        assert_eq!(wr(h, n, v as c_long, d), EW_OK, "#{n}");
        assert_eq!(rd(h, n), (EW_OK, v, d), "#{n}");
    }
    // Vacant: 0 with dec_val -1.
    assert_eq!(wr(h, 100, 0, -1), EW_OK);
    assert_eq!(rd(h, 100), (EW_OK, 0, -1));
    // A 64-bit long is taken as its low 32 bits (as FANUC's x86-64 library).
    assert_eq!(wr(h, 103, 0x1_0000_0007, 0), EW_OK);
    assert_eq!(rd(h, 103), (EW_OK, 7, 0));
    sim::free(h);
}

#[test]
fn range_read_matches_single_reads() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    assert_eq!(wr(h, 101, -5, 2), EW_OK);
    let mut b = IODBMR::default();
    assert_eq!(
        unsafe { cnc_rdmacror(h, 99 + 1, 102, 8 + 8 * 3, &mut b) },
        EW_OK
    );
    assert_eq!((b.datano_s, b.datano_e), (100, 102));
    let got: Vec<(i32, i16)> = b.data[..3].iter().map(|r| (r.mcr_val, r.dec_val)).collect();
    assert_eq!(got, [(12345, 3), (-5, 2), (0, -1)]);
    for (i, n) in (100..=102).enumerate() {
        assert_eq!(rd(h, n), (EW_OK, got[i].0, got[i].1));
    }
    sim::free(h);
}

#[test]
fn range_read_writes_no_more_than_length() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    // Five variables asked for, room for two: EW_LENGTH after the
    // exchange, nothing written (as FANUC's library).
    let mut buf = [0xCCu8; 64];
    let r = unsafe { cnc_rdmacror(h, 100, 104, 8 + 8 * 2, buf.as_mut_ptr().cast()) };
    assert_eq!(r, EW_LENGTH);
    assert!(buf.iter().all(|b| *b == 0xCC), "{buf:?}");
    // Room for all five: written, and nothing after them.
    let r = unsafe { cnc_rdmacror(h, 100, 104, 8 + 8 * 5, buf.as_mut_ptr().cast()) };
    assert_eq!(r, EW_OK);
    assert!(buf[8 + 8 * 5..].iter().all(|b| *b == 0xCC), "{buf:?}");
    assert_eq!(&buf[8..12], &12345i32.to_le_bytes());
    sim::free(h);
}

#[test]
fn protection_and_numbers() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    // Write-protected #990-#999: EW_PROT, value unchanged.
    assert_eq!(wr(h, 995, 1, 0), EW_PROT);
    assert_eq!(rd(h, 995), (EW_OK, 325, 2));
    // Numbers that do not exist: EW_NUMBER both ways, nothing changes.
    assert_eq!(rd(h, 200).0, EW_NUMBER);
    assert_eq!(wr(h, 200, 1, 0), EW_NUMBER);
    assert_eq!(rd(h, 1000).0, EW_NUMBER);
    // A range reaching a missing number: EW_NUMBER, buffer untouched.
    let mut buf = [0xCCu8; 48];
    let r = unsafe { cnc_rdmacror(h, 198, 202, 48, buf.as_mut_ptr().cast()) };
    assert_eq!(r, EW_NUMBER);
    assert!(buf.iter().all(|b| *b == 0xCC));
    // Decimal places a CNC refuses: EW_DATA, value unchanged.
    assert_eq!(wr(h, 100, 1, 12), EW_DATA);
    assert_eq!(wr(h, 100, 1, -2), EW_DATA);
    assert_eq!(rd(h, 100), (EW_OK, 12345, 3));
    sim::free(h);
}

#[test]
fn local_checks_before_traffic() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    // Local variables (#1..#33, anything below 100): EW_NUMBER.
    assert_eq!(wr(h, 1, 1, 0), EW_NUMBER);
    assert_eq!(wr(h, 99, 1, 0), EW_NUMBER);
    assert_eq!(wr(h, -1, 1, 0), EW_NUMBER);
    // dec_val outside -128..127: EW_DATA (FANUC's library, every class).
    assert_eq!(wr(h, 100, 1, 32767), EW_DATA);
    assert_eq!(wr(h, 100, 1, 128), EW_DATA);
    assert_eq!(wr(h, 100, 1, -129), EW_DATA);
    // length must be at least 10.
    assert_eq!(unsafe { cnc_wrmacro(h, 100, 8, 1, 0) }, EW_LENGTH);
    assert_eq!(unsafe { cnc_wrmacro(h, 100, 9, 1, 0) }, EW_LENGTH);
    assert_eq!(rd(h, 100), (EW_OK, 12345, 3), "nothing was written");
    // A longer length is accepted, as by FANUC's library.
    assert_eq!(unsafe { cnc_wrmacro(h, 100, 12, 12345, 3) }, EW_OK);
    // rdmacro: length at least 10; NULL buffers.
    let mut m = ODBM::default();
    assert_eq!(unsafe { cnc_rdmacro(h, 100, 9, &mut m) }, EW_LENGTH);
    assert_eq!(m, ODBM::default());
    assert_eq!(
        unsafe { cnc_rdmacro(h, 100, 10, std::ptr::null_mut()) },
        EW_DATA
    );
    assert_eq!(
        unsafe { cnc_rdmacror(h, 100, 101, 24, std::ptr::null_mut()) },
        EW_DATA
    );
    sim::free(h);
    // A freed handle.
    assert_eq!(unsafe { cnc_rdmacro(h, 100, 10, &mut m) }, EW_HANDLE);
    assert_eq!(wr(h, 100, 1, 0), EW_HANDLE);
    // FANUC's library checks cnc_wrmacro's length before the handle.
    assert_eq!(unsafe { cnc_wrmacro(h, 100, 8, 1, 0) }, EW_LENGTH);
}

#[test]
fn series16_round_trip() {
    // FANUC's library sends the 16i class its record with base word 2;
    // the simulated 16i takes it as digits and decimals and answers base 10.
    let s = sim::start_toml(&PROFILE.replace("\"30i\"", "\"16i\""));
    let h = sim::alloc(&s);
    assert_eq!(rd(h, 100), (EW_OK, 12345, 3));
    assert_eq!(wr(h, 500, -98765, 4), EW_OK);
    assert_eq!(rd(h, 500), (EW_OK, -98765, 4));
    assert_eq!(wr(h, 50, 1, 0), EW_NUMBER);
    assert_eq!(unsafe { cnc_wrmacro(h, 500, 9, 1, 0) }, EW_LENGTH);
    sim::free(h);
}

#[test]
fn range_write_reads_back() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    let mut b = IODBMR {
        datano_s: 500,
        datano_e: 502,
        ..IODBMR::default()
    };
    for (i, (v, d)) in [(15, 1), (-2250, 3), (0, -1)].into_iter().enumerate() {
        b.data[i] = IODBMR_data {
            mcr_val: v,
            dec_val: d,
        };
    }
    assert_eq!(unsafe { cnc_wrmacror(h, 8 + 8 * 3, &mut b) }, EW_OK);
    assert_eq!(rd(h, 500), (EW_OK, 15, 1));
    assert_eq!(rd(h, 501), (EW_OK, -2250, 3));
    assert_eq!(rd(h, 502), (EW_OK, 0, -1));
    let mut back = IODBMR::default();
    assert_eq!(unsafe { cnc_rdmacror(h, 500, 502, 48, &mut back) }, EW_OK);
    assert_eq!(&back.data[..3], &b.data[..3]);

    // Local checks (FANUC's): the last dec_val must lie within length,
    // numbers from 100, s <= e, dec_val not 32767 / below -1.
    assert_eq!(unsafe { cnc_wrmacror(h, 8 * 3 + 5, &mut b) }, EW_LENGTH);
    assert_eq!(unsafe { cnc_wrmacror(h, 8 * 3 + 6, &mut b) }, EW_OK);
    b.data[1].dec_val = 32767;
    assert_eq!(unsafe { cnc_wrmacror(h, 48, &mut b) }, EW_DATA);
    b.data[1].dec_val = -2;
    assert_eq!(unsafe { cnc_wrmacror(h, 48, &mut b) }, EW_DATA);
    b.data[1].dec_val = 3;
    b.datano_s = 99;
    assert_eq!(unsafe { cnc_wrmacror(h, 48, &mut b) }, EW_NUMBER);
    b.datano_s = 503;
    assert_eq!(unsafe { cnc_wrmacror(h, 48, &mut b) }, EW_NUMBER);
    assert_eq!(
        unsafe { cnc_wrmacror(h, 48, std::ptr::null_mut()) },
        EW_DATA
    );
    // A range touching protected #990-#999: EW_PROT, none written.
    b.datano_s = 988;
    b.datano_e = 990;
    assert_eq!(unsafe { cnc_wrmacror(h, 48, &mut b) }, EW_PROT);
    assert_eq!(rd(h, 988), (EW_OK, 0, -1));
    sim::free(h);
}

#[test]
fn macro_info_counts_the_common_variables() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    let mut i = ODBMVINF::default();
    assert_eq!(unsafe { cnc_rdmacroinfo(h, &mut i) }, EW_OK);
    assert_eq!((i.use_no1, i.use_no2), (100, 500));
    assert_eq!(unsafe { cnc_rdmacroinfo(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
}

#[test]
fn doubles_round_trip() {
    let s = sim::start_toml(PROFILE);
    let h = sim::alloc(&s);
    // 400 variables from #500: FANUC's library writes 177 per request and
    // reads 179 per request; both loops are exercised.
    let mut vals: Vec<f64> = (0..400).map(|i| f64::from(i) * 0.25 - 50.0).collect();
    let mut n: [u32; 2] = [400, 0xdead];
    let r = unsafe { cnc_wrmacror2(h, 500, n.as_mut_ptr().cast(), vals.as_mut_ptr()) };
    assert_eq!(r, EW_OK);
    assert_eq!(n, [400, 0xdead], "*num is 4 bytes");
    let mut back = vec![f64::NAN; 410];
    n[0] = 400;
    let r = unsafe { cnc_rdmacror2(h, 500, n.as_mut_ptr().cast(), back.as_mut_ptr()) };
    assert_eq!(r, EW_OK);
    assert_eq!(n[0], 400);
    assert_eq!(&back[..400], &vals[..]);
    assert!(
        back[400..].iter().all(|x| x.is_nan()),
        "no more than *num written"
    );
    // The same values through the decimal interface.
    assert_eq!(rd(h, 501), (EW_OK, -4975, 2));
    assert_eq!(rd(h, 504), (EW_OK, -49, 0));

    // Reading past the last variable: a short answer ends the read.
    n[0] = 10;
    let r = unsafe { cnc_rdmacror2(h, 195, n.as_mut_ptr().cast(), back.as_mut_ptr()) };
    assert_eq!(r, EW_OK);
    assert_eq!(n[0], 5);
    // *num 0: EW_LENGTH before any traffic; protected or missing: nothing written.
    n[0] = 0;
    let r = unsafe { cnc_rdmacror2(h, 100, n.as_mut_ptr().cast(), back.as_mut_ptr()) };
    assert_eq!(r, EW_LENGTH);
    n[0] = 2;
    let mut two = [1.0, 2.0];
    let r = unsafe { cnc_wrmacror2(h, 989, n.as_mut_ptr().cast(), two.as_mut_ptr()) };
    assert_eq!(r, EW_PROT);
    assert_eq!(rd(h, 989), (EW_OK, 0, -1));
    let r = unsafe { cnc_wrmacror2(h, 199, n.as_mut_ptr().cast(), two.as_mut_ptr()) };
    assert_eq!(r, EW_NUMBER);
    let mut nan = [f64::NAN];
    n[0] = 1;
    let r = unsafe { cnc_wrmacror2(h, 100, n.as_mut_ptr().cast(), nan.as_mut_ptr()) };
    assert_eq!(r, EW_DATA);
    sim::free(h);
}
