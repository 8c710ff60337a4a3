//! Call batching on a handle (src/client/batch.rs): queueing a batchable
//! read's exchange, and fwlib_batch_end's frames and replay.

use super::conn::Deadline;
use super::handles::Handle;
use crate::error::{Error, Result};
use crate::ew::EW_FUNC;
use crate::proto::call::{Ctx, Erased};
use crate::proto::packet::{ReqSub, RespSub};

/// Bytes a subpacket takes in a request body.
fn sub_len(s: &ReqSub) -> usize {
    2 + 6 + 20 + s.payload.len()
}

impl Handle {
    /// An exchange while the handle batches: the replayed call's answers,
    /// or (queueing) the subpackets kept and [`Error::Queued`].
    pub(super) fn batched(&self, c: &mut Erased<'_>, cx: &Ctx) -> Result<()> {
        let mut s = self.state.lock();
        let Some(b) = s.batch.as_mut() else {
            return Err(Error::local(EW_FUNC, "the batch has ended"));
        };
        if let Some(resp) = b.replay.take() {
            drop(s);
            return (c.decode)(cx, &resp);
        }
        if b.pending.is_some() {
            // A second exchange of one call: not batchable after all.
            return Err(Error::local(
                EW_FUNC,
                "a call made a second exchange in a batch",
            ));
        }
        let mut subs = Vec::new();
        (c.request)(cx, &mut subs);
        b.pending = Some(subs);
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
            let mut resp = Vec::new();
            let mut raw = Erased {
                request: &|_, out| out.extend_from_slice(&subs),
                decode: &mut |_, r| {
                    resp = r.to_vec();
                    Ok(())
                },
            };
            match self.pair.call(&mut raw, path, unit, deadline) {
                Ok(()) => {
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
                    let r = super::batch::batchable(|| {
                        std::panic::catch_unwind(std::panic::AssertUnwindSafe(run))
                    });
                    super::handles::forget();
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
