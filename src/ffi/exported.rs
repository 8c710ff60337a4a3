//! The functions src/ffi/ exports by hand, as data: build.rs writes the
//! export table from it (`ffi::exports::EXPORTS`: which are written, in
//! which area, which answer a fixed code, which are our extensions) and
//! keeps the extensions out of fwlib32.h. The described functions are not
//! here: build.rs writes them from src/spec/table/. A test checks this list
//! against the `pub extern "C" fn`s of src/ffi/*.rs, and tests/artifacts/artifacts.rs
//! against the library's symbols.
//!
//! Compiled into build.rs too (`#[path]`): plain data only (`crate::ew` is
//! src/ew.rs there as here).

use crate::ew::EW_MMCSYS;
use std::os::raw::c_short;

/// The functions written by hand in src/ffi/<area>.rs: (area, names).
#[rustfmt::skip]
pub const WRITTEN: &[(&str, &[&str])] = &[
    ("alarm", &[
        "cnc_rdalmmsg", "cnc_rdalmmsg2", "cnc_rdalminfo", "cnc_rdopmsg",
        "cnc_rdopmsg3", "cnc_rdalmhistry", "cnc_rdalmhistry2",
    ]),
    ("axisdata", &["cnc_rdsvmeter", "cnc_rdspmeter", "cnc_rdaxisdata"]),
    ("download", &[
        "cnc_dwnstart", "cnc_download", "cnc_dwnend", "cnc_dwnstart3", "cnc_download3",
        "cnc_dwnend3", "cnc_dwnstart4", "cnc_download4", "cnc_dwnend4", "cnc_dncstart", "cnc_dnc",
        "cnc_dncend", "cnc_dncstart2", "cnc_dnc2", "cnc_dncend2",
    ]),
    ("dynamic", &["cnc_rddynamic2", "cnc_rddynamic", "cnc_rddynamico8"]),
    ("folder", &[
        "cnc_pdf_rdactpt", "cnc_pdf_wractpt", "cnc_rdpdf_line", "cnc_wrpdf_line",
        "cnc_rdpdf_subdir", "cnc_rdpdf_alldir",
    ]),
    ("handle", &[
        "cnc_startupprocess", "cnc_exitprocess", "cnc_allclibhndl3", "cnc_allclibhdl3",
        "cnc_allclibhndl4", "cnc_freelibhndl", "cnc_resetconnect", "cnc_settimeout", "cnc_getpath",
        "cnc_setpath", "cnc_getdtailerr",
    ]),
    ("history", &[
        "cnc_rdophistry", "cnc_rdophistry4", "cnc_rdomhistry", "cnc_rdomhistry2",
        "cnc_rdalmhistry5", "cnc_rdpitchr", "cnc_wrhissgnl3",
    ]),
    ("machine", &["cnc_rdprstrinfo"]),
    ("macros", &[
        "cnc_rdmacro", "cnc_wrmacro", "cnc_rdmacror", "cnc_wrmacror",
    ]),
    ("memory", &[
        "cnc_rdprogdir2", "cnc_rdmdiprog", "cnc_wrmdiprog", "cnc_rdproginfo", "cnc_rdprogdir2o8",
    ]),
    ("offset", &[
        "cnc_rdtofs", "cnc_wrtofs", "cnc_rdtofsr", "cnc_rdzofs", "cnc_wrzofs", "cnc_wrwkcdshft",
        "cnc_rdzofsr",
    ]),
    ("param", &["cnc_wrparas"]),
    ("paraminfo", &[
        "cnc_rdparainfo", "cnc_rddiaginfo", "cnc_rdparam_ext", "cnc_rddiag_ext", "cnc_rdparainfo3",
    ]),
    ("pmc", &[
        "pmc_rdpmcrng", "pmc_wrpmcrng", "pmc_getdtailerr", "pmc_rdpmcinfo", "pmc_select_pmc_unit",
        "pmc_get_pmc_unit_types", "pmc_rdalmmsg",
    ]),
    ("position", &[
        "cnc_rdposition",
       
        "cnc_getfigure",
    ]),
    ("program", &[
        "cnc_rdexecprog", "cnc_modal", "cnc_gettimer",
        "cnc_settimer", "cnc_rdprogdir", "cnc_rdprogdir3",
        "cnc_rdprogdiro8",
    ]),
    ("spindle", &[
        "cnc_acts2", "cnc_rdspeed", "cnc_rdspload", "cnc_rdspmaxrpm", "cnc_rdspgear",
    ]),
    ("status", &[
        "cnc_sysinfo", "cnc_sysinfo_ex", "cnc_statinfo", "cnc_statinfo2",
    ]),
    ("tool", &[
        "cnc_rdtoolgrp", "cnc_rdtlctldata", "cnc_instlifedt", "cnc_wrgrpinfo",
        "cnc_rdtlusegrp", "cnc_rdtool", "cnc_rdtooldata", "cnc_rdtoolinfo",
    ]),
    ("upload", &[
        "cnc_upstart", "cnc_upstart3", "cnc_upstart4", "cnc_upload3", "cnc_upload4", "cnc_upload",
        "cnc_cupload", "cnc_upend3", "cnc_upend4", "cnc_upend",
    ]),
];

/// FANUC's functions that none of its Ethernet libraries implements and
/// that take no handle (src/ffi/absent.rs), with the `EW_*` code each
/// answers without traffic (there read from here); those on a handle are
/// table entries (src/spec/table/absent.rs).
pub const ABSENT: &[(&str, c_short)] = &[("cnc_allclibhndl", EW_MMCSYS)];

/// Our `fwlib_*` extensions (src/ffi/ext.rs), declared in fwlib32_ext.h only.
pub const EXTENSIONS: &[&str] = &[
    "fwlib_set_reconnect",
    "fwlib_batch_begin",
    "fwlib_batch_end",
    "fwlib_batch_limits",
];

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    /// The names of the `pub extern "C" fn`s of src/ffi/<area>.rs.
    fn written_in(area: &str) -> BTreeSet<String> {
        let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("src/ffi/{area}.rs"));
        std::fs::read_to_string(p)
            .unwrap()
            .lines()
            .filter(|l| l.trim_start().starts_with("pub "))
            .filter_map(|l| l.split_once("extern \"C\" fn ").map(|(_, r)| r))
            .map(|r| {
                r.chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect()
            })
            .collect()
    }

    fn set<'a>(names: impl IntoIterator<Item = &'a str>) -> BTreeSet<String> {
        names.into_iter().map(str::to_owned).collect()
    }

    #[test]
    fn the_lists_are_the_ffi_files_functions() {
        let mut areas: Vec<String> =
            std::fs::read_dir(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/ffi"))
                .unwrap()
                .map(|e| e.unwrap().path())
                .filter(|p| p.extension().is_some_and(|x| x == "rs"))
                .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
                .filter(|a| !written_in(a).is_empty())
                .collect();
        areas.sort();
        let mut listed: Vec<String> = WRITTEN.iter().map(|(a, _)| a.to_string()).collect();
        listed.extend(["absent".to_string(), "ext".to_string()]);
        listed.sort();
        assert_eq!(areas, listed, "the areas of src/ffi/ that export functions");
        for (area, names) in WRITTEN {
            assert_eq!(
                written_in(area),
                set(names.iter().copied()),
                "src/ffi/{area}.rs"
            );
        }
        assert_eq!(written_in("absent"), set(ABSENT.iter().map(|a| a.0)));
        assert_eq!(written_in("ext"), set(EXTENSIONS.iter().copied()));
        assert!(
            WRITTEN.iter().all(|a| !a.1.is_empty()),
            "an area lists no function"
        );
    }
}
