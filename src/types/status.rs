//! Connection group and status structures.

use super::{LONG, MAX_AXIS, MAX_CNCPATH, ULONG};
use std::os::raw::{c_char, c_short};

/// cnc_sysinfo: CNC system information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYS {
    pub addinfo: c_short,
    pub max_axis: c_short,
    pub cnc_type: [c_char; 2],
    pub mt_type: [c_char; 2],
    pub series: [c_char; 4],
    pub version: [c_char; 4],
    pub axes: [c_char; 2],
}

/// cnc_statinfo: CNC status information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBST {
    pub hdck: c_short,
    pub tmmode: c_short,
    pub aut: c_short,
    pub run: c_short,
    pub motion: c_short,
    pub mstb: c_short,
    pub emergency: c_short,
    pub alarm: c_short,
    pub edit: c_short,
}

/// cnc_statinfo2: CNC status information 2.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBST2 {
    pub hdck: c_short,
    pub tmmode: c_short,
    pub aut: c_short,
    pub run: c_short,
    pub motion: c_short,
    pub mstb: c_short,
    pub emergency: c_short,
    pub alarm: c_short,
    pub edit: c_short,
    pub warning: c_short,
    pub o3dchk: c_short,
    pub ext_opt: c_short,
    pub restart: c_short,
}

/// cnc_getdtailerr: detail of the last error.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBERR {
    pub err_no: c_short,
    pub err_dtno: c_short,
}

/// One path of ODBSYSEX.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYSEX_PATH {
    /// Machine type as two ASCII characters (" M", " T", ...).
    pub system: c_short,
    pub group: c_short,
    pub attrib: c_short,
    pub ctrl_axis: c_short,
    pub ctrl_srvo: c_short,
    pub ctrl_spdl: c_short,
    pub mchn_no: c_short,
    pub reserved: c_short,
}

/// cnc_sysinfo_ex: the CNC's maximum and controlled axes, spindles, paths
/// and machine groups, and per path.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYSEX {
    pub max_axis: c_short,
    pub max_spdl: c_short,
    pub max_path: c_short,
    pub max_mchn: c_short,
    pub ctrl_axis: c_short,
    pub ctrl_srvo: c_short,
    pub ctrl_spdl: c_short,
    pub ctrl_path: c_short,
    pub ctrl_mchn: c_short,
    pub addinfo: c_short,
    pub reserved: [c_short; 2],
    pub path: [ODBSYSEX_PATH; MAX_CNCPATH],
}

/// cnc_rdpitchr: pitch error compensation data (5 points as declared; the
/// caller's `length` says how many really fit).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBPI {
    pub datano_s: c_short,
    pub dummy: c_short,
    pub datano_e: c_short,
    pub data: [c_char; 5],
}

/// cnc_rdctrldi: the spindle control input signals.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSPDI {
    pub sgnl1: c_char,
    pub sgnl2: c_char,
    pub sgnl3: c_char,
    pub sgnl4: c_char,
}

/// cnc_rdctrldo: the spindle control output signals.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSPDO {
    pub sgnl1: c_char,
    pub sgnl2: c_char,
    pub sgnl3: c_char,
    pub sgnl4: c_char,
}

/// cnc_rdprstrinfo: program restart information.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPRS {
    pub datano: c_short,
    pub r#type: c_short,
    pub data_info: [c_short; 5],
    pub rstr_bc: LONG,
    pub rstr_m: [LONG; 35],
    pub rstr_t: [LONG; 2],
    pub rstr_s: LONG,
    pub rstr_b: LONG,
    pub dest: [LONG; MAX_AXIS],
    pub dist: [LONG; MAX_AXIS],
}

impl Default for ODBPRS {
    fn default() -> Self {
        ODBPRS {
            datano: 0,
            r#type: 0,
            data_info: [0; 5],
            rstr_bc: 0,
            rstr_m: [0; 35],
            rstr_t: [0; 2],
            rstr_s: 0,
            rstr_b: 0,
            dest: [0; MAX_AXIS],
            dist: [0; MAX_AXIS],
        }
    }
}

/// cnc_rdopnlsgnl: the software operator panel's signals (`type` selects
/// which members the CNC fills).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBSGNL {
    pub datano: c_short,
    pub r#type: c_short,
    pub mode: c_short,
    pub hndl_ax: c_short,
    pub hndl_mv: c_short,
    pub rpd_ovrd: c_short,
    pub jog_ovrd: c_short,
    pub feed_ovrd: c_short,
    pub spdl_ovrd: c_short,
    pub blck_del: c_short,
    pub sngl_blck: c_short,
    pub machn_lock: c_short,
    pub dry_run: c_short,
    pub mem_prtct: c_short,
    pub feed_hold: c_short,
}

/// cnc_rdopnlgnrl / cnc_wropnlgnrl: the software operator panel's general
/// purpose switches (`sgnal` bit k is switch k + 1; `type` selects them).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBGNRL {
    pub datano: c_short,
    pub r#type: c_short,
    pub sgnal: c_char,
}

/// cnc_rdopnlgsname / cnc_wropnlgsname: the names of the software
/// operator panel's eight general purpose switches (8 characters and a
/// NUL each; `type` selects them).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRDNA {
    pub datano: c_short,
    pub r#type: c_short,
    pub sgnl1_name: [c_char; 9],
    pub sgnl2_name: [c_char; 9],
    pub sgnl3_name: [c_char; 9],
    pub sgnl4_name: [c_char; 9],
    pub sgnl5_name: [c_char; 9],
    pub sgnl6_name: [c_char; 9],
    pub sgnl7_name: [c_char; 9],
    pub sgnl8_name: [c_char; 9],
}

/// cnc_rdopnlgnrl2 / cnc_wropnlgnrl2: the software operator panel's
/// general purpose switches, `type` and `sgnal` as shorts.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBGNRL2 {
    pub datano: c_short,
    pub r#type: c_short,
    pub sgnal: c_short,
}

/// cnc_rdopnlgsname2 / cnc_wropnlgsname2: the names of the software
/// operator panel's sixteen general purpose switches (8 characters and a
/// NUL each; `type` selects them).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRDNA2 {
    pub datano: c_short,
    pub r#type: c_short,
    pub sgnl1_name: [c_char; 9],
    pub sgnl2_name: [c_char; 9],
    pub sgnl3_name: [c_char; 9],
    pub sgnl4_name: [c_char; 9],
    pub sgnl5_name: [c_char; 9],
    pub sgnl6_name: [c_char; 9],
    pub sgnl7_name: [c_char; 9],
    pub sgnl8_name: [c_char; 9],
    pub sgnl9_name: [c_char; 9],
    pub sgnl10_name: [c_char; 9],
    pub sgnl11_name: [c_char; 9],
    pub sgnl12_name: [c_char; 9],
    pub sgnl13_name: [c_char; 9],
    pub sgnl14_name: [c_char; 9],
    pub sgnl15_name: [c_char; 9],
    pub sgnl16_name: [c_char; 9],
}

/// cnc_rdsyshard: one board (hardware) of the CNC: its two ID words, its
/// group and hardware IDs, how many of it are mounted, its slot, and the
/// display format of each ID.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYSH {
    pub id1: ULONG,
    pub id2: ULONG,
    pub group_id: c_short,
    pub hard_id: c_short,
    pub hard_num: c_short,
    pub slot_no: c_short,
    pub id1_format: c_short,
    pub id2_format: c_short,
}

/// cnc_rdsyssoft: the CNC's slots (physical `slot_no_p`, 0xff ending the
/// list; logical `slot_no_l`), the module and software ID of each, the
/// series and version of the software on each (4 characters, then a NUL),
/// and the series and version of the named software (boot, servo, PMC,
/// ladder, macro, C executor, ...).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBSYSS {
    pub slot_no_p: [c_char; 16],
    pub slot_no_l: [c_char; 16],
    pub module_id: [c_short; 16],
    pub soft_id: [c_short; 16],
    pub soft_series: [[c_char; 5]; 16],
    pub soft_version: [[c_char; 5]; 16],
    pub soft_inst: c_short,
    pub boot_ser: [c_char; 5],
    pub boot_ver: [c_char; 5],
    pub servo_ser: [c_char; 5],
    pub servo_ver: [c_char; 5],
    pub pmc_ser: [c_char; 5],
    pub pmc_ver: [c_char; 5],
    pub ladder_ser: [c_char; 5],
    pub ladder_ver: [c_char; 5],
    pub mcrlib_ser: [c_char; 5],
    pub mcrlib_ver: [c_char; 5],
    pub mcrapl_ser: [c_char; 5],
    pub mcrapl_ver: [c_char; 5],
    pub spl1_ser: [c_char; 5],
    pub spl1_ver: [c_char; 5],
    pub spl2_ser: [c_char; 5],
    pub spl2_ver: [c_char; 5],
    pub spl3_ser: [c_char; 5],
    pub spl3_ver: [c_char; 5],
    pub c_exelib_ser: [c_char; 5],
    pub c_exelib_ver: [c_char; 5],
    pub c_exeapl_ser: [c_char; 5],
    pub c_exeapl_ver: [c_char; 5],
    pub int_vga_ser: [c_char; 5],
    pub int_vga_ver: [c_char; 5],
    pub out_vga_ser: [c_char; 5],
    pub out_vga_ver: [c_char; 5],
    pub pmm_ser: [c_char; 5],
    pub pmm_ver: [c_char; 5],
    pub pmc_mng_ser: [c_char; 5],
    pub pmc_mng_ver: [c_char; 5],
    pub pmc_shin_ser: [c_char; 5],
    pub pmc_shin_ver: [c_char; 5],
    pub pmc_shout_ser: [c_char; 5],
    pub pmc_shout_ver: [c_char; 5],
    pub pmc_c_ser: [c_char; 5],
    pub pmc_c_ver: [c_char; 5],
    pub pmc_edit_ser: [c_char; 5],
    pub pmc_edit_ver: [c_char; 5],
    pub lddr_mng_ser: [c_char; 5],
    pub lddr_mng_ver: [c_char; 5],
    pub lddr_apl_ser: [c_char; 5],
    pub lddr_apl_ver: [c_char; 5],
    pub spl4_ser: [c_char; 5],
    pub spl4_ver: [c_char; 5],
    pub mcr2_ser: [c_char; 5],
    pub mcr2_ver: [c_char; 5],
    pub mcr3_ser: [c_char; 5],
    pub mcr3_ver: [c_char; 5],
    pub eth_boot_ser: [c_char; 5],
    pub eth_boot_ver: [c_char; 5],
    pub reserve: [[c_char; 5]; 8],
}

/// cnc_rdsyssoft2: ODBSYSS, then the embedded Ethernet's series and
/// version and more reserved entries.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(non_snake_case)]
pub struct ODBSYSS2 {
    pub slot_no_p: [c_char; 16],
    pub slot_no_l: [c_char; 16],
    pub module_id: [c_short; 16],
    pub soft_id: [c_short; 16],
    pub soft_series: [[c_char; 5]; 16],
    pub soft_version: [[c_char; 5]; 16],
    pub soft_inst: c_short,
    pub boot_ser: [c_char; 5],
    pub boot_ver: [c_char; 5],
    pub servo_ser: [c_char; 5],
    pub servo_ver: [c_char; 5],
    pub pmc_ser: [c_char; 5],
    pub pmc_ver: [c_char; 5],
    pub ladder_ser: [c_char; 5],
    pub ladder_ver: [c_char; 5],
    pub mcrlib_ser: [c_char; 5],
    pub mcrlib_ver: [c_char; 5],
    pub mcrapl_ser: [c_char; 5],
    pub mcrapl_ver: [c_char; 5],
    pub spl1_ser: [c_char; 5],
    pub spl1_ver: [c_char; 5],
    pub spl2_ser: [c_char; 5],
    pub spl2_ver: [c_char; 5],
    pub spl3_ser: [c_char; 5],
    pub spl3_ver: [c_char; 5],
    pub c_exelib_ser: [c_char; 5],
    pub c_exelib_ver: [c_char; 5],
    pub c_exeapl_ser: [c_char; 5],
    pub c_exeapl_ver: [c_char; 5],
    pub int_vga_ser: [c_char; 5],
    pub int_vga_ver: [c_char; 5],
    pub out_vga_ser: [c_char; 5],
    pub out_vga_ver: [c_char; 5],
    pub pmm_ser: [c_char; 5],
    pub pmm_ver: [c_char; 5],
    pub pmc_mng_ser: [c_char; 5],
    pub pmc_mng_ver: [c_char; 5],
    pub pmc_shin_ser: [c_char; 5],
    pub pmc_shin_ver: [c_char; 5],
    pub pmc_shout_ser: [c_char; 5],
    pub pmc_shout_ver: [c_char; 5],
    pub pmc_c_ser: [c_char; 5],
    pub pmc_c_ver: [c_char; 5],
    pub pmc_edit_ser: [c_char; 5],
    pub pmc_edit_ver: [c_char; 5],
    pub lddr_mng_ser: [c_char; 5],
    pub lddr_mng_ver: [c_char; 5],
    pub lddr_apl_ser: [c_char; 5],
    pub lddr_apl_ver: [c_char; 5],
    pub spl4_ser: [c_char; 5],
    pub spl4_ver: [c_char; 5],
    pub mcr2_ser: [c_char; 5],
    pub mcr2_ver: [c_char; 5],
    pub mcr3_ser: [c_char; 5],
    pub mcr3_ver: [c_char; 5],
    pub eth_boot_ser: [c_char; 5],
    pub eth_boot_ver: [c_char; 5],
    pub reserve: [[c_char; 5]; 8],
    pub embEthe_ser: [c_char; 5],
    pub embEthe_ver: [c_char; 5],
    pub reserve2: [[c_char; 5]; 38],
}

/// cnc_rdsyssoft3: one software of the CNC: its ID, series and edition
/// (four characters each, then a fifth byte as the CNC sent it).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYSS3 {
    pub soft_id: c_short,
    pub soft_series: [c_char; 5],
    pub soft_edition: [c_char; 5],
}

/// cnc_rdsyssoft3_str: one software of the CNC: its ID, name, series and
/// edition (the bytes as the CNC sent them).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSYSS3_STR {
    pub soft_id: c_short,
    pub soft_name: [c_char; 13],
    pub soft_series: [c_char; 5],
    pub soft_edition: [c_char; 5],
    pub dummy: [c_char; 3],
}

/// cnc_rdservoid / cnc_rdfromservoid: the specifications and serial
/// numbers of an axis's servo motor, pulse coder, servo amplifier and
/// power supply (characters as the CNC sent them).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCSVID {
    pub mt_spc: [c_char; 20],
    pub mt_srn: [c_char; 10],
    pub plc_spc: [c_char; 22],
    pub plc_srn: [c_char; 9],
    pub svm_spc: [c_char; 22],
    pub svm_srn: [c_char; 12],
    pub psm_spc: [c_char; 22],
    pub psm_srn: [c_char; 12],
}

/// cnc_rdspindleid / cnc_rdfromspindleid: the specifications and serial
/// numbers of a spindle's motor, sub motor, amplifier and power supply.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCSPID {
    pub mt_spc: [c_char; 20],
    pub mt_srn: [c_char; 10],
    pub sbmt_spc: [c_char; 20],
    pub sbmt_srn: [c_char; 10],
    pub spm_spc: [c_char; 22],
    pub spm_srn: [c_char; 12],
    pub psm_spc: [c_char; 22],
    pub psm_srn: [c_char; 12],
}

/// cnc_rdservoid2 / cnc_rdfromservoid2: ODBCSVID's parts, then the
/// software series and edition of the servo amplifier and of the power
/// supply, and the specifications and serial numbers of power modules 1
/// and 2 (characters as the CNC sent them).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCSVID2 {
    pub mt_spc: [c_char; 20],
    pub mt_srn: [c_char; 10],
    pub plc_spc: [c_char; 22],
    pub plc_srn: [c_char; 9],
    pub svm_spc: [c_char; 22],
    pub svm_srn: [c_char; 12],
    pub psm_spc: [c_char; 22],
    pub psm_srn: [c_char; 12],
    pub svs_see: [c_char; 9],
    pub pss_see: [c_char; 9],
    pub pm1_spc: [c_char; 22],
    pub pm1_srn: [c_char; 9],
    pub pm2_spc: [c_char; 22],
    pub pm2_srn: [c_char; 9],
}

/// cnc_rdspindleid2 / cnc_rdfromspindleid2: ODBCSPID's parts, then the
/// power supply's software series and edition.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCSPID2 {
    pub mt_spc: [c_char; 20],
    pub mt_srn: [c_char; 10],
    pub sbmt_spc: [c_char; 20],
    pub sbmt_srn: [c_char; 10],
    pub spm_spc: [c_char; 22],
    pub spm_srn: [c_char; 12],
    pub psm_spc: [c_char; 22],
    pub psm_srn: [c_char; 12],
    pub pss_see: [c_char; 9],
}
