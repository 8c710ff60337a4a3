//! Functions FANUC's header declares but none of its Ethernet libraries
//! implements: neither its Linux libfwlib32.so nor its Windows fwlibe1.dll
//! has them (HSSB-only functions, other machine families' and options').
//! They are exported so that programs calling them compile against our
//! header and link, and they answer as FANUC's Windows library does on an
//! Ethernet handle: `EW_VERSION` (-7), without traffic, writing nothing.
//! A bad handle is `EW_HANDLE` (-8) first, as for every call.
//!
//! A function is one row: its name and its C parameters after
//! `unsigned short FlibHndl`, as FANUC's header declares them (a
//! parameter's name where the header or FANUC's documentation gives one;
//! build.rs names the others `a`, `b`, ... in order). build.rs writes each
//! export from its row (`crate::ffi::absent`), and so its declaration in
//! fwlib32.h. Functions taking a struct or a `double` by value are not
//! rows: tests/bad_input.rs calls every declared function with integer
//! arguments.

mod other;
mod read;
mod write;

/// Every row: the reads, the writes, the others.
pub const ROWS: &[&[(&str, &str)]] = &[read::ROWS, write::ROWS, other::ROWS];
