//! The custom macro variables' functions in IEEE doubles (cnc_rdmacror2,
//! cnc_wrmacror2): FANUC's library sends both through one routine each
//! (`inter_rdmacror2`, `inter_wrmacror2`), the command its only difference
//! from the P-code ones (docs/protocol/macro.md).

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// Where the ranges of custom macro variables end, as FANUC's library cuts
/// cnc_rdmacror2's and cnc_wrmacror2's count at the end of the start's
/// range (recorded: `500 -1` and `500 1000` read #500..#999, `999 2`
/// writes #999 alone): #0..#99, #100..#499, #500..#999 on every class;
/// other starts are not cut.
pub const MACRO_ENDS: &[Ends] = &[ends(0, 99), ends(100, 499), ends(500, 999)];

const fn ends(lo: i32, hi: i32) -> Ends {
    Ends {
        classes: Classes::All,
        lo,
        hi,
        end: End::At(hi),
    }
}

/// One IEEE double a record, to or from the caller's `double` array.
const DOUBLE: &[Field] = &[doubles(0, 1, "")];

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdmacror2",
        // Moved from the hand-written code; its recordings settle it.
        learnt: None,
        doc: "Reads `*num` custom macro variables from `s_no` as IEEE doubles into `data`, bit-exact; `*num` becomes the number read. `s_no` and `*num` are 32-bit, as in FANUC's x86-64 library (4 bytes of `*num` read and written). `*num` 0 is EW_LENGTH before any traffic; the count is cut to the end of `s_no`'s range (#99, #499, #999; compared unsigned: 0xffffffff reads to the end) and a count of 0 or below as an `int` reads nothing (`*num` 0). Requests carry at most 179 variables; an answer shorter than its request ends the read. No more than each request's doubles are written (FANUC's library writes whatever the CNC sends). An error answer leaves `*num` as it was; EW_NUMBER after some variables ends the read with them. How a CNC marks a vacant variable in this form is not known.",
        params: &[
            Param::ULong("s_no"),
            Param::LongCount("num"),
            Param::Out("data", "double"),
        ],
        checks: &[nonzero(1)],
        forms: &[every_class(cmd::RDMACROR2, &[Word::Arg(0), Word::Arg(1)])],
        records: Some(Records {
            fields: DOUBLE,
            out: 0,
            to: "",
            elem: "double",
            max: 179,
            count: None,
            room: None,
        }),
        // 179 doubles a request, from `s_no` on.
        pages: Some(Pages {
            bytes: 179 * 8,
            advance: Some(0),
            from_done: true,
            room: None,
            until_short: true,
        }),
        ends: MACRO_ENDS,
        ..COMMAND
    },
    Func {
        name: "cnc_wrmacror2",
        learnt: None,
        doc: "Writes `*num` custom macro variables from `s_no` from the IEEE doubles `data`, bit-exact; `*num` becomes the number the CNC wrote. `s_no` and `*num` are 32-bit, as in FANUC's x86-64 library. `*num` 0 is EW_LENGTH before any traffic; the variables past the end of `s_no`'s range (#99, #499, #999) are left out, as FANUC's library does. Requests carry at most 177 variables; the next is sent only when the CNC wrote the whole previous one, and `*num` is the sum of the answers' counts (a count cut short in the answer reads as 0). An error answer leaves `*num` as it was, the requests before it written; EW_NUMBER after some variables ends the write with them.",
        params: &[
            Param::ULong("s_no"),
            Param::LongCount("num"),
            Param::In("data", "double"),
        ],
        checks: &[nonzero(1)],
        forms: &[every_class(cmd::WRMACROR2, &[Word::Arg(0)])],
        // The answer: how many the CNC wrote.
        reply: &[skip(I32)],
        payload: Some(Payload {
            fields: DOUBLE,
            elem: "double",
            count: 1,
            max: u16::MAX,
        }),
        // 177 doubles a request, from `s_no` on.
        pages: Some(Pages {
            bytes: 177 * 8,
            advance: Some(0),
            from_done: false,
            room: None,
            until_short: true,
        }),
        ends: MACRO_ENDS,
        ..COMMAND
    },
];
