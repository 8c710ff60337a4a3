//! The Rust API: typed, safe reads of a CNC for Rust programs using this
//! crate as a library, over the same connection pairs and codec as the C
//! functions (not through them).
//!
//! ```
//! use fwlib32::native::{Cnc, Decimal};
//! use fwlib32::sim::{Profile, Simulator};
//! use std::time::Duration;
//!
//! let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?; // a 31i mill
//! let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
//!
//! println!("{} {}", cnc.status()?.mode, cnc.status()?.run); // MEM STRT
//! for axis in cnc.positions()? {
//!     println!("{} {}", axis.name, axis.absolute); // X 125.000 ...
//! }
//! let limit: f64 = cnc.param(1320, Some(1))?; // stroke limit of X, mm
//! assert_eq!(limit, 800.0);
//! assert_eq!(cnc.macro_var(500)?, Some(Decimal::new(25400, 3)));
//! let d100: Vec<i16> = cnc.pmc(fwlib32::native::PmcArea::D, 100..=120)?; // 11 words
//! assert_eq!(d100.len(), 11);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Errors name the FOCAS function that failed and carry its `EW_*` code and
//! the detail words (see [`Error`]).

mod alarm;
mod batch;
mod cnc;
mod decimal;
mod error;
mod executing;
mod macros;
mod meter;
mod modal;
mod param;
mod part;
mod pmc;
mod position;
mod program;
#[cfg(feature = "serde")]
mod ser;
mod shopfloor;
mod status;

pub use alarm::{Alarm, AlarmKind, HistoryEntry, Timestamp};
pub use batch::{Batch, Replies, Ticket};
pub use cnc::{Cnc, DEFAULT_PORT};
pub use decimal::{Decimal, ParseDecimalError};
pub use error::{Detail, Error, Ew, Result};
pub use meter::Meter;
pub use param::{FromValue, Kind, Param, Value};
pub use pmc::{PMC_CHUNK, ParsePmcAreaError, PmcArea, PmcType};
pub use position::{AxisPosition, Unit};
pub use program::ProgramEntry;
pub use shopfloor::{GroupTool, OperatorMessage, ToolLifeGroup};
pub use status::{AlarmState, Emergency, Execution, Mode, Motion, Run, Status, SysInfo};
