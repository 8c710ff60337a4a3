//! Tool numbers, tool life and counters.
//!
//! Recorded from FANUC's library against a fake CNC (not from a real CNC):
//! cnc_rdntool, cnc_rdlife and cnc_rdcount all read the group record of
//! 0x008b [grp, grp]; cnc_rdtoolgrp reads it and then the group's tools
//! with 0x004d [grp, 1, ntool] (cnc_toolnum's command).

use super::call::Single;
use super::packet::ReqSub;
use super::value::Value;
use super::wire::{DecodeError, Reader, Wire, Writer};
use crate::wire_struct;

/// Tool life group record: args [grp, grp].
pub const TLGROUP: u16 = 0x008b;
/// Tools of a group: args [grp, s, e] (cnc_toolnum: [grp, n, n]).
pub const TLTOOLS: u16 = 0x004d;
/// Inserts a tool into a group: args [grp, tuse_num, tool number].
pub const TLINSERT: u16 = 0x0054;
/// Punch press tool control data (no args).
pub const TLCTL: u16 = 0x009a;

wire_struct! {
    /// Payload of 0x008b: group number, then the number of tools, tool life
    /// and life counter as value records. FANUC's library reads the value
    /// words at payload offsets 4 (ntool), 12 (life) and 20 (count).
    pub struct ToolGroup {
        pub grp: i32,
        pub ntool: Value,
        pub life: Value,
        pub count: Value,
    }
}

/// cnc_instlifedt: an empty answer.
pub fn tlinsert(grp: i16, tuse: i16, tool: i32) -> Single<super::offset::Ack> {
    let args = [i32::from(grp), i32::from(tuse), tool];
    Single::new(ReqSub::cnc(TLINSERT, &args))
}

pub fn tlgroup(grp: i16) -> Single<ToolGroup> {
    let g = i32::from(grp);
    Single::new(ReqSub::cnc(TLGROUP, &[g, g]))
}

wire_struct! {
    /// One tool of a group in a 0x004d answer (16 bytes).
    pub struct ToolEntry {
        pub tool_num: i32,
        pub length_num: i32,
        pub radius_num: i32,
        pub tinfo: i32,
    }
}

/// Payload of 0x004d: i32 group, i32 first tool-use number, then 16-byte
/// tool records (FANUC's library numbers them tuse 1, 2, ... in order). A
/// ragged tail is ignored, as FANUC's library ignores it.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ToolList {
    pub grp: i32,
    pub first: i32,
    pub tools: Vec<ToolEntry>,
}

impl Wire for ToolList {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.grp);
        w.i32(self.first);
        self.tools.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let grp = r.i32()?;
        let first = r.i32()?;
        let mut tools = Vec::new();
        while r.remaining() >= 16 {
            tools.push(ToolEntry::decode(r)?);
        }
        Ok(ToolList { grp, first, tools })
    }
}

/// Most tools one 0x004d request asks for, as FANUC's library does.
pub const TOOLS_PER_REQUEST: i32 = 89;

/// Tools 1.. of group `grp` (the group number the 0x008b answer gave), at
/// most [`TOOLS_PER_REQUEST`], as FANUC's cnc_rdtoolgrp asks.
pub fn tltools(grp: i32, ntool: i32) -> Single<ToolList> {
    Single::new(ReqSub::cnc(
        TLTOOLS,
        &[grp, 1, ntool.min(TOOLS_PER_REQUEST)],
    ))
}

wire_struct! {
    /// Payload of 0x009a (cnc_rdtlctldata), read from FANUC's library code
    /// (it only sends it to a punch press or laser, mt_type " P" / " L"):
    /// 32-bit words, of which the short fields take the low 16 bits and
    /// t_axis_dec the low byte. Not exercised against any CNC.
    pub struct ToolCtl {
        pub slct: i32,
        pub used_tool: i32,
        pub turret_indx: i32,
        pub zero_tl_no: i32,
        pub total_punch0: i32,
        pub total_punch1: i32,
        pub t_axis_move: i32,
        pub reserved: i32,
        pub t_axis_dec: i32,
    }
}

pub fn tlctl() -> Single<ToolCtl> {
    Single::new(ReqSub::cnc(TLCTL, &[]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proto::call::{Call, Ctx};

    #[test]
    fn the_tool_list_request_asks_the_answered_group_for_at_most_89_tools() {
        let r = tltools(7, 100).request(&Ctx::default());
        assert_eq!((r[0].cmd, &r[0].args[..3]), (TLTOOLS, &[7, 1, 89][..]));
        let r = tltools(7, 3).request(&Ctx::default());
        assert_eq!(&r[0].args[..3], &[7, 1, 3]);
    }
}
