//! The alarm status (docs/protocol/alarm.md): the 32 bits of `(1,0x001a)`,
//! which cnc_rddynamic reads too; the alarm history's length.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_alarm",
        doc: "Reads the alarm status bits; `data` = their low 16 bits.",
        params: &[Param::Out("alarm", "ODBALM")],
        forms: &[every_class(cmd::ALARM, &[])],
        reply: &[to(U32, "data", I16)],
        ..super::base::COMMAND
    },
    Func {
        name: "cnc_alarm2",
        doc: "Reads the alarm status bits (32 bits, 4 bytes written into the `long`).",
        params: &[Param::Out("alarm", "long")],
        forms: &[every_class(cmd::ALARM, &[])],
        reply: &[to(U32, "", U32)],
        ..super::base::COMMAND
    },
    Func {
        name: "cnc_rdalmhisno",
        doc: "Reads the number of alarm history entries: the low 16 bits of the CNC's 32-bit count, as FANUC's library writes them.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(cmd::RDALMHISNO, &[])],
        reply: &[to(I32, "", U16)],
        ..super::base::COMMAND
    },
    Func {
        name: "cnc_rdalmhisno3",
        learnt: Some(&[]),
        doc: "Reads the number of alarm history entries (the 30i's history): the low 16 bits of the CNC's 32-bit count.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(cmd::RDALMHISNO3, &[])],
        reply: &[to(I32, "", U16)],
        ..super::base::COMMAND
    },
];
