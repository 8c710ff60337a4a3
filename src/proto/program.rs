//! Program execution: numbers, names, blocks, modal data, timers.

use super::call::{Call, Ctx, Single, payload};
pub use super::cmd::{
    EXEPRGNAME, EXEPRGNAME2, GETTIMER, MODAL_AUX, MODAL_G, PDF_ADD, PDF_ALLDIR, PDF_COPY, PDF_DEL,
    PDF_DELALL, PDF_DELLINE, PDF_DRIVE, PDF_INF, PDF_MOVE, PDF_RDACTPT, PDF_RDCURDIR, PDF_RDLINE,
    PDF_RDMAIN, PDF_RENAME, PDF_SLCTMAIN, PDF_SUBDIR, PDF_SUBDIRN, PDF_WRACTPT, PDF_WRCURDIR,
    PDF_WRLINE, RDEXECPROG, RDMDIPROG, RDOPMODE, RDPROGDIR, RDPROGINFO, RDTIMER, SETTIMER,
    WRMDIPROG,
};
use super::packet::{ReqSub, RespSub};
use super::wire::{DecodeError, Reader, Wire, Writer};
use crate::error::Result;
use crate::wire_struct;

// --- program ---

wire_struct! {
    /// Payload of 0x0007 (cnc_rdproginfo): programs stored and free, bytes
    /// used and free (missing bytes read as zeros, as FANUC's library).
    pub struct ProgInfo {
        pub reg_prg: i32,
        pub unreg_prg: i32,
        pub used_mem: i32,
        pub unused_mem: i32,
    }
}

/// Records FANUC's library asks for per 0x0006 exchange.
pub const PROGDIR_CHUNK: i32 = 19;

wire_struct! {
    /// Payload of 0x0162 (cnc_rdactpt): program number and block pointer.
    pub struct ActPt {
        pub prog_no: i32,
        pub blk_no: i32,
    }
}

wire_struct! {
    /// Payload of 0x0120 (cnc_rdtimer): minutes and milliseconds.
    pub struct Timer {
        pub minute: i32,
        pub msec: i32,
    }
}

wire_struct! {
    /// Payload of 0x0045 (cnc_gettimer) and of the 0x0046 request (cnc_settimer).
    pub struct Clock {
        pub year: i16,
        pub month: i16,
        pub day: i16,
        pub hour: i16,
        pub minute: i16,
        pub second: i16,
    }
}

wire_struct! {
    /// Payload of 0x004d (cnc_toolnum).
    pub struct ToolNum {
        pub datano: i32,
        pub kind: i32,
        pub data: i32,
    }
}

wire_struct! {
    /// Payload of 0x008b (cnc_rdntool).
    pub struct NTool {
        pub datano: i32,
        pub data: i32,
    }
}

wire_struct! {
    /// One G-code group of 0x0021: code within the group, flag (bit 0: commanded in the block).
    pub struct GCode {
        pub code: u8,
        pub flag: u8,
    }
}

wire_struct! {
    /// One record of 0x0022: value, then flag1 / flag2 in bytes 5 and 7.
    pub struct AuxCode {
        pub value: i32,
        pub pad1: u8,
        pub flag1: u8,
        pub pad2: u8,
        pub flag2: u8,
    }
}

/// Payload of 0x0020 (cnc_rdexecprog): block number and program text.
/// `blknum` None is the empty payload, an empty result (FANUC's library
/// reads past its buffer there).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ExecProg {
    pub blknum: Option<i32>,
    pub text: Vec<u8>,
}

impl Wire for ExecProg {
    fn encode(&self, w: &mut Writer) {
        if let Some(b) = self.blknum {
            w.i32(b);
            w.bytes(&self.text);
        }
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        if r.remaining() == 0 {
            return Ok(ExecProg::default());
        }
        let blknum = r.i32()?;
        let text = r.rest().to_vec();
        r.bytes(text.len())?;
        Ok(ExecProg {
            blknum: Some(blknum),
            text,
        })
    }
}

/// A payload as bytes: 0x0036 / 0x0037, the MDI program's text.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct PathName(pub Vec<u8>);

impl Wire for PathName {
    fn encode(&self, w: &mut Writer) {
        w.bytes(&self.0);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let b = r.rest().to_vec();
        r.bytes(b.len())?;
        Ok(PathName(b))
    }
}

/// Payload of 0x0021: one [code, flag] pair per group (possibly none). A
/// trailing odd byte is ignored.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct GModal(pub Vec<GCode>);

impl Wire for GModal {
    fn encode(&self, w: &mut Writer) {
        self.0.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let n = r.remaining() / 2;
        let mut whole = Reader::new(r.bytes(n * 2)?);
        Ok(GModal(Vec::decode(&mut whole)?))
    }
}

/// Payload of 0x0022: 8-byte records (possibly none); a ragged tail is
/// no record (FANUC's library counts length / 8 of them).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct AuxModal(pub Vec<AuxCode>);

impl Wire for AuxModal {
    fn encode(&self, w: &mut Writer) {
        self.0.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let n = r.remaining() / 8;
        let mut whole = Reader::new(r.bytes(n * 8)?);
        let v = Vec::decode(&mut whole)?;
        r.bytes(r.remaining())?;
        Ok(AuxModal(v))
    }
}

/// (1,0x20)\[length\], cut to what fits in one answer.
pub fn rdexecprog(length: u16) -> Single<ExecProg> {
    let n = i32::from(length).min(super::packet::MAX_ANSWER as i32);
    Single::new(ReqSub::cnc(RDEXECPROG, &[n]))
}

pub fn gettimer(kind: i16) -> Single<Clock> {
    Single::padded(ReqSub::cnc(GETTIMER, &[i32::from(kind)]))
}

/// cnc_settimer: the six words with the half of `kind` filled (0 date, 1 time)
/// and zeros in the other half; the reply's payload is not used.
#[derive(Debug, Clone)]
pub struct SetTimer {
    pub kind: i16,
    pub clock: Clock,
}

impl Call for SetTimer {
    type Output = ();
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(SETTIMER, &[i32::from(self.kind)]).with_payload(self.clock.to_bytes())]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        super::call::sub(resp, 0).map(|_| ())
    }
}

/// What cnc_modal reads for a `type`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModalKind {
    /// 0x0021 with this code: G-code groups.
    G(i32),
    /// 0x0022 with this code: other codes, written in payload order.
    Aux(i32),
    /// 0x0022 code −1: every other code, reordered into raux1\[27\] by [`AUX_ORDER`].
    AuxAll,
}

/// Codes of types 100..=126 (FANUC's table); also the payload record each
/// raux1\[k\] of type −2 comes from.
pub const AUX_ORDER: [i32; 27] = [
    1, 3, 4, 5, 6, 10, 11, 21, 22, 20, 18, 19, 0, 2, 7, 8, 9, 16, 17, 23, 24, 25, 26, 27, 28, 12,
    13,
];

/// cnc_modal's type → subpacket map (FANUC's library; other types are EW_NUMBER).
pub fn modal_kind(kind: i16) -> Option<ModalKind> {
    let t = i32::from(kind);
    Some(match t {
        -1..=99 => ModalKind::G(t),
        -4 => ModalKind::G(-2),
        -5 => ModalKind::G(-3),
        300..=399 => ModalKind::G(t - 200),
        100..=126 => ModalKind::Aux(AUX_ORDER[(t - 100) as usize]),
        200..=299 => ModalKind::Aux(t - 100),
        -2 => ModalKind::AuxAll,
        -3 => ModalKind::Aux(-2),
        _ => return None,
    })
}

/// The decoded answer of cnc_modal.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Modal {
    G(GModal),
    Aux(AuxModal),
}

#[derive(Debug, Clone, Copy)]
pub struct ModalCall {
    pub kind: ModalKind,
    pub block: i16,
}

impl Call for ModalCall {
    type Output = Modal;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let b = i32::from(self.block);
        vec![match self.kind {
            ModalKind::G(c) => ReqSub::cnc(MODAL_G, &[c, b]),
            ModalKind::Aux(c) => ReqSub::cnc(MODAL_AUX, &[c, b]),
            ModalKind::AuxAll => ReqSub::cnc(MODAL_AUX, &[-1, b]),
        }]
    }
    /// An answer with fewer records than asked, or none, is data (FANUC's
    /// library returns EW_OK and writes what there is).
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Modal> {
        Ok(match self.kind {
            ModalKind::G(_) => Modal::G(payload(resp, 0)?),
            _ => Modal::Aux(payload(resp, 0)?),
        })
    }
}

/// One 72-byte record of 0x0006: number, size in bytes, comment (as the CNC
/// sends it, with its parentheses), modification date (year, month, day,
/// hour, minute, one more word).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DirEntry {
    pub number: i32,
    pub length: i32,
    pub comment: [u8; 52],
    pub date: [u16; 6],
}

impl Default for DirEntry {
    fn default() -> Self {
        DirEntry {
            number: 0,
            length: 0,
            comment: [0; 52],
            date: [0; 6],
        }
    }
}

impl DirEntry {
    /// The comment up to its first NUL.
    pub fn comment_text(&self) -> &[u8] {
        self.comment.split(|c| *c == 0).next().unwrap_or(&[])
    }
}

impl Wire for DirEntry {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.number);
        w.i32(self.length);
        w.bytes(&self.comment);
        for d in self.date {
            w.u16(d);
        }
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let number = r.i32()?;
        let length = r.i32()?;
        let comment = r.array()?;
        let mut date = [0u16; 6];
        for d in &mut date {
            *d = r.u16()?;
        }
        Ok(DirEntry {
            number,
            length,
            comment,
            date,
        })
    }
}

/// Payload of 0x0006: the records (empty: no program from `top` on); a
/// ragged tail is ignored, as FANUC's library ignores it.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ProgDir(pub Vec<DirEntry>);

impl Wire for ProgDir {
    fn encode(&self, w: &mut Writer) {
        self.0.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let n = r.remaining() / 72;
        (0..n)
            .map(|_| DirEntry::decode(r))
            .collect::<Result<_, _>>()
            .map(ProgDir)
    }
}

/// One 0x0006 exchange: up to `count` programs numbered `top` or more.
pub fn progdir(top: i32, count: i32, code: i32) -> Single<ProgDir> {
    Single::new(ReqSub::cnc(RDPROGDIR, &[top, count, code]))
}

/// cnc_rdprogdir3's type → 0x0006 code (FANUC's library: 0→0, 1→1, 2→3).
pub fn progdir3_code(kind: i16) -> Option<i32> {
    match kind {
        0 => Some(0),
        1 => Some(1),
        2 => Some(3),
        _ => None,
    }
}

/// cnc_rdprogdir's text (FANUC's library, learnt from it with a fake CNC):
/// type 0 "O1O1000%", type 1 "%\nO1\nO1000(COMMENT)\n%" (the leading
/// "%\n" only with at least one entry), type 2 "O1100O1000(COMMENT)2048%"
/// (number, comment, size run together). No NUL terminator.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct DirText {
    kind: i16,
    room: usize,
    body: Vec<u8>,
    /// An entry did not fit.
    pub full: bool,
}

impl DirText {
    pub fn new(kind: i16, room: u16) -> Self {
        DirText {
            kind,
            room: room as usize,
            ..DirText::default()
        }
    }

    fn prefix(&self) -> usize {
        if self.kind == 1 { 2 } else { 0 }
    }

    /// Appends one entry if it and the final "%" fit in `room` bytes;
    /// false (and `full`) when it does not.
    pub fn push(&mut self, e: &DirEntry) -> bool {
        let mut t = format!("O{}", e.number).into_bytes();
        match self.kind {
            0 => {}
            1 => {
                t.extend_from_slice(e.comment_text());
                t.push(b'\n');
            }
            _ => {
                t.extend_from_slice(e.comment_text());
                t.extend_from_slice(e.length.to_string().as_bytes());
            }
        }
        if self.prefix() + self.body.len() + t.len() + 1 > self.room {
            self.full = true;
            return false;
        }
        self.body.extend_from_slice(&t);
        true
    }

    /// The finished text (at most `room` bytes when `room` ≥ 1).
    pub fn finish(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.body.len() + 3);
        if self.kind == 1 && !self.body.is_empty() {
            out.extend_from_slice(b"%\n");
        }
        out.extend_from_slice(&self.body);
        out.push(b'%');
        out
    }
}
