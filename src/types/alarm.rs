//! Alarms, alarm messages, operator messages and the alarm history.

#[allow(unused_imports)]
use super::{LONG, ULONG};
