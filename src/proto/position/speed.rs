//! cnc_rdspeed (recorded with FANUC's library, docs/protocol/position.md).
//! 30i: 0xa4\[3\], 0x8a\[1\], 0x88\[3\], 0x88\[4\], 0x24 and/or 0x25, 0xa4\[3\];
//! 16i: 0x24, 0x25, 0x88\[0\], 0x0e\[3106\], 0x0e\[3107\], 0x0e\[9936\], 0x21\[4\],
//! PMC G28 of the path; Series 15: 0x24, 0x25, 0x88\[0\], 0x95, 0x8a.

use super::payload::{Count, Name};
use super::read::{be16, expect_subs, need, whole, zext};
use crate::error::{Error, Result};
use crate::proto::call::{Call, Ctx, payload, sub};
use crate::proto::cmd::{ACTF, ACTS, COUNT, RDSPDLNAME, SPINDLE_SHOWN15, UNITS};
use crate::proto::open::CncClass;
use crate::proto::packet::{ReqSub, RespSub};
use crate::proto::value::Value;

/// 16i class: parameters FANUC's library reads with the speeds. 3107 bit 3
/// shows the actual feed per revolution under G95; what it takes from 3106
/// and 9936 was not seen (no bit of either changed an output).
pub const PARAM_SPEED_DISPLAY: [i32; 3] = [3106, 3107, 9936];
/// 16i class: the PMC G byte FANUC's library reads with the speeds (G28 of
/// path 1, G1028 of path 2 ...); no bit of it changed an output.
pub const SPEED_PMC_G: i32 = 28;
/// 16i class: the modal G group (0x21 code) whose code 1 (G95, feed per
/// revolution) makes the feed unit per revolution when 3107 bit 3 is set.
pub const FEED_GROUP: i32 = 4;

/// cnc_rdspeed: `feed` (type 0 or -1), `spindle` (1 or -1).
#[derive(Debug, Clone, Copy)]
pub struct Speed {
    pub feed: bool,
    pub spindle: bool,
}

/// One SPEEDELM as FANUC's library fills it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SpeedValue {
    pub data: i32,
    pub dec: i16,
    pub unit: i16,
    pub disp: i16,
    pub name: u8,
    pub suff: u8,
}

/// The elements asked: `actf` for the feed, `acts` for the spindle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SpeedReply {
    pub actf: Option<SpeedValue>,
    pub acts: Option<SpeedValue>,
}

fn speed_value(v: Value, unit: i16, disp: i16, name: u8, suff: u8) -> SpeedValue {
    SpeedValue {
        data: v.value,
        dec: v.exp,
        unit,
        disp,
        name,
        suff,
    }
}

impl Call for Speed {
    type Output = SpeedReply;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        match cx.class {
            CncClass::Series30 => {
                let c = ReqSub::cnc(COUNT, &[3]);
                let mut v = vec![
                    c.clone(),
                    ReqSub::cnc(RDSPDLNAME, &[1]),
                    ReqSub::cnc(UNITS, &[3]),
                    ReqSub::cnc(UNITS, &[4]),
                ];
                if self.feed {
                    v.push(ReqSub::cnc(ACTF, &[]));
                }
                if self.spindle {
                    v.push(ReqSub::cnc(ACTS, &[]));
                }
                v.push(c);
                v
            }
            CncClass::Series16 { kind: 2 } => vec![
                ReqSub::cnc(ACTF, &[]),
                ReqSub::cnc(ACTS, &[]),
                ReqSub::cnc(UNITS, &[0]),
                ReqSub::cnc(SPINDLE_SHOWN15, &[]),
                ReqSub::cnc(RDSPDLNAME, &[]),
            ],
            CncClass::Series16 { .. } => {
                let mut v = vec![
                    ReqSub::cnc(ACTF, &[]),
                    ReqSub::cnc(ACTS, &[]),
                    ReqSub::cnc(UNITS, &[0]),
                ];
                v.extend(
                    PARAM_SPEED_DISPLAY.map(|n| ReqSub::cnc(crate::proto::cmd::RDPARAM16, &[n, n])),
                );
                v.push(ReqSub::cnc(crate::proto::program::MODAL_G, &[FEED_GROUP]));
                let g = SPEED_PMC_G + 1000 * (i32::from(cx.path.max(1)) - 1);
                v.push(ReqSub::pmc(crate::proto::pmc::RDPMCRNG, &[g, g, 0, 0]));
                v
            }
        }
    }

    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<SpeedReply> {
        match cx.class {
            CncClass::Series30 => self.decode30(resp),
            CncClass::Series16 { kind } => self.decode16(kind == 2, resp),
        }
    }
}

impl Speed {
    /// 30i: actf unit = word 0 of 0x88[3] minus 3, disp 0, name 'F'; acts
    /// unit 2, and with a display count (first or last 0xa4) of 0 disp 0 and name 'S', else disp
    /// 1 and the first 0x8a entry's name and suffix. FANUC ignores an error
    /// in 0x8a when only the feed is asked.
    fn decode30(&self, resp: &[RespSub]) -> Result<SpeedReply> {
        let n = 5 + usize::from(self.feed) + usize::from(self.spindle);
        expect_subs(resp, n)?;
        let count: Count = payload(resp, 0)?;
        // The first whole 4-byte 0x8a entry (a ragged tail is none: FANUC
        // reads no name unless it shows one [fuzz seed 0x20311129: a 1-byte
        // answer with count 0 is 'S', EW_OK]); its error counts when the
        // spindle is asked.
        let first_name = |s: &RespSub| {
            whole::<Name>(&s.payload, 4)
                .ok()
                .and_then(|n| n.first().map(|n| n.bytes))
        };
        let name = if self.spindle {
            first_name(sub(resp, 1)?)
        } else {
            sub(resp, 1).ok().and_then(first_name)
        };
        let units: Vec<u16> = payload(resp, 2)?;
        let _: Vec<u8> = payload(resp, 3)?;
        let mut at = 4;
        let mut next = |want: bool| -> Result<Option<Value>> {
            if !want {
                return Ok(None);
            }
            let v = payload(resp, at)?;
            at += 1;
            Ok(Some(v))
        };
        let actf = next(self.feed)?;
        let acts = next(self.spindle)?;
        let last: Count = payload(resp, at)?;
        let feed_unit = *units
            .first()
            .ok_or_else(|| Error::short("0x88 unit payload is empty"))?;
        let shown = count.n != 0 && last.n != 0;
        let name = match (self.spindle && shown, name) {
            (true, None) => return Err(Error::short("no spindle name entry")),
            (_, n) => n.unwrap_or_default(),
        };
        Ok(SpeedReply {
            actf: actf.map(|f| speed_value(f, (feed_unit as i16).wrapping_sub(3), 0, b'F', 0)),
            // The name is shown when both display counts (the first and
            // the last 0xa4 answers) are not 0 [fuzz seed 0x20301129
            // `s6Llong`: first 1, last 0 is 'S'; crafted: 1/1, 2/1, 1/2,
            // 1/0xffff show it, 0/1 and 1/0 do not].
            acts: acts.map(|s| {
                if !shown {
                    speed_value(s, 2, 0, b'S', 0)
                } else {
                    speed_value(s, 2, 1, name[0], name[1])
                }
            }),
        })
    }

    /// 16i class and Series 15: any CNC error (first in subpacket order) is
    /// the result. actf: disp 1, name 'F', unit 1 (inch) when word 0 of
    /// 0x88[0] is not 0, else 0, plus 3 (per revolution) on the 16i when
    /// parameter 3107 bit 3 is set and the group of 0x21[4] is code 1 (G95).
    /// acts: unit 2, disp 1; name 'S' (16i), or on a Series 15 the name and
    /// suffix of the 0x8a entry that 0x95 word 0 numbers (1-based; none:
    /// zeros).
    fn decode16(&self, s15: bool, resp: &[RespSub]) -> Result<SpeedReply> {
        let n = if s15 { 5 } else { 8 };
        expect_subs(resp, n)?;
        for i in 0..n {
            sub(resp, i)?;
        }
        let p = |i: usize| &resp[i].payload;
        let mut out = SpeedReply::default();
        if self.feed {
            let f: Value = payload(resp, 0)?;
            need(p(2), 2, "0x88[0]")?;
            let mut unit = i16::from(be16(p(2), 0) != 0);
            if !s15 {
                let par = p(4);
                need(par, 12, "parameter 3107")?;
                need(p(6), 1, "modal group")?;
                let bit3 = i32::from_be_bytes([par[8], par[9], par[10], par[11]]) & 8 != 0;
                if bit3 && p(6)[0] == 1 {
                    unit += 3;
                }
            }
            out.actf = Some(speed_value(f, unit, 1, b'F', 0));
        }
        if self.spindle {
            let s: Value = payload(resp, 1)?;
            let (name, suff) = if s15 {
                need(p(3), 2, "0x95")?;
                let k = be16(p(3), 0) as i16;
                let names = p(4);
                if k >= 1 {
                    let e: [u8; 2] = zext(names.get(4 * (k as usize - 1)..).unwrap_or(&[]));
                    (e[0], e[1])
                } else {
                    (0, 0)
                }
            } else {
                (b'S', 0)
            };
            out.acts = Some(speed_value(s, 2, 1, name, suff));
        }
        Ok(out)
    }
}
