//! Tool management, tool life and tool geometry beyond tool.rs.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use super::{IODBTLMAG, IODBTLMAG2, IODBTLMNG_F2, LONG, MAX_AXIS};
use std::os::raw::{c_char, c_short, c_uchar};

/// Data of `cnc_wr1length`, `cnc_wr1radius`, `cnc_wrt1info`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBITD2 {
    pub datano: c_short,
    pub r#type: LONG,
    pub data: LONG,
}

/// Data of `cnc_rdedgedatapage`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBTLMGR_ADD_INFO {
    pub dsp_info: LONG,
    pub data_kind: c_short,
}

/// `cnc_magazinesrch`, `cnc_toolsrch`: Search  magazine management data.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IDBTLM_SRCHDT {
    pub id_info: IDBTLM,
    pub srch_cond: c_short,
    pub add_cond: c_short,
}

/// `cnc_rdtlgeomsize`, `cnc_wrtlgeomsize`: read tool geom size data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLGS {
    pub data1: LONG,
    pub data2: LONG,
    pub tooltype: c_char,
    pub install: c_char,
    pub toolname: [c_char; 9],
    pub dummy: c_char,
}

/// `cnc_rdtlgeomsize_ext2`, `cnc_wrtlgeomsize_ext2`: read extended tool geom size data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLGSEXT2 {
    pub data1: LONG,
    pub data2: LONG,
    pub data3: LONG,
    pub data4: LONG,
    pub data5: LONG,
    pub data6: LONG,
    pub data7: LONG,
    pub data8: LONG,
    pub data9: LONG,
    pub data10: LONG,
    pub tooltype: c_char,
    pub install: c_char,
    pub holder: c_char,
    pub toolname: [c_char; 9],
}

/// Data of `cnc_rdtoollife_data`, `cnc_rdtoollife_tcodedata`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLLF {
    pub T_code_sum: LONG,
    pub life_count_sum: LONG,
    pub rem_life_sum: LONG,
    pub max_life_sum: LONG,
    pub notice_life_sum: LONG,
    pub tools_sum: c_short,
    pub notice_stat_sum: c_char,
    pub count_type_sum: c_char,
}

/// Data of `cnc_rdtoollifed_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLLFD {
    pub order: c_short,
    pub tool_num: c_short,
    pub life_count: LONG,
    pub rem_life: LONG,
    pub max_life: LONG,
    pub notice_life: LONG,
    pub life_stat: c_char,
    pub count_type: c_char,
    pub reserve: c_short,
}

/// The `item` member of `IODBTLM2`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBTLM2_item {
    pub data1: c_uchar,
    pub data2: c_short,
    pub data4: LONG,
}

/// `cnc_rdtool2`: read data.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBTLM2 {
    pub number: c_short,
    pub reserve: c_short,
    pub item: IODBTLM2_item,
}

/// Data of `cnc_magazinesrch`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMAG_SRCHINFO {
    pub startInfo: IODBTLMAG2,
    pub result: IODBTLMAG,
}

/// Data of `cnc_rdtlmgr_check`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMGR_CHECK {
    pub T_code: LONG,
    pub tool_num: c_short,
    pub reserve: c_short,
}

/// The `page` member of `IODBTLMGR_PAGE_info`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMGR_PAGE_info_page {
    pub s_edg: IODBTLMGR_EDG,
    pub e_edg: IODBTLMGR_EDG,
}

/// The `info` member of `IODBTLMGR_PAGE`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IODBTLMGR_PAGE_info {
    pub edg: IODBTLMGR_EDG,
    pub page: IODBTLMGR_PAGE_info_page,
}

/// Data of `cnc_rdedgedatapage`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IODBTLMGR_PAGE {
    pub info: IODBTLMGR_PAGE_info,
}

/// Data of `cnc_tool_in3`, `cnc_wredgedata`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMNG_MU_EDGE_DATA {
    pub life_count: LONG,
    pub max_life: LONG,
    pub rest_life: LONG,
    pub life_stat: c_uchar,
    pub cust_bits: c_uchar,
    pub reserve_s: c_short,
    pub H_code: c_short,
    pub D_code: c_short,
    pub spindle_speed: LONG,
    pub feedrate: LONG,
    pub G_code: c_short,
    pub W_code: c_short,
    pub custom1: LONG,
    pub custom2: LONG,
    pub custom3: LONG,
    pub custom4: LONG,
}

/// Data of `cnc_srttl_getdata`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMNG_SORT {
    pub tl_num: c_short,
    pub reserve: c_short,
    pub data: IODBTLMNG_F2,
}

/// The `sp_name` member of `IODBTLSPWTNAME`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLSPWTNAME_sp_name {
    pub sp_pos1: [c_char; 5],
    pub sp_pos2: [c_char; 5],
    pub sp_pos3: [c_char; 5],
    pub sp_pos4: [c_char; 5],
}

/// The `wt_name` member of `IODBTLSPWTNAME`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLSPWTNAME_wt_name {
    pub wt_pos1: [c_char; 5],
    pub wt_pos2: [c_char; 5],
    pub wt_pos3: [c_char; 5],
    pub wt_pos4: [c_char; 5],
}

/// Data of `cnc_rdspdlwaitname`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLSPWTNAME {
    pub sp_name: IODBTLSPWTNAME_sp_name,
    pub wt_name: IODBTLSPWTNAME_wt_name,
}

/// Data of `cnc_rdtoollife_data`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTL_RDTYPE {
    pub r#type: c_uchar,
    pub data_type: c_uchar,
    pub renew: c_char,
    pub reserve: c_char,
}

/// Data of `cnc_rdtool_cause`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTOOL_CAUSENME {
    pub cause1: [c_char; 8],
    pub cause2: [c_char; 8],
    pub cause3: [c_char; 8],
    pub cause4: [c_char; 8],
    pub cause5: [c_char; 8],
}

/// Data of `cnc_rdtool_inhis`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTOOL_INHIS {
    pub tool_no: c_short,
    pub reserve: c_short,
    pub date: IODBTOOL_DATE,
    pub tool_f2: IODBTLMNG_F2,
}

/// Data of `cnc_rdtool_outhis`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTOOL_OUTHIS {
    pub tool_no: c_short,
    pub cause: c_short,
    pub date: IODBTOOL_DATE,
    pub tool_f2: IODBTLMNG_F2,
}

/// `cnc_rdofslength`: read tool length offset data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBOFSLEN {
    pub len: LONG,
    pub dec: LONG,
}

/// `cnc_rdposofs`: read tool position offset for position data.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPOFS {
    pub mode: c_short,
    pub ofsvct: [LONG; MAX_AXIS],
}

/// `cnc_tool_srh_free_min_num`: Serch free number.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBTL_FREE_NUM {
    pub edge_gp: c_short,
    pub ofs_h: c_short,
    pub ofs_d: c_short,
    pub ofs_g: c_short,
    pub ofs_w: c_short,
    pub reserve: [c_short; 3],
}

/// Data of `cnc_rdtool_inhis`, `cnc_rdtool_outhis`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTOOL_DATE {
    pub year: c_short,
    pub mon: c_short,
    pub day: c_short,
    pub hour: c_short,
    pub min: c_short,
    pub sec: c_short,
}

/// Data of `cnc_rdedgedatapage`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBTLMGR_EDG {
    pub data_no: c_short,
    pub edge_no: c_short,
}

/// The `item` member of `IDBTLM`.
#[repr(C)]
#[derive(Clone, Copy)]
pub union IDBTLM_item {
    pub data1: c_uchar,
    pub data2: c_short,
    pub data4: LONG,
}

/// Data of `cnc_magazinesrch`, `cnc_toolsrch`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct IDBTLM {
    pub data_id: c_short,
    pub item: IDBTLM_item,
}
