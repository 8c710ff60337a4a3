//! Every function described by data alone (src/spec/types.rs): one entry
//! each. build.rs exports them (src/ffi/described.rs), the codec and the
//! simulator read them through `crate::spec::FUNCS`, the oracle generates
//! their probe words and cases from them.
//!
//! Compiled into build.rs too: plain data only.

use super::types::Int::*;
use super::types::*;

/// A command: no argument, no answer.
const COMMAND: Func = Func {
    name: "",
    doc: "",
    params: &[],
    checks: &[],
    forms: &[],
    reply: &[],
    records: None,
    short: Short::Zeros,
    dims: &[],
};

/// A servo figure of each axis into `long data[]`: the value word of each
/// 0x0056 value record (value, then base and exponent).
const SERVO_LONGS: Func = Func {
    name: "",
    doc: "",
    params: &[Param::Out("data", "long")],
    checks: &[],
    forms: &[],
    reply: &[],
    records: Some(Records {
        fields: &[to(I32, "", I32), skip(I32)],
        out: 0,
        to: "",
        elem: "long",
        max: 32,
        count: None,
        room: None,
    }),
    short: Short::Zeros,
    dims: &[],
};

pub const FUNCS: &[Func] = &[
    // --- operation ---
    Func {
        name: "cnc_start",
        doc: "Cycle start: the CNC runs the selected main program (MEMORY mode, no alarm; else EW_REJECT).",
        forms: &[every_class(0x0001, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset",
        doc: "Resets the CNC: the running program stops, reset-clearable alarms are cleared.",
        forms: &[every_class(0x0002, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset2",
        doc: "Resets the CNC as cnc_reset does (needs the FOCAS option, else EW_NOOPT).",
        checks: &[NEEDS_OPTION],
        forms: &[every_class(0x02c5, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clralm",
        doc: "Clears the CNC's active alarms of type `id` (cnc_rdalmmsg's types).",
        params: &[Param::Short("id")],
        forms: &[every_class(0x0087, &[Word::Arg(0)])],
        dims: &["3|0|1|2|-1|100|32767"],
        ..COMMAND
    },
    // --- program ---
    Func {
        name: "cnc_rdprgnum",
        doc: "Reads the running and main program numbers (the low 16 bits of each, as FANUC's library stores them in the default ODBPRO's shorts).",
        params: &[Param::Out("prgnum", "ODBPRO")],
        checks: &[],
        forms: &[every_class(0x001c, &[])],
        reply: &[to(I32, "data", I16), to(I32, "mdata", I16)],
        records: None,
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
        records: None,
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
        records: None,
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
        records: None,
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdtimer",
        doc: "Reads a timer (`type` 0 power-on, 1 operating, 2 cutting, 3 cycle, 4 free) as minutes and milliseconds.",
        params: &[Param::Short("type"), Param::Out("time", "IODBTIME")],
        checks: &[],
        forms: &[every_class(0x0120, &[Word::Arg(0)])],
        reply: &[to(I32, "minute", I32), to(I32, "msec", I32)],
        records: None,
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
        records: None,
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
        records: None,
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
        records: None,
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
        records: None,
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
        records: None,
        short: Short::Error,
        dims: &[],
    },
    // --- machine information ---
    Func {
        name: "cnc_rdproctime",
        doc: "Reads the machining times of the last programs run.",
        params: &[Param::Out("proc_time", "ODBPTIME")],
        checks: &[],
        forms: &[every_class(0x0075, &[])],
        reply: &[],
        // Whole 12-byte records, their number written to `num`.
        records: Some(Records {
            fields: &[
                to(I32, "prg_no", I32),
                to(I16, "hour", I16),
                to(I16, "minute", I8),
                to(I16, "second", I8),
                skip(I16),
            ],
            out: 0,
            to: "data",
            elem: "ODBPTIME_DATA",
            max: 10,
            count: Some("num"),
            room: None,
        }),
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdetherinfo",
        doc: "Reads the Ethernet board's type and device.",
        params: &[Param::Out("type", "short"), Param::Out("device", "short")],
        checks: &[],
        forms: &[every_class(0x0159, &[])],
        reply: &[to_out(0, I16, "", I16), to_out(1, I16, "", I16)],
        records: None,
        short: Short::Zeros,
        dims: &[],
    },
    // --- servo ---
    Func {
        name: "cnc_rdloopgain",
        doc: "Reads the servo loop gain of each axis (4 bytes written per `long`).",
        forms: &[every_class(0x0056, &[Word::Const(0)])],
        ..SERVO_LONGS
    },
    Func {
        name: "cnc_rdsrvspeed",
        doc: "Reads the actual servo motor speed of each axis (4 bytes written per `long`).",
        forms: &[every_class(0x0056, &[Word::Const(2)])],
        ..SERVO_LONGS
    },
    Func {
        name: "cnc_rdcurrent",
        doc: "Reads the actual servo current of each axis.",
        params: &[Param::Out("data", "short")],
        checks: &[],
        forms: &[every_class(0x0056, &[Word::Const(1)])],
        reply: &[],
        records: Some(Records {
            fields: &[to(I32, "", I16), skip(I32)],
            out: 0,
            to: "",
            elem: "short",
            max: 32,
            count: None,
            room: None,
        }),
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdspdlalm",
        doc: "Reads the alarm state of each spindle, one byte per spindle (at most 8).",
        params: &[Param::Out("data", "char")],
        checks: &[],
        forms: &[every_class(0x005a, &[])],
        reply: &[],
        // The low byte of each i16, as many as the answer holds.
        records: Some(Records {
            fields: &[to(I16, "", I8)],
            out: 0,
            to: "",
            elem: "char",
            max: 8,
            count: None,
            room: None,
        }),
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdpitchinfo",
        doc: "Reads the number of pitch error compensation points.",
        params: &[Param::Out("datano", "short")],
        checks: &[],
        forms: &[every_class(0x0014, &[])],
        reply: &[to(I32, "", I16)],
        records: None,
        short: Short::Zeros,
        dims: &[],
    },
    // --- offsets and tool life ---
    Func {
        name: "cnc_rdtofsinfo2",
        doc: "Reads the tool offset memory type, the number of offsets and which offsets are enabled.",
        params: &[Param::Out("tlinf", "ODBTLINF2")],
        checks: &[],
        forms: &[every_class(0x000a, &[])],
        // The 0x000a answer of cnc_rdtofsinfo, with the enable word after it.
        reply: &[
            skip(I16),
            to(I16, "use_no", I16),
            to(I16, "ofs_type", I16),
            to(I16, "ofs_enable", I16),
        ],
        records: None,
        short: Short::Zeros,
        dims: &[],
    },
    Func {
        name: "cnc_rdngrp",
        doc: "Reads the number of tool life groups.",
        params: &[Param::Out("grp", "ODBTLIFE2")],
        checks: &[],
        forms: &[every_class(0x004a, &[])],
        reply: &[to(I32, "data", I32)],
        records: None,
        short: Short::Zeros,
        dims: &[],
    },
    // --- PMC units ---
    Func {
        name: "pmc_get_number_of_pmc",
        doc: "Reads how many PMC units the CNC has (4 bytes written into the `long`).",
        params: &[Param::Out("piNum", "long")],
        checks: &[],
        forms: &[pmc(0x800e, &[])],
        reply: &[to(I32, "", I32)],
        records: None,
        short: Short::Zeros,
        dims: &[],
    },
    // --- programs in memory ---
    Func {
        name: "cnc_search",
        doc: "Selects program `prog_no` as the main program.",
        params: &[Param::Short("prog_no")],
        forms: &[every_class(0x0003, &[Word::Arg(0)])],
        dims: &["100|1234|0|-1|7|9999|10000|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_delete",
        doc: "Deletes program `prog_no`.",
        params: &[Param::Short("prog_no")],
        forms: &[every_class(0x0005, &[Word::Arg(0)])],
        dims: &["100|1234|0|-1|7|9999|10000|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_delall",
        doc: "Deletes every program (those protected or in use stay).",
        forms: &[every_class(0x0004, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_copyprog",
        doc: "Copies program `top_prog` to a new program `bottom_prog`.",
        params: &[Param::Long("top_prog"), Param::Long("bottom_prog")],
        forms: &[every_class(0x01c6, &[Word::Arg(0), Word::Arg(1)])],
        dims: &[
            "100|0|-1|7|1234|99999999|100000000",
            "200|0|-1|100|1234|9999|10000|99999999|100000000",
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_renameprog",
        doc: "Renumbers program `old_num` as `new_num`.",
        params: &[Param::Long("old_num"), Param::Long("new_num")],
        forms: &[every_class(0x01c7, &[Word::Arg(0), Word::Arg(1)])],
        dims: &[
            "100|0|-1|7|1234|99999999|100000000",
            "200|0|-1|100|1234|9999|10000|99999999|100000000",
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_condense",
        doc: "Condenses program memory (`type` 0, program `prog_num`).",
        params: &[Param::Short("type"), Param::Long("prog_num")],
        forms: &[every_class(0x01c8, &[Word::Arg(0), Word::Arg(1)])],
        dims: &["0|1|-1|2", "100|0|-1|1234|7"],
        ..COMMAND
    },
    Func {
        name: "cnc_wrmdipntr",
        doc: "Sets the execution pointer of MDI operation.",
        params: &[Param::Long("exe_pntr")],
        forms: &[every_class(0x0039, &[Word::Arg(0)])],
        dims: &["0|1|-1|10|100|1000"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdmdipntr",
        doc: "Reads the execution pointers of MDI operation.",
        params: &[Param::Out("mdipntr", "ODBMDIP")],
        checks: &[],
        forms: &[every_class(0x0038, &[])],
        reply: &[
            to(I32, "mdiprog", I16),
            to(I32, "mdipntr", I32),
            to(I32, "crntprog", I16),
            to(I32, "crntpntr", I32),
        ],
        records: None,
        short: Short::Zeros,
        dims: &[],
    },
    // --- operation and operator-message histories ---
    Func {
        name: "cnc_rdophisno",
        doc: "Reads the number of operation history entries.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(0x0069, &[])],
        reply: &[to(I32, "", U16)],
        ..COMMAND
    },
    Func {
        name: "cnc_startophis",
        doc: "Starts recording the operation history.",
        forms: &[every_class(0x0068, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_stopophis",
        doc: "Stops recording the operation history.",
        forms: &[every_class(0x0067, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clearophis",
        doc: "Clears the operation history.",
        params: &[Param::Short("type")],
        forms: &[every_class(0x006d, &[Word::Arg(0)])],
        dims: &["0|1|2|-1|3"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdomhisno",
        doc: "Reads the number of operator message history entries.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(0x01b4, &[])],
        reply: &[to(U16, "", U16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdomhisinfo",
        doc: "Reads the operator message history's size: most entries, entries held, characters per message.",
        params: &[Param::Out("ominfo", "ODBOMIF")],
        forms: &[every_class(0x0072, &[])],
        reply: &[
            to(I32, "om_max", U16),
            to(I32, "om_sum", U16),
            to(I32, "om_char", U16),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_startomhis",
        doc: "Starts recording the operator message history.",
        forms: &[every_class(0x0071, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_stopomhis",
        doc: "Stops recording the operator message history.",
        forms: &[every_class(0x0070, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clearomhis",
        doc: "Clears the operator message history.",
        // The 30i class names the history to clear (2); the 16i sends 0.
        forms: &[
            Form {
                classes: Classes::S30,
                class: 1,
                cmd: 0x0074,
                words: &[Word::Const(2)],
            },
            every_class(0x0074, &[]),
        ],
        ..COMMAND
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
            to(I32, "type", I16),
            to(I32, "data", I32),
        ],
        records: None,
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
        records: None,
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
        records: None,
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
        records: None,
        short: Short::Error,
        dims: &["1|0|-1|2|9999"],
    },
    Func {
        name: "cnc_rdgrpid2",
        doc: "Reads the tool life group of tool number `tno` (`type` = `tno`, `dummy` untouched).",
        params: &[Param::Long("tno"), Param::Out("tlife", "ODBTLIFE5")],
        checks: &[],
        forms: &[every_class(0x0047, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I32), to(I32, "data", I32)],
        records: None,
        short: Short::Zeros,
        dims: &["11|0|-1|1|5|9999|99999999"],
    },
    Func {
        name: "cnc_rdwkcdshft",
        doc: "Reads the work coordinate shift of axis `axis` (-1: all axes) into `data` (`type` = `axis`; `length` must hold 4 bytes and the axes, else EW_LENGTH after the reply).",
        params: &[
            Param::Short("axis"),
            Param::Short("length"),
            Param::Out("shift", "IODBWCSF"),
        ],
        checks: &[Check {
            arg: 0,
            lo: -32768,
            hi: 32,
            code: 4,
        }],
        forms: &[every_class(0x0063, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16)],
        records: Some(Records {
            fields: &[to(I32, "", I32), skip(I32)],
            out: 0,
            to: "data",
            elem: "long",
            max: 32,
            count: None,
            room: Some(1),
        }),
        short: Short::Zeros,
        dims: &["1|-1|0|2|3|4|32|33|-2", "8|4|7|12|0|-1|132|136"],
    },
    // Base cases on group 2 (cnc_rdlife and others read group 1).
    Func {
        name: "cnc_deltlifedt",
        doc: "Deletes the `tuse_num`-th tool of tool life group `grpno`.",
        params: &[Param::Short("grpno"), Param::Short("tuse_num")],
        forms: &[every_class(0x0055, &[Word::Arg(0), Word::Arg(1)])],
        dims: &["2|0|-1|1|9999", "1|0|-1|2|99"],
        ..COMMAND
    },
    Func {
        name: "cnc_deltlifegrp",
        doc: "Deletes tool life group `grpno`.",
        params: &[Param::Short("grpno")],
        forms: &[every_class(0x0053, &[Word::Arg(0)])],
        dims: &["2|0|-1|1|9999|32767"],
        ..COMMAND
    },
];
