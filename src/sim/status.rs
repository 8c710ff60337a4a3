//! The CNC's identity and status: the open body, system information
//! (cnc_sysinfo, the Series-15 start-up words), the status words
//! (cnc_statinfo ...), the CNC id and the Ethernet board.

use super::Machine;
use super::profile::{Class, MachineKind};
use super::route::{Asked, Route, enc};
use super::service::{CncError, Reply};
use crate::ew::EW_LENGTH;
use crate::proto::cmd;
use crate::proto::cmd::{
    RDETHERINFO, RDFROMSERVOID, RDFROMSPINDLEID, RDSERVOID, RDSPINDLEID, RDSYSHARD, RDSYSSOFT,
    RDSYSSOFT3, RDSYSSOFT3_STR,
};
use crate::proto::open::OpenBody;
use crate::proto::position::SPINDLE_SHOWN15;
use crate::proto::status::{Status, Status2, SysInfo, Word};

pub(super) const ROUTES: &[Route] = &[
    Route::cnc(cmd::SYSINFO, |m, q| enc(m.sysinfo(q.path))),
    Route::cnc(cmd::STATINFO, |m, q| {
        enc(m.statinfo2(q.path).map(Status::from))
    }),
    Route::cnc(cmd::STATINFO2, |m, q| enc(m.statinfo2(q.path))),
    Route::cnc(cmd::HDCK, |m, q| {
        enc(m.path(q.path).map(|p| Word {
            value: p.status.hdck,
        }))
    }),
    Route::cnc(cmd::TMMODE, |m, q| {
        enc(m.path(q.path).map(|p| Word {
            value: p.status.tmmode,
        }))
    }),
    // Series 15 (16i class, kind 2) answers its start-up companion of
    // sysinfo; the words cnc_rdposition reads from it are known, the rest
    // are not (src/sim/position.rs).
    Route::cnc(cmd::SYSINFO15, |m, q| {
        m.series15()?;
        enc(m.sysinfo15(q.path))
    }),
    Route::cnc(SPINDLE_SHOWN15, |m, q| {
        m.series15()?;
        enc(m.spindle_shown15(q.path))
    }),
    // cnc_rdcncid: the profile's `cnc_id` words (at most four).
    Route::table(cmd::RDCNCID, |m, _| {
        Ok(m.profile.cnc.cnc_id.iter().map(|w| i64::from(*w)).collect())
    }),
    Route::table(RDETHERINFO, ether_info),
    // cnc_getmacaddress: the profile's digits (at most 12) and a NUL.
    Route::table(cmd::GETMACADDRESS, |m, _| {
        let mac = m.profile.cnc.mac_address.bytes().take(12);
        Ok(mac.chain([0]).map(i64::from).collect())
    }),
    Route::table(RDSYSHARD, boards),
    Route::table(RDSYSSOFT3, software),
    Route::table(RDSYSSOFT3_STR, software),
    Route::table(RDSYSSOFT, slots_software),
    Route::table(RDSERVOID, |m, q| drive_id(&m.profile.system.servo, q)),
    Route::table(RDFROMSERVOID, |m, q| drive_id(&m.profile.system.servo, q)),
    Route::table(RDSPINDLEID, |m, q| drive_id(&m.profile.system.spindle, q)),
    Route::table(RDFROMSPINDLEID, |m, q| {
        drive_id(&m.profile.system.spindle, q)
    }),
    Route::table(cmd::RDSERVOID2, |m, q| drive_id(&m.profile.system.servo, q)),
    Route::table(cmd::RDFROMSERVOID2, |m, q| {
        drive_id(&m.profile.system.servo, q)
    }),
    Route::table(cmd::RDSPINDLEID2, |m, q| {
        drive_id(&m.profile.system.spindle, q)
    }),
    Route::table(cmd::RDFROMSPINDLEID2, |m, q| {
        drive_id(&m.profile.system.spindle, q)
    }),
];

/// cnc_rdservoid / cnc_rdspindleid, their saved copies and their *2 forms
/// (the simulated CNC's last ID check found the drives it has): drive
/// `q.arg(0)` (1 the first) of the profile's list (the parts, the software,
/// the power modules: as many as the layout has), each string in its field, NUL-padded and
/// cut to leave a NUL (the field lengths are the reply layout's); no such
/// drive is EW_NUMBER.
fn drive_id(drives: &[super::profile::system::DriveId], q: &Asked<'_>) -> Reply<Vec<i64>> {
    let d = usize::try_from(q.arg(0) - 1)
        .ok()
        .and_then(|k| drives.get(k))
        .ok_or(CncError::NUMBER)?;
    let parts = [&d.motor, &d.sub, &d.amplifier, &d.power_supply];
    let texts = parts.into_iter().flat_map(|p| p.iter());
    let texts = texts.chain(&d.software).chain(d.modules.iter().flatten());
    let mut v = Vec::new();
    for (f, t) in q.f.reply.iter().zip(texts) {
        let n = usize::from(f.n);
        let b = t.as_bytes();
        v.extend((0..n).map(|i| match b.get(i) {
            Some(c) if i + 1 < n => i64::from(*c as i8),
            _ => 0,
        }));
    }
    Ok(v)
}

/// The entries `s_no` (1 the first) on a list of `len` that a request for
/// `num` of them answers, at most `max`: a `num` below 1 is EW_LENGTH, an
/// `s_no` below 1 EW_NUMBER; past the list's end, none.
fn listed(len: usize, s_no: i32, num: i32, max: u16) -> Reply<std::ops::Range<usize>> {
    if num < 1 {
        return Err(CncError::new(EW_LENGTH));
    }
    let first = usize::try_from(s_no - 1).map_err(|_| CncError::NUMBER)?;
    let n = (num as usize).min(usize::from(max));
    Ok(first.min(len)..(first + n).min(len))
}

/// cnc_rdsyshard: the profile's boards (`[[system.board]]`) from `s_no` on,
/// after a 32-bit count.
fn boards(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let all = &m.profile.system.boards;
    let max = q.f.records.map_or(0, |r| r.max);
    let got = &all[listed(all.len(), q.arg(0), q.arg(1), max)?];
    let mut v = vec![0, got.len() as i64];
    for b in got {
        v.extend([i64::from(b.id1), i64::from(b.id2)]);
        v.extend(
            [
                b.group_id,
                b.hard_id,
                b.hard_num,
                b.slot_no,
                b.id1_format,
                b.id2_format,
            ]
            .map(i64::from),
        );
    }
    Ok(v)
}

/// cnc_rdsyssoft3 / cnc_rdsyssoft3_str: the profile's software (`[system]
/// software`) from `s_no` on, after their count and the total; series and
/// edition are 4 characters each (space-padded), then a 0; for
/// cnc_rdsyssoft3_str each with its name before them.
fn software(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let all = &m.profile.system.software;
    let max = q.f.records.map_or(0, |r| r.max);
    let got = &all[listed(all.len(), q.arg(0), q.arg(1), max)?];
    let mut v = vec![got.len() as i64, all.len() as i64];
    let chars = |s: &str| -> [i64; 5] {
        let b = s.as_bytes();
        std::array::from_fn(|i| match i {
            4 => 0,
            _ => i64::from(b.get(i).copied().unwrap_or(b' ') as i8),
        })
    };
    // cnc_rdsyssoft3_str's records: the name, NUL-padded in its field
    // (13 bytes, cut to leave a NUL), before the series; 3 zero bytes after.
    let named =
        q.f.records
            .is_some_and(|r| r.fields.iter().any(|f| f.to == Some("soft_name")));
    for s in got {
        v.push(i64::from(s.id));
        if named {
            let b = s.name.as_bytes();
            v.extend((0..13).map(|i| match b.get(i) {
                Some(c) if i < 12 => i64::from(*c as i8),
                _ => 0,
            }));
        }
        v.extend(chars(&s.series));
        v.extend(chars(&s.edition));
        if named {
            v.extend([0; 3]);
        }
    }
    Ok(v)
}

/// cnc_rdsyssoft / cnc_rdsyssoft2: the profile's slots (`[system] slot`,
/// logical order) and named software (`named`), each software's series and
/// edition from `software` (so cnc_rdsyssoft3 lists them alike), walked
/// along the reply's fields (the longer cnc_rdsyssoft2's): the physical
/// slots ascending then 0xff; module and software IDs at each slot's place
/// in its bank; the logical table's words the physical slot in the high
/// byte (0xffff unused); series and edition by logical slot; each named
/// pair (`SYSSOFT_PAIRS`) its software's, unset characters 0xff;
/// `soft_inst`; zeros elsewhere.
fn slots_software(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    use crate::spec::table::info::{LOGICAL, MODULES, SERIES, SLOTS, SOFTS, SYSSOFT_PAIRS};
    let sys = &m.profile.system;
    let slots = &sys.slots[..sys.slots.len().min(16)];
    let mut physical: Vec<u8> = slots.iter().map(|s| s.slot).collect();
    physical.sort_unstable();
    // A software's 8 characters: series then edition, 0xff unset.
    let chars = |id: Option<i16>| -> [i64; 8] {
        let s = id.and_then(|id| sys.software.iter().find(|s| s.id == id));
        std::array::from_fn(|i| {
            let text = s.map(|s| if i < 4 { &s.series } else { &s.edition });
            text.and_then(|t| t.as_bytes().get(i % 4).copied())
                .map_or(-1, |c| i64::from(c as i8))
        })
    };
    // Reply field k's `n` integers by ID (`id` of a slot) at each slot's
    // place in bank `high`.
    let by_slot = |n: usize, high: bool, id: fn(&super::profile::system::Slot) -> i16| {
        let mut w = vec![0; n];
        for s in slots.iter().filter(|s| (s.slot >= 0x80) == high) {
            if let Some(x) = w.get_mut(usize::from(s.slot & 0xf)) {
                *x = i64::from(id(s));
            }
        }
        w
    };
    let mut v = Vec::new();
    for (k, f) in q.f.reply.iter().enumerate() {
        let n = usize::from(f.n);
        let k = k as u8;
        let part: Vec<i64> = if k == SLOTS {
            (0..n)
                .map(|i| physical.get(i).map_or(-1, |s| i64::from(*s as i8)))
                .collect()
        } else if k == MODULES.0 || k == MODULES.1 {
            by_slot(n, k == MODULES.1, |s| s.module_id)
        } else if k == SOFTS.0 || k == SOFTS.1 {
            by_slot(n, k == SOFTS.1, |s| s.software)
        } else if k == LOGICAL {
            (0..n)
                .map(|i| match (i % 2, slots.get(i / 2)) {
                    (0, Some(s)) => i64::from(s.slot),
                    (_, Some(_)) => 0,
                    (_, None) => 0xff,
                })
                .collect()
        } else if k == SERIES {
            (0..n)
                .map(|i| {
                    let s = slots.get(i / 8).map(|s| s.software);
                    chars(s)[i % 8]
                })
                .collect()
        } else if let Some((_, names)) = SYSSOFT_PAIRS.iter().find(|(at, _)| *at == k) {
            // Each named pair: its software's series, then its edition.
            (names.iter())
                .flat_map(|name| chars(sys.named.get(*name).copied()))
                .take(n)
                .collect()
        } else if f.to == Some("soft_inst") {
            vec![i64::from(sys.soft_inst)]
        } else {
            // The bytes nobody reads.
            vec![0; n]
        };
        v.extend(part);
    }
    Ok(v)
}

fn ether_info(m: &mut Machine, _: &Asked<'_>) -> Reply<Vec<i64>> {
    let c = &m.profile.cnc;
    Ok(vec![c.ether_type.into(), c.ether_device.into()])
}

fn fixed<const N: usize>(s: &str) -> [u8; N] {
    // Right-aligned and space-padded, as a CNC reports " M" or " 3".
    let mut out = [b' '; N];
    let b = s.as_bytes();
    let n = b.len().min(N);
    out[N - n..].copy_from_slice(&b[..n]);
    out
}

fn mt_word(kind: MachineKind) -> u16 {
    match kind {
        MachineKind::Mill => 0x204d,
        MachineKind::Lathe => 0x2054,
        MachineKind::Punch => 0x2050,
    }
}

impl Machine {
    /// The open-response body (SPEC.md §3.2).
    pub fn open_body_of(&self) -> OpenBody {
        let c = &self.profile.cnc;
        let n = self.profile.paths.len() as u16;
        let axes = |p: &super::profile::Path| p.axes.len() as u16;
        let spindles = |p: &super::profile::Path| p.spindles.len() as u16;
        match c.class {
            Class::Series30 => {
                // The words cnc_sysinfo_ex reports (src/proto/open.rs): one
                // machine group; the controlled axes (all servo) and spindles.
                let mut header = [0u16; 20];
                header[2] = 3;
                header[3] = c.max_axes;
                header[4] = c.max_spindles;
                header[5] = n;
                header[6] = 1;
                header[8] = self.profile.paths.iter().map(axes).sum();
                header[9] = header[8];
                // Non-zero: the CNC reports spindle information (SPEC.md §5.3).
                header[10] = self.profile.paths.iter().map(spindles).sum();
                header[11] = n;
                header[12] = 1;
                header[14] = c.option;
                let paths = self
                    .profile
                    .paths
                    .iter()
                    .map(|p| {
                        let mut e = [0u16; 16];
                        e[0] = mt_word(p.machine);
                        e[1] = 1;
                        e[3] = axes(p);
                        e[5] = spindles(p);
                        e[6] = 1;
                        e
                    })
                    .collect();
                OpenBody::Series30 { header, paths }
            }
            Class::Series16 => {
                let header = [0, c.kind, c.max_axes, c.max_spindles, n, n, 0, 0];
                let paths = self
                    .profile
                    .paths
                    .iter()
                    .map(|p| [mt_word(p.machine), 0, c.max_axes, c.max_spindles])
                    .collect();
                OpenBody::Series16 { header, paths }
            }
        }
    }

    fn sysinfo(&mut self, path: u16) -> Reply<SysInfo> {
        let c = &self.profile.cnc;
        let p = self.path(path)?;
        let mt = match p.machine {
            MachineKind::Mill => " M",
            MachineKind::Lathe => " T",
            MachineKind::Punch => " P",
        };
        Ok(SysInfo {
            addinfo: c.addinfo,
            max_axis: c.max_axes,
            cnc_type: fixed(&c.cnc_type),
            mt_type: fixed(mt),
            series: fixed(&c.series),
            version: fixed(&c.version),
            axes: fixed(&p.axes.len().to_string()),
        })
    }

    fn statinfo2(&mut self, path: u16) -> Reply<Status2> {
        let s = self.path(path)?.status;
        Ok(Status2 {
            aut: s.aut,
            run: s.run,
            motion: s.motion,
            mstb: s.mstb,
            emergency: s.emergency,
            alarm: s.alarm,
            edit: s.edit,
            warning: s.warning,
            o3dchk: s.o3dchk,
            ext_opt: s.ext_opt,
            restart: s.restart,
        })
    }
}
