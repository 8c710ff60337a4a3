//! The FOCAS2 Ethernet codec, sans-IO: bytes in, structures out. Shared by the
//! client library and the simulator.

pub mod alarm;
pub mod call;
pub mod described;
pub mod download;
pub mod frame;
pub mod history;
pub mod machine;
pub mod macros;
pub mod maintenance;
pub mod names;
pub mod offset;
pub mod open;
pub mod packet;
pub mod param;
pub mod pmc;
pub mod position;
pub mod program;
pub mod status;
pub mod tool;
pub mod upload;
pub mod value;
pub mod wire;

/// Command words of the subpackets (class 1 = CNC unless noted).
pub mod cmd {
    pub const SYSINFO: u16 = 0x0018;
    pub const STATINFO: u16 = 0x0019;
    pub const STATINFO2: u16 = 0x00e2;
    pub const HDCK: u16 = 0x00e1;
    pub const TMMODE: u16 = 0x0098;
    pub const RDCNCID: u16 = 0x00e8;
    /// 16i class: read parameter (also the FOCAS option probe, parameter 9968).
    pub const RDPARAM16: u16 = 0x000e;
    /// Series 15 start-up companion of sysinfo.
    pub const SYSINFO15: u16 = 0x008c;
    /// 30i class: read parameter (Series 15: option probe, parameter 9153).
    pub const RDPARAM: u16 = 0x008d;
}

/// Parameters the 16i-class library reads at connect to learn the FOCAS option.
pub const OPTION_PARAM_16: i32 = 9968;
pub const OPTION_PARAM_15: i32 = 9153;
