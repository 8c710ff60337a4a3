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
        function: "cnc_acts2",
        cases: &[
            "acts2_v3_shape_empty",
            "acts2_v3_shape_half",
            "acts2_v3_shape_short1",
        ],
        reason: COUNT_PAST_PAYLOAD,
    },
    Deviation {
        function: "cnc_rddynamic",
        cases: &[
            "rddynamic_v3_shape_empty",
            "rddynamic_v3_shape_half",
            "rddynamic_v3_shape_short1",
            "rddynamic_v3_shape_missing_sub2",
            "rddynamic_v3_shape_half_sub2",
            "rddynamic_v2_shape_empty",
            "rddynamic_v2_shape_half",
            "rddynamic_v2_shape_short1",
            "rddynamic_v2_shape_missing_sub2",
            "rddynamic_v2_shape_half_sub2",
        ],
        reason: FIELDS_PAST_PAYLOAD,
    },
    Deviation {
        function: "cnc_rddynamic2",
        cases: &[
            "rddynamic2_v3_shape_empty",
            "rddynamic2_v3_shape_half",
            "rddynamic2_v3_shape_short1",
            "rddynamic2_v3_shape_missing_sub2",
            "rddynamic2_v3_shape_half_sub2",
            "rddynamic2_v2_shape_empty",
            "rddynamic2_v2_shape_half",
            "rddynamic2_v2_shape_short1",
            "rddynamic2_v2_shape_missing_sub2",
            "rddynamic2_v2_shape_half_sub2",
        ],
        reason: FIELDS_PAST_PAYLOAD,
    },
    Deviation {
        function: "cnc_rdspload",
        cases: &[
            "rdspload_v3_shape_empty",
            "rdspload_v3_shape_half",
            "rdspload_v3_shape_short1",
        ],
        reason: COUNT_PAST_PAYLOAD,
    },
];

/// cnc_acts2 / cnc_rdspload on the 30i class.
const COUNT_PAST_PAYLOAD: &str = "FANUC's library reads the spindle count of an empty or one-byte 0xa4 payload from the bytes after it (the next subpacket's header); ours returns EW_PROTOCOL (-17) and writes nothing";

/// cnc_rddynamic / cnc_rddynamic2.
const FIELDS_PAST_PAYLOAD: &str = "FANUC's library reads the fields of a payload shorter than them from the next subpacket's header, and with a subpacket missing reads the later ones shifted, writing that into the caller's struct; ours returns EW_PROTOCOL (-17) and writes nothing";

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
