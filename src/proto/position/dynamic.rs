//! cnc_rddynamic2 / cnc_rddynamic: the 9-subpacket frame.

use super::codes::pos;
use super::payload::{AlarmBits, ProgNums, SeqNum};
use super::read::{expect_subs, need, records};
use crate::error::{Error, Result};
use crate::proto::call::{Call, Ctx, payload, sub};
use crate::proto::cmd::{ACTF, ACTS, ALARM, POSITION, PRGNUM, SEQNUM};
use crate::proto::packet::{ReqSub, RespSub};

/// The 9-subpacket frame of cnc_rddynamic2 / cnc_rddynamic.
#[derive(Debug, Clone, Copy)]
pub struct Dynamic {
    pub axis: i16,
}

/// What the frame carries, as far as it was read: FANUC's library writes
/// each group of fields as it reads its subpacket, so an error in a later
/// subpacket leaves the earlier fields written. `pos` = absolute, machine,
/// relative, distance values (one per record received; a kind not read
/// yet is empty).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct DynamicData {
    pub alarm: Option<u32>,
    /// Running and main program numbers.
    pub prgnum: Option<(i32, i32)>,
    pub seqnum: Option<i32>,
    pub actf: Option<i32>,
    pub acts: Option<i32>,
    /// Set once the position subpackets are reached (FANUC writes the axis
    /// word then, even when the first of them is an error).
    pub axis: bool,
    pub pos: Option<[Vec<i32>; 4]>,
    /// The CNC's error in the subpacket where reading stopped.
    pub error: Option<Error>,
}

/// The four 0x26 codes of the dynamic frame, in the struct's order.
pub const DYNAMIC_POS: [i32; 4] = [pos::ABSOLUTE, pos::MACHINE, pos::RELATIVE, pos::DISTANCE];

impl Call for Dynamic {
    type Output = DynamicData;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let a = i32::from(self.axis);
        let mut v = vec![
            ReqSub::cnc(ALARM, &[]),
            ReqSub::cnc(PRGNUM, &[]),
            ReqSub::cnc(SEQNUM, &[]),
            ReqSub::cnc(ACTF, &[]),
            ReqSub::cnc(ACTS, &[]),
        ];
        v.extend(DYNAMIC_POS.map(|c| ReqSub::cnc(POSITION, &[c, a])));
        v
    }
    /// A frame cut short or a payload shorter than its fields is
    /// EW_PROTOCOL with nothing to write (FANUC's library reads the next
    /// subpacket's bytes as the fields); a CNC error ends the reading with
    /// the fields before it kept.
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<DynamicData> {
        expect_subs(resp, 9)?;
        let mut d = DynamicData::default();
        let cnc = |i: usize| -> Result<Option<Error>> {
            match sub(resp, i) {
                Ok(_) => Ok(None),
                Err(e @ Error::Cnc { .. }) => Ok(Some(e)),
                Err(e) => Err(e),
            }
        };
        macro_rules! step {
            ($i:expr, $body:expr) => {
                if let Some(e) = cnc($i)? {
                    d.error = Some(e);
                    return Ok(d);
                }
                $body;
            };
        }
        step!(0, d.alarm = Some(payload::<AlarmBits>(resp, 0)?.bits));
        step!(1, {
            let p: ProgNums = payload(resp, 1)?;
            d.prgnum = Some((p.data, p.mdata));
        });
        step!(2, d.seqnum = Some(payload::<SeqNum>(resp, 2)?.data));
        // actf / acts: FANUC's library takes the record's value word only,
        // so a payload holding that word is whole [fuzz, rddynamic `s5L`:
        // a 4-byte 0x25 answer].
        step!(3, d.actf = Some(value_word(resp, 3)?));
        step!(4, d.acts = Some(value_word(resp, 4)?));
        d.axis = true;
        // Each kind takes the whole records that came, none too (FANUC's
        // library answers EW_OK for an empty position answer, one axis
        // too; it writes the records packed, ours each at its place,
        // src/ffi/dynamic.rs, README). Each kind is
        // kept as it is read: an error in a later position subpacket leaves
        // the earlier kinds written [fuzz, rddynamico8 `e13053s7`].
        for k in 0..4 {
            step!(5 + k, {
                let v = records(resp, 5 + k, 0)?;
                d.pos.get_or_insert_with(Default::default)[k] = v.iter().map(|v| v.value).collect();
            });
        }
        Ok(d)
    }
}

/// The value word (the first 4 bytes) of subpacket `i`'s value record;
/// a payload shorter than the word is EW_PROTOCOL (FANUC's library reads
/// the rest from the next subpacket's header, listed).
fn value_word(resp: &[RespSub], i: usize) -> Result<i32> {
    let p = &sub(resp, i)?.payload;
    need(p, 4, "value word")?;
    Ok(i32::from_be_bytes([p[0], p[1], p[2], p[3]]))
}
