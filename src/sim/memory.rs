//! The program functions of connection 2 on the program store
//! (src/sim/store.rs): select, delete, copy, rename, memory information
//! and the MDI program. Refusals are the store's (EW_DATA, EW_PROT,
//! EW_BUSY, EW_OVRFLOW) and change nothing.

use super::Machine;
use super::service::Reply;
use crate::proto::packet::{CLASS_CNC, ReqSub};
use crate::proto::program::{ProgInfo, RDMDIPROG, RDPROGINFO, WRMDIPROG};
use crate::proto::wire::Wire;

impl Machine {
    /// The answer of a program function described as data (`None`: not one
    /// of them): the reply's integers, as `CncService::described` gives them.
    pub(crate) fn memory_answer(
        &mut self,
        name: &str,
        path: u16,
        a: &[i32],
    ) -> Option<Reply<Vec<i64>>> {
        let arg = |i: usize| a.get(i).copied().unwrap_or(0);
        let today = self.today();
        let s = &mut self.store;
        let done = |r: Reply<()>| Some(r.map(|()| Vec::new()));
        match name {
            "cnc_search" => done(s.select(path, arg(0))),
            "cnc_delete" => done(s.remove(path, arg(0)).map(drop)),
            "cnc_delall" => done(s.remove_all(path).map(drop)),
            "cnc_copyprog" => done(s.copy(path, arg(0), arg(1), today)),
            "cnc_renameprog" => done(s.rename(path, arg(0), arg(1), today)),
            "cnc_condense" => done(s.condense(path, arg(0), arg(1))),
            "cnc_wrmdipntr" => done(s.path_mut(path).map(|p| p.mdi_pntr = arg(0))),
            "cnc_rdmdipntr" => Some(s.path(path).map(|p| {
                let n = i64::from(p.mdi_pntr);
                vec![0, n, 0, n]
            })),
            _ => None,
        }
    }

    /// The program commands answered as bytes: memory information
    /// (cnc_rdproginfo), the MDI program's text (cnc_rdmdiprog), a new one
    /// (cnc_wrmdiprog, in any mode: the MDI program is not in the store).
    pub(crate) fn memory_raw(&mut self, sub: &ReqSub) -> Option<Reply<Vec<u8>>> {
        if sub.class != CLASS_CNC || ![RDMDIPROG, WRMDIPROG, RDPROGINFO].contains(&sub.cmd) {
            return None;
        }
        Some(self.store.path_mut(sub.path).map(|s| {
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
        }))
    }
}
