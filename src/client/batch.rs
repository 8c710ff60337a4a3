//! Call batching (fwlib32_ext.h: fwlib_batch_begin, fwlib_batch_end,
//! fwlib_batch_limits), client side.
//!
//! While a handle batches, each batchable read runs twice. Queued: its
//! local checks run as they always do (a failure returns at once), then
//! its exchange records the subpackets it would send ([`Batch::pending`])
//! and ends the call with [`Error::Queued`]; the exported function's body
//! is kept ([`Deferred`], by `ffi_boundary!`). At the batch's end the
//! queued subpackets go out in as few request frames as the limits allow,
//! and each kept body runs again: its exchange now takes its own share of
//! the answers ([`Batch::replay`]) and decodes it, so it writes the
//! caller's outputs and returns exactly what the same call made alone
//! would. Calls that are not batchable (writes, transfers, connection 1,
//! reads that need an earlier answer to form their next request) return
//! EW_REJECT while the handle batches, without traffic.

use super::conn::Deadline;
use super::handles::Handle;
use crate::error::{Error, Result};
use crate::ew::{EW_FUNC, EW_REJECT};
use crate::proto::call::{Call, Ctx};
use crate::proto::packet::{ReqSub, RespSub};
use std::cell::{Cell, RefCell};
use std::sync::Arc;

/// An exported function's body kept to run again at the batch's end.
pub struct Deferred(pub Box<dyn FnMut() -> Result<()>>);

// SAFETY: the body holds the caller's pointers, which the C contract keeps
// valid until fwlib_batch_end (whichever thread calls it); it runs only
// there, under the handle's batch, once.
unsafe impl Send for Deferred {}

/// How much one request frame of a batch may carry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Limits {
    pub subpackets: usize,
    /// Bytes of the frame's body (the subpacket count word and subpackets).
    pub body: usize,
}

/// One queued call.
struct Item {
    name: &'static str,
    subs: Vec<ReqSub>,
    run: Deferred,
}

/// A handle's batch (`HandleState::batch`).
#[derive(Default)]
pub struct Batch {
    pub limits: Limits,
    items: Vec<Item>,
    /// The subpackets the call being queued would send.
    pending: Option<Vec<ReqSub>>,
    /// The answers the call being replayed takes (None: not replaying).
    replay: Option<Vec<RespSub>>,
}

/// Handles batching in the process: while none does, the batchable reads
/// run as every other export (no box, no thread-local).
static ACTIVE: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// Some handle batches.
pub fn active() -> bool {
    ACTIVE.load(std::sync::atomic::Ordering::Acquire) > 0
}

/// A handle began (`true`) or ended a batch.
pub fn set_active(on: bool) {
    if on {
        ACTIVE.fetch_add(1, std::sync::atomic::Ordering::AcqRel);
    } else {
        ACTIVE.fetch_sub(1, std::sync::atomic::Ordering::AcqRel);
    }
}

thread_local! {
    /// The running export may join a batch (`ffi_read!`).
    static BATCHABLE: Cell<bool> = const { Cell::new(false) };
    /// The batching handle the running call was queued on.
    static QUEUED_ON: RefCell<Option<Arc<Handle>>> = const { RefCell::new(None) };
}

/// Runs `f` as an export that may join a batch (`ffi_read!`); the handle
/// it queued on, if any, is forgotten after [`defer`] could take it.
pub fn batchable<T>(f: impl FnOnce() -> T) -> T {
    let before = BATCHABLE.with(|c| c.replace(true));
    let r = f();
    BATCHABLE.with(|c| c.set(before));
    r
}

/// A call on handle `h`, which batches: EW_REJECT unless the running
/// export may join a batch; else `h` is where it queues.
pub fn admit(h: &Arc<Handle>) -> Result<()> {
    if !BATCHABLE.with(Cell::get) {
        return Err(Error::local(
            EW_REJECT,
            "not batchable: call it before fwlib_batch_begin or after fwlib_batch_end",
        ));
    }
    QUEUED_ON.with(|q| *q.borrow_mut() = Some(h.clone()));
    Ok(())
}

/// Forgets the handle a call that did not queue was admitted on.
pub fn forget() {
    QUEUED_ON.with(|q| q.borrow_mut().take());
}

/// Keeps the body of the call just queued (it ended with
/// [`Error::Queued`]): EW_OK, its result comes at fwlib_batch_end.
pub fn defer(name: &'static str, run: Box<dyn FnMut() -> Result<()>>) -> i16 {
    let h = QUEUED_ON.with(|q| q.borrow_mut().take());
    let mut s = h.as_ref().map(|h| h.state.lock());
    match s.as_mut().and_then(|s| s.batch.as_mut()) {
        Some(b) => match b.pending.take() {
            Some(subs) => {
                b.items.push(Item {
                    name,
                    subs,
                    run: Deferred(run),
                });
                crate::ew::EW_OK
            }
            None => crate::ew::EW_UNEXP,
        },
        None => crate::ew::EW_UNEXP,
    }
}

impl std::fmt::Debug for Batch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Batch({} queued, {:?})", self.items.len(), self.limits)
    }
}

/// A state copy keeps no batch: its calls belong to the handle.
impl Clone for Batch {
    fn clone(&self) -> Batch {
        Batch::new(self.limits)
    }
}

impl Batch {
    pub fn new(limits: Limits) -> Batch {
        Batch {
            limits,
            items: Vec::new(),
            pending: None,
            replay: None,
        }
    }

    /// Calls queued so far.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }
}

/// Sends nothing: the answers recorded for the subpackets given.
struct Raw<'a>(&'a [ReqSub]);

impl Call for Raw<'_> {
    type Output = Vec<RespSub>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        self.0.to_vec()
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<RespSub>> {
        Ok(resp.to_vec())
    }
}

/// Bytes a subpacket takes in a request body.
fn sub_len(s: &ReqSub) -> usize {
    2 + 6 + 20 + s.payload.len()
}

impl Handle {
    /// Marks the handle batching or not (counted in [`active`]).
    pub fn set_batching(&self, on: bool) {
        if self.batching.swap(on, std::sync::atomic::Ordering::AcqRel) != on {
            set_active(on);
        }
    }

    /// An exchange while the handle batches: the replayed call's answers,
    /// or (queueing) the subpackets kept and [`Error::Queued`].
    pub(super) fn batched<C: Call>(&self, c: &C, cx: &Ctx) -> Result<C::Output> {
        let mut s = self.state.lock();
        let Some(b) = s.batch.as_mut() else {
            return Err(Error::local(EW_FUNC, "the batch has ended"));
        };
        if let Some(resp) = b.replay.take() {
            drop(s);
            return c.decode(cx, &resp);
        }
        if b.pending.is_some() {
            // A second exchange of one call: not batchable after all.
            return Err(Error::local(
                EW_FUNC,
                "a call made a second exchange in a batch",
            ));
        }
        b.pending = Some(c.request(cx));
        Err(Error::Queued)
    }

    /// fwlib_batch_end: sends the queued calls, then runs each kept body
    /// against its answers (a panic caught); each call's code in queue
    /// order. `finish` turns a body's result into the code its export
    /// returns (`crate::ffi::finish`).
    pub fn end_batch(
        &self,
        finish: impl Fn(&'static str, std::thread::Result<Result<()>>) -> i16,
    ) -> Result<Vec<i16>> {
        let (items, limits, path, unit, timeout) = {
            let mut s = self.state.lock();
            let b = s
                .batch
                .as_mut()
                .ok_or_else(|| Error::local(EW_FUNC, "no batch begun (fwlib_batch_begin)"))?;
            let items = std::mem::take(&mut b.items);
            (items, b.limits, s.path, s.pmc_unit, s.timeout)
        };
        // Whole calls into frames within the limits (a call larger than
        // them goes alone, as it would unbatched).
        let mut frames: Vec<std::ops::Range<usize>> = Vec::new();
        let (mut subs, mut body) = (0, 2);
        for (i, it) in items.iter().enumerate() {
            let (n, len) = (it.subs.len(), it.subs.iter().map(sub_len).sum::<usize>());
            match frames.last_mut() {
                Some(f) if subs + n <= limits.subpackets && body + len <= limits.body => {
                    f.end = i + 1;
                    subs += n;
                    body += len;
                }
                _ => {
                    frames.push(i..i + 1);
                    (subs, body) = (n, 2 + len);
                }
            }
        }
        let mut answers: Vec<Result<Vec<RespSub>>> = Vec::with_capacity(items.len());
        for f in &frames {
            let subs: Vec<ReqSub> = items[f.clone()]
                .iter()
                .flat_map(|it| it.subs.clone())
                .collect();
            let deadline = Deadline::after_secs(timeout);
            match self.pair.call(&Raw(&subs), path, unit, deadline) {
                Ok(resp) => {
                    let mut at = 0;
                    for it in &items[f.clone()] {
                        let n = it.subs.len();
                        let share = resp[at.min(resp.len())..(at + n).min(resp.len())].to_vec();
                        answers.push(Ok(share));
                        at += n;
                    }
                }
                Err(e) => answers.extend(items[f.clone()].iter().map(|_| Err(e.clone()))),
            }
        }
        let mut codes = Vec::with_capacity(items.len());
        for (mut it, answer) in items.into_iter().zip(answers) {
            let r = match answer {
                Ok(resp) => {
                    if let Some(b) = self.state.lock().batch.as_mut() {
                        b.replay = Some(resp);
                        b.pending = None;
                    }
                    let run = &mut it.run.0;
                    let r =
                        batchable(|| std::panic::catch_unwind(std::panic::AssertUnwindSafe(run)));
                    QUEUED_ON.with(|q| q.borrow_mut().take());
                    match r {
                        Ok(r) => r,
                        Err(p) => {
                            codes.push(finish(it.name, Err(p)));
                            continue;
                        }
                    }
                }
                Err(e) => {
                    self.note(&e);
                    Err(e)
                }
            };
            if let Some(b) = self.state.lock().batch.as_mut() {
                b.replay = None;
                b.pending = None;
            }
            let r = r.map_err(|e| match e {
                Error::Queued => Error::local(EW_FUNC, "a call made a second exchange in a batch"),
                e => e,
            });
            codes.push(finish(it.name, Ok(r)));
        }
        Ok(codes)
    }
}
