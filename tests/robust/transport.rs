//! How answers are read on connection 2 (src/client/conn.rs): frames in
//! pieces or several to a read, frames of another kind discarded, and the
//! handle's timeout bounding a call whatever timeout the socket had before
//! (socket timeouts are set only when the one set does not fit).

use crate::common;

use common::*;
use fwlib32::ew::*;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_short, c_ushort};
use std::time::{Duration, Instant};

/// cnc_modal(h, -1, 0, ..) and an answer with one pair {10, flag 0}.
const MODAL_REQ: &str =
    "a0a0a0a000012101001e0001001c000100010021ffffffff00000000000000000000000000000000";
const MODAL_RESP: &str = "a0a0a0a00003210200140001001200010001002100000000000000020a00";
/// A frame of a kind nobody asked for (an upload end on connection 2).
const STRAY: &str = "a0a0a0a0000317010000";

fn connect(server: &mut Replay, timeout: std::os::raw::c_long) -> c_ushort {
    replay_connect(server, timeout)
}

/// cnc_modal(-1): its return and the G-code byte of the one pair.
fn modal(h: c_ushort) -> (c_short, u8) {
    let mut b = [0xCCu8; size_of::<ODBMDL>()];
    let r = unsafe { cnc_modal(h, -1, 0, b.as_mut_ptr().cast()) };
    (r, b[4])
}

/// Plays `resp` (pieces written in turn, `pause` apart) as the answer to
/// cnc_modal(-1).
fn modal_answered(server: &mut Replay, h: c_ushort, resp: &[&str], pause: Duration) -> c_short {
    let mut events = vec![Event::parse(2, "req", MODAL_REQ)];
    for (i, piece) in resp.iter().enumerate() {
        if i > 0 {
            events.push(Event::new(2, Ev::Delay(pause)));
        }
        events.push(Event::parse(2, "resp", piece));
    }
    let ((r, g), m) = server.step("modal", events, || modal(h));
    assert!(m.is_empty(), "{}", m.join("\n"));
    if r == EW_OK {
        assert_eq!(g, 10, "the pair's G code");
    }
    r
}

#[test]
fn an_answer_in_pieces_is_read_whole() {
    let mut s = Replay::start();
    let h = connect(&mut s, 3);
    let pause = Duration::from_millis(20);
    // Header, then body; part of the header, then the rest; byte by byte
    // across the header's end.
    let (head, body) = MODAL_RESP.split_at(20);
    assert_eq!(modal_answered(&mut s, h, &[head, body], pause), EW_OK);
    let (a, b) = MODAL_RESP.split_at(8);
    assert_eq!(modal_answered(&mut s, h, &[a, b], pause), EW_OK);
    let pieces: Vec<&str> = (0..6)
        .map(|i| &MODAL_RESP[16 + 2 * i..18 + 2 * i])
        .collect();
    let mut all = vec![&MODAL_RESP[..16]];
    all.extend(pieces);
    all.push(&MODAL_RESP[28..]);
    assert_eq!(modal_answered(&mut s, h, &all, pause), EW_OK);
    s.close(h);
}

#[test]
fn frames_of_another_kind_are_discarded_wherever_reads_cut_them() {
    let mut s = Replay::start();
    let h = connect(&mut s, 3);
    let pause = Duration::from_millis(20);
    // A stray frame and the answer in one write (one read takes both).
    let both = format!("{STRAY}{MODAL_RESP}");
    assert_eq!(modal_answered(&mut s, h, &[&both], pause), EW_OK);
    // Two stray frames and the answer's first bytes, then the rest.
    let first = format!("{STRAY}{STRAY}{}", &MODAL_RESP[..14]);
    assert_eq!(
        modal_answered(&mut s, h, &[&first, &MODAL_RESP[14..]], pause),
        EW_OK
    );
    // Nothing left over: the next call reads its own answer.
    assert_eq!(modal_answered(&mut s, h, &[MODAL_RESP], pause), EW_OK);
    s.close(h);
}

/// A call whose answer stops after `sent` (hex) ends with EW_SOCKET once
/// the handle's 1 s timeout has passed, though the connection was opened
/// with a 3 s timeout and a call on it already armed the socket for that:
/// getdtailerr then tells which part of the frame was missing.
fn stalled(sent: &str) -> (i16, i16) {
    let mut s = Replay::start();
    let h = connect(&mut s, 3);
    assert_eq!(
        modal_answered(&mut s, h, &[MODAL_RESP], Duration::ZERO),
        EW_OK
    );
    assert_eq!(cnc_settimeout(h, 1), EW_OK);
    let t0 = Instant::now();
    let ((r, _), m) = s.step(
        "modal, stalled",
        ev(&[(2, "req", MODAL_REQ), (2, "resp", sent)]),
        || modal(h),
    );
    let took = t0.elapsed();
    assert!(m.is_empty(), "{}", m.join("\n"));
    assert_eq!(r, EW_SOCKET);
    assert!(took >= Duration::from_secs(1), "gave up after {took:?}");
    // The 3 s the socket was armed for must not have been waited out.
    assert!(
        took < Duration::from_millis(2500),
        "the 1 s timeout ended the call only after {took:?}"
    );
    let mut e = ODBERR {
        err_no: 0,
        err_dtno: 0,
    };
    assert_eq!(unsafe { cnc_getdtailerr(h, &mut e) }, EW_OK);
    // The pair is torn down: the free sends nothing.
    let (r, m) = s.step("free", vec![], || cnc_freelibhndl(h));
    assert!(m.is_empty(), "{}", m.join("\n"));
    assert_eq!(r, EW_OK);
    let m = s.finish();
    assert!(m.is_empty(), "{}", m.join("\n"));
    (e.err_no, e.err_dtno)
}

#[test]
fn a_header_cut_short_times_out_by_the_handles_timeout() {
    assert_eq!(stalled(&MODAL_RESP[..10]), (9, 1));
}

#[test]
fn a_body_cut_short_times_out_by_the_handles_timeout() {
    assert_eq!(stalled(&MODAL_RESP[..26]), (9, 2));
}
