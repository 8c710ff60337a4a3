//! What the simulated CNC answers for the position area: positions, names,
//! feed, speeds, loads, figures, and the alarm / program / sequence words of
//! the dynamic frame. Everything is read from the profile and the live
//! state at request time, so motion written there by the running program
//! (src/sim/clock.rs) shows up at once.
//!
//! Wire forms are those FANUC's library reads (SPEC.md §5.3). Where the
//! meaning of a word is not known, the answer is a plausible constant
//! (marked below).

use super::Machine;
use super::profile::{Axis, Spindle};
use super::route::{Asked, Route, enc};
use super::service::{CncError, Reply};
use crate::ew::{EW_ATTRIB, EW_NUMBER};
use crate::proto::cmd::{HDL3D_AXES, HDL3D_TIP, POSERR, RDCTRLSIG, RDSPCSS, RDSPDLALM};
use crate::proto::position::{
    ACTF, ACTS, ALARM, AXIS_FLAGS, AlarmBits, AxisNames, COUNT, Count, Figure, Figures, GETFIGURE,
    Name, POSITION, PRGNUM, PosNames, ProgNums, RDAXISNAME, RDSPDLNAME, SEQNUM, SERVO_LOAD,
    SPEED_A5, SPINDLE, SeqNum, UNITS, pos, spdl,
};
use crate::proto::program::AUX_ORDER;
use crate::proto::value::{BASE_10, Value};
use crate::proto::wire::Writer;

pub(super) const ROUTES: &[Route] = &[
    // cnc_alarm's and cnc_alarm2's layout (cnc_rddynamic reads the same bits).
    Route::table(ALARM, |m, q| {
        m.alarm_bits(q.path).map(|a| vec![i64::from(a.bits)])
    }),
    // cnc_rdprgnum's and cnc_rdseqnum's layouts (cnc_rddynamic reads the
    // same words).
    Route::table(PRGNUM, |m, q| {
        m.prog_nums(q.path)
            .map(|n| vec![i64::from(n.data), i64::from(n.mdata)])
    }),
    Route::table(SEQNUM, |m, q| {
        m.seq_num(q.path).map(|n| vec![i64::from(n.data)])
    }),
    Route::cnc(ACTF, |m, q| enc(m.actual(q.path, false))),
    Route::cnc(ACTS, |m, q| enc(m.actual(q.path, true))),
    Route::cnc(SPEED_A5, |m, q| enc(m.speed_a5(q.path))),
    // [code, axis]: cnc_absolute & co.'s layout (`type` not sent, then the
    // value records), which cnc_rddynamic2, cnc_rdaxisdata ... read too.
    Route::table(POSITION, |m, q| {
        let v = m.positions(q.path, q.words[0], q.words[1])?;
        let recs = v
            .iter()
            .flat_map(|r| [r.value, r.base.into(), r.exp.into()]);
        Ok(std::iter::once(0).chain(recs.map(i64::from)).collect())
    }),
    Route::cnc(GETFIGURE, |m, q| enc(m.figures(q.path, q.args[0]))),
    // [-1]: the names per position kind; else the 4-byte axis names.
    Route::cnc(RDAXISNAME, |m, q| match q.args[0] {
        -1 => enc(m.axis_pos_names(q.path)),
        _ => enc(m.axis_names(q.path)),
    }),
    // cnc_rdspdlname's layout: 4 name bytes per spindle.
    Route::table(RDSPDLNAME, |m, q| {
        m.spindle_names(q.path)
            .map(|v| v.iter().flat_map(|n| n.bytes.map(i64::from)).collect())
    }),
    Route::cnc(SPINDLE, |m, q| {
        enc(m.spindle_data(q.path, q.args[0], q.args[1]))
    }),
    Route::cnc(SERVO_LOAD, |m, q| enc(m.servo_load(q.path, q.args[0]))),
    Route::cnc(UNITS, |m, q| enc(m.units(q.path, q.args[0]))),
    Route::cnc(AXIS_FLAGS, |m, q| enc(m.axis_flags(q.path))),
    Route::cnc(COUNT, |m, q| enc(m.counts(q.path, q.args[0]))),
    // [0 | 1]: the spindle control input / output signals.
    Route::cnc(RDCTRLSIG, |m, q| match q.args[0] {
        0 | 1 => m.spindle_signals(q.path, q.args[0] == 1),
        _ => Err(ATTRIB),
    }),
    Route::table(RDSPDLALM, spindle_alarms),
    // [0]: each spindle's position deviation (cnc_rdposerrs); [1], [2]:
    // spindle 1's, spindle 2's (cnc_rdposerrs2); [3]: the Z axis's
    // (cnc_rdposerrz, rigid tapping).
    Route::table(POSERR, |m, q| {
        let p = m.path(q.path)?;
        let spindle = |i: usize| p.spindles.get(i).map_or(0, spindle_deviation);
        match q.words[0] {
            // Each record: the deviation and a word FANUC's library skips.
            0 => Ok(p
                .spindles
                .iter()
                .flat_map(|s| [spindle_deviation(s), 0])
                .collect()),
            k @ (1 | 2) => Ok(vec![spindle(k as usize - 1)]),
            3 => Ok(vec![
                p.axes
                    .iter()
                    .find(|a| a.name == "Z")
                    .map_or(0, |a| i64::from(servo_delay(a))),
            ]),
            _ => Err(NUMBER),
        }
    }),
    Route::table(RDSPCSS, spindle_css),
    // cnc_rd3dtooltip: [1] the 3D handle's axes and their tool tip.
    Route::cnc(HDL3D_AXES, |m, q| m.handle3d(q.path, q.args[0], false)),
    Route::cnc(HDL3D_TIP, |m, q| m.handle3d(q.path, q.args[0], true)),
];

/// The most axes the 3D handle answers for (ODB3DHDL's arrays).
const HANDLE3D_AXES: usize = 5;

impl Machine {
    /// cnc_rd3dtooltip's subpackets: `[1]` the path's first axes (at most
    /// [`HANDLE3D_AXES`]), their numbers (0x0110, `axes`) or the tool tip,
    /// each axis's absolute position (the programmed tool tip), as value
    /// records (0x0111, `data`). `[2]` (a second
    /// set FANUC's library asks for) is not on this CNC: EW_NOOPT, which
    /// FANUC's library reads as "none" [ours].
    fn handle3d(&self, path: u16, k: i32, tip: bool) -> Reply<Vec<u8>> {
        let p = self.path(path)?;
        match k {
            1 => {}
            2 => return Err(CncError::new(crate::ew::EW_NOOPT)),
            _ => return Err(NUMBER),
        }
        let axes = p.axes.iter().take(HANDLE3D_AXES);
        if !tip {
            let mut w = Writer::new();
            (1..=axes.len()).for_each(|n| w.i16(n as i16));
            return Ok(w.into_vec());
        }
        enc(Ok(axes
            .map(|a| Value::decimal(a.absolute, a.decimals))
            .collect::<Vec<Value>>()))
    }
}

/// cnc_rdspdlalm: the alarm word of each spindle (at most 8).
fn spindle_alarms(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    Ok(m.path(q.path)?
        .spindles
        .iter()
        .take(8)
        .map(|s| i64::from(s.alarm))
        .collect())
}

/// Parameter: the maximum spindle speed (r.p.m.), first spindle.
const MAX_SPINDLE_SPEED: i32 = 3772;

/// cnc_rdspcss: the S code in force (what the running program set, else
/// the profile's modal table), the surface speed of G96 (the simulator
/// follows no G96: its modal groups stop at group 07, so none is
/// commanded) and the maximum spindle speed parameter.
fn spindle_css(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let s = m.aux_modal(q.path, AUX_ORDER[super::modal::S])?;
    let srpm = s.0.first().map_or(0, |c| c.value);
    let smax = m.param_value(MAX_SPINDLE_SPEED, 1).unwrap_or(0);
    Ok(vec![i64::from(srpm), 0, i64::from(smax)])
}

const ATTRIB: CncError = CncError::new(EW_ATTRIB);
const NUMBER: CncError = CncError::new(EW_NUMBER);
/// Rated servo current (A) of an axis whose profile gives none.
const DEFAULT_RATED_CURRENT: f64 = 10.0;
/// Position loop gain when the profile gives none, 0.01/s.
const DEFAULT_LOOP_GAIN: i32 = 3000;

/// The 4-byte name entry of an axis: name, suffix, two zero bytes.
fn axis_name(a: &Axis) -> [u8; 4] {
    let mut n = [0u8; 4];
    n[0] = a.name.bytes().next().unwrap_or(0);
    n[1] = a.suffix.bytes().next().unwrap_or(0);
    n
}

/// The 4-byte name entry of a spindle: the profile's name characters
/// ("S", "S1" ...), zero-padded.
fn spindle_name(s: &Spindle) -> [u8; 4] {
    let mut n = [0u8; 4];
    for (d, b) in n.iter_mut().zip(s.name.bytes()) {
        *d = b;
    }
    n
}

/// An empty record for an axis slot the path does not use.
const UNUSED: Value = Value {
    value: 0,
    base: BASE_10,
    exp: 0,
};

impl Machine {
    pub(crate) fn alarm_bits(&self, path: u16) -> Reply<AlarmBits> {
        let bits = self
            .live(path)?
            .alarms
            .iter()
            .filter(|a| (0..32).contains(&a.kind))
            .fold(0u32, |b, a| b | 1 << a.kind);
        Ok(AlarmBits { bits })
    }

    pub(crate) fn prog_nums(&self, path: u16) -> Reply<ProgNums> {
        Ok(ProgNums {
            data: self.shown_program(path)?.0,
            mdata: self.store.path(path)?.main,
        })
    }

    pub(crate) fn seq_num(&self, path: u16) -> Reply<SeqNum> {
        Ok(SeqNum {
            data: self.live(path)?.seq,
        })
    }

    /// 0xa5 (rdaxisdata class 5 type 2): its meaning is not known; the
    /// simulator answers 0 with 0 decimals.
    pub(crate) fn speed_a5(&self, path: u16) -> Reply<Value> {
        self.path(path)?;
        Ok(Value::decimal(0, 0))
    }

    /// Feed rate of the path, or the speed of its first spindle.
    pub(crate) fn actual(&self, path: u16, spindle: bool) -> Reply<Value> {
        let p = self.path(path)?;
        let v = if spindle {
            p.spindles.first().map_or(0, |s| s.speed)
        } else {
            p.feed
        };
        Ok(Value::decimal(v, 0))
    }

    /// 0x26: one record for axis 1..=axes, `max_axes` records for -1 (the
    /// path's axes, then zero records), as a real CNC answers.
    pub(crate) fn positions(&self, path: u16, code: i32, axis: i32) -> Reply<Vec<Value>> {
        let p = self.path(path)?;
        // Codes 13 and 14: the program restart position and the distance
        // from here to it, after a reset interrupted a program (else 0).
        let restart = self
            .run
            .get(usize::from(path).wrapping_sub(1))
            .and_then(|r| r.restart.as_ref());
        if let (13 | 14, Some(r)) = (code, restart) {
            let rec = |(i, a): (usize, &Axis)| {
                let dest = r.dest.get(i).copied().unwrap_or(a.absolute);
                let v = if code == 13 {
                    dest
                } else {
                    dest.wrapping_sub(a.absolute)
                };
                Value::decimal(v, a.decimals)
            };
            return match axis {
                -1 => {
                    let max = usize::from(self.profile.cnc.max_axes);
                    let mut v: Vec<Value> = p.axes.iter().enumerate().map(rec).collect();
                    v.resize(max.max(v.len()), UNUSED);
                    Ok(v)
                }
                n if n >= 1 && (n as usize) <= p.axes.len() => {
                    Ok(vec![rec((n as usize - 1, &p.axes[n as usize - 1]))])
                }
                _ => Err(ATTRIB),
            };
        }
        let pick: fn(&Axis) -> i32 = match code {
            pos::ABSOLUTE | pos::ABSOLUTE2 => |a| a.absolute,
            pos::MACHINE => |a| a.machine,
            pos::RELATIVE | pos::RELATIVE2 => |a| a.relative,
            pos::DISTANCE | pos::DISTANCE2 => |a| a.distance,
            pos::SKIP => |a| a.skip,
            // The servo delay: the axis's feed over its loop gain; the
            // acc/dec delay: the feed over half the time constant.
            pos::SERVO_DELAY => servo_delay,
            pos::ACCDEC_DELAY => |a| delay(a, a.accdec_ms.unwrap_or(DEFAULT_ACCDEC_MS) / 2000.0),
            // rdaxisdata class 1 types 7..17: codes whose meaning is not
            // recorded; the simulator answers 0 for every axis.
            11..=18 | 37..=39 => |_| 0,
            _ => return Err(NUMBER),
        };
        let rec = |a: &Axis| Value::decimal(pick(a), a.decimals);
        match axis {
            -1 => {
                let max = usize::from(self.profile.cnc.max_axes);
                let mut v: Vec<Value> = p.axes.iter().map(rec).collect();
                v.resize(max.max(v.len()), UNUSED);
                Ok(v)
            }
            n if n >= 1 && (n as usize) <= p.axes.len() => Ok(vec![rec(&p.axes[n as usize - 1])]),
            _ => Err(ATTRIB),
        }
    }

    /// 0x1b: input/output figures of the path's axes (types 0 and 1 are
    /// answered alike; what distinguishes them is not known).
    pub(crate) fn figures(&self, path: u16, data_type: i32) -> Reply<Figures> {
        if !(0..=1).contains(&data_type) {
            return Err(ATTRIB);
        }
        let p = self.path(path)?;
        Ok(Figures {
            count: p.axes.len() as i32,
            axes: p
                .axes
                .iter()
                .map(|a| Figure {
                    input: a.input_figures.unwrap_or(a.decimals),
                    output: a.output_figures.unwrap_or(a.decimals),
                })
                .collect(),
        })
    }

    pub(crate) fn axis_names(&self, path: u16) -> Reply<Vec<Name>> {
        let p = self.path(path)?;
        Ok(p.axes
            .iter()
            .map(|a| Name {
                bytes: axis_name(a),
            })
            .collect())
    }

    /// 0x89[-1]: the same name for the absolute, machine and relative
    /// displays (the fourth entry is unused). A 16i-class CNC (not the
    /// Series 15) adds empty entries up to its maximum axes: FANUC's
    /// library reads that many (cnc_rdposition).
    pub(crate) fn axis_pos_names(&self, path: u16) -> Reply<AxisNames> {
        let p = self.path(path)?;
        let mut axes: Vec<PosNames> = p
            .axes
            .iter()
            .map(|a| {
                let n = axis_name(a);
                PosNames {
                    absolute: n,
                    machine: n,
                    relative: n,
                    other: [0; 4],
                }
            })
            .collect();
        if self.is_16i_proper() {
            axes.resize(
                usize::from(self.profile.cnc.max_axes).max(axes.len()),
                PosNames::default(),
            );
        }
        Ok(AxisNames {
            count: p.axes.len() as i32,
            axes,
        })
    }

    pub(crate) fn spindle_names(&self, path: u16) -> Reply<Vec<Name>> {
        let p = self.path(path)?;
        Ok(p.spindles
            .iter()
            .map(|s| Name {
                bytes: spindle_name(s),
            })
            .collect())
    }

    /// 0x40: code 0 (serial spindle load) and 4 (load meter) answer the
    /// load in %, 3 (actual speed) and 5 (motor speed) the speed.
    pub(crate) fn spindle_data(&self, path: u16, code: i32, sp_no: i32) -> Reply<Vec<Value>> {
        let p = self.path(path)?;
        let pick: fn(&Spindle) -> i32 = match code {
            spdl::LOAD_SERIAL | spdl::LOAD_METER => |s| s.load,
            spdl::MAX_RPM_RATIO => |s| s.max_rpm_ratio,
            spdl::GEAR_RATIO => |s| s.gear_ratio,
            spdl::SPEED_ACT | spdl::SPEED_METER => |s| s.speed,
            // rdaxisdata classes 3/4 types 3 and 4: meaning not recorded, 0.
            6 | 7 => |_| 0,
            _ => return Err(NUMBER),
        };
        let rec = |s: &Spindle| Value::decimal(pick(s), 0);
        match sp_no {
            -1 => {
                let mut v: Vec<Value> = p.spindles.iter().map(rec).collect();
                self.pad_16i(&mut v, self.profile.cnc.max_spindles);
                Ok(v)
            }
            n if n >= 1 && (n as usize) <= p.spindles.len() => {
                Ok(vec![rec(&p.spindles[n as usize - 1])])
            }
            _ => Err(NUMBER),
        }
    }

    /// 0x56, per axis of the path: [0] position loop gain, [1] servo load
    /// meter (%), [2] motor speed (rpm), [3] servo current in amperes (one
    /// decimal), the load's share of the axis's rated current, so it follows
    /// the motion as the load does.
    pub(crate) fn servo_load(&self, path: u16, code: i32) -> Reply<Vec<Value>> {
        let p = self.path(path)?;
        let rec = |a: &Axis| match code {
            0 => Value::decimal(a.loop_gain.unwrap_or(DEFAULT_LOOP_GAIN), 0),
            1 => Value::decimal(a.servo_load, 0),
            2 => Value::decimal(a.servo_speed, 0),
            _ => Value::decimal(current_tenths(a), 1),
        };
        match code {
            0..=3 => {
                let mut v: Vec<Value> = p.axes.iter().map(rec).collect();
                self.pad_16i(&mut v, self.profile.cnc.max_axes);
                Ok(v)
            }
            _ => Err(NUMBER),
        }
    }

    /// A 16i-class CNC other than the Series 15 (kind 2).
    fn is_16i_proper(&self) -> bool {
        self.profile.cnc.class == super::profile::Class::Series16 && self.profile.cnc.kind != 2
    }

    /// A 16i-class CNC answers all-axes / all-spindles data with a record
    /// for every axis (spindle) it can have, the unused ones zero: FANUC's
    /// library reads that many records.
    fn pad_16i(&self, v: &mut Vec<Value>, max: u16) {
        if self.profile.cnc.class == super::profile::Class::Series16 {
            v.resize(usize::from(max).max(v.len()), UNUSED);
        }
    }

    /// 0x88: [1] and [2] two words per axis (FANUC's library reads word 0
    /// of [1] as the position unit, word 1 of [2] as the machine-position
    /// unit; both words carry the axis unit here); [3] word 0 = feed unit
    /// in ODBAXDT codes: 3 mm/min, 4 inch/min when the path's first axis is
    /// an inch axis (as [0] tells the 16i class), 6 / 7 per revolution in
    /// G95 (modal group 05 code 1); [4] meaning unknown: zeros. [0] (the
    /// 16i class's cnc_rdspeed): two words per axis, 1 for an inch axis
    /// (FANUC's library shows the feed in inches when word 0 is not 0). A
    /// 16i-class CNC (not the Series 15) answers [0], [1], [2] for its
    /// maximum axes, the unused ones zero (cnc_rdposition reads that many).
    pub(crate) fn units(&self, path: u16, kind: i32) -> Reply<Vec<u16>> {
        let p = self.path(path)?;
        let per_axis = |f: fn(&Axis) -> u16| {
            let mut v: Vec<u16> = p.axes.iter().flat_map(|a| [f(a), f(a)]).collect();
            if self.is_16i_proper() {
                v.resize((2 * usize::from(self.profile.cnc.max_axes)).max(v.len()), 0);
            }
            v
        };
        match kind {
            0 => Ok(per_axis(|a| u16::from(a.unit == 1))),
            1 | 2 => Ok(per_axis(|a| a.unit as u16)),
            3 => {
                let inch = u16::from(p.axes.first().is_some_and(|a| a.unit == 1));
                let per_rev = self.modal_g(path, 4) == 1;
                Ok(vec![if per_rev { 6 } else { 3 } + inch, 0, 0, 0])
            }
            4 => Ok(vec![0; 4]),
            _ => Err(NUMBER),
        }
    }

    /// 0x8c (Series 15): the path's axis count, a word whose meaning is not
    /// known (0), then one display word per axis, which cnc_rdposition
    /// copies as `disp`: 1, or 0 for an axis whose position parameter 3115
    /// hides (bit 0, as on the 16i class).
    pub(crate) fn sysinfo15(&self, path: u16) -> Reply<Vec<u16>> {
        let p = self.path(path)?;
        let mut v = vec![p.axes.len() as u16, 0];
        v.extend((1..=p.axes.len()).map(|i| {
            let hidden = self
                .param_value(crate::proto::position::PARAM_POS_DISPLAY, i as i16)
                .is_some_and(|x| x & 1 != 0);
            u16::from(!hidden)
        }));
        Ok(v)
    }

    /// 0x95 (Series 15): the spindle (1-based) whose name is shown with the
    /// actual speed: the first, or 0 for a path without spindles.
    pub(crate) fn spindle_shown15(&self, path: u16) -> Reply<Vec<u16>> {
        let p = self.path(path)?;
        Ok(vec![u16::from(!p.spindles.is_empty())])
    }

    /// Errors unless this is a Series 15 (16i class, kind 2).
    pub(crate) fn series15(&self) -> Reply<()> {
        match (self.profile.cnc.class, self.profile.cnc.kind) {
            (super::profile::Class::Series16, 2) => Ok(()),
            _ => Err(CncError::FUNC),
        }
    }
    /// 0xa3: per axis, bits 0 and 1 set (FANUC's library derives the
    /// machine and absolute display flags from them; the other bits'
    /// meaning is not known).
    pub(crate) fn axis_flags(&self, path: u16) -> Reply<Vec<u32>> {
        Ok(vec![0b11; self.path(path)?.axes.len()])
    }

    /// 0xa4: [0] and [2] the path's axes, [1] and [3] its spindles.
    pub(crate) fn counts(&self, path: u16, kind: i32) -> Reply<Count> {
        let p = self.path(path)?;
        let n = match kind {
            0 | 2 => p.axes.len(),
            1 | 3 => p.spindles.len(),
            _ => return Err(NUMBER),
        };
        Ok(Count { n: n as u16 })
    }
}

/// Acc/dec time constant when the profile gives none, ms.
const DEFAULT_ACCDEC_MS: f64 = 32.0;

/// The servo delay (position deviation) of an axis: its feed over its
/// loop gain, in the axis's units (cnc_srvdelay, cnc_rdposerrz).
fn servo_delay(a: &Axis) -> i32 {
    delay(
        a,
        100.0 / f64::from(a.loop_gain.unwrap_or(DEFAULT_LOOP_GAIN).max(1)),
    )
}

/// Position coder pulses per spindle revolution when the profile gives none.
const DEFAULT_PULSES_PER_REV: i32 = 4096;

/// The position deviation of a spindle, in position coder pulses: its
/// speed (pulses per second) over its position loop gain (0 for a spindle
/// at rest, as a spindle out of position control has none).
fn spindle_deviation(s: &Spindle) -> i64 {
    let pulses =
        f64::from(s.speed) / 60.0 * f64::from(s.pulses_per_rev.unwrap_or(DEFAULT_PULSES_PER_REV));
    let gain = f64::from(s.loop_gain.unwrap_or(DEFAULT_LOOP_GAIN).max(1)) / 100.0;
    (pulses / gain).round() as i64
}

/// The distance the axis travels in `seconds` at its current feed (the
/// servo motor speed times the lead), in the axis's units.
fn delay(a: &Axis, seconds: f64) -> i32 {
    let mm_per_s = f64::from(a.servo_speed) * a.lead.unwrap_or(super::run::DEFAULT_LEAD) / 60.0;
    (mm_per_s * seconds * 10f64.powi(i32::from(a.decimals))).round() as i32
}

impl Machine {
    /// 0x005b (cnc_rdctrldi / cnc_rdctrldo): four signal bytes per spindle
    /// of the path, from PMC unit 1: the input signals G070..G073 (spindle
    /// k: G070 + 4k ...), the output signals F045..F048, of which the
    /// running machine sets F045's ALMA (bit 0, the spindle's alarm), SSTA
    /// (bit 1, speed zero) and SARA (bit 3, turning at speed). Each
    /// spindle's four bytes go as one big-endian word, the first signal
    /// byte lowest (what FANUC's library writes as sgnl1..sgnl4).
    pub(crate) fn spindle_signals(&mut self, path: u16, output: bool) -> Reply<Vec<u8>> {
        use crate::proto::pmc::PmcRange;
        let spindles: Vec<(i32, i16)> = self
            .path(path)?
            .spindles
            .iter()
            .map(|s| (s.speed, s.alarm))
            .collect();
        let mut out = Vec::new();
        for (k, (speed, alarm)) in spindles.into_iter().enumerate() {
            let (adr_type, first) = if output { (1, 45) } else { (0, 70) };
            let s = first + 4 * k as u16;
            let range = PmcRange {
                adr_type,
                data_type: 0,
                s,
                e: s + 3,
            };
            let mut b = self.profile.pmc.read(1, &range).unwrap_or(vec![0; 4]);
            if output {
                b[0] = (b[0] & !0x0b)
                    | u8::from(alarm != 0)
                    | u8::from(speed == 0) << 1
                    | u8::from(speed != 0 && alarm == 0) << 3;
            }
            b.reverse();
            out.extend(b);
        }
        Ok(out)
    }
}

/// An axis's servo current in 0.1 A: its load's share of its rated current
/// (cnc_rdaxisdata class 2 type 2, the sampling channels' `current`).
pub(super) fn current_tenths(a: &Axis) -> i32 {
    let rated = a.rated_current.unwrap_or(DEFAULT_RATED_CURRENT);
    (rated * 10.0 * f64::from(a.servo_load) / 100.0).round() as i32
}
