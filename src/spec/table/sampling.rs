//! Servo data sampling, cnc_sdt* (FANUC's 32-bit x86 build 1.0.0 exports
//! them, its x86-64 build does not; learnt from the 32-bit build,
//! docs/protocol/position.md "Servo data sampling").

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_sdtclrchnl",
        learnt: Some(&[]),
        doc: "Clears the servo data sampling channels (sends `(1,0x0134)`, nothing else; FANUC's 32-bit library only).",
        forms: &[every_class(cmd::SDTCLRCHNL, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_sdtstartsmpl",
        learnt: Some(&[]),
        doc: "Starts sampling the servo data channels: `type` (as an unsigned 16-bit number) and `cycle` are sent as the request's two words, unchecked (FANUC's 32-bit library only).",
        params: &[Param::ShortAs("type", U16), Param::Long("cycle")],
        forms: &[every_class(
            cmd::SDTSTARTSMPL,
            &[Word::Arg(0), Word::Arg(1)],
        )],
        // The cases (tools/oracle/cases.rs) sweep both words.
        ..COMMAND
    },
    Func {
        name: "cnc_sdtcancelsmpl",
        learnt: Some(&[]),
        doc: "Cancels the servo data sampling (sends `(1,0x0136)`; FANUC's 32-bit library only).",
        forms: &[every_class(cmd::SDTCANCELSMPL, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_sdtendsmpl",
        learnt: Some(&[]),
        doc: "Ends the servo data sampling (sends `(1,0x0138)`; FANUC's 32-bit library only).",
        forms: &[every_class(cmd::SDTENDSMPL, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_sdtread1shot",
        learnt: Some(&[
            "written past the pointee: argument 0: 16 bytes written into a 2-byte pointee",
        ]),
        doc: "Reads the current value of each servo data sampling channel: always 8 `unsigned short`s (16 bytes) written, the ones the answer does not hold as 0 (FANUC's 32-bit library only).",
        params: &[Param::Out("data", "unsigned short")],
        forms: &[every_class(cmd::SDTREAD1SHOT, &[])],
        reply: &[Field {
            n: 8,
            ..to(U16, "", U16)
        }],
        ..COMMAND
    },
];
