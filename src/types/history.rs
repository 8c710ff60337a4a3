//! The histories: alarm, operator (signals, MDI keys, messages) and
//! operator-message histories, beside src/ffi/history.rs.

use super::LONG;
use std::os::raw::{c_char, c_short, c_ushort};

// --- alarm history ---

/// One record of ODBAHIS (48 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS_ALM {
    pub dummy: c_short,
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_char,
    pub year: c_char,
    pub month: c_char,
    pub day: c_char,
    pub hour: c_char,
    pub minute: c_char,
    pub second: c_char,
    pub dummy2: c_char,
    pub len_msg: c_short,
    pub alm_msg: [c_char; 32],
}

/// cnc_rdalmhistry: alarm history (10 records as declared; the caller's
/// `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS {
    pub s_no: c_ushort,
    pub r#type: c_short,
    pub e_no: c_ushort,
    pub alm_his: [ODBAHIS_ALM; 10],
}

/// One record of ODBAHIS2 (52 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS2_ALM {
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub len_msg: c_short,
    pub alm_msg: [c_char; 32],
}

/// cnc_rdalmhistry2: alarm history, all fields as shorts.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAHIS2 {
    pub s_no: c_ushort,
    pub e_no: c_ushort,
    pub alm_his: [ODBAHIS2_ALM; 10],
}

/// cnc_rdomhisinfo: the operator message history's size: most entries,
/// entries held, characters per message.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOMIF {
    pub om_max: c_ushort,
    pub om_sum: c_ushort,
    pub om_char: c_ushort,
}

/// One signal of IODBSIG: a PMC signal byte the operation history records
/// (the 16i's form, without the PMC number).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSIG_DATA {
    /// The entry's number (1..20).
    pub ent_no: c_short,
    /// The byte's address number.
    pub sig_no: c_short,
    /// The address letter as a number (0 G, 1 F, 2 Y, 3 X ...).
    pub sig_name: c_char,
    /// The bits recorded.
    pub mask_pat: c_char,
}

/// cnc_rdhissgnl: the signals the operation history records, 20 entries.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSIG {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [IODBSIG_DATA; 20],
}

/// One signal of IODBSIG3: a PMC signal byte the operation history records.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSIG3_DATA {
    /// The entry's number (1..60).
    pub ent_no: c_short,
    /// The PMC (1..).
    pub pmc_no: c_short,
    /// The byte's address number.
    pub sig_no: c_short,
    /// The address letter as a number (0 G, 1 F, 2 Y, 3 X ...).
    pub sig_name: c_char,
    /// The bits recorded.
    pub mask_pat: c_char,
}

/// cnc_rdhissgnl3 / cnc_wrhissgnl3: the signals the operation history
/// records, 60 entries.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBSIG3 {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [IODBSIG3_DATA; 60],
}

// --- operation and operator message histories, alarm history 5 ---

/// ODBHIS alarm record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBHIS_ALM {
    pub rec_type: c_short,
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_char,
    pub dummy: c_char,
}

/// ODBHIS MDI key record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBHIS_MDI {
    pub rec_type: c_short,
    pub key_code: c_char,
    pub pw_flag: c_char,
    pub dummy: [c_char; 4],
}

/// ODBHIS signal record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBHIS_SGN {
    pub rec_type: c_short,
    pub sig_name: c_char,
    pub sig_old: c_char,
    pub sig_new: c_char,
    pub dummy: c_char,
    pub sig_no: c_short,
}

/// ODBHIS date record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBHIS_DATE {
    pub rec_type: c_short,
    pub year: c_char,
    pub month: c_char,
    pub day: c_char,
    pub pw_flag: c_char,
    pub dummy: [c_char; 2],
}

/// ODBHIS time record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBHIS_TIME {
    pub rec_type: c_short,
    pub hour: c_char,
    pub minute: c_char,
    pub second: c_char,
    pub pw_flag: c_char,
    pub dummy: [c_char; 2],
}

/// One 8-byte ODBHIS record, by its `rec_type`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBHIS_DATA {
    pub rec_alm: ODBHIS_ALM,
    pub rec_mdi: ODBHIS_MDI,
    pub rec_sgn: ODBHIS_SGN,
    pub rec_date: ODBHIS_DATE,
    pub rec_time: ODBHIS_TIME,
}

impl Default for ODBHIS_DATA {
    fn default() -> Self {
        ODBHIS_DATA {
            rec_alm: ODBHIS_ALM::default(),
        }
    }
}

impl std::fmt::Debug for ODBHIS_DATA {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ODBHIS_DATA")
            .field("rec_alm", unsafe { &self.rec_alm })
            .finish()
    }
}

/// cnc_rdophistry: operation history (10 records as declared; the caller's
/// `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ODBHIS {
    pub s_no: c_ushort,
    pub r#type: c_short,
    pub e_no: c_ushort,
    pub data: [ODBHIS_DATA; 10],
}

/// cnc_rdomhistry: one operator message history entry.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBOMHIS {
    pub om_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub om_msg: [c_char; 256],
}

/// One entry of ODBOMHIS2.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBOMHIS2_OPM {
    pub dsp_flg: c_short,
    pub om_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub ope_msg: [c_char; 256],
}

/// cnc_rdomhistry2: operator message history (10 entries as declared).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBOMHIS2 {
    pub s_no: c_ushort,
    pub e_no: c_ushort,
    pub opm_his: [ODBOMHIS2_OPM; 10],
}

/// One entry of ODBAHIS5 (516 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBAHIS5_ALM {
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub len_msg: c_short,
    pub pth_no: c_short,
    pub sys_alm: c_short,
    pub dsp_flg: c_short,
    pub axis_num: c_short,
    pub alm_msg: [c_char; 64],
    pub g_modal: [LONG; 10],
    pub g_dp: [c_char; 10],
    pub dummy1: c_short,
    pub a_modal: [LONG; 10],
    pub a_dp: [c_char; 10],
    pub dummy2: c_short,
    pub abs_pos: [LONG; 32],
    pub abs_dp: [c_char; 32],
    pub mcn_pos: [LONG; 32],
    pub mcn_dp: [c_char; 32],
}

/// cnc_rdalmhistry5: alarm history with the modal and position snapshot (10 entries as declared).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBAHIS5 {
    pub s_no: c_ushort,
    pub e_no: c_ushort,
    pub alm_his: [ODBAHIS5_ALM; 10],
}

// --- operation history 4 (cnc_rdophistry4) ---

/// ODBOPHIS4 MDI key record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_MDI {
    pub key_code: c_char,
    pub pw_flag: c_char,
    pub pth_no: c_short,
    pub ex_flag: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
}

/// ODBOPHIS4 signal record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_SGN {
    pub sig_name: c_short,
    pub sig_no: c_short,
    pub sig_old: c_char,
    pub sig_new: c_char,
    pub pmc_no: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub dummy: c_short,
}

/// ODBOPHIS4 alarm record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_ALM {
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub pth_no: c_short,
}

/// ODBOPHIS4 date record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_DATE {
    pub evnt_type: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub dummy: c_short,
}

/// ODBOPHIS4 alarm record with the modal and position snapshot.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBOPHIS4_IAL {
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub pth_no: c_short,
    pub sys_alm: c_short,
    pub dsp_flg: c_short,
    pub axis_num: c_short,
    pub dummy1: c_short,
    pub g_modal: [LONG; 10],
    pub g_dp: [c_char; 10],
    pub dummy2: c_short,
    pub a_modal: [LONG; 10],
    pub a_dp: [c_char; 10],
    pub dummy3: c_short,
    pub abs_pos: [LONG; 32],
    pub abs_dp: [c_char; 32],
    pub mcn_pos: [LONG; 32],
    pub mcn_dp: [c_char; 32],
}

/// ODBOPHIS4 alarm record with its message and the snapshot.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBOPHIS4_MAL {
    pub alm_grp: c_short,
    pub alm_no: c_short,
    pub axis_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub pth_no: c_short,
    pub sys_alm: c_short,
    pub dsp_flg: c_short,
    pub axis_num: c_short,
    pub alm_msg: [c_char; 64],
    pub dummy1: c_short,
    pub g_modal: [LONG; 10],
    pub g_dp: [c_char; 10],
    pub dummy2: c_short,
    pub a_modal: [LONG; 10],
    pub a_dp: [c_char; 10],
    pub dummy3: c_short,
    pub abs_pos: [LONG; 32],
    pub abs_dp: [c_char; 32],
    pub mcn_pos: [LONG; 32],
    pub mcn_dp: [c_char; 32],
}

/// ODBOPHIS4 operator message record.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBOPHIS4_OPM {
    pub dsp_flg: c_short,
    pub om_no: c_short,
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub ope_msg: [c_char; 256],
}

/// ODBOPHIS4 tool offset record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_OFS {
    pub ofs_grp: c_short,
    pub ofs_no: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub pth_no: c_short,
    pub ofs_old: LONG,
    pub ofs_new: LONG,
    pub old_dp: c_short,
    pub new_dp: c_short,
}

/// ODBOPHIS4 parameter record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_PRM {
    pub prm_grp: c_short,
    pub prm_num: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub prm_len: c_short,
    pub prm_no: LONG,
    pub prm_old: LONG,
    pub prm_new: LONG,
    pub old_dp: c_short,
    pub new_dp: c_short,
}

/// ODBOPHIS4 work offset record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_WOF {
    pub ofs_grp: c_short,
    pub ofs_no: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub pth_no: c_short,
    pub axis_no: c_short,
    pub dummy: c_short,
    pub ofs_old: LONG,
    pub ofs_new: LONG,
    pub old_dp: c_short,
    pub new_dp: c_short,
}

/// ODBOPHIS4 macro variable record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_MAC {
    pub mac_no: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub pth_no: c_short,
    pub dummy: c_short,
    pub mac_old: LONG,
    pub mac_new: LONG,
    pub old_dp: c_short,
    pub new_dp: c_short,
}

/// ODBOPHIS4 macro variable record (32-bit variable number).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_MAC2 {
    pub mac_no: LONG,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
    pub pth_no: c_short,
    pub mac_old: LONG,
    pub mac_new: LONG,
    pub old_dp: c_short,
    pub new_dp: c_short,
}

/// ODBOPHIS4 screen change record.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOPHIS4_SCRN {
    pub scrn_old: c_short,
    pub scrn_new: c_short,
    pub dummy: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
}

/// The body of one ODBOPHIS4 record, by its `rec_type`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBOPHIS4_u {
    pub rec_mdi: ODBOPHIS4_MDI,
    pub rec_sgn: ODBOPHIS4_SGN,
    pub rec_alm: ODBOPHIS4_ALM,
    pub rec_date: ODBOPHIS4_DATE,
    pub rec_ial: ODBOPHIS4_IAL,
    pub rec_mal: ODBOPHIS4_MAL,
    pub rec_opm: ODBOPHIS4_OPM,
    pub rec_ofs: ODBOPHIS4_OFS,
    pub rec_prm: ODBOPHIS4_PRM,
    pub rec_wof: ODBOPHIS4_WOF,
    pub rec_mac: ODBOPHIS4_MAC,
    pub rec_mac2: ODBOPHIS4_MAC2,
    pub rec_scrn: ODBOPHIS4_SCRN,
}

impl std::fmt::Debug for ODBOPHIS4_u {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ODBOPHIS4_u").finish_non_exhaustive()
    }
}

/// cnc_rdophistry4: one operation history record. The records are packed
/// one after the other in the caller's buffer, each `rec_len` bytes long
/// (the size of its kind's member plus 4), not `sizeof(ODBOPHIS4)`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct ODBOPHIS4 {
    pub rec_len: c_short,
    pub rec_type: c_short,
    pub u: ODBOPHIS4_u,
}
