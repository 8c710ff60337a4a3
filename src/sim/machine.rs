//! The simulated machine: state built from a profile, served through [`CncService`].

use super::profile::{Class, MachineKind, Profile};
use super::service::{CncError, CncService, Reply};
use crate::proto::OPTION_PARAM_16;
use crate::proto::open::OpenBody;
use crate::proto::param::Param16;
use crate::proto::status::{CncId, Status, Status2, SysInfo, Word};

pub struct Machine {
    pub profile: Profile,
    /// When the simulator started: the running program's clock.
    pub started: std::time::Instant,
    /// Live state per path (what a running machine changes).
    pub run: Vec<super::run::PathRun>,
}

fn fixed<const N: usize>(s: &str) -> [u8; N] {
    // Right-aligned and space-padded, as a CNC reports " M" or " 3".
    let mut out = [b' '; N];
    let b = s.as_bytes();
    let n = b.len().min(N);
    out[N - n..].copy_from_slice(&b[..n]);
    out
}

impl Machine {
    pub fn new(profile: Profile) -> Machine {
        Machine {
            run: Machine::initial_run(&profile),
            profile,
            started: std::time::Instant::now(),
        }
    }

    fn path(&self, path: u16) -> Reply<&super::profile::Path> {
        self.profile
            .paths
            .get(path as usize - 1)
            .ok_or(CncError::PATH)
    }

    fn mt_word(kind: MachineKind) -> u16 {
        match kind {
            MachineKind::Mill => 0x204d,
            MachineKind::Lathe => 0x2054,
        }
    }
}

impl CncService for Machine {
    fn open_body(&self) -> OpenBody {
        let c = &self.profile.cnc;
        let n = self.profile.paths.len() as u16;
        let has_spindles = self.profile.paths.iter().any(|p| !p.spindles.is_empty());
        match c.class {
            Class::Series30 => {
                let mut header = [0u16; 20];
                header[2] = 3;
                header[3] = c.max_axes;
                header[4] = c.max_spindles;
                header[5] = n;
                header[10] = u16::from(has_spindles);
                header[11] = n;
                header[14] = c.option;
                let paths = self
                    .profile
                    .paths
                    .iter()
                    .map(|p| {
                        let mut e = [0u16; 16];
                        e[0] = Self::mt_word(p.machine);
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
                    .map(|p| [Self::mt_word(p.machine), 0, c.max_axes, c.max_spindles])
                    .collect();
                OpenBody::Series16 { header, paths }
            }
        }
    }

    fn max_sessions(&self) -> usize {
        self.profile.cnc.max_sessions
    }

    fn advance(&mut self, now: std::time::Instant) {
        self.advance_to(now);
    }

    fn sysinfo(&mut self, path: u16) -> Reply<SysInfo> {
        let c = &self.profile.cnc;
        let p = self.path(path)?;
        let mt = match p.machine {
            MachineKind::Mill => " M",
            MachineKind::Lathe => " T",
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

    fn statinfo(&mut self, path: u16) -> Reply<Status> {
        self.statinfo2(path).map(Status::from)
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

    fn hdck(&mut self, path: u16) -> Reply<Word> {
        Ok(Word {
            value: self.path(path)?.status.hdck,
        })
    }

    fn tmmode(&mut self, path: u16) -> Reply<Word> {
        Ok(Word {
            value: self.path(path)?.status.tmmode,
        })
    }

    fn cnc_id(&mut self) -> Reply<CncId> {
        Ok(CncId(self.profile.cnc.cnc_id.clone()))
    }

    fn param16(&mut self, _path: u16, number: i32, axis: i16) -> Reply<Param16> {
        // The 16i-class FOCAS option probe; the parameter table proper
        // arrives with the data-surface functions.
        if self.profile.cnc.class == Class::Series16 && number == OPTION_PARAM_16 {
            return Ok(Param16 {
                number,
                axis,
                ptype: 0,
                values: vec![i32::from(self.profile.cnc.option), 0, 0, 0, 0, 0, 0, 0],
            });
        }
        Err(CncError::NUMBER)
    }

    // --- position ---

    // --- program ---

    // --- alarm ---

    // --- param ---

    // --- macros ---

    // --- pmc ---

    // --- offset ---

    // --- tool ---

    // --- upload ---
    fn upload(&mut self, req: &crate::proto::upload::StartReq) -> Reply<Vec<u8>> {
        self.upload_text(req)
    }
}
