//! Sans-IO codec tests, no sockets:
//!
//! * every request frame FANUC's library sent in the golden vectors (for the
//!   functions we implement) equals what our codec encodes for that call;
//! * every response frame in the vectors decodes, and re-encodes to the same
//!   bytes where its encoding is canonical; what we reject, FANUC rejected too;
//! * property tests: decode(encode(x)) == x for frames and every wire
//!   structure, and no decoder panics on arbitrary bytes.

mod common;

use common::*;
use fwlib32::proto::call::{Call, Ctx};
use fwlib32::proto::frame::{
    CLIENT_VERSION, Frame, FrameHeader, HEADER_LEN, MAGIC, ftype, max_body_len,
};
use fwlib32::proto::open::{CncClass, OpenBody};
use fwlib32::proto::packet::{
    ReqSub, RespSub, decode_request, decode_response, encode_request, encode_response,
};
use fwlib32::proto::param::Param16;
use fwlib32::proto::status::{
    CncId, StatInfo, Status, Status2, SysInfo, Word, rdcncid, sysinfo_at_connect,
};
use fwlib32::proto::wire::{DecodeError, Wire, Writer};
use fwlib32::proto::{OPTION_PARAM_15, OPTION_PARAM_16, cmd};
use proptest::collection::vec;
use proptest::prelude::*;

// ---------------------------------------------------------------------------
// Request frames of the vectors
// ---------------------------------------------------------------------------

/// Connect-time data requests (SPEC.md §3.1, §3.4), composed from the codec's
/// pieces: the start-up sysinfo frame and, for the 16i class, the option read.
fn startup_requests(open: &OpenBody) -> Vec<Vec<ReqSub>> {
    let words = open.path_words();
    let paths: Vec<u16> = (1..=words.len() as u16)
        .filter(|p| words[*p as usize - 1] != 0)
        .collect();
    let mut first = sysinfo_at_connect(&paths);
    let class = open.class();
    if class == (CncClass::Series16 { kind: 2 }) {
        let mut s = ReqSub::cnc(cmd::SYSINFO15, &[]);
        s.path = 1;
        first.push(s);
    }
    let option = match class {
        CncClass::Series30 | CncClass::Series16 { kind: 3 } => None,
        CncClass::Series16 { kind: 2 } => Some((cmd::RDPARAM, OPTION_PARAM_15)),
        CncClass::Series16 { .. } => Some((cmd::RDPARAM16, OPTION_PARAM_16)),
    };
    let mut frames = vec![first];
    if let Some((c, n)) = option {
        let mut s = ReqSub::cnc(c, &[n, n]);
        s.path = 1;
        frames.push(vec![s]);
    }
    frames
}

/// The subpackets of a call, stamped with the current path as the client does.
fn stamped(c: &impl Call, cx: &Ctx, path: u16) -> Vec<ReqSub> {
    let mut subs = c.request(cx);
    for s in &mut subs {
        if s.path == 0 {
            s.path = path;
        }
    }
    subs
}

fn data_frame(subs: &[ReqSub]) -> Vec<u8> {
    Frame::new(CLIENT_VERSION, ftype::DATA_REQ, encode_request(subs)).encode()
}

/// Probe words whose requests we can build; cases with any other word are
/// functions not implemented yet and are skipped.
const KNOWN: &[&str] = &[
    "slot",
    "seth",
    "startup",
    "exitprocess",
    "alloc",
    "alloc4",
    "free",
    "thread_alloc",
    "thread_free",
    "thread_statinfo",
    "settimeout",
    "sysinfo",
    "statinfo",
    "statinfo2",
    "rdcncid",
    "getpath",
    "setpath",
    "getdtailerr",
    // --- position ---

    // --- program ---

    // --- alarm ---

    // --- param ---

    // --- macros ---

    // --- pmc ---

    // --- offset ---

    // --- tool ---

    // --- upload ---
    "upstart",
    "upstart3",
    "upload3",
    "upend3",
];

fn num(s: &str) -> i64 {
    match s.strip_prefix("0x") {
        Some(h) => i64::from_str_radix(h, 16).unwrap(),
        None => s.parse().unwrap(),
    }
}

/// Checks one case's request frames; (frames checked, mismatches).
fn check_requests(case: &Case) -> (usize, Vec<String>) {
    let id = format!("{}/{}", case.function, case.name);
    let mut cx = Ctx {
        class: if case.profile == "v2" {
            CncClass::Series16 { kind: 1 }
        } else {
            CncClass::Series30
        },
        ..Ctx::default()
    };
    let mut path: u16 = 1;
    let (mut n, mut bad) = (0, Vec::new());
    for (i, call) in case.calls.iter().enumerate() {
        let args = call.args();
        if call.word() == "setpath" && call.ret == Some(0) {
            path = num(&args[0]).max(1) as u16;
        }
        let mut open: Option<OpenBody> = None;
        let mut data_k = 0;
        for e in &call.frames {
            match &e.ev {
                Ev::Resp(b) if e.ftype() == Some(ftype::OPEN_RESP) => {
                    let (f, _) = Frame::decode(b).unwrap().unwrap();
                    if let Ok(o) = OpenBody::decode(f.version, &f.body) {
                        cx.class = o.class();
                        open = Some(o);
                    }
                }
                Ev::Req(got) => {
                    let want = match e.ftype() {
                        Some(ftype::OPEN_REQ) => Frame::new(
                            CLIENT_VERSION,
                            ftype::OPEN_REQ,
                            (e.conn as u16).to_be_bytes().to_vec(),
                        )
                        .encode(),
                        Some(ftype::CLOSE_REQ) => {
                            Frame::new(CLIENT_VERSION, ftype::CLOSE_REQ, vec![]).encode()
                        }
                        Some(ftype::ID_REQ) => {
                            let id = num(&args[1]) as u32;
                            Frame::new(CLIENT_VERSION, ftype::ID_REQ, id.to_be_bytes().to_vec())
                                .encode()
                        }
                        Some(ftype::DATA_REQ) => {
                            let subs = match call.word() {
                                "alloc" | "alloc4" | "thread_alloc" => {
                                    let o = open
                                        .as_ref()
                                        .expect("open response before start-up requests");
                                    let all = startup_requests(o);
                                    data_k += 1;
                                    match all.get(data_k - 1) {
                                        Some(s) => s.clone(),
                                        None => {
                                            bad.push(format!(
                                                "{id} call {i}: unexpected start-up frame {}",
                                                hex(got)
                                            ));
                                            continue;
                                        }
                                    }
                                }
                                "statinfo" | "thread_statinfo" => {
                                    stamped(&StatInfo::<Status>::new(), &cx, path)
                                }
                                "statinfo2" => stamped(&StatInfo::<Status2>::new(), &cx, path),
                                "rdcncid" => stamped(&rdcncid(), &cx, path),
                                w => {
                                    bad.push(format!("{id} call {i}: no request known for `{w}`"));
                                    continue;
                                }
                            };
                            // The decoder reads back what the encoder wrote.
                            let (f, _) = Frame::decode(got).unwrap().unwrap();
                            match decode_request(&f.body) {
                                Ok(back) if back == subs => {}
                                r => bad.push(format!(
                                    "{id} call {i}: decode_request gives {r:?}, expected {subs:?}"
                                )),
                            }
                            data_frame(&subs)
                        }
                        // --- upload ---
                        Some(ftype::UPLOAD_START_REQ) => {
                            use fwlib32::proto::upload::{StartReq, range_name};
                            let (dtype, s, e) = match call.word() {
                                "upstart" => (0, num(&args[0]), num(&args[0])),
                                _ => (num(&args[0]), num(&args[1]), num(&args[2])),
                            };
                            let req = StartReq {
                                dtype: dtype as i16,
                                path,
                                start: range_name(s as i32, e as i32),
                                end: String::new(),
                            };
                            Frame::new(CLIENT_VERSION, ftype::UPLOAD_START_REQ, req.encode())
                                .encode()
                        }
                        Some(ftype::UPLOAD_END_ACK) => {
                            Frame::new(CLIENT_VERSION, ftype::UPLOAD_END_ACK, vec![]).encode()
                        }
                        Some(ftype::UPLOAD_ABORT) => Frame::new(
                            CLIENT_VERSION,
                            ftype::UPLOAD_ABORT,
                            fwlib32::proto::upload::ABORT_BODY.to_vec(),
                        )
                        .encode(),
                        t => {
                            bad.push(format!(
                                "{id} call {i}: request of unexpected type {t:04x?}"
                            ));
                            continue;
                        }
                    };
                    n += 1;
                    if &want != got {
                        bad.push(format!(
                            "{id} call {i} `{}`: request differs\n    FANUC {}\n    ours  {}",
                            call.probe_cmd,
                            hex(got),
                            hex(&want)
                        ));
                    }
                }
                _ => {}
            }
        }
    }
    (n, bad)
}

#[test]
fn request_frames_equal_fanuc() {
    if !vectors_available() {
        return;
    }
    let (mut frames, mut cases, mut skipped, mut bad) = (0, 0, 0, Vec::new());
    for f in load_vectors() {
        for case in &f.cases {
            if case.calls.iter().any(|c| !KNOWN.contains(&c.word())) {
                skipped += 1;
                continue;
            }
            cases += 1;
            let (n, b) = check_requests(case);
            frames += n;
            bad.extend(b);
        }
    }
    println!(
        "request frames: {frames} checked in {cases} cases ({skipped} cases of functions not implemented yet)"
    );
    assert!(frames > 50, "only {frames} request frames checked");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

// ---------------------------------------------------------------------------
// Response frames of the vectors
// ---------------------------------------------------------------------------

/// True when every subpacket's payload-length word fills its subpacket (the
/// only encoding our encoder produces).
fn canonical_response(body: &[u8]) -> bool {
    let mut at = 2;
    while at + 16 <= body.len() {
        let len = u16::from_be_bytes([body[at], body[at + 1]]) as usize;
        let plen = u16::from_be_bytes([body[at + 14], body[at + 15]]) as usize;
        if plen + 16 != len {
            return false;
        }
        at += len;
    }
    at == body.len()
}

#[test]
fn response_frames_decode_and_reencode() {
    if !vectors_available() {
        return;
    }
    let (mut total, mut data, mut reencoded, mut opens) = (0, 0, 0, 0);
    let mut bad = Vec::new();
    for file in load_vectors() {
        for case in &file.cases {
            for (i, call) in case.calls.iter().enumerate() {
                let id = format!(
                    "{}/{} call {i} `{}`",
                    case.function, case.name, call.probe_cmd
                );
                // What FANUC returned for this call: a frame we reject must have
                // failed in FANUC's library too (-17 malformed, -16 incomplete).
                let rejected = |what: &str, bad: &mut Vec<String>, codes: &[i16]| {
                    if !call.ret.is_some_and(|r| codes.contains(&r)) {
                        bad.push(format!("{id}: {what}, but FANUC returned {:?}", call.ret));
                    }
                };
                for e in &call.frames {
                    let Ev::Resp(b) = &e.ev else { continue };
                    // One write of the fake CNC may carry several frames (upload data).
                    let mut rest: &[u8] = b;
                    while !rest.is_empty() {
                        total += 1;
                        let f = match Frame::decode(rest) {
                            Ok(Some((f, used))) => {
                                if f.encode() != rest[..used] {
                                    bad.push(format!(
                                        "{id}: frame does not re-encode: {}",
                                        hex(&rest[..used])
                                    ));
                                }
                                rest = &rest[used..];
                                f
                            }
                            Ok(None) => {
                                rejected("incomplete frame", &mut bad, &[-16]);
                                break;
                            }
                            Err(err) => {
                                rejected(&format!("frame rejected ({err})"), &mut bad, &[-17]);
                                break;
                            }
                        };
                        match f.ftype >> 8 {
                            0x21 => {
                                data += 1;
                                match decode_response(&f.body) {
                                    Ok(subs) => {
                                        if canonical_response(&f.body) {
                                            reencoded += 1;
                                            if encode_response(&subs) != f.body {
                                                bad.push(format!(
                                                    "{id}: response does not re-encode: {}",
                                                    hex(b)
                                                ));
                                            }
                                        }
                                    }
                                    Err(err) => rejected(
                                        &format!("response rejected ({err})"),
                                        &mut bad,
                                        &[-17],
                                    ),
                                }
                            }
                            0x01 => {
                                opens += 1;
                                match OpenBody::decode(f.version, &f.body) {
                                    Ok(o) => {
                                        if o.to_bytes() != f.body {
                                            bad.push(format!(
                                                "{id}: open body does not re-encode: {}",
                                                hex(b)
                                            ));
                                        }
                                    }
                                    Err(err) => rejected(
                                        &format!("open body rejected ({err})"),
                                        &mut bad,
                                        &[-17],
                                    ),
                                }
                            }
                            _ => {}
                        }
                    }
                }
            }
        }
    }
    println!(
        "response frames: {total} ({data} data frames, {reencoded} canonical ones re-encoded; {opens} open responses)"
    );
    assert!(data > 100 && reencoded > 100 && opens > 20);
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn payload_length_word_bounds_the_payload() {
    // rdcncid garbled_payload_len_4_of_16: 16 bytes present, 4 announced.
    let body = unhex("000100200001000100e80000000000000004000102030405060708090a0b0c0d0e0f");
    let subs = decode_response(&body).unwrap();
    assert_eq!(subs[0].payload, vec![0, 1, 2, 3]);
    assert!(!canonical_response(&body));
    assert_eq!(
        CncId::from_bytes(&subs[0].payload).unwrap(),
        CncId(vec![0x00010203])
    );
}

// ---------------------------------------------------------------------------
// Property tests
// ---------------------------------------------------------------------------

fn req_sub() -> impl Strategy<Value = ReqSub> {
    (
        any::<u16>(),
        any::<u16>(),
        any::<u16>(),
        any::<[i32; 5]>(),
        vec(any::<u8>(), 0..48),
    )
        .prop_map(|(class, path, cmd, args, payload)| ReqSub {
            class,
            path,
            cmd,
            args,
            payload,
        })
}

fn resp_sub() -> impl Strategy<Value = RespSub> {
    (
        (any::<u16>(), any::<u16>(), any::<u16>()),
        (any::<i16>(), any::<u16>(), any::<u16>()),
        vec(any::<u8>(), 0..48),
    )
        .prop_map(
            |((class, path, cmd), (error, detail1, detail2), payload)| RespSub {
                class,
                path,
                cmd,
                error,
                detail1,
                detail2,
                payload,
            },
        )
}

fn open_body() -> impl Strategy<Value = (u16, OpenBody)> {
    let v3 = (
        3u16..=6,
        prop::array::uniform20(any::<u16>()),
        vec(prop::array::uniform16(any::<u16>()), 0..4),
    )
        .prop_map(|(v, mut header, paths)| {
            header[5] = paths.len() as u16;
            (v, OpenBody::Series30 { header, paths })
        });
    let v2 = (
        0u16..=2,
        prop::array::uniform8(any::<u16>()),
        vec(prop::array::uniform4(any::<u16>()), 0..4),
    )
        .prop_map(|(v, mut header, paths)| {
            header[4] = paths.len() as u16;
            (v, OpenBody::Series16 { header, paths })
        });
    prop_oneof![v3, v2]
}

fn sysinfo() -> impl Strategy<Value = SysInfo> {
    (
        (any::<u16>(), any::<u16>()),
        (any::<[u8; 2]>(), any::<[u8; 2]>()),
        (any::<[u8; 4]>(), any::<[u8; 4]>(), any::<[u8; 2]>()),
    )
        .prop_map(
            |((addinfo, max_axis), (cnc_type, mt_type), (series, version, axes))| SysInfo {
                addinfo,
                max_axis,
                cnc_type,
                mt_type,
                series,
                version,
                axes,
            },
        )
}

fn status() -> impl Strategy<Value = Status> {
    any::<[i16; 7]>().prop_map(|w| Status {
        aut: w[0],
        run: w[1],
        motion: w[2],
        mstb: w[3],
        emergency: w[4],
        alarm: w[5],
        edit: w[6],
    })
}

fn status2() -> impl Strategy<Value = Status2> {
    any::<[i16; 11]>().prop_map(|w| Status2 {
        aut: w[0],
        run: w[1],
        motion: w[2],
        mstb: w[3],
        emergency: w[4],
        alarm: w[5],
        edit: w[6],
        warning: w[7],
        o3dchk: w[8],
        ext_opt: w[9],
        restart: w[10],
    })
}

fn param16() -> impl Strategy<Value = Param16> {
    (
        any::<i32>(),
        any::<i16>(),
        any::<u16>(),
        vec(any::<i32>(), 0..=8),
    )
        .prop_map(|(number, axis, ptype, values)| Param16 {
            number,
            axis,
            ptype,
            values,
        })
}

/// Bodies of counted subpacket lists whose length words may or may not fit.
fn list_body() -> impl Strategy<Value = Vec<u8>> {
    (0u16..5, vec((0u16..80, vec(any::<u8>(), 0..80)), 0..5)).prop_map(|(count, subs)| {
        let mut w = Writer::new();
        w.u16(count);
        for (len, bytes) in subs {
            w.u16(len);
            w.bytes(&bytes);
        }
        w.into_vec()
    })
}

fn roundtrip<T: Wire + PartialEq + std::fmt::Debug>(x: &T) -> Result<(), TestCaseError> {
    let b = x.to_bytes();
    prop_assert_eq!(&T::from_bytes(&b)?, x);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        // No regression files next to the sources of an integration test.
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn frame_roundtrip(version in any::<u16>(), ft in any::<u16>(), mut body in vec(any::<u8>(), 0..600)) {
        body.truncate(max_body_len(version));
        let f = Frame::new(version, ft, body);
        let b = f.encode();
        prop_assert_eq!(b.len(), HEADER_LEN + f.body.len());
        prop_assert_eq!(Frame::decode(&b), Ok(Some((f.clone(), b.len()))));
        // Any proper prefix is incomplete, never an error.
        let cut = b.len() / 2;
        prop_assert_eq!(Frame::decode(&b[..cut]), Ok(None));
    }

    #[test]
    fn frame_header_roundtrip(version in any::<u16>(), ft in any::<u16>(), len in any::<u16>()) {
        let h = FrameHeader { version, ftype: ft, len };
        let mut w = Writer::new();
        h.encode(&mut w);
        let b = w.into_vec();
        prop_assert_eq!(b.len(), HEADER_LEN);
        prop_assert_eq!(&b[..4], &MAGIC);
        if (len as usize) <= max_body_len(version) {
            prop_assert_eq!(FrameHeader::decode(&b), Ok(h));
        } else {
            let is_oversize = matches!(FrameHeader::decode(&b), Err(DecodeError::Oversize { .. }));
            prop_assert!(is_oversize);
        }
    }

    #[test]
    fn request_list_roundtrip(subs in vec(req_sub(), 1..5)) {
        prop_assert_eq!(decode_request(&encode_request(&subs)), Ok(subs));
    }

    #[test]
    fn response_list_roundtrip(subs in vec(resp_sub(), 1..5)) {
        let body = encode_response(&subs);
        prop_assert!(canonical_response(&body));
        prop_assert_eq!(decode_response(&body), Ok(subs));
    }

    #[test]
    fn open_body_roundtrip((version, o) in open_body()) {
        let b = o.to_bytes();
        prop_assert_eq!(OpenBody::decode(version, &b), Ok(o.clone()));
        // One byte more or less is a wrong size.
        prop_assert!(OpenBody::decode(version, &b[..b.len() - 1]).is_err());
        let mut longer = b.clone();
        longer.push(0);
        prop_assert!(OpenBody::decode(version, &longer).is_err());
    }

    #[test]
    fn wire_structs_roundtrip(
        s in sysinfo(),
        st in status(),
        st2 in status2(),
        w in any::<i16>(),
        id in vec(any::<u32>(), 0..=4),
        p in param16(),
    ) {
        roundtrip(&s)?;
        prop_assert_eq!(s.to_bytes().len(), 18);
        roundtrip(&st)?;
        prop_assert_eq!(st.to_bytes().len(), 14);
        roundtrip(&st2)?;
        prop_assert_eq!(st2.to_bytes().len(), 22);
        roundtrip(&Word { value: w })?;
        roundtrip(&CncId(id))?;
        roundtrip(&p)?;
    }

    #[test]
    fn decoders_never_panic(b in vec(any::<u8>(), 0..700), version in 0u16..=6) {
        let _ = Frame::decode(&b);
        let _ = FrameHeader::decode(&b);
        let _ = decode_request(&b);
        let _ = decode_response(&b);
        let _ = OpenBody::decode(version, &b);
        let _ = SysInfo::from_bytes(&b);
        let _ = Status::from_bytes(&b);
        let _ = Status2::from_bytes(&b);
        let _ = Word::from_bytes(&b);
        let _ = CncId::from_bytes(&b);
        let _ = Param16::from_bytes(&b);
        let _ = Vec::<u32>::from_bytes(&b);
    }

    #[test]
    fn framing_decoders_never_panic_past_the_magic(version in any::<u16>(), ft in any::<u16>(), len in any::<u16>(), rest in vec(any::<u8>(), 0..400)) {
        let mut b = MAGIC.to_vec();
        b.extend_from_slice(&version.to_be_bytes());
        b.extend_from_slice(&ft.to_be_bytes());
        b.extend_from_slice(&len.to_be_bytes());
        b.extend_from_slice(&rest);
        match Frame::decode(&b) {
            Ok(Some((f, used))) => {
                prop_assert_eq!(used, HEADER_LEN + len as usize);
                prop_assert_eq!(f.body.len(), len as usize);
            }
            Ok(None) => prop_assert!(rest.len() < len as usize),
            Err(e) => {
                let oversize = matches!(e, DecodeError::Oversize { .. });
                prop_assert!(oversize, "{:?}", e);
            }
        }
    }

    #[test]
    fn list_decoders_never_panic(body in list_body(), version in 0u16..=6) {
        if let Ok(subs) = decode_response(&body) {
            if canonical_response(&body) {
                prop_assert_eq!(encode_response(&subs), body.clone());
            }
        }
        if let Ok(subs) = decode_request(&body) {
            prop_assert_eq!(encode_request(&subs), body.clone());
        }
        let _ = OpenBody::decode(version, &body);
    }
}

// --- upload ---

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn upload_start_body_roundtrip(
        dtype in any::<i16>(),
        path in any::<u16>(),
        start in "[ -~]{0,255}",
        end in "[ -~]{0,255}",
    ) {
        use fwlib32::proto::upload::{START_BODY_LEN, StartReq};
        let r = StartReq { dtype, path, start, end };
        let b = r.encode();
        prop_assert_eq!(b.len(), START_BODY_LEN);
        prop_assert_eq!(StartReq::decode(&b), r);
    }

    #[test]
    fn upload_error_body_roundtrip(code in any::<i16>(), d1 in any::<u16>(), d2 in any::<u16>()) {
        use fwlib32::proto::upload::{decode_error, error_body};
        prop_assert_eq!(decode_error(&error_body(code, d1, d2)), (code, d1, d2));
    }

    #[test]
    fn upload_decoders_never_panic(b in vec(any::<u8>(), 0..700)) {
        let r = fwlib32::proto::upload::StartReq::decode(&b);
        let _ = r.range();
        let _ = fwlib32::proto::upload::decode_error(&b);
    }
}
