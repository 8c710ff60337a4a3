//! The ranges offsets may be set in: tool offsets, work zero offsets and
//! the work coordinate shift.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// The answer of each: the lowest and highest value as value records
/// (their base and exponent words not read: the values are copied as
/// sent), then the status. A short answer's missing bytes read as the
/// request's from its third word on (recorded: an empty answer's
/// `data_min` is `1000 + type`, or the axis), as FANUC's library reads
/// the answer into its request's buffer.
const RANGE: &[Field] = &[
    to(I32, "data_min", I32),
    skip(I32),
    to(I32, "data_max", I32),
    skip(I32),
    to(I32, "status", I32),
];

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_tofs_rnge",
        doc: "Reads the range tool offset `number` of type `type` (as cnc_rdtofs numbers them) may be set in: lowest and highest value and its status; the type goes as `1000 + type` (cnc_wrtofs's single form).",
        params: &[
            Param::Short("number"),
            Param::Short("type"),
            Param::Out("rnge", "ODBDATRNG"),
        ],
        forms: &[every_class(
            cmd::TOFS_RNGE,
            &[Word::Arg(0), Word::Const(0), Word::Plus(1, 1000)],
        )],
        reply: RANGE,
        short: Short::Request,
        dims: &["1|0|-1|2|99|32767", "0|1|2|3|-1|4|-1000|32767"],
        learnt: Some(&[
            "word 2 computed: 1000 + type (recorded: Word::Plus)",
            "a short answer reads the request's bytes (recorded)",
        ]),
        ..COMMAND
    },
    Func {
        name: "cnc_zofs_rnge",
        doc: "Reads the range work zero offset `number` (0 the external offset, 1.. G54..) of axis `axis` may be set in: lowest and highest value and its status.",
        params: &[
            Param::Short("number"),
            Param::Short("axis"),
            Param::Out("rnge", "ODBDATRNG"),
        ],
        forms: &[every_class(
            cmd::ZOFS_RNGE,
            &[Word::Arg(0), Word::Const(0), Word::Arg(1)],
        )],
        reply: RANGE,
        short: Short::Request,
        dims: &["1|0|-1|2|6|7|32767", "1|0|-1|2|3|4|32|33"],
        learnt: Some(&["a short answer reads the request's bytes (recorded)"]),
        ..COMMAND
    },
    Func {
        name: "cnc_wksft_rnge",
        doc: "Reads the range the work coordinate shift of axis `axis` may be set in: lowest and highest value and its status.",
        params: &[Param::Short("axis"), Param::Out("rnge", "ODBDATRNG")],
        forms: &[every_class(cmd::WKSFT_RNGE, &[Word::Arg(0)])],
        reply: RANGE,
        short: Short::Request,
        dims: &["1|0|-1|2|3|4|32|33"],
        learnt: Some(&[
            "a short answer reads the request's bytes (as cnc_zofs_rnge; its third word is 0)",
        ]),
        ..COMMAND
    },
];
