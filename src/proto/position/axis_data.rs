//! cnc_rdsvmeter / cnc_rdspmeter / cnc_rdaxisdata / cnc_rdposition (30i
//! class): the meter / axis-data frames.

use super::codes::{ALL, pos};
use super::payload::{AxisNames, Count, Name, UnitWords};
use super::read::{expect_subs, whole, whole_records, zext};
use crate::error::{Error, Result};
use crate::proto::call::{Call, Ctx, payload, sub};
use crate::proto::cmd::{
    ACTF, ACTS, AXIS_FLAGS, COUNT, POSITION, RDAXISNAME, RDSPDLNAME, SERVO_LOAD, SPINDLE, UNITS,
};
use crate::proto::packet::{ReqSub, RespSub};
use crate::proto::value::Value;

/// What a meter / axis-data frame asks for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum AxisData {
    /// rdaxisdata class 1 / rdposition: position type codes (0x26).
    Positions(Vec<i32>),
    /// rdaxisdata class 2 / rdsvmeter: 0x56 codes.
    Servo(Vec<i32>),
    /// rdaxisdata class 3 / rdspmeter: 0x40 codes.
    Spindle(Vec<i32>),
    /// rdaxisdata class 4: 0x40 codes for spindle 1 (0xa4\[3\], 0x8a\[1\],
    /// 0x40[code, 1], 0xa4\[3\]).
    FirstSpindle(Vec<i32>),
    /// rdaxisdata class 5: the speed frame (0xa4\[3\], 0x8a\[1\], 0x88\[3\],
    /// 0x88\[4\], one of ACTF / ACTS / SPEED_A5 per type, 0xa4\[3\]); always
    /// one item.
    Speed(Vec<u16>),
}

/// One decoded value with its name and unit/flag words.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct AxisValue {
    pub name: [u8; 4],
    pub data: i32,
    pub dec: i16,
    /// Unit word (class 1: from 0x88).
    pub unit: i16,
    /// Class 1: the flag computed from 0xa3 (FANUC's formula).
    pub flag: i16,
    /// Only the first two name bytes are written (class 5 'F' / 'S').
    pub short_name: bool,
}

/// `values[k][i]` = value of code `k` for axis/spindle `i`, for the
/// `count` = min(first count, last count, `limit`) items.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct AxisDataReply {
    pub count: usize,
    pub values: Vec<Vec<AxisValue>>,
    /// A CNC error in a subpacket after the first count: FANUC's library
    /// still writes the count (and nothing else) before returning it.
    pub error: Option<Error>,
}

/// The frame plus the caller's limit (`*len` / `*num`).
#[derive(Debug, Clone)]
pub struct AxisDataCall {
    pub what: AxisData,
    pub limit: i16,
}

impl AxisDataCall {
    /// 16i class: count = maximum axes (servo) or spindles (spindle) of the
    /// open body, limited by the caller; names from the last subpacket
    /// (servo names: only the first two bytes, the third is 0).
    fn decode16(&self, cx: &Ctx, codes: &[i32], resp: &[RespSub]) -> Result<AxisDataReply> {
        let servo = matches!(self.what, AxisData::Servo(_));
        let mut got = Vec::with_capacity(codes.len());
        for k in 0..codes.len() {
            got.push(whole_records(resp, k)?);
        }
        // The names are the frame's last subpacket: FANUC's library reads
        // the entries past its payload as zeros (its receive buffer is zero
        // past the frame).
        let names_p = &sub(resp, codes.len())?.payload;
        let max = if servo {
            cx.axes()
        } else {
            usize::from(cx.max_spindles)
        };
        // FANUC reads max-axes/spindles records regardless of the payload
        // size (a real CNC answers that many); we stop at the whole records
        // actually answered (never garbage).
        let answered = got.iter().map(Vec::len).min();
        let count = max
            .min(self.limit.max(0) as usize)
            .min(answered.unwrap_or(0));
        let names: Vec<Name> = (0..count)
            .map(|i| Name {
                bytes: zext(names_p.get(4 * i..).unwrap_or(&[])),
            })
            .collect();
        let mut values = Vec::with_capacity(codes.len());
        for recs in &got {
            let row = recs
                .iter()
                .zip(&names)
                .take(count)
                .map(|(r, n)| {
                    let mut name = n.bytes;
                    if servo {
                        name[2] = 0;
                    }
                    AxisValue {
                        name,
                        data: r.value,
                        dec: r.exp,
                        ..AxisValue::default()
                    }
                })
                .collect();
            values.push(row);
        }
        Ok(AxisDataReply {
            count,
            values,
            error: None,
        })
    }

    fn count_arg(&self) -> i32 {
        match self.what {
            AxisData::Positions(_) => 0,
            AxisData::Spindle(_) => 1,
            AxisData::Servo(_) => 2,
            AxisData::FirstSpindle(_) | AxisData::Speed(_) => 3,
        }
    }
}

fn is_machine(code: i32) -> bool {
    code == pos::MACHINE
}

impl Call for AxisDataCall {
    type Output = AxisDataReply;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        if cx.class.is_16i() {
            // 16i class (recorded from FANUC's library): no 0xa4 counts, the
            // data first, the names last (spindle names with arg 0).
            match &self.what {
                AxisData::Servo(codes) => {
                    let mut v: Vec<ReqSub> = codes
                        .iter()
                        .map(|k| ReqSub::cnc(SERVO_LOAD, &[*k]))
                        .collect();
                    v.push(ReqSub::cnc(RDAXISNAME, &[]));
                    return v;
                }
                AxisData::Spindle(codes) => {
                    let mut v: Vec<ReqSub> = codes
                        .iter()
                        .map(|k| ReqSub::cnc(SPINDLE, &[*k, ALL]))
                        .collect();
                    v.push(ReqSub::cnc(RDSPDLNAME, &[]));
                    return v;
                }
                // rdaxisdata (the only user of these) is EW_FUNC on a 16i
                // before any request; rdposition has its own 16i form
                // ([`Position16`]).
                AxisData::Positions(_) | AxisData::FirstSpindle(_) | AxisData::Speed(_) => {}
            }
        }
        let c = ReqSub::cnc(COUNT, &[self.count_arg()]);
        let mut v = vec![c.clone()];
        match &self.what {
            AxisData::Positions(codes) => {
                v.push(ReqSub::cnc(RDAXISNAME, &[ALL]));
                v.push(ReqSub::cnc(UNITS, &[1]));
                v.push(ReqSub::cnc(UNITS, &[2]));
                v.push(ReqSub::cnc(AXIS_FLAGS, &[0, ALL]));
                v.extend(codes.iter().map(|k| ReqSub::cnc(POSITION, &[*k, ALL])));
            }
            AxisData::Servo(codes) => {
                v.push(ReqSub::cnc(RDAXISNAME, &[]));
                v.extend(codes.iter().map(|k| ReqSub::cnc(SERVO_LOAD, &[*k])));
            }
            AxisData::Spindle(codes) => {
                v.push(ReqSub::cnc(RDSPDLNAME, &[ALL]));
                v.extend(codes.iter().map(|k| ReqSub::cnc(SPINDLE, &[*k, ALL])));
            }
            AxisData::FirstSpindle(codes) => {
                v.push(ReqSub::cnc(RDSPDLNAME, &[1]));
                v.extend(codes.iter().map(|k| ReqSub::cnc(SPINDLE, &[*k, 1])));
            }
            AxisData::Speed(cmds) => {
                v.push(ReqSub::cnc(RDSPDLNAME, &[1]));
                v.push(ReqSub::cnc(UNITS, &[3]));
                v.push(ReqSub::cnc(UNITS, &[4]));
                v.extend(cmds.iter().map(|k| ReqSub::cnc(*k, &[])));
            }
        }
        v.push(c);
        v
    }

    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<AxisDataReply> {
        if cx.class.is_16i()
            && let AxisData::Servo(codes) | AxisData::Spindle(codes) = &self.what
        {
            return self.decode16(cx, codes, resp);
        }
        if let AxisData::Speed(cmds) = &self.what {
            return decode_speed(cmds, self.limit, resp);
        }
        let (codes, data_at) = match &self.what {
            AxisData::Positions(c) => (c, 5),
            AxisData::Servo(c) | AxisData::Spindle(c) | AxisData::FirstSpindle(c) => (c, 2),
            AxisData::Speed(_) => unreachable!("decoded above"),
        };
        expect_subs(resp, data_at + codes.len() + 1)?;
        // The opening count; FANUC's library reads a payload shorter than
        // its word from the next subpacket's header (listed), so ours knows
        // it only when whole.
        let p0 = &sub(resp, 0)?.payload;
        let first = (p0.len() >= 2).then(|| u16::from_be_bytes([p0[0], p0[1]]));
        let room = self.limit.max(0) as usize;
        let last_at = data_at + codes.len();
        // A closing count of 0 answered without an error: no records,
        // EW_OK, whatever error an earlier subpacket holds [fuzz, seed
        // 0x20271128, rdsvmeter path 2 `e4s2`: error 4 in the data
        // subpacket, closing count 0: num 0, EW_OK].
        if let Ok(s) = sub(resp, last_at)
            && u16::from_be_bytes(zext(&s.payload)) == 0
        {
            return Ok(AxisDataReply {
                count: 0,
                values: vec![vec![]; codes.len()],
                error: None,
            });
        }
        for i in 1..resp.len() {
            if let Err(e @ Error::Cnc { .. }) = sub(resp, i) {
                // An error in the closing count: FANUC's library returns it
                // with the count unwritten [fuzz, rdsvmeter `e11s3`].
                // A CNC error after the first count: the count is still
                // written.
                let Some(first) = first.filter(|_| i != last_at) else {
                    return Err(e);
                };
                return Ok(AxisDataReply {
                    count: usize::from(first).min(room),
                    values: vec![vec![]; codes.len()],
                    error: Some(e),
                });
            }
        }
        // Errors count in subpacket order.
        let mut got = Vec::with_capacity(codes.len());
        let names = match &self.what {
            AxisData::Positions(_) => {
                let names: AxisNames = payload(resp, 1)?;
                // Whole 4-byte entries: FANUC's library reads the count's
                // entries and ignores a longer tail [fuzz, rdposition
                // `s2Twlong`]; too few for the count stays EW_PROTOCOL below.
                let u1: Vec<UnitWords> = whole(&sub(resp, 2)?.payload, 4)?;
                let u2: Vec<UnitWords> = whole(&sub(resp, 3)?.payload, 4)?;
                let flags: Vec<u32> = whole(&sub(resp, 4)?.payload, 4)?;
                Some((names, u1, u2, flags))
            }
            _ => None,
        };
        let plain_names: Vec<Name> = match names {
            // A name entry cut after its third byte (name, suffixes) is
            // still a name: FANUC's library uses those three bytes [fuzz,
            // rdsvmeter `s1Ln350cut`]; its fourth reads as 0.
            None => sub(resp, 1)?
                .payload
                .chunks(4)
                .take_while(|c| c.len() >= 3)
                .map(|c| Name { bytes: zext(c) })
                .collect(),
            Some(_) => vec![],
        };
        // FANUC's library reads the count's records and no further: bytes
        // past the last whole record are ignored [fuzz, rdsvmeter `s2Tvlong`].
        for k in 0..codes.len() {
            got.push(whole_records(resp, data_at + k)?);
        }
        // The closing count ends the frame: a payload shorter than its word
        // reads zero-extended, as FANUC's library reads it [fuzz, rdsvmeter
        // `s3Tshort1`].
        let last = u16::from_be_bytes(zext(&sub(resp, last_at)?.payload));
        let known = usize::from(last).min(room);
        // Without the opening count the result is known only when the
        // closing count or the room makes it 0.
        let count = match first {
            Some(first) => known.min(usize::from(first)),
            None if known == 0 => 0,
            None => return Err(Error::short("the opening count is cut")),
        };

        let mut values = Vec::with_capacity(codes.len());
        for (code, recs) in codes.iter().zip(&got) {
            if recs.len() < count {
                return Err(Error::short("fewer value records than the count"));
            }
            let mut row = Vec::with_capacity(count);
            for (i, r) in recs.iter().take(count).enumerate() {
                let mut v = AxisValue {
                    data: r.value,
                    dec: r.exp,
                    ..AxisValue::default()
                };
                match &names {
                    Some((n, u1, u2, fl)) => {
                        let (n, u1, u2, f) =
                            (n.axes.get(i), u1.get(i), u2.get(i), fl.get(i).copied());
                        let (Some(n), Some(u1), Some(u2), Some(f)) = (n, u1, u2, f) else {
                            return Err(Error::short(
                                "fewer name/unit/flag entries than the count",
                            ));
                        };
                        if is_machine(*code) {
                            v.name = n.machine;
                            v.unit = u2.w1 as i16;
                            v.flag = ((f >> 11) | (f & 1)) as i16;
                        } else {
                            v.name = if *code == pos::RELATIVE2 {
                                n.relative
                            } else {
                                n.absolute
                            };
                            // Code 12 takes the second unit word (FANUC's library).
                            v.unit = if *code == 12 { u1.w1 } else { u1.w0 } as i16;
                            // FANUC's library: the distance to go takes bit 2
                            // where the other positions take bit 1.
                            v.flag = if *code == pos::DISTANCE2 {
                                (f >> 3) | ((f >> 2) & 1)
                            } else {
                                (f >> 3) | ((f >> 1) & 1)
                            } as i16;
                        }
                    }
                    None => {
                        let Some(n) = plain_names.get(i) else {
                            return Err(Error::short("fewer names than the count"));
                        };
                        v.name = n.bytes;
                    }
                }
                row.push(v);
            }
            values.push(row);
        }
        Ok(AxisDataReply {
            count,
            values,
            error: None,
        })
    }
}

/// Class 5 [oracle, /tmp/orc/findings via FANUC's library]: always one item
/// (whatever the 0xa4 counts). ACTF: name "F" (2 bytes), unit = word 0 of
/// 0x88[3], flag 0. ACTS: unit 5; first count 0 → name "S" (2 bytes), flag 0,
/// else the first 0x8a entry (4 bytes), flag 1. SPEED_A5: name "F", unit =
/// word 0 of 0x88[4], flag 2. Data/dec from the record. An error in 0x8a
/// counts only when ACTS is asked.
fn decode_speed(cmds: &[u16], limit: i16, resp: &[RespSub]) -> Result<AxisDataReply> {
    let first: Count = payload(resp, 0)?;
    let spindle = cmds.contains(&ACTS);
    let names: Vec<Name> = if spindle {
        payload(resp, 1)?
    } else {
        Vec::new()
    };
    let u3: Vec<u16> = payload(resp, 2)?;
    let u4: Vec<u16> = payload(resp, 3)?;
    let mut recs = Vec::with_capacity(cmds.len());
    for k in 0..cmds.len() {
        recs.push(payload::<Value>(resp, 4 + k)?);
    }
    let _: Count = payload(resp, 4 + cmds.len())?;
    let word0 = |u: &[u16]| {
        u.first()
            .map(|w| *w as i16)
            .ok_or_else(|| Error::short("0x88 unit payload is empty"))
    };
    let f_name = [b'F', 0, 0, 0];
    let count = usize::from(limit >= 1);
    let mut values = Vec::with_capacity(cmds.len());
    for (cmd, r) in cmds.iter().zip(&recs) {
        let mut v = AxisValue {
            data: r.value,
            dec: r.exp,
            short_name: true,
            name: f_name,
            ..AxisValue::default()
        };
        match *cmd {
            ACTF => v.unit = word0(&u3)?,
            ACTS => {
                v.unit = 5;
                if first.n == 0 {
                    v.name = [b'S', 0, 0, 0];
                } else {
                    let n = names
                        .first()
                        .ok_or_else(|| Error::short("no spindle name entry"))?;
                    v.name = n.bytes;
                    v.short_name = false;
                    v.flag = 1;
                }
            }
            _ => {
                v.unit = word0(&u4)?;
                v.flag = 2;
            }
        }
        values.push(if count == 1 { vec![v] } else { Vec::new() });
    }
    Ok(AxisDataReply {
        count,
        values,
        error: None,
    })
}
