//! COMPATIBILITY.md, generated: one row for every cnc_*/pmc_* function
//! FANUC's fwlib32.h declares (tools/compat/fanuc-functions.txt, names
//! only), saying whether we export it and how (fwlib32::ffi::exports, the
//! table build.rs writes from the exports' sources), on which CNC classes
//! and in how many cases it was checked against FANUC's library
//! (tests/vectors/), what the simulator answers (measured here: the oracle's
//! base call of every exported function through its probe, or the first
//! other generated argument list the simulator answers EW_OK, against the
//! simulator on the 30i, 16i and Series 15 classes; about 3 s) and the
//! deviations of tests/deviations/mod.rs with their reasons.
//!
//! The test regenerates the file in memory and fails when the committed one
//! differs; `FWLIB32_UPDATE_COMPAT=1 cargo test --test recorded compat::` writes it.
//! It also checks the measurements against the exports table: every export
//! answered, and those exported to answer EW_VERSION (EW_MMCSYS) do so
//! without a request on every class.

use crate::cases;
use crate::deviations;
use crate::fake;
use crate::probe;
use crate::profiles;
use crate::toolchain;

use fwlib32::ffi::exports::{EXPORTS, Export, How};
use fwlib32::native::Ew;
use probe::{Answer, Probe};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::time::Duration;

const UPDATE_VAR: &str = "FWLIB32_UPDATE_COMPAT";

/// The simulator's clock for every measured call, as the oracle's.
const ELAPSED: Duration = Duration::from_millis(2500);

/// The CNC classes, in column order: (profile of the oracle, name).
const CLASSES: &[(&str, &str)] = &[("v3", "30i"), ("v2", "16i"), ("s15", "Series 15")];

/// Probe calls for the exported functions the oracle's case generator does
/// not cover (no FANUC Ethernet library has them, or they are ours), each
/// measured like a generated word's base call: (word, arguments).
const EXTRA: &[(&str, &str)] = &[
    ("allclibhdl3", "10"),
    ("allclibhndl", ""),
    ("fwlib_set_reconnect", "1"),
    ("fwlib_batch_begin", ""),
    ("fwlib_batch_end", "16"),
    ("fwlib_batch_limits", "16 4126"),
];

fn root() -> PathBuf {
    toolchain::manifest_dir()
}

// ---------------------------------------------------------------------------
// The facts
// ---------------------------------------------------------------------------

/// tools/compat/fanuc-functions.txt: (name, exported by FANUC's Linux library).
fn fanuc_functions() -> Vec<(String, bool)> {
    let path = root().join("tools/compat/fanuc-functions.txt");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let v: Vec<(String, bool)> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let mut w = l.split_whitespace();
            let (name, linux) = (w.next().unwrap(), w.next());
            assert!(
                matches!(linux, Some("linux" | "-")) && w.next().is_none(),
                "{}: bad line {l:?}",
                path.display()
            );
            (name.to_string(), linux == Some("linux"))
        })
        .collect();
    assert!(
        v.windows(2).all(|w| w[0].0 < w[1].0),
        "{}: not sorted",
        path.display()
    );
    v
}

/// One case recorded from FANUC's library.
struct RecCase {
    name: String,
    profile: String,
    /// The functions it calls (its own, the detail word's, set-up and
    /// read-backs): each call's return and outputs are compared.
    calls: BTreeSet<String>,
}

/// The recorded cases by the function their vector file is named after.
type Recorded = BTreeMap<String, Vec<RecCase>>;

/// The `"key": "value"` strings of a pretty-printed vector file with their
/// offsets.
fn values<'a>(text: &'a str, key: &str) -> Vec<(usize, &'a str)> {
    let pat = format!("\"{key}\": \"");
    text.match_indices(&pat)
        .map(|(i, _)| {
            let rest = &text[i + pat.len()..];
            (i, &rest[..rest.find('"').unwrap_or(0)])
        })
        .collect()
}

/// tests/vectors/*.json: every case's name, profile and calls, by function.
/// The files are written by the oracle with their keys sorted: a case's
/// `calls` (each with its `probe_cmd`) come before its `name` and
/// `profile`, which are keys of the cases only.
fn recorded() -> Recorded {
    let dir = root().join("tests/vectors");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    let mut out = Recorded::new();
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let function = values(&text, "function");
        let (names, profiles) = (values(&text, "name"), values(&text, "profile"));
        assert!(
            function.len() == 1 && names.len() == profiles.len() && !names.is_empty(),
            "{}: one function and a name and profile per case expected",
            f.display()
        );
        let cmds = values(&text, "probe_cmd");
        let mut next = 0;
        let cases = out.entry(function[0].1.to_string()).or_default();
        for ((at, name), (_, profile)) in names.iter().zip(&profiles) {
            let mut calls = BTreeSet::new();
            while next < cmds.len() && cmds[next].0 < *at {
                calls.insert(cases::function(word_of(cmds[next].1)));
                next += 1;
            }
            cases.push(RecCase {
                name: name.to_string(),
                profile: profile.to_string(),
                calls,
            });
        }
    }
    out
}

/// The cases that check a function, by function: its own (its vector
/// file's), else those of other functions that call it (`cnc_upload3` in
/// `cnc_upstart3`'s), with the functions they are named after.
type Checks<'a> = BTreeMap<String, (Vec<&'a RecCase>, Vec<&'a str>)>;

fn checks(recorded: &Recorded) -> Checks<'_> {
    let mut out = Checks::new();
    for (f, cs) in recorded {
        for c in cs {
            for called in &c.calls {
                if recorded.contains_key(called) {
                    continue;
                }
                let e = out.entry(called.clone()).or_default();
                e.0.push(c);
                if e.1.last() != Some(&f.as_str()) {
                    e.1.push(f);
                }
            }
        }
    }
    for (f, cs) in recorded {
        out.insert(f.clone(), (cs.iter().collect(), Vec::new()));
    }
    out
}

/// The class a recorded profile belongs to (v3, v3w, v3p2: the 30i ...).
fn class_of(profile: &str) -> &'static str {
    CLASSES
        .iter()
        .find(|(p, _)| profile.starts_with(p))
        .map(|c| c.1)
        .unwrap_or_else(|| panic!("recorded profile {profile:?} of no class"))
}

// ---------------------------------------------------------------------------
// Measuring the simulator
// ---------------------------------------------------------------------------

/// One call as the simulator (through our library) answered it.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Seen {
    /// The return code; None when the probe found no such function or died.
    ret: Option<i64>,
    /// The library sent the CNC a request during the call.
    request: bool,
}

/// A call made while measuring: the function, what it answered, whether it
/// was the case's own call, and the function of the case it was made in.
struct Obs {
    function: String,
    seen: Seen,
    main: bool,
    /// A main call's probe command when not the base call.
    args: Option<String>,
    case: String,
}

fn word_of(cmd: &str) -> &str {
    cmd.split_whitespace().next().unwrap_or("")
}

/// The calls of one case of word `w` with `args`: a handle (unless the
/// word allocates its own), the word's set-up, the word (main), the detail
/// word and the calls after it, then every handle freed (so no connection,
/// upload or handle survives into the next case).
fn case_calls(w: &cases::Word, args: &str) -> Vec<(String, bool)> {
    let main = if args.is_empty() {
        w.word.to_string()
    } else {
        format!("{} {args}", w.word)
    };
    let detail = if w.word.starts_with("pmc_") {
        "pmc_getdtailerr"
    } else {
        "getdtailerr"
    };
    let mut v = Vec::new();
    if !matches!(w.word, "alloc4" | "allclibhdl3") {
        v.push(("alloc 10".to_string(), false));
    }
    v.extend(w.setup.iter().map(|c| (c.to_string(), false)));
    v.push((main, true));
    v.push((detail.to_string(), false));
    v.extend(w.after.iter().map(|c| (c.to_string(), false)));
    v.push(("exitprocess".to_string(), false));
    v
}

/// Runs each word against one simulator with `profile`, through one probe
/// process: its base case, and when the simulator does not answer that
/// with EW_OK, its other generated argument lists in turn until one is.
fn run_words(words: &[&cases::Word], profile: &str, probe_exe: &Path, lib: &Path) -> Vec<Obs> {
    let fake = fake::Fake::start(profiles::profile(profile), ELAPSED, None);
    let spawn = || Probe::spawn(toolchain::target_command(probe_exe), lib, fake.port);
    let mut p = spawn();
    let mut out = Vec::new();
    for w in words {
        let case = cases::function(w.word);
        for (i, (_, args)) in cases::arg_lists(w).iter().enumerate() {
            fake.take_sent(0);
            let mut main_ok = false;
            for (cmd, main) in case_calls(w, args) {
                let mut answer = p.call(&cmd);
                // A program polls an upload until its data has arrived.
                let polls = matches!(word_of(&cmd), "upload3" | "upload4" | "cupload");
                for _ in 0..400 {
                    match answer {
                        Answer::Done { ret: 10, .. } if polls => {
                            std::thread::sleep(Duration::from_millis(5));
                            answer = p.call(&cmd);
                        }
                        _ => break,
                    }
                }
                // Frames that have no answer (download and DNC data, an
                // upload's abort) may still be on their way: wait for the
                // bytes the probe saw the library write.
                let request = fake.take_sent(p.sent).iter().any(|r| r.dir == "req");
                let ret = match answer {
                    Answer::Done { ret, .. } => Some(ret),
                    _ => None,
                };
                // Another argument list counts when the CNC answered it.
                main_ok |= main && ret == Some(0) && (i == 0 || request);
                out.push(Obs {
                    function: cases::function(word_of(&cmd)),
                    seen: Seen { ret, request },
                    main,
                    args: (main && i > 0).then(|| cmd.clone()),
                    case: case.clone(),
                });
                if matches!(answer, Answer::Crashed(_)) {
                    p = spawn();
                    break;
                }
            }
            if main_ok {
                break;
            }
        }
    }
    p.finish();
    out
}

/// What the simulator answered one function on one class.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Answered {
    seen: Seen,
    /// Not the base call: this probe command.
    args: Option<String>,
    /// Measured in this other function's case (a call that needs it first).
    after: Option<String>,
}

/// What the simulator answered one function on one class: the case's own
/// call when it answered EW_OK (the base call, else the first other
/// argument list the CNC answered EW_OK: not one the library settled
/// without a request, as a count of 0), else an EW_OK in another
/// function's case (`cnc_upload3` after `cnc_upstart3`), else the own base
/// call's answer, else the first call seen.
fn pick(function: &str, obs: &[Obs]) -> Option<Answered> {
    let of: Vec<&Obs> = obs.iter().filter(|o| o.function == function).collect();
    let answered = |o: &Obs, after: Option<String>| Answered {
        seen: o.seen.clone(),
        args: o.args.clone(),
        after,
    };
    let served = |o: &&&Obs| o.seen.ret == Some(0) && (o.args.is_none() || o.seen.request);
    if let Some(o) = of.iter().filter(|o| o.main).find(served) {
        return Some(answered(o, None));
    }
    if let Some(o) = of.iter().filter(|o| !o.main).find(served) {
        // The handle every case allocates first needs nothing before it.
        let after =
            (o.case != function && o.function != "cnc_allclibhndl3").then(|| o.case.clone());
        return Some(answered(o, after));
    }
    of.iter()
        .find(|o| o.main && o.args.is_none())
        .or(of.first())
        .map(|o| answered(o, None))
}

/// Per function, per class (CLASSES order): what the simulator answered.
type Measured = BTreeMap<String, Vec<Option<Answered>>>;

fn measure() -> Measured {
    let lib = toolchain::cdylib();
    let probe_dir = toolchain::scratch("compat-probe"); // removed when the test ends
    let probe_exe = probe::build(&root(), &probe_dir);
    // The functions no Ethernet library of FANUC's has, by their words.
    let absent = fwlib32::spec::table::absent::ROWS
        .iter()
        .copied()
        .flatten()
        .map(|(name, _)| (name.strip_prefix("cnc_").unwrap_or(name), ""));
    let rows: &[(&str, &str)] = EXTRA
        .iter()
        .copied()
        .chain(absent)
        .collect::<Vec<_>>()
        .leak();
    let extra: Vec<cases::Word> = rows
        .iter()
        .map(|(word, args)| cases::Word {
            word,
            dims: &[],
            combos: std::slice::from_ref(args),
            setup: &[],
            after: &[],
            writes: false,
        })
        .collect();
    let generated = cases::words();
    let words: Vec<&cases::Word> = generated.iter().chain(&extra).collect();
    // One simulator and probe per profile: a class's profile, its
    // write-enabled form for writes.
    let mut groups: BTreeMap<(usize, String), Vec<&cases::Word>> = BTreeMap::new();
    for (ci, (class, _)) in CLASSES.iter().enumerate() {
        for w in &words {
            let p = cases::class_profile(w.word, class);
            let p = if w.writes {
                format!("{p}w")
            } else {
                p.to_string()
            };
            groups.entry((ci, p)).or_default().push(w);
        }
    }
    let runs: Vec<(usize, Vec<Obs>)> = std::thread::scope(|s| {
        let handles: Vec<_> = groups
            .iter()
            .map(|((ci, p), ws)| {
                let (lib, exe) = (&lib, &probe_exe);
                s.spawn(move || (*ci, run_words(ws, p, exe, lib)))
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    let mut by_class: Vec<Vec<Obs>> = CLASSES.iter().map(|_| Vec::new()).collect();
    for (ci, obs) in runs {
        by_class[ci].extend(obs);
    }
    let mut out = Measured::new();
    for e in EXPORTS {
        out.insert(
            e.name.to_string(),
            by_class.iter().map(|obs| pick(e.name, obs)).collect(),
        );
    }
    out
}

/// An answer: its code, and `no request` where the library sent none
/// (`with_request` false: left out, for a call measured after another
/// function's, whose requests depend on how far that got).
fn seen_text(s: &Seen, with_request: bool) -> String {
    let code = match s.ret {
        Some(r) => {
            let name = Ew(r as i16).name();
            if r == 0 {
                name.to_string()
            } else {
                format!("{name} ({r})")
            }
        }
        None => "no answer (function missing or the probe died)".to_string(),
    };
    if s.request || !with_request {
        code
    } else {
        format!("{code}, no request")
    }
}

/// The simulator cell: one answer, or the classes grouped by answer.
fn simulator_cell(per_class: &[Option<Answered>]) -> String {
    let texts: Vec<String> = per_class
        .iter()
        .map(|m| match m {
            None => "not measured".to_string(),
            Some(a) => {
                let mut t = seen_text(&a.seen, a.after.is_none());
                if let Some(cmd) = &a.args {
                    t = format!("{t} with `{cmd}`");
                }
                if let Some(after) = &a.after {
                    t = format!("{t} after `{after}`");
                }
                t
            }
        })
        .collect();
    if texts.iter().all(|t| *t == texts[0]) {
        return texts[0].clone();
    }
    let mut groups: Vec<(Vec<&str>, &str)> = Vec::new();
    for (i, t) in texts.iter().enumerate() {
        match groups.iter_mut().find(|g| g.1 == t) {
            Some(g) => g.0.push(CLASSES[i].1),
            None => groups.push((vec![CLASSES[i].1], t)),
        }
    }
    groups
        .iter()
        .map(|(cs, t)| format!("{}: {t}", cs.join(", ")))
        .collect::<Vec<_>>()
        .join("; ")
}

// ---------------------------------------------------------------------------
// The document
// ---------------------------------------------------------------------------

fn ours_cell(e: Option<&Export>) -> String {
    match e.map(|e| e.how) {
        None => "not exported".to_string(),
        Some(How::Written { area }) => format!("implemented (`src/ffi/{area}.rs`)"),
        Some(How::Described) if learnt(e.unwrap().name).is_some() => {
            "learnt from FANUC's library, as data (`src/spec/table/`)".to_string()
        }
        Some(How::Described) => "described as data (`src/spec/table/`)".to_string(),
        Some(How::NotOnEthernet { code, ew }) if ew == "EW_VERSION" => {
            format!("{ew} ({code}), as FANUC's Ethernet library")
        }
        Some(How::NotOnEthernet { code, ew }) => format!("{ew} ({code}): HSSB only"),
        Some(How::Extension) => "our extension (`fwlib32_ext.h`)".to_string(),
    }
}

/// What the learner left unsettled for a learnt table entry.
fn learnt(name: &str) -> Option<&'static [&'static str]> {
    fwlib32::spec::FUNCS
        .iter()
        .find(|f| f.name == name)
        .and_then(|f| f.learnt)
}

fn learnt_cell(name: &str) -> String {
    match learnt(name) {
        None => "—".to_string(),
        Some([]) => "nothing".to_string(),
        Some(open) => open.join("; "),
    }
}

fn checked_cell(checks: &Checks, function: &str) -> String {
    let Some((cases, of)) = checks.get(function) else {
        return "—".to_string();
    };
    let per: Vec<String> = CLASSES
        .iter()
        .filter_map(|(_, class)| {
            let n = cases
                .iter()
                .filter(|c| class_of(&c.profile) == *class)
                .count();
            (n > 0).then(|| format!("{class} {n}"))
        })
        .collect();
    let mut t = format!("{} ({})", cases.len(), per.join(", "));
    if !of.is_empty() {
        let of: Vec<String> = of.iter().map(|f| format!("`{f}`")).collect();
        t.push_str(&format!(", in the cases of {}", of.join(", ")));
    }
    t
}

/// GitHub's anchor of a `### name` heading.
fn anchor(name: &str) -> String {
    name.to_lowercase()
}

fn generate(measured: &Measured) -> String {
    let fanuc = fanuc_functions();
    let declared: BTreeSet<&str> = fanuc.iter().map(|f| f.0.as_str()).collect();
    let recorded = recorded();
    let checks = checks(&recorded);
    let export = |n: &str| EXPORTS.iter().find(|e| e.name == n);
    let devs_of = |n: &str| -> Vec<&deviations::Deviation> {
        deviations::ORACLE
            .iter()
            .filter(|d| d.function == n)
            .collect()
    };
    let sim = |n: &str| match measured.get(n) {
        Some(m) => simulator_cell(m),
        None => "—".to_string(),
    };
    let dev_cell = |n: &str| match devs_of(n).len() {
        0 => "—".to_string(),
        k => format!("[{k}](#{})", anchor(n)),
    };

    // The counts.
    let exported_declared: Vec<&Export> = EXPORTS
        .iter()
        .filter(|e| declared.contains(e.name))
        .collect();
    let count = |f: &dyn Fn(&How) -> bool| exported_declared.iter().filter(|e| f(&e.how)).count();
    let written = count(&|h| matches!(h, How::Written { .. }));
    let described = count(&|h| *h == How::Described);
    let version = count(&|h| {
        matches!(
            h,
            How::NotOnEthernet {
                ew: "EW_VERSION",
                ..
            }
        )
    });
    let other_absent = count(&|h| matches!(h, How::NotOnEthernet { .. })) - version;
    let linux = fanuc.iter().filter(|f| f.1).count();
    let missing_linux = fanuc
        .iter()
        .filter(|f| f.1 && export(&f.0).is_none())
        .count();
    let own_cases = declared
        .iter()
        .filter(|f| recorded.contains_key(**f))
        .count();
    let checked = declared.iter().filter(|f| checks.contains_key(**f)).count();
    let all_cases: Vec<&RecCase> = recorded.values().flatten().collect();
    let class_cases: Vec<String> = CLASSES
        .iter()
        .map(|(_, c)| {
            format!(
                "{c} {}",
                all_cases
                    .iter()
                    .filter(|x| class_of(&x.profile) == *c)
                    .count()
            )
        })
        .collect();
    let served: Vec<&Export> = exported_declared
        .iter()
        .copied()
        .filter(|e| !matches!(e.how, How::NotOnEthernet { .. }))
        .collect();
    let all_ok = served
        .iter()
        .filter(|e| {
            measured[e.name]
                .iter()
                .all(|m| m.as_ref().is_some_and(|a| a.seen.ret == Some(0)))
        })
        .count();
    let dev_functions: BTreeSet<&str> = deviations::ORACLE.iter().map(|d| d.function).collect();
    let beyond: Vec<&Export> = EXPORTS
        .iter()
        .filter(|e| !declared.contains(e.name))
        .collect();

    let mut s = String::new();
    s.push_str(
        "# Compatibility with FANUC's FOCAS2 library\n\n\
         <!-- GENERATED by tests/recorded/compat.rs: do not edit. Refresh with\n     \
         FWLIB32_UPDATE_COMPAT=1 cargo test --test recorded compat::\n     \
         (`cargo test` fails when this file is stale). -->\n\n\
         Every `cnc_*` and `pmc_*` function FANUC's `fwlib32.h` declares, and what\n\
         this library does with it. For a built program, `focas compat PROGRAM`\n\
         lists the functions it calls and which of them this library lacks\n\
         (README.md, \"Will my program work?\").\n\n",
    );
    s.push_str("## Summary\n\n| | functions |\n|---|---:|\n");
    let mut row = |what: &str, n: String| s.push_str(&format!("| {what} | {n} |\n"));
    row(
        "declared by FANUC's `fwlib32.h` (`cnc_*`, `pmc_*`)",
        fanuc.len().to_string(),
    );
    row(
        "… exported by FANUC's Linux x86-64 library",
        linux.to_string(),
    );
    row(
        "exported by this library",
        exported_declared.len().to_string(),
    );
    row("… implemented by hand (`src/ffi/`)", written.to_string());
    row(
        "… described as data (`src/spec/table/`)",
        described.to_string(),
    );
    row(
        "… … of which learnt from FANUC's library (`oracle learn`)",
        exported_declared
            .iter()
            .filter(|e| learnt(e.name).is_some())
            .count()
            .to_string(),
    );
    row(
        "… answering `EW_VERSION` (-7) without a request, as FANUC's Ethernet library",
        version.to_string(),
    );
    row(
        "… answering another code without a request (`cnc_allclibhndl`: HSSB only)",
        other_absent.to_string(),
    );
    row(
        "not exported by this library",
        (fanuc.len() - exported_declared.len()).to_string(),
    );
    row(
        "… of which FANUC's Linux library exports",
        missing_linux.to_string(),
    );
    row(
        "checked against FANUC's library (recorded cases, `tests/vectors/`)",
        format!(
            "{checked} ({own_cases} with cases of their own; {} cases: {})",
            all_cases.len(),
            class_cases.join(", ")
        ),
    );
    row(
        "served, and answered `EW_OK` by the simulator on every class",
        format!("{all_ok} of {}", served.len()),
    );
    row(
        "with deviations from FANUC's library, listed with their reasons",
        format!(
            "{} ({} entries)",
            dev_functions.len(),
            deviations::ORACLE.len()
        ),
    );
    row(
        "exported beyond FANUC's header (ours)",
        beyond.len().to_string(),
    );

    s.push_str(
        "\n## Columns\n\n\
         * **FANUC Linux**: `yes` when FANUC's Linux x86-64 library exports the\n  \
         function; `—` when only FANUC's header declares it (Windows, HSSB or\n  \
         other libraries).\n\
         * **ours**: how this library exports it: implemented by hand, described\n  \
         as data (one table entry, `docs/adding-a-function.md`), answering\n  \
         `EW_VERSION` without a request as FANUC's Ethernet library does (the\n  \
         program links and runs), or not exported (a program calling it does\n  \
         not load: the dynamic loader reports the symbol missing).\n\
         * **learner left unsettled**: for a function learnt from FANUC's\n  \
         library (`oracle learn`, `tools/oracle/README.md`), what the\n  \
         learner's draft could not settle (computed fields, type tags,\n  \
         overruns, crashes on coded replies), which review settled by\n  \
         probing and recording; `nothing` when the draft was clean, `—` for\n  \
         functions written from recordings by hand.\n\
         * **checked against FANUC's library**: the cases recorded from FANUC's\n  \
         library (`tests/vectors/`) that `cargo test` replays to ours\n  \
         (`tests/recorded/oracle.rs`), by CNC class: every request byte, return code and\n  \
         byte written must be FANUC's unless a deviation says why not.\n\
         * **simulator**: what `focas-sim` answered, measured when this file was\n  \
         generated: the oracle's base call of the function\n  \
         (`tools/oracle/cases.rs`) through our library, against the built-in\n  \
         profile (a 31i mill) as a 30i, a 16i and a Series 15 (write-enabled for\n  \
         writes); where the base call is refused, the first of the oracle's\n  \
         other argument lists the simulator answers `EW_OK` (`with` the\n  \
         probe's command: the word, then the arguments in order). `no\n  \
         request`: the library answered without sending the CNC a request;\n  \
         `after cnc_x`: measured in `cnc_x`'s case (a call that needs `cnc_x`\n  \
         first, as an upload its start; whether it sent a request is left\n  \
         out, as it depends on how far the upload got).\n\
         * **deviations**: where this library differs from FANUC's on purpose\n  \
         (`tests/deviations/mod.rs`); the reasons are [below](#deviations).\n",
    );

    s.push_str(
        "\n## Functions\n\n\
         | function | FANUC Linux | ours | learner left unsettled | checked against FANUC's library | simulator | deviations |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for (name, linux) in &fanuc {
        s.push_str(&format!(
            "| `{name}` | {} | {} | {} | {} | {} | {} |\n",
            if *linux { "yes" } else { "—" },
            ours_cell(export(name)),
            learnt_cell(name),
            checked_cell(&checks, name),
            sim(name),
            dev_cell(name),
        ));
    }

    s.push_str(
        "\n## Beyond FANUC's header\n\n\
         Exported by this library, not declared by FANUC's `fwlib32.h`.\n\n\
         | function | ours | checked against FANUC's library | simulator | deviations |\n\
         |---|---|---|---|---|\n",
    );
    for e in &beyond {
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} |\n",
            e.name,
            ours_cell(Some(e)),
            checked_cell(&checks, e.name),
            sim(e.name),
            dev_cell(e.name),
        ));
    }

    s.push_str(
        "\n## Deviations\n\n\
         Where this library differs from FANUC's on purpose, in the recorded\n\
         cases named (`tests/deviations/mod.rs`; README.md \"Where we differ\n\
         from FANUC's library\" says it for people).\n",
    );
    for f in &dev_functions {
        s.push_str(&format!("\n### {f}\n\n"));
        let names: Vec<&String> = recorded
            .get(*f)
            .map(|c| c.iter().map(|x| &x.name).collect())
            .unwrap_or_default();
        for d in devs_of(f) {
            let n = names
                .iter()
                .filter(|c| d.cases.iter().any(|p| deviations::matches(p, c)))
                .count();
            let pats: Vec<String> = d.cases.iter().map(|p| format!("`{p}`")).collect();
            s.push_str(&format!(
                "* {} ({n} case{}: {})\n",
                d.reason,
                if n == 1 { "" } else { "s" },
                pats.join(", ")
            ));
        }
    }
    s
}

/// The measured answers agree with the exports table: a function exported
/// to answer a code as FANUC's Ethernet library does answers it, without
/// a request, on every class; every export was measured.
fn check_measured(measured: &Measured) {
    for e in EXPORTS {
        let m = &measured[e.name];
        assert!(
            m.iter()
                .all(|x| x.as_ref().is_some_and(|a| a.seen.ret.is_some())),
            "{}: not measured on every class ({m:?}): give it a probe word (tools/oracle/probe.c) and an entry in EXTRA (tests/recorded/compat.rs)",
            e.name
        );
        if let How::NotOnEthernet { code, .. } = e.how {
            for x in m {
                assert_eq!(
                    x.as_ref().map(|a| &a.seen),
                    Some(&Seen {
                        ret: Some(code.into()),
                        request: false
                    }),
                    "{}",
                    e.name
                );
            }
        }
    }
}

#[test]
fn compatibility_md_is_fresh() {
    let start = std::time::Instant::now();
    let measured = measure();
    let took = start.elapsed();
    check_measured(&measured);
    let text = generate(&measured);
    let path = root().join("COMPATIBILITY.md");
    println!(
        "COMPATIBILITY.md generated in {:.1} s (measuring {:.1} s)",
        start.elapsed().as_secs_f64(),
        took.as_secs_f64()
    );
    if std::env::var(UPDATE_VAR).as_deref() == Ok("1") {
        std::fs::write(&path, &text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    if committed != text {
        let diff: Vec<String> = committed
            .lines()
            .zip(text.lines())
            .filter(|(a, b)| a != b)
            .take(10)
            .map(|(a, b)| format!("- {a}\n+ {b}"))
            .collect();
        panic!(
            "{} is stale ({} lines committed, {} generated); refresh it with\n    {UPDATE_VAR}=1 cargo test --test recorded compat::\nfirst differences:\n{}",
            path.display(),
            committed.lines().count(),
            text.lines().count(),
            diff.join("\n")
        );
    }
}
