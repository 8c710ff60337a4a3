//! Where our library differs from FANUC's on purpose, for the oracle's
//! recorded cases (tests/vectors/): each entry names the cases and the
//! reason a user would accept. The shared golden set's table is in
//! tests/vectors.rs (DEVIATIONS); README.md lists both.

use super::common::Case;

pub struct Deviation {
    /// The vector file's function.
    pub function: &'static str,
    /// Case names: exact, or a prefix ending in `*`.
    pub cases: &'static [&'static str],
    pub reason: &'static str,
}

pub const ORACLE: &[Deviation] = &[
    Deviation {
        function: "cnc_rdcount",
        cases: &[
            "rdcount_v2_shape_empty",
            "rdcount_v2_shape_half",
            "rdcount_v2_shape_short1",
            "rdcount_v3_shape_empty",
            "rdcount_v3_shape_half",
            "rdcount_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rddiaginfo",
        cases: &["rddiaginfo_v2_shape_empty", "rddiaginfo_v3_shape_empty"],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rddiagnum",
        cases: &[
            "rddiagnum_v2_shape_empty",
            "rddiagnum_v2_shape_half",
            "rddiagnum_v2_shape_short1",
            "rddiagnum_v3_shape_empty",
            "rddiagnum_v3_shape_half",
            "rddiagnum_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdlife",
        cases: &[
            "rdlife_v2_shape_empty",
            "rdlife_v2_shape_half",
            "rdlife_v2_shape_short1",
            "rdlife_v3_shape_empty",
            "rdlife_v3_shape_half",
            "rdlife_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdmacro",
        cases: &[
            "rdmacro_v2_a1_0",
            "rdmacro_v2_a1_1",
            "rdmacro_v2_a1_1000",
            "rdmacro_v2_a1_10000",
            "rdmacro_v2_a1_32767",
            "rdmacro_v2_a1_m1",
            "rdmacro_v2_a1_m32768",
            "rdmacro_v2_shape_empty",
            "rdmacro_v2_shape_err1",
            "rdmacro_v2_shape_err2",
            "rdmacro_v2_shape_err3",
            "rdmacro_v2_shape_err4",
            "rdmacro_v2_shape_err5",
            "rdmacro_v2_shape_err6",
            "rdmacro_v2_shape_err7",
            "rdmacro_v2_shape_errm1",
            "rdmacro_v2_shape_half",
            "rdmacro_v2_shape_short1",
            "rdmacro_v3_a1_0",
            "rdmacro_v3_a1_1",
            "rdmacro_v3_a1_1000",
            "rdmacro_v3_a1_10000",
            "rdmacro_v3_a1_32767",
            "rdmacro_v3_a1_m1",
            "rdmacro_v3_a1_m32768",
            "rdmacro_v3_shape_empty",
            "rdmacro_v3_shape_err1",
            "rdmacro_v3_shape_err2",
            "rdmacro_v3_shape_err3",
            "rdmacro_v3_shape_err4",
            "rdmacro_v3_shape_err5",
            "rdmacro_v3_shape_err6",
            "rdmacro_v3_shape_err7",
            "rdmacro_v3_shape_errm1",
            "rdmacro_v3_shape_half",
            "rdmacro_v3_shape_short1",
        ],
        reason: "FANUC's library writes datano and an uninitialised mcr_val (different on every run) even when the CNC answers an error or a short or empty answer; ours writes nothing unless the call returns EW_OK, EW_PROTOCOL for a short answer",
    },
    Deviation {
        function: "cnc_rdmacroinfo",
        cases: &[
            "rdmacroinfo_v2_shape_empty",
            "rdmacroinfo_v2_shape_half",
            "rdmacroinfo_v2_shape_short1",
            "rdmacroinfo_v3_shape_empty",
            "rdmacroinfo_v3_shape_half",
            "rdmacroinfo_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdmacror2",
        cases: &["rdmacror2_v2_shape_longer", "rdmacror2_v3_shape_longer"],
        reason: "FANUC's library writes every double the CNC sends, past the requested *num (an overrun); ours writes at most *num",
    },
    Deviation {
        function: "cnc_rdntool",
        cases: &["rdntool_v2_shape_empty", "rdntool_v3_shape_empty"],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdparainfo",
        cases: &["rdparainfo_v2_shape_empty", "rdparainfo_v3_shape_empty"],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdparainfo",
        cases: &["rdparainfo_v2_shape_longer", "rdparainfo_v3_shape_longer"],
        reason: "FANUC's library writes every entry the CNC sends, past read_no (an overrun); ours caps info_no at read_no",
    },
    Deviation {
        function: "cnc_rdparam",
        cases: &["rdparam_v2_shape_empty", "rdparam_v3_shape_empty"],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdparanum",
        cases: &[
            "rdparanum_v2_shape_empty",
            "rdparanum_v2_shape_half",
            "rdparanum_v2_shape_short1",
            "rdparanum_v3_shape_empty",
            "rdparanum_v3_shape_half",
            "rdparanum_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdtofs",
        cases: &[
            "rdtofs_v2_shape_empty",
            "rdtofs_v2_shape_half",
            "rdtofs_v2_shape_short1",
            "rdtofs_v3_shape_empty",
            "rdtofs_v3_shape_half",
            "rdtofs_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdtofsinfo",
        cases: &[
            "rdtofsinfo_v2_shape_empty",
            "rdtofsinfo_v2_shape_half",
            "rdtofsinfo_v2_shape_short1",
            "rdtofsinfo_v3_shape_empty",
            "rdtofsinfo_v3_shape_half",
            "rdtofsinfo_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdtofsr",
        cases: &["rdtofsr_v2_shape_short1", "rdtofsr_v3_shape_short1"],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdtoolgrp",
        cases: &[
            "rdtoolgrp_v2_shape_empty",
            "rdtoolgrp_v2_shape_half",
            "rdtoolgrp_v2_shape_short1",
            "rdtoolgrp_v3_shape_empty",
            "rdtoolgrp_v3_shape_half",
            "rdtoolgrp_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdzofs",
        cases: &[
            "rdzofs_v2_shape_empty",
            "rdzofs_v2_shape_half",
            "rdzofs_v2_shape_short1",
            "rdzofs_v3_shape_empty",
            "rdzofs_v3_shape_half",
            "rdzofs_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_rdzofsinfo",
        cases: &[
            "rdzofsinfo_v2_shape_empty",
            "rdzofsinfo_v2_shape_half",
            "rdzofsinfo_v2_shape_short1",
            "rdzofsinfo_v3_shape_empty",
            "rdzofsinfo_v3_shape_half",
            "rdzofsinfo_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "cnc_toolnum",
        cases: &["toolnum_v2_shape_empty", "toolnum_v3_shape_empty"],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "pmc_rdpmcinfo",
        cases: &[
            "pmc_rdpmcinfo_v2_shape_empty",
            "pmc_rdpmcinfo_v2_shape_half",
            "pmc_rdpmcinfo_v2_shape_short1",
            "pmc_rdpmcinfo_v3_shape_empty",
            "pmc_rdpmcinfo_v3_shape_half",
            "pmc_rdpmcinfo_v3_shape_short1",
        ],
        reason: "FANUC's library reads the bytes a short or empty answer lacks from its receive buffer, which still holds the request's and earlier frames' bytes (e.g. cnc_rdparam's datano becomes the axis asked), and returns EW_OK with them; ours returns EW_PROTOCOL (-17) and writes nothing",
    },
    Deviation {
        function: "pmc_rdpmcrng",
        cases: &[
            "pmc_rdpmcrng_v2_shape_longer",
            "pmc_rdpmcrng_v3_shape_longer",
        ],
        reason: "FANUC's library copies the whole reply into the caller's buffer, past the requested range and length; ours writes no more than they hold",
    },
];

fn matches(pat: &str, name: &str) -> bool {
    match pat.strip_suffix('*') {
        Some(p) => name.starts_with(p),
        None => pat == name,
    }
}

/// The deviation a recorded case is listed under, if any.
pub fn oracle(case: &Case) -> Option<&'static Deviation> {
    ORACLE
        .iter()
        .find(|d| d.function == case.function && d.cases.iter().any(|p| matches(p, &case.name)))
}
