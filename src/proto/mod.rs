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

/// Command words of the subpackets: the registry (src/spec/commands.rs).
pub use crate::spec::commands as cmd;

/// Parameters the 16i-class library reads at connect to learn the FOCAS option.
pub const OPTION_PARAM_16: i32 = 9968;
pub const OPTION_PARAM_15: i32 = 9153;
