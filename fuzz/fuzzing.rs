//! The entry points of the fuzz targets (fuzz/fuzz_targets/, cargo-fuzz)
//! and of the corpus replay test (tests/robust/fuzz_corpus.rs): this one file,
//! included by both (`#[path]`), so that they cannot drift apart. Each
//! takes arbitrary bytes and must return without a panic, a hang or an
//! unbounded allocation, whatever the bytes. It uses only the library's
//! public API.
//!
//! * [`reply`]: the client's decoding of a CNC's answer, fed whole frames:
//!   the frame header, the subpacket list and the payload, through the
//!   decoder of one exported function (the open and start-up answers, the
//!   hand-written [`Call`]s, every function of [`fwlib32::spec::FUNCS`]).
//! * [`request`]: the simulator's decoding of a client's frames, answered
//!   by a fresh [`Machine`] as its sessions answer them, with the trace
//!   lines of both directions.
//! * [`profile`]: the profile loader (TOML, validation), and a machine
//!   built from any profile it accepts.

#![allow(dead_code)]

use fwlib32::proto::call::{self, Call, Ctx};
use fwlib32::proto::described::{Described, for_request};
use fwlib32::proto::frame::{Frame, FrameHeader, HEADER_LEN, ftype};
use fwlib32::proto::open::{CncClass, OpenBody};
use fwlib32::proto::packet::ReqSub;
use fwlib32::proto::packet::{RespSub, decode_request, decode_response_into, encode_response};
use fwlib32::proto::position::{AxisData, AxisDataCall, Dynamic, Position16, Speed, SpindleData};
use fwlib32::proto::{
    alarm as pa, history as ph, macros as pm, offset as po, param as pp, pmc, program as pg,
};
use fwlib32::proto::{position as ps, status as st, tool as pt, upload as pu};
use fwlib32::sim::service::CncService;
use fwlib32::sim::trace::Namer;
use fwlib32::sim::{Machine, Profile};
use std::hint::black_box;
use std::sync::OnceLock;
use std::time::Duration;

/// The bytes before the frames of a [`reply`] input: the decoder (two
/// bytes, big-endian: there are more than 256), the CNC the handle talks
/// to, and four argument words.
pub const REPLY_PREFIX: usize = 3 + 8;

/// The caller's argument words of a reply input.
type Args = [i32; 4];

/// One decoder of [`reply`]: the exported functions it serves and how it
/// decodes a data answer (after [`Call::request`] with the same arguments).
struct Decoder {
    names: &'static [&'static str],
    run: fn(&Ctx, &Args, &[RespSub]),
}

fn go<C: Call>(c: C, cx: &Ctx, resp: &[RespSub]) {
    black_box(c.request(cx));
    let _ = black_box(c.decode(cx, resp));
}

/// A short list of codes from an argument (the meter and axis-data calls).
fn codes(a: i32) -> Vec<i32> {
    (0..(a & 7))
        .map(|k| a.wrapping_shr(3).wrapping_add(k))
        .collect()
}

fn table(a: i32) -> pp::Table {
    if a & 1 == 0 {
        pp::Table::Param
    } else {
        pp::Table::Diag
    }
}

/// Every hand-written call of the exported functions (src/ffi), by the C
/// functions that make it.
const HAND: &[Decoder] = &[
    Decoder {
        names: &["cnc_statinfo"],
        run: |cx, _, r| go(st::StatInfo::<st::Status>::new(), cx, r),
    },
    Decoder {
        names: &["cnc_statinfo2"],
        run: |cx, _, r| go(st::StatInfo::<st::Status2>::new(), cx, r),
    },
    Decoder {
        names: &["cnc_rdalmmsg"],
        run: |cx, a, r| go(pa::rdalmmsg::<32>(a[0] as i16, a[1] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_rdalmmsg2"],
        run: |cx, a, r| go(pa::rdalmmsg::<64>(a[0] as i16, a[1] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_rdalminfo"],
        run: |cx, a, r| go(pa::rdalminfo(a[0] as i16, a[1] as i16, a[2]), cx, r),
    },
    Decoder {
        names: &["cnc_rdopmsg"],
        run: |cx, a, r| go(pa::rdopmsg(a[0] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_rdalmhistry", "cnc_rdalmhistry2"],
        run: |cx, a, r| go(pa::rdalmhistry(a[0] as u16, a[1] as u16), cx, r),
    },
    Decoder {
        names: &["cnc_rddynamic", "cnc_rddynamic2", "cnc_rddynamico8"],
        run: |cx, a, r| go(Dynamic { axis: a[0] as i16 }, cx, r),
    },
    Decoder {
        names: &[
            "cnc_rdspload",
            "cnc_rdspmaxrpm",
            "cnc_rdspgear",
            "cnc_acts2",
        ],
        run: |cx, a, r| {
            let c = SpindleData {
                code: a[0],
                sp_no: a[1] as i16,
            };
            go(c, cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdspeed"],
        run: |cx, a, r| {
            let c = Speed {
                feed: a[0] & 1 != 0,
                spindle: a[0] & 2 != 0,
            };
            go(c, cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdaxisdata", "cnc_rdsvmeter", "cnc_rdspmeter"],
        run: |cx, a, r| {
            let what = match a[0] & 7 {
                0 => AxisData::Positions(codes(a[1])),
                1 => AxisData::Servo(codes(a[1])),
                2 => AxisData::Spindle(codes(a[1])),
                3 => AxisData::FirstSpindle(codes(a[1])),
                _ => AxisData::Speed(codes(a[1]).into_iter().map(|c| c as u16).collect()),
            };
            go(
                AxisDataCall {
                    what,
                    limit: a[2] as i16,
                },
                cx,
                r,
            )
        },
    },
    Decoder {
        names: &["cnc_rdposition"],
        run: |cx, a, r| {
            let c = Position16 {
                s15: a[0] & 1 != 0,
                limit: a[1] as i16,
            };
            go(c, cx, r)
        },
    },
    Decoder {
        // Byte answers (src/ffi/folder.rs, src/ffi/memory.rs).
        names: &[
            "cnc_rdmdiprog",
            "cnc_wrmdiprog",
            "cnc_rdpdf_subdir",
            "cnc_rdpdf_alldir",
            "cnc_pdf_rdactpt",
            "cnc_pdf_wractpt",
            "cnc_rdpdf_line",
            "cnc_wrpdf_line",
        ],
        run: |cx, a, r| {
            let sub = ReqSub::cnc(a[0] as u16, &[a[1], a[2], a[3]]);
            go(call::Single::<pg::PathName>::new(sub), cx, r)
        },
    },
    Decoder {
        names: &["pmc_rdalmmsg"],
        run: |cx, a, r| go(pmc::AlarmMsgs { s: a[0], n: a[1] }, cx, r),
    },
    Decoder {
        names: &["cnc_wrwkcdshft"],
        run: |cx, a, r| go(po::wrwkcdshft(a[0] as i16, &[a[1], a[2]]), cx, r),
    },
    Decoder {
        names: &["cnc_instlifedt"],
        run: |cx, a, r| go(pt::tlinsert(a[0] as i16, a[1] as i16, a[2]), cx, r),
    },
    Decoder {
        names: &["cnc_rdproginfo"],
        run: |cx, a, r| {
            let sub = ReqSub::cnc(a[0] as u16, &[a[1]]);
            go(call::Single::<pg::ProgInfo>::padded(sub), cx, r)
        },
    },
    Decoder {
        names: &["cnc_wrhissgnl3"],
        run: |cx, a, r| {
            let e = ph::Sig3 {
                ent_no: a[1] as i16,
                pmc_no: a[2] as i16,
                sig_no: a[3] as i16,
                sig_name: a[2] as u8,
                mask_pat: a[3] as u8,
            };
            let entries = vec![e; (a[0] & 63).min(60) as usize];
            go(ph::WriteSig3 { entries }, cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdophistry"],
        run: |cx, a, r| go(ph::rdophistry(a[0] as u16, a[1] as u16), cx, r),
    },
    Decoder {
        names: &["cnc_rdophistry4"],
        run: |cx, a, r| {
            let c = ph::OpHis4 { s: a[0], e: a[1] };
            black_box(c.request(cx));
            if let Ok(ans) = c.decode(cx, r) {
                let (recs, _) = ph::op4_walk(&ans, a[2] & 0xffff);
                for (kind, t, wire) in &recs {
                    let mut out = vec![0u8; kind.size];
                    ph::op4_put(kind, *t, wire, &mut out);
                    black_box(out);
                }
            }
        },
    },
    Decoder {
        names: &["cnc_rdopmsg3"],
        run: |cx, a, r| go(pa::rdopmsg3(a[0] & 1 != 0, a[1], a[2] as i16, a[3]), cx, r),
    },
    Decoder {
        names: &["cnc_rdprstrinfo"],
        run: |cx, _, r| go(fwlib32::proto::machine::PrstrInfo, cx, r),
    },
    Decoder {
        names: &["cnc_rdomhistry"],
        run: |cx, a, r| go(ph::rdomhistry(a[0] as u16, a[1] as u16), cx, r),
    },
    Decoder {
        names: &["cnc_rdomhistry2"],
        run: |cx, a, r| go(ph::rdomhistry2(a[0] as u16, a[1] as u16), cx, r),
    },
    Decoder {
        names: &["cnc_rdalmhistry5"],
        run: |cx, a, r| go(ph::rdalmhistry5(a[0] as u16, a[1] as u16), cx, r),
    },
    Decoder {
        names: &["cnc_rdpitchr"],
        run: |cx, a, r| go(ph::rdpitchr(a[0], a[1]), cx, r),
    },
    Decoder {
        names: &["cnc_rdparainfo3"],
        run: |cx, a, r| go(pp::rdparainfo3(a[0] as i16, a[1] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_getfigure"],
        run: |cx, a, r| go(ps::getfigure(a[0] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_rdtoolgrp"],
        run: |cx, a, r| go(pt::tlgroup(a[0] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_rdtoolgrp"],
        run: |cx, a, r| go(pt::tltools(a[0], a[1]), cx, r),
    },
    Decoder {
        names: &["cnc_rdtlctldata"],
        run: |cx, _, r| go(pt::tlctl(), cx, r),
    },
    Decoder {
        names: &["cnc_wrgrpinfo"],
        run: |cx, a, r| {
            let g = pt::GroupWrite {
                life: a[2],
                count_type: a[2] & 1,
                count: a[2] >> 1,
                w3: -1,
                w4: -1,
            };
            go(pt::wrgrpinfo(a[0] as i16, a[1] as i16, &[g; 3]), cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdtlusegrp"],
        run: |cx, _, r| go(pt::usegrp(), cx, r),
    },
    Decoder {
        names: &["cnc_rdtlusegrp"],
        run: |cx, a, r| go(pt::OptGroups([a[0], a[1], a[2]]), cx, r),
    },
    Decoder {
        names: &["cnc_rdtool"],
        run: |cx, a, r| go(pt::RdTool::new(a[0], a[1]), cx, r),
    },
    Decoder {
        names: &["cnc_rdtooldata"],
        run: |cx, a, r| {
            let c = pt::PunchData {
                tool_no: a[0] as i16,
                n: a[1] as i16,
            };
            go(c, cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdtoolinfo"],
        run: |cx, _, r| go(pt::PunchInfo, cx, r),
    },
    Decoder {
        names: &["cnc_rdexecprog"],
        run: |cx, a, r| go(pg::rdexecprog(a[0] as u16), cx, r),
    },
    Decoder {
        names: &["cnc_modal"],
        run: |cx, a, r| {
            if let Some(kind) = pg::modal_kind(a[0] as i16) {
                let block = a[1] as i16;
                go(pg::ModalCall { kind, block }, cx, r)
            }
        },
    },
    Decoder {
        names: &["cnc_gettimer"],
        run: |cx, a, r| go(pg::gettimer(a[0] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_settimer"],
        run: |cx, a, r| {
            let clock = pg::Clock {
                year: a[1] as i16,
                ..Default::default()
            };
            go(
                pg::SetTimer {
                    kind: a[0] as i16,
                    clock,
                },
                cx,
                r,
            )
        },
    },
    Decoder {
        names: &[
            "cnc_rdprogdir",
            "cnc_rdprogdir2",
            "cnc_rdprogdir3",
            "cnc_rdprogdiro8",
            "cnc_rdprogdir2o8",
        ],
        run: |cx, a, r| go(pg::progdir(a[0], a[1], a[2]), cx, r),
    },
    Decoder {
        names: &["cnc_rdparainfo", "cnc_rddiaginfo"],
        run: |cx, a, r| {
            let c = pp::ReadInfo {
                table: table(a[0]),
                start: a[1],
                count: a[2],
            };
            go(c, cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdparam_ext", "cnc_rddiag_ext"],
        run: |cx, a, r| {
            let numbers = (0..(a[1] & 15)).map(|k| a[2].wrapping_add(k)).collect();
            let c = pp::ReadExt {
                table: table(a[0]),
                numbers,
            };
            go(c, cx, r)
        },
    },
    Decoder {
        names: &["cnc_wrparas"],
        run: |cx, a, r| {
            let rec = pp::Packed {
                number: a[0] as i16,
                axis: a[1] as i8,
                ptype: (a[2] & 7) as u8,
                values: vec![pp::Num::int(a[3]); (a[3] & 3) as usize],
            };
            let records = vec![rec; (a[0] & 3) as usize];
            go(pp::WriteSeveral { records }, cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdtofs"],
        run: |cx, a, r| go(po::rdtofs(a[0] as i16, a[1] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_wrtofs"],
        run: |cx, a, r| go(po::wrtofs(a[0] as i16, a[1] as i16, a[2]), cx, r),
    },
    Decoder {
        names: &["cnc_rdtofsr"],
        run: |cx, a, r| go(po::rdtofsr(a[0] as i16, a[1] as i16, a[2] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_rdzofs"],
        run: |cx, a, r| go(po::rdzofs(a[0] as i16, a[1] as i16), cx, r),
    },
    Decoder {
        names: &["cnc_wrzofs"],
        run: |cx, a, r| {
            let values = vec![a[2]; (a[3] & 7) as usize];
            go(po::wrzofs(a[0] as i16, a[1] as i16, &values), cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdzofsr"],
        run: |cx, a, r| {
            let c = po::ReadZofsRange {
                s: a[0],
                e: a[1],
                axis: a[2] as i16,
            };
            go(c, cx, r)
        },
    },
    Decoder {
        names: &["cnc_rdmacro", "cnc_rdmacror"],
        run: |cx, a, r| go(pm::ReadMacros { s: a[0], e: a[1] }, cx, r),
    },
    Decoder {
        names: &["cnc_wrmacro", "cnc_wrmacror"],
        run: |cx, a, r| {
            let values = vec![(a[2], a[3] as i16); (a[1] & 7) as usize];
            go(pm::WriteMacros { s: a[0], values }, cx, r)
        },
    },
    Decoder {
        names: &["pmc_rdpmcrng"],
        run: |cx, a, r| go(pmc::ReadPmc(range(a)), cx, r),
    },
    Decoder {
        names: &["pmc_wrpmcrng"],
        run: |cx, a, r| {
            let range = range(a);
            let data = vec![0x5a; range.span().min(4096)];
            go(pmc::WritePmc { range, data }, cx, r)
        },
    },
    Decoder {
        names: &["pmc_rdpmcinfo"],
        run: |cx, a, r| go(pmc::rdpmcinfo(a[0] as i16), cx, r),
    },
    Decoder {
        names: &["pmc_select_pmc_unit"],
        run: |cx, a, r| go(pmc::SelectUnit { unit: a[0] }, cx, r),
    },
    Decoder {
        names: &["pmc_get_pmc_unit_types"],
        run: |cx, a, r| go(pmc::UnitTypes { most: a[0] }, cx, r),
    },
];

fn range(a: &Args) -> pmc::PmcRange {
    pmc::PmcRange {
        adr_type: a[0] as i16,
        data_type: a[1] as i16,
        s: a[2] as u16,
        e: a[3] as u16,
    }
}

/// Decoders before the hand-written calls: the connection's open answer
/// and the start-up exchanges (sysinfo, the Series 15 companion, the
/// option parameter), as `cnc_allclibhndl3` reads them.
const CONNECT: usize = 1;

/// How many decoders [`reply`] chooses from: the connect step, the
/// hand-written calls, then [`fwlib32::spec::FUNCS`] in table order.
pub fn decoders() -> usize {
    CONNECT + HAND.len() + fwlib32::spec::FUNCS.len()
}

/// The exported functions the hand-written decoders name.
pub fn hand_written_names() -> impl Iterator<Item = &'static str> {
    HAND.iter().flat_map(|d| d.names.iter().copied())
}

/// The decoder of exported function `name` (the first, where several
/// serve it), for seeding a corpus.
pub fn decoder(name: &str) -> Option<u16> {
    let i = if name == "cnc_allclibhndl3" {
        0
    } else if let Some(i) = HAND.iter().position(|d| d.names.contains(&name)) {
        CONNECT + i
    } else {
        CONNECT + HAND.len() + fwlib32::spec::FUNCS.iter().position(|f| f.name == name)?
    };
    u16::try_from(i).ok()
}

/// The CNC of a reply input: class in bits 0-1 (30i, 16i, Series 15, 16i
/// kind 3), maximum axes in bits 2-4 and spindles in 5-7 (small, usual,
/// and more than any struct holds).
pub fn ctx_byte(class: CncClass, max_axes: u16) -> u8 {
    let c = match class {
        CncClass::Series30 => 0,
        CncClass::Series16 { kind: 2 } => 2,
        CncClass::Series16 { kind: 3 } => 3,
        CncClass::Series16 { .. } => 1,
    };
    let a = AXES.iter().position(|&x| x == max_axes).unwrap_or(4) as u8;
    c | a << 2 | 4 << 5
}

const AXES: [u16; 8] = [0, 1, 3, 8, 32, 33, 255, u16::MAX];
const SPINDLES: [u16; 8] = [0, 1, 2, 4, 8, 9, 255, u16::MAX];

fn ctx_of(b: u8) -> Ctx {
    let class = match b & 3 {
        0 => CncClass::Series30,
        1 => CncClass::Series16 { kind: 1 },
        2 => CncClass::Series16 { kind: 2 },
        _ => CncClass::Series16 { kind: 3 },
    };
    Ctx {
        class,
        max_axes: AXES[usize::from(b >> 2 & 7)],
        max_spindles: SPINDLES[usize::from(b >> 5)],
        path: 1,
        mt_type: *b" M",
    }
}

/// The frames of a byte stream as the client reads them (src/client/conn.rs):
/// a header checked before its body is awaited, then the whole frame; the
/// stream ends at a bad header or a frame cut short.
fn frames(mut b: &[u8]) -> impl Iterator<Item = (FrameHeader, &[u8])> {
    std::iter::from_fn(move || {
        let h = FrameHeader::decode(b.get(..HEADER_LEN)?).ok()?;
        let total = HEADER_LEN + usize::from(h.len);
        let body = b.get(HEADER_LEN..total)?;
        b = &b[total..];
        Some((h, body))
    })
}

/// The client's side: `data` is [decoder (two bytes), CNC (see [`ctx_byte`]), four
/// big-endian i16 argument words, then the CNC's frames]. Each frame of
/// the kind the decoder waits for is decoded (others are skipped, as the
/// client skips them).
pub fn reply(data: &[u8]) {
    if data.len() < REPLY_PREFIX {
        return;
    }
    let n = decoders();
    let which = usize::from(u16::from_be_bytes([data[0], data[1]])) % n;
    let cx = ctx_of(data[2]);
    let mut a: Args = [0; 4];
    for (k, w) in a.iter_mut().enumerate() {
        *w = i32::from(i16::from_be_bytes([data[3 + 2 * k], data[4 + 2 * k]]));
    }
    let stream = &data[REPLY_PREFIX..];
    let mut resp = Vec::new();
    for (h, body) in frames(stream) {
        if which < CONNECT {
            connect(&h, body, &mut resp);
            continue;
        }
        if h.kind() != 0x21 || decode_response_into(body, &mut resp).is_err() {
            continue;
        }
        match HAND.get(which - CONNECT) {
            Some(d) => (d.run)(&cx, &a, &resp),
            None => {
                let f = &fwlib32::spec::FUNCS[which - CONNECT - HAND.len()];
                go(Described::new(f, &a), &cx, &resp);
            }
        }
    }
}

/// The connect step's answers: the open body (its class, paths, axes and
/// the cnc_sysinfo_ex words), then the start-up data answers as
/// src/client/pair.rs reads them.
fn connect(h: &FrameHeader, body: &[u8], resp: &mut Vec<RespSub>) {
    if h.kind() == 0x01 {
        if let Ok(open) = OpenBody::decode(h.version, body) {
            black_box((open.class(), open.path_words(), open.system_ex(3)));
            black_box((open.maxpath_no(), open.max_spindles(), open.frame_version()));
            for p in 0..=open.path_count() + 1 {
                black_box(open.max_axes(p));
            }
        }
    } else if h.kind() == 0x21 && decode_response_into(body, resp).is_ok() {
        for i in 0..resp.len() {
            let _ = black_box(call::payload::<st::SysInfo>(resp, i));
        }
        let _ = black_box(call::payload::<pp::Param16>(resp, 0));
    } else if h.ftype == ftype::UPLOAD_ABORT {
        black_box(pu::decode_error(body));
    }
}

/// The profiles the simulator side answers as: the built-in 30i mill and
/// its 16i and Series 15 forms.
fn profiles() -> &'static [Profile; 3] {
    static P: OnceLock<[Profile; 3]> = OnceLock::new();
    P.get_or_init(|| {
        let base = fwlib32::sim::profile::DEFAULT_PROFILE;
        let class16 = |kind: u16| {
            let t = base.replacen(
                "class = \"30i\"",
                &format!("class = \"16i\"\nkind = {kind}"),
                1,
            );
            Profile::parse(&t).expect("16i profile")
        };
        [Profile::default(), class16(1), class16(2)]
    })
}

/// The simulator's side: `data` is [profile (30i, 16i, Series 15) and
/// clock byte, then the client's frames]. A fresh machine answers every
/// frame as a session does (src/sim/session.rs), and both directions are
/// traced.
pub fn request(data: &[u8]) {
    let Some((&sel, mut stream)) = data.split_first() else {
        return;
    };
    let profile = profiles()[usize::from(sel & 3) % 3].clone();
    let mut m = Machine::new(profile);
    let at = m.started + Duration::from_millis(u64::from(sel >> 2) * 250);
    let open = m.open_body();
    let (version, namer) = (open.frame_version(), Namer::new(open.class()));
    // As many frames as a connection could send in one go.
    for _ in 0..64 {
        let Ok(Some((frame, used))) = Frame::decode(stream) else {
            return;
        };
        stream = &stream[used..];
        let reply = match frame.ftype {
            ftype::DATA_REQ => {
                let Ok(subs) = decode_request(&frame.body) else {
                    return;
                };
                black_box(namer.request(&frame, &subs));
                m.advance(at);
                let resp: Vec<RespSub> = subs.iter().map(|s| m.answer(s)).collect();
                // A described function's answer decodes as the client decodes it.
                for (s, r) in subs.iter().zip(&resp) {
                    if let Some(f) = for_request(s, open.class()) {
                        let args = fwlib32::proto::described::args_of(f, open.class(), s);
                        let _ = black_box(fwlib32::proto::described::decode(f, &args, &r.payload));
                    }
                }
                let r = Frame::new(version, ftype::DATA_RESP, encode_response(&resp));
                black_box(namer.answer(&r, &subs, &resp));
                r
            }
            ftype::UPLOAD_START_REQ => {
                black_box(namer.request(&frame, &[]));
                let (out, _) = fwlib32::sim::session::upload(&mut m, version, &frame);
                black_box(out);
                continue;
            }
            ftype::OPEN_REQ => Frame::new(version, ftype::OPEN_RESP, m.open_body().to_bytes()),
            _ => {
                black_box(namer.request(&frame, &[]));
                continue;
            }
        };
        black_box(reply.encode());
    }
}

/// The profile loader: `data` as TOML text; a profile it accepts makes a
/// machine whose start-up answers (open, sysinfo per path) are encoded.
pub fn profile(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(p) = Profile::parse(text) else {
        return;
    };
    let _ = black_box(p.check_faults(3));
    black_box(fwlib32::sim::fleet::vary(&p, 3));
    let paths = p.paths.len() as u16;
    let mut m = Machine::new(p);
    black_box(m.open_body().to_bytes());
    for path in 1..=paths {
        for cmd in [fwlib32::proto::cmd::SYSINFO, fwlib32::proto::cmd::STATINFO] {
            let mut q = fwlib32::proto::packet::ReqSub::cnc(cmd, &[]);
            q.path = path;
            black_box(m.answer(&q));
        }
    }
    let at = m.started + Duration::from_secs(1);
    m.advance(at);
}
