//! `oracle fuzz`: replies drawn from what a CNC may send, independent of
//! our simulator's values, given to FANUC's library and to ours for the
//! same C call.
//!
//! Each round picks a function (in turn), one of its generated cases (its
//! arguments, class: 30i, 16i, Series 15, path 2), and draws the reply to
//! the function's call: per subpacket, from the function's reply layout
//! (src/spec/table: fixed fields and records) when it has one, else from
//! the simulator's answer taken as a template (its 4-byte and 2-byte words,
//! its 8-byte value records: base 10 and base 2 with every exponent, its
//! length). Fields get 0, 1, -1, the type's minimum and maximum or random
//! values; record counts go from 0 to past the maximum; payloads come one
//! byte short, truncated inside a record, longer, or empty; an error code
//! goes into any subpacket. FANUC's run draws the reply; ours gets the very
//! same bytes. Return codes, every output byte, in-out counts, request
//! frames and the following getdtailerr are compared (main.rs `diff`).
//!
//! A difference is shrunk (subpackets put back to the simulator's answer,
//! changed words put back, payloads cut) while it stays a difference, and
//! FANUC's side of the smallest one is recorded into
//! tests/vectors/FUNCTION.fuzz.json, which `cargo test` replays
//! (tests/recorded/oracle.rs). The same seed gives the same run.

use super::cases::{self, Case, Word};
use super::fake::{Fake, Mutator, Sub};
use super::probe::{Answer, Probe};
use super::profiles::profile;
use super::{ELAPSED, Ran, call_json, deviations, diff, word};
use fwlib32::spec::{self, Func, Int};
use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// splitmix64: seedable, the same everywhere.
#[derive(Clone)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn chance(&mut self, one_in: usize) -> bool {
        self.below(one_in) == 0
    }
}

/// What one subpacket answers: error code and payload.
pub type Plan = Vec<(i16, Vec<u8>)>;

/// Error codes a CNC may put in a subpacket.
const ERRORS: &[i16] = &[
    1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, -1, -2, -8,
];

fn int_value(rng: &mut Rng, t: Int) -> i64 {
    let (min, max): (i64, i64) = match t {
        Int::I8 | Int::IdChar => (i8::MIN.into(), i8::MAX.into()),
        Int::U8 | Int::Char => (0, u8::MAX.into()),
        Int::I16 => (i16::MIN.into(), i16::MAX.into()),
        Int::U16 => (0, u16::MAX.into()),
        Int::I32 => (i32::MIN.into(), i32::MAX.into()),
        Int::U32 | Int::BaseExp => (0, u32::MAX.into()),
        // A double's bits: any pattern (NaNs too).
        Int::F64 => (i64::MIN, i64::MAX),
    };
    match rng.below(9) {
        0 | 1 => 0,
        2 => 1,
        3 => -1,
        4 => min,
        5 => max,
        6 => rng.below(10) as i64,
        _ => rng.next() as i64,
    }
}

fn put_int(out: &mut Vec<u8>, t: Int, v: i64) {
    let b = v.to_be_bytes();
    out.extend_from_slice(&b[8 - t.size()..]);
}

fn fields(rng: &mut Rng, fs: &[spec::Field], out: &mut Vec<u8>) {
    for f in fs.iter().filter(|f| f.arg.is_none()) {
        for _ in 0..f.n {
            let v = int_value(rng, f.wire);
            put_int(out, f.wire, v);
        }
    }
}

/// A payload one byte short, cut inside a record, longer or empty; the
/// label says which.
fn tail(rng: &mut Rng, p: &mut Vec<u8>, rec: usize) -> &'static str {
    match rng.below(10) {
        0 if !p.is_empty() => {
            p.pop();
            "short1"
        }
        1 if p.len() > 1 => {
            let cut = 1 + rng.below(rec.clamp(2, p.len()) - 1);
            p.truncate(p.len() - cut);
            "cut"
        }
        2 => {
            for _ in 0..1 + rng.below(8) {
                p.push(rng.next() as u8);
            }
            "long"
        }
        3 => {
            p.clear();
            "empty"
        }
        _ => "",
    }
}

/// A payload from the function's reply layout.
fn from_layout(rng: &mut Rng, f: &Func, template: &[u8]) -> (Vec<u8>, String) {
    let mut p = Vec::new();
    fields(rng, f.reply, &mut p);
    let mut label = String::from("L");
    let mut rec = 4;
    if let Some(r) = &f.records {
        rec = r.wire_len().max(1);
        let fixed = f.reply.iter().map(|x| x.wire_len()).sum::<usize>();
        let was = template.len().saturating_sub(fixed) / rec;
        let max = usize::from(r.max);
        let n = match rng.below(9) {
            0 => 0,
            1 => 1,
            2 => max.saturating_sub(1),
            3 => max,
            4 => max + 1,
            5 => max + 1 + rng.below(4),
            6 => was,
            _ => rng.below(max + 1),
        };
        // A frame holds at most about 1400 bytes of answer.
        let n = n.min(1400 / rec);
        for _ in 0..n {
            fields(rng, r.fields, &mut p);
        }
        label = format!("Ln{n}");
        // A count the CNC sends before the records (Func::counted): mostly
        // theirs, else the random one drawn (label `c`).
        if let Some(k) = f.counted.map(usize::from) {
            if rng.below(4) == 0 {
                label.push('c');
            } else if let Some(c) = f.reply.get(k) {
                let at: usize = f.reply[..k].iter().map(|x| x.wire_len()).sum();
                let mut b = Vec::new();
                put_int(&mut b, c.wire, n as i64);
                p[at..at + b.len()].copy_from_slice(&b);
            }
        }
    }
    let t = tail(rng, &mut p, rec);
    (p, format!("{label}{t}"))
}

/// A payload from the simulator's answer: words, value records and length varied.
fn from_template(rng: &mut Rng, template: &[u8]) -> (Vec<u8>, String) {
    let mut p = template.to_vec();
    let mut label = String::from("T");
    // Value records (i32 value, u16 base 10 or 2, i16 exponent).
    let mut o = 0;
    let mut vals = false;
    while o + 8 <= p.len() {
        if (p[o + 4..o + 6] == [0, 10] || p[o + 4..o + 6] == [0, 2]) && rng.chance(2) {
            let base: u16 = if rng.chance(2) { 2 } else { 10 };
            let exp: i16 = match rng.below(6) {
                0 => i16::MIN,
                1 => i16::MAX,
                2 => -(rng.below(12) as i16),
                _ => rng.below(40) as i16,
            };
            let v = int_value(rng, Int::I32) as i32;
            p[o..o + 4].copy_from_slice(&v.to_be_bytes());
            p[o + 4..o + 6].copy_from_slice(&base.to_be_bytes());
            p[o + 6..o + 8].copy_from_slice(&exp.to_be_bytes());
            vals = true;
            o += 8;
        } else {
            o += 4;
        }
    }
    if vals {
        label.push('v');
    }
    // Words.
    let mut i = 0;
    while i + 2 <= p.len() {
        if rng.chance(6) {
            if i + 4 <= p.len() && rng.chance(2) {
                let v = int_value(rng, Int::I32) as i32;
                p[i..i + 4].copy_from_slice(&v.to_be_bytes());
            } else {
                let v = int_value(rng, Int::I16) as i16;
                p[i..i + 2].copy_from_slice(&v.to_be_bytes());
            }
            label.push('w');
        }
        i += 4;
    }
    label.truncate(6);
    // More records: the last 4 or 8 bytes repeated.
    if rng.chance(6) && p.len() >= 8 {
        let r = if rng.chance(2) { 8 } else { 4 };
        let last = p[p.len() - r..].to_vec();
        for _ in 0..1 + rng.below(40) {
            if p.len() + r > 1400 {
                break;
            }
            p.extend_from_slice(&last);
        }
        label.push_str("more");
    }
    let t = tail(rng, &mut p, 8);
    label.push_str(t);
    (p, label)
}

/// The reply's subpackets, drawn; the label names what was done.
fn draw(rng: &mut Rng, subs: &[Sub], s16: bool, s15: bool) -> (Plan, String) {
    let mut plan: Plan = subs.iter().map(|s| (err_of(s), s.1.clone())).collect();
    let mut labels = Vec::new();
    let n = subs.len();
    if n == 0 {
        return (plan, "none".into());
    }
    // An error code in one subpacket.
    if rng.chance(5) {
        let i = rng.below(n);
        let code = if rng.chance(8) {
            rng.next() as i16
        } else {
            ERRORS[rng.below(ERRORS.len())]
        };
        plan[i] = (code, Vec::new());
        labels.push(format!("e{code}s{i}"));
    }
    let changes = if n == 1 { 1 } else { 1 + rng.below(n) };
    for _ in 0..changes {
        let i = rng.below(n);
        if plan[i].0 != 0 {
            continue;
        }
        let cmd = u16::from_be_bytes([subs[i].0[6], subs[i].0[7]]);
        let class = u16::from_be_bytes([subs[i].0[2], subs[i].0[3]]);
        let layout = (class == 1).then(|| spec::by_cmd(cmd, s16, s15)).flatten();
        let (p, l) = match layout {
            Some(f) if rng.chance(2) => from_layout(rng, f, &subs[i].1),
            _ => from_template(rng, &subs[i].1),
        };
        plan[i].1 = p;
        labels.push(format!("s{i}{l}"));
    }
    (plan, labels.join("-"))
}

fn err_of(s: &Sub) -> i16 {
    i16::from_be_bytes([s.0[8], s.0[9]])
}

fn apply(subs: &mut [Sub], plan: &Plan) {
    for (s, (e, p)) in subs.iter_mut().zip(plan) {
        s.0[8..10].copy_from_slice(&e.to_be_bytes());
        s.1 = p.clone();
    }
}

/// How a run's target reply is made.
#[derive(Clone)]
enum Source {
    /// Drawn with this seed; the plan and the template are kept.
    Draw(u64, bool, bool),
    /// These bytes.
    Fixed(Plan),
}

struct Outcome {
    ran: Vec<Ran>,
    /// The simulator's answer and the reply sent, when the target call had one.
    template: Option<Plan>,
    plan: Option<Plan>,
    label: String,
}

/// Runs `case` against a fresh fake CNC, the reply of call `target` made by `src`.
fn run(case: &Case, target: usize, src: &Source, probe_exe: &Path, lib: &Path) -> Outcome {
    let fake = Fake::start(profile(case.profile), ELAPSED, case.fault);
    let mut p = Probe::spawn(std::process::Command::new(probe_exe), lib, fake.port);
    let seen: Arc<Mutex<Option<(Plan, Plan, String)>>> = Arc::new(Mutex::new(None));
    let mut all: Vec<String> = vec![
        "startup 1 fwlib.log".into(),
        format!("alloc {}", case.timeout),
    ];
    all.extend(case.calls.iter().map(|c| c.0.clone()));
    all.push("free".into());
    let mut ran = Vec::new();
    for (k, cmd) in all.into_iter().enumerate() {
        if k == target + 2 {
            let (src, seen) = (src.clone(), seen.clone());
            let m: Mutator = Box::new(move |subs: &mut Vec<Sub>| {
                let template: Plan = subs.iter().map(|s| (err_of(s), s.1.clone())).collect();
                let (plan, label) = match src {
                    Source::Draw(seed, s16, s15) => draw(&mut Rng::new(seed), subs, s16, s15),
                    Source::Fixed(p) => (p, String::new()),
                };
                apply(subs, &plan);
                *seen.lock().unwrap() = Some((template, plan, label));
            });
            fake.mutate_next(m);
        }
        // A call that never returns is ended after 20 s (a hung library).
        let pid = p.pid();
        let done = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let d2 = done.clone();
        let watchdog = std::thread::spawn(move || {
            let t = Instant::now();
            while !d2.load(std::sync::atomic::Ordering::SeqCst) {
                if t.elapsed() > Duration::from_secs(20) {
                    unsafe { libc::kill(pid as i32, libc::SIGKILL) };
                    return;
                }
                std::thread::sleep(Duration::from_millis(20));
            }
        });
        let answer = p.call(&cmd);
        done.store(true, std::sync::atomic::Ordering::SeqCst);
        let _ = watchdog.join();
        if k == target + 2 {
            fake.mutate_done();
        }
        if super::record(&fake, cmd, answer, &mut ran) {
            break;
        }
    }
    p.finish();
    let seen = seen.lock().unwrap().take();
    let (template, plan, label) = match seen {
        Some((t, p, l)) => (Some(t), Some(p), l),
        None => (None, None, String::new()),
    };
    Outcome {
        ran,
        template,
        plan,
        label,
    }
}

fn crashed(r: &[Ran]) -> bool {
    r.iter().any(|x| matches!(x.answer, Answer::Crashed(_)))
}

/// Differences of FANUC's run and ours with the same target reply; None
/// when FANUC's library crashed or hung (nothing to compare with).
fn compare(
    case: &Case,
    target: usize,
    plan: &Plan,
    probe_exe: &Path,
    fanuc: &Path,
    ours: &Path,
) -> Option<(Outcome, Vec<String>)> {
    let src = Source::Fixed(plan.clone());
    let f = run(case, target, &src, probe_exe, fanuc);
    if crashed(&f.ran) {
        return None;
    }
    let o = run(case, target, &src, probe_exe, ours);
    let d = diff(&f.ran, &o.ran);
    Some((f, d))
}

/// The smallest plan found that still differs: subpackets put back to the
/// template, changed 4-byte words put back, payloads cut.
fn shrink(
    case: &Case,
    target: usize,
    template: &Plan,
    mut plan: Plan,
    probe_exe: &Path,
    fanuc: &Path,
    ours: &Path,
) -> (Plan, Option<Outcome>) {
    let mut budget = 24;
    let mut best: Option<Outcome> = None;
    let try_plan = |p: &Plan, best: &mut Option<Outcome>, budget: &mut i32| -> bool {
        if *budget <= 0 {
            return false;
        }
        *budget -= 1;
        match compare(case, target, p, probe_exe, fanuc, ours) {
            Some((f, d)) if !d.is_empty() => {
                *best = Some(f);
                true
            }
            _ => false,
        }
    };
    for i in 0..plan.len() {
        if plan[i] != template[i] {
            let mut p = plan.clone();
            p[i] = template[i].clone();
            if try_plan(&p, &mut best, &mut budget) {
                plan = p;
            }
        }
    }
    for i in 0..plan.len() {
        // Cut the payload from the end while it differs.
        while plan[i].1.len() >= 4 && plan[i].1.len() > template[i].1.len() {
            let mut p = plan.clone();
            let keep = (p[i].1.len() - 1) / 4 * 4;
            p[i].1.truncate(keep.max(template[i].1.len()));
            if !try_plan(&p, &mut best, &mut budget) {
                break;
            }
            plan = p;
        }
        // Words back to the template's.
        let n = plan[i].1.len().min(template[i].1.len()) / 4;
        for w in 0..n {
            let r = 4 * w..4 * w + 4;
            if plan[i].1[r.clone()] != template[i].1[r.clone()] {
                let mut p = plan.clone();
                p[i].1[r.clone()].copy_from_slice(&template[i].1[r]);
                if try_plan(&p, &mut best, &mut budget) {
                    plan = p;
                }
            }
        }
    }
    (plan, best)
}

/// The deviation listing a fuzz case, if any (tests/deviations ORACLE).
fn listed(function: &str, name: &str) -> bool {
    deviations::ORACLE
        .iter()
        .any(|d| d.function == function && d.cases.iter().any(|p| deviations::matches(p, name)))
}

/// What differs, in words: return, output, count, request, crash.
fn kinds(d: &[String]) -> String {
    let mut k = Vec::new();
    for (pat, name) in [
        ("requests differ", "request"),
        ("Crashed", "crash"),
        ("calls ran", "calls"),
    ] {
        if d.iter().any(|x| x.contains(pat)) {
            k.push(name);
        }
    }
    if d.iter()
        .any(|x| x.contains("fanuc ret") || x.contains("`: fanuc"))
        && k.is_empty()
    {
        k.push("answer");
    }
    k.join("+")
}

fn record(out: &Path, function: &str, case: &Case, name: &str, f: &Outcome) {
    let path = out.join(format!("{function}.fuzz.json"));
    let mut file: Value = std::fs::read_to_string(&path)
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or_else(|| {
            json!({
                "function": function,
                "source": "recorded by `oracle fuzz` (tools/oracle/fuzz.rs) from FANUC's Linux x86-64 library: replies drawn from the function's reply layout, shrunk",
                "cases": [],
            })
        });
    let cases = file["cases"].as_array_mut().unwrap();
    if cases.iter().any(|c| c["name"] == name) {
        return;
    }
    cases.push(json!({
        "name": name,
        "profile": case.profile,
        "calls": f.ran.iter().map(call_json).collect::<Vec<_>>(),
    }));
    std::fs::write(&path, serde_json::to_string_pretty(&file).unwrap() + "\n")
        .expect("write vector file");
}

pub struct Opts {
    pub fanuc: PathBuf,
    pub ours: PathBuf,
    pub seconds: u64,
    pub seed: u64,
    pub only: Vec<String>,
    pub out: PathBuf,
}

/// Runs the fuzzer; the process's exit code.
pub fn fuzz(o: &Opts, probe_exe: &Path) -> i32 {
    let words: Vec<Word> = cases::words()
        .into_iter()
        .filter(|w| {
            o.only.is_empty()
                || o.only
                    .iter()
                    .any(|x| x == w.word || *x == cases::function(w.word))
        })
        .filter(|w| {
            !matches!(
                w.word,
                "startup" | "exitprocess" | "getdtailerr" | "pmc_getdtailerr"
            )
        })
        .collect();
    // Each word's cases: plain calls (no broken set-up, no fixed shape).
    let mut pool: Vec<(String, Vec<(Case, usize)>)> = words
        .iter()
        .map(|w| {
            let cs = cases::cases_of(w)
                .into_iter()
                .filter(|c| c.fault.is_none() && c.calls.iter().all(|x| x.1.is_none()))
                .filter_map(|c| {
                    let t = c.calls.iter().position(|x| word(&x.0) == w.word)?;
                    Some((c, t))
                })
                .collect();
            (w.word.to_string(), cs)
        })
        .filter(|(_, cs): &(String, Vec<(Case, usize)>)| !cs.is_empty())
        .collect();
    let start = Instant::now();
    let mut rng = Rng::new(o.seed);
    let mut tried: BTreeMap<String, usize> = BTreeMap::new();
    let mut silent: BTreeMap<String, usize> = BTreeMap::new();
    let (mut replies, mut differences, mut deviating, mut fanuc_crashes) = (0, 0, 0, 0);
    let mut recorded: BTreeMap<String, usize> = BTreeMap::new();
    let mut turn = 0usize;
    while start.elapsed() < Duration::from_secs(o.seconds) && !pool.is_empty() {
        let k = turn % pool.len();
        turn += 1;
        let (w, cs) = &pool[k];
        let (case, target) = cs[rng.below(cs.len())].clone();
        let function = cases::function(w);
        let prof = profile(case.profile);
        let s16 = prof.cnc.class != fwlib32::sim::profile::Class::Series30;
        let s15 = s16 && prof.cnc.kind == 2;
        let seed = rng.next();
        let f = run(
            &case,
            target,
            &Source::Draw(seed, s16, s15),
            probe_exe,
            &o.fanuc,
        );
        let (Some(template), Some(plan)) = (f.template.clone(), f.plan.clone()) else {
            // No data reply to this call: after a few, the word leaves the rotation.
            let n = silent.entry(w.clone()).or_default();
            *n += 1;
            if *n >= 3 && !tried.contains_key(w) {
                pool.remove(k);
            }
            continue;
        };
        replies += 1;
        *tried.entry(w.clone()).or_default() += 1;
        if crashed(&f.ran) {
            fanuc_crashes += 1;
            continue;
        }
        let ours = run(
            &case,
            target,
            &Source::Fixed(plan.clone()),
            probe_exe,
            &o.ours,
        );
        let d = diff(&f.ran, &ours.ran);
        if d.is_empty() {
            continue;
        }
        differences += 1;
        let kind = kinds(&d);
        // The generated case's name (its class and arguments: `v3_a1_0`),
        // what differs, what the reply was: deviations match on these.
        let name = format!(
            "fuzz_{w}_{}_{}_{}_{seed:016x}",
            case.name,
            kind,
            f.label.replace(['-', ' '], "_")
        );
        let is_listed = listed(&function, &name);
        if is_listed {
            deviating += 1;
        }
        let cut = |x: &String| -> String { x.chars().take(400).collect() };
        println!(
            "DIFF {function}/{name}{}\n{}",
            if is_listed { " (listed)" } else { "" },
            d.iter().map(cut).collect::<Vec<_>>().join("\n")
        );
        // Shrink and record at most 3 per function and kind.
        let key = format!("{function}/{}/{kind}", case.profile);
        let n = recorded.entry(key).or_default();
        if *n < 3 {
            *n += 1;
            let (small, best) =
                shrink(&case, target, &template, plan, probe_exe, &o.fanuc, &o.ours);
            let f2 = match best {
                Some(b) => b,
                None => run(&case, target, &Source::Fixed(small), probe_exe, &o.fanuc),
            };
            if !crashed(&f2.ran) {
                record(&o.out, &function, &case, &name, &f2);
            }
        }
    }
    println!("replies per function:");
    for (w, n) in &tried {
        println!("  {}: {n}", cases::function(w));
    }
    if fanuc_crashes > 0 {
        println!("{fanuc_crashes} replies crashed or hung FANUC's library (not compared)");
    }
    println!(
        "fuzz: {replies} replies, {} functions, {differences} differences ({deviating} listed deviations)",
        tried.len()
    );
    i32::from(differences > deviating)
}
