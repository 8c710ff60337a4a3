//! Exchanges recorded from FANUC's library (x86-64, 1.0.5) with throwaway probes against
//! our own small fake CNC, replayed to our library: every request we send must
//! equal the one FANUC's library sent, byte for byte, and every output buffer
//! (pre-filled with 0xCC) must hold exactly the bytes FANUC's library wrote.
//! The fake CNC's answers are our choices, not a real CNC's; what FANUC's
//! library made of them is the observation (docs/protocol/).

use crate::common;

use common::*;
use fwlib32::ew::*;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_short, c_ushort};

const FILL: u8 = 0xCC;

/// A replay server with a connected handle.
struct Fake {
    server: Replay,
    h: c_ushort,
}

impl Fake {
    fn connect() -> Fake {
        let mut server = Replay::start();
        let h = replay_connect(&mut server, 3);
        Fake { server, h }
    }

    /// Runs `f` while the server expects `req` and answers `resp` on conn 2.
    fn exchange<T>(&mut self, label: &str, req: &str, resp: &str, f: impl FnOnce() -> T) -> T {
        let (r, m) = self
            .server
            .step(label, ev(&[(2, "req", req), (2, "resp", resp)]), f);
        assert!(m.is_empty(), "{}", m.join("\n"));
        r
    }

    fn close(self) {
        self.server.close(self.h);
    }
}

fn unhex_ws(s: &str) -> Vec<u8> {
    unhex(&s.split_whitespace().collect::<String>())
}

/// Our buffer holds FANUC's bytes, then 0xCC to its end.
fn assert_wrote(label: &str, got: &[u8], fanuc: &str) {
    let want = unhex_ws(fanuc);
    assert!(
        got.len() >= want.len()
            && got[..want.len()] == want[..]
            && got[want.len()..].iter().all(|b| *b == FILL),
        "{label}: output differs\n  FANUC {}\n  ours  {}",
        hex(&want),
        hex(&got[..got.iter().rposition(|b| *b != FILL).map_or(0, |i| i + 1)])
    );
}

fn rdaxisdata(
    h: c_ushort,
    cls: c_short,
    types: &[c_short],
    len: c_short,
) -> (c_short, c_short, Vec<u8>) {
    let mut t = types.to_vec();
    let mut n = len;
    let mut b = vec![FILL; 64 * size_of::<ODBAXDT>()];
    let r = unsafe {
        cnc_rdaxisdata(
            h,
            cls,
            t.as_mut_ptr(),
            types.len() as c_short,
            &mut n,
            b.as_mut_ptr().cast(),
        )
    };
    (r, n, b)
}

/// cnc_rdaxisdata class 2: types 0 and 1 ask 0x56[1] (unit 8), type 2 asks
/// 0x56[3] (unit 9); names are the 4 bytes of the 0x89 entries, flag 0.
#[test]
fn rdaxisdata_class_2_servo_load_and_current() {
    let mut f = Fake::connect();
    let h = f.h;
    let (r, n, b) = f.exchange(
        "rdaxisdata(2, [0, 1, 2], 4)",
        "a0a0a0a00001210100aa0006
         001c0001000100a4 0000000200000000000000000000000000000000
         001c000100010089 0000000000000000000000000000000000000000
         001c000100010056 0000000100000000000000000000000000000000
         001c000100010056 0000000100000000000000000000000000000000
         001c000100010056 0000000300000000000000000000000000000000
         001c0001000100a4 0000000200000000000000000000000000000000",
        "a0a0a0a00003210200ba0006
         00120001000100a40000000000000002 0003
         001c000100010089000000000000000c 58000000590000005a000000
         00280001000100560000000000000018 00000064000a000000000065000a000100000066000a0002
         00280001000100560000000000000018 00000064000a000000000065000a000100000066000a0002
         00280001000100560000000000000018 0000012c000a00000000012d000a00010000012e000a0002
         00120001000100a40000000000000002 0003",
        || rdaxisdata(h, 2, &[0, 1, 2], 4),
    );
    assert_eq!((r, n), (EW_OK, 3));
    let load = "5800000064000000000008000000cccc 5900000065000000010008000000cccc
                5a00000066000000020008000000cccc cccccccccccccccccccccccccccccccc";
    assert_wrote(
        "rdaxisdata(2, [0, 1, 2], 4)",
        &b,
        &format!(
            "{load} {load} 580000002c010000000009000000cccc 590000002d010000010009000000cccc
             5a0000002e010000020009000000"
        ),
    );
    // *len 2 of 3 axes: two records.
    let (r, n, b) = f.exchange(
        "rdaxisdata(2, [2], 2)",
        "a0a0a0a00001210100720004
         001c0001000100a4 0000000200000000000000000000000000000000
         001c000100010089 0000000000000000000000000000000000000000
         001c000100010056 0000000300000000000000000000000000000000
         001c0001000100a4 0000000200000000000000000000000000000000",
        "a0a0a0a000032102006a0004
         00120001000100a40000000000000002 0003
         001c000100010089000000000000000c 58000000590000005a000000
         00280001000100560000000000000018 0000012c000a00000000012d000a00010000012e000a0002
         00120001000100a40000000000000002 0003",
        || rdaxisdata(h, 2, &[2], 2),
    );
    assert_eq!((r, n), (EW_OK, 2));
    assert_wrote(
        "rdaxisdata(2, [2], 2)",
        &b,
        "580000002c010000000009000000cccc 590000002d010000010009000000",
    );
    // Type 3 is refused before any traffic, as by FANUC's library.
    assert_eq!(rdaxisdata(h, 2, &[3], 4).0, EW_ATTRIB);
    f.close();
}

/// The position frame of rdaxisdata class 1 type 3 / rdposition type 3,
/// 8 axes with the 0xa3 flag words 0, 2, 4, 6, 8, 12, 0x18, 0x804.
const DIST_REQ: &str = "a0a0a0a00001210100c60007
    001c0001000100a4 0000000000000000000000000000000000000000
    001c000100010089 ffffffff00000000000000000000000000000000
    001c000100010088 0000000100000000000000000000000000000000
    001c000100010088 0000000200000000000000000000000000000000
    001c0001000100a3 00000000ffffffff000000000000000000000000
    001c000100010026 00000003ffffffff000000000000000000000000
    001c0001000100a4 0000000000000000000000000000000000000000";
const DIST_RESP: &str = "a0a0a0a000032102019a0007
    00120001000100a40000000000000002 0008
    00940001000100890000000000000084 00000008
      41310000423200004333000044340000 42310000433200004433000045340000
      43310000443200004533000046340000 44310000453200004633000047340000
      45310000463200004733000048340000 46310000473200004833000049340000
      473100004832000049330000 4a340000 48310000493200004a3300004b340000
    00300001000100880000000000000020 000100020003000400050006000700080009000a000b000c000d000e000f0010
    00300001000100880000000000000020 000100020003000400050006000700080009000a000b000c000d000e000f0010
    00300001000100a30000000000000020 00000000 00000002 00000004 00000006 00000008 0000000c 00000018 00000804
    00500001000100260000000000000040 00000bb8000a0003 00000bb9000a0003 00000bba000a0003 00000bbb000a0003
      00000bbc000a0003 00000bbd000a0003 00000bbe000a0003 00000bbf000a0003
    00120001000100a40000000000000002 0008";

/// The distance-to-go flag is `(f >> 3) | ((f >> 2) & 1)` of the 0xa3 word
/// (the other positions take bit 1): FANUC's library gave the flags 0, 0, 1,
/// 1, 1, 1, 3, 257 for the words above, and rdposition's `disp` their bit 0.
#[test]
fn distance_to_go_flag_as_fanuc() {
    let mut f = Fake::connect();
    let h = f.h;
    let (r, n, b) = f.exchange("rdaxisdata(1, [3], 8)", DIST_REQ, DIST_RESP, || {
        rdaxisdata(h, 1, &[3], 8)
    });
    assert_eq!((r, n), (EW_OK, 8));
    assert_wrote(
        "rdaxisdata(1, [3], 8)",
        &b,
        "41310000b80b0000030001000000cccc 42310000b90b0000030003000000cccc
         43310000ba0b0000030005000100cccc 44310000bb0b0000030007000100cccc
         45310000bc0b0000030009000100cccc 46310000bd0b000003000b000100cccc
         47310000be0b000003000d000300cccc 48310000bf0b000003000f000101",
    );

    let mut n: c_short = 8;
    let mut pos = vec![FILL; 16 * size_of::<ODBPOS>()];
    let r = f.exchange("rdposition(3, 8)", DIST_REQ, DIST_RESP, || unsafe {
        cnc_rdposition(h, 3, &mut n, pos.as_mut_ptr().cast())
    });
    assert_eq!((r, n), (EW_OK, 8));
    let skip = "cc".repeat(36);
    let mut want = String::new();
    for rec in [
        "b80b00000300010000004131",
        "b90b00000300030000004231",
        "ba0b00000300050001004331",
        "bb0b00000300070001004431",
        "bc0b00000300090001004531",
        "bd0b000003000b0001004631",
        "be0b000003000d0001004731",
        "bf0b000003000f0001004831",
    ] {
        want.push_str(&skip);
        want.push_str(rec);
    }
    assert_wrote("rdposition(3, 8)", &pos, &want);
    f.close();
}

const RDPARAM_6711_ALL_AXES: &str =
    "a0a0a0a000012101001e0001001c00010001008d00001a3700001a37ffffffff0000000000000000";

/// The fake CNC's answer to [`RDPARAM_6711_ALL_AXES`]: parameter 6711 with
/// this axis word, type word and `n` records 0x11223344 + i (base 10, dec 0).
fn rdparam_answer(axis_word: &str, ptype: &str, n: u32) -> String {
    let mut recs = String::new();
    for i in 0..n {
        recs.push_str(&format!("{:08x}000a0000", 0x1122_3344 + i));
    }
    let sub_len = 16 + 8 + 8 * n as usize;
    format!(
        "a0a0a0a00003 2102 {:04x} 0001 {sub_len:04x} 0001 0001 008d 0000 0000 0000 {:04x} 00001a37 {axis_word} {ptype} {recs}",
        sub_len + 2,
        sub_len - 16
    )
}

/// cnc_rdparam(h, 6711, -1 /*ALL_AXES*/, length, ..): FANUC's library counts
/// the values by the answer's axis word, not by the axis asked. Axis word 0
/// (a non-axis parameter): one value, length 8 is enough. Axis word -1:
/// max-axes (32) values, so length must be 4 + 32 · size (132 for a 2-word,
/// 68 for a word parameter), else EW_LENGTH with datano and the axis word
/// written.
#[test]
fn rdparam_all_axes_values_by_the_answers_axis_word() {
    let mut f = Fake::connect();
    let h = f.h;
    let rd = |length: c_short| {
        let mut b = vec![FILL; 2 * size_of::<IODBPSD>()];
        let r = unsafe { cnc_rdparam(h, 6711, -1, length, b.as_mut_ptr().cast()) };
        (r, b)
    };
    let non_axis = rdparam_answer("0000", "0003", 1);
    let (r, b) = f.exchange("non-axis, 8", RDPARAM_6711_ALL_AXES, &non_axis, || rd(8));
    assert_eq!(r, EW_OK);
    assert_wrote("non-axis, 8", &b, "371a0000 44332211");
    let (r, b) = f.exchange("non-axis, 6", RDPARAM_6711_ALL_AXES, &non_axis, || rd(6));
    assert_eq!(r, EW_LENGTH);
    assert_wrote("non-axis, 6", &b, "371a0000");

    let all = rdparam_answer("ffff", "0003", 32);
    let (r, b) = f.exchange("all axes, 8", RDPARAM_6711_ALL_AXES, &all, || rd(8));
    assert_eq!(r, EW_LENGTH);
    assert_wrote("all axes, 8", &b, "371affff");
    let (r, b) = f.exchange("all axes, 131", RDPARAM_6711_ALL_AXES, &all, || rd(131));
    assert_eq!(r, EW_LENGTH);
    assert_wrote("all axes, 131", &b, "371affff");
    let (r, b) = f.exchange("all axes, 132", RDPARAM_6711_ALL_AXES, &all, || rd(132));
    assert_eq!(r, EW_OK);
    let mut want = String::from("371affff");
    for i in 0..32u32 {
        want.push_str(&hex(&(0x1122_3344 + i).to_le_bytes()));
    }
    assert_wrote("all axes, 132", &b, &want);

    let words = rdparam_answer("ffff", "0002", 32);
    let (r, _) = f.exchange("word, 67", RDPARAM_6711_ALL_AXES, &words, || rd(67));
    assert_eq!(r, EW_LENGTH);
    let (r, b) = f.exchange("word, 68", RDPARAM_6711_ALL_AXES, &words, || rd(68));
    assert_eq!(r, EW_OK);
    let mut want = String::from("371affff");
    for i in 0..32u32 {
        want.push_str(&hex(&((0x3344 + i) as u16).to_le_bytes()));
    }
    assert_wrote("word, 68", &b, &want);
    f.close();
}

/// cnc_modal's all-codes types answered with fewer records than the struct
/// holds: FANUC's library returns EW_OK. Type -2 writes every one of its 27
/// raux1 slots, a record the CNC did not send as zeros (value and both flag
/// bytes; bytes 6..7 untouched) — zeros even right after a complete answer
/// carried non-zero values there, so not stale bytes; -3 and -1 write the
/// records there are, none for an empty answer.
#[test]
fn modal_all_codes_with_fewer_records() {
    let mut f = Fake::connect();
    let h = f.h;
    let modal = |t: c_short| {
        let mut b = vec![FILL; 2 * size_of::<ODBMDL>()];
        let r = unsafe { cnc_modal(h, t, 0, b.as_mut_ptr().cast()) };
        (r, b)
    };
    // -2: records 0..4 (values 100..104, flag bytes 1).
    let (r, b) = f.exchange(
        "modal(-2), 5 records",
        "a0a0a0a000012101001e0001001c000100010022ffffffff00000000000000000000000000000000",
        "a0a0a0a000032102003a0001 0038000100010022000000000000 0028
         0000006400010001 0000006500010001 0000006600010001 0000006700010001 0000006800010001",
        || modal(-2),
    );
    assert_eq!(r, EW_OK);
    // raux1[k] = record AUX_ORDER[k] = 1, 3, 4, 5, 6, 10, 11, 21, 22, 20, 18, 19, 0, 2, 7 ...
    let z = "000000000000cccc";
    let mut want = String::from("feff0000");
    for rec in [
        1, 3, 4, 5, 6, 10, 11, 21, 22, 20, 18, 19, 0, 2, 7, 8, 9, 16, 17, 23, 24, 25, 26, 27, 28,
        12, 13,
    ] {
        if rec < 5 {
            want.push_str(&format!("{:02x}0000000101cccc", 100 + rec));
        } else {
            want.push_str(z);
        }
    }
    assert_wrote("modal(-2), 5 records", &b, want.trim_end_matches("cccc"));
    // -3 and -1, empty answers: only datano and type.
    let (r, b) = f.exchange(
        "modal(-3), no record",
        "a0a0a0a000012101001e0001001c000100010022fffffffe00000000000000000000000000000000",
        "a0a0a0a0000321020012000100100001000100220000000000000000",
        || modal(-3),
    );
    assert_eq!(r, EW_OK);
    assert_wrote("modal(-3), no record", &b, "fdff0000");
    let (r, b) = f.exchange(
        "modal(-1), no pair",
        "a0a0a0a000012101001e0001001c000100010021ffffffff00000000000000000000000000000000",
        "a0a0a0a0000321020012000100100001000100210000000000000000",
        || modal(-1),
    );
    assert_eq!(r, EW_OK);
    assert_wrote("modal(-1), no pair", &b, "ffff0000");
    // -1 with one pair {10, flag 0}: one G-code byte.
    let (r, b) = f.exchange(
        "modal(-1), one pair",
        "a0a0a0a000012101001e0001001c000100010021ffffffff00000000000000000000000000000000",
        "a0a0a0a00003210200140001001200010001002100000000000000020a00",
        || modal(-1),
    );
    assert_eq!(r, EW_OK);
    assert_wrote("modal(-1), one pair", &b, "ffff00000a");
    f.close();
}
