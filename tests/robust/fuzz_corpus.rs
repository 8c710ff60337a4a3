//! The fuzz corpora (fuzz/corpus/<target>/, docs/reliability.md "Fuzzing") replayed
//! through the fuzz targets' own entry points (fuzz/fuzzing.rs, included), so CI
//! needs no fuzzer: every input must decode without a panic. And every
//! function whose recorded vectors show a data answer has a decoder in the
//! `reply` target.

use crate::fuzzing;

use std::path::Path;

fn replay(target: &str, run: fn(&[u8])) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz/corpus")
        .join(target);
    let mut n = 0;
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    for p in files {
        let data = std::fs::read(&p).unwrap();
        let r = std::panic::catch_unwind(|| run(&data));
        assert!(r.is_ok(), "{target}: {} panicked", p.display());
        n += 1;
    }
    assert!(n > 0, "{target}: empty corpus");
    println!("{target}: {n} inputs");
}

#[test]
fn reply_corpus_decodes() {
    replay("reply", fuzzing::reply);
}

#[test]
fn request_corpus_decodes() {
    replay("request", fuzzing::request);
}

#[test]
fn profile_corpus_loads() {
    replay("profile", fuzzing::profile);
}

/// The inputs that crashed a target before their fix (fuzz/regressions/<target>/).
#[test]
fn found_defects_stay_fixed() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/regressions");
    for (target, run) in [
        ("reply", fuzzing::reply as fn(&[u8])),
        ("request", fuzzing::request),
        ("profile", fuzzing::profile),
    ] {
        let Ok(dir) = std::fs::read_dir(root.join(target)) else {
            continue;
        };
        for e in dir {
            let p = e.unwrap().path();
            let data = std::fs::read(&p).unwrap();
            let r = std::panic::catch_unwind(|| run(&data));
            assert!(r.is_ok(), "{} crashes again", p.display());
        }
    }
}

#[test]
fn the_decoders_name_exported_functions() {
    // The first two input bytes choose among them: all must be reachable.
    assert!(fuzzing::decoders() <= 65536);
    for name in fuzzing::hand_written_names() {
        assert!(
            fwlib32::ffi::exports::export(name).is_some(),
            "{name} is not exported"
        );
        assert!(
            fwlib32::spec::FUNCS.iter().all(|f| f.name != name),
            "{name} is described in src/spec/table/: its decoder is the table's"
        );
    }
}

#[test]
fn every_function_answered_with_data_has_a_decoder() {
    use fwlib32::ffi::exports::{How, export};
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/vectors");
    let mut missing = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_stem().unwrap().to_str().unwrap().to_string();
        let text = std::fs::read_to_string(&p).unwrap();
        let traffic = text.contains("\"type\": \"2102\"");
        let ours = matches!(
            export(&name).map(|e| e.how),
            Some(How::Written { .. } | How::Described)
        );
        // Functions without a data exchange of their own (handles, paths,
        // timeouts, error details, the upload frames) have no decoder.
        let local = [
            "cnc_freelibhndl",
            "cnc_setpath",
            "cnc_getpath",
            "cnc_settimeout",
            "cnc_getdtailerr",
            "pmc_getdtailerr",
            "cnc_sysinfo",
            "cnc_sysinfo_ex",
            "cnc_startupprocess",
            "cnc_exitprocess",
            "cnc_resetconnect",
            "cnc_allclibhndl4",
            "pmc_get_current_pmc_unit",
            "cnc_upstart",
            "cnc_upstart3",
            "cnc_upstart4",
            "cnc_upload",
            "cnc_cupload",
            "cnc_upend",
            // Download and DNC: connection 1's frames, no data answer.
            "cnc_dwnstart",
            "cnc_download",
            "cnc_dwnend",
            "cnc_dwnstart3",
            "cnc_download3",
            "cnc_dwnend3",
            "cnc_dwnstart4",
            "cnc_download4",
            "cnc_dwnend4",
            "cnc_dncstart",
            "cnc_dnc",
            "cnc_dncend",
            "cnc_dncstart2",
            "cnc_dnc2",
            "cnc_dncend2",
        ];
        if traffic && ours && !local.contains(&name.as_str()) && fuzzing::decoder(&name).is_none() {
            missing.push(name);
        }
    }
    assert!(
        missing.is_empty(),
        "add these to the decoders of fuzz/fuzzing.rs: {missing:?}"
    );
}
