//! Every function described by data alone (src/spec/types.rs): one entry
//! each. build.rs exports them (src/ffi/described.rs), the codec and the
//! simulator read them through `crate::spec::FUNCS`, the oracle generates
//! their probe words and cases from them.
//!
//! Compiled into build.rs too: plain data only.

use super::types::Int::*;
use super::types::*;

pub const FUNCS: &[Func] = &[
    // --- program ---
    Func {
        name: "cnc_rdprgnum",
        doc: "Reads the running and main program numbers (the low 16 bits of each, as FANUC's library stores them in the default ODBPRO's shorts).",
        params: &[Param::Out("prgnum", "ODBPRO")],
        checks: &[],
        forms: &[every_class(0x001c, &[])],
        reply: &[to(I32, "data", I16), to(I32, "mdata", I16)],
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdseqnum",
        doc: "Reads the sequence number of the block being executed.",
        params: &[Param::Out("seqnum", "ODBSEQ")],
        checks: &[],
        forms: &[every_class(0x001d, &[])],
        reply: &[to(I32, "data", I32)],
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdblkcount",
        doc: "Reads the number of blocks executed (4 bytes written into the `long`).",
        params: &[Param::Out("prog_bc", "long")],
        checks: &[],
        forms: &[every_class(0x0035, &[])],
        reply: &[to(I32, "", I32)],
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdactpt",
        doc: "Reads the execution pointer: program number and block number (4 bytes written into each `long`).",
        params: &[Param::Out("prog_no", "long"), Param::Out("blk_no", "long")],
        checks: &[],
        forms: &[every_class(0x0162, &[])],
        reply: &[to_out(0, I32, "", I32), to_out(1, I32, "", I32)],
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdtimer",
        doc: "Reads a timer (`type` 0 power-on, 1 operating, 2 cutting, 3 cycle, 4 free) as minutes and milliseconds.",
        params: &[Param::Short("r#type"), Param::Out("time", "IODBTIME")],
        checks: &[],
        forms: &[every_class(0x0120, &[Word::Arg(0)])],
        reply: &[to(I32, "minute", I32), to(I32, "msec", I32)],
        short: Short::Zeros,
        dims: &["0|1|2|3|4|-1|5"],
    },
    // --- feed and speed ---
    Func {
        name: "cnc_actf",
        doc: "Reads the actual feed rate (F).",
        params: &[Param::Out("actualfeed", "ODBACT")],
        checks: &[],
        forms: &[every_class(0x0024, &[])],
        reply: &[to(I32, "data", I32)],
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_acts",
        doc: "Reads the actual spindle speed (S).",
        params: &[Param::Out("actualspindle", "ODBACT")],
        checks: &[],
        forms: &[every_class(0x0025, &[])],
        reply: &[to(I32, "data", I32)],
        short: Short::Zeros,
        dims: &[],
    },
    // --- offsets, macros ---
    Func {
        name: "cnc_rdtofsinfo",
        doc: "Reads the tool offset memory type and the number of offsets.",
        params: &[Param::Out("tlinf", "ODBTLINF")],
        checks: &[],
        forms: &[every_class(0x000a, &[])],
        reply: &[skip(I16), to(I16, "use_no", I16), to(I16, "ofs_type", I16)],
        short: Short::Error,
        dims: &[],
    },
    Func {
        name: "cnc_rdzofsinfo",
        doc: "Reads the number of work zero offsets.",
        params: &[Param::Out("ofs_no", "short")],
        checks: &[],
        forms: &[every_class(0x000d, &[])],
        reply: &[to(I32, "", I16)],
        short: Short::Error,
        dims: &[],
    },
    Func {
        name: "cnc_rdmacroinfo",
        doc: "Reads how many common variables the CNC has: `use_no1` (#100..), `use_no2` (#500..).",
        params: &[Param::Out("buf", "ODBMVINF")],
        checks: &[],
        forms: &[every_class(0x0017, &[])],
        reply: &[to(I32, "use_no1", I16), to(I32, "use_no2", I16)],
        short: Short::Error,
        dims: &[],
    },
    // --- tool life ---
    Func {
        name: "cnc_toolnum",
        doc: "Reads the tool number of the `tuse_num`-th tool of tool-life group `grp_num`.",
        params: &[
            Param::Short("grp_num"),
            Param::Short("tuse_num"),
            Param::Out("toolnum", "ODBTLIFE4"),
        ],
        checks: &[],
        forms: &[every_class(
            0x004d,
            &[Word::Arg(0), Word::Arg(1), Word::Arg(1)],
        )],
        reply: &[
            to(I32, "datano", I16),
            to(I32, "r#type", I16),
            to(I32, "data", I32),
        ],
        short: Short::Error,
        dims: &["1|0|-1|2|9999", "0|1|-1|2|99"],
    },
    Func {
        name: "cnc_rdntool",
        doc: "Reads the number of tools in tool-life group `grp_num`.",
        params: &[Param::Short("grp_num"), Param::Out("tool", "ODBTLIFE3")],
        checks: &[],
        forms: &[every_class(0x008b, &[Word::Arg(0), Word::Arg(0)])],
        reply: &[to(I32, "datano", I16), to(I32, "data", I32)],
        short: Short::Error,
        dims: &["1|0|-1|2|9999"],
    },
    Func {
        name: "cnc_rdlife",
        doc: "Reads the tool life of tool group `number` (`data`; `dummy` untouched; `datano` the group number the CNC answered).",
        params: &[Param::Short("number"), Param::Out("life", "ODBTLIFE3")],
        checks: &[],
        forms: &[every_class(0x008b, &[Word::Arg(0), Word::Arg(0)])],
        // Group, then tools, life and counter as value records (value, base, exponent).
        reply: &[
            to(I32, "datano", I16),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
            skip(I32),
            skip(I32),
            skip(I32),
        ],
        short: Short::Error,
        dims: &["1|0|-1|2|9999"],
    },
    Func {
        name: "cnc_rdcount",
        doc: "Reads the tool life counter of tool group `number`.",
        params: &[Param::Short("number"), Param::Out("count", "ODBTLIFE3")],
        checks: &[],
        forms: &[every_class(0x008b, &[Word::Arg(0), Word::Arg(0)])],
        reply: &[
            to(I32, "datano", I16),
            skip(I32),
            skip(I32),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
            skip(I32),
        ],
        short: Short::Error,
        dims: &["1|0|-1|2|9999"],
    },
];
