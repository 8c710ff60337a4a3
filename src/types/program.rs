//! Program execution: numbers, names, blocks, modal data, timers, upload.

#[allow(unused_imports)]
use super::{LONG, ULONG};
use std::os::raw::{c_char, c_short};

// --- program ---

/// cnc_rdexecpt: a program pointer (declared for programs that call it; no
/// FANUC Ethernet library implements it).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PRGPNT {
    pub prog_no: LONG,
    pub blk_no: LONG,
}

/// cnc_rdprgnum: running and main program numbers (low 16 bits, as FANUC's).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPRO {
    pub dummy: [c_short; 2],
    pub data: c_short,
    pub mdata: c_short,
}

/// cnc_rdprgnumo8: running and main program numbers, 8 digits each.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPROO8 {
    pub dummy: [c_short; 2],
    pub data: LONG,
    pub mdata: LONG,
}

/// cnc_rdcommand: one commanded value of a block: the address letter,
/// which of the block's words of that address (M codes: 1, 2, 3 ...), a
/// flag, the value and its decimal places.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCMD {
    pub adrs: c_char,
    pub num: c_char,
    pub flag: c_short,
    pub cmd_val: LONG,
    pub dec_val: LONG,
}

/// cnc_rdseqnum: sequence number.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSEQ {
    pub dummy: [c_short; 2],
    pub data: LONG,
}

/// cnc_exeprgname: name and number of the running program.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBEXEPRG {
    pub name: [c_char; 36],
    pub o_num: LONG,
}

impl Default for ODBEXEPRG {
    fn default() -> Self {
        ODBEXEPRG {
            name: [0; 36],
            o_num: 0,
        }
    }
}

/// One modal code other than a G code (cnc_modal aux / raux1 / raux2).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct MODAL_AUX {
    pub aux_data: LONG,
    pub flag1: c_char,
    pub flag2: c_char,
}

/// The union of ODBMDL.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBMDL_modal {
    pub g_data: c_char,
    pub g_rdata: [c_char; 35],
    pub g_1shot: [c_char; 4],
    pub aux: MODAL_AUX,
    pub raux1: [MODAL_AUX; 27],
    pub raux2: [MODAL_AUX; 32],
}

impl Default for ODBMDL_modal {
    fn default() -> Self {
        ODBMDL_modal {
            raux2: [MODAL_AUX::default(); 32],
        }
    }
}

impl std::fmt::Debug for ODBMDL_modal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // Every member is plain bytes: show the largest view.
        f.debug_struct("ODBMDL_modal")
            .field("raux2", unsafe { &self.raux2 })
            .finish()
    }
}

/// cnc_modal: modal data (G codes or other codes).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ODBMDL {
    pub datano: c_short,
    pub r#type: c_short,
    pub modal: ODBMDL_modal,
}

/// cnc_rdtimer: a timer as minutes and milliseconds.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTIME {
    pub minute: LONG,
    pub msec: LONG,
}

/// IODBTIMER date view.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTIMER_date {
    pub year: c_short,
    pub month: c_short,
    pub date: c_short,
}

/// IODBTIMER time view.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTIMER_time {
    pub hour: c_short,
    pub minute: c_short,
    pub second: c_short,
}

/// The union of IODBTIMER: date (type 0) or time (type 1).
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBTIMER_data {
    pub date: IODBTIMER_date,
    pub time: IODBTIMER_time,
}

impl Default for IODBTIMER_data {
    fn default() -> Self {
        IODBTIMER_data {
            date: IODBTIMER_date::default(),
        }
    }
}

impl std::fmt::Debug for IODBTIMER_data {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("IODBTIMER_data")
            .field("date", unsafe { &self.date })
            .finish()
    }
}

/// cnc_gettimer / cnc_settimer: the CNC's date (type 0) or time (type 1).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct IODBTIMER {
    pub r#type: c_short,
    pub dummy: c_short,
    pub data: IODBTIMER_data,
}

/// cnc_toolnum: tool number of a tool in a tool-life group (cnc_rd1length,
/// cnc_rd2length, cnc_rd1radius, cnc_rd2radius, cnc_t1info, cnc_t2info: its
/// H and D numbers and information).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTLIFE4 {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: LONG,
}

/// cnc_rdprogdir: the program directory as text ("O1O1000%", see the function).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PRGDIR {
    pub prg_data: [c_char; 256],
}

impl Default for PRGDIR {
    fn default() -> Self {
        PRGDIR { prg_data: [0; 256] }
    }
}

/// A date of PRGDIR3 (`mdate`, `cdate`).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PRGDIR3_date {
    pub year: c_short,
    pub month: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub minute: c_short,
    pub dummy: c_short,
}

/// cnc_rdprogdir3: one program of the directory (88 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PRGDIR3 {
    pub number: LONG,
    pub length: LONG,
    pub page: LONG,
    pub comment: [c_char; 52],
    pub mdate: PRGDIR3_date,
    pub cdate: PRGDIR3_date,
}

impl Default for PRGDIR3 {
    fn default() -> Self {
        PRGDIR3 {
            number: 0,
            length: 0,
            page: 0,
            comment: [0; 52],
            mdate: PRGDIR3_date::default(),
            cdate: PRGDIR3_date::default(),
        }
    }
}

/// cnc_rdprogdir4: FANUC's header names PRGDIR3 so (a `#define`).
pub type PRGDIR4 = PRGDIR3;

/// One program of ODBPTIME: its number and machining time.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPTIME_DATA {
    pub prg_no: LONG,
    pub hour: c_short,
    pub minute: c_char,
    pub second: c_char,
}

/// cnc_rdproctime: the machining times of the last programs run.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPTIME {
    pub num: c_short,
    pub data: [ODBPTIME_DATA; 10],
}

/// cnc_rdproginfo type 0: programs and memory, registered and free.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBNC_bin {
    pub reg_prg: c_short,
    pub unreg_prg: c_short,
    pub used_mem: LONG,
    pub unused_mem: LONG,
}

/// The union of ODBNC: binary (type 0) or ASCII (type 1).
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBNC_u {
    pub bin: ODBNC_bin,
    pub asc: [c_char; 31],
}

impl Default for ODBNC_u {
    fn default() -> Self {
        ODBNC_u { asc: [0; 31] }
    }
}

impl std::fmt::Debug for ODBNC_u {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ODBNC_u")
            .field("asc", unsafe { &self.asc })
            .finish()
    }
}

/// cnc_rdproginfo: program memory information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ODBNC {
    pub u: ODBNC_u,
}

/// cnc_rdmdipntr: execution pointers of MDI operation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBMDIP {
    pub mdiprog: c_short,
    pub mdipntr: LONG,
    pub crntprog: c_short,
    pub crntpntr: LONG,
}

/// cnc_rdmdipntro8: execution pointers of MDI operation, program numbers
/// of 8 digits.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBMDIPO8 {
    /// Program number executing.
    pub mdiprog: LONG,
    /// Its execution pointer.
    pub mdipntr: LONG,
    /// Program number prepared.
    pub crntprog: LONG,
    /// Its pointer.
    pub crntpntr: LONG,
}

/// cnc_rdprogdir2: one program of the directory.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PRGDIR2 {
    pub number: c_short,
    pub length: LONG,
    pub comment: [c_char; 51],
    pub dummy: c_char,
}

impl Default for PRGDIR2 {
    fn default() -> Self {
        PRGDIR2 {
            number: 0,
            length: 0,
            comment: [0; 51],
            dummy: 0,
        }
    }
}

/// cnc_rdprogdir2o8: one program of the directory, its number 8 digits.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PRGDIR2O8 {
    pub number: LONG,
    pub length: LONG,
    pub comment: [c_char; 51],
    pub dummy: c_char,
}

impl Default for PRGDIR2O8 {
    fn default() -> Self {
        PRGDIR2O8 {
            number: 0,
            length: 0,
            comment: [0; 51],
            dummy: 0,
        }
    }
}

/// cnc_rdpdf_drive: the program drives ("CNC_MEM" ...).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPDFDRV {
    pub max_num: c_short,
    pub dummy: c_short,
    pub drive: [[c_char; 12]; 16],
}

/// cnc_rdpdf_inf: a drive's capacity and directories.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPDFINF {
    pub used_page: LONG,
    pub all_page: LONG,
    pub used_dir: LONG,
    pub all_dir: LONG,
}

/// cnc_rdpdf_subdirn: directories and files a directory holds.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPDFNFIL {
    pub dir_num: c_short,
    pub file_num: c_short,
}

/// cnc_rdpdf_subdir input: the folder and the first entry wanted.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBPDFSDIR {
    pub path: [c_char; 212],
    pub req_num: c_short,
    pub dummy: c_short,
}

/// cnc_rdpdf_subdir output: one sub-folder.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPDFSDIR {
    pub sub_exist: c_short,
    pub dummy: c_short,
    pub d_f: [c_char; 36],
}

/// cnc_rdpdf_alldir input: the folder, the first entry, size and format kinds.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBPDFADIR {
    pub path: [c_char; 212],
    pub req_num: c_short,
    pub size_kind: c_short,
    pub r#type: c_short,
    pub dummy: c_short,
}

/// cnc_rdpdf_alldir output: one folder or program.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBPDFADIR {
    pub data_kind: c_short,
    pub year: c_short,
    pub mon: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
    pub dummy: c_short,
    pub dummy2: LONG,
    pub size: LONG,
    pub attr: ULONG,
    pub d_f: [c_char; 36],
    pub comment: [c_char; 52],
    pub o_time: [c_char; 12],
}
