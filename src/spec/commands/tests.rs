//! The registry's tests: every command number is written in src/spec/commands.rs
//! only, and the registry agrees with the table, the codec and the simulator.

use super::*;
use std::path::{Path, PathBuf};

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Every .rs file of src/ but the registry's: (path from src/, its code with
/// comments cut).
fn code() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &mut files);
    files.sort();
    assert!(files.len() > 50, "src/ has {} files", files.len());
    files
        .iter()
        .map(|p| {
            let rel = p
                .strip_prefix(&root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            let text = std::fs::read_to_string(p).unwrap();
            let code: Vec<&str> = text
                .lines()
                .map(|l| match l.find("//") {
                    Some(i) if !l[..i].contains('"') => &l[..i],
                    _ => l,
                })
                .collect();
            (rel, code.join("\n"))
        })
        .filter(|(rel, _)| !rel.starts_with("spec/commands"))
        .collect()
}

/// The identifier after each match of `prefix` in `text` (its last
/// path segment), where one follows.
fn names_after<'a>(text: &'a str, prefix: &str) -> Vec<&'a str> {
    text.match_indices(prefix)
        .filter_map(|(i, _)| {
            let rest = text[i + prefix.len()..].trim_start();
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(rest.len());
            let path = &rest[..end];
            let last = path.rsplit("::").next()?;
            (!last.is_empty()).then_some(last)
        })
        .collect()
}

#[test]
fn each_command_is_listed_once_with_the_exported_functions_sending_it() {
    for (i, c) in COMMANDS.iter().enumerate() {
        for d in &COMMANDS[..i] {
            assert!(
                (d.class, d.cmd) != (c.class, c.cmd),
                "{} and {} are both ({}, {:#06x})",
                d.name,
                c.name,
                c.class,
                c.cmd
            );
            assert_ne!(d.name, c.name);
        }
        assert!(c.class == CLASS_CNC || c.class == CLASS_PMC, "{}", c.name);
        assert!(!c.senders.is_empty(), "{} names no function", c.name);
        for (k, f) in c.senders.iter().enumerate() {
            assert!(
                crate::ffi::exports::export(f).is_some(),
                "{}: {f} is not an exported function",
                c.name
            );
            assert!(!c.senders[..k].contains(f), "{}: {f} twice", c.name);
        }
    }
    assert!(COMMANDS.len() >= 150, "{} commands", COMMANDS.len());
}

#[test]
fn every_command_the_codec_sends_is_registered_with_its_senders() {
    // The table: each form's command, with its function among the senders.
    for f in crate::spec::FUNCS {
        // Without a form, the answer is the library's own on every class
        // (pmc_get_current_pmc_unit), or a code (pmc_rdmsg).
        let local = f
            .local
            .is_some_and(|l| l.classes == crate::spec::Classes::All)
            || f.answers().is_some();
        assert!(!f.forms.is_empty() || local, "{} sends nothing", f.name);
        for form in f.forms {
            let c = find(form.class, form.cmd).unwrap_or_else(|| {
                panic!(
                    "{}: ({}, {:#06x}) is not registered",
                    f.name, form.class, form.cmd
                )
            });
            assert!(
                c.senders.contains(&f.name),
                "{}: {} does not name it as a sender",
                f.name,
                c.name
            );
        }
    }
    // The hand-written requests and the simulator's arms: each constant
    // a command of the class it is sent or matched as.
    let (mut seen, mut by_class) = (0, 0);
    for (file, text) in code() {
        for (prefix, class) in [
            ("ReqSub::cnc(", CLASS_CNC),
            ("ReqSub::pmc(", CLASS_PMC),
            ("(CLASS_CNC, ", CLASS_CNC),
            ("(CLASS_PMC, ", CLASS_PMC),
            ("Route::cnc(", CLASS_CNC),
            ("Route::table(", CLASS_CNC),
            ("Route::pmc(", CLASS_PMC),
            ("Route::pmc_table(", CLASS_PMC),
        ] {
            for name in names_after(&text, prefix) {
                if !name.starts_with(|c: char| c.is_ascii_uppercase()) {
                    continue; // a variable: its value comes from a constant
                }
                let c = COMMANDS.iter().find(|c| c.name == name);
                let c = c.unwrap_or_else(|| {
                    panic!("src/{file}: {prefix}{name}: not a registered command")
                });
                assert_eq!(c.class, class, "src/{file}: {prefix}{name}");
                seen += 1;
                by_class += usize::from(!prefix.starts_with("ReqSub"));
            }
        }
    }
    // Requests built in the area files and the simulator's rows were met.
    assert!(
        seen > 150 && by_class > 60,
        "{seen} commands, {by_class} arms"
    );
}

#[test]
fn no_source_file_but_the_registry_writes_a_command_number() {
    // Constants of u16 numbers that are not commands: frame types, the
    // first handle, a port, a record type, value bases.
    const NOT_COMMANDS: &[(&str, &str)] = &[
        ("proto/frame.rs", "OPEN_REQ"),
        ("proto/frame.rs", "OPEN_RESP"),
        ("proto/frame.rs", "OPEN_REJECT"),
        ("proto/frame.rs", "CLOSE_REQ"),
        ("proto/frame.rs", "CLOSE_RESP"),
        ("proto/frame.rs", "DATA_REQ"),
        ("proto/frame.rs", "DATA_RESP"),
        ("proto/frame.rs", "UPLOAD_START_REQ"),
        ("proto/frame.rs", "UPLOAD_START_RESP"),
        ("proto/frame.rs", "UPLOAD_DATA"),
        ("proto/frame.rs", "UPLOAD_END"),
        ("proto/frame.rs", "UPLOAD_END_ACK"),
        ("proto/frame.rs", "UPLOAD_ABORT"),
        ("proto/frame.rs", "ID_REQ"),
        ("proto/frame.rs", "ID_RESP"),
        ("proto/frame.rs", "ID_REJECT"),
        ("proto/frame.rs", "CLIENT_VERSION"),
        ("client/handles.rs", "FIRST"),
        ("native/cnc.rs", "DEFAULT_PORT"),
        ("proto/history/op4.rs", "OP4_RESTART_TYPE"),
        ("proto/value.rs", "BASE_10"),
        ("proto/value.rs", "BASE_2"),
    ];
    // Where a command is written: a number right after one of these.
    const AT: &[&str] = &[
        "every_class(",
        "pmc(",
        "cmd: ",
        "cmd == ",
        "ReqSub::cnc(",
        "ReqSub::pmc(",
        "ReqSub::with_class(",
        "(CLASS_CNC, ",
        "(CLASS_PMC, ",
        "function_commands(",
        "command_name(CLASS_CNC, ",
        "command_name(CLASS_PMC, ",
    ];
    let mut bad = Vec::new();
    let mut consts = 0;
    for (file, text) in code() {
        for at in AT {
            for (i, _) in text.match_indices(at) {
                let rest = text[i + at.len()..].trim_start();
                if rest.starts_with(|c: char| c.is_ascii_digit()) {
                    let line = text[..i].lines().count();
                    bad.push(format!(
                        "src/{file}:{line}: {at}{}",
                        &rest[..rest.len().min(8)]
                    ));
                }
            }
        }
        for line in text.lines() {
            let l = line.trim_start();
            let Some(rest) = l.split_once("const ").map(|(_, r)| r) else {
                continue;
            };
            let Some((name, value)) = rest.split_once(": u16 =") else {
                continue;
            };
            if value.trim_start().starts_with(|c: char| c.is_ascii_digit())
                && !NOT_COMMANDS.contains(&(file.as_str(), name.trim()))
            {
                bad.push(format!("src/{file}: const {}", rest.trim()));
            }
            consts += 1;
        }
    }
    assert!(consts > 10, "{consts} u16 constants seen");
    assert!(
        bad.is_empty(),
        "command numbers outside src/spec/commands.rs:\n{}",
        bad.join("\n")
    );
}
