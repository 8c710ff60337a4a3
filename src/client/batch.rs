//! Call batching (fwlib32_ext.h: fwlib_batch_begin, fwlib_batch_end,
//! fwlib_batch_limits), client side.
//!
//! While a handle batches, each batchable read runs twice. Queued: its
//! local checks run as they always do (a failure returns at once), then
//! its exchange records the subpackets it would send (`Batch::pending`)
//! and ends the call with [`Error::Queued`](crate::error::Error::Queued); the exported function's body
//! is kept ([`Deferred`], by `ffi_boundary!`). At the batch's end the
//! queued subpackets go out in as few request frames as the limits allow,
//! and each kept body runs again: its exchange now takes its own share of
//! the answers (`Batch::replay`) and decodes it, so it writes the
//! caller's outputs and returns exactly what the same call made alone
//! would. Calls that are not batchable (writes, transfers, connection 1,
//! reads that need an earlier answer to form their next request) return
//! EW_REJECT while the handle batches, without traffic.

use crate::error::Result;
use crate::proto::open::CncClass;
use crate::proto::packet::{ReqSub, RespSub};
use std::cell::Cell;

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

/// The most FANUC's library puts in one request frame, by CNC class: the
/// largest the recorded cases show (tests/ffi/batch.rs checks it against
/// tests/vectors). 30i: 16 subpackets (cnc_rdparam_ext, 16 numbers in
/// frames of 16); 16i: 14 (the same call in frames of 14, 14, 4); Series
/// 15: 9 (cnc_rddynamic). Bodies: 4126 bytes (cnc_wrmdiprog) on the 30i
/// and 16i classes, 1450 (cnc_wrgrpinfo, 71 groups) on Series 15.
pub fn default_limits(class: CncClass) -> Limits {
    let (subpackets, body) = match class {
        CncClass::Series30 => (16, 4126),
        CncClass::Series16 { kind: 2 } => (9, 1450),
        CncClass::Series16 { .. } => (14, 4126),
    };
    Limits { subpackets, body }
}

/// One queued call.
pub(crate) struct Item {
    pub(crate) name: &'static str,
    pub(crate) subs: Vec<ReqSub>,
    pub(crate) run: Deferred,
}

/// A handle's batch (`HandleState::batch`).
#[derive(Default)]
pub struct Batch {
    pub limits: Limits,
    pub(crate) items: Vec<Item>,
    /// The subpackets the call being queued would send.
    pub(crate) pending: Option<Vec<ReqSub>>,
    /// The answers the call being replayed takes (None: not replaying).
    pub(crate) replay: Option<Vec<RespSub>>,
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
}

/// Runs `f` as an export that may join a batch (`ffi_read!`).
pub fn batchable<T>(f: impl FnOnce() -> T) -> T {
    let before = BATCHABLE.with(|c| c.replace(true));
    let r = f();
    BATCHABLE.with(|c| c.set(before));
    r
}

/// The running export may join a batch.
pub fn is_batchable() -> bool {
    BATCHABLE.with(Cell::get)
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

    /// Keeps the call whose subpackets are pending with its body; false
    /// when none is pending.
    pub(crate) fn queue(&mut self, name: &'static str, run: Deferred) -> bool {
        match self.pending.take() {
            Some(subs) => {
                self.items.push(Item { name, subs, run });
                true
            }
            None => false,
        }
    }
}
