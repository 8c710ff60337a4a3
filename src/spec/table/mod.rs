//! Every function described by data alone (src/spec/types.rs): one entry
//! each. build.rs exports them (src/ffi/described/), the codec and the
//! simulator read them through `crate::spec::FUNCS`, the oracle generates
//! their probe words and cases from them.
//!
//! Compiled into build.rs too: plain data only (`crate::ew` is src/ew.rs
//! there as here).

use super::types::*;

/// The functions no Ethernet library of FANUC's has (not [`FUNCS`]).
pub mod absent;
mod alarm;
mod axes;
/// The entries others start from (`..COMMAND`).
pub mod base;
mod feed;
pub mod folder;
pub mod history;
pub mod info;
pub mod macros;
pub mod magazine;
mod maintenance;
pub mod memory;
mod names;
pub mod offset;
pub mod offset_life;
mod offset_range;
pub mod operation;
mod param;
pub mod pmc;
mod pmc_data;
mod position;
pub mod program;
mod sampling;
mod screen;
pub mod servo;
mod setting;
mod signals;
pub mod status;
pub mod tool_group;
pub mod tool_life;

/// The areas' entries, in this order.
const AREAS: &[&[Func]] = &[
    operation::FUNCS,
    program::FUNCS,
    folder::FUNCS,
    feed::FUNCS,
    offset::FUNCS,
    macros::FUNCS,
    info::FUNCS,
    servo::FUNCS,
    position::FUNCS,
    offset_life::FUNCS,
    pmc::FUNCS,
    pmc_data::FUNCS,
    memory::FUNCS,
    history::FUNCS,
    tool_life::FUNCS,
    tool_group::FUNCS,
    offset_range::FUNCS,
    magazine::FUNCS,
    maintenance::FUNCS,
    names::FUNCS,
    param::FUNCS,
    setting::FUNCS,
    sampling::FUNCS,
    status::FUNCS,
    screen::FUNCS,
    axes::FUNCS,
    signals::FUNCS,
    alarm::FUNCS,
];

const LEN: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < AREAS.len() {
        n += AREAS[i].len();
        i += 1;
    }
    n
};

// One static copy: FUNCS refers to it.
static ALL: [Func; LEN] = {
    let mut all = [base::COMMAND; LEN];
    let (mut n, mut i) = (0, 0);
    while i < AREAS.len() {
        let mut j = 0;
        while j < AREAS[i].len() {
            all[n] = kept(AREAS[i][j]);
            n += 1;
            j += 1;
        }
        i += 1;
    }
    all
};

/// Every described function, area by area.
pub const FUNCS: &[Func] = &ALL;

/// Entry `f` as the static table keeps it. The installed library (`make`'s
/// build, `--cfg fwlib32_slim`: build.rs sets it when `FWLIB32_SLIM` is 1)
/// keeps only what a call reads: its [`Func::doc`], [`Func::dims`] and
/// [`Func::learnt`] (read by build.rs, the oracle and COMPATIBILITY.md,
/// never by a call: tests/artifacts/size.rs checks) are left out, so their
/// text and pointers are not in the library (about 30 KB). The entries
/// above are constants: only what this static holds is in the binary.
const fn kept(f: Func) -> Func {
    if cfg!(fwlib32_slim) {
        Func {
            doc: "",
            dims: &[],
            learnt: None,
            ..f
        }
    } else {
        f
    }
}
