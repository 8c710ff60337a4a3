//! What a simulated CNC answers, one method per function. Every method has
//! a default that answers EW_FUNC (1), as a CNC lacking the function does,
//! so the simulator grows one function at a time.

use crate::ew;
use crate::proto::cmd;
use crate::proto::open::OpenBody;
use crate::proto::packet::{CLASS_CNC, ReqSub, RespSub};
use crate::proto::param::Param16;
use crate::proto::status::{CncId, Status, Status2, SysInfo, Word};
use crate::proto::wire::Wire;
// --- position ---
use crate::proto::position::{AlarmBits, ProgNums, SeqNum};
// --- program ---
use crate::proto::program as pprog;
// --- alarm ---
use crate::proto::alarm::{self as palarm, OpMsg};

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
    fn cnc_id(&mut self) -> Reply<CncId> {
        unsupported()
    }
    /// 16i-class parameter read (0x000e).
    fn param16(&mut self, path: u16, number: i32, axis: i16) -> Reply<Param16> {
        unsupported()
    }

    // --- position ---
    /// 0x001a: alarm bit map (cnc_alarm, cnc_alarm2, rddynamic2).
    fn alarm_bits(&mut self, path: u16) -> Reply<AlarmBits> {
        unsupported()
    }
    /// 0x001c: running and main program numbers.
    fn program_numbers(&mut self, path: u16) -> Reply<ProgNums> {
        unsupported()
    }
    /// 0x001d: sequence number.
    fn sequence_number(&mut self, path: u16) -> Reply<SeqNum> {
        unsupported()
    }

    // --- program ---
    fn block_count(&mut self, path: u16) -> Reply<i32> {
        unsupported()
    }
    fn actpt(&mut self, path: u16) -> Reply<pprog::ActPt> {
        unsupported()
    }
    fn exe_prgname(&mut self, path: u16) -> Reply<pprog::ExePrgName> {
        unsupported()
    }
    fn exe_prgname2(&mut self, path: u16) -> Reply<pprog::PathName> {
        unsupported()
    }
    /// 0x0020[length]: executing program text.
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
    /// 0x0120[type]: timers.
    fn timer(&mut self, path: u16, kind: i32) -> Reply<pprog::Timer> {
        unsupported()
    }
    /// 0x0045[type]: date and time.
    fn clock(&mut self, path: u16, kind: i32) -> Reply<pprog::Clock> {
        unsupported()
    }
    /// 0x0046[type] + 12-byte payload: set date or time.
    fn set_clock(&mut self, path: u16, kind: i32, payload: &[u8]) -> Reply<()> {
        unsupported()
    }
    /// 0x0057: operation mode.
    fn opmode(&mut self, path: u16) -> Reply<pprog::OpMode> {
        unsupported()
    }
    /// 0x004d[grp, tuse, tuse]: tool number in a tool-life group.
    fn toolnum(&mut self, path: u16, grp: i32, tuse: i32) -> Reply<pprog::ToolNum> {
        unsupported()
    }
    /// 0x008b[grp, grp]: number of tools in a tool-life group.
    fn ntool(&mut self, path: u16, grp: i32) -> Reply<pprog::NTool> {
        unsupported()
    }

    // --- alarm ---
    /// 0x0023[type, num, _, text_len]: active alarms, records already encoded.
    fn alarm_messages(&mut self, path: u16, kind: i32, num: i32, text_len: i32) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// 0x0034[type]: operator message.
    fn opmsg(&mut self, path: u16, kind: i32) -> Reply<OpMsg> {
        unsupported()
    }

    // --- param ---

    // --- macros ---

    // --- pmc ---

    // --- offset ---

    // --- tool ---
}

fn enc<T: Wire>(r: Reply<T>) -> Reply<Vec<u8>> {
    r.map(|v| v.to_bytes())
}

/// Answers one request subpacket.
pub fn dispatch(svc: &mut dyn CncService, sub: &ReqSub) -> RespSub {
    let p = sub.path;
    let a = sub.args;
    let paths = svc.open_body().path_count() as u16;
    let r = if sub.class == CLASS_CNC && (p == 0 || p > paths) {
        Err(CncError::PATH)
    } else {
        match (sub.class, sub.cmd) {
            (CLASS_CNC, cmd::SYSINFO) => enc(svc.sysinfo(p)),
            (CLASS_CNC, cmd::STATINFO) => enc(svc.statinfo(p)),
            (CLASS_CNC, cmd::STATINFO2) => enc(svc.statinfo2(p)),
            (CLASS_CNC, cmd::HDCK) => enc(svc.hdck(p)),
            (CLASS_CNC, cmd::TMMODE) => enc(svc.tmmode(p)),
            (CLASS_CNC, cmd::RDCNCID) => enc(svc.cnc_id()),
            (CLASS_CNC, cmd::RDPARAM16) => enc(svc.param16(p, a[0], a[2] as i16)),

            // --- position ---
            (CLASS_CNC, palarm::ALARM) => enc(svc.alarm_bits(p)),
            (CLASS_CNC, pprog::RDPRGNUM) => enc(svc.program_numbers(p)),
            (CLASS_CNC, pprog::RDSEQNUM) => enc(svc.sequence_number(p)),

            // --- program ---
            (CLASS_CNC, pprog::RDBLKCOUNT) => enc(svc.block_count(p)),
            (CLASS_CNC, pprog::RDACTPT) => enc(svc.actpt(p)),
            (CLASS_CNC, pprog::EXEPRGNAME) => enc(svc.exe_prgname(p)),
            (CLASS_CNC, pprog::EXEPRGNAME2) => enc(svc.exe_prgname2(p)),
            (CLASS_CNC, pprog::RDEXECPROG) => enc(svc.exec_prog(p, a[0])),
            (CLASS_CNC, pprog::MODAL_G) => enc(svc.modal_g(p, a[0], a[1])),
            (CLASS_CNC, pprog::MODAL_AUX) => enc(svc.modal_aux(p, a[0], a[1])),
            (CLASS_CNC, pprog::RDTIMER) => enc(svc.timer(p, a[0])),
            (CLASS_CNC, pprog::GETTIMER) => enc(svc.clock(p, a[0])),
            (CLASS_CNC, pprog::SETTIMER) => {
                svc.set_clock(p, a[0], &sub.payload).map(|_| Vec::new())
            }
            (CLASS_CNC, pprog::RDOPMODE) => enc(svc.opmode(p)),
            (CLASS_CNC, pprog::TOOLNUM) => enc(svc.toolnum(p, a[0], a[1])),
            (CLASS_CNC, pprog::RDNTOOL) => enc(svc.ntool(p, a[0])),

            // --- alarm ---
            (CLASS_CNC, palarm::RDALMMSG) => svc.alarm_messages(p, a[0], a[1], a[3]),
            (CLASS_CNC, palarm::RDOPMSG) => enc(svc.opmsg(p, a[0])),

            // --- param ---

            // --- macros ---

            // --- pmc ---

            // --- offset ---

            // --- tool ---
            _ => Err(CncError::FUNC),
        }
    };
    match r {
        Ok(payload) => RespSub::ok(sub, payload),
        Err(e) => RespSub::err(sub, e.code, e.detail.0, e.detail.1),
    }
}
