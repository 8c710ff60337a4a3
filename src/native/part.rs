//! One typed read as data: the subpackets it sends (a `proto` [`Call`]'s),
//! a bound on its answer's size, and how its answer becomes the typed
//! value. A single read sends one part in a frame; a batch packs several.

use super::error::{Error, Result};
use crate::proto::call::{Call, Ctx};
use crate::proto::packet::{ReqSub, RespSub};
use std::any::Any;

/// Bytes of a response subpacket's fixed fields (SPEC.md §4).
pub(crate) const RESP_HEADER: usize = 16;

/// A typed read.
pub(crate) trait Part {
    type Out;
    /// The FOCAS function it is (named in errors).
    fn call(&self) -> &'static str;
    fn subs(&self, cx: &Ctx) -> Vec<ReqSub>;
    /// Most bytes its answer adds to a response body (payloads and
    /// subpacket headers).
    fn answer_max(&self, cx: &Ctx) -> usize;
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Out>;
}

/// A `proto` call whose output `then` turns into the typed value;
/// `payload` bounds the answer's payload bytes.
pub(crate) struct Via<C, F> {
    pub call: &'static str,
    pub c: C,
    pub payload: usize,
    pub then: F,
}

/// A part reading `c`, its output turned by `then`.
pub(crate) fn via<C, T, F>(call: &'static str, c: C, payload: usize, then: F) -> Via<C, F>
where
    C: Call,
    F: Fn(C::Output) -> Result<T>,
{
    Via {
        call,
        c,
        payload,
        then,
    }
}

impl<C, T, F> Part for Via<C, F>
where
    C: Call,
    F: Fn(C::Output) -> Result<T>,
{
    type Out = T;
    fn call(&self) -> &'static str {
        self.call
    }
    fn subs(&self, cx: &Ctx) -> Vec<ReqSub> {
        self.c.request(cx)
    }
    fn answer_max(&self, cx: &Ctx) -> usize {
        self.payload + RESP_HEADER * self.c.request(cx).len()
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<T> {
        let raw = self
            .c
            .decode(cx, resp)
            .map_err(|e| Error::of(self.call, e))?;
        (self.then)(raw)
    }
}

/// A value known without traffic (what the CNC told at connect time).
pub(crate) struct Ready<T>(pub Result<T>);

impl<T: Clone> Part for Ready<T> {
    type Out = T;
    fn call(&self) -> &'static str {
        match &self.0 {
            Ok(_) => "",
            Err(e) => e.call(),
        }
    }
    fn subs(&self, _: &Ctx) -> Vec<ReqSub> {
        Vec::new()
    }
    fn answer_max(&self, _: &Ctx) -> usize {
        0
    }
    fn decode(&self, _: &Ctx, _: &[RespSub]) -> Result<T> {
        self.0.clone()
    }
}

/// A part refused before any traffic (a bad argument): its error.
pub(crate) struct Failed<T>(Error, std::marker::PhantomData<fn() -> T>);

impl<T> Failed<T> {
    pub(crate) fn new(e: Error) -> Failed<T> {
        Failed(e, std::marker::PhantomData)
    }
}

impl<T> Part for Failed<T> {
    type Out = T;
    fn call(&self) -> &'static str {
        self.0.call()
    }
    fn subs(&self, _: &Ctx) -> Vec<ReqSub> {
        Vec::new()
    }
    fn answer_max(&self, _: &Ctx) -> usize {
        0
    }
    fn decode(&self, _: &Ctx, _: &[RespSub]) -> Result<T> {
        Err(self.0.clone())
    }
}

/// A part whose output a function turns further.
pub(crate) struct Then<P, F>(pub P, pub F);

impl<P: Part, T, F: Fn(P::Out) -> Result<T>> Part for Then<P, F> {
    type Out = T;
    fn call(&self) -> &'static str {
        self.0.call()
    }
    fn subs(&self, cx: &Ctx) -> Vec<ReqSub> {
        self.0.subs(cx)
    }
    fn answer_max(&self, cx: &Ctx) -> usize {
        self.0.answer_max(cx)
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<T> {
        (self.1)(self.0.decode(cx, resp)?)
    }
}

/// A part whose output type is erased, for batches.
pub(crate) trait AnyPart: Send {
    fn call(&self) -> &'static str;
    fn subs(&self, cx: &Ctx) -> Vec<ReqSub>;
    fn answer_max(&self, cx: &Ctx) -> usize;
    /// A `Box<Result<Out>>`.
    fn decode_any(&self, cx: &Ctx, resp: &[RespSub]) -> Box<dyn Any + Send>;
}

impl<P> AnyPart for P
where
    P: Part + Send,
    P::Out: Send + 'static,
{
    fn call(&self) -> &'static str {
        Part::call(self)
    }
    fn subs(&self, cx: &Ctx) -> Vec<ReqSub> {
        Part::subs(self, cx)
    }
    fn answer_max(&self, cx: &Ctx) -> usize {
        Part::answer_max(self, cx)
    }
    fn decode_any(&self, cx: &Ctx, resp: &[RespSub]) -> Box<dyn Any + Send> {
        Box::new(self.decode(cx, resp))
    }
}

/// One part as a call: its typed result never fails the exchange, so the
/// caller tells transport errors (`Err`) from the part's own (`Ok(Err)`).
pub(crate) struct One<'a, P>(pub &'a P);

impl<P: Part> Call for One<'_, P> {
    type Output = Result<P::Out>;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        self.0.subs(cx)
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> crate::error::Result<Self::Output> {
        Ok(self.0.decode(cx, resp))
    }
}

/// Several parts in one request frame: their subpackets one after the
/// other; each part decodes its own share of the answer.
pub(crate) struct Frame<'a>(pub &'a [Box<dyn AnyPart>]);

impl Call for Frame<'_> {
    type Output = Vec<Box<dyn Any + Send>>;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        self.0.iter().flat_map(|p| p.subs(cx)).collect()
    }
    /// A CNC answering fewer subpackets than asked leaves the later parts
    /// short: they give their own protocol errors.
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> crate::error::Result<Self::Output> {
        let mut at = 0;
        Ok(self
            .0
            .iter()
            .map(|p| {
                let n = p.subs(cx).len();
                let from = at.min(resp.len());
                let to = (at + n).min(resp.len());
                at += n;
                p.decode_any(cx, &resp[from..to])
            })
            .collect())
    }
}
