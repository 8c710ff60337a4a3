//! The PMC requests (class 2) on the unit the subpacket's path word names:
//! ranges read and written (a signal change goes into the operation
//! history), the unit's areas, types and selection, title, alarm messages
//! and timer types. The PMC memory itself is src/sim/pmc.rs.

use super::Machine;
use super::route::{Route, enc};
use super::service::Reply;
use crate::proto::cmd::{
    KPMSIZ, NUMBER_OF_LADDER, PMC_COUNT, RDCNTL_EXRELAY_GRP, RDCNTLGRP, RDPMCTITLE2,
    SEQ_PROGRAM_TYPE, WRCNTL_EXRELAY_GRP, WRCNTLGRP,
};
use crate::proto::pmc::{
    GET_TIMER_TYPE, PMC_RDALMMSG, PmcRange, RDPMCINFO, RDPMCRNG, RDPMCTITLE, SELECT_UNIT,
    SET_TIMER_TYPE, UNIT_TYPES, WRPMCRNG,
};

pub(super) const ROUTES: &[Route] = &[
    Route::pmc(RDPMCRNG, |m, q| {
        m.profile.pmc.read(q.path, &PmcRange::from_args(&q.args))
    }),
    Route::pmc(WRPMCRNG, |m, q| {
        m.write_pmc(q.path, PmcRange::from_args(&q.args), &q.payload)
            .map(|()| Vec::new())
    }),
    Route::pmc(RDPMCINFO, |m, q| {
        enc(m.profile.pmc.info(q.path, q.args[0] as i16))
    }),
    Route::pmc(UNIT_TYPES, |m, q| {
        enc(Ok(m.profile.pmc.unit_types(q.args[0])))
    }),
    Route::pmc(SELECT_UNIT, |m, q| {
        m.profile.pmc.select(q.args[0]).map(|()| Vec::new())
    }),
    Route::pmc_table(RDPMCTITLE, |m, q| m.profile.pmc.title(q.path, q.f)),
    Route::pmc(PMC_RDALMMSG, |m, q| {
        m.profile.pmc.alarm_messages(q.path, q.args[0], q.args[1])
    }),
    Route::pmc_table(GET_TIMER_TYPE, |m, q| {
        m.profile.pmc.timer_types(q.path, q.arg(0), q.arg(1))
    }),
    Route::pmc_table(SET_TIMER_TYPE, |m, q| {
        m.profile
            .pmc
            .set_timer_types(q.path, q.arg(0), q.arg(1), q.payload)
            .map(|()| Vec::new())
    }),
    Route::pmc_table(PMC_COUNT, |m, _| Ok(vec![m.profile.pmc.units() as i64])),
    Route::pmc_table(RDCNTLGRP, |m, q| {
        Ok(vec![0, i64::from(m.profile.pmc.groups(q.path)?[0])])
    }),
    Route::pmc_table(WRCNTLGRP, |m, q| {
        (m.profile.pmc.set_group(q.path, false, q.arg(0))).map(|()| Vec::new())
    }),
    Route::pmc_table(RDCNTL_EXRELAY_GRP, |m, q| {
        Ok(vec![0, i64::from(m.profile.pmc.groups(q.path)?[1])])
    }),
    Route::pmc_table(KPMSIZ, |m, q| {
        Ok(vec![i64::from(m.profile.pmc.ladders(q.path)?.0)])
    }),
    Route::pmc_table(NUMBER_OF_LADDER, |m, q| {
        Ok(vec![i64::from(m.profile.pmc.ladders(q.path)?.1)])
    }),
    Route::pmc_table(WRCNTL_EXRELAY_GRP, |m, q| {
        (m.profile.pmc.set_group(q.path, true, q.arg(0))).map(|()| Vec::new())
    }),
    Route::pmc_table(RDPMCTITLE2, |m, q| m.profile.pmc.title(q.path, q.f)),
    Route::pmc_table(SEQ_PROGRAM_TYPE, |m, q| {
        Ok(m.profile.pmc.unit_info(q.path)?.program_type.values())
    }),
];

impl Machine {
    /// Writes a range of PMC unit `unit`. Signal changes (G, F, Y, X:
    /// address types 0..3) go into the operation history, one record per
    /// changed byte the history's signal table selects.
    fn write_pmc(&mut self, unit: u16, range: PmcRange, data: &[u8]) -> Reply<()> {
        let old = self.profile.pmc.read(unit, &range).unwrap_or_default();
        self.profile.pmc.write(unit, &range, data)?;
        if (0..=3).contains(&range.adr_type) {
            let new = self.profile.pmc.read(unit, &range).unwrap_or_default();
            for (k, (o, n)) in old.iter().zip(&new).enumerate() {
                if o != n {
                    let byte = i32::from(range.s) + k as i32;
                    self.record_pmc_signal(unit, range.adr_type, byte, *o, *n);
                }
            }
        }
        Ok(())
    }
}
