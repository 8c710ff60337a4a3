//! The periodic maintenance answers: each item's remaining life counts
//! down with the cnc_rdtimer counter of its type on the simulator's clock
//! (type 1 power-on, 2 operating, 3 cutting time; 0 does not count).
//! Writes set items and machine-specific names; a refused write changes
//! nothing.

use super::Machine;
use super::profile::maintenance::{ITEMS, Item, MCN_ITEMS, TYPE_MAX};
use super::route::Route;
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::maintenance::{
    ITEM_LEN, ITEMS_MAX, NAME_LEN, NAMES_MAX, PmItem, RDPM_CNCITEM, RDPM_ITEM, RDPM_MCNITEM,
    WRPM_ITEM, WRPM_MCNITEM,
};

/// The periodic maintenance commands (class 1, any path).
pub(super) const ROUTES: &[Route] = &[
    Route::cnc(RDPM_CNCITEM, |m, q| {
        let list = &m.profile.maintenance.cnc_items;
        Machine::pm_names(list, list.len(), q.args)
    }),
    Route::cnc(RDPM_MCNITEM, |m, q| {
        Machine::pm_names(&m.profile.maintenance.machine_items, MCN_ITEMS, q.args)
    }),
    Route::cnc(RDPM_ITEM, |m, q| {
        let a = q.args;
        slots(a[0], a[1].min(i32::from(ITEMS_MAX)), ITEMS)
            .map(|r| r.flat_map(|i| m.pm_item(i).to_wire()).collect())
    }),
    Route::cnc(WRPM_MCNITEM, |m, q| m.pm_write_names(q.args[0], &q.payload)),
    Route::cnc(WRPM_ITEM, |m, q| {
        m.pm_write_items(q.args[0], q.args[1], &q.payload)
            .map(|()| Vec::new())
    }),
];

/// A name as its 62 wire bytes, zero-padded.
fn name_bytes(s: &str) -> [u8; NAME_LEN] {
    let mut b = [0; NAME_LEN];
    let n = s.len().min(NAME_LEN);
    b[..n].copy_from_slice(&s.as_bytes()[..n]);
    b
}

/// The text of a name's wire bytes (up to the first zero).
fn name_text(b: &[u8]) -> String {
    let end = b.iter().position(|&c| c == 0).unwrap_or(b.len());
    String::from_utf8_lossy(&b[..end]).into_owned()
}

/// Slots `start..start+n` of `slots` (1-based): EW_NUMBER when `start` is
/// outside, EW_LENGTH when `n` < 1; cut at the last slot.
fn slots(start: i32, n: i32, slots: usize) -> Reply<std::ops::Range<usize>> {
    if n < 1 {
        return Err(CncError::new(ew::EW_LENGTH));
    }
    if start < 1 || start as usize > slots {
        return Err(CncError::NUMBER);
    }
    let s = start as usize - 1;
    Ok(s..(s + n as usize).min(slots))
}

impl Machine {
    /// The counter an item of type `ty` counts with, in ms (None: type 0).
    fn pm_counter(&self, ty: i32) -> Option<i64> {
        let kind = match ty {
            1..=TYPE_MAX => ty - 1,
            _ => return None,
        };
        let t = self.timer(kind).ok()?;
        Some(i64::from(t.minute) * 60_000 + i64::from(t.msec))
    }

    /// The counter of type `ty` at power-on (the profile's minutes).
    fn pm_power_on(&self, ty: i32) -> i64 {
        let t = &self.profile.timers;
        let min = match ty {
            1 => t.power_on,
            2 => t.operating,
            3 => t.cutting,
            _ => 0,
        };
        i64::from(min) * 60_000
    }

    /// Item slot `i` now: its remaining minutes counted down since it was
    /// set (0 at most), stat 1 once its life is used up, else 0.
    pub(crate) fn pm_item(&self, i: usize) -> PmItem {
        let it = (self.profile.maintenance.items.get(i).cloned()).unwrap_or_default();
        let used = self.pm_counter(it.r#type).map_or(0, |now| {
            (now - it.base.unwrap_or_else(|| self.pm_power_on(it.r#type))) / 60_000
        });
        let remain = (i64::from(it.remain) - used).max(0) as i32;
        PmItem {
            name: name_bytes(&it.name),
            r#type: it.r#type,
            total: it.total,
            remain,
            stat: i32::from(it.r#type != 0 && remain == 0),
        }
    }

    /// 0xbf[reset, start] + items: all or nothing; a type outside 0..=3,
    /// a negative total or a remain outside 0..=total is EW_DATA. `reset`
    /// 1 starts each item's life anew (remain = total).
    fn pm_write_items(&mut self, reset: i32, start: i32, data: &[u8]) -> Reply<()> {
        if data.is_empty() || !data.len().is_multiple_of(ITEM_LEN) {
            return Err(CncError::new(ew::EW_LENGTH));
        }
        let r = slots(start, (data.len() / ITEM_LEN) as i32, ITEMS)?;
        if r.len() != data.len() / ITEM_LEN {
            return Err(CncError::NUMBER);
        }
        let new: Vec<PmItem> = data.chunks_exact(ITEM_LEN).map(PmItem::from_wire).collect();
        let bad = |p: &PmItem| {
            !(0..=TYPE_MAX).contains(&p.r#type)
                || p.total < 0
                || (reset == 0 && !(0..=p.total).contains(&p.remain))
        };
        if new.iter().any(bad) {
            return Err(CncError::new(ew::EW_DATA));
        }
        let items: Vec<Item> = new
            .iter()
            .map(|p| Item {
                name: name_text(&p.name),
                r#type: p.r#type,
                total: p.total,
                remain: if reset != 0 { p.total } else { p.remain },
                base: self.pm_counter(p.r#type),
            })
            .collect();
        let list = &mut self.profile.maintenance.items;
        if list.len() < r.end {
            list.resize(r.end, Item::default());
        }
        for (slot, it) in r.zip(items) {
            list[slot] = it;
        }
        Ok(())
    }

    /// The names `args[0]..` (at most `args[1]`, and the answer's most)
    /// of a list of `n` slots.
    fn pm_names(list: &[String], n: usize, a: [i32; 5]) -> Reply<Vec<u8>> {
        let r = slots(a[0], a[1].min(i32::from(NAMES_MAX)), n)?;
        Ok(
            r.flat_map(|i| name_bytes(list.get(i).map_or("", |s| s.as_str())))
                .collect(),
        )
    }

    /// [s] + names: the machine-specific item names from slot `s`.
    fn pm_write_names(&mut self, s: i32, p: &[u8]) -> Reply<Vec<u8>> {
        if p.is_empty() || !p.len().is_multiple_of(NAME_LEN) {
            return Err(CncError::new(ew::EW_LENGTH));
        }
        let n = p.len() / NAME_LEN;
        match slots(s, n as i32, MCN_ITEMS) {
            Ok(r) if r.len() == n => {
                let list = &mut self.profile.maintenance.machine_items;
                if list.len() < r.end {
                    list.resize(r.end, String::new());
                }
                for (slot, b) in r.zip(p.chunks_exact(NAME_LEN)) {
                    list[slot] = name_text(b);
                }
                Ok(Vec::new())
            }
            Ok(_) => Err(CncError::NUMBER),
            Err(e) => Err(e),
        }
    }
}
