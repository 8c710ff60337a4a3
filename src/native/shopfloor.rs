//! Reads a shop-floor monitor polls (the `focas adapter`'s, as FANUC's
//! MTConnect adapter makes them): every spindle's actual speed
//! (cnc_acts2), the running program's full name (cnc_exeprgname2), the
//! operator message on display (cnc_rdopmsg), the tool life group in use
//! (cnc_rdntool), and the tool table: tool life groups with their tools
//! (cnc_rdgrpinfo, cnc_rdtoolgrp) and tool offsets (cnc_rdtofsr). Each in a
//! [`Batch`] too.

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::error::{Error, Result};
use super::part::{Part, via};
use crate::proto::alarm as pa;
use crate::proto::described::Described;
use crate::proto::offset as po;
use crate::proto::position::{SpindleData, spdl};
use crate::proto::program as pp;
use crate::proto::tool as pt;
use crate::types::MAX_SPINDLE;

/// An operator message on display.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct OperatorMessage {
    /// Its number (2001 ...).
    pub number: i32,
    pub text: String,
}

/// One tool life group with its tools.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ToolLifeGroup {
    pub number: i32,
    /// Tool life (uses or minutes, as `count_type`).
    pub life: i32,
    pub count: i32,
    /// 0 uses, 1 minutes.
    pub count_type: i32,
    pub tools: Vec<GroupTool>,
}

/// A tool of a tool life group.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct GroupTool {
    /// The T number.
    pub number: i32,
    /// Its length (H) and radius (D) offset numbers.
    pub length_offset: i32,
    pub radius_offset: i32,
    pub info: i32,
}

fn speeds_part() -> impl Part<Out = Vec<i32>> + Send + 'static {
    const CALL: &str = "cnc_acts2";
    let c = SpindleData {
        code: spdl::SPEED_ACT,
        sp_no: -1,
    };
    // Two counts and a value record per spindle.
    via(CALL, c, 16 + 8 * MAX_SPINDLE, |(n, recs)| {
        Ok(recs
            .iter()
            .take(usize::from(n).min(MAX_SPINDLE))
            .map(|r| r.value)
            .collect())
    })
}

fn name_part() -> impl Part<Out = String> + Send + 'static {
    let f = crate::spec::find("cnc_exeprgname2").expect("a described function");
    via("cnc_exeprgname2", Described::new(f, &[]), 256, |n| {
        let s: Vec<u8> = n.iter().map(|c| *c as u8).take_while(|c| *c != 0).collect();
        Ok(String::from_utf8_lossy(&s).into_owned())
    })
}

fn opmsg_part() -> impl Part<Out = Option<OperatorMessage>> + Send + 'static {
    via("cnc_rdopmsg", pa::rdopmsg(0), 12 + 256, |m| {
        if m.datano == -1 {
            return Ok(None);
        }
        let n = usize::try_from(m.char_num).unwrap_or(0).min(m.text.len());
        let t = m.text[..n].split(|c| *c == 0).next().unwrap_or(&[]);
        Ok(Some(OperatorMessage {
            number: m.datano,
            text: String::from_utf8_lossy(t).trim_end().to_string(),
        }))
    })
}

fn ntool_part(group: i16) -> impl Part<Out = (i32, i32)> + Send + 'static {
    // An answer under 4 bytes (None) is a group of no tools.
    via("cnc_rdntool", pt::tlgroup(group), 28, |g| {
        let g = g.unwrap_or_default();
        Ok((g.grp, g.ntool.value))
    })
}

fn groups_part(first: i16, last: i16) -> impl Part<Out = Vec<(i32, pt::GroupRecord)>> + Send {
    via(
        "cnc_rdgrpinfo",
        pt::grpinfo(first, last),
        4 + 32 * 44,
        |r| {
            Ok((r.groups.iter().enumerate())
                .map(|(i, g)| (r.first + i as i32, *g))
                .collect())
        },
    )
}

fn tools_part(group: i32, ntool: i32) -> impl Part<Out = Vec<GroupTool>> + Send {
    let n = ntool.clamp(0, pt::TOOLS_PER_REQUEST) as usize;
    via(
        "cnc_rdtoolgrp",
        pt::tltools(group, ntool),
        8 + 16 * n,
        |l| {
            Ok(l.tools
                .iter()
                .map(|t| GroupTool {
                    number: t.tool_num,
                    length_offset: t.length_num,
                    radius_offset: t.radius_num,
                    info: t.tinfo,
                })
                .collect())
        },
    )
}

fn offsets_part(first: i16, last: i16) -> impl Part<Out = Vec<i32>> + Send {
    let n = (i32::from(last) - i32::from(first) + 1).max(0) as usize;
    via(
        "cnc_rdtofsr",
        po::rdtofsr(first, -1, last),
        8 * 4 * n,
        |v| Ok(v.0.iter().map(|r| r.value).collect()),
    )
}

impl Cnc {
    /// Every spindle's actual speed, min⁻¹ (cnc_acts2, all spindles).
    pub fn spindle_speeds(&self) -> Result<Vec<i32>> {
        self.run(speeds_part())
    }

    /// The running program's full name, as the CNC gives it
    /// ("//CNC_MEM/USER/PATH1/O1234"; cnc_exeprgname2).
    pub fn program_name(&self) -> Result<String> {
        self.run(name_part())
    }

    /// The operator message on display, if any (cnc_rdopmsg, type 0).
    pub fn operator_message(&self) -> Result<Option<OperatorMessage>> {
        self.run(opmsg_part())
    }

    /// cnc_rdntool of `group`: the group number the CNC answers and its
    /// number of tools (group 0: the CNC's first group).
    pub fn tool_group_tools(&self, group: i16) -> Result<(i32, i32)> {
        self.run(ntool_part(group))
    }

    /// Tool life groups `first..=last` (at most 44 a read; numbers the CNC
    /// lacks answer as empty groups) with their tools: two exchanges.
    pub fn tool_life_groups(&self, first: i16, last: i16) -> Result<Vec<ToolLifeGroup>> {
        let groups = self.run(groups_part(first, last))?;
        let mut b = self.batch();
        let tickets: Vec<_> = (groups.iter())
            .map(|(n, g)| (g.ntool > 0).then(|| b.push(tools_part(*n, g.ntool))))
            .collect();
        let mut r = b.send()?;
        let mut out = Vec::new();
        for ((n, g), t) in groups.into_iter().zip(tickets) {
            let tools = match t {
                Some(t) => r.take(t)?,
                None => Vec::new(),
            };
            out.push(ToolLifeGroup {
                number: n,
                life: g.life,
                count: g.count,
                count_type: g.count_type,
                tools,
            });
        }
        Ok(out)
    }

    /// Tool offsets `first..=last`, every type of each (offset memory C:
    /// radius wear, radius geometry, length wear, length geometry), in
    /// least input increments, one after another (cnc_rdtofsr, type -1).
    pub fn tool_offsets(&self, first: i16, last: i16) -> Result<Vec<i32>> {
        if last < first {
            return Err(Error::invalid(
                "cnc_rdtofsr",
                super::error::Ew::NUMBER,
                "start number after end number",
            ));
        }
        self.run(offsets_part(first, last))
    }
}

impl Batch<'_> {
    /// [`Cnc::spindle_speeds`] in the batch.
    pub fn spindle_speeds(&mut self) -> Ticket<Vec<i32>> {
        self.push(speeds_part())
    }

    /// [`Cnc::program_name`] in the batch.
    pub fn program_name(&mut self) -> Ticket<String> {
        self.push(name_part())
    }

    /// [`Cnc::operator_message`] in the batch.
    pub fn operator_message(&mut self) -> Ticket<Option<OperatorMessage>> {
        self.push(opmsg_part())
    }

    /// [`Cnc::tool_offsets`] in the batch.
    pub fn tool_offsets(&mut self, first: i16, last: i16) -> Ticket<Vec<i32>> {
        if last < first {
            return self.push(super::part::Ready(Err(Error::invalid(
                "cnc_rdtofsr",
                super::error::Ew::NUMBER,
                "start number after end number",
            ))));
        }
        self.push(offsets_part(first, last))
    }

    /// [`Cnc::tool_group_tools`] in the batch.
    pub fn tool_group_tools(&mut self, group: i16) -> Ticket<(i32, i32)> {
        self.push(ntool_part(group))
    }
}

fn entry_part(number: u32) -> impl Part<Out = Option<super::ProgramEntry>> + Send + 'static {
    let code = pp::progdir3_code(2).unwrap_or(3);
    let n = number.min(i32::MAX as u32) as i32;
    via(
        "cnc_rdprogdir3",
        pp::progdir(n, 1, code),
        72 * 2,
        move |d| {
            Ok(d.0
                .iter()
                .find(|e| e.number == n)
                .map(super::program::entry))
        },
    )
}

impl Cnc {
    /// Program O`number`'s directory entry (its comment, size, date), if
    /// the current path's memory holds it (cnc_rdprogdir3 type 2, one
    /// program).
    pub fn program_entry(&self, number: u32) -> Result<Option<super::ProgramEntry>> {
        self.run(entry_part(number))
    }
}

impl Batch<'_> {
    /// [`Cnc::program_entry`] in the batch.
    pub fn program_entry(&mut self, number: u32) -> Ticket<Option<super::ProgramEntry>> {
        self.push(entry_part(number))
    }
}
