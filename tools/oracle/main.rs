//! The differential oracle: FANUC's library against ours, call by call.
//!
//! ```text
//! cargo run --example oracle -- record  --lib FANUC.so [--only WORD] [--out tests/vectors]
//! cargo run --example oracle -- compare --lib FANUC.so [--ours OUR.so] [--only WORD]
//! cargo run --example oracle -- verify  --lib LIB.so [FILE.json ...]
//! cargo run --example oracle -- list    [--only WORD]
//! cargo run --release --example oracle -- fuzz --lib FANUC.so [--seconds N] [--seed S] [--only f,g]
//! cargo run --release --example oracle -- learn --lib FANUC.so [--lib FANUC32.so] --header fwlib32.h [--only f,g] [--check | --unexported] [--out FILE]
//! ```
//!
//! `record` runs every generated case (tools/oracle/cases.rs) against a
//! fake CNC (our simulator behind a recording, reply-shaping proxy) with the
//! given library, and writes what crossed the wire and what the library
//! returned and wrote as vector files. `compare` runs each case with both
//! libraries against identical fake CNCs and prints every difference.
//! `verify` replays committed vector files to a library. Nothing is
//! downloaded: the library's path is given (or `ORACLE_LIB`).

#[path = "../../tests/common/mod.rs"]
mod common;

mod cases;
#[allow(dead_code)]
#[path = "../../tests/deviations/mod.rs"]
mod deviations;
mod fake;
mod fuzz;
mod learn;
mod probe;
mod profiles;
mod replay;

use cases::Case;
use fake::{Fake, Rec};
use probe::{Answer, Probe};
use profiles::profile;
use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// The simulator's clock for every case: both runs of a case see one state.
const ELAPSED: Duration = Duration::from_millis(2500);

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// One call as it ran live.
struct Ran {
    cmd: String,
    answer: Answer,
    frames: Vec<Rec>,
}

fn word(cmd: &str) -> &str {
    cmd.split_whitespace().next().unwrap_or("")
}

/// Records a call that has just returned, with the frames the fake CNC saw
/// for it; true when the probe crashed (the case ends there). Sockets are
/// closed as the call returns: the proxy is given a moment to see it.
fn record(fake: &Fake, cmd: String, answer: Answer, ran: &mut Vec<Ran>) -> bool {
    let settle = matches!(word(&cmd), "alloc" | "free" | "exitprocess" | "setpath");
    let frames = fake.take(Duration::from_millis(if settle { 20 } else { 1 }));
    let crashed = matches!(answer, Answer::Crashed(_));
    ran.push(Ran {
        cmd,
        answer,
        frames,
    });
    crashed
}

/// Runs a case live against a fresh fake CNC; None when its reply shape
/// changed nothing (a duplicate of the plain case).
fn run_live(case: &Case, probe_exe: &Path, lib: &Path) -> Option<Vec<Ran>> {
    let fake = Fake::start(profile(case.profile), ELAPSED, case.fault);
    let mut p = Probe::spawn(std::process::Command::new(probe_exe), lib, fake.port);
    let alloc = if case.fault == Some(fake::Fault::Refuse) {
        format!("alloc {} 127.0.0.1 {}", case.timeout, replay::DEAD_PORT)
    } else {
        format!("alloc {}", case.timeout)
    };
    let mut all: Vec<(String, Option<fake::Shape>)> =
        vec![("startup 1 fwlib.log".into(), None), (alloc, None)];
    all.extend(case.calls.iter().cloned());
    all.push(("free".into(), None));
    let mut ran = Vec::new();
    let mut shaped = false;
    for (cmd, shape) in all {
        fake.shape_next(shape);
        let answer = p.call(&cmd);
        shaped |= fake.shape_done();
        if record(&fake, cmd, answer, &mut ran) {
            break;
        }
    }
    p.finish();
    let wanted_shape = case.calls.iter().any(|c| c.1.is_some());
    (!wanted_shape || shaped).then_some(ran)
}

fn hex(b: &[u8]) -> String {
    b.iter().map(|x| format!("{x:02x}")).collect()
}

fn ranges(b: &[u8]) -> Vec<[usize; 2]> {
    let mut out: Vec<[usize; 2]> = Vec::new();
    for (i, x) in b.iter().enumerate() {
        if *x != 0xCC {
            match out.last_mut() {
                Some(r) if r[1] == i => r[1] = i + 1,
                _ => out.push([i, i + 1]),
            }
        }
    }
    out
}

fn call_json(r: &Ran) -> Value {
    let frames: Vec<Value> = r
        .frames
        .iter()
        .map(|f| {
            let mut v = json!({"conn": f.conn, "dir": f.dir});
            if !f.bytes.is_empty() {
                v["type"] = json!(format!("{:02x}{:02x}", f.bytes[6], f.bytes[7]));
                v["hex"] = json!(hex(&f.bytes));
            }
            v
        })
        .collect();
    let mut v = json!({"probe_cmd": r.cmd, "frames": frames});
    match &r.answer {
        Answer::Done {
            ret,
            fields,
            b0,
            b1,
        } => {
            v["return"] = json!(ret);
            let (n0, n1) = probe::buffer_names(word(&r.cmd));
            let mut outs = serde_json::Map::new();
            for (name, b) in [(n0, b0), (n1, b1)] {
                if !b.is_empty() {
                    outs.insert(
                        name.into(),
                        json!({"written_ranges": ranges(b), "hex": hex(b)}),
                    );
                }
            }
            v["outputs"] = Value::Object(outs);
            for (k, x) in fields {
                v[k] = json!(x);
            }
        }
        Answer::Missing(f) => v["missing"] = json!(f),
        Answer::Crashed(why) => {
            v["crashed"] = json!(true);
            v["notes"] = json!(why);
        }
    }
    v
}

struct Args {
    cmd: String,
    lib: Option<PathBuf>,
    /// `--lib` given again (learn: the functions the first lacks).
    more_libs: Vec<PathBuf>,
    ours: Option<PathBuf>,
    only: Vec<String>,
    out: PathBuf,
    files: Vec<PathBuf>,
    seconds: u64,
    seed: u64,
    header: Option<PathBuf>,
    check: bool,
    unexported: bool,
}

fn args() -> Args {
    let mut a = std::env::args().skip(1);
    let mut r = Args {
        cmd: a.next().unwrap_or_default(),
        lib: std::env::var_os("ORACLE_LIB").map(PathBuf::from),
        more_libs: Vec::new(),
        ours: None,
        only: Vec::new(),
        out: root().join("tests/vectors"),
        files: Vec::new(),
        seconds: 60,
        seed: 1,
        header: None,
        check: false,
        unexported: false,
    };
    let mut lib_given = false;
    while let Some(x) = a.next() {
        match x.as_str() {
            "--lib" if lib_given => r.more_libs.extend(a.next().map(PathBuf::from)),
            "--lib" => {
                lib_given = true;
                r.lib = a.next().map(PathBuf::from)
            }
            "--ours" => r.ours = a.next().map(PathBuf::from),
            "--header" => r.header = a.next().map(PathBuf::from),
            "--check" => r.check = true,
            "--unexported" => r.unexported = true,
            "--only" => r.only.extend(
                a.next()
                    .into_iter()
                    .flat_map(|s| s.split(',').map(String::from).collect::<Vec<_>>()),
            ),
            "--out" => r.out = a.next().map(PathBuf::from).unwrap_or(r.out),
            "--seconds" => r.seconds = a.next().and_then(|x| x.parse().ok()).unwrap_or(60),
            "--seed" => {
                r.seed = a
                    .next()
                    .and_then(|x| match x.strip_prefix("0x") {
                        Some(h) => u64::from_str_radix(h, 16).ok(),
                        None => x.parse().ok(),
                    })
                    .unwrap_or(1)
            }
            f => r.files.push(PathBuf::from(f)),
        }
    }
    r
}

/// Every generated case, by the C function its vector file is named after.
fn generated(only: &[String]) -> BTreeMap<String, Vec<Case>> {
    let mut by_fn: BTreeMap<String, Vec<Case>> = BTreeMap::new();
    // A vector file holds every word of its function: asking for one word
    // records its function's other words too (rdparam_ext and rdparam_ext32).
    let functions: Vec<String> = only.iter().map(|w| cases::function(w)).collect();
    let keep = |w: &str| only.is_empty() || functions.contains(&cases::function(w));
    for w in cases::words().iter().filter(|w| keep(w.word)) {
        by_fn.entry(cases::function(w.word)).or_default().extend(
            cases::cases_of(w).into_iter().map(|mut c| {
                c.name = format!("{}_{}", w.word, c.name);
                c
            }),
        );
    }
    if keep("alloc") {
        by_fn
            .entry("cnc_allclibhndl3".into())
            .or_default()
            .extend(cases::connect_cases());
    }
    if keep("getdtailerr") {
        by_fn
            .entry("cnc_getdtailerr".into())
            .or_default()
            .extend(cases::detail_cases());
    }
    by_fn
}

fn our_lib() -> PathBuf {
    // The profile this oracle was built with (target/release/examples/oracle).
    let release = std::env::current_exe()
        .ok()
        .is_some_and(|e| e.components().any(|c| c.as_os_str() == "release"));
    let dir = root().join(if release {
        "target/release"
    } else {
        "target/debug"
    });
    let so = dir.join("libfwlib32.so");
    let mut args = vec!["build", "--lib"];
    if release {
        args.push("--release");
    }
    let status =
        std::process::Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
            .args(&args)
            .arg("--manifest-path")
            .arg(root().join("Cargo.toml"))
            .status();
    assert!(
        status.is_ok_and(|s| s.success()),
        "cargo build --lib failed"
    );
    so
}

fn main() {
    let a = args();
    // A 32-bit library (FANUC's x86 build) needs a probe built with -m32:
    // record, learn and list only (compare, verify and fuzz run our 64-bit
    // library with the same probe).
    let m32 = a.lib.as_deref().is_some_and(probe::elf32);
    if m32 && !matches!(a.cmd.as_str(), "record" | "learn" | "list") {
        eprintln!(
            "oracle {}: a 32-bit library can be recorded and learnt only",
            a.cmd
        );
        std::process::exit(2);
    }
    let probe_exe = probe::build_for(
        &root(),
        &std::env::temp_dir().join(format!("focas-oracle-{}", std::process::id())),
        m32,
    );
    let need_lib = || {
        a.lib
            .clone()
            .unwrap_or_else(|| panic!("give the library: --lib PATH or ORACLE_LIB=PATH"))
    };
    match a.cmd.as_str() {
        "list" => {
            let mut n = 0;
            for (f, cs) in generated(&a.only) {
                println!("{f}: {} cases", cs.len());
                n += cs.len();
            }
            println!("{n} cases");
        }
        "record" => {
            let lib = need_lib();
            std::fs::create_dir_all(&a.out).expect("output directory");
            let (mut total, mut skipped) = (0, 0);
            for (function, cs) in generated(&a.only) {
                let mut out = Vec::new();
                for c in &cs {
                    match run_live(c, &probe_exe, &lib) {
                        Some(ran)
                            if !ran.iter().any(|r| matches!(r.answer, Answer::Missing(_))) =>
                        {
                            let crashed =
                                ran.iter().any(|r| matches!(r.answer, Answer::Crashed(_)));
                            if crashed {
                                eprintln!(
                                    "{function}/{}: the library crashed; not recorded",
                                    c.name
                                );
                                skipped += 1;
                                continue;
                            }
                            out.push(json!({
                                "name": c.name,
                                "profile": c.profile,
                                "calls": ran.iter().map(call_json).collect::<Vec<_>>(),
                            }));
                        }
                        _ => skipped += 1,
                    }
                }
                total += out.len();
                if out.is_empty() {
                    continue;
                }
                let file = json!({
                    "function": function,
                    "source": format!("recorded by tools/oracle from FANUC's Linux {} library against focas-sim behind the oracle's reply-shaping proxy", if m32 { "x86 (32-bit)" } else { "x86-64" }),
                    "cases": out,
                });
                let path = a.out.join(format!("{function}.json"));
                std::fs::write(&path, serde_json::to_string_pretty(&file).unwrap() + "\n")
                    .expect("write vector file");
                println!("{}: {} cases", path.display(), out.len());
            }
            println!(
                "recorded {total} cases ({skipped} left out: duplicates, crashes, missing functions)"
            );
        }
        "compare" => {
            let lib = need_lib();
            let ours = a.ours.clone().unwrap_or_else(our_lib);
            let (mut n, mut bad) = (0, 0);
            for (function, cs) in generated(&a.only) {
                for c in &cs {
                    let (Some(f), Some(o)) = (
                        run_live(c, &probe_exe, &lib),
                        run_live(c, &probe_exe, &ours),
                    ) else {
                        continue;
                    };
                    n += 1;
                    let d = diff(&f, &o);
                    if !d.is_empty() {
                        bad += 1;
                        println!(
                            "DIFF {function}/{} ({})\n{}",
                            c.name,
                            c.profile,
                            d.join("\n")
                        );
                    }
                }
            }
            println!("{n} cases compared, {bad} differ");
        }
        "verify" => {
            let lib = need_lib();
            let files = if a.files.is_empty() {
                vector_files(&a.out)
            } else {
                a.files.clone()
            };
            let (mut n, mut bad) = (0, 0);
            for f in files {
                for c in common::load_file(&f).cases {
                    n += 1;
                    let m =
                        replay::replay_case(|| std::process::Command::new(&probe_exe), &lib, &c);
                    if !m.is_empty() {
                        bad += 1;
                        println!("DIFF {}/{}\n{}", c.function, c.name, m.join("\n"));
                    }
                }
            }
            println!("{n} cases verified, {bad} differ");
        }
        "learn" => {
            let opts = learn::Opts {
                lib: need_lib(),
                header: a
                    .header
                    .clone()
                    .unwrap_or_else(|| panic!("give FANUC's header: --header PATH")),
                only: a.only.clone(),
                out: a.files.first().cloned().or_else(|| {
                    std::env::args()
                        .skip_while(|x| x != "--out")
                        .nth(1)
                        .map(PathBuf::from)
                }),
                check: a.check,
                unexported: a.unexported,
                // each further library with a probe of its own width
                more: a
                    .more_libs
                    .iter()
                    .enumerate()
                    .map(|(k, l)| {
                        let dir = std::env::temp_dir()
                            .join(format!("focas-oracle-{}-{k}", std::process::id()));
                        (l.clone(), probe::build_for(&root(), &dir, probe::elf32(l)))
                    })
                    .collect(),
            };
            let code = learn::run(&opts, &probe_exe);
            let _ = std::fs::remove_dir_all(probe_exe.parent().unwrap());
            for (_, exe) in &opts.more {
                let _ = std::fs::remove_dir_all(exe.parent().unwrap());
            }
            std::process::exit(code);
        }
        "fuzz" => {
            let opts = fuzz::Opts {
                fanuc: need_lib(),
                ours: a.ours.clone().unwrap_or_else(our_lib),
                seconds: a.seconds,
                seed: a.seed,
                only: a.only.clone(),
                out: a.out.clone(),
            };
            let code = fuzz::fuzz(&opts, &probe_exe);
            let _ = std::fs::remove_dir_all(probe_exe.parent().unwrap());
            std::process::exit(code);
        }
        _ => {
            eprintln!(
                "usage: oracle record|compare|verify|list|fuzz|learn [--lib PATH] [--header PATH] [--check] [--unexported] [--ours PATH] [--only WORD,..] [--out DIR] [FILES]"
            );
            std::process::exit(2);
        }
    }
    let _ = std::fs::remove_dir_all(probe_exe.parent().unwrap());
}

pub fn vector_files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "json"))
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// Call by call: requests, return codes, outputs, counts.
fn diff(fanuc: &[Ran], ours: &[Ran]) -> Vec<String> {
    let mut out = Vec::new();
    for (f, o) in fanuc.iter().zip(ours) {
        let reqs = |r: &Ran| {
            r.frames
                .iter()
                .filter(|x| x.dir == "req")
                .map(|x| hex(&x.bytes))
                .collect::<Vec<_>>()
        };
        if reqs(f) != reqs(o) {
            out.push(format!(
                "  `{}`: requests differ\n    fanuc {:?}\n    ours  {:?}",
                f.cmd,
                reqs(f),
                reqs(o)
            ));
        }
        if f.answer != o.answer {
            out.push(format!(
                "  `{}`: fanuc {:?}\n    ours  {:?}",
                f.cmd,
                short(&f.answer),
                short(&o.answer)
            ));
        }
    }
    if fanuc.len() != ours.len() {
        out.push(format!(
            "  {} calls ran with fanuc's, {} with ours",
            fanuc.len(),
            ours.len()
        ));
    }
    out
}

fn short(a: &Answer) -> String {
    match a {
        Answer::Done {
            ret,
            fields,
            b0,
            b1,
        } => format!("ret {ret} {fields:?} b0 {} b1 {}", hex(b0), hex(b1)),
        other => format!("{other:?}"),
    }
}
