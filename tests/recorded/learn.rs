//! The learner's pure logic (tools/oracle/learn_pure.rs) on synthetic data:
//! no FANUC library, no header of FANUC's. A made-up header is parsed, a
//! made-up library's behaviour is simulated byte by byte (what it would
//! write from position-coded replies, what it would send for varied
//! arguments), and the learner must get back what the simulation did.

#[allow(dead_code)]
#[path = "../../tools/oracle/learn_pure.rs"]
mod pure;

use fwlib32::spec::table::base::COMMAND;
use fwlib32::spec::{Field, Func, Int::*, Param, Records, every_class, skip, to};
use pure::*;

const HEADER: &str = "
typedef struct rec { long no; short h; char m; char s; } REC;
typedef struct odbthing {
    short num;
    long value;
    union { short w[2]; long l; } u;
    char name[4];
    REC data[3];
} ODBTHING;
typedef ODBTHING ALIAS;
short cnc_thing( unsigned short, short, long *, ODBTHING * ) ;
short cnc_names( unsigned short, short, short *, char (*)[62]);
short cnc_float( unsigned short, double * ) ;
";

fn thing() -> Ty {
    Header::parse(HEADER).types["ODBTHING"].clone()
}

#[test]
fn header_types_and_prototypes() {
    let h = Header::parse(HEADER);
    let t = &h.types["ODBTHING"];
    // short at 0, long (4 bytes) at 4, union at 8, char[4] at 12, REC[3] at 16
    assert_eq!(member(t, "num").unwrap().0, 0);
    assert_eq!(member(t, "value").unwrap().0, 4);
    assert_eq!(member(t, "u").unwrap().0, 8);
    assert_eq!(member(t, "u.l").unwrap().0, 8);
    assert_eq!(member(t, "name").unwrap().0, 12);
    assert_eq!(member(t, "data").unwrap().0, 16);
    assert_eq!(h.types["REC"].size(), 8);
    assert_eq!(t.size(), 16 + 3 * 8);
    assert_eq!(h.types["ALIAS"], *t);
    let p = h.proto("cnc_thing").unwrap();
    assert_eq!(p.params.len(), 4);
    assert_eq!(
        p.params[1].0,
        Ty::Int {
            size: 2,
            signed: true
        }
    );
    assert_eq!(
        p.params[2].0,
        Ty::Ptr(Box::new(Ty::Int {
            size: 4,
            signed: true
        }))
    );
    let n = h.proto("cnc_names").unwrap();
    assert_eq!(
        n.params[3].0,
        Ty::Ptr(Box::new(Ty::Array(
            Box::new(Ty::Int {
                size: 1,
                signed: true
            }),
            62
        )))
    );
    assert_eq!(h.proto("cnc_float").unwrap().params[1].0.size(), 8);
    let mut lv = Vec::new();
    leaves(t, 0, "", &mut lv);
    assert_eq!(lv[0].path, "num");
    assert!(
        lv.iter()
            .any(|l| l.path == "data[2].s" && l.off == 16 + 16 + 7)
    );
}

#[test]
fn position_codes_decode_and_constants_do_not() {
    for i in [0usize, 1, 250, 251, 252, 1000, 1427, 20000] {
        let v: [u8; PASSES] = std::array::from_fn(|p| code(i, p));
        assert_eq!(decode(v), Some(i), "position {i}");
        assert!(v.iter().all(|b| *b != 0));
    }
    // a byte the library writes whatever the reply (an echoed argument 1)
    assert_eq!(decode([1, 1, 1]), None);
    assert_eq!(decode([0, 1, 8]), None);
}

/// A made-up library: what it writes into a 40-byte ODBTHING from `reply`:
/// num from the low half of a 4-byte word at 0 (narrowing), value at 4,
/// u.w[0..2] two 2-byte words at 8 and 10, name from bytes 12..16, and
/// one record {no 4 bytes at 16, h a 2-byte word at 20 sign-extended into
/// nothing (a short), m at 23, s at 24}, then a computed byte in name[3].
fn library(reply: &[u8], out: &mut [u8]) {
    let be16 = |o: usize| [reply[o + 1], reply[o]];
    let be32 = |o: usize| [reply[o + 3], reply[o + 2], reply[o + 1], reply[o]];
    out[0..2].copy_from_slice(&be16(2));
    out[4..8].copy_from_slice(&be32(4));
    out[8..10].copy_from_slice(&be16(8));
    out[10..12].copy_from_slice(&be16(10));
    out[12..15].copy_from_slice(&reply[12..15]);
    out[15] = reply[12].wrapping_add(reply[13]); // computed
    out[16..20].copy_from_slice(&be32(16));
    out[20..22].copy_from_slice(&be16(20));
    out[22] = reply[23];
    out[23] = reply[24];
}

fn observe(lib: fn(&[u8], &mut [u8])) -> [[Vec<u8>; 2]; PASSES] {
    std::array::from_fn(|p| {
        let reply = coded(256, p);
        [0xCCu8, 0x33].map(|fill| {
            let mut out = vec![fill; 40];
            lib(&reply, &mut out);
            out
        })
    })
}

#[test]
fn byte_map_finds_fields_and_flags_computed_bytes() {
    let map = map_bytes(&observe(library));
    assert_eq!(map[0], Src::At(3));
    assert_eq!(map[1], Src::At(2));
    assert_eq!(map[2], Src::Kept); // padding after num
    assert_eq!(map[15], Src::Computed);
    let mut lv = Vec::new();
    leaves(&thing(), 0, "", &mut lv);
    let mut odd = Vec::new();
    let p = placed(0, &map, &lv, &mut odd);
    assert!(odd.iter().any(|o| o.contains("name[3]")), "{odd:?}");
    let find = |path: &str| p.iter().find(|x| x.path == path).cloned();
    let num = find("num").unwrap();
    assert_eq!((num.at, num.wire, num.c), (2, I16, I16));
    let value = find("value").unwrap();
    assert_eq!((value.at, value.wire, value.c), (4, I32, I32));
    assert_eq!(find("u.w[1]").unwrap().at, 10);
    assert_eq!(find("name[0]").unwrap().wire, I8);
    assert_eq!(find("data[0].no").unwrap().at, 16);
    assert_eq!(find("data[0].m").unwrap().at, 23);
    assert!(find("data[1].no").is_none());
}

/// A library that writes a wire 2-byte word into a long with its sign.
fn widening(reply: &[u8], out: &mut [u8]) {
    let v = i16::from_be_bytes([reply[200], reply[201]]) as i32;
    out[4..8].copy_from_slice(&v.to_le_bytes());
}

#[test]
fn sign_extension_is_a_signed_wire_word() {
    let map = map_bytes(&observe(widening));
    let mut lv = Vec::new();
    leaves(&thing(), 0, "", &mut lv);
    let mut odd = Vec::new();
    let p = placed(0, &map, &lv, &mut odd);
    assert!(odd.is_empty(), "{odd:?}");
    assert_eq!(p.len(), 1);
    assert_eq!((p[0].at, p[0].wire, p[0].c), (200, I16, I32));
    // the bytes it moves: the word swapped, then its sign twice, as the
    // byte map saw them
    let m = moves(&p);
    assert_eq!(
        m,
        vec![
            (0, 4, Src::At(201)),
            (0, 5, Src::At(200)),
            (0, 6, Src::Sign(200)),
            (0, 7, Src::Sign(200)),
        ]
    );
    assert_eq!(&map[4..8], &[m[0].2, m[1].2, m[2].2, m[3].2]);
}

/// The committed-entry side: the same library described as a table entry
/// moves the same bytes; an entry off by one field does not.
#[test]
fn a_described_entry_agrees_with_the_byte_map_and_a_wrong_one_does_not() {
    const RIGHT: Func = Func {
        name: "cnc_thing",
        doc: "",
        params: &[Param::Out("thing", "ODBTHING")],
        checks: &[],
        forms: &[every_class(1, &[])],
        reply: &[
            to(I32, "num", I16),
            to(I32, "value", I32),
            Field {
                wire: I16,
                n: 2,
                out: 0,
                to: Some("u"),
                c: I16,
                arg: None,
            },
        ],
        ..COMMAND
    };
    const WRONG: Func = Func {
        reply: &[skip(I32), to(I32, "value", I32), to(I32, "u", I32)],
        ..RIGHT
    };
    let map = map_bytes(&observe(library));
    let mut lv = Vec::new();
    leaves(&thing(), 0, "", &mut lv);
    let learnt = placed(0, &map, &lv, &mut Vec::new());
    // the fixed fields only: the first 12 bytes
    let within = |m: &(usize, usize, Src)| m.1 < 12;
    let l: Vec<_> = moves(&learnt).into_iter().filter(within).collect();
    let right: Vec<_> = moves(&expected(&RIGHT, &[thing()], 64, usize::MAX).unwrap())
        .into_iter()
        .filter(within)
        .collect();
    let wrong: Vec<_> = moves(&expected(&WRONG, &[thing()], 64, usize::MAX).unwrap())
        .into_iter()
        .filter(within)
        .collect();
    assert_eq!(l, right);
    assert_ne!(l, wrong);
}

/// Records: a caller's array of REC written from 8-byte wire records
/// after a 4-byte head; the learner finds the repeat and the entry's
/// records agree.
#[test]
fn records_repeat_and_match_a_records_entry() {
    fn records_lib(reply: &[u8], out: &mut [u8]) {
        for k in 0..3 {
            let (w, o) = (4 + 8 * k, 8 * k);
            out[o..o + 4].copy_from_slice(&[reply[w + 3], reply[w + 2], reply[w + 1], reply[w]]);
            out[o + 4..o + 6].copy_from_slice(&[reply[w + 5], reply[w + 4]]);
            out[o + 6] = reply[w + 6];
            out[o + 7] = reply[w + 7];
        }
    }
    let map = map_bytes(&observe(records_lib));
    let rec = Header::parse(HEADER).types["REC"].clone();
    let mut lv = Vec::new();
    leaves(&Ty::Array(Box::new(rec.clone()), 5), 0, "", &mut lv);
    let mut p = placed(0, &map, &lv, &mut Vec::new());
    p.sort_by_key(|x| x.at);
    let r = repeat(&p).expect("a repeat");
    assert_eq!((r.first, r.per, r.wire, r.out, r.n), (0, 4, 8, 8, 3));
    const ENTRY: Func = Func {
        name: "cnc_recs",
        doc: "",
        params: &[Param::Count("num"), Param::Out("rec", "REC")],
        checks: &[],
        forms: &[every_class(2, &[])],
        reply: &[skip(I32)],
        records: Some(&Records {
            fields: &[
                to(I32, "no", I32),
                to(I16, "h", I16),
                to(U8, "m", I8),
                to(U8, "s", I8),
            ],
            out: 0,
            to: "",
            elem: "REC",
            max: 10,
            count: None,
            room: None,
        }),
        ..COMMAND
    };
    // three asked: the three records written
    let e = expected(&ENTRY, std::slice::from_ref(&rec), 64, 3).unwrap();
    assert_eq!(moves(&e), moves(&p));
    // two asked: the entry writes two, the library wrote three
    let e2 = expected(&ENTRY, &[rec], 64, 2).unwrap();
    assert_ne!(moves(&e2), moves(&p));
}

fn frame(subs: &[(u16, u16, [i32; 5], &[u8])]) -> Vec<u8> {
    let mut body = (subs.len() as u16).to_be_bytes().to_vec();
    for (class, cmd, words, payload) in subs {
        body.extend(((28 + payload.len()) as u16).to_be_bytes());
        body.extend(class.to_be_bytes());
        body.extend(1u16.to_be_bytes());
        body.extend(cmd.to_be_bytes());
        for w in words {
            body.extend(w.to_be_bytes());
        }
        body.extend_from_slice(payload);
    }
    let mut f = vec![0xa0, 0xa0, 0xa0, 0xa0, 0, 1, 0x21, 0x01];
    f.extend((body.len() as u16).to_be_bytes());
    f.extend(body);
    f
}

#[test]
fn request_frames_and_word_sources() {
    // cnc_thing(h, short type, long *num, ...): the made-up library sends
    // [type, 7, *num + 1, 0, payload length]
    let lib = |ty: i64, num: i64| {
        let payload = [1u8, 2, 3, 4, 5, 6];
        let f = frame(&[(
            1,
            0x0123,
            [ty as i16 as i32, 7, num as i32 + 1, 0, 6],
            &payload,
        )]);
        let s = subs(&f).unwrap();
        assert_eq!(s.len(), 1);
        assert_eq!((s[0].class, s[0].cmd), (1, 0x0123));
        assert_eq!(s[0].payload, payload);
        WordRun {
            args: vec![ty, num],
            words: s[0].words,
            payload_len: s[0].payload.len(),
        }
    };
    let runs = vec![lib(1, 4), lib(2, 4), lib(65535, 4), lib(1, 5), lib(1, 9)];
    let conv: [fn(i64) -> i32; 2] = [|v| v as i16 as i32, |v| v as i32];
    let w = learn_words(&runs, &conv);
    assert_eq!(w[0], WordSrc::Arg(0));
    assert_eq!(w[1], WordSrc::Const(7));
    assert!(matches!(w[2], WordSrc::Computed(_)), "{w:?}");
    assert_eq!(w[3], WordSrc::Const(0));
    assert_eq!(w[4], WordSrc::Len);
    // not a data request
    assert!(subs(&[0xa0, 0xa0, 0xa0, 0xa0, 0, 1, 0x01, 0x01, 0, 0]).is_none());
}

#[test]
fn local_checks_from_a_sweep() {
    // a library refusing type < 0 or > 32 with EW_NUMBER (3)
    let sweep: Vec<(i64, Option<i16>)> = [-32768, -2, -1, 0, 1, 5, 32, 33, 100, 32767]
        .iter()
        .map(|&v| (v, (!(0..=32).contains(&v)).then_some(3)))
        .collect();
    let c = learn_check(0, &sweep).unwrap().unwrap();
    assert_eq!((c.lo, c.hi, c.code), (0, 32, 3));
    // nothing refused: no check
    assert_eq!(learn_check(1, &[(0, None), (5, None)]).unwrap(), None);
    // a hole inside the accepted values cannot be one range
    assert!(learn_check(0, &[(0, None), (5, Some(3)), (9, None)]).is_err());
    // the committed form of the same check answers each swept value as
    // observed, a different bound does not
    let conv: [fn(i64) -> i32; 1] = [|v| v as i16 as i32];
    let same = fwlib32::spec::Check {
        arg: 0,
        lo: 0,
        hi: 32,
        code: 3,
    };
    assert!(same_answers(std::slice::from_ref(&sweep), &[same], &conv).is_ok());
    let other = fwlib32::spec::Check { hi: 31, ..same };
    let e = same_answers(std::slice::from_ref(&sweep), &[other], &conv).unwrap_err();
    assert!(e.contains("argument 0 = 32"), "{e}");
    // another code for the same values differs too
    let code = fwlib32::spec::Check { code: 2, ..same };
    assert!(same_answers(std::slice::from_ref(&sweep), &[code], &conv).is_err());
    // a sweep that is not one range (no learnt check) is still compared
    // value by value: a committed range refusing the accepted 9 differs
    let holed = vec![(0, None), (5, Some(3)), (9, None)];
    let range = fwlib32::spec::Check {
        arg: 0,
        lo: 0,
        hi: 4,
        code: 3,
    };
    let e = same_answers(&[holed], &[range], &conv).unwrap_err();
    assert!(e.contains("argument 0 = 9"), "{e}");
}

#[test]
fn a_draft_is_table_syntax_with_its_flags() {
    let map = map_bytes(&observe(library));
    let mut lv = Vec::new();
    leaves(&thing(), 0, "", &mut lv);
    let mut flags = Vec::new();
    let mut reply = placed(0, &map, &lv, &mut flags);
    reply.sort_by_key(|x| x.at);
    let d = Draft {
        name: "cnc_thing".into(),
        params: vec![
            DParam::Short("a0".into()),
            DParam::Out("a1".into(), "ODBTHING".into()),
        ],
        forms: vec![DForm {
            classes: "All",
            class: 1,
            cmd: 0x123,
            words: vec![WordSrc::Arg(0)],
            more: 0,
        }],
        reply,
        flags,
        ..Draft::default()
    };
    let t = d.text();
    assert!(t.contains("// LEARNT"));
    assert!(t.contains("name: \"cnc_thing\""));
    assert!(t.contains("words: &[Word::Arg(0)]"));
    assert!(
        t.contains("skip(I16),\n            to(I16, \"num\", I16),"),
        "{t}"
    );
    assert!(
        t.contains("Field { wire: I16, n: 2, out: 0, to: Some(\"u.w\"), c: I16, arg: None },"),
        "{t}"
    );
    assert!(t.contains("// - out 0 name[3]"), "{t}");
    // The open points travel with the entry, for COMPATIBILITY.md.
    let open = &t[t.find("learnt: Some(&[").expect("learnt marker")..];
    assert!(
        open.contains("\n            \"out 0 name[3]: [Computed]\",\n"),
        "{t}"
    );
}

/// A text parameter's payload (a C string in a fixed field) puts its
/// length in the fifth word, as a records payload does; a form without
/// payload leaves the word 0.
#[test]
fn a_text_parameter_sends_its_length_in_the_fifth_word() {
    const TEXT: Func = Func {
        name: "cnc_text",
        doc: "",
        params: &[Param::Short("type"), Param::Text("path", 256)],
        checks: &[],
        forms: &[every_class(0x0123, &[fwlib32::spec::Word::Arg(0)])],
        ..COMMAND
    };
    let (class, cmd, w) = committed_words(&TEXT, false, false).unwrap();
    assert_eq!((class, cmd), (1, 0x0123));
    assert_eq!(w[0], WordSrc::Arg(0));
    assert_eq!(w[4], WordSrc::Len);
    const NONE: Func = Func {
        params: &[Param::Short("type")],
        ..TEXT
    };
    assert_eq!(
        committed_words(&NONE, false, false).unwrap().2[4],
        WordSrc::Const(0)
    );
}

/// Records `elem: "char[N]"` from a `char[N]` member on: each record one
/// name of N bytes (consecutive members), not one character.
#[test]
fn records_of_char_arrays_step_by_the_array() {
    let hdr = Header::parse(
        "typedef struct names { short no; short type; char n1[5]; char n2[5]; char n3[5]; } NAMES;",
    );
    let ty = hdr.types["NAMES"].clone();
    const ENTRY: Func = Func {
        name: "cnc_names",
        doc: "",
        params: &[Param::Out("buf", "NAMES")],
        checks: &[],
        forms: &[every_class(3, &[])],
        records: Some(&Records {
            fields: &[Field {
                wire: U8,
                n: 4,
                out: 0,
                to: Some(""),
                c: I8,
                arg: None,
            }],
            out: 0,
            to: "n1",
            elem: "char[5]",
            max: 3,
            count: None,
            room: None,
        }),
        ..COMMAND
    };
    let m = moves(&expected(&ENTRY, &[ty], 12, usize::MAX).unwrap());
    // record k: reply bytes 4k.. into bytes 4 + 5k..
    let want: Vec<(usize, usize, Src)> = (0..3)
        .flat_map(|k| (0..4).map(move |b| (0, 4 + 5 * k + b, Src::At(4 * k + b))))
        .collect();
    assert_eq!(m, want);
}

/// The committed answer `oracle learn --check` compares a sweep with is the
/// whole entry's on each class: cnc_rdpmacror's order check, the ends of
/// its ranges (the 16i class reads #1000..#9999 and negative starts alone)
/// and its first request on the 30i class (traffic before the checks);
/// and its end word as FANUC's library sent it (tests/vectors).
#[test]
fn a_range_reads_ends_and_first_request_per_class() {
    let f = fwlib32::spec::find("cnc_rdpmacror").unwrap();
    const M: i32 = i32::MAX;
    // (s, e) -> the end word sent on 30i, 16i, Series 15
    for (s, e, ends) in [
        (0, M, [99, 99, 99]),
        (100, M, [278, 278, 199]),
        (322, M, [499, 499, 500]),
        (822, M, [999, 999, 999]),
        (19822, M, [19999, 19999, 20000]),
        (99822, M, [99999, 99999, 99999]),
        (199822, M, [199999, 199999, 200000]),
        (-1, M, [M, M, M]),
        (-1, 4999, [177, 177, 177]),
        (i32::MIN, M, [M, M, M]),
        (i32::MIN, -2147478648, [-2147483470; 3]),
    ] {
        for (k, (s16, s15)) in [(false, false), (true, false), (true, true)]
            .into_iter()
            .enumerate()
        {
            assert_eq!(f.upto(s, e, 178, s16, s15), ends[k], "{s} {e} class {k}");
        }
    }
    let answer = |a: &[i32], s16, s15| {
        if f.sends_first(a, s16, s15) {
            None
        } else {
            f.refusal(a, s16, s15, true)
        }
    };
    let number = Some(fwlib32::ew::EW_NUMBER);
    // backwards: refused, but on the 30i after its first request
    assert_eq!(answer(&[10001, 10000, 52], false, false), number);
    assert_eq!(answer(&[20000, 10004, 52], false, false), None);
    assert_eq!(answer(&[20000, 10004, 52], true, false), number);
    // read alone on the 16i class only
    for (s, e) in [(1000, 1001), (9999, 10004), (-1, 0), (i32::MIN, M)] {
        assert_eq!(answer(&[s, e, 52], true, false), number, "{s} {e}");
        assert_eq!(answer(&[s, e, 52], true, true), None, "{s} {e}");
        assert_eq!(answer(&[s, e, 52], false, false), None, "{s} {e}");
    }
    assert_eq!(answer(&[1000, 1000, 52], true, false), None);
    assert_eq!(answer(&[-1, -1, 52], true, false), None);
}

/// A flag word: a constant for a nonzero argument, 0 for 0 (the table's
/// `Word::Nonzero`), learnt as such and compared with the entry's.
#[test]
fn a_flag_word_for_a_nonzero_argument() {
    let run = |a: i64, b: i64| WordRun {
        args: vec![a, b],
        words: [a as i32, 0, 0, 0, if b != 0 { 0x10000 } else { 0 }],
        payload_len: 0,
    };
    let runs = vec![run(1, 1), run(2, 1), run(1, 2), run(1, 0), run(1, 6)];
    let conv: [fn(i64) -> i32; 2] = [|v| v as i16 as i32, |v| v as i16 as i32];
    let w = learn_words(&runs, &conv);
    assert_eq!(w[0], WordSrc::Arg(0));
    assert_eq!(w[4], WordSrc::Nonzero(1, 0x10000));
    // without a run at 0 it is not told from a computed word
    let w = learn_words(&runs[..3], &conv);
    assert!(matches!(w[4], WordSrc::Const(0x10000)), "{w:?}");
    const F: Func = Func {
        name: "cnc_flag",
        doc: "",
        params: &[Param::Short("a"), Param::Short("b")],
        forms: &[every_class(
            1,
            &[
                fwlib32::spec::Word::Arg(0),
                fwlib32::spec::Word::Const(0),
                fwlib32::spec::Word::Const(0),
                fwlib32::spec::Word::Const(0),
                fwlib32::spec::Word::Nonzero(1, 0x10000),
            ],
        )],
        ..COMMAND
    };
    let c = committed_words(&F, false, false).unwrap();
    assert_eq!(c.2[4], WordSrc::Nonzero(1, 0x10000));
    let learnt = DForm {
        classes: "All",
        class: 1,
        cmd: 1,
        words: learn_words(&runs, &conv),
        more: 0,
    };
    assert_eq!(same_form(&learnt, &c), Ok(()));
}

/// Bytes written as 0 off the wire: a name's NUL after its characters.
/// The learner finds the zero leaf (not the zero-extension of a moved
/// integer) and the entry's `zero` field names the same bytes.
#[test]
fn zeroed_bytes_are_zero_fields() {
    // name[0..3] from reply bytes 0..3, name[3] always 0; num from a
    // 2-byte word (its high byte is no zero field: a moved short).
    fn lib(reply: &[u8], out: &mut [u8]) {
        out[12..15].copy_from_slice(&reply[0..3]);
        out[15] = 0;
        out[0] = reply[4];
        out[1] = 0;
    }
    let map = map_bytes(&observe(lib));
    let mut lv = Vec::new();
    leaves(&thing(), 0, "", &mut lv);
    let (zl, zb) = learnt_zeros(0, &map, &lv);
    assert_eq!(zl, vec![("name[3]".to_string(), I8)]);
    assert_eq!(zb, vec![(0, 15)]);
    const F: Func = Func {
        name: "cnc_thing",
        doc: "",
        params: &[Param::Out("thing", "ODBTHING")],
        forms: &[every_class(1, &[])],
        reply: &[
            fwlib32::spec::text(3, "name"),
            fwlib32::spec::zero("name[3]", I8),
        ],
        ..COMMAND
    };
    assert_eq!(committed_zeros(&F, &[thing()], 3, usize::MAX).unwrap(), zb);
    // a zero field is no echo and moves no reply byte
    assert_eq!(
        moves(&expected(&F, &[thing()], 3, usize::MAX).unwrap()).len(),
        3
    );
}

/// A write's reply field read into no output (the records it did) needs no
/// output; a typed block, value records, lookups, a count in the reply and
/// several subpackets are why an entry's reply is not bytes moved.
#[test]
fn replies_that_do_not_map_say_why() {
    const W: Func = Func {
        name: "cnc_write",
        doc: "",
        params: &[Param::Short("a")],
        forms: &[every_class(1, &[])],
        reply: &[skip(I32)],
        ..COMMAND
    };
    assert_eq!(expected(&W, &[], 4, usize::MAX), Ok(Vec::new()));
    assert_eq!(entry_not_clean(&W), None);
    let counted = Func {
        counted: Some(0),
        ..W
    };
    assert!(entry_not_clean(&counted).unwrap().contains("Func::counted"));
    const VALUE: &[Field] = &[
        fwlib32::spec::digits(0, "num"),
        fwlib32::spec::places(0, "num"),
    ];
    let values = Func { reply: VALUE, ..W };
    assert!(entry_not_clean(&values).unwrap().contains("value record"));
    let more = Func {
        more: &[&[fwlib32::spec::Word::Const(2)]],
        ..W
    };
    assert!(entry_not_clean(&more).unwrap().contains("2 answers"));
    // a lookup's bytes: its member on, its elements' integers
    const LOOKUP: &[fwlib32::spec::Lookup] = &[fwlib32::spec::Lookup {
        to: "u",
        c: I16,
        n: 2,
        fill: -1,
        key: fwlib32::spec::Key::Own,
        end: 0xff,
        pick: fwlib32::spec::Pick::Split {
            mask: 0xf,
            low: 0,
            high: 0,
        },
    }];
    let looked = Func {
        lookups: LOOKUP,
        ..W
    };
    assert!(entry_not_clean(&looked).unwrap().contains("lookups: u"));
    assert_eq!(lookup_spans(&looked, &thing()), vec![(8, 4)]);
}
