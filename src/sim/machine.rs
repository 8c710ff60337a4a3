//! The simulated machine served through [`CncService`]: each request goes to
//! the area that answers it. The machine's state is [`Machine`] (src/sim/run.rs).

use super::profile::{Class, MachineKind};
pub use super::run::Machine;
use super::service::{CncError, CncService, Reply};
use crate::proto::open::OpenBody;
use crate::proto::param::{InfoList, NumRange, Param16, ParamType30, Table};
use crate::proto::status::{CncId, Status, Status2, SysInfo, Word};
use crate::proto::wire::Wire;
use crate::proto::{OPTION_PARAM_15, OPTION_PARAM_16};
use crate::spec::Func;

fn fixed<const N: usize>(s: &str) -> [u8; N] {
    // Right-aligned and space-padded, as a CNC reports " M" or " 3".
    let mut out = [b' '; N];
    let b = s.as_bytes();
    let n = b.len().min(N);
    out[N - n..].copy_from_slice(&b[..n]);
    out
}

impl Machine {
    pub(crate) fn path(&self, path: u16) -> Reply<&super::profile::Path> {
        self.profile
            .paths
            .get(path as usize - 1)
            .ok_or(CncError::PATH)
    }

    fn mt_word(kind: MachineKind) -> u16 {
        match kind {
            MachineKind::Mill => 0x204d,
            MachineKind::Lathe => 0x2054,
            MachineKind::Punch => 0x2050,
        }
    }
}

impl CncService for Machine {
    fn open_body(&self) -> OpenBody {
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
                        e[0] = Self::mt_word(p.machine);
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

    fn sysinfo15(&mut self, path: u16) -> Reply<Vec<u16>> {
        // Series 15 (16i class, kind 2) answers its start-up companion of
        // sysinfo; the words cnc_rdposition reads from it are known, the
        // rest are not (src/sim/position.rs).
        self.series15()?;
        self.pos_sysinfo15(path)
    }

    fn spindle_shown15(&mut self, path: u16) -> Reply<Vec<u16>> {
        self.series15()?;
        self.pos_spindle_shown15(path)
    }
    fn cnc_id(&mut self) -> Reply<CncId> {
        Ok(CncId(self.profile.cnc.cnc_id.clone()))
    }

    fn param16(&mut self, path: u16, number: i32, e: i32, axis: i16) -> Reply<Vec<u8>> {
        if self.profile.cnc.class != Class::Series16 {
            return Err(CncError::FUNC);
        }
        // The 16i-class FOCAS option probe (SPEC.md §3.4).
        if number == OPTION_PARAM_16 && e == number {
            return Ok(Param16 {
                number,
                axis,
                ptype: 0,
                values: vec![i32::from(self.profile.cnc.option), 0, 0, 0, 0, 0, 0, 0],
            }
            .to_bytes());
        }
        self.table_read16_range(path, Table::Param, number, e, axis)
    }

    // --- position ---
    fn alarm_bits(&mut self, path: u16) -> Reply<crate::proto::position::AlarmBits> {
        self.pos_alarm_bits(path)
    }
    fn prog_nums(&mut self, path: u16) -> Reply<crate::proto::position::ProgNums> {
        self.pos_prog_nums(path)
    }
    fn seq_num(&mut self, path: u16) -> Reply<crate::proto::position::SeqNum> {
        self.pos_seq_num(path)
    }
    fn actual(&mut self, path: u16, spindle: bool) -> Reply<crate::proto::value::Value> {
        self.pos_actual(path, spindle)
    }
    fn speed_a5(&mut self, path: u16) -> Reply<crate::proto::value::Value> {
        self.pos_speed_a5(path)
    }
    fn positions(
        &mut self,
        path: u16,
        code: i32,
        axis: i32,
    ) -> Reply<Vec<crate::proto::value::Value>> {
        self.pos_positions(path, code, axis)
    }
    fn figures(&mut self, path: u16, data_type: i32) -> Reply<crate::proto::position::Figures> {
        self.pos_figures(path, data_type)
    }
    fn axis_names(&mut self, path: u16) -> Reply<Vec<crate::proto::position::Name>> {
        self.pos_axis_names(path)
    }
    fn axis_pos_names(&mut self, path: u16) -> Reply<crate::proto::position::AxisNames> {
        self.pos_axis_pos_names(path)
    }
    fn spindle_names(&mut self, path: u16) -> Reply<Vec<crate::proto::position::Name>> {
        self.pos_spindle_names(path)
    }
    fn spindle_data(
        &mut self,
        path: u16,
        code: i32,
        sp_no: i32,
    ) -> Reply<Vec<crate::proto::value::Value>> {
        self.pos_spindle_data(path, code, sp_no)
    }
    fn servo_load(&mut self, path: u16, code: i32) -> Reply<Vec<crate::proto::value::Value>> {
        self.pos_servo_load(path, code)
    }
    fn units(&mut self, path: u16, kind: i32) -> Reply<Vec<u16>> {
        self.pos_units(path, kind)
    }
    fn axis_flags(&mut self, path: u16) -> Reply<Vec<u32>> {
        self.pos_axis_flags(path)
    }
    fn counts(&mut self, path: u16, kind: i32) -> Reply<crate::proto::position::Count> {
        self.pos_counts(path, kind)
    }

    // --- program ---
    fn exe_prgname(&mut self, path: u16) -> Reply<crate::proto::program::ExePrgName> {
        self.sim_exe_prgname(path)
    }

    fn exe_prgname2(&mut self, path: u16) -> Reply<crate::proto::program::PathName> {
        self.sim_exe_prgname2(path)
    }

    fn exec_prog(&mut self, path: u16, length: i32) -> Reply<crate::proto::program::ExecProg> {
        self.sim_exec_prog(path, length)
    }

    fn modal_g(
        &mut self,
        path: u16,
        code: i32,
        _block: i32,
    ) -> Reply<crate::proto::program::GModal> {
        self.sim_modal_g(path, code)
    }

    fn modal_aux(
        &mut self,
        path: u16,
        code: i32,
        _block: i32,
    ) -> Reply<crate::proto::program::AuxModal> {
        self.sim_modal_aux(path, code)
    }

    fn timer(&mut self, _path: u16, kind: i32) -> Reply<crate::proto::program::Timer> {
        self.sim_timer(kind)
    }

    fn clock(&mut self, _path: u16, kind: i32) -> Reply<crate::proto::program::Clock> {
        self.sim_clock(kind)
    }

    fn set_clock(&mut self, _path: u16, kind: i32, payload: &[u8]) -> Reply<()> {
        self.sim_set_clock(kind, payload)
    }

    fn opmode(&mut self, path: u16) -> Reply<crate::proto::program::OpMode> {
        self.sim_opmode(path)
    }

    fn prog_dir(
        &mut self,
        path: u16,
        top: i32,
        count: i32,
        code: i32,
    ) -> Reply<crate::proto::program::ProgDir> {
        self.sim_prog_dir(path, top, count, code)
    }

    // --- alarm ---
    fn alarm_messages(&mut self, path: u16, kind: i32, num: i32, text_len: i32) -> Reply<Vec<u8>> {
        self.sim_alarm_messages(path, kind, num, text_len)
    }

    fn opmsg(&mut self, path: u16, kind: i32) -> Reply<crate::proto::alarm::OpMsg> {
        self.sim_opmsg(path, kind)
    }
    fn opmsg3(&mut self, path: u16, start: i32, kind: i32, n: i32) -> Reply<Vec<u8>> {
        self.sim_opmsg3(path, start, kind, n)
    }
    fn restart_info(&mut self, path: u16, k: i32) -> Reply<Vec<u8>> {
        Machine::restart_info(self, path, k)
    }
    fn ctrl_signals(&mut self, path: u16, output: bool) -> Reply<Vec<u8>> {
        self.spindle_signals(path, output)
    }

    // --- param ---
    fn param_read30(
        &mut self,
        path: u16,
        table: Table,
        s: i32,
        e: i32,
        axis: i16,
    ) -> Reply<Vec<u8>> {
        let c = &self.profile.cnc;
        if c.class == Class::Series16
            && c.kind == 2
            && table == Table::Param
            && s == OPTION_PARAM_15
        {
            // The Series-15 FOCAS option probe (SPEC.md §3.4), in the
            // 16i value form the library reads it in.
            let p = Param16 {
                number: s,
                axis,
                ptype: 0,
                values: vec![i32::from(c.option), 0, 0, 0, 0, 0, 0, 0],
            };
            return Ok(p.to_bytes());
        }
        if c.class == Class::Series16 && c.kind == 2 && s == e {
            // A Series 15 reads parameters and diagnosis data with the 30i
            // commands, answered in the 16i value form (as FANUC's library
            // reads them).
            return self
                .table_read16(path, table, s, axis)
                .map(|p| p.to_bytes());
        }
        if c.class != Class::Series30 {
            return Err(CncError::FUNC);
        }
        self.table_read30(path, table, s, e, axis)
    }
    fn diag16(&mut self, path: u16, s: i32, e: i32, axis: i16) -> Reply<Vec<u8>> {
        if self.profile.cnc.class != Class::Series16 {
            return Err(CncError::FUNC);
        }
        self.table_read16_range(path, Table::Diag, s, e, axis)
    }
    fn param_type30(&mut self, _path: u16, table: Table, number: i32) -> Reply<ParamType30> {
        if self.profile.cnc.class != Class::Series30 {
            return Err(CncError::FUNC);
        }
        self.table_type30(table, number)
    }
    fn param_info3(&mut self, _path: u16, s: i32, n: i32) -> Reply<Vec<u8>> {
        self.table_info3(s, n)
    }
    fn param_num(&mut self, _path: u16, table: Table) -> Reply<NumRange> {
        Ok(self.table_num(table))
    }
    fn param_info(&mut self, _path: u16, table: Table, s: i32, n: i32) -> Reply<InfoList> {
        self.table_info(table, s, n)
    }
    fn param_write(&mut self, path: u16, class16: bool, payload: &[u8]) -> Reply<Vec<u8>> {
        if class16 != (self.profile.cnc.class == Class::Series16) {
            return Err(CncError::FUNC);
        }
        self.table_write(path, class16, payload)
    }

    // --- macros ---
    fn read_macros(&mut self, path: u16, s: i32, e: i32) -> Reply<Vec<crate::proto::value::Value>> {
        self.sim_read_macros(path, s, e)
    }

    fn write_macros(
        &mut self,
        path: u16,
        s: i32,
        e: i32,
        records: &[crate::proto::value::Value],
    ) -> Reply<()> {
        self.sim_write_macros(path, s, e, records)
    }

    fn read_macros_double(
        &mut self,
        path: u16,
        s: i32,
        n: i32,
    ) -> Reply<Vec<crate::proto::macros::Double>> {
        self.sim_read_macros_double(path, s, n)
    }

    fn write_macros_double(
        &mut self,
        path: u16,
        s: i32,
        values: &[crate::proto::macros::Double],
    ) -> Reply<i32> {
        self.sim_write_macros_double(path, s, values)
    }

    // --- pmc ---
    fn read_pmc(&mut self, unit: u16, range: crate::proto::pmc::PmcRange) -> Reply<Vec<u8>> {
        self.profile.pmc.read(unit, &range)
    }

    fn write_pmc(
        &mut self,
        unit: u16,
        range: crate::proto::pmc::PmcRange,
        data: &[u8],
    ) -> Reply<()> {
        let old = self.profile.pmc.read(unit, &range).unwrap_or_default();
        self.profile.pmc.write(unit, &range, data)?;
        // Signal changes (G, F, Y, X: address types 0..3) go into the
        // operation history, one record per changed byte the history's
        // signal table selects.
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

    fn pmc_info(&mut self, unit: u16, adr_type: i16) -> Reply<crate::proto::pmc::PmcInfo> {
        self.profile.pmc.info(unit, adr_type)
    }

    fn pmc_unit_types(&mut self, most: i32) -> Reply<Vec<i32>> {
        Ok(self.profile.pmc.unit_types(most))
    }

    fn pmc_select(&mut self, unit: i32) -> Reply<()> {
        self.profile.pmc.select(unit)
    }

    // --- offset ---
    fn rdtofs(
        &mut self,
        path: u16,
        s: i32,
        e: i32,
        kind: i32,
    ) -> Reply<Vec<crate::proto::value::Value>> {
        self.tofs_read(path, s, e, kind)
    }
    fn wrtofs(
        &mut self,
        path: u16,
        n: i32,
        kind: i32,
        payload: &[u8],
    ) -> Reply<crate::proto::offset::Ack> {
        self.tofs_write(path, n, kind, payload)
    }
    fn rdzofs(
        &mut self,
        path: u16,
        s: i32,
        e: i32,
        axis: i32,
    ) -> Reply<Vec<crate::proto::value::Value>> {
        self.zofs_read(path, s, e, axis)
    }
    fn wrzofs(
        &mut self,
        path: u16,
        n: i32,
        axis: i32,
        payload: &[u8],
    ) -> Reply<crate::proto::offset::Ack> {
        self.zofs_write(path, n, axis, payload)
    }
    fn rdalmhistry(&mut self, s: i32, e: i32) -> Reply<crate::proto::alarm::AlmHistory> {
        self.history_read(s, e)
    }
    fn rdalmhisno(&mut self) -> Reply<crate::proto::offset::Count> {
        self.history_count()
    }
    fn history_records(&mut self, path: u16, cmd: u16, args: [i32; 5]) -> Reply<Vec<u8>> {
        self.history_bytes(path, cmd, args)
    }

    // --- described functions ---
    fn described(&mut self, f: &'static Func, path: u16, args: &[i32]) -> Reply<Vec<i64>> {
        let v = |x: i32| i64::from(x);
        match f.name {
            "cnc_rdblkcount" => Ok(vec![v(self.sim_block_count(path)?)]),
            "cnc_rdactpt" => self
                .sim_actpt(path)
                .map(|a| vec![v(a.prog_no), v(a.blk_no)]),
            "cnc_rdmacroinfo" => self
                .sim_macro_info(path)
                .map(|m| vec![v(m.use_no1), v(m.use_no2)]),
            "cnc_rdtofsinfo2" => self.tofs_info(path).map(|t| {
                let w = [t.reserved, t.use_no, t.ofs_type, t.enable];
                w.map(i64::from).to_vec()
            }),
            "cnc_rdproctime" => {
                let max = f.records.map_or(0, |r| usize::from(r.max));
                let runs = self.sim_proc_times(path, max)?;
                Ok(runs
                    .iter()
                    .flat_map(|r| [r[0], r[1], r[2], r[3], 0])
                    .collect())
            }
            "cnc_start" => self.cycle_start(path).map(|_| vec![]),
            "cnc_reset" | "cnc_reset2" => self.reset(path).map(|_| vec![]),
            "cnc_clralm" => self.clear_alarms(path, args[0] as i16).map(|_| vec![]),
            "cnc_rdspdlalm" => Ok(self
                .path(path)?
                .spindles
                .iter()
                .take(8)
                .map(|s| i64::from(s.alarm))
                .collect()),
            "cnc_rdpitchinfo" => Ok(vec![i64::from(self.profile.pitch.size)]),
            "pmc_get_number_of_pmc" => Ok(vec![self.profile.pmc.units() as i64]),
            "cnc_rdgrpid2" => self
                .tl_group_of_tool(path, args[0])
                .map(|g| vec![v(args[0]), v(g)]),
            "cnc_rdwkcdshft" => self
                .shift_read(path, args[0])
                .map(|r| [vec![v(args[0])], r].concat()),
            "cnc_deltlifegrp" => self.tl_delete(path, args[0], None).map(|_| vec![]),
            "cnc_deltlifedt" => self.tl_delete(path, args[0], Some(args[1])).map(|_| vec![]),
            "cnc_rdngrp" => self.tl_group_count(path).map(|n| vec![v(n)]),
            "cnc_rdzofsinfo" => self.zofs_info(path).map(|c| vec![v(c.value)]),
            "cnc_rdetherinfo" => {
                let c = &self.profile.cnc;
                Ok(vec![c.ether_type.into(), c.ether_device.into()])
            }
            name => match self.memory_answer(name, path, args) {
                Some(r) => r,
                None => self.history_answer(name).ok_or(CncError::FUNC),
            },
        }
    }

    // --- tool ---
    fn tool_groups(&mut self, path: u16, s: i32, e: i32) -> Reply<crate::proto::tool::GroupRange> {
        self.tl_groups(path, s, e)
    }
    fn tool_list(
        &mut self,
        path: u16,
        grp: i32,
        s: i32,
        e: i32,
    ) -> Reply<crate::proto::tool::ToolList> {
        self.tl_list(path, grp, s, e)
    }

    fn raw(&mut self, sub: &crate::proto::packet::ReqSub) -> Option<Reply<Vec<u8>>> {
        self.memory_raw(sub)
            .or_else(|| self.folder_raw(sub))
            .or_else(|| self.offset_raw(sub))
            .or_else(|| self.pmc_raw(sub))
            .or_else(|| self.maintenance_raw(sub))
            .or_else(|| self.history_raw(sub))
    }

    // --- upload ---
    fn upload(&mut self, req: &crate::proto::upload::StartReq) -> Reply<Vec<u8>> {
        self.upload_text(req)
    }
    fn receive(
        &mut self,
        how: crate::proto::download::Outgoing,
        req: &crate::proto::upload::StartReq,
        text: &[u8],
        done: bool,
    ) -> Reply<()> {
        match how {
            crate::proto::download::DOWNLOAD if done => self.download(req, text),
            crate::proto::download::DOWNLOAD => Ok(()),
            _ => self.dnc(req.path, text, done),
        }
    }
}

impl Machine {
    /// The PMC commands answered as bytes, on the unit of the subpacket's
    /// path word: 0x800b (title), 0x8010 (alarm messages), 0x804a / 0x804b
    /// (timer types).
    pub(crate) fn pmc_raw(&mut self, sub: &crate::proto::packet::ReqSub) -> Option<Reply<Vec<u8>>> {
        use crate::proto::pmc::{GET_TIMER_TYPE, PMC_RDALMMSG, RDPMCTITLE, SET_TIMER_TYPE};
        if sub.class != crate::proto::packet::CLASS_PMC {
            return None;
        }
        let (unit, a) = (sub.path, sub.args);
        let pmc = &mut self.profile.pmc;
        Some(match sub.cmd {
            RDPMCTITLE => pmc.title_bytes(unit),
            PMC_RDALMMSG => pmc.alarm_messages(unit, a[0], a[1]),
            GET_TIMER_TYPE => pmc.timer_types(unit, a[0], a[1]),
            SET_TIMER_TYPE => pmc
                .set_timer_types(unit, a[0], a[1], &sub.payload)
                .map(|()| Vec::new()),
            _ => return None,
        })
    }
}
