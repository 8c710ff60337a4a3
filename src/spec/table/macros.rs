//! The macro variables' functions in IEEE doubles: custom (cnc_rdmacror2,
//! cnc_wrmacror2) and P-code (cnc_rdpmacror2, cnc_wrpmacror2). FANUC's
//! library sends a read and a write of either through one routine each
//! (`inter_rdmacror2`, `inter_wrmacror2`): the command, the `type` word
//! (0 for the custom ones) and the ends of the ranges (`macroLast`) are
//! their only differences (docs/protocol/macro.md).

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;
use crate::ew::EW_ATTRIB;

/// Where the ranges of custom macro variables end, as FANUC's library cuts
/// cnc_rdmacror2's and cnc_wrmacror2's count at the end of the start's
/// range (`macroLast`; recorded: `500 -1` and `500 1000` read #500..#999,
/// `999 2` writes #999 alone): #0..#99, #100..#499, #500..#999; on a Series
/// 15 #0..#99, #100..#199, #200..#999; other starts are not cut (FANUC's
/// library cuts #13000..#13999 of a wire-cut machine too, not described).
pub const MACRO_ENDS: &[Ends] = &[
    ends(Classes::Not15, 0, 99),
    ends(Classes::Not15, 100, 499),
    ends(Classes::Not15, 500, 999),
    ends(Classes::S15, 0, 99),
    ends(Classes::S15, 100, 199),
    ends(Classes::S15, 200, 999),
];

/// Where the ranges of P-code macro variables end for cnc_rdpmacror2 and
/// cnc_wrpmacror2 (`macroLast`'s P-code ranges, not cnc_rdpmacror's
/// [`super::offset::P_CODE_ENDS`]): #0..#99, #100..#499, #500..#999,
/// #10000..#19999, #20000..#99999, #100000..#199999, #200000..#986431,
/// #986432..#4999999; on a Series 15 #0..#99, #100..#199, #200..#999,
/// #30000..#39999, #40000..#99099, #99100..#99199, #99200..#99999; other
/// starts are not cut.
pub const P_MACRO_ENDS: &[Ends] = &[
    ends(Classes::Not15, 0, 99),
    ends(Classes::Not15, 100, 499),
    ends(Classes::Not15, 500, 999),
    ends(Classes::Not15, 10000, 19999),
    ends(Classes::Not15, 20000, 99999),
    ends(Classes::Not15, 100000, 199999),
    ends(Classes::Not15, 200000, 986431),
    ends(Classes::Not15, 986432, 4999999),
    ends(Classes::S15, 0, 99),
    ends(Classes::S15, 100, 199),
    ends(Classes::S15, 200, 999),
    ends(Classes::S15, 30000, 39999),
    ends(Classes::S15, 40000, 99099),
    ends(Classes::S15, 99100, 99199),
    ends(Classes::S15, 99200, 99999),
];

const fn ends(classes: Classes, lo: i32, hi: i32) -> Ends {
    Ends {
        classes,
        lo,
        hi,
        end: End::At(hi),
    }
}

/// `type` of the P-code functions above 2: EW_ATTRIB before any traffic
/// (after `*num`'s check).
const TYPE: Check = Check {
    arg: 2,
    lo: 0,
    hi: 2,
    code: EW_ATTRIB,
};

/// One IEEE double a record, to or from the caller's `double` array.
const DOUBLE: &[Field] = &[doubles(0, 1, "")];

/// A read of IEEE doubles: one record a variable into `data`, 179 a
/// request from `s_no` on, an answer shorter than its request the last.
const READ: Func = Func {
    learnt: None,
    records: Some(&Records {
        fields: DOUBLE,
        out: 0,
        to: "",
        elem: "double",
        max: 179,
        count: None,
        room: None,
    }),
    pages: Some(Pages {
        bytes: 179 * 8,
        advance: Some(0),
        from_done: true,
        room: None,
        until_short: true,
    }),
    ..COMMAND
};

/// A write of IEEE doubles from `data`: 177 a request from `s_no` on,
/// the next only when the CNC wrote the whole previous one.
const WRITE: Func = Func {
    learnt: None,
    payload: Some(&Payload {
        fields: DOUBLE,
        elem: "double",
        count: 1,
        max: u16::MAX,
    }),
    pages: Some(Pages {
        bytes: 177 * 8,
        advance: Some(0),
        from_done: false,
        room: None,
        until_short: true,
    }),
    ..COMMAND
};

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdmacror2",
        // Moved from the hand-written code (learnt: None): its recordings
        // settle it.
        doc: "Reads `*num` custom macro variables from `s_no` as IEEE doubles into `data`, bit-exact; `*num` becomes the number read. `s_no` and `*num` are 32-bit, as in FANUC's x86-64 library (4 bytes of `*num` read and written). `*num` 0 is EW_LENGTH before any traffic; the count is cut to the end of `s_no`'s range (#99, #499, #999; compared unsigned: 0xffffffff reads to the end) and a count of 0 or below as an `int` reads nothing (`*num` 0). Requests carry at most 179 variables; an answer shorter than its request ends the read. No more than each request's doubles are written (FANUC's library writes whatever the CNC sends). An error answer leaves `*num` as it was; EW_NUMBER after some variables ends the read with them. How a CNC marks a vacant variable in this form is not known.",
        params: &[
            Param::ULong("s_no"),
            Param::LongCount("num"),
            Param::Out("data", "double"),
        ],
        checks: &[nonzero(1)],
        forms: &[every_class(cmd::RDMACROR2, &[Word::Arg(0), Word::Arg(1)])],
        ends: MACRO_ENDS,
        ..READ
    },
    Func {
        name: "cnc_wrmacror2",
        doc: "Writes `*num` custom macro variables from `s_no` from the IEEE doubles `data`, bit-exact; `*num` becomes the number the CNC wrote. `s_no` and `*num` are 32-bit, as in FANUC's x86-64 library. `*num` 0 is EW_LENGTH before any traffic; the variables past the end of `s_no`'s range (#99, #499, #999) are left out, as FANUC's library does. Requests carry at most 177 variables; the next is sent only when the CNC wrote the whole previous one, and `*num` is the sum of the answers' counts (a count cut short in the answer reads as 0). An error answer leaves `*num` as it was, the requests before it written; EW_NUMBER after some variables ends the write with them.",
        params: &[
            Param::ULong("s_no"),
            Param::LongCount("num"),
            Param::In("data", "double"),
        ],
        checks: &[nonzero(1)],
        forms: &[every_class(cmd::WRMACROR2, &[Word::Arg(0)])],
        // The answer: how many the CNC wrote; a count cut short reads on
        // in the request's bytes (FANUC's library reads the answer into
        // the buffer that held it: the third word, 0; fuzz).
        reply: &[skip(I32)],
        short: Short::Request,
        ends: MACRO_ENDS,
        ..WRITE
    },
    Func {
        name: "cnc_rdpmacror2",
        doc: "Reads `*num` P-code macro variables from `s_no` as IEEE doubles into `data`, as cnc_rdmacror2 reads custom ones (FANUC's library: the same routine), with `type` (0..2; what it selects is not known) as the request's third word: `*num` 0 is EW_LENGTH, then `type` above 2 EW_ATTRIB, before any traffic; the count is cut to the end of `s_no`'s range (#99, #499, #999, #19999, #99999, #199999, #986431, #4999999; a Series 15: #99, #199, #999, #39999, #99099, #99199, #99999; compared unsigned) and a count of 0 or below as an `int` reads nothing (`*num` 0). Requests carry at most 179 variables; an answer shorter than its request ends the read. No more than each request's doubles are written (FANUC's library writes whatever the CNC sends). An error answer leaves `*num` as it was; EW_NUMBER after some variables ends the read with them.",
        params: &[
            Param::ULong("s_no"),
            Param::LongCount("num"),
            Param::UShort("type"),
            Param::Out("data", "double"),
        ],
        checks: &[nonzero(1), TYPE],
        forms: &[every_class(
            cmd::RDPMACROR2,
            &[Word::Arg(0), Word::Arg(1), Word::Arg(2)],
        )],
        ends: P_MACRO_ENDS,
        dims: &[
            "10000|10100|19990|100|150|0|99999|200000|2147483647",
            "6|1|0|-1|179|180|400",
            "0|1|2|3|65535",
        ],
        ..READ
    },
    Func {
        name: "cnc_wrpmacror2",
        doc: "Writes `*num` P-code macro variables from `s_no` from the IEEE doubles `data`, as cnc_wrmacror2 writes custom ones (FANUC's library: the same routine), with `type` (0..2; what it selects is not known) as the request's third word: `*num` 0 is EW_LENGTH, then `type` above 2 EW_ATTRIB, before any traffic; the variables past the end of `s_no`'s range (as cnc_rdpmacror2) are left out. Requests carry at most 177 variables; the next is sent only when the CNC wrote the whole previous one, and `*num` is the sum of the answers' counts (a count cut short in the answer reads on in the request's bytes, as FANUC's library reads it: the third word, `type`). An error answer leaves `*num` as it was, the requests before it written; EW_NUMBER after some variables ends the write with them.",
        params: &[
            Param::ULong("s_no"),
            Param::LongCount("num"),
            Param::UShort("type"),
            Param::In("data", "double"),
        ],
        checks: &[nonzero(1), TYPE],
        forms: &[every_class(
            cmd::WRPMACROR2,
            &[Word::Arg(0), Word::Const(0), Word::Arg(2)],
        )],
        // A count cut short reads on in the request's bytes: its third
        // word, `type` (fuzz: `type` 2 and an answer of 3 bytes count 2).
        reply: &[skip(I32)],
        short: Short::Request,
        ends: P_MACRO_ENDS,
        ..WRITE
    },
    Func {
        name: "cnc_getrtmrvar",
        learnt: Some(&[]),
        doc: "Reads how many real-time custom macro volatile variables the CNC has (4 bytes written into the `long`).",
        params: &[Param::Out("num", "long")],
        forms: &[every_class(cmd::GETRTMRVAR, &[])],
        reply: &[to(I32, "", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_getrtmrvars",
        learnt: Some(&[]),
        doc: "Reads how many real-time custom macro non-volatile variables the CNC has (4 bytes written into the `long`).",
        params: &[Param::Out("num", "long")],
        forms: &[every_class(cmd::GETRTMRVARS, &[])],
        reply: &[to(I32, "", I32)],
        ..COMMAND
    },
];
