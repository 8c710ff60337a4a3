//! A row of the simulator's dispatch: the answer of one request command.
//! Each area file (src/sim/status.rs, position.rs ...) declares its rows
//! in a `ROUTES` slice; src/sim/dispatch.rs looks every subpacket up by
//! its (class, command) among all of them.

use super::Machine;
use super::service::Reply;
use crate::proto::packet::{CLASS_CNC, CLASS_PMC, ReqSub};
use crate::spec::Func;

/// An answer written by hand: the reply's bytes for the request (a layout
/// of src/proto). A command several functions share has one answer, which
/// tells them apart by the request's argument words.
pub type Bytes = fn(&mut Machine, &ReqSub) -> Reply<Vec<u8>>;

/// The answer of a function described as data (crate::spec): the reply's
/// integers in the order of its layout, which the dispatch encodes
/// through that layout (`crate::proto::described::encode`), the one the
/// client decodes with.
pub type Values = fn(&mut Machine, &Asked<'_>) -> Reply<Vec<i64>>;

/// A described function's request, as its answer reads it.
pub struct Asked<'a> {
    /// The function whose layout the answer fills (where functions share a
    /// command, the one with the longest reply).
    pub f: &'static Func,
    /// The subpacket's path word.
    pub path: u16,
    /// The caller's number arguments the request carried (then the input
    /// members its words carry, `Func::inputs`).
    pub args: &'a [i32],
    /// The request's five argument words as sent (where functions sharing
    /// a command differ by a constant word: cnc_rdposerrs's 0x0058).
    pub words: [i32; 5],
    /// A write's payload integers (`Func::payload`'s fields, record after
    /// record; whole records only).
    pub payload: &'a [i64],
    /// The request's payload bytes as sent (the text parameters' fields
    /// first, [`Asked::text`]).
    pub bytes: &'a [u8],
}

impl Asked<'_> {
    /// Number argument `i` (0 if the function has fewer).
    pub fn arg(&self, i: usize) -> i32 {
        self.args.get(i).copied().unwrap_or(0)
    }
    /// Text parameter `k`'s field (`Func::texts`) up to its NUL ("" if the
    /// request is shorter).
    pub fn text(&self, k: usize) -> String {
        let at: usize = self.f.texts().take(k).map(|(_, n)| n).sum();
        let n = self.f.texts().nth(k).map_or(0, |(_, n)| n);
        let b = self.bytes.get(at..).unwrap_or_default();
        let b = &b[..n.min(b.len())];
        let end = b.iter().position(|&c| c == 0).unwrap_or(b.len());
        String::from_utf8_lossy(&b[..end]).into_owned()
    }
}

/// How a command is answered.
#[derive(Clone, Copy)]
pub enum Answer {
    Bytes(Bytes),
    Values(Values),
}

/// One row: the subpacket class and command, and its answer.
#[derive(Clone, Copy)]
pub struct Route {
    pub class: u16,
    pub cmd: u16,
    pub answer: Answer,
}

impl Route {
    /// A CNC command (class 1) answered by hand.
    pub const fn cnc(cmd: u16, f: Bytes) -> Route {
        Route {
            class: CLASS_CNC,
            cmd,
            answer: Answer::Bytes(f),
        }
    }
    /// A PMC command (class 2) answered by hand.
    pub const fn pmc(cmd: u16, f: Bytes) -> Route {
        Route {
            class: CLASS_PMC,
            cmd,
            answer: Answer::Bytes(f),
        }
    }
    /// A CNC command of described functions.
    pub const fn table(cmd: u16, f: Values) -> Route {
        Route {
            class: CLASS_CNC,
            cmd,
            answer: Answer::Values(f),
        }
    }
    /// A PMC command of described functions.
    pub const fn pmc_table(cmd: u16, f: Values) -> Route {
        Route {
            class: CLASS_PMC,
            cmd,
            answer: Answer::Values(f),
        }
    }
    /// The row's key, as the dispatch sorts and finds it.
    pub const fn key(&self) -> (u16, u16) {
        (self.class, self.cmd)
    }
}

/// A typed reply's bytes (`crate::proto::wire::Wire`).
pub fn enc<T: crate::proto::wire::Wire>(r: Reply<T>) -> Reply<Vec<u8>> {
    r.map(|v| v.to_bytes())
}

/// The empty reply of a write that succeeded.
pub fn done(r: Reply<()>) -> Reply<Vec<u8>> {
    r.map(|()| Vec::new())
}

/// The empty values of a described command that succeeded.
pub fn none(r: Reply<()>) -> Reply<Vec<i64>> {
    r.map(|()| Vec::new())
}
