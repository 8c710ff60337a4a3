//! The CNC's identity and status: the open body, system information
//! (cnc_sysinfo, the Series-15 start-up words), the status words
//! (cnc_statinfo ...), the CNC id and the Ethernet board.

use super::Machine;
use super::profile::{Class, MachineKind};
use super::route::{Asked, Route, enc};
use super::service::Reply;
use crate::proto::cmd;
use crate::proto::cmd::RDETHERINFO;
use crate::proto::open::OpenBody;
use crate::proto::position::SPINDLE_SHOWN15;
use crate::proto::status::{CncId, Status, Status2, SysInfo, Word};

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
    Route::cnc(cmd::RDCNCID, |m, _| {
        enc(Ok(CncId(m.profile.cnc.cnc_id.clone())))
    }),
    Route::table(RDETHERINFO, ether_info),
];

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
