//! The setting data functions (the CNC's setting parameters,
//! docs/protocol/param.md "Setting data").

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// The setting data read's and write's forms on each class.
const fn set_form(classes: Classes, cmd: u16, words: &'static [Word]) -> Form {
    Form {
        classes,
        class: cmd::CLASS_CNC,
        cmd,
        words,
    }
}

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdsetnum",
        learnt: Some(&[]),
        doc: "Reads the smallest and largest setting data numbers and how many setting data there are.",
        params: &[Param::Out("setnum", "ODBSETNUM")],
        forms: &[every_class(cmd::RDSETNUM, &[])],
        // Three 32-bit words; their low halves are the numbers.
        reply: &[
            skip(I16),
            to(U16, "set_min", U16),
            skip(I16),
            to(U16, "set_max", U16),
            skip(I16),
            to(U16, "total_no", U16),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_rdset",
        learnt: Some(&[]),
        doc: "Reads one setting data item into IODBPSD, as cnc_rdparam reads a parameter: `length` must hold 4 + the values answered (one, or one per axis for an answer with a negative axis word).",
        params: &[
            Param::Short("number"),
            Param::Short("axis"),
            Param::Short("length"),
            Param::Out("param", "IODBPSD"),
        ],
        forms: &[
            set_form(
                Classes::S30,
                cmd::RDSET,
                &[Word::Arg(0), Word::Arg(0), Word::Arg(1)],
            ),
            set_form(
                Classes::S15,
                cmd::RDSET,
                &[Word::Arg(0), Word::Arg(0), Word::Arg(1)],
            ),
            set_form(
                Classes::S16Not15,
                cmd::RDSET16,
                &[Word::Arg(0), Word::Arg(0), Word::Arg(1)],
            ),
        ],
        block: Some(Block {
            length: 2,
            attributes: None,
            range: None,
            diag: false,
        }),
        // An empty or short answer: FANUC's library reads the rest from
        // its buffer, which held the request (datano = the axis asked).
        short: Short::Request,
        dims: &[
            "0|1|2|3|6|20|99|100|-1|9999",
            "0|1|-1|2|33|-2",
            "8|4|5|6|0|-1|12|132|260",
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_wrset",
        learnt: Some(&[]),
        doc: "Writes one setting data item from IODBPSD, as cnc_wrparam writes a parameter: its attributes read first, `length` must be 4 + the size of its values.",
        params: &[Param::Short("length"), Param::In("param", "IODBPSD")],
        forms: &[
            set_form(Classes::S30, cmd::WRSET, &[]),
            set_form(Classes::S15, cmd::WRSET, &[]),
            set_form(Classes::S16Not15, cmd::WRSET16, &[]),
        ],
        block: Some(super::param::WRITE),
        ..COMMAND
    },
    Func {
        name: "cnc_rdsetr",
        learnt: Some(&[]),
        doc: "Reads the setting data `*s_number..=*e_number` into `param` as packed records, as cnc_rdparar reads parameters: i16 number, i16 `(type << 8) | (axis & 0xff)`, the values, each record padded to a multiple of 4; asks again from the last number + 1 until `*e_number`. Then `*s_number` is the first number read, `*e_number` the last, `*length` (in: the buffer's size) the bytes used.",
        params: &[
            Param::Io("s_number"),
            Param::Short("axis"),
            Param::Io("e_number"),
            Param::Io("length"),
            Param::Out("param", "void"),
        ],
        checks: &[ordered(0, 2)],
        forms: &[
            set_form(
                Classes::S30,
                cmd::RDSET,
                &[Word::Arg(0), Word::Arg(2), Word::Arg(1)],
            ),
            set_form(
                Classes::S15,
                cmd::RDSET,
                &[Word::Arg(0), Word::Arg(2), Word::Arg(1)],
            ),
            set_form(
                Classes::S16Not15,
                cmd::RDSET16,
                &[Word::Arg(0), Word::Arg(2), Word::Arg(1)],
            ),
        ],
        block: Some(Block {
            length: 3,
            attributes: None,
            range: Some(Range { s: 0, e: 2 }),
            diag: false,
        }),
        dims: &[
            "0|20|1|-1|99|100",
            "0|-1|1|2",
            "99|20|0|1|100|9999",
            "100|8|4|0|-1|1000|4096",
        ],
        ..COMMAND
    },
];
