//! Data server, USB memory, embedded folders, DNC and remote diagnosis files.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{LONG, ULONG};
use std::os::raw::{c_char, c_short, c_uchar, c_ushort};

/// Data of `cnc_rdusbfilelist`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBUSBFILE {
    pub path: [c_char; 256],
    pub offset: ULONG,
    pub req_num: c_short,
    pub req_attrib: c_ushort,
    pub sort: c_char,
    pub req_comment: c_char,
    pub req_total: c_char,
    pub dummy: c_char,
}

/// Data of `cnc_searchusbfile`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBUSBSEARCH {
    pub path: [c_char; 256],
    pub s_fname: [c_char; 36],
    pub req_attrib: c_ushort,
    pub sort: c_char,
    pub dummy: c_char,
}

/// `cnc_rdcomparam`, `cnc_wrcomparam`: read communication parameter for DNC1, DNC2, OSI-Ethernet.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBCPRM {
    pub NcApli: [c_char; 65],
    pub Dummy1: c_char,
    pub HostApli: [c_char; 65],
    pub Dummy2: c_char,
    pub StatPstv: ULONG,
    pub StatNgtv: ULONG,
    pub Statmask: ULONG,
    pub AlarmStat: ULONG,
    pub PsclHaddr: ULONG,
    pub PsclLaddr: ULONG,
    pub SvcMode1: c_ushort,
    pub SvcMode2: c_ushort,
    pub FileTout: LONG,
    pub RemTout: LONG,
}

/// `cnc_dtsvrdset`, `cnc_dtsvwrset`: read setting data for Data Server.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBDSSET {
    pub host_ip: [c_char; 16],
    pub host_uname: [c_char; 32],
    pub host_passwd: [c_char; 32],
    pub host_dir: [c_char; 128],
    pub dtsv_mac: [c_char; 13],
    pub dtsv_ip: [c_char; 16],
    pub dtsv_mask: [c_char; 16],
}

/// `cnc_dncprgname`: read program name of DNC operation.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBDNCPRG {
    pub name: [c_char; 36],
    pub o_num: LONG,
}

/// One element of `ODBDSDIR.data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBDSDIR_data {
    pub file_name: [c_char; 16],
    pub comment: [c_char; 64],
    pub size: LONG,
    pub date: [c_char; 16],
}

/// `cnc_dtsvrdpgdir`: read file directory in Data Server.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBDSDIR {
    pub file_num: LONG,
    pub remainder: LONG,
    pub data_num: c_short,
    pub data: [ODBDSDIR_data; 32],
}

/// `cnc_dtsvmntinfo`: read maintenance information for Data Server.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDSMNT {
    pub empty_cnt: LONG,
    pub total_size: LONG,
    pub read_ptr: LONG,
    pub write_ptr: LONG,
}

/// `cnc_rdembedf_inf`: read embedded folder information.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBEMBEDFINF {
    pub used_page: LONG,
    pub all_page: LONG,
}

/// `cnc_pdf_rdcallstack`: read call stack PDF.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBNESTPDF {
    pub attrib: ULONG,
    pub comment: [c_char; 64],
    pub prog_name: [c_char; 245],
    pub dummy: [c_char; 7],
}

/// Data of `cnc_rdfsraminfo2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSRAMIF2 {
    pub protect: LONG,
    pub adrs: ULONG,
    pub size: LONG,
}

/// Data of `cnc_rdusbfilelist`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBUSBFILE {
    pub size: ULONG,
    pub attribute: c_ushort,
    pub long_name: c_ushort,
    pub year: c_ushort,
    pub mon: c_uchar,
    pub day: c_uchar,
    pub hour: c_uchar,
    pub min: c_uchar,
    pub sec: c_uchar,
    pub dummy: c_uchar,
    pub fname: [c_char; 36],
    pub comment: [c_char; 64],
}

/// Data of `cnc_rdusbfilelist`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBUSBINFO {
    pub f_num: c_short,
    pub next_entry: c_char,
    pub dummy: c_char,
    pub total: ULONG,
}

/// Data of `cnc_rdusbdevinfo`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBUSBSIZE {
    pub totalsize_h: ULONG,
    pub totalsize_l: ULONG,
    pub freesize_h: ULONG,
    pub freesize_l: ULONG,
}

/// `cnc_dsfile_req`: get file list infomation.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODB_IN_DSFILE_REQ {
    pub file: [c_char; 256],
    pub fnum: LONG,
    pub offset: LONG,
    pub detail: c_short,
    pub option: c_ushort,
}

/// `cnc_dsstat_rdfile`: get file list infomation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODB_IN_STAT_DSFILE {
    pub req_num: c_short,
    pub size_type: c_short,
}

/// Data of `cnc_dsstat_rdfile`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OUT_DSFILE {
    pub year: c_short,
    pub mon: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
    pub size: LONG,
    pub attr: ULONG,
    pub file: [c_char; 36],
    pub info: [c_char; 128],
}

/// Data of `cnc_dsstat_rdfile`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OUT_DSINFO {
    pub r#type: c_short,
    pub dummy: c_short,
    pub fnum: LONG,
    pub total: LONG,
    pub remain_h: ULONG,
    pub remain_l: ULONG,
    pub dir: [c_char; 256],
}

/// `cnc_pdf_rdrmtdgn`, `cnc_pdf_startrmtdgn`: Remote Diagnosis Start.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OUT_RMTDGNINFO {
    pub receipt_num: ULONG,
    pub time: ULONG,
    pub status: c_short,
    pub err_num: c_short,
    pub err_msg: [c_char; 36],
}
