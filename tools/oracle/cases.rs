//! The case generator: every word of the probe, along dimensions.
//!
//! A word is described once, by its argument dimensions: each dimension
//! lists its values, the first being the base. Cases are the base call, each
//! dimension varied alone over its other values, explicit combinations, the
//! base call on every CNC class, on path 2 and an absent path, and the base
//! call with every reply shape. Each call is followed by `cnc_getdtailerr`
//! (`pmc_getdtailerr` for PMC words), so the detail of every error is
//! recorded too.

use super::fake::{Fault, Shape};

/// One generated case.
#[derive(Debug, Clone)]
pub struct Case {
    pub name: String,
    /// v3 (30i), v2 (16i), s15 (Series 15), v3p2 (30i, two paths).
    pub profile: &'static str,
    pub fault: Option<Fault>,
    /// The calls after the connection; `Some(shape)` shapes that call's reply.
    pub calls: Vec<(String, Option<Shape>)>,
    /// Set-up calls made before the connection (settimeout, ...).
    pub timeout: i64,
}

/// A word: its dimensions ("|"-separated values, base first) and
/// explicit argument combinations.
pub struct Word {
    pub word: &'static str,
    pub dims: &'static [&'static str],
    pub combos: &'static [&'static str],
    /// Calls made before the word in every case (a write before its read-back ...).
    pub setup: &'static [&'static str],
    /// Calls made after the word, before getdtailerr.
    pub after: &'static [&'static str],
    /// A write: its cases run on the write-enabled profiles too (v3w, v2w:
    /// parameter write enable on, MDI mode).
    pub writes: bool,
}

const fn w(word: &'static str, dims: &'static [&'static str]) -> Word {
    Word {
        word,
        dims,
        combos: &[],
        setup: &[],
        after: &[],
        writes: false,
    }
}

const fn wc(
    word: &'static str,
    dims: &'static [&'static str],
    combos: &'static [&'static str],
) -> Word {
    Word {
        word,
        dims,
        combos,
        setup: &[],
        after: &[],
        writes: false,
    }
}

const AXIS: &str = "1|-1|2|3|0|4|32|33|-2";
const AXLEN: &str = "8|4|7|12|0|-1|132|136";

/// Every word the generator covers: the functions described as data
/// (src/spec/table/, their dimensions there) and the words below.
pub fn words() -> Vec<Word> {
    // A write's cases (payloads, read-backs) are written below by hand.
    let described = fwlib32::spec::FUNCS
        .iter()
        .filter(|f| !WORDS.iter().any(|w| w.word == f.word()))
        .map(|f| Word {
            word: f.word(),
            dims: f.dims,
            ..w("", &[])
        });
    described.chain(WORDS.iter().map(copy)).collect()
}

fn copy(x: &Word) -> Word {
    Word { ..*x }
}

/// The words written by hand: functions not (yet) described as data.
const WORDS: &[Word] = &[
    // Connection group and status.
    w("sysinfo", &[]),
    w("sysinfo_ex", &[]),
    w("statinfo", &[]),
    w("statinfo2", &[]),
    w("rdcncid", &[]),
    w("getpath", &[]),
    Word {
        after: &["getpath", "statinfo", "sysinfo"],
        ..w("setpath", &["1|2|0|-1|3|11|32767"])
    },
    Word {
        after: &["statinfo"],
        ..w("settimeout", &["10|0|1|-1|100"])
    },
    Word {
        after: &["statinfo", "getpath"],
        ..w("resetconnect", &[])
    },
    // Position.
    wc(
        "rddynamic2",
        &["1|-1|0|2|3|4|33|-2", "44|8|20|28|43|0|-1|100|540"],
        &["-1 540", "-1 60", "-1 44", "2 540"],
    ),
    wc(
        "rddynamic",
        &["1|-1|0|2|3|4|33|-2", "40|8|20|28|39|0|-1|100|536"],
        &["-1 536", "-1 56", "-1 40"],
    ),
    w("acts2", &["1|-1|0|2|3|8|9|-2"]),
    w("rdspeed", &["-1|0|1|2|3"]),
    w("rdspload", &["1|-1|0|2|9"]),
    w("rdspmaxrpm", &["1|-1|0|2|9"]),
    w("rdspgear", &["1|-1|0|2|9"]),
    w("rdspmeter", &["0|1|-1|2|3", "4|1|0|2|8|9|-1"]),
    w("rdsvmeter", &["4|1|0|2|3|32|33|-1"]),
    wc(
        "rdaxisdata",
        &[],
        &[
            "1 1 0 8",
            "1 1 1 8",
            "1 1 2 8",
            "1 1 3 8",
            "1 1 4 8",
            "1 1 5 8",
            "1 1 6 8",
            "1 1 7 8",
            "1 1 8 8",
            "1 1 9 8",
            "1 1 10 8",
            "1 1 17 8",
            "1 1 18 8",
            "1 1 -1 8",
            "1 4 0 1 2 3 8",
            "1 5 0 1 2 3 4 8",
            "1 2 0 3 32",
            "1 1 0 0",
            "1 1 0 1",
            "1 1 0 3",
            "1 1 0 32",
            "1 1 0 33",
            "1 1 0 -1",
            "1 0 8",
            "1 -1 8",
            "2 1 0 8",
            "2 1 1 8",
            "2 1 2 8",
            "2 1 3 8",
            "2 2 0 1 8",
            "2 3 0 1 2 8",
            "3 1 0 8",
            "3 1 1 8",
            "3 1 2 8",
            "3 2 0 1 8",
            "3 1 0 1",
            "4 1 0 8",
            "4 1 1 8",
            "5 1 0 8",
            "5 1 1 8",
            "5 1 2 8",
            "0 1 0 8",
            "6 1 0 8",
            "-1 1 0 8",
        ],
    ),
    w("rdposition", &["-1|0|1|2|3|4|5|-2", "4|1|0|2|3|32|33|-1"]),
    wc("absolute", &[AXIS, AXLEN], &["-1 132", "-1 16", "-1 20"]),
    wc("absolute2", &[AXIS, AXLEN], &["-1 132", "-1 16"]),
    wc("machine", &[AXIS, AXLEN], &["-1 132", "-1 16"]),
    wc("relative", &[AXIS, AXLEN], &["-1 132", "-1 16"]),
    wc("relative2", &[AXIS, AXLEN], &["-1 132", "-1 16"]),
    wc("distance", &[AXIS, AXLEN], &["-1 132", "-1 16"]),
    w("getfigure", &["0|1|-1|2|3"]),
    // Program.
    w("exeprgname", &[]),
    w("exeprgname2", &[]),
    w("rdexecprog", &["256|0|1|10|100|1024|4096|65535"]),
    w(
        "modal",
        &[
            "0|1|2|3|20|21|26|-1|-2|-3|-4|-5|100|101|102|103|104|105|106|107|108|109|110|111|112|113|114|115|116|117|118|119|120|121|122|123|124|125|126|127|128|129|130|131|132|200|300|-100",
            "0|1|2|3|-1",
        ],
    ),
    w("gettimer", &["0|1|2|-1"]),
    Word {
        after: &["gettimer 0", "gettimer 1"],
        ..wc(
            "settimer",
            &[],
            &[
                "0 2026 11 25",
                "1 12 30 45",
                "0 2026 13 1",
                "1 25 0 0",
                "2 0 0 0",
                "-1 0 0 0",
            ],
        )
    },
    w("rdopmode", &[]),
    w(
        "rdprogdir",
        &[
            "0|1|2|-1|3",
            "1|0|-1|1234|9999",
            "9999|0|1|1234|-1",
            "520|0|10|40|100|4096|65535",
        ],
    ),
    w(
        "rdprogdir3",
        &["0|1|2|-1|3", "0|1|1234|-1|9999", "10|0|1|2|-1|100"],
    ),
    w("rdproginfo", &["1|0|-1|2", "31|30|32|12|11|0|100"]),
    w(
        "rdprogdir2",
        &["0|1|2|-1|3", "0|1|100|1234|-1", "10|0|1|2|-1|100"],
    ),
    Word {
        setup: &["wrmdiprog 9 hex:4738304d33303b0a25"],
        ..w("rdmdiprog", &["256|0|1|8|9|10|-1|4096"])
    },
    Word {
        after: &["rdmdiprog 256"],
        ..w(
            "wrmdiprog",
            &[
                "9|0|1|4|-1|12|255|256|1024|1400|4096",
                "hex:4738304d33303b0a25",
            ],
        )
    },
    // Program data folders (30i).
    w("rdpdf_drive", &[]),
    w(
        "rdpdf_inf",
        &[
            "//CNC_MEM/|//CNC_MEM/USER/PATH1/|CNC_MEM|//DATA_SV/|x",
            "1|0|2|-1|3",
        ],
    ),
    w("rdpdf_curdir", &["1|0|2|-1|3"]),
    w(
        "wrpdf_curdir",
        &[
            "1|0|2|-1|3",
            "//CNC_MEM/USER/PATH1/|//CNC_MEM/USER/|//CNC_MEM/USER/PATH9/|x|//CNC_MEM/USER/PATH1",
        ],
    ),
    w(
        "rdpdf_subdirn",
        &["//CNC_MEM/USER/|//CNC_MEM/USER/PATH1/|//CNC_MEM/|//CNC_MEM/NONE/|x"],
    ),
    w(
        "pdf_add",
        &[
            "//CNC_MEM/USER/PATH1/O0200|//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/NEW/|//CNC_MEM/USER/PATH1/|x|O0300",
        ],
    ),
    w(
        "pdf_del",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O1234|//CNC_MEM/USER/PATH1/O0007|//CNC_MEM/USER/PATH1/|x|O0100",
        ],
    ),
    w(
        "pdf_slctmain",
        &["//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|//CNC_MEM/USER/PATH1/|x|O0100"],
    ),
    w("pdf_rdmain", &[]),
    w(
        "pdf_rename",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|x",
            "O0200|O1234|//CNC_MEM/USER/PATH1/O0200|x",
        ],
    ),
    w(
        "pdf_copy",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|x",
            "//CNC_MEM/USER/PATH1/O0200|//CNC_MEM/USER/PATH1/|//CNC_MEM/USER/PATH1/O1234|x",
        ],
    ),
    w(
        "pdf_move",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|x",
            "//CNC_MEM/USER/LIBRARY/|//CNC_MEM/USER/PATH1/|x",
        ],
    ),
    w(
        "rdpdf_subdir",
        &[
            "10|0|1|2|-1|100",
            "//CNC_MEM/USER/|//CNC_MEM/|//CNC_MEM/USER/PATH1/|x",
            "0|1|2|-1|5",
        ],
    ),
    w(
        "rdpdf_alldir",
        &[
            "10|0|1|2|-1|100",
            "//CNC_MEM/USER/PATH1/|//CNC_MEM/USER/|x",
            "0|1|2|-1|5",
            "1|0|2|-1",
            "1|0|2|-1",
        ],
    ),
    w(
        "pdf_delall",
        &["1|0|2|-1|3", "//CNC_MEM/USER/PATH1/|//CNC_MEM/USER/|x"],
    ),
    w(
        "pdf_delline",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|x",
            "2|0|1|5|-1",
            "1|0|2|10|-1",
        ],
    ),
    w("pdf_rdactpt", &["0|5|-1"]),
    w(
        "pdf_wractpt",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|x",
            "0|1|2|-1",
            "2|0|1|100|-1",
        ],
    ),
    w(
        "rdpdf_line",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|x",
            "1|0|2|5|-1|100",
            "3|0|1|10|-1",
            "256|0|1|10|-1|4096",
        ],
    ),
    w(
        "wrpdf_line",
        &[
            "//CNC_MEM/USER/PATH1/O0100|//CNC_MEM/USER/PATH1/O0007|x",
            "2|0|1|100|-1",
            "hex:4e353020473034583130",
            "10|0|1|5|-1",
        ],
    ),
    // Alarms and messages.
    w("alarm", &[]),
    w("alarm2", &[]),
    w(
        "rdalmmsg",
        &[
            "-1|0|1|2|3|4|5|6|7|8|9|10|11|12|13|14|15|16|31|32",
            "10|0|1|2|-1|100",
        ],
    ),
    w(
        "rdalmmsg2",
        &[
            "-1|0|1|2|3|4|5|6|7|8|9|10|11|12|13|14|15|16|31|32",
            "10|0|1|2|-1|100",
        ],
    ),
    w(
        "rdalminfo",
        &[
            "0|1|2|-1",
            "-1|0|1|2|3|4|5|6|7|8|9|10|11|12|13|14|15|20",
            "204|4|8|0|-1|100|1000|4096",
        ],
    ),
    w(
        "rdopmsg",
        &["0|1|2|3|4|-1|5", "262|6|0|-1|100|1048|2000|4096"],
    ),
    w("rdalmhisno", &[]),
    w(
        "rdalmhistry",
        &["1|0|2|3|10|-1", "3|1|5|10|0|100", "486|4|60|100|200|0|4096"],
    ),
    w(
        "rdalmhistry2",
        &["1|0|2|3|10|-1", "3|1|5|10|0|100", "524|4|60|100|200|0|4096"],
    ),
    w(
        "rdophistry",
        &["1|0|2|10|-1", "10|1|5|0|100", "86|6|14|0|-1|4096"],
    ),
    w("rdomhistry", &["1|0|2|-1", "10|0|1|2|1000"]),
    w(
        "rdomhistry2",
        &["1|0|2|-1", "3|1|10|0|100", "4096|0|4|276|1000|2724"],
    ),
    w(
        "rdalmhistry5",
        &["1|0|2|-1", "3|1|10|0|100", "4096|0|4|520|1036|5164"],
    ),
    wc(
        "accdecdly",
        &["1|-1|0|2|3|4|33", "8|4|12|0|-1|132"],
        &["-1 132", "-1 20", "2 8"],
    ),
    wc(
        "srvdelay",
        &["1|-1|0|2|3|4|33", "8|4|12|0|-1|132"],
        &["-1 132", "-1 20", "2 8"],
    ),
    wc(
        "skip",
        &["1|-1|0|2|3|4|33", "8|4|12|0|-1|132"],
        &["-1 132", "-1 20", "2 8"],
    ),
    w(
        "rdparam3",
        &[
            "6711|1320|0|-1|9999",
            "0|1|-1|2|33",
            "8|4|0|-1|132",
            "0|1|2|-1",
        ],
    ),
    w("rdparainfo3", &["0|1|1320|6711|-1|9999", "10|1|0|-1|100"]),
    wc(
        "rdpitchr",
        &["1|0|-1|2|100", "5|1|0|10|1000", "11|6|7|0|-1|100"],
        &["2 1000 2000", "300 1100 2000", "1020 1030 100"],
    ),
    // Parameters and diagnosis.
    w(
        "rdparam",
        &[
            "6711|1320|1420|1825|0|1|2|-1|9999|32767|3202|1020|1815",
            "0|1|2|3|-1|4|32|33|-2",
            "8|4|5|6|0|-1|12|16|40|136|260|264|500",
        ],
    ),
    wc(
        "rdparam_ext32",
        &[],
        &[
            "1 6711",
            "2 6711 1320",
            "3 6711 1320 9999",
            "1 1320",
            "4 0 1 2 3",
            "1 -1",
            "0",
            "-1",
            "2 1320 1320",
            "7 1 2 3 4 5 6 7",
            "8 1 2 3 4 5 6 7 8",
            "12 1 2 3 4 5 6 7 8 9 10 11 12",
            "16 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16",
            "32 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32",
        ],
    ),
    wc("rdparam_ext", &[], &["1 6711", "2 6711 1320", "1 9999"]),
    wc(
        "rddiag_ext32",
        &[],
        &["1 300", "2 300 301", "3 300 301 9999", "1 411", "0", "-1"],
    ),
    w(
        "rdparar",
        &[
            "6711|0|1320|-1|9999",
            "0|-1|1|2",
            "6711|6720|1320|0|-1|9999",
            "100|8|0|-1|1000|4096",
        ],
    ),
    w("rdparainfo", &["6711|0|1|1320|-1|9999", "10|1|0|100|65535"]),
    w("rdparanum", &[]),
    w(
        "diagnoss",
        &[
            "300|301|0|-1|411|9999|1000",
            "0|1|-1|2|33",
            "8|4|5|0|-1|12|40|260|264",
        ],
    ),
    w("rddiag", &["300|301|0|411", "0|1|-1", "8|4|0|-1"]),
    w("rddiaginfo", &["300|0|1|-1|411|9999", "10|1|0|100|65535"]),
    w("rddiagnum", &[]),
    // Macros.
    w(
        "rdmacro",
        &[
            "500|100|1|0|-1|999|1000|10000|32767|-32768",
            "10|8|9|0|-1|20",
        ],
    ),
    Word {
        after: &["rdmacro 500 10"],
        ..wc(
            "wrmacro",
            &[],
            &[
                "500 10 12345 3",
                "500 10 -1 -2",
                "500 10 2147483647 0",
                "500 10 -2147483648 9",
                "500 10 5 -1",
                "500 10 123 -3",
                "500 10 1 8",
                "500 10 1 10",
                "100 10 7 0",
                "0 10 1 1",
                "999 10 5 0",
                "-1 10 5 0",
                "500 8 5 0",
                "500 0 5 0",
                "500 12 5 0",
                "500 10 1 128",
                "500 10 1 -129",
                "500 10 7 -10",
                "500 10 -3 19",
                "500 10 0 3",
                "1000 10 5 1",
            ],
        )
    },
    w(
        "rdmacror",
        &[
            "500|1|100|0|-1|999",
            "505|500|1|100|-1|1000",
            "56|8|16|0|-1|1000",
        ],
    ),
    w("rdmacror2", &["500|1|100|0|99999", "6|1|0|-1|100|1000"]),
    // PMC.
    w(
        "pmc_rdpmcrng",
        &[
            "9|5|0|1|2|3|4|6|7|8|10|11|12|-1|20",
            "0|1|2|-1|3|4|5",
            "100|0|1|65535|9999",
            "105|100|0|200|9999",
            "14|8|9|10|0|300|1000",
        ],
    ),
    w("pmc_rdpmcinfo", &["-1|0|1|5|9|20"]),
    // PMC units: a selection addresses the later PMC calls of the handle.
    Word {
        after: &["pmc_get_current_pmc_unit", "pmc_rdpmcrng 9 0 0 3 12"],
        ..w("pmc_select_pmc_unit", &["2|1|0|3|-1|9"])
    },
    w("pmc_get_current_pmc_unit", &[]),
    w("pmc_get_pmc_unit_types", &["4|1|2|0|-1|8"]),
    // Offsets and tools.
    w(
        "rdtofs",
        &["1|0|-1|2|99|400|401", "0|1|2|3|-1|4|20", "8|4|0|-1|12"],
    ),
    w(
        "rdtofsr",
        &[
            "1|0|-1|10",
            "-1|0|1|2|3|9|20",
            "5|1|0|-1|400",
            "188|8|12|0|-1|1000",
        ],
    ),
    Word {
        after: &["rdtofs 1 0 8"],
        ..wc(
            "wrtofs",
            &[],
            &[
                "1 0 8 12345",
                "1 1 8 -5",
                "0 0 8 1",
                "1 0 4 1",
                "1 -1 8 1",
                "999 0 8 1",
            ],
        )
    },
    w(
        "rdzofs",
        &["1|0|-1|2|6|7|48|49", "1|-1|0|2|33|-2", "8|12|0|-1|132|136"],
    ),
    wc(
        "rdzofsr",
        &["1|0|-1|2", "-1|1|0|2", "6|1|0|7|-1", "1032|8|0|-1|100|2000"],
        &[
            "1 -1 6 648",
            "1 -1 6 776",
            "1 -1 1 136",
            "1 -1 20 2000",
            "-5 -1 6 1032",
            "1 -2 6 1032",
            "1 33 6 1032",
            "1 1 6 32",
            "1 1 6 31",
            "1 1 300 2000",
        ],
    ),
    w("rdtoolgrp", &["1|0|-1|2|9999", "120|8|0|-1|1000"]),
    w("rdtlctldata", &[]),
    // Tool life groups, tool management and punch-press tool data (tool branch).
    wc(
        "rdgrpinfo",
        &["1|0|-1|2|3|9999", "2|1|0|-1|3|9999", "88|0|-1|8|24|40|1000"],
        &[
            "1 9999 1000",
            "2 9999 1000",
            "1 44 1000",
            "1 45 1000",
            "3 3 88",
            "2 1 88",
            "1 2 71",
            "1 2 72",
            "1 2 39",
            "1 2 40",
            "1 2 56",
        ],
    ),
    Word {
        after: &["rdgrpinfo 1 2 40"],
        writes: true,
        ..wc(
            "wrgrpinfo",
            &[],
            &[
                "40 hex:010000000200cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "24 hex:010000000100cccc02000000960000000a00000001000000",
                "24 hex:010000000200cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "39 hex:010000000200cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "8 hex:010000000200cccc",
                "0 hex:010000000200cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "-1 hex:010000000200cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "40 hex:000000000100cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "40 hex:020000000100cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "40 hex:ffff00000000cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "56 hex:010000000300cccc02000000960000000a000000010000000100000058020000050000000000000003000000070000000800000009000000",
                "40 hex:020000000300cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "88 hex:010000000200cccc02000000960000000a0000000100000001000000580200000500000000000000",
                "24 hex:020000000200cccc02000000960000000a00000001000000",
                "24 hex:0f2700000f27cccc02000000960000000a00000001000000",
                "0 hex:020000000100cccc",
                "1428 hex:010000004700cccc02000000960000000a00000001000000",
                "1448 hex:010000004800cccc02000000960000000a00000001000000",
                "1608 hex:010000006400cccc02000000960000000a00000001000000",
                "40 hex:010000000200cccc02000000960000000a0000000200000001000000580200000500000000000000",
                "40 hex:010000000200cccc02000000960000000a00000001000000010000005802000005000000ffffffff",
            ],
        )
    },
    w("rdtlusegrp", &[]),
    w("rdtool", &["1|0|-1|2|9999", "1|0|-1|2|5|100"]),
    w("rdtooldata", &["1|0|-1|2|9999", "1|0|-1|2|5|100"]),
    w("rdtoolinfo", &[]),
    w("pmc_rdpmctitle", &[]),
    // PMC alarm messages (A bits of the profile's messages) and timer
    // types, on unit 1, then with many alarms (A0-A1 written: 14, more
    // than one answer holds) and on unit 2.
    Word {
        after: &[
            "pmc_wrpmcrng 10 hex:0400000000000100ff3f",
            "pmc_rdalmmsg 1 20",
            "pmc_rdalmmsg 12 2",
            "pmc_select_pmc_unit 2",
            "pmc_rdalmmsg 1 10",
        ],
        ..w("pmc_rdalmmsg", &["1|2|3|0|-1|100", "10|1|2|0|-1|11|12|100"])
    },
    Word {
        after: &["pmc_select_pmc_unit 2", "pmc_get_timer_type 1 4"],
        ..wc(
            "pmc_get_timer_type",
            &["1|0|2|3|250|251|65535", "4|0|1|2|3|250|251|65535"],
            &["2 4", "3 3", "250 250", "1 714", "1 1000"],
        )
    },
    Word {
        after: &["pmc_get_timer_type 1 4"],
        ..wc(
            "pmc_set_timer_type",
            &[],
            &[
                "1 1 hex:0100",
                "1 2 hex:01000200",
                "3 4 hex:05000100",
                "2 2 hex:0600",
                "1 3 hex:0100",
                "0 1 hex:0100",
                "2 1 hex:0100",
                "250 250 hex:0200",
                "251 251 hex:0000",
            ],
        )
    },
    // Periodic maintenance: item names and items (the profile's
    // [maintenance]), each write followed by its read-back.
    Word {
        after: &["rdpm_item 1 4"],
        ..wc(
            "wrpm_item",
            &[],
            &[
                "0 1 1 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000003200000000000000",
                "1 2 1 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000003200000000000000",
                "0 3 2 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc020000006400000032000000000000005345434f4e44204954454d000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc01000000c80000000a00000000000000",
                "0 0 1 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000003200000000000000",
                "0 10 1 hex:5345434f4e44204954454d000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc01000000c80000000a00000000000000",
                "0 11 1 hex:5345434f4e44204954454d000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc01000000c80000000a00000000000000",
                "0 1 2 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000003200000000000000",
                "0 1 1 hex:4241442054595045000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc07000000640000003200000000000000",
                "0 1 1 hex:4241442052454d41494e00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000009600000000000000",
                "1 1 1 hex:4241442052454d41494e00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000009600000000000000",
                "0 1 0 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000003200000000000000",
                "0 1 -1 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000003200000000000000",
                "0 1 30 hex:54455354204954454d0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000cccc02000000640000003200000000000000",
            ],
        )
    },
    Word {
        after: &["rdpm_mcnitem 1 4"],
        ..wc(
            "wrpm_mcnitem",
            &[],
            &[
                "1 1 hex:5350494e444c4520475245415345000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000",
                "2 2 hex:434f4f4c414e542050554d500000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000544f4f4c20434c414d5000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000",
                "20 1 hex:4c41535400000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000",
                "21 1 hex:5041535400000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000",
                "0 1 hex:5a45524f00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000",
                "1 0 hex:41",
                "1 -1 hex:41",
                "1 30 hex:41",
            ],
        )
    },
    // Writes (each followed by its read-back).
    Word {
        after: &["rdparam 6711 0 8", "rdparam 1320 -1 132"],
        writes: true,
        ..wc(
            "wrparam",
            &[],
            &[
                "8 hex:371a0000e8030000",
                "8 hex:371a0000ffffffff",
                "6 hex:371a0000e803",
                "12 hex:371a0000e8030000",
                "4 hex:371a0000",
                "0 hex:371a0000e8030000",
                "-1 hex:371a0000e8030000",
                "8 hex:0f270000e8030000",
                "8 hex:28050100e8030000",
                "132 hex:28050000a0860100a0860100a0860100",
                "8 hex:00000000e8030000",
                "10 hex:371a0000e8030000",
                "36 hex:371a0000e8030000",
                "260 hex:371a0000e8030000",
            ],
        )
    },
    Word {
        after: &[
            "rdparam 6711 0 8",
            "rdparam 6712 0 8",
            "rdparam 1320 -1 260",
        ],
        writes: true,
        ..wc(
            "wrparas",
            &[],
            &[
                "8 hex:371a0003e8030000",
                "16 hex:371a0003e8030000381a0003d0070000",
                "12 hex:28050104a086010003000000",
                "12 hex:2805010412345678cdab0000",
                "8 hex:371a0003ffffffff",
                "8 hex:0f270003e8030000",
                "8 hex:371a0002e8030000",
                "8 hex:371a0005e8030000",
                "6 hex:371a0003e803",
                "4 hex:371a0003",
                "0 hex:371a0003e8030000",
                "-1 hex:371a0003e8030000",
                "12 hex:371a0003e8030000381a0003",
                "48 hex:371a000301000000381a000302000000391a000303000000371a000304000000381a000305000000391a000306000000",
                "96 hex:371a000301000000381a000302000000391a000303000000371a000304000000381a000305000000391a000306000000371a000307000000381a000308000000391a000309000000371a00030a000000381a00030b000000391a00030c000000",
            ],
        )
    },
    Word {
        after: &["rdmacror 500 502 32"],
        ..wc(
            "wrmacror",
            &[],
            &[
                "32 hex:f4010000f6010000393000000300000000000000000000000000000000000000",
                "24 hex:f4010000f501000039300000030000000100000000000000",
                "16 hex:f4010000f40100003930000003000000",
                "8 hex:f4010000f4010000",
                "0 hex:f4010000f4010000",
                "2 hex:f4010000f4010000",
                "6 hex:f4010000f4010000",
                "7 hex:f4010000f4010000",
                "32 hex:0100000003000000010000000000000001000000000000000100000000000000",
                "32 hex:e7030000e9030000010000000000000001000000000000000100000000000000",
                "14 hex:e7030000e90300000100000000000000",
                "32 hex:f3010000f5010000010000000000000001000000000000000100000000000000",
            ],
        )
    },
    Word {
        after: &["rdmacror2 500 3"],
        ..wc(
            "wrmacror2",
            &[],
            &[
                "500 1 hex:0000000000c05e40",
                "500 3 hex:0000000000c05e40000000000000f03f182d4454fb210940",
                "500 0 hex:0000000000c05e40",
                "100 1 hex:0000000000000000",
                "999 2 hex:0000000000c05e400000000000c05e40",
                "0 1 hex:0000000000c05e40",
            ],
        )
    },
    Word {
        after: &["rdzofs 1 1 8", "rdzofs 1 -1 132"],
        ..wc(
            "wrzofs",
            &[],
            &[
                "8 hex:010001003930000000",
                "8 hex:01000100c7cfffff",
                "132 hex:0100ffff393000003a3000003b300000",
                "12 hex:0100010039300000",
                "4 hex:01000100",
                "0 hex:01000100",
                "8 hex:00000100",
                "8 hex:07000100",
                "8 hex:01002100",
                "8 hex:0100feff",
            ],
        )
    },
    Word {
        after: &["rdntool 2", "toolnum 2 1", "toolnum 2 2"],
        ..wc(
            "instlifedt",
            &[],
            &[
                "hex:0200010063000000",
                "hex:0200020063000000",
                "hex:0200030063000000",
                "hex:0200000063000000",
                "hex:0200ffff63000000",
                "hex:0100010005000000",
                "hex:0900010063000000",
                "hex:00000100ffffffff",
            ],
        )
    },
    Word {
        after: &["rdwkcdshft 1 8", "rdwkcdshft -1 132"],
        ..wc(
            "wrwkcdshft",
            &[],
            &[
                "8 hex:000001003930000000",
                "8 hex:00000200c7cfffff",
                "132 hex:0000ffff393000003a3000003b300000",
                "12 hex:0000010039300000",
                "4 hex:00000100",
                "0 hex:00000100",
                "8 hex:00000000",
                "8 hex:00002100",
                "8 hex:0000feff",
                "8 hex:00000400",
            ],
        )
    },
    Word {
        after: &["pmc_rdpmcrng 9 0 100 103 12"],
        ..wc(
            "pmc_wrpmcrng",
            &[],
            &[
                "12 hex:0900000064006700010203040000",
                "10 hex:09000000640065000102",
                "9 hex:090000006400640005",
                "12 hex:090001006400670001020304",
                "16 hex:0900020064006700010203040506",
                "12 hex:0300000000000300010203",
                "12 hex:0100000000000300010203",
                "8 hex:0900000064006400",
                "0 hex:0900000064006700",
                "12 hex:1400000064006700010203",
            ],
        )
    },
    // Connection group: the calls around the handle's life.
    Word {
        after: &["statinfo", "alloc 10", "statinfo"],
        ..w("free", &[])
    },
    Word {
        after: &["statinfo", "free"],
        ..w("exitprocess", &[])
    },
    w("getdtailerr", &[]),
    w("pmc_getdtailerr", &[]),
    Word {
        after: &["statinfo", "free"],
        ..wc("alloc4", &[], &["10 0", "10 1", "10 305419896"])
    },
    Word {
        after: &["statinfo"],
        ..wc(
            "startup",
            &[],
            &[
                "0 f.log",
                "1 f.log",
                "2 f.log",
                "3 f.log",
                "4 f.log",
                "-1 f.log",
                "1 \\xe9t\\xe9.log",
            ],
        )
    },
    // Program upload on connection 1.
    Word {
        after: &["upload 300", "upload 300", "upload 300", "upend"],
        ..wc("upstart", &[], &["1234", "1", "0", "-1", "9999"])
    },
    Word {
        after: &["upload3 256", "upload3 256", "upload3 4096", "upend3"],
        ..wc(
            "upstart3",
            &[],
            &[
                "0 1234 1234",
                "0 1 9999",
                "0 0 0",
                "1 1234 1234",
                "-1 1234 1234",
                "0 1234 1",
                "0 9999 9999",
            ],
        )
    },
    Word {
        after: &["upload4 256", "upload4 4096", "upend4"],
        ..wc(
            "upstart4",
            &[],
            &[
                "0 O1234",
                "0 //CNC_MEM/USER/PATH1/O1234",
                "0 O9999",
                "1 O1234",
                "0 1234",
                "-1 O1234",
                // A Latin-1 name goes as its bytes (\xHH: see probe.c).
                "0 //CNC_MEM/USER/\\xc4RGER/O1234",
            ],
        )
    },
    Word {
        setup: &["upstart 1234"],
        after: &["cupload 256", "cupload 256", "upend"],
        ..wc("cupload", &[], &["256", "0", "4"])
    },
    wc("upload", &[], &["256"]),
    wc("upend", &[], &[""]),
    // Program download and DNC operation on connection 1: the text is
    // uploaded back after the end, so the vectors show what was stored.
    Word {
        after: &[
            "download3 %|O4321(NEW)|G00X1.|M30|%",
            "dwnend3",
            "upstart4 0 O4321",
            "upload4 4096",
            "upend4",
        ],
        ..wc("dwnstart3", &[], &["0", "1", "-1", "5"])
    },
    Word {
        setup: &["dwnstart3 0"],
        after: &["dwnend3", "upstart4 0 O4321", "upload4 4096", "upend4"],
        ..wc(
            "download3",
            &[],
            &[
                "%|O4321(NEW)|G00X1.|M30|%",
                "|O4321|M30|%",
                "%|O4321|M30|O4322|M30|%",
                "gen:3000",
                "gen:1280",
                "gen:1281",
                "gen:2560",
                "gen:2561",
                "gen:6000",
                "%|O4321|M30|% 0",
                "%|O4321|M30|% -1",
                "%|O1234|M30|%",
                "%|O4321|G0X1?|M30|%",
                "%|(NO|NUMBER)|M30|%",
            ],
        )
    },
    Word {
        setup: &["dwnstart3 0", "dwnstart3 0", "upstart3 0 1234 1234"],
        after: &["dwnend3", "upstart3 0 4321 4321", "upload3 4096", "upend3"],
        ..wc("download4", &[], &["%|O4321|M30|%"])
    },
    Word {
        setup: &["dwnstart3 0", "download3 %|O4321|M30|%"],
        after: &["dwnend3", "upstart4 0 O4321", "upload4 4096", "upend4"],
        ..wc("dwnend3", &[], &[""])
    },
    Word {
        setup: &["dwnstart3 0", "download3 gen:3000", "download3 gen:3000"],
        after: &["download3 gen:100", "dwnend3"],
        ..wc("download4", &[], &["gen:700"])
    },
    Word {
        after: &[
            "download4 %|O4321|M30|%",
            "dwnend4",
            "upstart4 0 O4321",
            "upload4 4096",
            "upend4",
        ],
        ..wc(
            "dwnstart4",
            &[],
            &[
                "0 //CNC_MEM/USER/PATH1/",
                "0",
                "1 O4321",
                "-1 O4321",
                "0 //CNC_MEM/USER/\\xc4RGER/",
            ],
        )
    },
    wc("dwnend4", &[], &[""]),
    Word {
        after: &[
            "download %|O4321|M30|%",
            "dwnend",
            "upstart 4321",
            "upload 300",
            "upend",
        ],
        ..wc("dwnstart", &[], &[""])
    },
    Word {
        setup: &["dwnstart"],
        after: &["dwnend", "upstart 4321", "upload 300", "upend"],
        ..wc(
            "download",
            &[],
            &[
                "%|O4321|M30|%",
                "%|O4321|M30|% 0",
                "%|O4321|M30|% 256",
                "%|O4321|M30|% 257",
            ],
        )
    },
    wc("dwnend", &[], &[""]),
    Word {
        after: &["dnc %|O4321|M30|%", "dncend"],
        ..wc("dncstart", &[], &[""])
    },
    Word {
        setup: &["dncstart"],
        after: &["dnc %|O4321|M30|%", "dncend"],
        ..wc(
            "dnc",
            &[],
            &[
                "%|O4321|G00X1.|M30|%",
                "gen:3000",
                "%|O4321|% 0",
                "%|O4321|% 40959",
                "%|O4321|% 40960",
            ],
        )
    },
    wc("dncend", &[], &[""]),
    Word {
        after: &["dnc2 %|O4321|M30|%", "dncend2 -1"],
        ..wc("dncstart2", &[], &["O4321", "X"])
    },
    Word {
        setup: &["dncstart2 O4321"],
        after: &["dncend2 -1"],
        ..wc("dnc2", &[], &["%|O4321|M30|%", "%|O4321|M30|% 0"])
    },
    Word {
        setup: &["dncstart2 O4321", "dnc2 %|O4321|M30|%"],
        after: &["dncend2 -1"],
        ..wc("dncend2", &[], &["-1", "-32768", "0", "1", "-2"])
    },
    // Machine data (issue 11): operation history 4, operator message 3,
    // control signals, program restart information.
    wc(
        "rdophistry4",
        &[
            "1|0|2|4|5|-1",
            "10|1|0|3|4|100",
            "4096|0|4|16|20|24|30|80|100",
        ],
        &["2 2 4096", "1 1 24", "3 4 44", "4 1 4096"],
    ),
    wc(
        "rdopmsg3",
        &["0|-1|1|2|3|4|5|-2", "5|1|0|-1|2|6|12"],
        &["-1 12", "4 1"],
    ),
    w("rdctrldi", &[]),
    // The signals the operation history records: datano, type, entries
    // filled (a pattern), 0 for NULL, then entry 1's ent_no, pmc_no,
    // sig_no, sig_name.
    Word {
        after: &["rdhissgnl3"],
        writes: true,
        ..wc(
            "wrhissgnl3",
            &["1|0|-1|61", "60|0|1|3|61|-1|100", "60|0|3", "1|0"],
            &[
                "1 1 60 1 0",
                "1 1 60 1 61",
                "1 1 60 1 -1",
                "1 1 60 1 1 0",
                "1 1 60 1 1 2",
                "1 1 60 1 1 -1",
                "1 1 60 1 1 1 -1",
                "1 1 60 1 1 1 0 4",
                "1 1 60 1 1 1 0 -1",
                "1 3 3 1",
                "1 5 3 1",
                "1 1000 60 1",
            ],
        )
    },
    w("rdctrldo", &[]),
    // After a reset that interrupted the running program: restart data.
    Word {
        setup: &["reset"],
        ..w("rdprstrinfo", &[])
    },
];

/// The C function a word calls.
pub fn function(word: &str) -> String {
    match word {
        "rdparam_ext32" => "cnc_rdparam_ext".into(),
        "rddiag_ext32" => "cnc_rddiag_ext".into(),
        "alloc" | "thread_alloc" => "cnc_allclibhndl3".into(),
        "alloc4" => "cnc_allclibhndl4".into(),
        "free" | "thread_free" => "cnc_freelibhndl".into(),
        "thread_statinfo" => "cnc_statinfo".into(),
        "startup" => "cnc_startupprocess".into(),
        "exitprocess" => "cnc_exitprocess".into(),
        w if w.starts_with("pmc_") || w.starts_with("fwlib_") => w.into(),
        w => format!("cnc_{w}"),
    }
}

fn detail_word(word: &str) -> &'static str {
    if word.starts_with("pmc_") {
        "pmc_getdtailerr"
    } else {
        "getdtailerr"
    }
}

/// The argument lists of a word: base, then each dimension varied alone,
/// then the explicit combinations (duplicates left out).
pub fn arg_lists(w: &Word) -> Vec<(String, String)> {
    let dims: Vec<Vec<&str>> = w.dims.iter().map(|d| d.split('|').collect()).collect();
    let base: Vec<&str> = dims.iter().map(|d| d[0]).collect();
    let mut out: Vec<(String, String)> = Vec::new();
    let mut push = |label: String, args: Vec<&str>| {
        let a = args.join(" ");
        if !out.iter().any(|(_, x)| *x == a) {
            out.push((label, a));
        }
    };
    if !dims.is_empty() || w.combos.is_empty() {
        push("base".into(), base.clone());
    }
    for (i, d) in dims.iter().enumerate() {
        for v in &d[1..] {
            let mut a = base.clone();
            a[i] = v;
            push(format!("a{}_{}", i + 1, v.replace('-', "m")), a);
        }
    }
    for c in w.combos {
        push(
            format!("c_{}", c.replace(' ', "_").replace('-', "m")),
            c.split(' ').collect(),
        );
    }
    out
}

fn cmd(word: &str, args: &str) -> String {
    if args.is_empty() {
        word.to_string()
    } else {
        format!("{word} {args}")
    }
}

/// The calls of one case of word `w` with `args`.
fn calls_for(
    w: &Word,
    args: &str,
    shape: Option<Shape>,
    prefix: &[&str],
) -> Vec<(String, Option<Shape>)> {
    let mut v: Vec<(String, Option<Shape>)> =
        prefix.iter().map(|c| (c.to_string(), None)).collect();
    v.extend(w.setup.iter().map(|c| (c.to_string(), None)));
    v.push((cmd(w.word, args), shape));
    v.push((detail_word(w.word).to_string(), None));
    v.extend(w.after.iter().map(|c| (c.to_string(), None)));
    v
}

/// The reply shapes every word's base call is recorded with.
pub const SHAPES: &[(&str, Shape)] = &[
    ("err1", Shape::Error(0, 1)),
    ("err2", Shape::Error(0, 2)),
    ("err3", Shape::Error(0, 3)),
    ("err4", Shape::Error(0, 4)),
    ("err5", Shape::Error(0, 5)),
    ("err6", Shape::Error(0, 6)),
    ("err7", Shape::Error(0, 7)),
    ("errm1", Shape::Error(0, -1)),
    ("err_sub2", Shape::Error(1, 5)),
    ("err_sub3", Shape::Error(2, 5)),
    ("empty", Shape::Empty(0)),
    ("half", Shape::Half(0)),
    ("short1", Shape::MinusOne(0)),
    ("longer", Shape::Longer(0, 8)),
    ("longer_sub2", Shape::Longer(1, 4)),
    ("missing_sub2", Shape::Missing(1)),
    ("half_sub2", Shape::Half(1)),
];

pub const CLASSES: &[&str] = &["v3", "v2", "s15"];

/// The profile a word's cases of a class run on. FANUC's 16i form of
/// cnc_rdposition reads a name entry (16 bytes) and a unit pair for every
/// axis of the path's maximum, with four 0x26 answers of that many records,
/// all in one frame of at most 1450 bytes: a 16i with 32 axes per path (the
/// built-in profile's maximum) cannot answer it (at most 5 name entries fit),
/// so its 16i-class cases run on a 16i with 8 axes per path.
pub fn class_profile(word: &str, profile: &'static str) -> &'static str {
    match (word, profile) {
        ("rdposition", "v2") => "v2a8",
        ("rdposition", "v2p2") => "v2p2a8",
        _ => profile,
    }
}

/// The words sent only to a punch press (profiles v3pu, v2pu).
const PUNCH_WORDS: &[&str] = &["rdtooldata", "rdtoolinfo"];

/// Every case of one word.
pub fn cases_of(w: &Word) -> Vec<Case> {
    let mut out = Vec::new();
    let mut case = |name: String, profile: &'static str, calls| {
        out.push(Case {
            name,
            profile,
            fault: None,
            calls,
            timeout: 10,
        })
    };
    let lists = arg_lists(w);
    let write_profiles: &[&'static str] = if w.writes { &["v3w", "v2w"] } else { &[] };
    // Punch-press functions: every case on a punch press too (on the mill
    // profiles FANUC's library sends nothing).
    if PUNCH_WORDS.contains(&w.word) {
        for profile in ["v3pu", "v2pu"] {
            for (label, args) in &lists {
                case(
                    format!("{profile}_{label}"),
                    profile,
                    calls_for(w, args, None, &[]),
                );
            }
            for (label, shape) in SHAPES {
                case(
                    format!("{profile}_shape_{label}"),
                    profile,
                    calls_for(w, &lists[0].1, Some(*shape), &[]),
                );
            }
        }
    }
    for profile in write_profiles {
        for (label, args) in &lists {
            case(
                format!("{profile}_{label}"),
                profile,
                calls_for(w, args, None, &[]),
            );
        }
    }
    for (pi, profile) in CLASSES.iter().enumerate() {
        let profile = class_profile(w.word, profile);
        for (label, args) in &lists {
            // Every variation on the 30i and 16i classes; Series 15 gets
            // the base and the combinations.
            if pi == 2 && label.starts_with('a') {
                continue;
            }
            case(
                format!("{profile}_{label}"),
                profile,
                calls_for(w, args, None, &[]),
            );
        }
    }
    let base = &lists[0].1;
    for profile in ["v3", "v2"] {
        let profile = class_profile(w.word, profile);
        for (label, shape) in SHAPES {
            case(
                format!("{profile}_shape_{label}"),
                profile,
                calls_for(w, base, Some(*shape), &[]),
            );
        }
    }
    for profile in ["v3", "v2", "s15"] {
        for (k, payload) in replies(w.word).into_iter().enumerate() {
            // A 16i's frames hold at most 1450 bytes.
            if profile != "v3" && payload.len() > 1400 {
                continue;
            }
            case(
                format!("{profile}_reply{k}"),
                profile,
                calls_for(w, base, Some(Shape::Payload(0, payload)), &[]),
            );
        }
    }
    if w.word != "setpath" {
        case(
            "v3p2_path2".into(),
            "v3p2",
            calls_for(w, base, None, &["setpath 2"]),
        );
        case(
            "v3p2_path3".into(),
            "v3p2",
            calls_for(w, base, None, &["setpath 3"]),
        );
        let p2 = class_profile(w.word, "v2p2");
        case(
            format!("{p2}_path2"),
            p2,
            calls_for(w, base, None, &["setpath 2"]),
        );
    }
    out
}

/// Connection set-up cases (cnc_allclibhndl3): every handshake step broken.
pub fn connect_cases() -> Vec<Case> {
    let faults: &[(&str, Fault)] = &[
        ("refused", Fault::Refuse),
        ("close_open1", Fault::CloseOpen(1)),
        ("close_open2", Fault::CloseOpen(2)),
        ("silent_open1", Fault::SilentOpen(1)),
        ("silent_open2", Fault::SilentOpen(2)),
        ("short_open1", Fault::ShortOpen(1)),
        ("short_open2", Fault::ShortOpen(2)),
        ("sysinfo_err1", Fault::SysinfoError(1)),
        ("sysinfo_err6", Fault::SysinfoError(6)),
        ("sysinfo_errm1", Fault::SysinfoError(-1)),
        ("sysinfo_silent", Fault::SysinfoSilent),
        ("sysinfo_close", Fault::SysinfoClose),
        ("probe_err1", Fault::ProbeError(1)),
        ("probe_err6", Fault::ProbeError(6)),
        ("probe_half", Fault::ProbeHalf),
    ];
    let mut out = Vec::new();
    for profile in CLASSES {
        for (label, f) in faults {
            if label.starts_with("probe") && *profile == "v3" {
                continue; // the 30i class makes no option probe
            }
            out.push(Case {
                name: format!("{profile}_{label}"),
                profile,
                fault: Some(*f),
                calls: vec![("statinfo".into(), None), ("getdtailerr".into(), None)],
                timeout: 1,
            });
        }
    }
    out
}

/// Crafted answers a word's base call is recorded with too (the payload of
/// its first reply subpacket): record types and layouts the simulator's
/// machine never sends.
fn replies(word: &str) -> Vec<&'static [u8]> {
    let leak = |v: Vec<u8>| -> &'static [u8] { Box::leak(v.into_boxed_slice()) };
    match word {
        "rdophistry4" => [
            (0, 9, &[0, 1, 2, 3, 4, 5, 6, 7, 8][..]),
            (0, 8, &[9, 10, 11, 12, 0xffff, 13, 0, 1]),
            // Type 13 sends FANUC's record loop to index 9.
            (0, 5, &[0, 1, 13, 2, 3]),
            (0, 4, &[0, 1, 14, 2]),
            // More to come: the next exchange asks the simulator from 3.
            (1, 2, &[0, 1]),
            // A count beyond the records sent.
            (0, 5, &[0, 1, 2]),
            (0, -1, &[0]),
        ]
        .into_iter()
        .map(|(more, count, types)| leak(op4_answer(more, count, types)))
        .collect(),
        "rdctrldi" | "rdctrldo" => [&[0x11, 0x22][..], &[1, 2, 3, 4, 5, 6, 7, 8], &[0xa5; 64]]
            .into_iter()
            .collect(),
        // The block counter answer (subpacket 1): more words than its
        // member holds run on into the next members.
        "rdprstrinfo" => [1, 3, 40, 100]
            .into_iter()
            .map(|n| {
                leak(
                    (1..=n)
                        .flat_map(|k: i32| (0x100 + k).to_be_bytes())
                        .collect(),
                )
            })
            .collect(),
        // An answer with less text than the 256 bytes (a Series 15 writes
        // nothing then).
        "rdopmsg" => vec![leak(opmsg3_answer(&[(2001, 0, "SHORT")])[..40].to_vec())],
        "rdopmsg3" => [
            &[(2001, 0, "CHECK COOLANT"), (70001, 4, "WORLD")][..],
            &[(1, 0, "A"); 6],
            &[(-1, 2, "")],
        ]
        .into_iter()
        .map(|msgs| leak(opmsg3_answer(msgs)))
        .chain([leak(opmsg3_answer(&[(7, 1, "SHORT")])[..267].to_vec())])
        .chain([leak({
            let mut b = opmsg3_answer(&[(9, 0, "LONG")]);
            b[8..12].copy_from_slice(&300i32.to_be_bytes());
            b.extend([0x5a; 20]);
            b
        })])
        .collect(),
        _ => Vec::new(),
    }
}

/// An operation history 4 answer: the more flag, the count, then one
/// record of each type, its bytes a pattern (length and type in front).
fn op4_answer(more: i32, count: i32, types: &[u16]) -> Vec<u8> {
    let wire = |t: u16| match t {
        0 => 20,
        1 | 7 => 40,
        2 | 8 => 36,
        3 | 5 => 32,
        4 | 11 | 13 => 28,
        6 => 276,
        9 => 456,
        10 => 520,
        12 => 16,
        0xffff => 4,
        _ => 20,
    };
    let mut b = more.to_be_bytes().to_vec();
    b.extend(count.to_be_bytes());
    for (i, &t) in types.iter().enumerate() {
        let n = wire(t);
        let mut r: Vec<u8> = (0..n).map(|k| (7 * i + 1 + k) as u8).collect();
        r[0..2].copy_from_slice(&(n as u16).to_be_bytes());
        r[2..4].copy_from_slice(&t.to_be_bytes());
        b.extend(r);
    }
    b
}

/// Operator message 3 records: i32 number, type, characters, 256 text
/// bytes (0xab past the text, to see what is copied).
fn opmsg3_answer(msgs: &[(i32, i32, &str)]) -> Vec<u8> {
    let mut b = Vec::new();
    for (n, t, text) in msgs {
        b.extend(n.to_be_bytes());
        b.extend(t.to_be_bytes());
        b.extend((text.len() as i32).to_be_bytes());
        let mut x = text.as_bytes().to_vec();
        x.resize(256, 0xab);
        b.extend(x);
    }
    b
}
