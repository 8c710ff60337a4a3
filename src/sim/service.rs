//! What a simulated CNC answers, one method per function. Every method has
//! a default that answers EW_FUNC (1), as a CNC lacking the function does,
//! so the simulator grows one function at a time.

use crate::ew;
use crate::proto::cmd;
use crate::proto::described;
use crate::proto::open::OpenBody;
use crate::proto::packet::{CLASS_CNC, CLASS_PMC, ReqSub, RespSub};
use crate::proto::param::{self, InfoList, NumRange, ParamType30, Table};
use crate::proto::status::{CncId, Status, Status2, SysInfo, Word};
use crate::proto::wire::Wire;
use crate::spec::Func;
// --- offset ---
use crate::proto::alarm::AlmHistory;
use crate::proto::offset::{Ack, Count};
use crate::proto::tool::{GroupRange, ToolList};
use crate::proto::value::Value;
// --- position ---
// --- program ---
use crate::proto::program as pprog;
// --- alarm ---
use crate::proto::alarm::OpMsg;

/// An error code a CNC puts in a response subpacket.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CncError {
    pub code: i16,
    pub detail: (u16, u16),
}

impl CncError {
    pub const fn new(code: i16) -> CncError {
        CncError {
            code,
            detail: (0, 0),
        }
    }
    pub const FUNC: CncError = CncError::new(ew::EW_FUNC);
    pub const NUMBER: CncError = CncError::new(ew::EW_NUMBER);
    pub const PATH: CncError = CncError::new(ew::EW_PATH);
}

pub type Reply<T> = Result<T, CncError>;

fn unsupported<T>() -> Reply<T> {
    Err(CncError::FUNC)
}

/// A CNC as the wire sees it. `path` is the 1-based path of the subpacket.
#[allow(unused_variables)]
pub trait CncService: Send {
    /// The open-response body (SPEC.md §3.2).
    fn open_body(&self) -> OpenBody;
    fn max_sessions(&self) -> usize {
        0
    }
    /// Brings the machine's running state (program cycle, scheduled events)
    /// up to `now`. Called once per data frame, before its subpackets are
    /// answered, so one frame sees one consistent snapshot.
    fn advance(&mut self, now: std::time::Instant) {}
    fn sysinfo(&mut self, path: u16) -> Reply<SysInfo> {
        unsupported()
    }
    fn statinfo(&mut self, path: u16) -> Reply<Status> {
        unsupported()
    }
    fn statinfo2(&mut self, path: u16) -> Reply<Status2> {
        unsupported()
    }
    fn hdck(&mut self, path: u16) -> Reply<Word> {
        unsupported()
    }
    fn tmmode(&mut self, path: u16) -> Reply<Word> {
        unsupported()
    }
    /// 0x8c: the Series-15 start-up companion of sysinfo (words; also
    /// read by cnc_rdposition: axis count and display words).
    fn sysinfo15(&mut self, path: u16) -> Reply<Vec<u16>> {
        unsupported()
    }
    /// 0x95: the Series-15 spindle whose name the speed display shows.
    fn spindle_shown15(&mut self, path: u16) -> Reply<Vec<u16>> {
        unsupported()
    }
    fn cnc_id(&mut self) -> Reply<CncId> {
        unsupported()
    }
    /// 16i-class parameter read (0x000e).
    /// 16i read of parameters (0x000e) [s, e, axis]: one item (`s == e`)
    /// or a range (cnc_rdparar), as answer blocks.
    fn param16(&mut self, path: u16, s: i32, e: i32, axis: i16) -> Reply<Vec<u8>> {
        unsupported()
    }

    // --- position ---
    /// 0x1a: one bit per active alarm type (also cnc_alarm / cnc_alarm2).
    fn alarm_bits(&mut self, path: u16) -> Reply<crate::proto::position::AlarmBits> {
        unsupported()
    }
    /// 0x1c: running and main program numbers (also cnc_rdprgnum).
    fn prog_nums(&mut self, path: u16) -> Reply<crate::proto::position::ProgNums> {
        unsupported()
    }
    /// 0x1d: sequence number (also cnc_rdseqnum).
    fn seq_num(&mut self, path: u16) -> Reply<crate::proto::position::SeqNum> {
        unsupported()
    }
    /// 0x24 (`spindle` false) / 0x25 (true): actual feed / spindle speed.
    fn actual(&mut self, path: u16, spindle: bool) -> Reply<crate::proto::value::Value> {
        unsupported()
    }
    /// 0xa5: rdaxisdata class 5 type 2 (meaning unknown).
    fn speed_a5(&mut self, path: u16) -> Reply<crate::proto::value::Value> {
        unsupported()
    }
    /// 0x26[code, axis]: positions (axis -1: max-axes records).
    fn positions(
        &mut self,
        path: u16,
        code: i32,
        axis: i32,
    ) -> Reply<Vec<crate::proto::value::Value>> {
        unsupported()
    }
    /// 0x1b\[type\]: input/output figures per axis.
    fn figures(&mut self, path: u16, data_type: i32) -> Reply<crate::proto::position::Figures> {
        unsupported()
    }
    /// 0x89\[0\]: 4-byte axis names.
    fn axis_names(&mut self, path: u16) -> Reply<Vec<crate::proto::position::Name>> {
        unsupported()
    }
    /// 0x89[-1]: names per position kind.
    fn axis_pos_names(&mut self, path: u16) -> Reply<crate::proto::position::AxisNames> {
        unsupported()
    }
    /// 0x8a: 4-byte spindle names.
    fn spindle_names(&mut self, path: u16) -> Reply<Vec<crate::proto::position::Name>> {
        unsupported()
    }
    /// 0x40[code, sp_no]: spindle data records.
    fn spindle_data(
        &mut self,
        path: u16,
        code: i32,
        sp_no: i32,
    ) -> Reply<Vec<crate::proto::value::Value>> {
        unsupported()
    }
    /// 0x56\[code\]: servo load records per axis.
    fn servo_load(&mut self, path: u16, code: i32) -> Reply<Vec<crate::proto::value::Value>> {
        unsupported()
    }
    /// 0x88\[kind\]: unit words.
    fn units(&mut self, path: u16, kind: i32) -> Reply<Vec<u16>> {
        unsupported()
    }
    /// 0xa3: display flags per axis.
    fn axis_flags(&mut self, path: u16) -> Reply<Vec<u32>> {
        unsupported()
    }
    /// 0xa4\[kind\]: axis / spindle counts.
    fn counts(&mut self, path: u16, kind: i32) -> Reply<crate::proto::position::Count> {
        unsupported()
    }

    // --- program ---
    fn exe_prgname(&mut self, path: u16) -> Reply<pprog::ExePrgName> {
        unsupported()
    }
    fn exe_prgname2(&mut self, path: u16) -> Reply<pprog::PathName> {
        unsupported()
    }
    /// 0x0020\[length\]: executing program text.
    fn exec_prog(&mut self, path: u16, length: i32) -> Reply<pprog::ExecProg> {
        unsupported()
    }
    /// 0x0021[code, block]: G-code groups.
    fn modal_g(&mut self, path: u16, code: i32, block: i32) -> Reply<pprog::GModal> {
        unsupported()
    }
    /// 0x0022[code, block]: other modal codes.
    fn modal_aux(&mut self, path: u16, code: i32, block: i32) -> Reply<pprog::AuxModal> {
        unsupported()
    }
    /// 0x0120\[type\]: timers.
    fn timer(&mut self, path: u16, kind: i32) -> Reply<pprog::Timer> {
        unsupported()
    }
    /// 0x0045\[type\]: date and time.
    fn clock(&mut self, path: u16, kind: i32) -> Reply<pprog::Clock> {
        unsupported()
    }
    /// 0x0046\[type\] + 12-byte payload: set date or time.
    fn set_clock(&mut self, path: u16, kind: i32, payload: &[u8]) -> Reply<()> {
        unsupported()
    }
    /// 0x0057: operation mode.
    fn opmode(&mut self, path: u16) -> Reply<pprog::OpMode> {
        unsupported()
    }
    /// 0x0006[top, count, code]: program directory records.
    fn prog_dir(&mut self, path: u16, top: i32, count: i32, code: i32) -> Reply<pprog::ProgDir> {
        unsupported()
    }

    // --- alarm ---
    /// 0x0023[type, num, _, text_len]: active alarms, records already encoded.
    fn alarm_messages(&mut self, path: u16, kind: i32, num: i32, text_len: i32) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// 0x0034\[type\]: operator message.
    fn opmsg(&mut self, path: u16, kind: i32) -> Reply<OpMsg> {
        unsupported()
    }
    /// 0x005b[0 | 1]: the spindle control input / output signals
    /// (cnc_rdctrldi / cnc_rdctrldo), already encoded.
    fn ctrl_signals(&mut self, path: u16, output: bool) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// 0x0043\[k\]: program restart data (cnc_rdprstrinfo), encoded.
    fn restart_info(&mut self, path: u16, k: i32) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// 0x00d0[start, type, n]: operator messages (cnc_rdopmsg3, 30i),
    /// records already encoded.
    fn opmsg3(&mut self, path: u16, start: i32, kind: i32, n: i32) -> Reply<Vec<u8>> {
        unsupported()
    }

    // --- param ---
    /// 30i read of parameters (0x008d) or diagnosis data (0x0093) [s, e, axis].
    fn param_read30(
        &mut self,
        path: u16,
        table: Table,
        s: i32,
        e: i32,
        axis: i16,
    ) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// 16i read of diagnosis data (0x0030) [s, e, axis]; parameters go through `param16`.
    fn diag16(&mut self, path: u16, s: i32, e: i32, axis: i16) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// 30i attribute record of a parameter (0x00a0) or diagnosis item (0x00a2).
    fn param_type30(&mut self, path: u16, table: Table, number: i32) -> Reply<ParamType30> {
        unsupported()
    }
    /// cnc_rdparainfo3 (0x00a0 with the list flag): parameters from `s` on.
    fn param_info3(&mut self, path: u16, s: i32, n: i32) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// cnc_rdparanum (0x0011) / cnc_rddiagnum (0x0032).
    fn param_num(&mut self, path: u16, table: Table) -> Reply<NumRange> {
        unsupported()
    }
    /// cnc_rdparainfo (0x0010) / cnc_rddiaginfo (0x0031).
    fn param_info(&mut self, path: u16, table: Table, s: i32, n: i32) -> Reply<InfoList> {
        unsupported()
    }
    /// Parameter write: 30i 0x008e, 16i 0x000f (`class16`).
    fn param_write(&mut self, path: u16, class16: bool, payload: &[u8]) -> Reply<Vec<u8>> {
        unsupported()
    }

    // --- macros ---
    /// Custom macro variables `s..=e` (0x0015).
    fn read_macros(&mut self, path: u16, s: i32, e: i32) -> Reply<Vec<crate::proto::value::Value>> {
        unsupported()
    }
    /// Writes custom macro variables `s..=e` (0x0016).
    fn write_macros(
        &mut self,
        path: u16,
        s: i32,
        e: i32,
        records: &[crate::proto::value::Value],
    ) -> Reply<()> {
        unsupported()
    }
    /// `n` variables from `s` as doubles (0x00a7).
    fn read_macros_double(
        &mut self,
        path: u16,
        s: i32,
        n: i32,
    ) -> Reply<Vec<crate::proto::macros::Double>> {
        unsupported()
    }
    /// Writes variables from `s` as doubles; answers the count (0x00a8).
    fn write_macros_double(
        &mut self,
        path: u16,
        s: i32,
        values: &[crate::proto::macros::Double],
    ) -> Reply<i32> {
        unsupported()
    }

    // --- pmc ---
    /// A PMC range's bytes (class 2, 0x8001).
    /// PMC unit `unit` (the subpacket's path word): a range's bytes (0x8001).
    fn read_pmc(&mut self, unit: u16, range: crate::proto::pmc::PmcRange) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// Writes a range (0x8002).
    fn write_pmc(
        &mut self,
        unit: u16,
        range: crate::proto::pmc::PmcRange,
        data: &[u8],
    ) -> Reply<()> {
        unsupported()
    }
    /// The unit's address areas (0x8003).
    fn pmc_info(&mut self, unit: u16, adr_type: i16) -> Reply<crate::proto::pmc::PmcInfo> {
        unsupported()
    }
    /// The PMC unit types, at most `most` (0x800f).
    fn pmc_unit_types(&mut self, most: i32) -> Reply<Vec<i32>> {
        unsupported()
    }
    /// Whether the CNC has PMC unit `unit` (0x800c).
    fn pmc_select(&mut self, unit: i32) -> Reply<()> {
        unsupported()
    }

    // --- offset ---
    /// 0x0008 [s, e, type] (type ≥ 1000: cnc_rdtofs's single form).
    fn rdtofs(&mut self, path: u16, s: i32, e: i32, kind: i32) -> Reply<Vec<Value>> {
        unsupported()
    }
    /// 0x0009 [n, n, 1000 + type] + one record.
    fn wrtofs(&mut self, path: u16, n: i32, kind: i32, payload: &[u8]) -> Reply<Ack> {
        unsupported()
    }
    /// 0x000b [s, e, axis].
    fn rdzofs(&mut self, path: u16, s: i32, e: i32, axis: i32) -> Reply<Vec<Value>> {
        unsupported()
    }
    /// 0x000c [n, n, axis] + records.
    fn wrzofs(&mut self, path: u16, n: i32, axis: i32, payload: &[u8]) -> Reply<Ack> {
        unsupported()
    }
    /// 0x006c [s, e, 1]: alarm history entries s..=e (1 = newest).
    fn rdalmhistry(&mut self, s: i32, e: i32) -> Reply<AlmHistory> {
        unsupported()
    }
    fn rdalmhisno(&mut self) -> Reply<Count> {
        unsupported()
    }
    /// The range reads of src/proto/history.rs (0x006a, 0x0073, 0x01b5,
    /// 0x01d1, 0x0012): the answer's bytes for the request's arguments.
    fn history_records(&mut self, path: u16, cmd: u16, args: [i32; 5]) -> Reply<Vec<u8>> {
        unsupported()
    }

    // --- tool ---
    /// 0x008b [s, e]: tool life group records (s = e: one group).
    fn tool_groups(&mut self, path: u16, s: i32, e: i32) -> Reply<GroupRange> {
        unsupported()
    }
    /// 0x004d [grp, s, e]: tools s..=e of a group.
    fn tool_list(&mut self, path: u16, grp: i32, s: i32, e: i32) -> Reply<ToolList> {
        unsupported()
    }

    // --- described functions (crate::spec) ---
    /// A function described as data: the reply's integers in the order of
    /// its layout (the codec encodes them). `args` are the caller's number
    /// arguments the request carried.
    fn described(&mut self, f: &'static Func, path: u16, args: &[i32]) -> Reply<Vec<i64>> {
        unsupported()
    }

    /// A command answered as bytes by the machine (`None`: not one it
    /// knows this way), tried before the described functions.
    fn raw(&mut self, sub: &ReqSub) -> Option<Reply<Vec<u8>>> {
        None
    }

    // --- upload ---
    /// Program upload on connection 1 (0x1501): the text to push in 0x1604
    /// frames, or the error for the CNC's error frame.
    fn upload(&mut self, req: &crate::proto::upload::StartReq) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// A download or DNC operation on connection 1: `text` is what its data
    /// frames carried so far; called after each data frame, and with `done`
    /// at the client's end frame. An error goes back in the CNC's error
    /// frame (and ends the transfer); Ok at the end is the end's answer.
    fn receive(
        &mut self,
        how: crate::proto::download::Outgoing,
        req: &crate::proto::upload::StartReq,
        text: &[u8],
        done: bool,
    ) -> Reply<()> {
        unsupported()
    }
}

fn enc<T: Wire>(r: Reply<T>) -> Reply<Vec<u8>> {
    r.map(|v| v.to_bytes())
}

/// Answers one request subpacket.
pub fn dispatch(svc: &mut dyn CncService, sub: &ReqSub) -> RespSub {
    let p = sub.path;
    let a = sub.args;
    let open = svc.open_body();
    let (paths, class) = (open.path_count() as u16, open.class());
    let r = if sub.class == CLASS_CNC && (p == 0 || p > paths) {
        Err(CncError::PATH)
    } else {
        match (sub.class, sub.cmd) {
            (CLASS_CNC, cmd::SYSINFO) => enc(svc.sysinfo(p)),
            (CLASS_CNC, cmd::STATINFO) => enc(svc.statinfo(p)),
            (CLASS_CNC, cmd::STATINFO2) => enc(svc.statinfo2(p)),
            (CLASS_CNC, cmd::HDCK) => enc(svc.hdck(p)),
            (CLASS_CNC, cmd::TMMODE) => enc(svc.tmmode(p)),
            (CLASS_CNC, cmd::SYSINFO15) => enc(svc.sysinfo15(p)),
            (CLASS_CNC, cmd::SPINDLE_SHOWN15) => enc(svc.spindle_shown15(p)),
            (CLASS_CNC, cmd::RDCNCID) => enc(svc.cnc_id()),
            (CLASS_CNC, cmd::RDPARAM16) => svc.param16(p, a[0], a[1], a[2] as i16),

            // --- position ---
            (CLASS_CNC, cmd::ALARM) => enc(svc.alarm_bits(p)),
            (CLASS_CNC, cmd::PRGNUM) => enc(svc.prog_nums(p)),
            (CLASS_CNC, cmd::SEQNUM) => enc(svc.seq_num(p)),
            (CLASS_CNC, cmd::ACTF) => enc(svc.actual(p, false)),
            (CLASS_CNC, cmd::ACTS) => enc(svc.actual(p, true)),
            (CLASS_CNC, cmd::SPEED_A5) => enc(svc.speed_a5(p)),
            (CLASS_CNC, cmd::POSITION) => enc(svc.positions(p, a[0], a[1])),
            (CLASS_CNC, cmd::GETFIGURE) => enc(svc.figures(p, a[0])),
            (CLASS_CNC, cmd::RDAXISNAME) if a[0] == -1 => enc(svc.axis_pos_names(p)),
            (CLASS_CNC, cmd::RDAXISNAME) => enc(svc.axis_names(p)),
            (CLASS_CNC, cmd::RDSPDLNAME) => enc(svc.spindle_names(p)),
            (CLASS_CNC, cmd::SPINDLE) => enc(svc.spindle_data(p, a[0], a[1])),
            (CLASS_CNC, cmd::SERVO_LOAD) => enc(svc.servo_load(p, a[0])),
            (CLASS_CNC, cmd::UNITS) => enc(svc.units(p, a[0])),
            (CLASS_CNC, cmd::AXIS_FLAGS) => enc(svc.axis_flags(p)),
            (CLASS_CNC, cmd::COUNT) => enc(svc.counts(p, a[0])),

            // --- program ---
            (CLASS_CNC, cmd::EXEPRGNAME) => enc(svc.exe_prgname(p)),
            (CLASS_CNC, cmd::EXEPRGNAME2) => enc(svc.exe_prgname2(p)),
            (CLASS_CNC, cmd::RDEXECPROG) => enc(svc.exec_prog(p, a[0])),
            (CLASS_CNC, cmd::MODAL_G) => enc(svc.modal_g(p, a[0], a[1])),
            (CLASS_CNC, cmd::MODAL_AUX) => enc(svc.modal_aux(p, a[0], a[1])),
            (CLASS_CNC, cmd::RDTIMER) => enc(svc.timer(p, a[0])),
            (CLASS_CNC, cmd::GETTIMER) => enc(svc.clock(p, a[0])),
            (CLASS_CNC, cmd::SETTIMER) => svc.set_clock(p, a[0], &sub.payload).map(|_| Vec::new()),
            (CLASS_CNC, cmd::RDOPMODE) => enc(svc.opmode(p)),
            (CLASS_CNC, cmd::RDPROGDIR) => enc(svc.prog_dir(p, a[0], a[1], a[2])),

            // --- alarm ---
            (CLASS_CNC, cmd::RDALMMSG) => svc.alarm_messages(p, a[0], a[1], a[3]),
            (CLASS_CNC, cmd::RDOPMSG) => enc(svc.opmsg(p, a[0])),
            (CLASS_CNC, cmd::RDOPMSG3) => svc.opmsg3(p, a[0], a[1], a[2]),
            (CLASS_CNC, cmd::RDPRSTR) => svc.restart_info(p, a[0]),
            (CLASS_CNC, cmd::RDCTRLSIG) => match a[0] {
                0 | 1 => svc.ctrl_signals(p, a[0] == 1),
                _ => Err(CncError::new(ew::EW_ATTRIB)),
            },

            // --- param ---
            (CLASS_CNC, cmd::RDPARAM) => svc.param_read30(p, Table::Param, a[0], a[1], a[2] as i16),
            (CLASS_CNC, cmd::DIAGNOSS) => svc.param_read30(p, Table::Diag, a[0], a[1], a[2] as i16),
            (CLASS_CNC, cmd::DIAGNOSS16) => svc.diag16(p, a[0], a[1], a[2] as i16),
            (CLASS_CNC, cmd::PARAMTYPE) if a[4] == param::INFO3_FLAG => {
                svc.param_info3(p, a[0], a[1])
            }
            (CLASS_CNC, cmd::PARAMTYPE) => enc(svc.param_type30(p, Table::Param, a[0])),
            (CLASS_CNC, cmd::DIAGTYPE) => enc(svc.param_type30(p, Table::Diag, a[0])),
            (CLASS_CNC, cmd::RDPARANUM) => enc(svc.param_num(p, Table::Param)),
            (CLASS_CNC, cmd::RDDIAGNUM) => enc(svc.param_num(p, Table::Diag)),
            (CLASS_CNC, cmd::RDPARAINFO) => enc(svc.param_info(p, Table::Param, a[0], a[1])),
            (CLASS_CNC, cmd::RDDIAGINFO) => enc(svc.param_info(p, Table::Diag, a[0], a[1])),
            (CLASS_CNC, cmd::WRPARAM) => svc.param_write(p, false, &sub.payload),
            (CLASS_CNC, cmd::WRPARAM16) => svc.param_write(p, true, &sub.payload),

            // --- macros ---
            (CLASS_CNC, cmd::RDMACRO) => enc(svc.read_macros(p, a[0], a[1])),
            (CLASS_CNC, cmd::WRMACRO) => {
                match Vec::<crate::proto::value::Value>::from_bytes(&sub.payload) {
                    Ok(v) => svc.write_macros(p, a[0], a[1], &v).map(|()| Vec::new()),
                    Err(_) => Err(CncError::new(ew::EW_LENGTH)),
                }
            }
            (CLASS_CNC, cmd::RDMACROR2) => enc(svc.read_macros_double(p, a[0], a[1])),
            (CLASS_CNC, cmd::WRMACROR2) => {
                match Vec::<crate::proto::macros::Double>::from_bytes(&sub.payload) {
                    Ok(v) => enc(svc.write_macros_double(p, a[0], &v)),
                    Err(_) => Err(CncError::new(ew::EW_LENGTH)),
                }
            }

            // --- pmc ---
            (CLASS_PMC, cmd::RDPMCRNG) => {
                svc.read_pmc(p, crate::proto::pmc::PmcRange::from_args(&a))
            }
            (CLASS_PMC, cmd::WRPMCRNG) => svc
                .write_pmc(p, crate::proto::pmc::PmcRange::from_args(&a), &sub.payload)
                .map(|()| Vec::new()),
            (CLASS_PMC, cmd::RDPMCINFO) => enc(svc.pmc_info(p, a[0] as i16)),
            (CLASS_PMC, cmd::UNIT_TYPES) => enc(svc.pmc_unit_types(a[0])),
            (CLASS_PMC, cmd::SELECT_UNIT) => svc.pmc_select(a[0]).map(|()| Vec::new()),

            // --- offset ---
            (CLASS_CNC, cmd::RDTOFS) => enc(svc.rdtofs(p, a[0], a[1], a[2])),
            (CLASS_CNC, cmd::WRTOFS) => enc(svc.wrtofs(p, a[0], a[2], &sub.payload)),
            (CLASS_CNC, cmd::RDZOFS) => enc(svc.rdzofs(p, a[0], a[1], a[2])),
            (CLASS_CNC, cmd::WRZOFS) => enc(svc.wrzofs(p, a[0], a[2], &sub.payload)),
            (CLASS_CNC, cmd::RDALMHISTRY) => enc(svc.rdalmhistry(a[0], a[1])),
            (CLASS_CNC, cmd::RDALMHISNO) => enc(svc.rdalmhisno()),
            (
                CLASS_CNC,
                c @ (cmd::RDOPHISTRY
                | cmd::RDOPHISTRY4
                | cmd::RDOMHISTRY
                | cmd::RDOMHISTRY2
                | cmd::RDALMHISTRY5
                | cmd::RDPITCHR),
            ) => svc.history_records(p, c, a),

            // --- tool ---
            (CLASS_CNC, cmd::TLGROUP) => enc(svc.tool_groups(p, a[0], a[1])),
            (CLASS_CNC, cmd::TLTOOLS) => enc(svc.tool_list(p, a[0], a[1], a[2])),
            _ => match (svc.raw(sub), described::for_request(sub, class)) {
                (Some(r), _) => r,
                (None, Some(f)) => svc
                    .described(f, p, &described::args_of(f, class, sub))
                    .and_then(|v| described::encode(f, &v).map_err(|_| CncError::FUNC)),
                (None, None) => Err(CncError::FUNC),
            },
        }
    };
    match r {
        Ok(payload) => RespSub::ok(sub, payload),
        Err(e) => RespSub::err(sub, e.code, e.detail.0, e.detail.1),
    }
}
