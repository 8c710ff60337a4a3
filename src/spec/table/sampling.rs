//! Servo data sampling, cnc_sdt* (FANUC's 32-bit x86 build 1.0.0 exports
//! them, its x86-64 build does not; learnt from the 32-bit build,
//! docs/protocol/position.md "Servo data sampling").

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// cnc_sdtsetchnl's code of each `type` (0..37) of an axis channel.
const AXIS_CODES: &[i32] = &[
    5, 4, 1, 2, 3, 22, 7, 25, 50, 99, 23, 113, 114, 48, 75, 78, 81, 84, 49, 76, 79, 82, 85, 51, 52,
    65, 66, 104, 105, 106, 8, 15, 16, 99, 100, 101, 102, 103,
];

/// cnc_sdtsetchnl's code of each `type` (0..12) of a spindle channel
/// (`axis` -1).
const SPINDLE_CODES: &[i32] = &[13, 1, 3, 4, 22, 31, 32, 2, 39, 60, 33, 34, 62];

/// cnc_sdtsetchnl's byte of each `shift` (0..15): `0x0c | shift << 4`.
const SHIFT_BYTES: &[i32] = &[
    0x0c, 0x1c, 0x2c, 0x3c, 0x4c, 0x5c, 0x6c, 0x7c, 0x8c, 0x9c, 0xac, 0xbc, 0xcc, 0xdc, 0xec, 0xfc,
];

/// cnc_sdtsetchnl's payload fields, by index: `chno`, `axis`, `cycle`, the
/// shift byte, 0, the code.
const CHNO: u8 = 0;
const AXIS: u8 = 1;
const CYCLE: u8 = 2;
const SHIFT: u8 = 3;
const CODE: u8 = 5;

/// A channel member's check: detail `detail` (FANUC's library numbers the
/// members 20..23).
const fn member(
    classes: Classes,
    of: u8,
    when: Option<(u8, i32, i32)>,
    ok: &'static [(i32, i32)],
    detail: i16,
) -> Rule {
    Rule {
        classes,
        of: Of::Field(of),
        when,
        ok,
        code: crate::ew::EW_DATA,
        detail,
    }
}

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_sdtsetchnl",
        learnt: Some(&[
            "computed bytes: the payload's code from `type` (two code tables), its sign from the axis's parameter 1023 (one exchange per axis channel, per class), the shift byte from `shift`, `cycle` in every record",
            "checks with detail codes: `cycle` per class (detail 3), each channel's members (20..23), the axes per class",
        ]),
        doc: "Sets `n` servo data sampling channels (1..8) from `chan[]`, sampled every `cycle` (8 or more; -1 too on the 30i class; else EW_DATA, detail 3). Each channel in turn is checked (`type` 0..37 of an axis or 0..12 of a spindle, `axis` -1; `chno` 1..8; `axis` -1 or an axis of the path; `shift` 0..15: else EW_DATA, details 20..23) and, on an axis, the axes' parameter 1023 read; then all are sent, 12 bytes each: `chno`, `axis`, `cycle`, `0x0c | shift << 4`, 0 and the code of `type`, negated for an axis whose parameter 1023 is even (FANUC's 32-bit library only).",
        params: &[
            Param::Short("n"),
            Param::Long("cycle"),
            Param::In("chan", "IDBSDTCHAN"),
        ],
        checks: &[Check {
            arg: 0,
            lo: 1,
            hi: 8,
            code: crate::ew::EW_NUMBER,
        }],
        rules: &[
            Rule {
                classes: Classes::S30,
                of: Of::Arg(1),
                when: None,
                ok: &[(-1, -1), (8, i32::MAX)],
                code: crate::ew::EW_DATA,
                detail: 3,
            },
            Rule {
                classes: Classes::S16,
                of: Of::Arg(1),
                when: None,
                ok: &[(8, i32::MAX)],
                code: crate::ew::EW_DATA,
                detail: 3,
            },
            member(Classes::All, CODE, Some((AXIS, -1, -1)), &[(0, 12)], 20),
            member(Classes::All, CODE, None, &[(0, 37)], 20),
            member(Classes::All, CHNO, None, &[(1, 8)], 21),
            member(Classes::S30, AXIS, None, &[(-1, -1), (1, AXES)], 22),
            // The 16i class: the tens read like a path number.
            member(
                Classes::S16,
                AXIS,
                None,
                &[(-3, -1), (1, 8), (11, 18), (21, 28)],
                22,
            ),
            member(Classes::All, SHIFT, None, &[(0, 15)], 23),
        ],
        each: &[
            // Parameter 1023 (servo axis number) of all axes, 8-byte value
            // records; any error answer is EW_UNEXP.
            Each {
                classes: Classes::S30,
                when: (AXIS, 1, 127),
                cmd: cmd::RDPARAM,
                words: &[1023, 1023, -1, 0, 0x10000],
                tens: false,
                value: Some((11, 8, I8)),
                error: Some(crate::ew::EW_UNEXP),
            },
            // cnc_rdparam's 16i form, 4-byte values, on the path the axis's
            // tens name (1 for 1..8) whatever the handle's; an error
            // answer's code is the call's.
            Each {
                classes: Classes::S16,
                when: (AXIS, 1, 127),
                cmd: cmd::RDPARAM16,
                words: &[1023, 1023, -1, 0, 0],
                tens: true,
                value: Some((11, 4, I8)),
                error: None,
            },
            // `axis` -3 and -2 on the 16i class: diagnosis 400, in the
            // diagnosis read's 16i form (Series 15: its 30i form); what
            // FANUC's library reads from a data answer is not known.
            Each {
                classes: Classes::S16Not15,
                when: (AXIS, -3, -2),
                cmd: cmd::DIAGNOSS16,
                words: &[400, 400, 0, 0, 0],
                tens: true,
                value: None,
                error: Some(crate::ew::EW_UNEXP),
            },
            Each {
                classes: Classes::S15,
                when: (AXIS, -3, -2),
                cmd: cmd::DIAGNOSS,
                words: &[400, 400, 0, 0, 0],
                tens: true,
                value: None,
                error: Some(crate::ew::EW_UNEXP),
            },
        ],
        codes: &[
            Code {
                field: CYCLE,
                when: None,
                value: CodeValue::Arg(1),
                negate: false,
            },
            Code {
                field: SHIFT,
                when: None,
                value: CodeValue::Table(SHIFT_BYTES),
                negate: false,
            },
            Code {
                field: CODE,
                when: Some((AXIS, -1, -1)),
                value: CodeValue::Table(SPINDLE_CODES),
                negate: false,
            },
            Code {
                field: CODE,
                when: None,
                value: CodeValue::Table(AXIS_CODES),
                negate: true,
            },
        ],
        forms: &[every_class(cmd::SDTSETCHNL, &[Word::Arg(0)])],
        payload: Some(&Payload {
            fields: &[
                to(I16, "chno", I8),
                to(I16, "axis", I8),
                skip(I32),
                to(U8, "shift", U16),
                skip(U8),
                to(I16, "type", I16),
            ],
            elem: "IDBSDTCHAN",
            count: 0,
            max: 8,
        }),
        ..COMMAND
    },
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
