//! The client side: connection pairs, sessions and the handle table.
//! Blocking std::net, no threads of its own.

pub mod batch;
pub mod batching;
pub mod conn;
pub mod conn1;
pub mod download;
pub mod handles;
pub mod log;
pub mod pair;
pub mod upload;

use crate::error::{Error, Result};
use crate::proto::call::{self, Call, Ctx, Erased};
use crate::proto::download::Outgoing;
use crate::proto::status::SysInfo;
use crate::proto::upload::StartReq;
use conn::Deadline;
use handles::{DETAIL_CODES, Handle};
pub(crate) use handles::{begin_call, end_call, keep_detail};

/// The same for pmc_getdtailerr (SPEC.md §6.2, from FANUC's code).
const PMC_DETAIL_CODES: [i16; 6] = [3, 5, 8, 13, 17, 18];

impl Handle {
    /// What calls know about the CNC on this handle's current path.
    pub fn ctx(&self) -> Ctx {
        let path = self.state.lock().path;
        self.pair.info.ctx(path)
    }

    /// The sysinfo answer the CNC gave at connect time for this handle's
    /// current path; None if the path has none.
    pub fn sysinfo(&self) -> Option<SysInfo> {
        let path = self.state.lock().path as usize;
        self.pair.info.sysinfo.get(path - 1).copied().flatten()
    }

    /// Runs a call on this handle's pair with its path and timeout, and
    /// records the error detail.
    pub fn call<C: Call>(&self, c: &C) -> Result<C::Output> {
        call::erased(c, |e| self.call_erased(e))
    }

    // The one copy of the exchange path: not inlined into the generic
    // shims, with the layers below inlined into it (no result copies
    // between them).
    #[inline(never)]
    fn call_erased(&self, c: &mut Erased<'_>) -> Result<()> {
        let r = self.exchange(c);
        match &r {
            // A successful exchange keeps the last error's words (FANUC).
            Ok(_) => {}
            Err(e) => self.note(e),
        }
        r
    }

    /// One exchange on the pair with the handle's path, by its timeout; a
    /// torn-down pair is first reconnected within that same time when the
    /// handle asked for it (fwlib_set_reconnect).
    #[inline(always)]
    fn exchange(&self, c: &mut Erased<'_>) -> Result<()> {
        let (path, timeout, reconnect, unit) = {
            let s = self.state.lock();
            (s.path, s.timeout, s.reconnect, s.pmc_unit)
        };
        if self.batching.load(std::sync::atomic::Ordering::Acquire) {
            return self.batched(c, &self.pair.info.ctx(path));
        }
        let deadline = Deadline::after_secs(timeout);
        if reconnect && self.pair.is_dead() {
            self.pair.revive(deadline, timeout)?;
            // A new connection: cnc_getdtailerr reports again.
            self.state.lock().detail_frozen = false;
        }
        self.pair.call(c, path, unit, deadline)
    }

    /// Sets the first detail word cnc_getdtailerr reports (a local check
    /// FANUC's library numbers), unless a socket error froze it.
    pub fn set_detail(&self, d: i16) {
        keep_detail();
        let mut s = self.state.lock();
        if !s.detail_frozen {
            s.detail = (d, 0);
        }
    }

    /// Updates the detail words cnc_getdtailerr reports.
    pub fn note(&self, e: &Error) {
        keep_detail();
        let mut s = self.state.lock();
        if s.detail_frozen {
            return;
        }
        match e {
            Error::Cnc {
                code,
                detail1,
                detail2,
            } if DETAIL_CODES.contains(code) => s.detail = (*detail1 as i16, *detail2 as i16),
            Error::Socket { detail, .. } => {
                s.detail = *detail;
                s.detail_frozen = true;
            }
            Error::Protocol { detail, .. } => s.detail = *detail,
            _ => {}
        }
    }

    /// cnc_dwnstart* / cnc_dncstart* on this handle's pair (see
    /// [`pair::Pair::send_start`]).
    pub fn send_start(
        &self,
        h: u16,
        how: Outgoing,
        req: &StartReq,
        defer: bool,
        timeout: i32,
    ) -> Result<()> {
        self.pair
            .send_start(h, how, req, defer, timeout, |o| self.on_pair(o))
    }

    /// cnc_download* / cnc_dnc* (see [`pair::Pair::send_data`]).
    pub fn send_data(&self, h: u16, how: Outgoing, data: &[u8], timeout: i32) -> Result<()> {
        self.pair
            .send_data(h, how, data, timeout, |o| self.on_pair(o))
    }

    /// cnc_dwnend* / cnc_dncend* (see [`pair::Pair::send_end`]).
    pub fn send_end(&self, h: u16, how: Outgoing, timeout: i32) -> Result<()> {
        self.pair.send_end(h, how, timeout, |o| self.on_pair(o))
    }

    /// cnc_dncend2 with an error result (see [`pair::Pair::send_abort`]).
    pub fn send_abort(&self, h: u16, how: Outgoing, code: i16, timeout: i32) -> Result<()> {
        self.pair
            .send_abort(h, how, code, timeout, |o| self.on_pair(o))
    }

    /// cnc_upstart and relatives on this handle's pair; `h` is its number.
    pub fn upload_start(&self, h: u16, req: &StartReq, timeout: i32) -> Result<()> {
        self.pair.upload_start(h, req, timeout, |o| self.on_pair(o))
    }

    /// cnc_upload3 on this handle's pair (see [`pair::Pair::upload_read`]).
    pub fn upload_read(&self, h: u16, out: &mut [u8], timeout: i32) -> Result<usize> {
        self.pair.upload_read(h, out, timeout, |o| self.on_pair(o))
    }

    /// Blocks until the handle's upload has something to read (see
    /// [`pair::Pair::upload_wait`]).
    pub fn upload_wait(&self, h: u16, timeout: i32) -> Result<()> {
        self.pair.upload_wait(h, timeout)
    }

    /// cnc_upend3 on this handle's pair.
    pub fn upload_end(&self, h: u16, timeout: i32) -> Result<()> {
        self.pair.upload_end(h, timeout, |o| self.on_pair(o))
    }

    /// Whether handle `o` still exists and is on this handle's pair.
    fn on_pair(&self, o: u16) -> bool {
        handles::get(o).is_ok_and(|x| std::ptr::eq(&*x.pair, &*self.pair))
    }

    /// Runs a PMC call (pmc_*): as [`Handle::call`], but the error detail
    /// goes to pmc_getdtailerr's words, not cnc_getdtailerr's.
    pub fn call_pmc<C: Call>(&self, c: &C) -> Result<C::Output> {
        call::erased(c, |e| self.call_pmc_erased(e))
    }

    #[inline(never)]
    fn call_pmc_erased(&self, c: &mut Erased<'_>) -> Result<()> {
        let r = self.exchange(c);
        let mut s = self.state.lock();
        match &r {
            // A successful exchange keeps the last error's words (FANUC).
            Ok(_) => {}
            Err(Error::Cnc {
                code,
                detail1,
                detail2,
            }) if PMC_DETAIL_CODES.contains(code) => {
                s.pmc_detail = (*detail1 as i16, *detail2 as i16)
            }
            Err(Error::Socket { detail, .. } | Error::Protocol { detail, .. }) => {
                s.pmc_detail = *detail
            }
            Err(_) => {}
        }
        r
    }
}
