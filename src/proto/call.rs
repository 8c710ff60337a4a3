//! A FOCAS call as data: the subpackets to send and how to read the answer.
//! Sans-IO: the client session sends what `request` returns and hands the
//! response subpackets to `decode`; the codec tests do the same without sockets.

use super::open::CncClass;
use super::packet::{ReqSub, RespSub};
use super::wire::Wire;
use crate::error::{Error, Result};
use std::marker::PhantomData;

/// What a call needs to know about the CNC it talks to.
#[derive(Debug, Clone, Copy)]
pub struct Ctx {
    pub class: CncClass,
    /// Maximum axes of the current path (record count of all-axes answers).
    pub max_axes: u16,
    /// Maximum spindles (open body); the 16i class uses it as the record
    /// count of spindle answers (no 0xa4 count subpackets).
    pub max_spindles: u16,
    /// The handle's current path (1-based).
    pub path: u16,
    /// The machine type of the current path from the start-up sysinfo
    /// (" M", " T", " W" wire cut ...).
    pub mt_type: [u8; 2],
}

impl Ctx {
    /// The current path is a wire-cut machine (mt_type " W").
    pub fn wire_cut(&self) -> bool {
        self.mt_type == *b" W"
    }

    /// `max_axes` as a record count, capped at MAX_AXIS (32).
    pub fn axes(&self) -> usize {
        (self.max_axes as usize).min(crate::types::MAX_AXIS)
    }
}

impl Default for Ctx {
    fn default() -> Self {
        Ctx {
            class: CncClass::Series30,
            max_axes: 32,
            max_spindles: 8,
            path: 1,
            mt_type: *b" M",
        }
    }
}

pub trait Call {
    type Output;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub>;
    /// [`Call::request`] appended to `out`, a list the connection reuses:
    /// the calls made most override it so that they allocate nothing.
    fn request_into(&self, cx: &Ctx, out: &mut Vec<ReqSub>) {
        out.extend(self.request(cx));
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Output>;
}

/// A [`Call`] with its output type erased: the request, and a decoder that
/// keeps what it decodes. The client's exchange path takes this, so its
/// code exists once, not once per call type.
pub struct Erased<'a> {
    /// Appends the request's subpackets (see [`Call::request_into`]).
    pub request: &'a dyn Fn(&Ctx, &mut Vec<ReqSub>),
    pub decode: &'a mut dyn FnMut(&Ctx, &[RespSub]) -> Result<()>,
}

/// Runs `c` through `run` (an exchange path that takes an [`Erased`]
/// call) and gives what `c` decoded.
pub fn erased<C: Call>(
    c: &C,
    run: impl FnOnce(&mut Erased<'_>) -> Result<()>,
) -> Result<C::Output> {
    let mut out = None;
    run(&mut Erased {
        request: &|cx, out| c.request_into(cx, out),
        decode: &mut |cx, resp| {
            out = Some(c.decode(cx, resp)?);
            Ok(())
        },
    })?;
    out.ok_or_else(|| Error::protocol(crate::error::detail::SUB_MISSING, "no answer was decoded"))
}

/// Subpacket `i` of a response, its error code turned into an [`Error`].
pub fn sub(resp: &[RespSub], i: usize) -> Result<&RespSub> {
    let s = resp.get(i).ok_or_else(|| {
        Error::protocol(
            crate::error::detail::SUB_MISSING,
            format!(
                "response has {} subpackets, expected at least {}",
                resp.len(),
                i + 1
            ),
        )
    })?;
    if s.error != 0 {
        return Err(Error::Cnc {
            code: s.error,
            detail1: s.detail1,
            detail2: s.detail2,
        });
    }
    Ok(s)
}

/// The payload of subpacket `i`, decoded as `T`.
pub fn payload<T: Wire>(resp: &[RespSub], i: usize) -> Result<T> {
    Ok(T::from_bytes(&sub(resp, i)?.payload)?)
}

/// The payload of subpacket `i` decoded as `T` after zero-extending it to
/// `len` bytes: FANUC's library reads a short answer's missing fields from
/// what follows in its buffer, zeros in every one-subpacket case recorded
/// (docs/protocol/framing.md), so a fixed-size answer cut short gives zeros in the
/// fields it lacks.
pub fn payload_padded<T: Wire>(resp: &[RespSub], i: usize, len: usize) -> Result<T> {
    let p = &sub(resp, i)?.payload;
    if p.len() >= len {
        return Ok(T::from_bytes(p)?);
    }
    let mut b = p.clone();
    b.resize(len, 0);
    Ok(T::from_bytes(&b)?)
}

/// The commonest call: one subpacket whose payload decodes as `T`.
#[derive(Debug, Clone)]
pub struct Single<T> {
    pub sub: ReqSub,
    /// Zero-extend a shorter payload to this many bytes before decoding
    /// ([`Single::padded`]); 0: a short payload is EW_PROTOCOL.
    pad: usize,
    _out: PhantomData<fn() -> T>,
}

impl<T: Wire> Single<T> {
    pub fn new(sub: ReqSub) -> Self {
        Single {
            sub,
            pad: 0,
            _out: PhantomData,
        }
    }
}

impl<T: Wire + Default> Single<T> {
    /// A fixed-size answer read as FANUC's library reads it: missing bytes
    /// are zeros (see [`payload_padded`]).
    pub fn padded(sub: ReqSub) -> Self {
        Single {
            sub,
            pad: T::default().to_bytes().len(),
            _out: PhantomData,
        }
    }
}

impl<T: Wire> Call for Single<T> {
    type Output = T;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![self.sub.clone()]
    }
    fn request_into(&self, _: &Ctx, out: &mut Vec<ReqSub>) {
        out.push(self.sub.clone());
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<T> {
        payload_padded(resp, 0, self.pad)
    }
}

/// The whole records of subpacket `i`'s payload; a ragged tail (part of a
/// record) is ignored, as FANUC's library ignores it.
pub fn records<T: Wire + Default>(resp: &[RespSub], i: usize) -> Result<Vec<T>> {
    let p = &sub(resp, i)?.payload;
    let size = T::default().to_bytes().len().max(1);
    p.chunks_exact(size)
        .map(|c| T::from_bytes(c).map_err(Into::into))
        .collect()
}
