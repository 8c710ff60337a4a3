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
        function: "cnc_rdcncid",
        cases: &["rdcncid_v3_shape_longer", "rdcncid_v2_shape_longer"],
        reason: "FANUC's library writes every word of a longer answer, past the four of the caller's buffer; ours writes at most four",
    },
    Deviation {
        function: "cnc_rdexecprog",
        cases: &["rdexecprog_v3_a1_0", "rdexecprog_v2_a1_0"],
        reason: "with *length 0 FANUC's library sets *length 65535 and writes text past the caller's buffer; ours writes *blknum and *length 0 only",
    },
    Deviation {
        function: "cnc_rdexecprog",
        cases: &[
            "rdexecprog_v3_shape_empty",
            "rdexecprog_v2_shape_empty",
            "rdexecprog_v3p2_path2",
            "rdexecprog_v2p2_path2",
        ],
        reason: "an empty answer (an idle path) makes FANUC's library set *length 65532 and read past its receive buffer into the caller's; ours gives *length 0 and an empty string",
    },
    Deviation {
        function: "cnc_rdopmode",
        cases: &["rdopmode_v3_shape_longer", "rdopmode_v2_shape_longer"],
        reason: "FANUC's library writes every word of a longer answer, past the caller's short; ours writes one",
    },
    Deviation {
        function: "cnc_rdprgnum",
        cases: &["rdprgnum_v3_shape_err*", "rdprgnum_v2_shape_err*"],
        reason: "when the CNC answers an error FANUC's library writes uninitialised stack bytes into data and mdata; ours writes nothing",
    },
    Deviation {
        function: "cnc_rdprogdir3",
        cases: &[
            "rdprogdir3_v3_a2_9999",
            "rdprogdir3_v2_a2_9999",
            "rdprogdir3_v3_shape_empty",
            "rdprogdir3_v2_shape_empty",
        ],
        reason: "with no program found FANUC's library sets *top_prog from the first record of the caller's buffer (whatever it held); ours leaves *top_prog as given",
    },
    Deviation {
        function: "cnc_statinfo",
        cases: &["statinfo_v3_shape_longer", "statinfo_v2_shape_longer"],
        reason: "FANUC's library writes every status word of a longer answer, past ODBST; ours writes the seven the struct holds",
    },
    Deviation {
        function: "cnc_statinfo",
        cases: &["statinfo_v3_shape_half_sub2", "statinfo_v2_shape_half_sub2"],
        reason: "an empty handle-retrace answer makes FANUC's library read the next subpacket's length as hdck; ours returns EW_PROTOCOL and writes nothing",
    },
    Deviation {
        function: "cnc_statinfo2",
        cases: &["statinfo2_v3_shape_longer", "statinfo2_v2_shape_longer"],
        reason: "FANUC's library writes every status word of a longer answer, past ODBST2; ours writes the eleven the struct holds",
    },
    Deviation {
        function: "cnc_statinfo2",
        cases: &[
            "statinfo2_v3_shape_half_sub2",
            "statinfo2_v2_shape_half_sub2",
        ],
        reason: "an empty handle-retrace answer makes FANUC's library read the next subpacket's length as hdck; ours returns EW_PROTOCOL and writes nothing",
    },
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
