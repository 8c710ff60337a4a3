//! The program functions of connection 2 on the program store
//! (src/sim/store.rs): select, delete, copy, rename, memory information
//! and the MDI program. Refusals are the store's (EW_DATA, EW_PROT,
//! EW_BUSY, EW_OVRFLOW) and change nothing.

use super::Machine;
use super::route::{Route, none};
use super::service::Reply;
use crate::proto::cmd::{
    CONDENSE, COPYPROG, DELALL, DELETE, RDMDIPNTR, RDMDIPRGSTAT, RENAMEPROG, SEARCH, WRMDIPNTR,
};
use crate::proto::packet::ReqSub;
use crate::proto::program::{ProgInfo, RDMDIPROG, RDPROGINFO, WRMDIPROG};
use crate::proto::wire::Wire;

pub(super) const ROUTES: &[Route] = &[
    Route::cnc(RDMDIPROG, |m, q| m.memory_bytes(q)),
    Route::cnc(WRMDIPROG, |m, q| m.memory_bytes(q)),
    Route::cnc(RDPROGINFO, |m, q| m.memory_bytes(q)),
    Route::table(SEARCH, |m, q| none(m.store.select(q.path, q.arg(0)))),
    Route::table(DELETE, |m, q| {
        none(m.store.remove(q.path, q.arg(0)).map(drop))
    }),
    Route::table(DELALL, |m, q| none(m.store.remove_all(q.path).map(drop))),
    Route::table(COPYPROG, |m, q| {
        let today = m.today();
        none(m.store.copy(q.path, q.arg(0), q.arg(1), today))
    }),
    Route::table(RENAMEPROG, |m, q| {
        let today = m.today();
        none(m.store.rename(q.path, q.arg(0), q.arg(1), today))
    }),
    Route::table(CONDENSE, |m, q| {
        none(m.store.condense(q.path, q.arg(0), q.arg(1)))
    }),
    Route::table(WRMDIPNTR, |m, q| {
        none(m.store.path_mut(q.path).map(|p| p.mdi_pntr = q.arg(0)))
    }),
    Route::table(RDMDIPNTR, |m, q| {
        m.store.path(q.path).map(|p| {
            let n = i64::from(p.mdi_pntr);
            vec![0, n, 0, n]
        })
    }),
    // cnc_rdmdiprgstat: MDI_EXIST (2) with an MDI program stored
    // (cnc_wrmdiprog), and then MDI_START_TOP (4) while its execution
    // pointer is at the top (cnc_wrmdipntr 0); MDI_NO_PROG (0) without one.
    Route::table(RDMDIPRGSTAT, |m, q| {
        m.store.path(q.path).map(|p| {
            let stat = match (p.mdi.is_empty(), p.mdi_pntr) {
                (true, _) => 0,
                (false, 0) => MDI_EXIST | MDI_START_TOP,
                (false, _) => MDI_EXIST,
            };
            vec![stat]
        })
    }),
];

/// cnc_rdmdiprgstat's bits (FANUC's names): an MDI program is stored; it
/// starts from its top.
const MDI_EXIST: i64 = 1 << 1;
const MDI_START_TOP: i64 = 1 << 2;

impl Machine {
    /// The program commands answered as bytes: memory information
    /// (cnc_rdproginfo), the MDI program's text (cnc_rdmdiprog), a new one
    /// (cnc_wrmdiprog, in any mode: the MDI program is not in the store).
    fn memory_bytes(&mut self, sub: &ReqSub) -> Reply<Vec<u8>> {
        self.store.path_mut(sub.path).map(|s| {
            let (n, used) = (s.count(), s.used());
            let left = |max: usize, used: usize| max.saturating_sub(used) as i32;
            match sub.cmd {
                RDMDIPROG => s.mdi.clone(),
                RDPROGINFO => ProgInfo {
                    reg_prg: n as i32,
                    unreg_prg: left(s.max_programs, n),
                    used_mem: used as i32,
                    unused_mem: left(s.capacity, used),
                }
                .to_bytes(),
                _ => {
                    s.mdi = sub.payload.clone();
                    Vec::new()
                }
            }
        })
    }
}
