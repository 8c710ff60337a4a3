//! `[system]`: what the CNC is built of, as its system configuration
//! screen lists it: its boards (cnc_rdsyshard), its software series and
//! editions (cnc_rdsyssoft3), the slots they are on and the named ones
//! (cnc_rdsyssoft, cnc_rdsyssoft2), and the ID information of its servo and
//! spindle drives (cnc_rdservoid, cnc_rdspindleid and their saved copies).

use serde::Deserialize;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct System {
    /// The boards, first to last (cnc_rdsyshard's `s_no` 1 is the first).
    #[serde(rename = "board")]
    pub boards: Vec<Board>,
    /// The software, first to last (cnc_rdsyssoft3's `s_no` 1 is the first).
    pub software: Vec<Software>,
    /// The servo drives, axis 1 first (cnc_rdservoid, cnc_rdfromservoid).
    pub servo: Vec<DriveId>,
    /// The spindle drives, spindle 1 first (cnc_rdspindleid,
    /// cnc_rdfromspindleid; `sub_motor` is the sub spindle motor).
    pub spindle: Vec<DriveId>,
    /// cnc_getcncmodel: the model code.
    pub model: i16,
    /// cnc_getlanguage: the display language (cnc_chglang changes it).
    pub language: i16,
    /// cnc_rdope_lvl: the operation level.
    pub operation_level: i16,
    /// cnc_rdprt_lvl / cnc_wrprt_lvl: per data kind (0 the first), the
    /// operation levels it needs to be [modified, output].
    pub protection: Vec<[i16; 2]>,
    /// cnc_rdmenuswitch / cnc_wrmenuswitch: bit k the k-th menu switch.
    pub menu_switch: u16,
    /// cnc_rdmdlconfig2: the CNC module configuration bytes (at most 128
    /// answered; what each byte means is not known).
    pub module_config: Vec<i8>,
    /// The slots, in the CNC's logical order (cnc_rdsyssoft's logical
    /// slots; its physical list is theirs in ascending order).
    #[serde(rename = "slot")]
    pub slots: Vec<Slot>,
    /// The software in named places, by ID (`software`'s): the keys are
    /// ODBSYSS2's member names less `_ser`/`_ver` (`boot`, `servo`, `pmc`,
    /// `ladder`, `mcrlib`, ..., `eth_boot`, `embEthe`); the others are
    /// unset (cnc_rdsyssoft, cnc_rdsyssoft2).
    pub named: std::collections::BTreeMap<String, i16>,
    /// cnc_rdsyssoft's `soft_inst` (the one byte the CNC sends).
    pub soft_inst: u8,
}

/// One slot: its physical number (from 0x80 the second bank; the low 4
/// bits place it in its bank), its module's ID and the ID of the software
/// on it (`software`'s, whose series and edition it shows).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Slot {
    pub slot: u8,
    pub module_id: i16,
    pub software: i16,
}

/// `[path.fixed_cycle]`: the canned cycle in force (cnc_rdfixcycle): its
/// G code (80: none), the plane's two axes and the drilling axis (axis
/// numbers), the initial level, R point and Z point, the repetitions
/// commanded and done, the cut-in depth (Q) and the shifts, in the axes'
/// least input increments.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FixedCycle {
    pub mode: i16,
    pub plane_axes: [i16; 2],
    pub drill_axis: i16,
    pub initial: i32,
    pub r_point: i32,
    pub z_point: i32,
    pub repeats: [i32; 2],
    pub cut: i32,
    pub shift: [i32; 2],
}

/// One drive's ID information: each part's specification and serial
/// number (cut to the field's length less its NUL).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DriveId {
    pub motor: [String; 2],
    /// The pulse coder (servo) or the sub motor (spindle).
    pub sub: [String; 2],
    pub amplifier: [String; 2],
    pub power_supply: [String; 2],
    /// The software series-editions the *2 forms read after the parts: the
    /// amplifier's then the power supply's (servo), the power supply's
    /// (spindle).
    pub software: Vec<String>,
    /// Power modules 1 and 2: [specification, serial number] each
    /// (cnc_rdservoid2).
    pub modules: [[String; 2]; 2],
}

/// One board: its two ID words, group and hardware IDs, how many are
/// mounted, its slot, and how each ID is shown (format codes).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Board {
    pub id1: u32,
    pub id2: u32,
    pub group_id: i16,
    pub hard_id: i16,
    pub hard_num: i16,
    pub slot_no: i16,
    pub id1_format: i16,
    pub id2_format: i16,
}

/// One software: its ID, name, series and edition (4 characters each; the
/// CNC sends a fifth byte after each, 0).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Software {
    pub id: i16,
    /// Its name (cnc_rdsyssoft3_str: 12 characters and a NUL at most).
    pub name: String,
    pub series: String,
    pub edition: String,
}

impl Default for System {
    fn default() -> Self {
        let board = |group_id, hard_id, slot_no, id1, id2| Board {
            id1,
            id2,
            group_id,
            hard_id,
            hard_num: 1,
            slot_no,
            id1_format: 0,
            id2_format: 0,
        };
        let soft = |id, name: &str, series: &str, edition: &str| Software {
            id,
            name: name.into(),
            series: series.into(),
            edition: edition.into(),
        };
        System {
            model: 0,
            language: 0,
            operation_level: 4,
            protection: vec![[4, 4], [4, 4], [7, 7]],
            menu_switch: 0x0005,
            module_config: Vec::new(),
            boards: vec![
                board(1, 1, 0, 0x0001_0203, 0x0000_0010),
                board(1, 2, 0, 0x0001_0405, 0x0000_0020),
                board(2, 1, 1, 0x0002_0101, 0x0000_0001),
            ],
            software: vec![
                soft(1, "BASIC", "G421", "08.0"),
                soft(2, "OPTION-A1", "90E0", "10.0"),
                soft(3, "SUB CPU", "40A1", "05.0"),
                soft(4, "BOOT", "60W3", "01.0"),
                soft(5, "SERVO", "90D0", "24.0"),
                soft(6, "PMC", "40B1", "03.0"),
            ],
            servo: (1..=3)
                .map(|k| DriveId {
                    motor: ["A06B-0075-B103".into(), format!("C11A0{k}123")],
                    sub: ["A860-2000-T301".into(), format!("P2{k}456")],
                    amplifier: ["A06B-6240-H105".into(), format!("V09B0{k}789")],
                    power_supply: ["A06B-6200-H011".into(), "E0AC12345".into()],
                    software: vec!["9096-08".into(), "9G00-02".into()],
                    modules: [
                        ["A06B-6400-H002".into(), format!("M1A0{k}55")],
                        [String::new(), String::new()],
                    ],
                })
                .collect(),
            spindle: vec![DriveId {
                motor: ["A06B-1446-B103".into(), "C20A12345".into()],
                sub: [String::new(), String::new()],
                amplifier: ["A06B-6220-H011".into(), "V10B12345".into()],
                power_supply: ["A06B-6200-H011".into(), "E0AC12345".into()],
                software: vec!["9G00-02".into()],
                modules: Default::default(),
            }],
            slots: vec![
                Slot {
                    slot: 0x01,
                    module_id: 0x00c4,
                    software: 2,
                },
                Slot {
                    slot: 0x00,
                    module_id: 0x0040,
                    software: 1,
                },
                Slot {
                    slot: 0x82,
                    module_id: 0x00a8,
                    software: 3,
                },
            ],
            named: [("boot", 4), ("servo", 5), ("pmc", 6)]
                .map(|(k, v)| (k.to_string(), v))
                .into(),
            soft_inst: 0,
        }
    }
}
