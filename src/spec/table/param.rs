//! Parameters and diagnosis data as typed parameter blocks ([`Block`]:
//! cnc_rdparam, cnc_diagnoss, cnc_wrparam, the range read cnc_rdparar) and
//! their number ranges (docs/protocol/param.md). Their attributes and the
//! packed write cnc_wrparas are hand-written (src/ffi/paraminfo.rs,
//! src/ffi/param.rs).

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// A read's or write's forms: the 16i class asks with `c16`, the 30i
/// class and a Series 15 with `c30` (first match wins).
const fn forms(c16: u16, c30: u16, words: &'static [Word]) -> [Form; 2] {
    [
        Form {
            classes: Classes::S16Not15,
            class: cmd::CLASS_CNC,
            cmd: c16,
            words,
        },
        Form {
            classes: Classes::All,
            class: cmd::CLASS_CNC,
            cmd: c30,
            words,
        },
    ]
}

/// One item `[n, n, axis]`.
const ONE: &[Word] = &[Word::Arg(0), Word::Arg(0), Word::Arg(1)];

/// One item read into IODBPSD / ODBDGN (`length` the third number).
const fn read(diag: bool) -> Block {
    Block {
        length: 2,
        attributes: None,
        range: None,
        diag,
    }
}

/// The three number parameters of a one-item read.
const READ_PARAMS: [Param; 3] = [
    Param::Short("number"),
    Param::Short("axis"),
    Param::Short("length"),
];

/// A number range: three 32-bit words whose low halves are the numbers.
const fn num_range(min: &'static str, max: &'static str) -> [Field; 6] {
    [
        skip(I16),
        to(U16, min, U16),
        skip(I16),
        to(U16, max, U16),
        skip(I16),
        to(U16, "total_no", U16),
    ]
}

const PARAM_FORMS: [Form; 2] = forms(cmd::RDPARAM16, cmd::RDPARAM, ONE);
const DIAG_FORMS: [Form; 2] = forms(cmd::DIAGNOSS16, cmd::DIAGNOSS, ONE);

/// A typed parameter block written (cnc_wrparam, cnc_wrset): its
/// attributes read first, except on Series 15.
pub(super) const WRITE: Block = Block {
    length: 0,
    attributes: Some(Classes::Not15),
    range: None,
    diag: false,
};

/// cnc_diagnoss, and cnc_rddiag its alias.
const DIAGNOSS: Func = Func {
    name: "cnc_diagnoss",
    doc: "Reads CNC diagnosis data, as cnc_rdparam reads parameters (sizes: byte and bit 1, word 2, 2-word 4, real 8).",
    params: &[
        READ_PARAMS[0],
        READ_PARAMS[1],
        READ_PARAMS[2],
        Param::Out("diag", "ODBDGN"),
    ],
    forms: &DIAG_FORMS,
    block: Some(read(true)),
    short: Short::Request,
    ..COMMAND
};

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdparam",
        doc: "Reads a CNC parameter: one axis (`axis` ≥ 1), no axis (0) or all axes (-1). The answer's axis word decides how many values come back: a negative one max-axes values, any other one value (a non-axis parameter read with -1). `length` must be at least 4 + their size (1 for bit and byte, 2 word, 4 2-word, 8 real each), checked after the exchange as FANUC does (EW_LENGTH with `datano` and `type` written; below 4 nothing is written). A Series 15 is asked with the 30i command (0x8d).",
        params: &[
            READ_PARAMS[0],
            READ_PARAMS[1],
            READ_PARAMS[2],
            Param::Out("param", "IODBPSD"),
        ],
        forms: &PARAM_FORMS,
        block: Some(read(false)),
        short: Short::Request,
        ..COMMAND
    },
    Func {
        name: "cnc_rdparam3",
        doc: "Reads a CNC parameter as cnc_rdparam does; a `type` other than 0 sets the request's fifth word (what the CNC makes of it is not known).",
        params: &[
            READ_PARAMS[0],
            READ_PARAMS[1],
            READ_PARAMS[2],
            Param::Short("type"),
            Param::Out("param", "IODBPSD"),
        ],
        // The fifth word: a short 1 in its first half for a `type` other than 0.
        forms: &forms(
            cmd::RDPARAM16,
            cmd::RDPARAM,
            &[
                Word::Arg(0),
                Word::Arg(0),
                Word::Arg(1),
                Word::Const(0),
                Word::Nonzero(3, 0x10000),
            ],
        ),
        block: Some(read(false)),
        short: Short::Request,
        ..COMMAND
    },
    DIAGNOSS,
    Func {
        name: "cnc_rddiag",
        doc: "The same as cnc_diagnoss (an alias some programs use).",
        ..DIAGNOSS
    },
    Func {
        name: "cnc_wrparam",
        doc: "Writes a CNC parameter. The parameter's attributes are read first (one exchange); `length` must then equal 4 + the size of the values (one value, or one per axis of the CNC's maximum for a negative `type`: -1, -2 and -32768 alike, as FANUC's library counts), else EW_LENGTH and nothing is written. A 30i type word other than 0..4 (none a CNC uses) is written back as it came with every value zero, whatever `length`, as FANUC's library does. The input is read with the l32 layout (values from offset 4). The write is sent once; the CNC decides whether it is allowed (parameter write enable, MDI mode ...). A 16i-class write carries one value slot per axis of the CNC's maximum (as FANUC's library). A Series 15 is not asked for the attributes: as FANUC's library, a `length` below 4 is EW_LENGTH before anything is sent, whatever the type; its type and axis come from `type`, `(type << 8) | (axis & 0xff)`, and the 30i write block is sent (0x8e).",
        params: &[Param::Short("length"), Param::In("param", "IODBPSD")],
        forms: &forms(cmd::WRPARAM16, cmd::WRPARAM, &[]),
        block: Some(WRITE),
        ..COMMAND
    },
    Func {
        name: "cnc_rdparar",
        doc: "Reads the parameters `*s_number..=*e_number` (those the CNC has) into `param` as packed records: i16 number, i16 type word `(type << 8) | (axis & 0xff)`, then one value (axis -1: one per axis of the CNC) of the type's size (bit and byte 1, word 2, 2-word 4, real 8 = value and decimals), each record padded to a multiple of 4 (the padding bytes are not written). Asks the CNC again from the last number received + 1 (the block's whole 32-bit number, wrapping) while that is not above `*e_number`; an answer without a whole block asks again from there too (from 1 before any block), and ends in EW_PROTOCOL when that would repeat the request just answered (FANUC's library repeats it for ever). On success `*s_number` is the first number read, `*e_number` the last, and `*length` (in: the buffer's size) the bytes used. `*s_number > *e_number` is EW_NUMBER without traffic. A record that does not fit with its padding is EW_LENGTH: the records before it stay written, as does its 4-byte header if that fits, and the three pointers keep their values (all as FANUC's library, checked against it with our simulator).",
        params: &[
            Param::Io("s_number"),
            Param::Short("axis"),
            Param::Io("e_number"),
            Param::Io("length"),
            Param::Out("param", "void"),
        ],
        checks: &[ordered(0, 2)],
        forms: &forms(
            cmd::RDPARAM16,
            cmd::RDPARAM,
            &[Word::Arg(0), Word::Arg(2), Word::Arg(1)],
        ),
        block: Some(Block {
            length: 3,
            attributes: None,
            range: Some(Range { s: 0, e: 2 }),
            diag: false,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdparanum",
        doc: "Reads the smallest and largest parameter numbers and how many there are.",
        params: &[Param::Out("paranum", "ODBPARANUM")],
        forms: &[every_class(cmd::RDPARANUM, &[])],
        reply: &num_range("para_min", "para_max"),
        short: Short::Error,
        ..COMMAND
    },
    Func {
        name: "cnc_rddiagnum",
        doc: "Reads the smallest and largest diagnosis numbers and how many there are.",
        params: &[Param::Out("diagnum", "ODBDIAGNUM")],
        forms: &[every_class(cmd::RDDIAGNUM, &[])],
        reply: &num_range("diag_min", "diag_max"),
        short: Short::Error,
        ..COMMAND
    },
];
