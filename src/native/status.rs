//! The CNC's status words (cnc_statinfo), system information (cnc_sysinfo)
//! and what it is executing (program and sequence numbers, feed, speed).

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::error::{Error, Ew, Result};
use super::part::{Part, Ready, via};
use crate::proto::described::Described;
use crate::proto::status::{StatInfo, Status as Words, SysInfo as RawSysInfo};
use std::fmt;

/// An enum over one status word: the values known by name, `Other` for the
/// rest; `code()` is the word, `Display` the CNC screen's abbreviation.
macro_rules! word_enum {
    ($(#[$m:meta])* $name:ident { $($(#[$vm:meta])* $v:ident = $code:literal, $text:literal;)* }) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum $name {
            $($(#[$vm])* $v,)*
            /// A value without a name here.
            Other(i16),
        }
        impl $name {
            pub fn from_code(code: i16) -> $name {
                match code {
                    $($code => $name::$v,)*
                    c => $name::Other(c),
                }
            }
            /// The status word.
            pub fn code(self) -> i16 {
                match self {
                    $($name::$v => $code,)*
                    $name::Other(c) => c,
                }
            }
        }
        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                match self {
                    $($name::$v => f.pad($text),)*
                    $name::Other(c) => f.pad(&c.to_string()),
                }
            }
        }
    };
}

word_enum! {
    /// The operation mode (`aut`).
    Mode {
        Mdi = 0, "MDI";
        /// Memory (automatic operation from a stored program).
        Mem = 1, "MEM";
        /// No mode selected.
        NoSelection = 2, "****";
        Edit = 3, "EDIT";
        /// Manual handle.
        Handle = 4, "HND";
        Jog = 5, "JOG";
        TeachJog = 6, "TJOG";
        TeachHandle = 7, "THND";
        /// Incremental feed.
        Incremental = 8, "INC";
        /// Reference position return.
        Reference = 9, "REF";
        /// Remote (DNC) operation.
        Remote = 10, "RMT";
    }
}

word_enum! {
    /// The automatic operation state (`run`).
    Run {
        /// Reset: no automatic operation.
        Reset = 0, "****";
        Stop = 1, "STOP";
        /// Feed hold.
        Hold = 2, "HOLD";
        /// Cycle start: running.
        Start = 3, "STRT";
        /// Retraction and recovery, or manual operation during it.
        Mstr = 4, "MSTR";
    }
}

word_enum! {
    /// Axis motion (`motion`).
    Motion {
        Idle = 0, "***";
        Moving = 1, "MTN";
        Dwell = 2, "DWL";
    }
}

word_enum! {
    /// Emergency stop and reset (`emergency`).
    Emergency {
        Clear = 0, "****";
        Emergency = 1, "EMG";
        Reset = 2, "RSET";
    }
}

word_enum! {
    /// Alarm state (`alarm`).
    AlarmState {
        Clear = 0, "****";
        Alarm = 1, "ALM";
        BatteryLow = 2, "BAT";
    }
}

/// The status of the current path, as cnc_statinfo reads it.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Status {
    pub mode: Mode,
    pub run: Run,
    pub motion: Motion,
    /// M, S, T, B function state (0 none, 1 waiting for FIN).
    pub mstb: i16,
    pub emergency: Emergency,
    pub alarm: AlarmState,
    /// Program editing state (0 none; the other values depend on the series).
    pub edit: i16,
}

impl Status {
    fn of(w: Words) -> Status {
        Status {
            mode: Mode::from_code(w.aut),
            run: Run::from_code(w.run),
            motion: Motion::from_code(w.motion),
            mstb: w.mstb,
            emergency: Emergency::from_code(w.emergency),
            alarm: AlarmState::from_code(w.alarm),
            edit: w.edit,
        }
    }
}

fn status_part() -> impl Part<Out = Status> + Send + 'static {
    const CALL: &str = "cnc_statinfo";
    via(CALL, StatInfo::<Words>::new(), 2 * 7 + 4, |r| {
        let w = r.words.map_err(|e| Error::of(CALL, e))?;
        if w.len() < 7 {
            return Err(Error::of(
                CALL,
                crate::error::Error::short("fewer than 7 status words"),
            ));
        }
        let words = Words {
            aut: w[0],
            run: w[1],
            motion: w[2],
            mstb: w[3],
            emergency: w[4],
            alarm: w[5],
            edit: w[6],
        };
        Ok(Status::of(words))
    })
}

/// What the CNC reported about itself at connect time (cnc_sysinfo).
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct SysInfo {
    /// CNC type: "31" (31i), "16" (16i), "0" (0i) ...
    pub cnc_type: String,
    /// Machine type: "M" (machining centre), "T" (lathe) ...
    pub mt_type: String,
    /// Software series, e.g. "G421".
    pub series: String,
    /// Software version, e.g. "08.0".
    pub version: String,
    /// Controlled axes of the path.
    pub axes: u16,
    /// The most axes a path can have.
    pub max_axes: u16,
    /// Additional information bits (`addinfo`).
    pub addinfo: u16,
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b)
        .trim_matches(|c: char| c == '\0' || c.is_whitespace())
        .to_string()
}

impl SysInfo {
    fn of(s: &RawSysInfo) -> SysInfo {
        SysInfo {
            cnc_type: text(&s.cnc_type),
            mt_type: text(&s.mt_type),
            series: text(&s.series),
            version: text(&s.version),
            axes: text(&s.axes).parse().unwrap_or(0),
            max_axes: s.max_axis,
            addinfo: s.addinfo,
        }
    }
}

/// What the current path executes: program and sequence numbers, actual
/// feed rate and spindle speed (cnc_rdprgnum, cnc_rdseqnum, cnc_actf,
/// cnc_acts in one frame).
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Execution {
    /// The O number running (or selected).
    pub program: u32,
    /// The main program's O number.
    pub main_program: u32,
    /// The sequence (N) number of the block executing.
    pub sequence: i32,
    /// Actual feed rate (mm/min or inch/min).
    pub feed: i32,
    /// Actual spindle speed (min⁻¹).
    pub spindle_speed: i32,
}

/// One described function (src/spec/table/) without arguments: its reply's integers.
pub(super) fn described(name: &'static str) -> impl Part<Out = Vec<i64>> + Send + 'static {
    let f = crate::spec::find(name).expect("a described function");
    via(name, Described::new(f, &[]), f.reply_len(), Ok)
}

/// The four parts of [`Execution`] as one: their subpackets in one frame.
struct ExecutionPart;

impl Part for ExecutionPart {
    type Out = Execution;
    fn call(&self) -> &'static str {
        "cnc_rdprgnum"
    }
    fn subs(&self, cx: &crate::proto::call::Ctx) -> Vec<crate::proto::packet::ReqSub> {
        Self::parts().iter().flat_map(|p| p.subs(cx)).collect()
    }
    fn answer_max(&self, cx: &crate::proto::call::Ctx) -> usize {
        Self::parts().iter().map(|p| p.answer_max(cx)).sum()
    }
    fn decode(
        &self,
        cx: &crate::proto::call::Ctx,
        resp: &[crate::proto::packet::RespSub],
    ) -> Result<Execution> {
        let mut v = Vec::new();
        for (i, p) in Self::parts().iter().enumerate() {
            let r = p.decode(cx, resp.get(i..i + 1).unwrap_or(&[]))?;
            v.push(r);
        }
        let w = |i: usize, k: usize| v[i].get(k).map_or(0, |x| *x as i32);
        Ok(Execution {
            // O numbers (a negative word: none).
            program: w(0, 0).max(0) as u32,
            main_program: w(0, 1).max(0) as u32,
            sequence: w(1, 0),
            feed: w(2, 0),
            spindle_speed: w(3, 0),
        })
    }
}

impl ExecutionPart {
    fn parts() -> [impl Part<Out = Vec<i64>>; 4] {
        ["cnc_rdprgnum", "cnc_rdseqnum", "cnc_actf", "cnc_acts"].map(described)
    }
}

fn sysinfo_part(cnc: &Cnc, path: u16) -> Ready<SysInfo> {
    let info = &cnc.handle().pair.info;
    Ready(
        info.sysinfo
            .get(usize::from(path).wrapping_sub(1))
            .copied()
            .flatten()
            .map(|s| SysInfo::of(&s))
            .ok_or_else(|| Error::invalid("cnc_sysinfo", Ew::PATH, format!("no path {path}"))),
    )
}

impl Cnc {
    /// The status of the current path (cnc_statinfo).
    ///
    /// ```
    /// use fwlib32::native::{Cnc, Mode, Run};
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// let st = cnc.status()?;
    /// assert_eq!((st.mode, st.run), (Mode::Mem, Run::Start));
    /// assert_eq!(st.mode.to_string(), "MEM");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn status(&self) -> Result<Status> {
        self.run(status_part())
    }

    /// The current path's system information (cnc_sysinfo; known since
    /// connecting, no traffic).
    ///
    /// ```
    /// # use fwlib32::native::Cnc;
    /// # use fwlib32::sim::{Profile, Simulator};
    /// # let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// # let cnc = Cnc::connect(&sim.addr().to_string(), std::time::Duration::from_secs(5))?;
    /// let info = cnc.sysinfo()?;
    /// assert_eq!((info.cnc_type.as_str(), info.mt_type.as_str(), info.axes), ("31", "M", 3));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn sysinfo(&self) -> Result<SysInfo> {
        self.run(sysinfo_part(self, self.path()))
    }

    /// The system information of path `path` (1..=[`Cnc::path_count`]).
    pub fn sysinfo_of(&self, path: u16) -> Result<SysInfo> {
        self.run(sysinfo_part(self, path))
    }

    /// The CNC's identification number (cnc_rdcncid): four 32-bit words.
    pub fn cnc_id(&self) -> Result<Vec<u32>> {
        let f = crate::spec::find("cnc_rdcncid").expect("a described function");
        self.run(via("cnc_rdcncid", Described::new(f, &[]), 16, |id| {
            Ok(id.into_iter().map(|w| w as u32).collect())
        }))
    }

    /// What the current path executes (see [`Execution`]), in one frame.
    pub fn execution(&self) -> Result<Execution> {
        self.run(ExecutionPart)
    }
}

impl Batch<'_> {
    /// [`Cnc::status`] in the batch.
    pub fn status(&mut self) -> Ticket<Status> {
        self.push(status_part())
    }

    /// [`Cnc::sysinfo`] in the batch (no traffic).
    pub fn sysinfo(&mut self) -> Ticket<SysInfo> {
        let p = sysinfo_part(self.cnc(), self.cnc().path());
        self.push(p)
    }

    /// [`Cnc::execution`] in the batch.
    pub fn execution(&mut self) -> Ticket<Execution> {
        self.push(ExecutionPart)
    }
}
