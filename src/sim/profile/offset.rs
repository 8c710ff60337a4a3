//! Profile sections `[path.offset]` and `[[path.tool_group]]`: tool and
//! work offsets, tool life groups (served by src/sim/offset.rs).

use serde::Deserialize;

/// `[path.offset]`: what cnc_rdtofs/cnc_rdzofs read and the writes change.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Offsets {
    /// Decimals of every offset value (3: 0.001 mm).
    pub decimals: i16,
    /// cnc_rdtofsinfo `ofs_type`: tool offset memory (0 A, 1 B, 2 C).
    pub memory: i16,
    /// cnc_rdtofsinfo2 `ofs_enable`: 1 when tool offsets are in use.
    pub enable: i16,
    /// cnc_rdbtofsinfo: how many B-axis tool offsets (0: none) and the
    /// sub function number of offset cancel.
    pub b_axis: i16,
    pub b_cancel: i16,
    /// cnc_rdtldata: the work zero point measurement's TL value (reference
    /// tool length, in the offsets' decimals).
    pub tl: i32,
    /// Tool offsets: row k is offset number k+1, one column per type
    /// (mill, memory C: radius wear, radius geometry, length wear, length
    /// geometry, types 0..3). Every row has the same number of columns.
    pub tool: Vec<Vec<i32>>,
    /// Work zero offsets: row 0 external, rows 1..6 G54..G59 (7.. G54.1 P1..),
    /// one column per axis (missing columns read 0).
    pub work: Vec<Vec<i32>>,
    /// Work coordinate shift (cnc_rdwkcdshft), one value per axis (missing
    /// axes read 0).
    pub shift: Vec<i32>,
    /// Fixture offsets: row k is fixture offset number k+1, one column per
    /// axis (missing columns read 0).
    pub fixture: Vec<Vec<i32>>,
    /// The fixture offset number in effect (0: none; cnc_rdactfixofs).
    pub fixture_active: i32,
    /// The volumetric compensation amount of each axis (cnc_rdvolccomp;
    /// missing axes read 0).
    pub volumetric: Vec<i32>,
    /// The lowest and highest value an offset may be set to, in the
    /// offsets' decimals (cnc_tofs_rnge, cnc_zofs_rnge, cnc_wksft_rnge).
    pub limits: [i32; 2],
    /// The setting status those functions answer with the range.
    pub limit_status: i32,
}

impl Default for Offsets {
    fn default() -> Self {
        Offsets {
            decimals: 3,
            memory: 2,
            enable: 1,
            b_axis: 0,
            b_cancel: 0,
            tl: 0,
            tool: Vec::new(),
            work: Vec::new(),
            shift: Vec::new(),
            fixture: Vec::new(),
            fixture_active: 0,
            volumetric: Vec::new(),
            limits: [-999_999_999, 999_999_999],
            limit_status: 0,
        }
    }
}

impl Offsets {
    pub fn validate(&self, axes: usize) -> Result<(), String> {
        if let Some(w) = self.tool.first().map(Vec::len)
            && self.tool.iter().any(|r| r.len() != w)
        {
            return Err("offset.tool rows must all have the same number of types".into());
        }
        if self.work.iter().any(|r| r.len() > axes) {
            return Err("offset.work rows have at most one value per axis".into());
        }
        if self.volumetric.len() > axes {
            return Err("offset.volumetric has at most one value per axis".into());
        }
        if self.fixture.iter().any(|r| r.len() > axes) {
            return Err("offset.fixture rows have at most one value per axis".into());
        }
        Ok(())
    }
}

/// `[path.tool_life]`: the tool life management's limits as the CNC's
/// configuration sets them (cnc_rdtlinfo); 0 where the profile gives none.
#[derive(Debug, Clone, Copy, Deserialize, Default, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct ToolLifeLimits {
    /// Groups the table holds.
    pub max_group: i32,
    /// Tools in a group.
    pub max_tool: i32,
    /// Largest life in minutes.
    pub max_minute: i32,
    /// Largest life in cycles.
    pub max_cycle: i32,
}

/// `[[path.tool_group]]`: a tool life group (cnc_rdlife, cnc_rdcount,
/// cnc_rdtoolgrp, and the tool numbers of cnc_toolnum).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct ToolGroupProfile {
    pub number: i32,
    /// Tool life (minutes or uses, as the CNC counts).
    pub life: i32,
    /// Tool life counter.
    pub count: i32,
    /// What the counter counts (cnc_rdgrpinfo's count_type): 0 uses, 1
    /// minutes (the simulator's convention).
    pub count_type: i32,
    /// The optional group number (cnc_rdtlusegrp's opt_*; 0: none).
    pub optional: i32,
    /// The use number of the group's tool in use (cnc_rdusetlno; 0: none).
    pub using: i32,
    /// The group's tools in use order (tool-use number 1, 2, ...).
    #[serde(rename = "tool")]
    pub tools: Vec<ToolProfile>,
}

#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct ToolProfile {
    /// T number.
    pub number: i32,
    /// Length (H) and radius (D) offset numbers.
    pub length: i32,
    pub radius: i32,
    /// Tool information bits (skip, expired ...).
    pub info: i32,
}

/// `[[path.managed_tool]]`: one entry of the tool management data
/// (cnc_rdtool), data numbers 1, 2, ... in order. With `group` set, the
/// life and the life counter are that tool life group's (what cnc_wrgrpinfo
/// writes); else `max_life` and `life_count`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct ManagedTool {
    /// T code.
    pub number: i32,
    pub life_count: i32,
    pub max_life: i32,
    /// Life status (0 not used, 1 in use, 2 expired, 3 broken: the
    /// simulator's numbers).
    pub life_stat: u8,
    /// H and D codes.
    pub length: i32,
    pub radius: i32,
    pub spindle_speed: i32,
    pub feedrate: i32,
    pub magazine: i32,
    pub pot: i32,
    /// Tool life group number (0: none).
    pub group: i32,
    /// Custom data 1..20.
    pub custom: Vec<i32>,
}

/// `[[path.punch_tool]]`: one tool of a punch press (cnc_rdtooldata; path
/// `machine = "punch"`), data numbers 1, 2, ... in order. Lengths in the
/// path's least input increment with `decimals` places, angles with
/// `angle_decimals`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PunchTool {
    pub number: i32,
    pub x_offset: i32,
    pub y_offset: i32,
    pub turret: i32,
    /// Changed tool number.
    pub change: i32,
    pub punch_count: i32,
    pub life: i32,
    /// Multi-tool radius and angle.
    pub radius: i32,
    pub radius_angle: i32,
    pub shape: i32,
    pub size_i: i32,
    pub size_j: i32,
    pub angle: i32,
    pub decimals: i32,
    pub angle_decimals: i32,
}

impl Default for PunchTool {
    fn default() -> Self {
        PunchTool {
            number: 0,
            x_offset: 0,
            y_offset: 0,
            turret: 0,
            change: 0,
            punch_count: 0,
            life: 0,
            radius: 0,
            radius_angle: 0,
            shape: 0,
            size_i: 0,
            size_j: 0,
            angle: 0,
            decimals: 3,
            angle_decimals: 3,
        }
    }
}
