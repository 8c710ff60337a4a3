//! Sans-IO codec tests, no sockets:
//!
//! * every request frame FANUC's library sent in the golden vectors (for the
//!   functions we implement) equals what our codec encodes for that call;
//! * every response frame in the vectors decodes, and re-encodes to the same
//!   bytes where its encoding is canonical; what we reject, FANUC rejected too;
//! * property tests: decode(encode(x)) == x for frames and every wire
//!   structure, and no decoder panics on arbitrary bytes.

use crate::common;

use common::*;
use fwlib32::proto::call::{Call, Ctx};
use fwlib32::proto::described::Described;
use fwlib32::proto::frame::{
    CLIENT_VERSION, Frame, FrameHeader, HEADER_LEN, MAGIC, ftype, max_body_len,
};
use fwlib32::proto::open::{CncClass, OpenBody};
use fwlib32::proto::packet::{
    ReqSub, RespSub, decode_request, decode_response, encode_request, encode_response,
};
use fwlib32::proto::param::{
    Param16, ParamInfo, ReadExt, ReadInfo, Table, WriteParam, ext_per_frame,
};
// --- program ---
use fwlib32::proto::alarm::{self as pa, AlmMsg, OpMsg};
use fwlib32::proto::position::{AlarmBits, ProgNums, SeqNum};
use fwlib32::proto::program::{
    self as pp, ActPt, AuxCode, AuxModal, Clock, ExecProg, GCode, GModal, NTool, PathName, Timer,
    ToolNum,
};
use fwlib32::proto::status::{StatInfo, Status, Status2, SysInfo, Word, sysinfo_at_connect};
use fwlib32::proto::wire::{DecodeError, Wire, Writer};
use fwlib32::proto::{OPTION_PARAM_15, OPTION_PARAM_16, cmd};
// --- macros ---
use fwlib32::proto::macros::{ReadMacros, WriteMacros};
use fwlib32::proto::value::Value;
// --- pmc ---
use fwlib32::proto::pmc::{PmcRange, ReadPmc, WritePmc, swap_elements};
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

/// Probe words whose requests we can build: every word the vectors use
/// (`request_frames_equal_fanuc` fails on a word missing here).
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
    "rdaxisname",
    "rdspdlname",
    "rddynamic2",
    "rddynamic",
    "actf",
    "acts",
    "acts2",
    "rdspmeter",
    "rdsvmeter",
    "rdaxisdata",
    "rdposition",
    "absolute",
    "absolute2",
    "machine",
    "relative",
    "relative2",
    "distance",
    "getfigure",
    // --- program ---
    "rdprgnum",
    "rdseqnum",
    "rdblkcount",
    "rdactpt",
    "exeprgname",
    "exeprgname2",
    "rdexecprog",
    "modal",
    "rdtimer",
    "gettimer",
    "toolnum",
    "rdntool",
    // --- alarm ---
    "rdalmmsg",
    "rdalmmsg2",
    "alarm",
    "alarm2",
    "rdopmsg",
    // --- param ---
    "rdparam",
    "diagnoss",
    "wrparam",
    "rdparainfo",
    "rddiaginfo",
    "rdparam_ext",
    "rdparam_ext32",
    "rdprogdir",
    "rdprogdir3",
    // --- macros ---
    "rdmacro",
    "wrmacro",
    "rdmacror",
    // --- pmc ---
    "pmc_rdpmcrng",
    "pmc_wrpmcrng",
    "pmc_getdtailerr",
    // --- offset ---
    "rdtofs",
    "rdzofs",
    "rdalmhistry",
    "rdalmhistry2",
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

/// The open answer a case that records no connect of its own was made
/// with: the recorded cnc_allclibhndl3 case of its class.
fn handshake_open(files: &[VectorFile], case: &Case) -> Option<OpenBody> {
    let name = match case.profile.as_str() {
        "v2" => "v2_kind1",
        "v3" => "v3_one_path",
        _ => return None,
    };
    let c = files
        .iter()
        .filter(|f| f.function == "cnc_allclibhndl3")
        .flat_map(|f| &f.cases)
        .find(|c| c.name == name)?;
    c.calls
        .iter()
        .flat_map(|c| &c.frames)
        .find_map(|e| match &e.ev {
            Ev::Resp(b) if e.ftype() == Some(ftype::OPEN_RESP) => {
                let (f, _) = Frame::decode(b).ok()??;
                OpenBody::decode(f.version, &f.body).ok()
            }
            _ => None,
        })
}

/// Checks one case's request frames; (frames checked, mismatches).
fn check_requests(case: &Case, handshake: Option<&OpenBody>) -> (usize, Vec<String>) {
    let id = format!("{}/{}", case.function, case.name);
    let mut cx = Ctx {
        class: if case.profile == "v2" {
            CncClass::Series16 { kind: 1 }
        } else {
            CncClass::Series30
        },
        ..Ctx::default()
    };
    if let Some(o) = handshake {
        cx.class = o.class();
        cx.max_axes = o.max_axes(1);
        cx.max_spindles = o.max_spindles();
    }
    let mut path: u16 = 1;
    let (mut n, mut bad) = (0, Vec::new());
    for (i, call) in case.calls.iter().enumerate() {
        let args = call.args();
        if call.word() == "setpath" && call.ret == Some(0) {
            path = num(&args[0]).max(1) as u16;
        }
        let mut open: Option<OpenBody> = None;
        let mut data_k = 0;
        // This call's data requests so far, and the last data response.
        let mut req_k = 0;
        let mut last_resp: Option<Vec<RespSub>> = None;
        for e in &call.frames {
            match &e.ev {
                Ev::Resp(b) if e.ftype() == Some(ftype::OPEN_RESP) => {
                    let (f, _) = Frame::decode(b).unwrap().unwrap();
                    if let Ok(o) = OpenBody::decode(f.version, &f.body) {
                        cx.class = o.class();
                        cx.max_axes = o.max_axes(path as usize);
                        cx.max_spindles = o.max_spindles();
                        open = Some(o);
                    }
                }
                Ev::Resp(b) if e.ftype() == Some(ftype::DATA_RESP) => {
                    // (Garbled recordings have frames that do not decode.)
                    last_resp = match Frame::decode(b) {
                        Ok(Some((f, _))) => decode_response(&f.body).ok(),
                        _ => None,
                    };
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
                            req_k += 1;
                            let first = req_k == 1;
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
                                // --- macros ---
                                "rdmacro" => {
                                    let n = num(&args[0]) as i32;
                                    stamped(&ReadMacros { s: n, e: n }, &cx, path)
                                }
                                "rdmacror" => {
                                    let (s, e) = (num(&args[0]) as i32, num(&args[1]) as i32);
                                    stamped(&ReadMacros { s, e }, &cx, path)
                                }
                                "wrmacro" => {
                                    let w = WriteMacros {
                                        s: num(&args[0]) as i32,
                                        values: vec![(num(&args[2]) as i32, num(&args[3]) as i16)],
                                    };
                                    stamped(&w, &cx, path)
                                }
                                // --- pmc ---
                                "pmc_rdpmcrng" => {
                                    let r = PmcRange {
                                        adr_type: num(&args[0]) as i16,
                                        data_type: num(&args[1]) as i16,
                                        s: num(&args[2]) as u16,
                                        e: num(&args[3]) as u16,
                                    };
                                    stamped(&ReadPmc(r), &cx, path)
                                }
                                "pmc_wrpmcrng" => {
                                    let b = unhex(args[1].strip_prefix("hex:").unwrap());
                                    let w16 = |i: usize| i16::from_le_bytes([b[i], b[i + 1]]);
                                    let range = PmcRange {
                                        adr_type: w16(0),
                                        data_type: w16(2),
                                        s: w16(4) as u16,
                                        e: w16(6) as u16,
                                    };
                                    let mut data = b[8..8 + range.span()].to_vec();
                                    swap_elements(range.data_type, &mut data);
                                    stamped(&WritePmc { range, data }, &cx, path)
                                }
                                // --- described as data (src/spec) ---
                                // (cnc_wrparam: two exchanges, the attribute read first, below.)
                                w if described(w).is_some() && w != "wrparam" => {
                                    let f = described(w).unwrap();
                                    let nums = c_args(f, &args);
                                    stamped(&Described::new(f, &nums), &cx, path)
                                }
                                // --- offset ---
                                "rdtofs" | "rdzofs" | "rdalmhistry" | "rdalmhistry2" => {
                                    offset_request(call.word(), &args, &cx, path)
                                }
                                w if position_request(w, &args).is_some() => {
                                    stamped(&Raw(position_request(w, &args).unwrap()), &cx, path)
                                }
                                // --- program ---
                                "rdexecprog" => {
                                    stamped(&pp::rdexecprog(num(&args[0]) as u16), &cx, path)
                                }
                                "modal" => {
                                    let kind = pp::modal_kind(num(&args[0]) as i16).unwrap();
                                    let block = num(&args[1]) as i16;
                                    stamped(&pp::ModalCall { kind, block }, &cx, path)
                                }
                                "gettimer" => {
                                    stamped(&pp::gettimer(num(&args[0]) as i16), &cx, path)
                                }
                                // --- alarm ---
                                "rdalmmsg" => stamped(
                                    &pa::rdalmmsg::<32>(num(&args[0]) as i16, num(&args[1]) as i16),
                                    &cx,
                                    path,
                                ),
                                "rdalmmsg2" => stamped(
                                    &pa::rdalmmsg::<64>(num(&args[0]) as i16, num(&args[1]) as i16),
                                    &cx,
                                    path,
                                ),
                                "rdopmsg" => stamped(&pa::rdopmsg(num(&args[0]) as i16), &cx, path),
                                // --- param ---
                                w @ ("rdparainfo" | "rddiaginfo") if first => {
                                    let r = ReadInfo {
                                        table: if w == "rdparainfo" {
                                            Table::Param
                                        } else {
                                            Table::Diag
                                        },
                                        start: num(&args[0]) as i16 as i32,
                                        count: num(&args[1]) as u16 as i32,
                                    };
                                    stamped(&r, &cx, path)
                                }
                                w @ ("rdparam_ext" | "rdparam_ext32") => {
                                    // FANUC's library reads the number array as
                                    // packed 32-bit ints: an LP64 long[] gives
                                    // {n0, 0, n1, 0, ...}.
                                    let n = num(&args[0]) as usize;
                                    let given: Vec<i32> =
                                        args[1..].iter().map(|a| num(a) as i32).collect();
                                    let numbers: Vec<i32> = if w == "rdparam_ext" {
                                        given.iter().flat_map(|v| [*v, 0]).take(n).collect()
                                    } else {
                                        given.into_iter().take(n).collect()
                                    };
                                    let chunk = numbers
                                        .chunks(ext_per_frame(&cx))
                                        .nth(req_k - 1)
                                        .unwrap_or(&[])
                                        .to_vec();
                                    stamped(
                                        &ReadExt {
                                            table: Table::Param,
                                            numbers: chunk,
                                        },
                                        &cx,
                                        path,
                                    )
                                }
                                "wrparam" => {
                                    let raw = unhex(args[1].strip_prefix("hex:").unwrap());
                                    let number = i16::from_le_bytes([raw[0], raw[1]]) as i32;
                                    if first {
                                        stamped(&ParamInfo { number }, &cx, path)
                                    } else {
                                        let info = last_resp
                                            .as_ref()
                                            .and_then(|r| ParamInfo { number }.decode(&cx, r).ok())
                                            .expect("the attribute answer before the write");
                                        let mut raw = raw.clone();
                                        raw.resize(260, 0);
                                        let w = WriteParam {
                                            number,
                                            axis: i16::from_le_bytes([raw[2], raw[3]]),
                                            ptype: info.ptype,
                                            values: info
                                                .elem
                                                .map(|e| e.get(&raw[4..]))
                                                .into_iter()
                                                .collect(),
                                        };
                                        stamped(&w, &cx, path)
                                    }
                                }
                                // --- program directory (first exchange) ---
                                "rdprogdir" if first => stamped(
                                    &pp::progdir(
                                        num(&args[1]) as i16 as i32,
                                        pp::PROGDIR_CHUNK,
                                        num(&args[0]) as i32,
                                    ),
                                    &cx,
                                    path,
                                ),
                                "rdprogdir3" if first => {
                                    let code = pp::progdir3_code(num(&args[0]) as i16).unwrap();
                                    let ask = (num(&args[2]) as i32).min(pp::PROGDIR_CHUNK);
                                    stamped(
                                        &pp::progdir(num(&args[1]) as i32, ask, code),
                                        &cx,
                                        path,
                                    )
                                }
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
                                end: Vec::new(),
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
    let (mut frames, mut cases, mut bad) = (0, 0, Vec::new());
    let files = load_vectors();
    for f in &files {
        for case in &f.cases {
            if let Some(c) = case.calls.iter().find(|c| !KNOWN.contains(&c.word())) {
                bad.push(format!(
                    "{}/{}: no request builder for the probe word `{}` (add it to KNOWN)",
                    case.function,
                    case.name,
                    c.word()
                ));
                continue;
            }
            cases += 1;
            let (n, b) = check_requests(case, handshake_open(&files, case).as_ref());
            frames += n;
            bad.extend(b);
        }
    }
    println!("request frames: {frames} checked in {cases} cases");
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
    let f = described("rdcncid").unwrap();
    assert_eq!(
        fwlib32::proto::described::decode(f, &[], &subs[0].payload).unwrap(),
        vec![0x00010203]
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
        p in param16(),
    ) {
        roundtrip(&s)?;
        prop_assert_eq!(s.to_bytes().len(), 18);
        roundtrip(&st)?;
        prop_assert_eq!(st.to_bytes().len(), 14);
        roundtrip(&st2)?;
        prop_assert_eq!(st2.to_bytes().len(), 22);
        roundtrip(&Word { value: w })?;
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
        if let Ok(subs) = decode_response(&body)
            && canonical_response(&body) {
                prop_assert_eq!(encode_response(&subs), body.clone());
            }
        if let Ok(subs) = decode_request(&body) {
            prop_assert_eq!(encode_request(&subs), body.clone());
        }
        let _ = OpenBody::decode(version, &body);
    }
}

// --- param ---

mod param_codec {
    use super::roundtrip;
    use fwlib32::proto::open::CncClass;
    use fwlib32::proto::param::*;
    use fwlib32::proto::value::Value;
    use fwlib32::proto::wire::Wire;
    use proptest::collection::vec;
    use proptest::prelude::*;

    fn value() -> impl Strategy<Value = Value> {
        (any::<i32>(), any::<u16>(), any::<i16>()).prop_map(|(value, base, exp)| Value {
            value,
            base,
            exp,
        })
    }

    fn elem() -> impl Strategy<Value = Elem> {
        prop_oneof![
            Just(Elem::Byte),
            Just(Elem::Word),
            Just(Elem::Long),
            Just(Elem::Real)
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

        #[test]
        fn param_payloads_roundtrip(
            number in any::<i32>(), axis in any::<i16>(), ptype in any::<u16>(),
            v30 in vec(value(), 0..33), v16 in vec(any::<i32>(), 0..9),
            t in (any::<i32>(), any::<i32>(), any::<i32>(), vec(any::<u16>(), 8)),
            info in (any::<i32>(), any::<i32>(), vec((any::<i32>(), any::<i32>()), 0..12)),
            range in (any::<i32>(), any::<i32>(), any::<i32>()),
        ) {
            roundtrip(&Param30 { number, axis, ptype, values: v30 })?;
            roundtrip(&Param16 { number, axis, ptype, values: v16 })?;
            let w = &t.3;
            let pt = ParamType30 {
                w0: t.0, w4: t.1, number: t.2, ptype: w[0], axis: w[1], unit_lo: w[2],
                unit_hi: w[3], kind: w[4], w22: w[5], flags: w[6], w26: w[7],
            };
            roundtrip(&pt)?;
            prop_assert_eq!(pt.to_bytes().len(), PARAMTYPE_LEN);
            let entries = info.2.iter().map(|(number, ptype)| InfoEntry { number: *number, ptype: *ptype }).collect();
            roundtrip(&InfoList { prev: info.0, next: info.1, entries })?;
            roundtrip(&NumRange { min: range.0, max: range.1, total: range.2 })?;
        }

        /// The C-side codec: get is put reversed, for every element kind.
        #[test]
        fn elem_get_is_put_reversed(e in elem(), value in any::<i32>(), dec in any::<i32>(), bytes in vec(any::<u8>(), 8)) {
            // bytes → value → bytes is the identity on the element's bytes.
            let n = e.get(&bytes);
            let mut out = vec![0u8; 8];
            e.put(&mut out, n);
            prop_assert_eq!(&out[..e.size()], &bytes[..e.size()]);
            // value → bytes → value is the identity for values of the element's range.
            let v = match e {
                Elem::Byte => Num::int(value as i8 as i32),
                Elem::Word => Num::int(value as i16 as i32),
                Elem::Long => Num::int(value),
                Elem::Real => Num { value, dec },
            };
            e.put(&mut out, v);
            prop_assert_eq!(e.get(&out), v);
        }

        /// A write payload decodes (as the simulator reads it) to what was written.
        #[test]
        fn write_payload_reads_back(number in any::<i16>(), axis in -1i16..=32, ptype in 0u16..=4,
                                    values in vec((any::<i32>(), -9i32..=9), 1..=8)) {
            let nums: Vec<Num> = values.iter().map(|(v, d)| Num { value: *v, dec: if ptype == 4 { *d } else { 0 } }).collect();
            let w = WriteParam { number: number as i32, axis, ptype, values: nums.clone() };
            let p = Param30::from_bytes(&w.payload(CncClass::Series30, WRITE_RECORDS_30))?;
            prop_assert_eq!((p.number, p.axis, p.ptype, p.values.len()), (number as i32, axis, ptype, WRITE_RECORDS_30));
            let back: Vec<Num> = p.values[..nums.len()].iter().map(|v| num_of_value(*v, ptype == 4)).collect();
            prop_assert_eq!(back, nums.clone());
            if ptype != 4 {
                let p = Param16::from_bytes(&w.payload(CncClass::Series16 { kind: 1 }, 8))?;
                prop_assert_eq!(p.values.len(), 8);
                prop_assert_eq!(&p.values[..nums.len()], &nums.iter().map(|n| n.value).collect::<Vec<_>>()[..]);
            }
        }

        /// cnc_rdparar / cnc_wrparas records: the C bytes read back
        /// (`from_c` is `to_c` reversed), and the write block of a record
        /// decodes, as a read answer block, to the same record.
        #[test]
        fn packed_records_roundtrip(number in any::<i16>(), axis in -1i8..=32, ptype in 0u8..=4,
                                    values in vec((any::<i32>(), any::<i16>()), 32), axes in 1usize..=32,
                                    tail in vec(any::<u8>(), 0..12)) {
            let n = Packed::count(axis, axes);
            let nums: Vec<Num> = values[..n].iter().map(|(v, d)| match ptype {
                0 | 1 => Num::int(*v as i8 as i32),
                2 => Num::int(*v as i16 as i32),
                3 => Num::int(*v),
                _ => Num { value: *v, dec: *d as i32 },
            }).collect();
            let r = Packed { number, axis, ptype, values: nums };
            let c = r.to_c();
            prop_assert_eq!(c.len(), 4 + n * [1, 1, 2, 4, 8][ptype as usize]);
            prop_assert_eq!(r.padded_len() % 4, 0);
            let mut buf = c.clone();
            buf.resize(r.padded_len(), 0);
            buf.extend(&tail);
            let (back, used) = Packed::from_c(&buf, axes)?;
            prop_assert_eq!(&back, &r);
            prop_assert_eq!(used, r.padded_len());
            // Every shorter input is EW_LENGTH, never a panic.
            for k in 0..c.len() {
                prop_assert!(Packed::from_c(&c[..k], axes).is_err());
            }
            let block = Param30::from_bytes(&r.to_block(CncClass::Series30, WRITE_RECORDS_30))?;
            prop_assert_eq!(block.values.len(), WRITE_RECORDS_30);
            prop_assert_eq!(&Packed::of_block(&block, axes)?, &r);
            // The 16i word block: 8 + 4 · max-axes bytes (a real for all
            // axes needs two words a value: more than one block holds).
            let block16 = r.to_block(CncClass::Series16 { kind: 1 }, WRITE_RECORDS_30);
            prop_assert_eq!(block16.len(), 8 + 4 * WRITE_RECORDS_30);
            if ptype != 4 || 2 * n <= WRITE_RECORDS_30 {
                prop_assert_eq!(Packed::of_block16(&block16, axes)?, r);
            }
        }

        #[test]
        fn param_decoders_never_panic(b in vec(any::<u8>(), 0..400)) {
            let _ = Packed::from_c(&b, 32);
            let _ = Param30::from_bytes(&b);
            let _ = ParamType30::from_bytes(&b);
            let _ = InfoList::from_bytes(&b);
            let _ = NumRange::from_bytes(&b);
        }
    }
}

// --- macros ---

/// A client call answered by the simulator's dispatch, sans-IO.
fn serve<C: Call>(m: &mut fwlib32::sim::Machine, c: &C) -> fwlib32::error::Result<C::Output> {
    let cx = Ctx::default();
    let resp: Vec<RespSub> = stamped(c, &cx, 1)
        .iter()
        .map(|s| fwlib32::sim::service::CncService::answer(m, s))
        .collect();
    c.decode(&cx, &resp)
}

fn machine() -> fwlib32::sim::Machine {
    fwlib32::sim::Machine::new(fwlib32::sim::Profile::default())
}

proptest! {
    #[test]
    fn value_records_roundtrip(value in any::<i32>(), base in any::<u16>(), exp in any::<i16>()) {
        let v = Value { value, base, exp };
        roundtrip(&v)?;
        prop_assert_eq!(v.to_bytes().len(), 8);
        if base == 10 {
            prop_assert_eq!(v.to_decimal(), (value, exp));
        }
    }

    /// A binary record converts to the same number in decimal: 9 significant
    /// digits, computed as FANUC's library computes them in its own 32-bit
    /// float (its truncated 10^-9 may take a unit or two off the 9th digit).
    #[test]
    fn base2_records_keep_their_value(value in any::<i32>(), exp in -40i16..40) {
        let (m, d) = Value { value, base: 2, exp }.to_decimal();
        let want = f64::from(value) / 2f64.powi(i32::from(exp));
        let got = f64::from(m) / 10f64.powi(i32::from(d));
        // At most 2 units of the 9th digit (a mantissa from 10^8): the
        // truncated 10^-9 steps (7e-9 is the worst of 200,000 drawn).
        let digit = 2.01e-8;
        prop_assert!((want - got).abs() <= 0.51e-9 + want.abs() * digit, "{} {} {}", want, m, d);
        if value != 0 {
            prop_assert!((100_000_000..1_000_000_000).contains(&m.unsigned_abs()), "{}", m);
        }
    }

    /// The oracle's recorded conversions (findings cnc_rdmacro_base2).
    #[test]
    fn base2_records_as_fanuc(_x in 0..1) {
        for ((v, b, e), want) in [
            ((5, 2, 1), (250000000, 8)),
            ((5, 2, 0), (500000000, 8)),
            ((5, 2, -1), (100000000, 7)),
            ((1, 2, 2), (250000000, 9)),
            ((-7, 2, 3), (-875000000, 9)),
            ((5, 0, 3), (625000000, 9)),
            ((5, 16, 1), (250000000, 8)),
            ((0, 2, 5), (0, 5)),
            ((1, 2, 10), (976563000, 12)),
            ((1, 2, 20), (954000000, 15)),
            ((1, 2, 24), (600000000, 16)),
            ((1, 2, 28), (400000000, 17)),
            ((3, 2, 31), (100000000, 17)),
            ((1, 2, 30), (931322575, 18)),
            ((12345, 2, 20), (117731090, 10)),
            ((1000001, 2, 1), (500000500, 3)),
            ((999999999, 2, 1), (500000000, 0)),
            ((1234567891, 2, 0), (123456789, -1)),
            ((3, 2, -29), (161061274, -1)),
            ((1, 2, -31), (214748365, -1)),
            ((3, 2, -40), (329853488, -4)),
            ((2000000000, 2, -1), (400000000, -1)),
            ((-1, 0, -1), (-200000000, 8)),
            ((5, 10, -1), (5, -1)),
        ] {
            prop_assert_eq!(Value { value: v, base: b, exp: e }.to_decimal(), want, "{:?}", (v, b, e));
        }
    }

    /// What cnc_wrmacro encodes, the simulator stores and cnc_rdmacror decodes.
    #[test]
    fn macros_write_then_read(s in 100i32..195, vals in vec((any::<i32>(), 0i16..=9), 1..5)) {
        let mut m = machine();
        let w = WriteMacros { s, values: vals.clone() };
        prop_assert_eq!(w.request(&Ctx::default()).len(), 1, "a write is one subpacket");
        serve(&mut m, &w).unwrap();
        let back = serve(&mut m, &ReadMacros { s, e: w.e() }).unwrap();
        let got: Vec<(i32, i16)> = back.iter().map(Value::to_decimal).collect();
        prop_assert_eq!(got, vals);
    }

    #[test]
    fn macro_decoders_never_panic(b in vec(any::<u8>(), 0..100)) {
        let _ = Value::from_bytes(&b);
        let _ = Vec::<Value>::from_bytes(&b);
    }
}

// --- pmc ---

proptest! {
    /// Element swapping is its own inverse (reads and writes share it).
    #[test]
    fn pmc_swap_is_an_involution(t in prop_oneof![Just(0i16), Just(1), Just(2), Just(4), Just(5)], b in vec(any::<u8>(), 0..64)) {
        let mut x = b.clone();
        swap_elements(t, &mut x);
        swap_elements(t, &mut x);
        prop_assert_eq!(x, b);
    }

    /// What pmc_wrpmcrng encodes, the simulator stores and pmc_rdpmcrng
    /// decodes; the same bytes read back as bytes.
    #[test]
    fn pmc_write_then_read(words in vec(any::<u16>(), 1..20), s in 0u16..1000) {
        let mut m = machine();
        let s = s * 2;
        let range = PmcRange { adr_type: 5, data_type: 1, s, e: s + 2 * words.len() as u16 - 1 };
        let data: Vec<u8> = words.iter().flat_map(|w| w.to_be_bytes()).collect();
        let w = WritePmc { range, data: data.clone() };
        prop_assert_eq!(w.request(&Ctx::default()).len(), 1, "a write is one subpacket");
        serve(&mut m, &w).unwrap();
        prop_assert_eq!(serve(&mut m, &ReadPmc(range)).unwrap(), data.clone());
        let bytes = PmcRange { data_type: 0, ..range };
        prop_assert_eq!(serve(&mut m, &ReadPmc(bytes)).unwrap(), data);
    }
}

// ---------------------------------------------------------------------------
// --- position ---
// ---------------------------------------------------------------------------

/// Already-built subpackets as a call (request side only).
struct Raw(Vec<ReqSub>);

impl Call for Raw {
    type Output = ();
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        self.0.clone()
    }
    fn decode(&self, _: &Ctx, _: &[RespSub]) -> fwlib32::error::Result<()> {
        Ok(())
    }
}

/// A described function's number arguments as its C parameters pass them
/// (a `short` cut to 16 bits, then as `Param::ShortAs` converts it).
fn c_args(f: &fwlib32::spec::Func, args: &[String]) -> Vec<i32> {
    let numbers = f.params.iter().filter_map(|p| p.conv(0).map(|_| p));
    args.iter()
        .zip(numbers)
        .filter_map(|(a, p)| p.conv(num(a)))
        .collect()
}

/// The described function (src/spec) of a probe word.
fn described(word: &str) -> Option<&'static fwlib32::spec::Func> {
    fwlib32::spec::FUNCS.iter().find(|f| f.word() == word)
}

/// The request of a position-area probe word, as src/ffi/position.rs builds it.
fn position_request(w: &str, a: &[String]) -> Option<Vec<ReqSub>> {
    use fwlib32::proto::position::*;
    let n = |i: usize| num(&a[i]);
    let cx = Ctx::default();
    let axes = |codes: Vec<i32>| AxisDataCall {
        what: AxisData::Positions(codes),
        limit: 8,
    };
    Some(match w {
        "rddynamic2" | "rddynamic" => Dynamic { axis: n(0) as i16 }.request(&cx),
        "acts2" => SpindleData {
            code: spdl::SPEED_ACT,
            sp_no: n(0) as i16,
        }
        .request(&cx),
        "rdspmeter" => {
            let codes = match n(0) {
                0 => vec![spdl::LOAD_METER],
                1 => vec![spdl::SPEED_METER],
                _ => vec![spdl::LOAD_METER, spdl::SPEED_METER],
            };
            AxisDataCall {
                what: AxisData::Spindle(codes),
                limit: 8,
            }
            .request(&cx)
        }
        "rdsvmeter" => AxisDataCall {
            what: AxisData::Servo(vec![1]),
            limit: 8,
        }
        .request(&cx),
        "rdaxisdata" => {
            let types: Vec<i32> = (0..n(1) as usize).map(|i| n(2 + i) as i32).collect();
            match n(0) {
                1 => axes(types),
                2 => AxisDataCall {
                    what: AxisData::Servo(vec![1; types.len()]),
                    limit: 8,
                },
                _ => AxisDataCall {
                    what: AxisData::Spindle(types.iter().map(|t| spdl::LOAD_METER + t).collect()),
                    limit: 8,
                },
            }
            .request(&cx)
        }
        "rdposition" => match n(0) {
            -1 => axes(vec![0, 1, 2, 3]),
            t => axes(vec![t as i32]),
        }
        .request(&cx),
        "getfigure" => getfigure(n(0) as i16).request(&cx),
        _ => return None,
    })
}

fn value() -> impl Strategy<Value = fwlib32::proto::value::Value> {
    (any::<i32>(), any::<u16>(), any::<i16>())
        .prop_map(|(value, base, exp)| fwlib32::proto::value::Value { value, base, exp })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 128,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn position_wire_structs_roundtrip(
        bits in any::<u32>(),
        (data, mdata) in (any::<i32>(), any::<i32>()),
        recs in vec(value(), 0..40),
        names in vec(any::<[u8; 4]>(), 0..32),
        pnames in vec(any::<[u8; 16]>(), 0..32),
        count in any::<i32>(),
        figs in vec((any::<i16>(), any::<i16>()), 0..32),
        units in vec((any::<u16>(), any::<u16>()), 0..32),
        n in any::<u16>(),
    ) {
        use fwlib32::proto::position::*;
        roundtrip(&AlarmBits { bits })?;
        roundtrip(&ProgNums { data, mdata })?;
        roundtrip(&SeqNum { data })?;
        prop_assert_eq!(ProgNums { data, mdata }.to_bytes().len(), 8);
        roundtrip(&recs)?;
        prop_assert_eq!(recs.to_bytes().len(), 8 * recs.len());
        let names: Vec<Name> = names.into_iter().map(|bytes| Name { bytes }).collect();
        roundtrip(&names)?;
        let axes = pnames
            .iter()
            .map(|b| PosNames {
                absolute: b[0..4].try_into().unwrap(),
                machine: b[4..8].try_into().unwrap(),
                relative: b[8..12].try_into().unwrap(),
                other: b[12..16].try_into().unwrap(),
            })
            .collect::<Vec<_>>();
        let an = AxisNames { count, axes };
        roundtrip(&an)?;
        prop_assert_eq!(an.to_bytes().len(), 4 + 16 * an.axes.len());
        let f = Figures {
            count,
            axes: figs.into_iter().map(|(input, output)| Figure { input, output }).collect(),
        };
        roundtrip(&f)?;
        let u: Vec<UnitWords> = units.into_iter().map(|(w0, w1)| UnitWords { w0, w1 }).collect();
        roundtrip(&u)?;
        roundtrip(&Count { n })?;
    }

    #[test]
    fn position_decoders_never_panic(b in vec(any::<u8>(), 0..300)) {
        use fwlib32::proto::position::*;
        let _ = AlarmBits::from_bytes(&b);
        let _ = ProgNums::from_bytes(&b);
        let _ = AxisNames::from_bytes(&b);
        let _ = Figures::from_bytes(&b);
        let _ = Vec::<fwlib32::proto::value::Value>::from_bytes(&b);
        let _ = Vec::<Name>::from_bytes(&b);
        let _ = Vec::<UnitWords>::from_bytes(&b);
    }
}

// ---------------------------------------------------------------------------
// --- offset ---: offsets, tool life and the alarm history
// ---------------------------------------------------------------------------

fn offset_request(word: &str, a: &[String], cx: &Ctx, path: u16) -> Vec<ReqSub> {
    use fwlib32::proto::{alarm, offset};
    let n = |i: usize| num(&a[i]);
    match word {
        "rdtofs" => stamped(&offset::rdtofs(n(0) as i16, n(1) as i16), cx, path),
        "rdzofs" => stamped(&offset::rdzofs(n(0) as i16, n(1) as i16), cx, path),
        _ => stamped(&alarm::rdalmhistry(n(0) as u16, n(1) as u16), cx, path),
    }
}

fn value_rec() -> impl Strategy<Value = fwlib32::proto::value::Value> {
    (any::<i32>(), any::<u16>(), any::<i16>())
        .prop_map(|(value, base, exp)| fwlib32::proto::value::Value { value, base, exp })
}

fn his_rec() -> impl Strategy<Value = fwlib32::proto::alarm::AlmHisRecord> {
    (
        (any::<i32>(), any::<i16>(), any::<i16>(), any::<i32>()),
        any::<[u16; 6]>(),
        (any::<i32>(), any::<[u8; 32]>()),
    )
        .prop_map(|((alm_no, reserved, alm_grp, axis), t, (msg_len, msg))| {
            fwlib32::proto::alarm::AlmHisRecord {
                alm_no,
                reserved,
                alm_grp,
                axis,
                year: t[0],
                month: t[1],
                day: t[2],
                hour: t[3],
                minute: t[4],
                second: t[5],
                msg_len,
                msg,
            }
        })
}

/// Records counted by the CNC's count (Func::counted, cnc_rdsyshard): that
/// many, at most the caller's `*num`, past the payload's end zeros (as
/// FANUC's library reads them); a negative count none.
#[test]
fn counted_records_follow_the_cncs_count() {
    use fwlib32::proto::described::decode;
    let f = (fwlib32::spec::FUNCS.iter())
        .find(|f| f.name == "cnc_rdsyshard")
        .unwrap();
    let board: Vec<u8> = (1..=20).collect();
    let answer = |count: i16, boards: usize| {
        let mut p = vec![0x12, 0x34];
        p.extend(count.to_be_bytes());
        (0..boards).for_each(|_| p.extend(&board));
        p
    };
    let rec: Vec<i64> = vec![
        0x01020304, 0x05060708, 0x090a, 0x0b0c, 0x0d0e, 0x0f10, 0x1112, 0x1314,
    ];
    let mut two = vec![0x1234, 2];
    two.extend(&rec);
    two.extend([0; 8]);
    assert_eq!(
        decode(f, &[1, 4], &answer(2, 1)).unwrap(),
        two,
        "the second from zeros"
    );
    let mut one = vec![0x1234, 3];
    one.extend(&rec);
    assert_eq!(
        decode(f, &[1, 1], &answer(3, 3)).unwrap(),
        one,
        "at most *num"
    );
    assert_eq!(decode(f, &[1, 4], &answer(-1, 2)).unwrap(), [0x1234, -1]);
    assert_eq!(decode(f, &[1, 4], &answer(0, 2)).unwrap(), [0x1234, 0]);
}

/// A range's records (Func::span, pmc_get_timer_type): at most `e - s + 1`
/// of those the answer holds, whole words only; a write (pmc_set_timer_type)
/// sends that many.
#[test]
fn a_range_bounds_its_records() {
    use fwlib32::proto::described::{decode, payload_records};
    let f = described("pmc_get_timer_type").unwrap();
    let answer = [0, 1, 0, 2, 0, 3, 0, 4, 9];
    assert_eq!(decode(f, &[2, 3], &answer).unwrap(), [1, 2]);
    assert_eq!(decode(f, &[1, 250], &answer).unwrap(), [1, 2, 3, 4]);
    assert_eq!(decode(f, &[5, 5], &[]).unwrap(), Vec::<i64>::new());
    let w = described("pmc_set_timer_type").unwrap();
    assert_eq!(payload_records(w, &[3, 7]), 5);
    assert_eq!(payload_records(w, &[1, 1]), 1);
}

/// A text member (`Int::Char`, cnc_exeprgname's name): the
/// characters after its first NUL read as zeros; a short answer as zeros.
#[test]
fn a_c_string_ends_at_its_nul() {
    use fwlib32::proto::described::decode;
    let f = described("exeprgname").unwrap();
    let mut p = vec![0, 0, 0x04, 0xd2];
    p.extend(b"O1234\0XY");
    p.resize(40, b'Z');
    let mut want = vec![1234];
    want.extend(b"O1234".iter().map(|c| i64::from(*c)));
    want.resize(37, 0);
    assert_eq!(decode(f, &[], &p).unwrap(), want);
    assert_eq!(
        decode(f, &[], &p[..6]).unwrap()[..3],
        [1234, i64::from(b'O'), i64::from(b'1')]
    );
    assert_eq!(decode(f, &[], &p[..6]).unwrap()[3..], [0; 34]);
}

/// Lookups (Func::lookups, cnc_rdsyssoft): a physical slot missing from the
/// logical table gets no logical slot (0xff) and ends the series lookups
/// there, while the IDs go on to the list's end (0xff); the second bank's
/// IDs from the second table; unset characters (0xff) read as NULs.
#[test]
fn syssoft_lookups_follow_fanucs_loops() {
    use fwlib32::proto::described::decode;
    let f = (fwlib32::spec::FUNCS.iter())
        .find(|f| f.name == "cnc_rdsyssoft")
        .unwrap();
    let mut p = vec![0u8; 664];
    // Physical slots 0x02, 0x05 (not in the logical table), 0x81; then 0xff.
    p[..16].fill(0xff);
    p[..3].copy_from_slice(&[0x02, 0x05, 0x81]);
    let word = |p: &mut Vec<u8>, at: usize, v: u16| p[at..at + 2].copy_from_slice(&v.to_be_bytes());
    word(&mut p, 16 + 4, 0x0a02); // module of 0x02
    word(&mut p, 16 + 10, 0x0a05); // module of 0x05
    word(&mut p, 48 + 2, 0x0a81); // module of 0x81 (second bank)
    word(&mut p, 80 + 4, 2);
    word(&mut p, 80 + 10, 5);
    word(&mut p, 112 + 2, 0x81);
    // Logical table: 0x81 first, then 0x02.
    word(&mut p, 144, 0x8100);
    word(&mut p, 146, 0x0200);
    (148..176).for_each(|k| p[k] = 0xff);
    p[208..216].copy_from_slice(b"AAAA1111");
    p[216..224].copy_from_slice(b"BB\xff\xff2222");
    p[336..340].copy_from_slice(b"BOOT");
    let v = decode(f, &[], &p).unwrap();
    let looked: usize = f.lookups.iter().map(|l| l.values()).sum();
    let tail = &v[v.len() - looked..];
    let (l, rest) = tail.split_at(16);
    let (module, rest) = rest.split_at(16);
    let (soft, rest) = rest.split_at(16);
    let (series, rest) = rest.split_at(80);
    let (version, pairs) = rest.split_at(80);
    let mut want = vec![-1i64; 16];
    want[..3].copy_from_slice(&[1, -1, 0]);
    assert_eq!(l, want, "slot_no_l: 0x05 has none");
    let mut want = vec![-1i64; 16];
    want[..3].copy_from_slice(&[0x0a02, 0x0a05, 0x0a81]);
    assert_eq!(module, want, "module_id to the list's end");
    let mut want = vec![-1i64; 16];
    want[..3].copy_from_slice(&[2, 5, 0x81]);
    assert_eq!(soft, want);
    let text = |c: &[i64]| c.iter().map(|x| *x as u8 as char).collect::<String>();
    assert_eq!(
        text(&series[..10]),
        "BB\0\0\0\0\0\0\0\0",
        "series of logical slot 1, then none"
    );
    assert!(series[5..].iter().all(|x| *x == 0), "ended at slot 0x05");
    assert_eq!(text(&version[..5]), "2222\0");
    assert!(version[5..].iter().all(|x| *x == 0));
    // The named pairs from boot_ser on: 4 characters, then a NUL.
    assert_eq!(text(&pairs[..10]), "BOOT\0\0\0\0\0\0");
}

#[test]
fn history_decoder_drops_a_ragged_tail() {
    use fwlib32::proto::alarm::AlmHistory;
    let vectors = unhex(
        "000001f4000000040000000107e800050011000d002d001e000000134f5430353030204f56455254524156454c203000000000000000000000000000",
    );
    let one = AlmHistory::from_bytes(&vectors).unwrap();
    assert_eq!(one.0.len(), 1);
    assert_eq!(
        (one.0[0].alm_no, one.0[0].year, one.0[0].msg_len),
        (500, 2024, 19)
    );
    assert_eq!(one.0[0].year_his(), 24);
    assert_eq!(one.0[0].year_his2(), -24);
    let ragged = AlmHistory::from_bytes(&vectors[..59]).unwrap();
    assert!(ragged.0.is_empty());
    assert!(AlmHistory::from_bytes(&[]).unwrap().0.is_empty());
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Every function described as data (src/spec): the simulator's encoder
    /// and the client's decoder are exact inverses, records included, for
    /// any integers of the wire's widths.
    #[test]
    fn described_replies_roundtrip(seed in vec(any::<u32>(), 0..600), records in 0usize..40) {
        use fwlib32::proto::described::{decode, encode};
        use fwlib32::spec::{FUNCS, Int};
        for f in FUNCS {
            // Several subpackets (cnc_rdposerrs2): each answers a share of
            // the fields, decoded per subpacket (the recorded cases).
            if !f.more.is_empty() {
                continue;
            }
            // Echo fields (not on the wire) decode as argument 0 of none: 0.
            let width = |x: &fwlib32::spec::Field| if x.arg.is_some() { None } else { Some(x.wire) };
            let widths: Vec<Option<Int>> = f.reply.iter().flat_map(|x| std::iter::repeat_n(width(x), x.n as usize)).collect();
            let rec: Vec<Option<Int>> = f.records.map_or(Vec::new(), |r| {
                r.fields.iter().flat_map(|x| std::iter::repeat_n(width(x), x.n as usize)).collect()
            });
            let n = f.records.map_or(0, |r| records.min(r.max as usize));
            let all: Vec<Option<Int>> = widths.iter().copied().chain((0..n).flat_map(|_| rec.iter().copied())).collect();
            let mut values: Vec<i64> = all
                .iter()
                .zip(seed.iter().cycle())
                .map(|(w, s)| match w {
                    None => 0,
                    Some(Int::I8 | Int::IdChar) => i64::from(*s as u8 as i8),
                    Some(Int::U8 | Int::Char) => i64::from(*s as u8),
                    Some(Int::I16) => i64::from(*s as u16 as i16),
                    Some(Int::U16) => i64::from(*s as u16),
                    Some(Int::I32) => i64::from(*s as i32),
                    Some(Int::U32) => i64::from(*s),
                    Some(Int::BaseExp) => i64::from(*s as u16 as i16),
                    // Any bits of a double (the seed's, spread).
                    Some(Int::F64) => u64::from(*s).wrapping_mul(0x9e37_79b9_7f4a_7c15) as i64,
                })
                .collect();
            if seed.is_empty() && !all.is_empty() {
                continue;
            }
            // Records counted by a reply field (Func::counted): the CNC's
            // count is theirs.
            if let Some(k) = f.counted.map(usize::from) {
                let at: usize = f.reply[..k].iter().map(|x| x.n as usize).sum();
                values[at] = n as i64;
            }
            let bytes = encode(f, &values).expect("encode");
            prop_assert_eq!(bytes.len(), f.reply_len() + n * f.records.map_or(0, |r| r.wire_len()));
            // FANUC's library's zeroed member reads 0 (cnc_rdpmacroinfo's use_no2).
            let mut expect = values.clone();
            fwlib32::proto::described::zero_unless(f, &mut expect);
            // A text (Int::Char) reads as zeros after its first NUL.
            let per_rec = f.records.map_or(&[][..], |r| r.fields);
            let layout = f.reply.iter().chain((0..n).flat_map(|_| per_rec.iter()));
            let mut at = 0;
            for x in layout {
                let run = &mut expect[at..at + x.n as usize];
                if x.wire == Int::Char && x.arg.is_none()
                    && let Some(nul) = run.iter().position(|v| *v == 0) {
                        run[nul..].iter_mut().for_each(|v| *v = 0);
                    }
                at += x.n as usize;
            }
            // The last number answered (Field::arg LAST): argument 0 (none:
            // 0) plus the records, less one.
            let mut at = 0;
            for x in f.reply {
                if x.arg == Some(fwlib32::spec::LAST) {
                    expect[at] = n as i64 - 1;
                }
                at += x.n as usize;
            }
            // An unset character (0xff) reads as a NUL.
            for (e, w) in expect.iter_mut().zip(&all) {
                if *w == Some(Int::IdChar) && *e == -1 {
                    *e = 0;
                }
            }
            // A range (Func::span) asks for the n records: 1..=n.
            let args: Vec<i32> = f.span.map_or(Vec::new(), |(s, e)| {
                let mut a = vec![0; usize::from(s.max(e)) + 1];
                a[usize::from(s)] = 1;
                a[usize::from(e)] = n as i32;
                a
            });
            // The lookups' integers (Func::lookups) follow the reply's.
            let mut got = decode(f, &args, &bytes).expect("decode");
            let looked: usize = f.lookups.iter().map(|l| l.values()).sum();
            prop_assert_eq!(got.len(), expect.len() + looked, "{}", f.name);
            got.truncate(expect.len());
            prop_assert_eq!(got, expect, "{}", f.name);
        }
    }

    #[test]
    fn offset_wire_roundtrip(
        v in vec(value_rec(), 0..40),
        info in (any::<i16>(), any::<i16>(), any::<i16>(), any::<i16>()),
        c in any::<i32>(),
    ) {
        use fwlib32::proto::offset::{Count, TofsInfo};
        roundtrip(&v)?;
        prop_assert_eq!(v.to_bytes().len(), 8 * v.len());
        let i = TofsInfo { reserved: info.0, use_no: info.1, ofs_type: info.2, enable: info.3 };
        roundtrip(&i)?;
        roundtrip(&Count { value: c })?;
    }

    /// The write encoder is the read decoder reversed: what wrtofs/wrzofs
    /// put in a payload decodes to the values written.
    #[test]
    fn offset_write_payload_is_the_read_record(values in vec(any::<i32>(), 1..33), n in any::<i16>(), axis in -1i16..33, kind in 0i16..10) {
        use fwlib32::proto::offset::{wrtofs, wrzofs, RDZOFS, WRZOFS, WRTOFS, RDTOFS, rdtofs, rdzofs};
        let cx = Ctx::default();
        let w = &wrzofs(n, axis, &values).request(&cx)[0];
        let r = &rdzofs(n, axis).request(&cx)[0];
        prop_assert_eq!((w.cmd, r.cmd), (WRZOFS, RDZOFS));
        prop_assert_eq!(&w.args[..3], &r.args[..3]);
        prop_assert_eq!(w.args[4] as usize, 8 * values.len());
        let back = Vec::<fwlib32::proto::value::Value>::from_bytes(&w.payload).unwrap();
        prop_assert_eq!(back.iter().map(|x| x.value).collect::<Vec<_>>(), values.clone());
        let w = &wrtofs(n, kind, values[0]).request(&cx)[0];
        let r = &rdtofs(n, kind).request(&cx)[0];
        prop_assert_eq!((w.cmd, r.cmd), (WRTOFS, RDTOFS));
        prop_assert_eq!(&w.args[..3], &r.args[..3]);
        let back = Vec::<fwlib32::proto::value::Value>::from_bytes(&w.payload).unwrap();
        prop_assert_eq!(back.len(), 1);
        prop_assert_eq!(back[0].value, values[0]);
    }

    #[test]
    fn history_roundtrip(recs in vec(his_rec(), 0..12)) {
        use fwlib32::proto::alarm::AlmHistory;
        let h = AlmHistory(recs);
        roundtrip(&h)?;
        prop_assert_eq!(h.to_bytes().len(), 60 * h.0.len());
        // The checked list is a prefix-cut, filtered list of the records.
        let valid = h.valid();
        prop_assert!(valid.iter().all(|r| r.time_ok() && r.msg_ok()));
        let cut = h.0.iter().position(|r| !r.msg_ok()).unwrap_or(h.0.len());
        let want: Vec<_> = h.0[..cut].iter().filter(|r| r.time_ok()).copied().collect();
        prop_assert_eq!(valid, want);
    }

    #[test]
    fn tool_wire_roundtrip(
        g in (any::<i32>(), value_rec(), value_rec(), value_rec()),
        tools in vec(any::<[i32; 4]>(), 0..10),
        head in any::<(i32, i32)>(),
        ctl in any::<[i32; 9]>(),
    ) {
        use fwlib32::proto::tool::{ToolCtl, ToolEntry, ToolGroup, ToolList};
        let tg = ToolGroup { grp: g.0, ntool: g.1, life: g.2, count: g.3 };
        roundtrip(&tg)?;
        prop_assert_eq!(tg.to_bytes().len(), 28);
        let tl = ToolList {
            grp: head.0,
            first: head.1,
            tools: tools.iter().map(|t| ToolEntry { tool_num: t[0], length_num: t[1], radius_num: t[2], tinfo: t[3] }).collect(),
        };
        roundtrip(&tl)?;
        let c = ToolCtl {
            slct: ctl[0], used_tool: ctl[1], turret_indx: ctl[2], zero_tl_no: ctl[3],
            total_punch0: ctl[4], total_punch1: ctl[5], t_axis_move: ctl[6], reserved: ctl[7], t_axis_dec: ctl[8],
        };
        roundtrip(&c)?;
        prop_assert_eq!(c.to_bytes().len(), 36);
    }

    #[test]
    fn offset_decoders_never_panic(b in vec(any::<u8>(), 0..400)) {
        let _ = Vec::<fwlib32::proto::value::Value>::from_bytes(&b);
        let _ = fwlib32::proto::offset::TofsInfo::from_bytes(&b);
        let _ = fwlib32::proto::offset::Count::from_bytes(&b);
        if let Ok(h) = fwlib32::proto::alarm::AlmHistory::from_bytes(&b) {
            prop_assert_eq!(h.0.len(), b.len() / 60);
            let _ = h.valid();
        }
        let _ = fwlib32::proto::tool::ToolGroup::from_bytes(&b);
        let _ = fwlib32::proto::tool::ToolList::from_bytes(&b);
        let _ = fwlib32::proto::tool::ToolCtl::from_bytes(&b);
    }
}

// --- program ---

fn alm_msg<const N: usize>() -> impl Strategy<Value = AlmMsg<N>> {
    (any::<[i32; 4]>(), vec(any::<u8>(), N)).prop_map(|(w, m)| {
        let mut msg = [0u8; N];
        msg.copy_from_slice(&m);
        AlmMsg {
            alm_no: w[0],
            kind: w[1],
            axis: w[2],
            msg_len: w[3],
            msg,
        }
    })
}

fn aux_code() -> impl Strategy<Value = AuxCode> {
    (any::<i32>(), any::<[u8; 4]>()).prop_map(|(value, b)| AuxCode {
        value,
        pad1: b[0],
        flag1: b[1],
        pad2: b[2],
        flag2: b[3],
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn program_and_alarm_structs_roundtrip(
        w in any::<[i32; 4]>(),
        h in any::<[i16; 6]>(),
        text in vec(any::<u8>(), 0..300),
        g in vec(any::<(u8, u8)>(), 1..40),
        aux in vec(aux_code(), 1..40),
        m32 in vec(alm_msg::<32>(), 0..6),
        m64 in vec(alm_msg::<64>(), 0..6),
    ) {
        roundtrip(&AlarmBits { bits: w[0] as u32 })?;
        roundtrip(&ProgNums { data: w[0], mdata: w[1] })?;
        roundtrip(&SeqNum { data: w[2] })?;
        roundtrip(&ActPt { prog_no: w[0], blk_no: w[1] })?;
        roundtrip(&PathName(text.clone()))?;
        roundtrip(&ExecProg { blknum: Some(w[0]), text: text.clone() })?;
        roundtrip(&ExecProg::default())?;
        prop_assert_eq!(ExecProg::default().to_bytes().len(), 0);
        roundtrip(&Timer { minute: w[0], msec: w[1] })?;
        let c = Clock { year: h[0], month: h[1], day: h[2], hour: h[3], minute: h[4], second: h[5] };
        roundtrip(&c)?;
        prop_assert_eq!(c.to_bytes().len(), 12);
        roundtrip(&ToolNum { datano: w[0], kind: w[1], data: w[2] })?;
        roundtrip(&NTool { datano: w[0], data: w[1] })?;
        roundtrip(&GModal(g.iter().map(|(code, flag)| GCode { code: *code, flag: *flag }).collect()))?;
        roundtrip(&AuxModal(aux.clone()))?;
        prop_assert_eq!(AuxModal(aux.clone()).to_bytes().len(), 8 * aux.len());
        roundtrip(&m32)?;
        roundtrip(&m64)?;
        prop_assert_eq!(m32.to_bytes().len(), 48 * m32.len());
        prop_assert_eq!(m64.to_bytes().len(), 80 * m64.len());
        roundtrip(&OpMsg { datano: w[0], kind: w[1], char_num: w[2], text })?;
    }

    #[test]
    fn program_and_alarm_decoders_never_panic(b in vec(any::<u8>(), 0..400)) {
        let _ = ExecProg::from_bytes(&b);
        let _ = GModal::from_bytes(&b);
        let _ = AuxModal::from_bytes(&b);
        let _ = Vec::<AlmMsg<32>>::from_bytes(&b);
        let _ = Vec::<AlmMsg<64>>::from_bytes(&b);
        let _ = OpMsg::from_bytes(&b);
        let _ = Clock::from_bytes(&b);
        // Short payloads are errors, never garbage.
        if b.len() < 12 {
            prop_assert!(OpMsg::from_bytes(&b).is_err());
            prop_assert!(Clock::from_bytes(&b).is_err());
        }
        if (1..4).contains(&b.len()) {
            prop_assert!(ExecProg::from_bytes(&b).is_err());
        }
        // Fewer than one pair / record: no record (cnc_modal decides whether
        // that is data). A 0x22 record list is length / 8 records, a ragged
        // tail ignored, as FANUC's library reads it (docs/protocol/status.md).
        if b.len() < 2 {
            prop_assert_eq!(GModal::from_bytes(&b).map(|g| g.0.len()), Ok(0));
        }
        prop_assert_eq!(AuxModal::from_bytes(&b).map(|a| a.0.len()), Ok(b.len() / 8));
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
        // Any bytes but NUL: names are bytes, not UTF-8.
        start in proptest::collection::vec(1u8..=255, 0..256),
        end in proptest::collection::vec(1u8..=255, 0..256),
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
