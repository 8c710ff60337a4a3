//! The handle table: `unsigned short` handles over sessions.
//!
//! A read-write lock guards the map for lookups; each handle has its own
//! small state lock, and network I/O happens under the pair's lock only
//! (mozilla ffi-support's model). Handles are never 0 and a freed number is
//! not handed out again until the counter wraps around, so a stale handle
//! gets EW_HANDLE instead of someone else's session.

use super::pair::Pair;
use crate::error::{Error, Result};
use crate::ew::EW_HANDLE;
use parking_lot::{Mutex, RwLock};
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::sync::Arc;

/// Most handles that can exist at once (FANUC's library: 1024, then it hangs).
pub const MAX_HANDLES: usize = 60_000;
/// FANUC numbers handles from 0x8001; we do too, so logs look familiar.
const FIRST: u16 = 0x8001;

#[derive(Debug, Clone)]
pub struct HandleState {
    pub path: u16,
    pub timeout: i32,
    /// (err_no, err_dtno) for cnc_getdtailerr.
    pub detail: (i16, i16),
    /// Once a call failed with EW_SOCKET the detail no longer changes (FANUC).
    pub detail_frozen: bool,
    /// (err_no, err_dtno) for pmc_getdtailerr, kept apart from the CNC's.
    pub pmc_detail: (i16, i16),
    /// fwlib_set_reconnect: a call after the pair was torn down reconnects
    /// it first (FANUC's library, and ours by default, answer EW_SOCKET
    /// until every handle is freed).
    pub reconnect: bool,
    /// The PMC unit the handle's PMC requests address (pmc_select_pmc_unit;
    /// FANUC's library starts at 1): the path word of PMC subpackets.
    pub pmc_unit: u16,
    /// The calls queued since fwlib_batch_begin (src/client/batch.rs).
    pub batch: Option<Box<super::batch::Batch>>,
    /// fwlib_batch_limits given outside a batch: the next batches' limits.
    pub batch_limits: Option<super::batch::Limits>,
}

pub struct Handle {
    pub pair: Arc<Pair>,
    pub state: Mutex<HandleState>,
    /// `state.batch` is set: the one check the hot path makes.
    pub batching: std::sync::atomic::AtomicBool,
}

impl Drop for Handle {
    /// A handle freed in the middle of a batch: its queued calls go with it.
    fn drop(&mut self) {
        self.set_batching(false);
    }
}

struct Table {
    map: HashMap<u16, Arc<Handle>, BuildHasherDefault<HandleHasher>>,
    next: u16,
}

/// Hashes a handle number with one multiplication (Fibonacci hashing):
/// every call looks its handle up, and the numbers are ours, not an
/// attacker's, so SipHash's protection buys nothing here.
#[derive(Default)]
struct HandleHasher(u64);

impl Hasher for HandleHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write_u16(&mut self, h: u16) {
        self.0 = u64::from(h).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    }
    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.0 = (self.0.rotate_left(8) ^ u64::from(*b)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        }
    }
}

static TABLE: RwLock<Option<Table>> = RwLock::new(None);

pub fn insert(pair: Arc<Pair>, timeout: i32) -> Result<u16> {
    let mut g = TABLE.write();
    let t = g.get_or_insert_with(|| Table {
        map: HashMap::default(),
        next: FIRST,
    });
    if t.map.len() >= MAX_HANDLES {
        return Err(Error::local(EW_HANDLE, "handle table full"));
    }
    let mut h = t.next;
    while h == 0 || t.map.contains_key(&h) {
        h = h.wrapping_add(1);
    }
    t.next = h.wrapping_add(1);
    t.map.insert(
        h,
        Arc::new(Handle {
            pair,
            state: Mutex::new(HandleState {
                path: 1,
                timeout,
                detail: (0, 0),
                detail_frozen: false,
                pmc_detail: (0, 0),
                reconnect: false,
                pmc_unit: 1,
                batch: None,
                batch_limits: None,
            }),
            batching: std::sync::atomic::AtomicBool::new(false),
        }),
    );
    Ok(h)
}

pub fn get(h: u16) -> Result<Arc<Handle>> {
    call_handle(h);
    let h = lookup(h)?;
    if h.batching.load(std::sync::atomic::Ordering::Acquire) {
        // A call on a batching handle: refused unless the running export
        // may join the batch; else the handle is where it queues.
        if !super::batch::is_batchable() {
            return Err(Error::local(
                crate::ew::EW_REJECT,
                "not batchable: call it before fwlib_batch_begin or after fwlib_batch_end",
            ));
        }
        QUEUED_ON.with(|q| *q.borrow_mut() = Some(h.clone()));
    }
    Ok(h)
}

thread_local! {
    /// The batching handle the running call was admitted on.
    static QUEUED_ON: std::cell::RefCell<Option<Arc<Handle>>> = const { std::cell::RefCell::new(None) };
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
    let queued = s
        .as_mut()
        .and_then(|s| s.batch.as_mut())
        .is_some_and(|b| b.queue(name, super::batch::Deferred(run)));
    if queued {
        crate::ew::EW_OK
    } else {
        crate::ew::EW_UNEXP
    }
}

impl Handle {
    /// Marks the handle batching or not (counted in `batch::active`).
    pub fn set_batching(&self, on: bool) {
        if self.batching.swap(on, std::sync::atomic::Ordering::AcqRel) != on {
            super::batch::set_active(on);
        }
    }
}

/// Handle `h` whether it batches or not (the batch functions themselves).
pub fn lookup(h: u16) -> Result<Arc<Handle>> {
    TABLE
        .read()
        .as_ref()
        .and_then(|t| t.map.get(&h).cloned())
        .ok_or_else(Error::handle)
}

pub fn remove(h: u16) -> Result<Arc<Handle>> {
    TABLE
        .write()
        .as_mut()
        .and_then(|t| t.map.remove(&h))
        .ok_or_else(Error::handle)
}

/// Removes handle `h` if it is still `which` (not a number handed out again
/// after cnc_exitprocess removed it); true when it was removed.
pub fn remove_exact(h: u16, which: &Arc<Handle>) -> bool {
    let mut g = TABLE.write();
    let Some(t) = g.as_mut() else {
        return false;
    };
    if t.map.get(&h).is_some_and(|x| Arc::ptr_eq(x, which)) {
        t.map.remove(&h);
        return true;
    }
    false
}

/// Removes every handle (cnc_exitprocess); returns them for closing.
pub fn drain() -> Vec<Arc<Handle>> {
    TABLE
        .write()
        .as_mut()
        .map(|t| t.map.drain().map(|(_, v)| v).collect())
        .unwrap_or_default()
}

pub fn count() -> usize {
    TABLE.read().as_ref().map_or(0, |t| t.map.len())
}

/// FANUC's rule for which CNC error codes update cnc_getdtailerr (SPEC.md §6.2);
/// a call refused locally with one of these codes sets them too (its own
/// detail, else 0). Nothing else changes them: a successful call keeps the
/// words of the last error (docs/protocol/framing.md, cnc_getdtailerr).
pub(crate) const DETAIL_CODES: [i16; 9] = [1, 3, 5, 6, 7, 8, 13, 14, 17];

thread_local! {
    /// The number of the handle the running export looked up first (its
    /// own handle).
    static CALL_HANDLE: std::cell::Cell<Option<u16>> = const { std::cell::Cell::new(None) };
    /// Whether the running export has set the detail words already.
    static DETAIL_SET: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Notes the handle an export runs on (the first it looks up).
pub(crate) fn call_handle(h: u16) {
    if CALL_HANDLE.get().is_none() {
        CALL_HANDLE.set(Some(h));
    }
}

/// Starts an export: forgets what an earlier call on this thread noted
/// (one made through the Rust API, which has no export around it).
pub(crate) fn begin_call() {
    CALL_HANDLE.set(None);
    DETAIL_SET.set(false);
}

/// Marks the running export's error as one that leaves cnc_getdtailerr's
/// words alone whatever its code (FANUC: a transfer call with no transfer
/// started, EW_FUNC).
pub(crate) fn keep_detail() {
    DETAIL_SET.set(true);
}

/// Ends an export: a local refusal whose code is one FANUC keeps details
/// for sets cnc_getdtailerr's words of the export's handle to 0/0, unless
/// the export set them itself (its own detail) or a socket error froze
/// them. Forgets the export's handle.
pub(crate) fn end_call(r: Option<&Error>) {
    let h = CALL_HANDLE.take();
    let set = DETAIL_SET.replace(false);
    if let (Some(h), Some(Error::Local { code, .. }), false) = (h, r, set)
        && DETAIL_CODES.contains(code)
        && let Ok(h) = lookup(h)
    {
        let mut s = h.state.lock();
        if !s.detail_frozen {
            s.detail = (0, 0);
        }
    }
}
