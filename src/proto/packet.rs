//! Data frames (0x2101 / 0x2102): a counted list of subpackets (SPEC.md §4).

use super::wire::{DecodeError, Reader, Writer};

/// Subpacket class words (src/spec/commands.rs).
pub use crate::spec::commands::{CLASS_CNC, CLASS_PMC};

/// The most answer payload FANUC's library asks a CNC for in one subpacket
/// (1428 bytes): record counts and byte lengths sent in a request are cut
/// to what fits in it (cnc_rdalmmsg, cnc_rdalminfo, cnc_rdalmhistry,
/// cnc_rdexecprog).
pub const MAX_ANSWER: usize = 1428;

/// `n` records of `size` bytes, cut to what fits in [`MAX_ANSWER`].
pub fn answer_records(n: i32, size: usize) -> i32 {
    n.min((MAX_ANSWER / size) as i32)
}

const REQ_FIXED: usize = 28;
const RESP_FIXED: usize = 16;

/// One command block of a request.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ReqSub {
    pub class: u16,
    pub path: u16,
    pub cmd: u16,
    pub args: [i32; 5],
    pub payload: Vec<u8>,
}

impl ReqSub {
    /// A CNC-class subpacket. Path 0 means "the handle's current path": the
    /// session stamps it before sending.
    pub fn cnc(cmd: u16, args: &[i32]) -> ReqSub {
        ReqSub::with_class(CLASS_CNC, cmd, args)
    }
    /// A PMC-class subpacket: always path 1 (the PMC is not per path; FANUC's
    /// library sends path 1 whatever the handle's current path).
    pub fn pmc(cmd: u16, args: &[i32]) -> ReqSub {
        ReqSub {
            path: 1,
            ..ReqSub::with_class(CLASS_PMC, cmd, args)
        }
    }
    fn with_class(class: u16, cmd: u16, args: &[i32]) -> ReqSub {
        let mut a = [0i32; 5];
        for (d, s) in a.iter_mut().zip(args) {
            *d = *s;
        }
        ReqSub {
            class,
            path: 0,
            cmd,
            args: a,
            payload: Vec::new(),
        }
    }
    /// A write-type subpacket: arg 5 carries the payload length.
    pub fn with_payload(mut self, payload: Vec<u8>) -> ReqSub {
        self.args[4] = payload.len() as i32;
        self.payload = payload;
        self
    }
}

/// One result block of a response.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct RespSub {
    pub class: u16,
    pub path: u16,
    pub cmd: u16,
    pub error: i16,
    pub detail1: u16,
    pub detail2: u16,
    pub payload: Vec<u8>,
}

impl RespSub {
    /// The answer to `req` carrying `payload`.
    pub fn ok(req: &ReqSub, payload: Vec<u8>) -> RespSub {
        RespSub {
            class: req.class,
            path: req.path,
            cmd: req.cmd,
            payload,
            ..RespSub::default()
        }
    }
    /// The answer to `req` carrying a CNC error code.
    pub fn err(req: &ReqSub, error: i16, detail1: u16, detail2: u16) -> RespSub {
        RespSub {
            class: req.class,
            path: req.path,
            cmd: req.cmd,
            error,
            detail1,
            detail2,
            payload: Vec::new(),
        }
    }
}

/// Encodes a request body: u16 count, then the subpackets.
pub fn encode_request(subs: &[ReqSub]) -> Vec<u8> {
    let mut w = Writer::with_capacity(2 + subs.len() * REQ_FIXED);
    encode_request_into(subs, &mut w);
    w.into_vec()
}

/// [`encode_request`], appended to `w` (a frame being built in a reused buffer).
/// Each subpacket's fixed part is put together on the stack and appended
/// whole (this runs on every call).
pub fn encode_request_into(subs: &[ReqSub], w: &mut Writer) {
    let payloads: usize = subs.iter().map(|s| s.payload.len()).sum();
    w.buf.reserve(2 + subs.len() * REQ_FIXED + payloads);
    w.u16(subs.len() as u16);
    for s in subs {
        let mut f = [0u8; REQ_FIXED];
        f[0..2].copy_from_slice(&((REQ_FIXED + s.payload.len()) as u16).to_be_bytes());
        f[2..4].copy_from_slice(&s.class.to_be_bytes());
        f[4..6].copy_from_slice(&s.path.to_be_bytes());
        f[6..8].copy_from_slice(&s.cmd.to_be_bytes());
        for (k, a) in s.args.iter().enumerate() {
            f[8 + 4 * k..12 + 4 * k].copy_from_slice(&a.to_be_bytes());
        }
        w.bytes(&f);
        w.bytes(&s.payload);
    }
}

/// Decodes a request body (the simulator's side).
pub fn decode_request(body: &[u8]) -> Result<Vec<ReqSub>, DecodeError> {
    decode_list(body, REQ_FIXED, |r, len| {
        let class = r.u16()?;
        let path = r.u16()?;
        let cmd = r.u16()?;
        let mut args = [0i32; 5];
        for a in &mut args {
            *a = r.i32()?;
        }
        let payload = r.bytes(len - REQ_FIXED)?.to_vec();
        Ok(ReqSub {
            class,
            path,
            cmd,
            args,
            payload,
        })
    })
}

/// Encodes a response body.
pub fn encode_response(subs: &[RespSub]) -> Vec<u8> {
    let mut w = Writer::with_capacity(
        2 + subs
            .iter()
            .map(|s| RESP_FIXED + s.payload.len())
            .sum::<usize>(),
    );
    w.u16(subs.len() as u16);
    for s in subs {
        w.u16((RESP_FIXED + s.payload.len()) as u16);
        w.u16(s.class);
        w.u16(s.path);
        w.u16(s.cmd);
        w.i16(s.error);
        w.u16(s.detail1);
        w.u16(s.detail2);
        w.u16(s.payload.len() as u16);
        w.bytes(&s.payload);
    }
    w.into_vec()
}

/// Decodes a response body, checking the count and that the subpacket
/// lengths add up to the body exactly. The payload-length word bounds the
/// payload (FANUC's library uses no more than it announces).
pub fn decode_response(body: &[u8]) -> Result<Vec<RespSub>, DecodeError> {
    let mut out = Vec::new();
    decode_response_into(body, &mut out)?;
    Ok(out)
}

/// [`decode_response`] into `out`, reusing its entries and their payload
/// buffers (a connection decodes every answer into the same list, so a
/// call allocates nothing for its answer once the list has grown). After
/// an error `out` holds nothing meaningful.
pub fn decode_response_into(body: &[u8], out: &mut Vec<RespSub>) -> Result<(), DecodeError> {
    // What a hostile answer can leave behind stays small.
    out.truncate(32);
    let n = check_lengths(body, RESP_FIXED)?;
    let be = |b: &[u8], i: usize| u16::from_be_bytes([b[i], b[i + 1]]);
    let mut at = 2;
    for k in 0..n {
        // Whole subpackets, their lengths checked above.
        let len = be(body, at) as usize;
        let s = &body[at..at + len];
        at += len;
        let plen = be(s, 14) as usize;
        let Some(payload) = s[RESP_FIXED..].get(..plen) else {
            return Err(DecodeError::Invalid("payload length exceeds its subpacket"));
        };
        if k == out.len() {
            out.push(RespSub::default());
        }
        let r = &mut out[k];
        r.class = be(s, 2);
        r.path = be(s, 4);
        r.cmd = be(s, 6);
        r.error = be(s, 8) as i16;
        r.detail1 = be(s, 10);
        r.detail2 = be(s, 12);
        r.payload.clear();
        r.payload.extend_from_slice(payload);
    }
    out.truncate(n);
    Ok(())
}

/// The first answered subpacket that does not echo its request's class
/// and command, in order (None when every one does). A CNC echoes both in
/// each result block; one that does not answers another request, or
/// another order, and its answer is not this call's. Only the subpackets
/// both lists hold are compared: a missing one is the decoders' error.
/// FANUC's library does not look (README.md, "Where we differ").
pub fn echo_mismatch(req: &[ReqSub], resp: &[RespSub]) -> Option<usize> {
    req.iter()
        .zip(resp)
        .position(|(q, r)| q.class != r.class || q.cmd != r.cmd)
}

fn decode_list<T>(
    body: &[u8],
    fixed: usize,
    mut one: impl FnMut(&mut Reader<'_>, usize) -> Result<T, DecodeError>,
) -> Result<Vec<T>, DecodeError> {
    let mut out = Vec::new();
    for_each_sub(body, fixed, |r, len| {
        out.push(one(r, len)?);
        Ok(())
    })?;
    Ok(out)
}

/// Checks a counted list of subpackets (the count is not zero, the length
/// words add up to the body exactly), then runs `one` on each subpacket,
/// positioned after its length word, with that length.
fn for_each_sub(
    body: &[u8],
    fixed: usize,
    mut one: impl FnMut(&mut Reader<'_>, usize) -> Result<(), DecodeError>,
) -> Result<(), DecodeError> {
    let count = check_lengths(body, fixed)?;
    let mut r = Reader::new(&body[2..]);
    for _ in 0..count {
        // The length word, checked above.
        let len = r.u16()? as usize;
        let start = r.position();
        one(&mut r, len)?;
        debug_assert_eq!(r.position() - start, len - 2);
    }
    Ok(())
}

/// Checks a counted list of subpackets: the count is not zero, and the
/// length words, each at least `fixed`, add up to the body exactly.
/// Lengths are checked against the body before anything is parsed, so a
/// lie in one length word cannot make us read another subpacket's bytes.
/// Gives the count.
fn check_lengths(body: &[u8], fixed: usize) -> Result<usize, DecodeError> {
    let Some(c) = body.get(..2) else {
        return Err(DecodeError::Short {
            need: 2,
            have: body.len(),
        });
    };
    let count = u16::from_be_bytes([c[0], c[1]]) as usize;
    if count == 0 {
        return Err(DecodeError::CountZero);
    }
    let mut at = 2usize;
    for _ in 0..count {
        let Some(l) = body.get(at..at + 2) else {
            return Err(DecodeError::SubLenTooBig);
        };
        let len = u16::from_be_bytes([l[0], l[1]]) as usize;
        if len < fixed {
            return Err(DecodeError::Invalid(
                "subpacket shorter than its fixed part",
            ));
        }
        at += len;
        if at > body.len() {
            return Err(DecodeError::SubLenTooBig);
        }
    }
    if at != body.len() {
        return Err(DecodeError::SubLenTooSmall);
    }
    Ok(count)
}
