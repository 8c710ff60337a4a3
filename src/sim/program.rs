//! The simulator's program, timer and alarm answers (areas `program` and
//! `alarm`). Live values (program, block, alarms) come from
//! [`super::run::PathRun`] at request time.

use super::Machine;
use super::modal::ProgramModal;
pub use super::profile::program::{Modal, OperatorMessage, Timers};
use super::route::{Asked, Route, enc};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::alarm::{OpMsg, RDALMMSG, RDOPMSG, RDOPMSG3};
use crate::proto::cmd::RDPROCTIME;
use crate::proto::cmd::{RDACTPT, RDBLKCOUNT, RDCOMMAND, RDMULTIPIECENO};
use crate::proto::program::{
    AUX_ORDER, ActPt, AuxCode, AuxModal, Clock, DirEntry, EXEPRGNAME, EXEPRGNAME2, ExecProg, GCode,
    GETTIMER, GModal, MODAL_AUX, MODAL_G, ProgDir, RDEXECPROG, RDOPMODE, RDPROGDIR, RDTIMER,
    SETTIMER, Timer,
};

pub(super) const ROUTES: &[Route] = &[
    Route::table(EXEPRGNAME, |m, q| m.exe_prgname(q.path)),
    Route::table(EXEPRGNAME2, |m, q| m.exe_prgname2(q.path)),
    Route::cnc(RDEXECPROG, |m, q| enc(m.exec_prog(q.path, q.args[0]))),
    Route::cnc(MODAL_G, |m, q| enc(m.g_modal(q.path, q.args[0]))),
    Route::cnc(MODAL_AUX, |m, q| enc(m.aux_modal(q.path, q.args[0]))),
    // cnc_rdtimer's layout.
    Route::table(RDTIMER, |m, q| {
        m.timer(q.arg(0))
            .map(|t| vec![i64::from(t.minute), i64::from(t.msec)])
    }),
    Route::cnc(GETTIMER, |m, q| enc(m.clock(q.args[0]))),
    Route::cnc(SETTIMER, |m, q| {
        m.set_clock(q.args[0], &q.payload).map(|()| Vec::new())
    }),
    // cnc_rdopmode: the path's `opmode` word.
    Route::table(RDOPMODE, |m, q| Ok(vec![i64::from(m.path(q.path)?.opmode)])),
    Route::cnc(RDPROGDIR, |m, q| {
        enc(m.prog_dir(q.path, q.args[0], q.args[1], q.args[2]))
    }),
    // [type, num, _, text_len]
    Route::cnc(RDALMMSG, |m, q| {
        m.alarm_messages(q.path, q.args[0], q.args[1], q.args[3])
    }),
    Route::cnc(RDOPMSG, |m, q| enc(m.opmsg(q.path, q.args[0]))),
    Route::cnc(RDOPMSG3, |m, q| {
        m.opmsg3(q.path, q.args[0], q.args[1], q.args[2])
    }),
    Route::table(RDBLKCOUNT, |m, q| {
        Ok(vec![i64::from(m.block_count(q.path)?)])
    }),
    Route::table(RDACTPT, |m, q| {
        m.actpt(q.path)
            .map(|a| vec![i64::from(a.prog_no), i64::from(a.blk_no)])
    }),
    Route::table(RDPROCTIME, processing_times),
    Route::table(RDCOMMAND, commanded),
    // cnc_rdmultipieceno: the path's `[path.cycle] multi_piece`.
    Route::table(RDMULTIPIECENO, |m, q| {
        Ok(vec![i64::from(m.path(q.path)?.cycle.multi_piece)])
    }),
];

/// cnc_rdcommand \[type, block\]: the values in force in the block in
/// execution (block 0) that cnc_modal's other codes read (the running
/// program's, else the profile's `[path.modal]`), one record per address
/// in cnc_modal's order (B D F H M S T), or the one of address `type`
/// (0 'A' .. 25 'Z'): the letter, 1 (its first word), flag 0, the value, 0
/// decimals. Other blocks: EW_NUMBER (the simulator keeps no look-ahead).
fn commanded(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let (kind, block) = (q.arg(0), q.arg(1));
    if block != 0 || !(-1..26).contains(&kind) {
        return Err(CncError::NUMBER);
    }
    let aux = &m.path(q.path)?.modal.aux;
    let set = &m.live(q.path)?.modal;
    let mut v = Vec::new();
    for (k, letter) in ProgramModal::letters() {
        let value = set
            .aux_value(k)
            .or_else(|| aux.get(&(100 + k).to_string()).copied());
        let wanted = kind == -1 || i64::from(kind) == letter as i64 - 'A' as i64;
        if let (Some(value), true) = (value, wanted) {
            v.extend([letter as i64, 1, 0, i64::from(value), 0]);
        }
    }
    Ok(v)
}

/// cnc_rdproctime: as many runs as the layout's records hold.
fn processing_times(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let max = q.f.records.map_or(0, |r| usize::from(r.max));
    let runs = m.proc_times(q.path, max)?;
    Ok(runs
        .iter()
        .flat_map(|r| [r[0], r[1], r[2], r[3], 0])
        .collect())
}
use crate::proto::wire::{Reader, Wire, Writer};

/// G-code groups answered for type −1 (g_rdata[35]).
const G_GROUPS: usize = 35;
/// One-shot G codes answered for types −4/−5 (g_1shot[4]).
const G_ONESHOT: usize = 4;
/// Records of other codes the CNC indexes by code (0..=28, see AUX_ORDER).
const AUX_CODES: i32 = 29;

fn err(code: i16) -> CncError {
    CncError::new(code)
}

impl Machine {
    /// cnc_rdproctime: the runs of the program completed, newest first (at
    /// most `max`): program number and its time as hours, minutes, seconds.
    pub(crate) fn proc_times(&self, path: u16, max: usize) -> Reply<Vec<[i64; 4]>> {
        let r = self.live(path)?;
        let secs = r.run_seconds.round() as i64;
        let n = (r.runs_done as usize).min(max);
        let one = [i64::from(r.program), secs / 3600, secs / 60 % 60, secs % 60];
        let earlier = self.profile.paths[path as usize - 1].proc_times.iter();
        Ok(std::iter::repeat_n(one, n)
            .chain(earlier.map(|t| t.map(i64::from)))
            .take(max)
            .collect())
    }

    pub(crate) fn block_count(&self, path: u16) -> Reply<i32> {
        Ok(self.live(path)?.block_count)
    }

    pub(crate) fn actpt(&self, path: u16) -> Reply<ActPt> {
        let r = self.live(path)?;
        Ok(ActPt {
            prog_no: r.program,
            blk_no: r.block as i32,
        })
    }

    /// The program's full path name: the profile's if it is one, else
    /// "//CNC_MEM/USER/PATH<n>/<name>".
    fn full_name(&self, path: u16) -> Reply<String> {
        let name = self.shown_program(path)?.1;
        Ok(if name.starts_with("//") || name.is_empty() {
            name
        } else {
            format!("//CNC_MEM/USER/PATH{path}/{name}")
        })
    }

    /// The program a path shows (cnc_rdprgnum, cnc_exeprgname): the one it
    /// executes, else the main program selected (cnc_search), as number
    /// and name.
    pub(crate) fn shown_program(&self, path: u16) -> Reply<(i32, String)> {
        let (r, s) = (self.live(path)?, self.store.path(path)?);
        if s.running != 0 || s.main == 0 {
            return Ok((r.program, r.program_name.clone()));
        }
        let p = s.find(s.main).map(super::store::Program::display_name);
        Ok((s.main, p.unwrap_or_default()))
    }

    /// cnc_exeprgname's layout: the O number, then the name's 36
    /// characters (at most 35, zeros after).
    pub(crate) fn exe_prgname(&self, path: u16) -> Reply<Vec<i64>> {
        let full = self.full_name(path)?;
        let short = full.rsplit('/').next().unwrap_or("").as_bytes();
        let mut v = vec![i64::from(self.shown_program(path)?.0)];
        v.extend((0..36).map(|k| {
            i64::from(if k < 35 {
                short.get(k).copied().unwrap_or(0)
            } else {
                0
            })
        }));
        Ok(v)
    }

    /// cnc_exeprgname2's layout: the full name's 255 characters (zeros
    /// after it), then the NUL.
    pub(crate) fn exe_prgname2(&self, path: u16) -> Reply<Vec<i64>> {
        let b = self.full_name(path)?.into_bytes();
        Ok((0..256)
            .map(|k| {
                i64::from(if k < 255 {
                    b.get(k).copied().unwrap_or(0)
                } else {
                    0
                })
            })
            .collect())
    }

    /// The executing text, at most `length` bytes. A path with no text to
    /// show answers its block number and no text (an idle path: four zero
    /// bytes), as a CNC does; FANUC's library reads past its buffer on an
    /// empty payload, so the simulator never sends one.
    pub(crate) fn exec_prog(&self, path: u16, length: i32) -> Reply<ExecProg> {
        let r = self.live(path)?;
        if r.program == 0 || r.exec_text.is_empty() {
            return Ok(ExecProg {
                blknum: Some(if r.program == 0 { 0 } else { r.block as i32 }),
                text: Vec::new(),
            });
        }
        let mut text = r.exec_text.clone().into_bytes();
        text.truncate(length.max(0) as usize);
        Ok(ExecProg {
            blknum: Some(r.block as i32),
            text,
        })
    }

    /// cnc_modal's G groups: what the running program set (src/sim/modal.rs),
    /// else the profile's table.
    pub(crate) fn g_modal(&self, path: u16, code: i32) -> Reply<GModal> {
        self.path(path)?;
        let at = |i: usize| GCode {
            code: self.modal_g(path, i),
            flag: 0,
        };
        Ok(GModal(match code {
            -1 => (0..G_GROUPS).map(at).collect(),
            -2 | -3 => vec![GCode::default(); G_ONESHOT],
            c if (0..G_GROUPS as i32).contains(&c) => vec![at(c as usize)],
            _ => return Err(CncError::NUMBER),
        }))
    }

    /// The code of G group type `t` (0 = group 01) on a valid `path`: the
    /// running program's, else the profile's.
    pub(crate) fn modal_g(&self, path: u16, t: usize) -> u8 {
        let i = usize::from(path) - 1;
        let set = self.run.get(i).and_then(|r| r.modal.g_code(t));
        set.unwrap_or_else(|| self.profile.paths[i].modal.g.get(t).copied().unwrap_or(0))
    }

    /// cnc_modal's other codes (F, S, M, T ...): what the running program
    /// set, else the profile's table.
    pub(crate) fn aux_modal(&self, path: u16, code: i32) -> Reply<AuxModal> {
        let aux = &self.path(path)?.modal.aux;
        let set = &self.live(path)?.modal;
        let rec = |c: i32| {
            let value = AUX_ORDER
                .iter()
                .position(|x| *x == c)
                .and_then(|k| {
                    set.aux_value(k)
                        .or_else(|| aux.get(&(100 + k).to_string()).copied())
                })
                .unwrap_or(0);
            AuxCode {
                value,
                ..AuxCode::default()
            }
        };
        Ok(AuxModal(match code {
            -1 | -2 => (0..AUX_CODES).map(rec).collect(),
            c if (0..AUX_CODES).contains(&c) => vec![rec(c)],
            _ => return Err(CncError::NUMBER),
        }))
    }

    /// Milliseconds from the simulator's start to the instant it was last
    /// advanced to (the frame being answered).
    fn elapsed_ms(&self) -> i64 {
        self.now.saturating_duration_since(self.started).as_millis() as i64
    }

    /// cnc_rdtimer: 0 power-on, 1 operating, 2 cutting, 3 cycle, 4 free,
    /// on the simulator's clock: the profile's minutes plus the time since
    /// the start, path 1 running (STRT), path 1 moving at feed; the cycle
    /// time is path 1's current (or last) run. A hold stops them.
    pub(crate) fn timer(&self, kind: i32) -> Reply<Timer> {
        let t = &self.profile.timers;
        let r = self.live(1)?;
        let min = |m: i32| i64::from(m) * 60_000;
        let ms = |s: f64| (s * 1000.0) as i64;
        let ms = match kind {
            0 => min(t.power_on) + self.elapsed_ms(),
            1 => min(t.operating) + ms(r.operating),
            2 => min(t.cutting) + ms(r.cutting),
            3 => ms(r.cycle),
            4 => min(t.free),
            _ => return Err(CncError::NUMBER),
        };
        let ms = ms + t.written_ms[kind as usize];
        Ok(Timer {
            minute: (ms / 60_000) as i32,
            msec: (ms % 60_000) as i32,
        })
    }

    /// The CNC clock (Unix seconds): the system clock, or with the
    /// profile's `clock_at_start` that instant plus the simulator's time
    /// (frozen with its clock), moved by cnc_settimer.
    fn clock_now(&self) -> i64 {
        let now = match self.profile.timers.clock_at_start {
            Some(t) => t + self.now.saturating_duration_since(self.started).as_secs() as i64,
            None => std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs() as i64),
        };
        now + self.profile.timers.clock_offset
    }

    /// cnc_gettimer: the system clock (local time) moved by cnc_settimer.
    pub(crate) fn clock(&self, kind: i32) -> Reply<Clock> {
        if kind != 0 && kind != 1 {
            return Err(CncError::NUMBER);
        }
        let t = local(self.clock_now());
        Ok(Clock {
            year: t.year(),
            month: t.month().into(),
            day: t.day().into(),
            hour: t.hour().into(),
            minute: t.minute().into(),
            second: t.second().into(),
        })
    }

    /// cnc_settimer: type 0 sets the date, 1 the time of day (the payload's
    /// other half is ignored); invalid values are EW_DATA.
    pub(crate) fn set_clock(&mut self, kind: i32, payload: &[u8]) -> Reply<()> {
        let c = Clock::decode(&mut Reader::new(payload)).map_err(|_| err(ew::EW_LENGTH))?;
        let now = self.clock_now();
        let cur = local(now);
        let bad = |_| err(ew::EW_DATA);
        let set = match kind {
            0 => {
                if !(1970..=2099).contains(&c.year)
                    || !(1..=12).contains(&c.month)
                    || !(1..=31).contains(&c.day)
                {
                    return Err(err(ew::EW_DATA));
                }
                // As mktime: the day counts from the first of the month
                // (February 31 is March 2 or 3).
                let first = jiff::civil::Date::new(c.year, c.month as i8, 1).map_err(bad)?;
                let day = first
                    .checked_add(jiff::Span::new().days(i64::from(c.day) - 1))
                    .map_err(bad)?;
                day.to_datetime(cur.time())
            }
            1 => {
                if !(0..=23).contains(&c.hour)
                    || !(0..=59).contains(&c.minute)
                    || !(0..=59).contains(&c.second)
                {
                    return Err(err(ew::EW_DATA));
                }
                let time = jiff::civil::Time::new(c.hour as i8, c.minute as i8, c.second as i8, 0)
                    .map_err(bad)?;
                cur.date().to_datetime(time)
            }
            _ => return Err(CncError::NUMBER),
        };
        let t = set
            .to_zoned(jiff::tz::TimeZone::system())
            .map_err(bad)?
            .timestamp()
            .as_second();
        self.profile.timers.clock_offset += t - now;
        Ok(())
    }

    /// 0x0023 (cnc_rdalmmsg/2, cnc_rdalminfo): up to `num` active alarms of
    /// `kind` (−1 all) as 16-byte heads and `text_len`-byte messages.
    pub(crate) fn alarm_messages(
        &self,
        path: u16,
        kind: i32,
        num: i32,
        text_len: i32,
    ) -> Reply<Vec<u8>> {
        if !(1..=256).contains(&text_len) {
            return Err(err(ew::EW_ATTRIB));
        }
        let mut w = Writer::new();
        for a in self
            .live(path)?
            .alarms
            .iter()
            .filter(|a| kind == -1 || i32::from(a.kind) == kind)
            .take(num.max(0) as usize)
        {
            let mut msg = a.message.clone().into_bytes();
            msg.truncate(text_len as usize);
            w.i32(a.number);
            w.i32(i32::from(a.kind));
            w.i32(i32::from(a.axis));
            w.i32(msg.len() as i32);
            msg.resize(text_len as usize, 0);
            w.bytes(&msg);
        }
        Ok(w.into_vec())
    }

    /// cnc_rdopmsg: the message of type 0..4 (none: number −1, no text);
    /// other types EW_ATTRIB. Unverified against a real CNC: FANUC's library
    /// gave EW_ATTRIB for type −1 in one oracle run (not analysed), and what
    /// a CNC answers with no message on display is not recorded.
    pub(crate) fn opmsg(&self, path: u16, kind: i32) -> Reply<OpMsg> {
        if !(0..=4).contains(&kind) {
            return Err(err(ew::EW_ATTRIB));
        }
        let shown = self.shown_messages(path)?;
        let m = shown.iter().find(|m| i32::from(m.kind) == kind);
        // The text area is always whole (256 bytes, zero-filled): what
        // cnc_rdopmsg3 reads on the 16i class as one 268-byte record.
        Ok(match m {
            Some(m) => {
                let mut text = m.text.clone().into_bytes();
                text.truncate(256);
                let char_num = text.len() as i32;
                text.resize(256, 0);
                OpMsg {
                    datano: m.number,
                    kind,
                    char_num,
                    text,
                }
            }
            None => OpMsg {
                datano: -1,
                kind,
                char_num: 0,
                text: vec![0; 256],
            },
        })
    }

    /// The operator messages on display on `path`: the profile's, then
    /// the macro message of the program running there (`#3006=n(TEXT)`,
    /// type 4).
    pub(crate) fn shown_messages(&self, path: u16) -> Reply<Vec<OperatorMessage>> {
        let mut v = self.path(path)?.opmsgs.clone();
        if let Some((number, text)) = self
            .run
            .get(path as usize - 1)
            .and_then(|r| r.message.clone())
        {
            v.push(OperatorMessage {
                number,
                kind: 4,
                text,
            });
        }
        Ok(v)
    }

    /// 0x00d0 [start, type, n] (cnc_rdopmsg3, 30i class): the messages of
    /// `type` on display (-1: all; other types than 0..4 EW_ATTRIB) from
    /// index `start` on, at most `n`, as 268-byte records (i32 number,
    /// type, characters, 256 text bytes); none there: an empty answer.
    pub(crate) fn opmsg3(&self, path: u16, start: i32, kind: i32, n: i32) -> Reply<Vec<u8>> {
        if !(-1..=4).contains(&kind) {
            return Err(err(ew::EW_ATTRIB));
        }
        let shown = self.shown_messages(path)?;
        let mut out = Vec::new();
        for m in shown
            .iter()
            .filter(|m| kind == -1 || i32::from(m.kind) == kind)
            .skip(start.max(0) as usize)
            .take(n.clamp(0, 5) as usize)
        {
            let mut text = m.text.clone().into_bytes();
            text.truncate(256);
            out.extend(m.number.to_be_bytes());
            out.extend(i32::from(m.kind).to_be_bytes());
            out.extend((text.len() as i32).to_be_bytes());
            text.resize(256, 0);
            out.extend(text);
        }
        Ok(out)
    }
}

/// Record codes of 0x0006: cnc_rdprogdir's types 0..2 and cnc_rdprogdir3's 0, 1, 3.
const PROGDIR_CODES: std::ops::RangeInclusive<i32> = 0..=3;

impl Machine {
    /// 0x0006: up to `count` stored programs numbered `top` or more, in
    /// number order, as full records whatever the code (a real CNC's reply
    /// to FANUC's library carries all fields for every type): size = the
    /// text's length in bytes, comment in parentheses (cut to 50
    /// characters), the profile's date. No program: an empty payload.
    pub(crate) fn prog_dir(&self, path: u16, top: i32, count: i32, code: i32) -> Reply<ProgDir> {
        if !PROGDIR_CODES.contains(&code) {
            return Err(err(ew::EW_ATTRIB));
        }
        if count <= 0 {
            return Err(err(ew::EW_LENGTH));
        }
        let progs = self.store.iter(path).filter(|p| p.number >= top);
        Ok(ProgDir(
            progs
                .take(count as usize)
                .map(|p| {
                    let mut comment = [0u8; 52];
                    if !p.comment.is_empty() {
                        let c: String = p.comment.chars().take(50).collect();
                        let t = format!("({c})");
                        let n = t.len().min(51);
                        comment[..n].copy_from_slice(&t.as_bytes()[..n]);
                    }
                    let d = p.modified;
                    DirEntry {
                        number: p.number,
                        length: p.size() as i32,
                        comment,
                        date: [d[0], d[1], d[2], d[3], d[4], 0],
                    }
                })
                .collect(),
        ))
    }

    /// Today's date on the CNC's clock (cnc_gettimer's, moved by
    /// cnc_settimer): what a stored or changed program is dated.
    pub fn today(&self) -> crate::sim::store::Date {
        let t = local(self.clock_now());
        [
            t.year(),
            t.month().into(),
            t.day().into(),
            t.hour().into(),
            t.minute().into(),
        ]
        .map(|v| v as u16)
    }
}

/// The local calendar time (this computer's zone) of a Unix time.
fn local(t: i64) -> jiff::civil::DateTime {
    jiff::Timestamp::from_second(t)
        .unwrap_or(jiff::Timestamp::UNIX_EPOCH)
        .to_zoned(jiff::tz::TimeZone::system())
        .datetime()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proto::wire::Wire;

    #[test]
    fn an_idle_path_answers_block_0_and_no_text() {
        // Four zero bytes, the form FANUC's library accepts (not an empty payload).
        let m = Machine::new(crate::sim::Profile::parse("[[path]]\n").expect("profile"));
        let a = m.exec_prog(1, 64).expect("an answer");
        assert_eq!(a.to_bytes(), [0, 0, 0, 0]);
    }
}
