//! `oracle learn`: learns a function of FANUC's header from FANUC's library
//! (issue 24, the learner) and writes a draft table entry for it.
//!
//! ```text
//! cargo run --release --example oracle -- learn --lib FANUC.so --header fwlib32.h [--only f,g] [--out FILE]
//! cargo run --release --example oracle -- learn --lib FANUC.so --header fwlib32.h --check   # the described functions
//! cargo run --release --example oracle -- learn --lib FANUC.so --lib FANUC32.so --header fwlib32.h --check   # those only in the 32-bit build from it
//! cargo run --release --example oracle -- learn --lib FANUC.so --header fwlib32.h --unexported
//! ```
//!
//! The header is read at run time from the path given (preprocessed by
//! `cc -E -P`); nothing of it is kept. Each call goes through the probe's
//! `callx` word against a fake CNC (tools/oracle/fake.rs) on the 30i, 16i
//! and Series 15 profiles. Per function:
//! - the plain call (every number 1, counts 4, outputs filled);
//! - each number varied alone: the request words are diffed to learn which
//!   argument lands in which word, per class;
//! - each number swept over its edges, then bisected: the values that
//!   return without traffic are the local checks;
//! - each pointer filled with position codes: the request bytes that come
//!   from it (an input struct's fields in the words or payload);
//! - replies of position-coded bytes (two passes) with the outputs filled
//!   with 0xCC and 0x33: which reply byte lands in which output byte; a
//!   rejected reply is retried shorter, then with a 16-bit count pinned at
//!   small offsets.
//!
//! `--check` learns the functions already described in src/spec/table and
//! compares each draft with the committed entry (request forms per class,
//! local checks on the values swept, reply bytes moved); `--unexported`
//! learns every `cnc_`/`pmc_` function of the header we do not export and
//! counts clean, flagged and failed drafts by reason.

#[path = "learn_pure.rs"]
pub mod pure;

use crate::fake::{Fake, Rec, Sub as RespSub};
use crate::probe::{Answer, Probe};
use crate::profiles::profile;
use fwlib32::spec::Int;
use pure::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

const CLASSES: [(&str, &str); 3] = [("v3", "S30"), ("v2", "S16"), ("s15", "S15")];
/// The punch press forms of the 30i and 16i classes (no Series 15 one).
const PUNCH: [(&str, &str); 2] = [("v3pu", "S30"), ("v2pu", "S16")];
const BUF: usize = 65536;
/// FANUC's socket error: a connection's trouble, never a local check.
const EW_SOCKET: i64 = -16;
/// How long one call may take before the probe is ended.
const CALL_LIMIT: Duration = Duration::from_secs(6);

pub struct Opts {
    pub lib: PathBuf,
    pub header: PathBuf,
    pub only: Vec<String>,
    pub out: Option<PathBuf>,
    pub check: bool,
    pub unexported: bool,
    /// Further libraries (`--lib` again) and the probe built for each:
    /// a function not in `lib` is learnt from the first that has it
    /// (FANUC's 32-bit x86 build has functions its x86-64 one lacks).
    pub more: Vec<(PathBuf, PathBuf)>,
}

/// One live conversation: a fake CNC of a class and a probe connected to it.
struct Session<'a> {
    probe_exe: &'a Path,
    lib: &'a Path,
    fake: Fake,
    probe: Option<Probe>,
    pub calls: usize,
    /// Calls that took longer than a second (the library waited for a
    /// reply that never came): after three, no more calls are made.
    pub slow: usize,
    /// A call sent nothing, then its request from a fresh process.
    pub stateful: bool,
}

/// What one call did.
struct Call {
    ret: Option<i64>,
    crashed: bool,
    missing: bool,
    b0: Vec<u8>,
    reqs: Vec<Vec<u8>>,
    frames: usize,
}

impl<'a> Session<'a> {
    fn new(probe_exe: &'a Path, lib: &'a Path, class: &'static str) -> Session<'a> {
        Session {
            probe_exe,
            lib,
            fake: Fake::start(profile(class), Duration::from_millis(2500), None),
            probe: None,
            calls: 0,
            slow: 0,
            stateful: false,
        }
    }
    fn probe(&mut self) -> &mut Probe {
        if self.probe.is_none() {
            let mut p = Probe::spawn(
                std::process::Command::new(self.probe_exe),
                self.lib,
                self.fake.port,
            );
            p.call("startup 1 fwlib.log");
            p.call("alloc 3");
            self.fake.take(Duration::from_millis(2));
            self.probe = Some(p);
        }
        self.probe.as_mut().unwrap()
    }
    /// One call: `cmd` the callx arguments after the fill; `mutate` makes
    /// the next data reply.
    fn call(&mut self, fill: u8, cmd: &str, mutate: Option<fake_reply::Maker>) -> Call {
        if self.slow >= 3 {
            return Call {
                ret: None,
                crashed: true,
                missing: false,
                b0: Vec::new(),
                reqs: Vec::new(),
                frames: 0,
            };
        }
        self.calls += 1;
        let started = std::time::Instant::now();
        let pid = self.probe().pid();
        if let Some(m) = mutate {
            self.fake.mutate_next(m);
        }
        let (tx, rx) = mpsc::channel::<()>();
        let dog = std::thread::spawn(move || {
            if rx.recv_timeout(CALL_LIMIT).is_err() {
                // SAFETY: the probe we started, by its id.
                unsafe { libc::kill(pid as i32, libc::SIGKILL) };
            }
        });
        let answer = self.probe().call(&format!("callx {fill} {cmd}"));
        let _ = tx.send(());
        let _ = dog.join();
        if started.elapsed() > Duration::from_secs(1) {
            self.slow += 1;
        }
        self.fake.mutate_done();
        let frames: Vec<Rec> = self.fake.take(Duration::from_millis(1));
        let reqs: Vec<Vec<u8>> = frames
            .iter()
            .filter(|f| f.dir == "req")
            .map(|f| f.bytes.clone())
            .collect();
        let mut c = Call {
            ret: None,
            crashed: false,
            missing: false,
            b0: Vec::new(),
            frames: reqs.len(),
            reqs,
        };
        match answer {
            Answer::Done { ret, b0, .. } => {
                c.ret = Some(ret);
                c.b0 = b0;
                c.b0.resize(BUF, fill);
            }
            Answer::Missing(_) => c.missing = true,
            Answer::Crashed(_) => {
                c.crashed = true;
                self.probe = None; // a new one for the next call
            }
        }
        c
    }
}

impl Drop for Session<'_> {
    fn drop(&mut self) {
        if let Some(p) = self.probe.take() {
            p.finish();
        }
    }
}

/// Replies the fake CNC sends: every subpacket's error cleared and its
/// payload replaced.
mod fake_reply {
    pub type Maker = crate::fake::Mutator;
    pub fn coded(len: usize, pass: usize, pin: Option<(usize, u16)>) -> Maker {
        Box::new(move |subs: &mut Vec<super::RespSub>| {
            for (k, s) in subs.iter_mut().enumerate() {
                s.0[8..14].fill(0);
                let mut p: Vec<u8> = (0..len)
                    .map(|i| super::pure::code(k * len + i, pass))
                    .collect();
                if let Some((at, v)) = pin
                    && at + 2 <= p.len()
                {
                    p[at..at + 2].copy_from_slice(&v.to_be_bytes());
                }
                s.1 = p;
            }
        })
    }
}

/// How an argument of the prototype is passed.
#[derive(Clone, Debug)]
enum Arg {
    /// A number: its C integer type.
    Num(Ty),
    /// A pointer to an integer: its value read before and after the call.
    IntPtr(Ty),
    /// A pointer to anything else (struct, char, void, array).
    Ptr(Ty),
}

struct Shape {
    args: Vec<Arg>,
    /// Each pointer's region in b0: (offset, span).
    regions: Vec<Option<(usize, usize)>>,
}

fn shape(p: &Proto) -> Result<Shape, String> {
    let Some((first, _)) = p.params.first() else {
        return Err("no handle parameter".into());
    };
    if !matches!(first, Ty::Int { size: 2, .. }) {
        return Err("no handle parameter".into());
    }
    let mut args = Vec::new();
    for (t, text) in &p.params[1..] {
        args.push(match t {
            Ty::Int { .. } => Arg::Num(t.clone()),
            Ty::Ptr(inner) => match &**inner {
                i @ Ty::Int { size: 2 | 4, .. } => Arg::IntPtr(i.clone()),
                i => Arg::Ptr(i.clone()),
            },
            Ty::Float(_) => return Err(format!("a floating-point argument ({text})")),
            _ => return Err(format!("an argument passed by value ({text})")),
        });
    }
    if args.len() > 11 {
        return Err("more than 11 arguments".into());
    }
    let nptr = args.iter().filter(|a| !matches!(a, Arg::Num(_))).count();
    let span = BUF.checked_div(nptr).map_or(0, |x| x / 16 * 16);
    let mut regions = Vec::new();
    let mut k = 0;
    for a in &args {
        if matches!(a, Arg::Num(_)) {
            regions.push(None);
        } else {
            regions.push(Some((k * span, span)));
            k += 1;
        }
    }
    for (a, r) in args.iter().zip(&regions) {
        if let (Arg::Ptr(t), Some((_, span))) = (a, r)
            && t.size() > *span
        {
            return Err(format!("a {}-byte output over its room", t.size()));
        }
    }
    Ok(Shape { args, regions })
}

fn conv_of(t: &Ty) -> fn(i64) -> i32 {
    match t {
        Ty::Int {
            size: 1,
            signed: true,
        } => |v| v as i8 as i32,
        Ty::Int {
            size: 1,
            signed: false,
        } => |v| v as u8 as i32,
        Ty::Int {
            size: 2,
            signed: true,
        } => |v| v as i16 as i32,
        Ty::Int {
            size: 2,
            signed: false,
        } => |v| v as u16 as i32,
        _ => |v| v as i32,
    }
}

/// The length of the C string a `char *` or `void *` argument holds (its
/// 0 byte reads as kept in the reply map).
const STRING: usize = 32;

fn is_bytes(a: &Arg) -> bool {
    matches!(a, Arg::Ptr(Ty::Int { size: 1, .. } | Ty::Void))
}

/// A little-endian integer's value.
fn le_value(b: &[u8], signed: bool) -> i64 {
    let mut v: i64 = 0;
    for (k, x) in b.iter().enumerate() {
        v |= (*x as i64) << (8 * k);
    }
    let bits = 8 * b.len() as u32;
    if signed && bits < 64 && v >> (bits - 1) & 1 == 1 {
        v -= 1 << bits;
    }
    v
}

fn hex(b: &[u8]) -> String {
    b.iter().map(|x| format!("{x:02x}")).collect()
}

/// The integer's bytes as C holds it (little-endian).
fn native(t: &Ty, v: i64) -> Vec<u8> {
    v.to_le_bytes()[..t.size().min(8)].to_vec()
}

/// Everything one call is made of.
#[derive(Clone)]
struct Setup {
    /// The value of each number and int pointer (others unused).
    vals: Vec<i64>,
    /// Bytes to put at a pointer's region start (position codes).
    fill_ptr: Vec<Option<Vec<u8>>>,
}

fn command(name: &str, sh: &Shape, s: &Setup) -> String {
    let mut c = format!("{name} H");
    for (i, a) in sh.args.iter().enumerate() {
        match (a, sh.regions[i]) {
            (Arg::Num(_), _) => c.push_str(&format!(" {}", s.vals[i])),
            (Arg::IntPtr(t), Some((off, _))) => {
                let b = s.fill_ptr[i]
                    .clone()
                    .unwrap_or_else(|| native(t, s.vals[i]));
                c.push_str(&format!(" @{off}={}", hex(&b)))
            }
            (Arg::Ptr(_), Some((off, span))) => match &s.fill_ptr[i] {
                Some(b) => c.push_str(&format!(" @{off}={}", hex(b))),
                None if is_bytes(&sh.args[i]) && span > STRING => {
                    // a C string argument ends inside its room
                    c.push_str(&format!(" @{off}!{STRING}"));
                }
                None => c.push_str(&format!(" @{off}")),
            },
            _ => c.push_str(" 0"),
        }
    }
    c
}

/// A plain input: each integer of `t` `w` (little-endian, cut to its
/// size), the rest 0.
fn plain_fill(t: &Ty, w: i64) -> Vec<u8> {
    let mut b = vec![0u8; t.size()];
    let mut lv = Vec::new();
    leaves(t, 0, "", &mut lv);
    for l in lv {
        let size = l.ty.size();
        if l.ty.int().is_some() && l.off + size <= b.len() {
            b[l.off..l.off + size].copy_from_slice(&w.to_le_bytes()[..size]);
        }
    }
    b
}

/// The data requests of a call as subpackets.
fn data_subs(c: &Call) -> Vec<Vec<Sub>> {
    c.reqs.iter().filter_map(|f| subs(f)).collect()
}

fn traffic(c: &Call) -> bool {
    !data_subs(c).is_empty()
}

/// Values a number is swept over.
const EDGES: &[i64] = &[
    0,
    -1,
    1,
    2,
    3,
    4,
    5,
    8,
    10,
    16,
    32,
    100,
    127,
    128,
    255,
    256,
    1000,
    9999,
    32767,
    -32768,
    65535,
    65536,
    2147483647,
    -2147483648,
    -2,
    -100,
];

/// What was learnt of one function on one class.
#[derive(Default)]
struct ClassLearnt {
    form: Option<DForm>,
    checks: Vec<LearntCheck>,
    /// Each argument's values swept and what each did: `Some(code)`
    /// returned without traffic, None sent a request.
    observed: Vec<Vec<(i64, Option<i16>)>>,
    /// Each argument's value in the plain call (the others' while one is
    /// swept).
    base: Vec<i64>,
    reply: Vec<Placed>,
    reply_len: usize,
    asked: usize,
    moved_past: Vec<String>,
    payload: Vec<Placed>,
    inputs: Vec<usize>,
    /// C strings sent in a fixed field: (argument, payload offset, bytes
    /// of the string sent in order).
    texts: Vec<(usize, usize, usize)>,
    outputs: Vec<usize>,
    /// (output's argument, leaf, C integer, number argument echoed)
    echoes: Vec<(usize, String, Int, usize)>,
    /// Output bytes written as 0 whatever the reply, off the wire:
    /// (output's argument, byte offset).
    zeros: Vec<(usize, usize)>,
    /// The leaves all of whose bytes are such zeros: (output's argument,
    /// leaf, C integer).
    zero_leaves: Vec<(usize, String, Int)>,
    /// A leaf learnt as the first number plus this (`LAST_ECHO`): the
    /// records the coded reply held, less one, when it is the last
    /// number answered.
    last_plus: Option<i64>,
    /// Each pointer's plain contents (an input's integers set alike), if
    /// not its fill.
    base_fill: Vec<Option<Vec<u8>>>,
    /// No request on any class: the integers the call writes, whatever
    /// the fill (output's argument, leaf, value).
    local: Option<Vec<(usize, String, i64)>>,
    /// The last request subpacket's form when another command went before
    /// it (an exchange first).
    own_form: Option<DForm>,
    flags: Vec<String>,
}

/// Learns `name` on one class. Err: the function could not be learnt at all.
#[allow(clippy::needless_range_loop)] // arguments by index, as the prototype numbers them
fn learn_class(
    sess: &mut Session,
    name: &str,
    sh: &Shape,
    hdr_types: &[Ty],
) -> Result<ClassLearnt, String> {
    let n = sh.args.len();
    let mut flags = Vec::new();
    let base_val = |a: &Arg| match a {
        Arg::IntPtr(_) => 4,
        _ => 1,
    };
    let mut base = Setup {
        vals: sh.args.iter().map(base_val).collect(),
        fill_ptr: vec![None; n],
    };
    // A call that sends nothing is made again by a fresh process: FANUC's
    // library keeps state between some calls (a sampling started refuses
    // the next start locally), which is not a local check.
    let run = |sess: &mut Session, s: &Setup| {
        let cmd = command(name, sh, s);
        let c = sess.call(0xCC, &cmd, None);
        if traffic(&c) || c.crashed || c.missing || sess.slow > 0 {
            return c;
        }
        if let Some(p) = sess.probe.take() {
            p.finish();
        }
        let again = sess.call(0xCC, &cmd, None);
        if traffic(&again) {
            // a socket error is no state kept (the fake CNC busy)
            sess.stateful |= c.ret != Some(EW_SOCKET);
            return again;
        }
        // A socket error is never a local check: once more.
        if again.ret == Some(EW_SOCKET) && !again.crashed {
            let third = sess.call(0xCC, &cmd, None);
            if traffic(&third) || third.ret != Some(EW_SOCKET) {
                return third;
            }
        }
        again
    };
    let mut c0 = run(sess, &base);
    if c0.missing {
        return Err("not in FANUC's library".into());
    }
    if c0.crashed {
        return Err("crashed on the plain call".into());
    }
    // No traffic: find values of each number that send something.
    // The values tried: small and large ones, and the size of each
    // pointer's pointee (a length in bytes the library checks against
    // the struct it reads), then the same with every input pointer's
    // integers 1 (a plain input: the caller's struct filled, not 0xCC).
    if !traffic(&c0) {
        let mut values: Vec<i64> = vec![0, 4, 100, 1000, -1, 10, 2, 32767];
        for a in &sh.args {
            if let Arg::Ptr(t) = a {
                let size = t.size() as i64;
                for v in [size, 2 * size] {
                    if v > 1 && !values.contains(&v) {
                        values.push(v);
                    }
                }
            }
        }
        // every integer of the inputs w: 1, then numbers a caller's
        // struct may need (a variable number, a range's start and end)
        let mut starts = vec![base.clone()];
        for w in [1, 100, 1000, 10000, 0] {
            let mut plain_in = base.clone();
            for (i, a) in sh.args.iter().enumerate() {
                // the caller's array: 16 such elements
                if let (Arg::Ptr(t), Some((_, span))) = (a, sh.regions[i])
                    && !is_bytes(a)
                    && t.size() <= span.min(4096)
                {
                    let one = plain_fill(t, w);
                    let k = (span.min(4096) / one.len().max(1)).clamp(1, 16);
                    plain_in.fill_ptr[i] = Some(one.repeat(k));
                }
            }
            if plain_in.fill_ptr.iter().any(Option::is_some) {
                starts.push(plain_in);
            }
        }
        'search: for (k, start) in starts.iter().enumerate() {
            if k > 0 {
                let c = run(sess, start);
                if traffic(&c) {
                    base = start.clone();
                    c0 = c;
                    break 'search;
                }
            }
            for i in 0..n {
                if matches!(sh.args[i], Arg::Ptr(_)) {
                    continue;
                }
                for &v in &values {
                    let mut s = start.clone();
                    s.vals[i] = v;
                    let c = run(sess, &s);
                    if std::env::var_os("ORACLE_LEARN_SWEEP").is_some() {
                        eprintln!("plain search: {} -> {:?}", command(name, sh, &s), c.ret);
                    }
                    if traffic(&c) {
                        base = s;
                        c0 = c;
                        break 'search;
                    }
                }
            }
        }
        if base.fill_ptr.iter().any(Option::is_some) {
            flags.push(
                "plain call: the input's integers set alike (filled with 0xCC it sent nothing)"
                    .into(),
            );
        }
    }
    if sess.slow > 0 {
        return Err("the plain call waited for more than a second (timed out)".into());
    }
    let plain_code = c0.ret;
    if !traffic(&c0) {
        return Err(format!(
            "no traffic (returns {} locally)",
            plain_code.unwrap_or(i64::MIN)
        ));
    }
    let s0 = data_subs(&c0);
    let first = s0[0][0].clone();
    let more = s0.iter().map(Vec::len).sum::<usize>() - 1 + (c0.frames - s0.len());
    // Requests: each number varied alone.
    let mut runs = vec![WordRun {
        args: base.vals.clone(),
        words: first.words,
        payload_len: first.payload.len(),
    }];
    // The call's last subpacket, when another command goes before it (an
    // exchange: attributes read, a parameter per record): the function's
    // own request, its words learnt as the first's.
    let own = s0
        .iter()
        .flatten()
        .last()
        .filter(|l| l.cmd != first.cmd || l.class != first.class)
        .cloned();
    let mut own_runs: Vec<WordRun> = own
        .iter()
        .map(|o| WordRun {
            args: base.vals.clone(),
            words: o.words,
            payload_len: o.payload.len(),
        })
        .collect();
    let mut observed = vec![Vec::new(); n];
    let mut checks = Vec::new();
    for i in 0..n {
        if matches!(sh.args[i], Arg::Ptr(_)) {
            continue;
        }
        let b = base.vals[i];
        // Each value alone; when fewer than two sent the request (the
        // others' checks refuse them: a range's start past its end), again
        // with the other numbers raised to 10 and 100.
        let mut sent = 0;
        for ctx in [None, Some(10), Some(100)] {
            if ctx.is_some() && sent >= 2 {
                break;
            }
            for v in [b + 1, b + 2, b - 1, b + 5] {
                let mut s = base.clone();
                if let Some(x) = ctx {
                    for (j, a) in sh.args.iter().enumerate() {
                        if j != i && !matches!(a, Arg::Ptr(_)) {
                            s.vals[j] = s.vals[j].max(x);
                        }
                    }
                }
                s.vals[i] = v;
                let c = run(sess, &s);
                if let (Some(o), Some(l)) = (&own, data_subs(&c).iter().flatten().last())
                    && l.cmd == o.cmd
                    && l.class == o.class
                {
                    own_runs.push(WordRun {
                        args: s.vals.clone(),
                        words: l.words,
                        payload_len: l.payload.len(),
                    });
                }
                if let Some(sub) = data_subs(&c).first().and_then(|f| f.first())
                    && sub.cmd == first.cmd
                {
                    sent += 1;
                    runs.push(WordRun {
                        args: s.vals.clone(),
                        words: sub.words,
                        payload_len: sub.payload.len(),
                    });
                }
            }
        }
        // Local checks: the edges, then each boundary bisected.
        let mut seen: BTreeMap<i64, Option<i16>> = BTreeMap::new();
        let probe_v = |sess: &mut Session, v: i64, seen: &mut BTreeMap<i64, Option<i16>>| {
            if let Some(x) = seen.get(&v) {
                return *x;
            }
            let mut s = base.clone();
            s.vals[i] = v;
            let c = run(sess, &s);
            let r = if traffic(&c) || c.crashed {
                None
            } else {
                Some(c.ret.unwrap_or(0) as i16)
            };
            seen.insert(v, r);
            r
        };
        probe_v(sess, b, &mut seen);
        for &v in EDGES {
            probe_v(sess, v, &mut seen);
        }
        // bisect between neighbours that differ
        for _ in 0..4 {
            let pts: Vec<(i64, Option<i16>)> = seen.iter().map(|(k, v)| (*k, *v)).collect();
            let mut changed = false;
            for w in pts.windows(2) {
                let ((a, ra), (z, rz)) = (w[0], w[1]);
                if ra.is_some() != rz.is_some() && z - a > 1 {
                    let (mut lo, mut hi) = (a, z);
                    let lo_ok = ra.is_none();
                    for _ in 0..40 {
                        if hi - lo <= 1 {
                            break;
                        }
                        let m = lo + (hi - lo) / 2;
                        let r = probe_v(sess, m, &mut seen);
                        if r.is_none() == lo_ok {
                            lo = m;
                        } else {
                            hi = m;
                        }
                    }
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        // in the C parameter's values (65535 is a short's -1)
        let conv = match &sh.args[i] {
            Arg::Num(t) | Arg::IntPtr(t) => conv_of(t),
            Arg::Ptr(_) => |v| v as i32,
        };
        let mut sweep: Vec<(i64, Option<i16>)> =
            seen.iter().map(|(k, v)| (conv(*k) as i64, *v)).collect();
        sweep.sort_by_key(|s| s.0);
        sweep.dedup_by_key(|s| s.0);
        if std::env::var_os("ORACLE_LEARN_SWEEP").is_some() {
            eprintln!("sweep arg {i}: {sweep:?}");
        }
        observed[i] = sweep.clone();
        match learn_check(i, &sweep) {
            Ok(Some(c)) => checks.push(c),
            Ok(None) => {}
            Err(e) => flags.push(format!("check: {e}")),
        }
    }
    let convs: Vec<fn(i64) -> i32> = sh
        .args
        .iter()
        .map(|a| match a {
            Arg::Num(t) | Arg::IntPtr(t) => conv_of(t),
            Arg::Ptr(_) => |_| i32::MIN,
        })
        .collect();
    let words = learn_words(&runs, &convs);
    for (k, w) in words.iter().enumerate() {
        if let WordSrc::Computed(v) = w {
            flags.push(format!("word {k} computed: {v:?}"));
        }
    }
    let mut form = DForm {
        classes: "All",
        class: first.class,
        cmd: first.cmd,
        words,
        more,
    };
    let own_form = own.as_ref().map(|o| DForm {
        classes: "All",
        class: o.class,
        cmd: o.cmd,
        words: learn_words(&own_runs, &convs),
        more: 0,
    });
    if more > 0 {
        flags.push(format!(
            "{} more subpackets or frames after the first",
            more
        ));
    }
    // A plain input (its integers set alike for the plain call): each
    // integer member varied alone; a word the plain call saw constant
    // that follows it is that member (`Word::Input`).
    for i in 0..n {
        let (Some(pf), Arg::Ptr(t)) = (base.fill_ptr[i].clone(), &sh.args[i]) else {
            continue;
        };
        let mut lv = Vec::new();
        leaves(t, 0, "", &mut lv);
        let mut evidence = Vec::new();
        for l in lv.iter().filter(|l| l.ty.int().is_some()) {
            let size = l.ty.size();
            let Some(ci) = l.ty.int() else { continue };
            let at = le_value(&pf[l.off..l.off + size], true);
            let mut seen: Vec<(i64, [i32; 5], bool)> = vec![(at, first.words, false)];
            for v in [at + 1, at + 2, at - 1, at + 5] {
                // alone, then with the other integers raised to it (a
                // range's end past its new start)
                for raise in [false, true] {
                    let mut s = base.clone();
                    let mut b = pf.clone();
                    if raise {
                        for o in lv.iter().filter(|o| o.ty.int().is_some()) {
                            let z = o.ty.size();
                            let was = le_value(&b[o.off..o.off + z], true);
                            if was < v {
                                b[o.off..o.off + z].copy_from_slice(&v.to_le_bytes()[..z]);
                            }
                        }
                    }
                    b[l.off..l.off + size].copy_from_slice(&v.to_le_bytes()[..size]);
                    s.fill_ptr[i] = Some(b);
                    let c = run(sess, &s);
                    if let Some(sub) = data_subs(&c).first().and_then(|f| f.first())
                        && sub.cmd == first.cmd
                    {
                        seen.push((ci.cut(v), sub.words, raise));
                        break;
                    }
                }
            }
            if seen.len() >= 2 {
                evidence.push((l.path.clone(), seen));
            }
        }
        // a word follows a member when every run of it does; of several
        // members (raised together), the one seen varied alone most
        for (k, w) in form.words.iter_mut().enumerate() {
            if !matches!(w, WordSrc::Const(_)) {
                continue;
            }
            let best = evidence
                .iter()
                .filter(|(_, seen)| seen.iter().all(|(v, ws, _)| ws[k] as i64 == *v))
                .max_by_key(|(_, seen)| seen.iter().filter(|r| !r.2).count());
            if let Some((path, _)) = best {
                *w = WordSrc::Input(path.clone());
            }
        }
    }
    // Inputs: each pointer's bytes position-coded; the request bytes from it.
    let mut payload = Vec::new();
    let mut inputs = Vec::new();
    let mut texts = Vec::new();
    let base_req = req_bytes(&first);
    for i in 0..n {
        // a pointer to an integer that no request word carries may be an
        // input too (a write's array of shorts)
        let (Some((_, span)), ty) = (
            sh.regions[i],
            match &sh.args[i] {
                Arg::Ptr(t) => t.clone(),
                Arg::IntPtr(t) if !form.words.contains(&WordSrc::Arg(i)) => t.clone(),
                _ => continue,
            },
        ) else {
            continue;
        };
        let len = if is_bytes(&sh.args[i]) {
            STRING
        } else {
            ty.size().max(1)
        }
        .min(span)
        .min(4096);
        let mut got: Vec<Vec<u8>> = Vec::new();
        for pass in 0..PASSES {
            let mut s = base.clone();
            let mut b = coded(len, pass);
            if len < span {
                b.push(0);
            }
            s.fill_ptr[i] = Some(b);
            let c = run(sess, &s);
            match data_subs(&c).first().and_then(|f| f.first()) {
                Some(sub) if sub.cmd == first.cmd => got.push(req_bytes(sub)),
                _ => break,
            }
        }
        if got.len() < PASSES {
            continue;
        }
        // region byte q -> request byte r
        let mut map = vec![Src::Kept; len];
        let mut from_it = false;
        for r in 0..got.iter().map(Vec::len).max().unwrap_or(0) {
            let v: [u8; PASSES] = std::array::from_fn(|p| got[p].get(r).copied().unwrap_or(0));
            if v.iter().all(|x| base_req.get(r) == Some(x)) {
                continue;
            }
            if let Some(q) = decode(v)
                && q < len
                && map[q] == Src::Kept
            {
                map[q] = Src::At(r);
                from_it = true;
            }
        }
        // A C string sent in a fixed field: its bytes in order from a
        // payload offset (as many as the field holds, up to the string's).
        if from_it
            && is_bytes(&sh.args[i])
            && let Some(Src::At(r0)) = map
                .first()
                .copied()
                .filter(|s| matches!(s, Src::At(r) if *r >= 20))
        {
            let n = map
                .iter()
                .enumerate()
                .take_while(|(q, s)| **s == Src::At(r0 + q))
                .count();
            inputs.push(i);
            texts.push((i, r0 - 20, n));
            continue;
        }
        if from_it {
            inputs.push(i);
            let mut lv = Vec::new();
            leaves(&ty, 0, "", &mut lv);
            // A member whose low byte lands in a request word's low byte
            // (its higher bytes the word's next ones, or not sent): the
            // word is that member, when the plain call saw it constant.
            let mut map = map;
            for l in &lv {
                let Some(Src::At(r)) = map.get(l.off).copied() else {
                    continue;
                };
                let size = l.ty.size().min(map.len() - l.off);
                let sent = (1..size)
                    .take_while(|b| r >= *b && map[l.off + b] == Src::At(r - b))
                    .count()
                    + 1;
                let whole = (sent..size).all(|b| map[l.off + b] == Src::Kept);
                if r < 20
                    && r % 4 == 3
                    && sent <= 4
                    && whole
                    && let Some(w @ WordSrc::Const(_)) = form.words.get_mut(r / 4)
                {
                    *w = WordSrc::Input(l.path.clone());
                    for b in 0..size {
                        map[l.off + b] = Src::Kept;
                    }
                }
            }
            let mut odd = Vec::new();
            let mut p = placed(0, &map, &lv, &mut odd);
            // A member in a request word: the word is that member (its
            // position codes seen there), when the plain call saw it
            // constant; otherwise flagged.
            for x in &mut p {
                if x.at < 20 {
                    let k = x.at / 4;
                    match form.words.get_mut(k) {
                        Some(w @ WordSrc::Const(_)) => *w = WordSrc::Input(x.path.clone()),
                        _ => flags.push(format!("input {}'s {} goes in word {}", i, x.path, k)),
                    }
                }
            }
            p.retain(|x| x.at >= 20);
            for x in &mut p {
                x.at -= 20;
            }
            p.sort_by_key(|x| x.at);
            payload.extend(p);
            flags.extend(odd.into_iter().map(|o| format!("input {o}")));
        }
    }
    // Replies: position-coded, two passes, two fills.
    let ptrs: Vec<usize> = (0..n).filter(|i| sh.regions[*i].is_some()).collect();
    let mut reply = Vec::new();
    let mut moved_past = Vec::new();
    let mut outputs = Vec::new();
    let mut reply_len = 0;
    let mut echoes = Vec::new();
    let mut zeros = Vec::new();
    let mut last_plus = None;
    let mut zero_leaves: Vec<(usize, String, Int)> = Vec::new();
    let asked = sh
        .args
        .iter()
        .enumerate()
        .find(|(_, a)| matches!(a, Arg::IntPtr(_)))
        .map_or(usize::MAX, |(i, _)| base.vals[i].max(0) as usize);
    if !ptrs.is_empty() {
        let out_total: usize = ptrs
            .iter()
            .map(|i| match &sh.args[*i] {
                Arg::Ptr(t) | Arg::IntPtr(t) => t.size(),
                _ => 0,
            })
            .sum();
        // (payload length, a pinned 16-bit value, a number changed)
        type Try = (usize, Option<(usize, u16)>, Option<(usize, i64)>);
        let mut tries: Vec<Try> = vec![
            (1428, None, None),
            (out_total.max(4), None, None),
            (64, None, None),
            (8, None, None),
        ];
        for at in [0, 2, 4, 6, 8] {
            for v in [1u16, 2] {
                tries.push((1428, Some((at, v)), None));
            }
        }
        for (i, a) in sh.args.iter().enumerate() {
            if matches!(a, Arg::Num(_)) {
                for v in [4096, 1000, 100, 32767, 8, 0, -1] {
                    tries.push((1428, None, Some((i, v))));
                }
            }
        }
        let mut obs: Option<[[Vec<u8>; 2]; PASSES]> = None;
        let mut accepted = None;
        for (len, pin, change) in tries {
            let mut setup = base.clone();
            if let Some((i, v)) = change {
                setup.vals[i] = v;
            }
            let mut got: [[Vec<u8>; 2]; PASSES] = Default::default();
            let mut ok = true;
            'runs: for pass in 0..PASSES {
                for (f, fill) in [0xCCu8, 0x33].into_iter().enumerate() {
                    let c = sess.call(
                        fill,
                        &command(name, sh, &setup),
                        Some(fake_reply::coded(len, pass, pin)),
                    );
                    if c.crashed {
                        flags.push(format!("crashed on a {len}-byte coded reply"));
                        ok = false;
                        break 'runs;
                    }
                    if c.ret != Some(0) {
                        ok = false;
                        break 'runs;
                    }
                    got[pass][f] = c.b0;
                }
            }
            if ok {
                if let Some((at, v)) = pin {
                    flags.push(format!(
                        "arbitrary replies refused: a 16-bit {v} pinned at reply byte {at} let it through (a count or type tag)"
                    ));
                }
                if let Some((i, v)) = change {
                    flags.push(format!(
                        "replies refused until argument {i} was {v} (a length or room checked after the reply?)"
                    ));
                }
                reply_len = len;
                obs = Some(got);
                accepted = Some((len, pin, setup));
                break;
            }
        }
        match obs {
            None => flags
                .push("every coded reply was refused (a count, length or type tag inside)".into()),
            Some(o) => {
                for &i in &ptrs {
                    let (off, span) = sh.regions[i].unwrap();
                    let cut = |v: &Vec<u8>| v[off..off + span].to_vec();
                    let mut region: [[Vec<u8>; 2]; PASSES] =
                        std::array::from_fn(|p| [cut(&o[p][0]), cut(&o[p][1])]);
                    // a plain input's bytes left as they were read as kept
                    if let Some(pf) = accepted.as_ref().and_then(|a| a.2.fill_ptr[i].as_ref()) {
                        for (k, b) in pf.iter().enumerate() {
                            let same = region.iter().flatten().all(|r| r.get(k) == Some(b));
                            if same {
                                for r in &mut region {
                                    r[0][k] = 0xCC;
                                    r[1][k] = 0x33;
                                }
                            }
                        }
                    }
                    let mut map = map_bytes(&region);
                    if is_bytes(&sh.args[i]) && map.get(STRING) == Some(&Src::Const(0)) {
                        map[STRING] = Src::Kept; // the string's end, as passed
                    }
                    let ty = match &sh.args[i] {
                        Arg::Ptr(t) | Arg::IntPtr(t) => t.clone(),
                        _ => unreachable!(),
                    };
                    let size = ty.size().max(1);
                    let written: Vec<usize> = map
                        .iter()
                        .enumerate()
                        .filter(|(_, s)| **s != Src::Kept)
                        .map(|(k, _)| k)
                        .collect();
                    if written.is_empty() {
                        continue;
                    }
                    outputs.push(i);
                    let last = *written.last().unwrap();
                    // a char or void buffer: its bytes as an array
                    let ty = match ty {
                        Ty::Void => Ty::Int {
                            size: 1,
                            signed: false,
                        },
                        t => t,
                    };
                    // The caller's array of pointees: bytes written past
                    // the first are flagged (records into an array the
                    // caller sized, or an overrun).
                    let elems = last / size + 1;
                    if last >= size {
                        moved_past.push(format!(
                            "argument {i}: {} bytes written into a {size}-byte pointee",
                            last + 1
                        ));
                    }
                    let mut lv = Vec::new();
                    leaves(&Ty::Array(Box::new(ty.clone()), elems), 0, "", &mut lv);
                    if elems == 1 {
                        for l in &mut lv {
                            l.path = l
                                .path
                                .trim_start_matches("[0]")
                                .trim_start_matches('.')
                                .to_string();
                        }
                    }
                    let mut odd = Vec::new();
                    let here = placed(i, &map, &lv, &mut odd);
                    // bytes zeroed off the wire (a string's NUL, a text
                    // member's rest): learnt as zero fields, not flagged
                    let (zl, zb) = learnt_zeros(i, &map, &lv);
                    zeros.extend(zb);
                    zero_leaves.extend(zl.into_iter().map(|(p, c)| (i, p, c)));
                    reply.extend(here);
                    // what the first pointee holds (past it: the flag above)
                    let first: Vec<Leaf> = lv.iter().filter(|l| l.off < size).cloned().collect();
                    odd.clear();
                    placed(i, &map, &first, &mut odd);
                    // A leaf of constant bytes equal to a number argument:
                    // an echo when it follows the argument changed.
                    let (len, pin, setup) = accepted.clone().unwrap();
                    for l in &first {
                        let bytes = &map[l.off..(l.off + l.ty.size()).min(map.len())];
                        let consts: Option<Vec<u8>> = bytes
                            .iter()
                            .map(|b| match b {
                                Src::Const(v) => Some(*v),
                                _ => None,
                            })
                            .collect();
                        let (Some(consts), Some(c)) = (consts, l.ty.int()) else {
                            continue;
                        };
                        let value = le_value(&consts, matches!(c, Int::I8 | Int::I16 | Int::I32));
                        // the argument itself, or (the first number) plus
                        // the records written less one: the last number
                        // answered
                        let first_num = sh.args.iter().position(|a| matches!(a, Arg::Num(_)));
                        let mut cands = Vec::new();
                        for (k, a) in sh.args.iter().enumerate() {
                            let Arg::Num(t) = a else { continue };
                            let v = conv_of(t)(setup.vals[k]) as i64;
                            if v == value {
                                cands.push((k, 0, k));
                            }
                            if Some(k) == first_num && value > v && value - v < 0x8000 {
                                cands.push((k, value - v, LAST_ECHO));
                            }
                        }
                        'cand: for (k, plus, as_k) in cands {
                            let Arg::Num(t) = &sh.args[k] else { continue };
                            let mut s2 = setup.clone();
                            s2.vals[k] += 2;
                            // refused locally: the other numbers raised too
                            // (a range's end past its new start)
                            let mut s3 = s2.clone();
                            for (j, a) in sh.args.iter().enumerate() {
                                if j != k && matches!(a, Arg::Num(_)) {
                                    s3.vals[j] = s3.vals[j].max(s2.vals[k]);
                                }
                            }
                            for s2 in [s2, s3] {
                                let c2 = sess.call(
                                    0xCC,
                                    &command(name, sh, &s2),
                                    Some(fake_reply::coded(len, 0, pin)),
                                );
                                let (off, _) = sh.regions[i].unwrap();
                                let got = c2.b0.get(off + l.off..off + l.off + consts.len());
                                let want = conv_of(t)(s2.vals[k]) as i64 + plus;
                                if c2.ret == Some(0)
                                    && got
                                        .is_some_and(|g| le_value(g, value < 0 || want < 0) == want)
                                {
                                    echoes.push((i, l.path.clone(), c, as_k));
                                    if as_k == LAST_ECHO {
                                        last_plus = Some(plus);
                                    }
                                    let prefix = format!("out {i} {}: ", l.path);
                                    odd.retain(|o| !o.starts_with(&prefix));
                                    break 'cand;
                                }
                                if c2.ret == Some(0) {
                                    break;
                                }
                            }
                        }
                    }
                    let zeroed = |o: &String| {
                        zero_leaves
                            .iter()
                            .any(|(k, p, _)| *k == i && o.starts_with(&format!("out {i} {p}: ")))
                    };
                    for o in odd {
                        if !zeroed(&o) {
                            flags.push(format!("reply: {o}"));
                        }
                    }
                    let _ = hdr_types;
                }
                reply.sort_by_key(|x| (x.at, x.out, x.off));
            }
        }
    }
    if sess.slow >= 3 {
        flags.push("calls timed out: learning stopped early".into());
    }
    if sess.stateful {
        flags.push(
            "state kept between calls: a call that sent nothing sent its request from a fresh process"
                .into(),
        );
    }
    Ok(ClassLearnt {
        form: Some(form),
        checks,
        observed,
        base: base.vals.clone(),
        reply,
        reply_len,
        asked,
        moved_past,
        payload,
        inputs,
        texts,
        outputs,
        echoes,
        zeros,
        zero_leaves,
        last_plus,
        base_fill: base.fill_ptr.clone(),
        local: None,
        own_form,
        flags,
    })
}

/// A function that sends nothing on any class and returns EW_OK: what its
/// plain call writes into each output (filled 0xCC, then 0x33), the
/// integers written whatever the fill.
fn learn_local(sess: &mut Session, name: &str, sh: &Shape) -> Result<ClassLearnt, String> {
    let n = sh.args.len();
    let base = Setup {
        vals: sh
            .args
            .iter()
            .map(|a| if matches!(a, Arg::IntPtr(_)) { 4 } else { 1 })
            .collect(),
        fill_ptr: vec![None; n],
    };
    let cmd = command(name, sh, &base);
    let a = sess.call(0xCC, &cmd, None);
    let b = sess.call(0x33, &cmd, None);
    if traffic(&a) || traffic(&b) || a.ret != Some(0) || b.ret != Some(0) {
        return Err("a local answer on one call, not on the next".into());
    }
    let mut values = Vec::new();
    let mut outputs = Vec::new();
    for (i, arg) in sh.args.iter().enumerate() {
        let (Some((off, span)), Arg::Ptr(t) | Arg::IntPtr(t)) = (sh.regions[i], arg) else {
            continue;
        };
        let region = |c: &Call| c.b0[off..off + span].to_vec();
        let obs: [[Vec<u8>; 2]; PASSES] = std::array::from_fn(|_| [region(&a), region(&b)]);
        let map = map_bytes(&obs);
        let mut lv = Vec::new();
        leaves(t, 0, "", &mut lv);
        for l in lv {
            let bytes: Option<Vec<u8>> = map
                .get(l.off..l.off + l.ty.size())
                .into_iter()
                .flatten()
                .map(|s| match s {
                    Src::Const(v) => Some(*v),
                    _ => None,
                })
                .collect();
            if let (Some(b), Some(_)) = (bytes, l.ty.int())
                && b.len() == l.ty.size()
            {
                values.push((i, l.path.clone(), le_value(&b, true)));
                if !outputs.contains(&i) {
                    outputs.push(i);
                }
            }
        }
    }
    Ok(ClassLearnt {
        base: base.vals,
        outputs,
        local: Some(values),
        flags: vec!["no request on any class: a local answer".into()],
        ..ClassLearnt::default()
    })
}

/// A request subpacket's words (20 bytes) and payload, as sent.
fn req_bytes(s: &Sub) -> Vec<u8> {
    let mut v: Vec<u8> = s.words.iter().flat_map(|w| w.to_be_bytes()).collect();
    v.extend_from_slice(&s.payload);
    v
}

/// The learnt function on every class, and its draft.
struct Learnt {
    draft: Draft,
    per_class: Vec<(&'static str, ClassLearnt)>,
}

fn learn(
    probe_exe: &Path,
    lib: &Path,
    hdr: &Header,
    name: &str,
    calls: &mut usize,
) -> Result<Learnt, String> {
    let proto = hdr.proto(name).ok_or("not in the header")?;
    let sh = shape(proto)?;
    let types: Vec<Ty> = proto.params.iter().map(|p| p.0.clone()).collect();
    let mut per = Vec::new();
    let mut local = Vec::new();
    let mut machine = None;
    let mut classes: &[(&str, &str)] = &CLASSES;
    let mut k = 0;
    while k < classes.len() {
        let (class, cname) = classes[k];
        let mut s = Session::new(probe_exe, lib, class);
        let r = learn_class(&mut s, name, &sh, &types);
        *calls += s.calls;
        match r {
            Ok(l) => per.push((cname, l)),
            // FANUC's library sends some functions only to the machine
            // type that has them: a punch press's start-up sysinfo.
            Err(e) if per.is_empty() && machine.is_none() && e.starts_with("no traffic") => {
                machine = Some(e);
                classes = &PUNCH;
                continue;
            }
            // No request on any class, EW_OK: a local answer, its
            // outputs learnt on each class.
            Err(e)
                if per.is_empty()
                    && machine
                        .as_deref()
                        .is_some_and(|m| m.starts_with("no traffic (returns 0 "))
                    && e.starts_with("no traffic (returns 0 ") =>
            {
                for (class, cname) in CLASSES {
                    let mut s = Session::new(probe_exe, lib, class);
                    let l = learn_local(&mut s, name, &sh);
                    *calls += s.calls;
                    per.push((cname, l?));
                }
                machine = None;
                break;
            }
            Err(e) if per.is_empty() => return Err(machine.unwrap_or(e)),
            // a local answer on this class: no form for it
            Err(e) if e.starts_with("no traffic") => local.push(format!("on {class}: {e}")),
            Err(e) => {
                return Err(format!("learnt on the 30i class, not on {class}: {e}"));
            }
        }
        k += 1;
    }
    let punch = machine.is_some();
    let mut d = Draft {
        name: name.into(),
        ..Draft::default()
    };
    let (_, l30) = &per[0];
    // Params: names from the header's position, kinds from what was learnt.
    let mut numbers = Vec::new();
    for (i, a) in sh.args.iter().enumerate() {
        let pname = format!("a{i}");
        let spelled = proto.params[i + 1].1.clone();
        d.params.push(match a {
            Arg::Num(Ty::Int { size: 4, .. }) => {
                numbers.push(i);
                DParam::Long(pname)
            }
            Arg::Num(_) => {
                numbers.push(i);
                DParam::Short(pname)
            }
            Arg::IntPtr(t) => {
                let in_word = l30
                    .form
                    .as_ref()
                    .is_some_and(|f| f.words.contains(&WordSrc::Arg(i)));
                if in_word {
                    numbers.push(i);
                    DParam::Count(pname)
                } else if l30.inputs.contains(&i) {
                    DParam::In(pname, c_name(t, &spelled))
                } else {
                    DParam::Out(pname, c_name(t, &spelled))
                }
            }
            Arg::Ptr(t) => {
                if l30.inputs.contains(&i) {
                    DParam::In(pname, c_name(t, &spelled))
                } else {
                    DParam::Out(pname, c_name(t, &spelled))
                }
            }
        });
    }
    let number_index = |i: usize| numbers.iter().position(|n| *n == i).unwrap_or(i);
    // Forms: one for every class when they agree.
    let forms: Vec<(&str, DForm)> = per
        .iter()
        .filter_map(|(c, l)| l.form.clone().map(|f| (*c, f)))
        .collect();
    let renumber = |f: &DForm| {
        let mut f = f.clone();
        for w in &mut f.words {
            match w {
                WordSrc::Arg(i) => *w = WordSrc::Arg(number_index(*i)),
                WordSrc::Nonzero(i, k) => *w = WordSrc::Nonzero(number_index(*i), *k),
                _ => {}
            }
        }
        f
    };
    let same = |a: &DForm, b: &DForm| a.class == b.class && a.cmd == b.cmd && a.words == b.words;
    if punch {
        d.flags.push(
            "machine type: no traffic on a mill; learnt on a punch press (30i and 16i, no Series 15)"
                .into(),
        );
    }
    for l in &local {
        d.flags
            .push(format!("no request {l} (a local answer on that class)"));
    }
    if !local.is_empty() {
        // each learnt class its own form, Series 15 before the 16i class
        let mut v: Vec<DForm> = forms
            .iter()
            .map(|(c, f)| {
                let mut f = renumber(f);
                f.classes = c;
                f
            })
            .collect();
        v.sort_by_key(|f| match f.classes {
            "S30" => 0,
            "S15" => 1,
            _ => 2,
        });
        d.forms = v;
    } else if forms.is_empty() {
        // a local answer: no request on any class
    } else if forms.iter().all(|f| same(&f.1, &forms[0].1)) {
        d.forms.push(renumber(&forms[0].1));
    } else if forms.len() == 2 {
        let (mut a, mut b) = (renumber(&forms[0].1), renumber(&forms[1].1));
        a.classes = "S30";
        b.classes = "S16";
        d.forms.extend([a, b]);
    } else {
        let (f30, f16, f15) = (&forms[0].1, &forms[1].1, &forms[2].1);
        let mut a = renumber(f30);
        a.classes = "S30";
        if same(f15, f16) {
            let mut b = renumber(f16);
            b.classes = "S16";
            d.forms.extend([a, b]);
        } else {
            let (mut b, mut c) = (renumber(f15), renumber(f16));
            b.classes = "S15";
            c.classes = "S16";
            d.forms.extend([a, b, c]);
        }
    }
    d.checks = l30
        .checks
        .iter()
        .map(|c| LearntCheck {
            arg: number_index(c.arg),
            ..*c
        })
        .collect();
    for (c, l) in &per[1..] {
        if l.checks != l30.checks {
            d.flags
                .push(format!("local checks differ on {c}: {:?}", l.checks));
        }
        if moves(&l.reply) != moves(&l30.reply) {
            d.flags.push(format!("the reply maps otherwise on {c}"));
        }
    }
    // Reply: a group of fields repeated at a fixed stride into an array
    // (a member's or the caller's) is the records.
    let mut reply = l30.reply.clone();
    let elem_size = |out: usize| match sh.args.get(out) {
        Some(Arg::Ptr(t) | Arg::IntPtr(t)) => t.size().max(1),
        _ => 0,
    };
    // records into the caller's array: one pointee each
    let whole = repeat(&reply).filter(|r| r.out == elem_size(reply[r.first].out));
    if let Some(r) = whole {
        let rec: Vec<Placed> = reply[r.first..r.first + r.per].to_vec();
        reply.truncate(r.first);
        d.records = Some((rec, r));
    } else {
        // the first pointee's fields (what was written past it is
        // flagged), records in one of its arrays
        reply.retain(|x| !x.path.starts_with('[') || x.path.starts_with("[0]"));
        if let Some(r) = repeat(&reply).filter(|r| r.per > 1) {
            let rec: Vec<Placed> = reply[r.first..r.first + r.per].to_vec();
            reply.truncate(r.first);
            d.records = Some((rec, r));
        }
    }
    d.flags.extend(
        l30.moved_past
            .iter()
            .map(|m| format!("written past the pointee: {m}")),
    );
    // outputs by their index among the Out parameters
    let out_index: Vec<usize> = d
        .params
        .iter()
        .enumerate()
        .filter(|(_, p)| matches!(p, DParam::Out(..)))
        .map(|(i, _)| i)
        .collect();
    let renum = |v: &mut Vec<Placed>| {
        for p in v.iter_mut() {
            p.out = out_index.iter().position(|o| *o == p.out).unwrap_or(p.out);
        }
    };
    renum(&mut reply);
    if let Some((rec, _)) = &mut d.records {
        renum(rec);
    }
    d.reply = reply;
    d.echoes = l30
        .echoes
        .iter()
        .map(|(o, path, c, k)| {
            (
                out_index.iter().position(|x| x == o).unwrap_or(*o),
                path.clone(),
                *c,
                number_index(*k),
            )
        })
        .collect();
    d.zeros = l30
        .zero_leaves
        .iter()
        .map(|(o, path, c)| {
            (
                out_index.iter().position(|x| x == o).unwrap_or(*o),
                path.clone(),
                *c,
            )
        })
        .collect();
    d.payload = l30.payload.clone();
    for f in &l30.flags {
        d.flags.push(f.clone());
    }
    for (c, l) in &per[1..] {
        for f in &l.flags {
            if !l30.flags.contains(f) {
                d.flags.push(format!("{c}: {f}"));
            }
        }
    }
    if l30.outputs.is_empty() && sh.regions.iter().any(Option::is_some) && l30.inputs.is_empty() {
        d.flags.push("no output written and no input read".into());
    }
    Ok(Learnt {
        draft: d,
        per_class: per,
    })
}

/// The table's C type name of a pointee: a typedef's name as the header
/// spells it, or the scalar's.
fn c_name(t: &Ty, spelled: &str) -> String {
    match t {
        Ty::Int { size: 1, .. } => "char".into(),
        Ty::Int {
            size: 2,
            signed: true,
        } => "short".into(),
        Ty::Int {
            size: 2,
            signed: false,
        } => "unsigned short".into(),
        Ty::Int { size: 4, .. } => "long".into(),
        _ => spelled
            .split_whitespace()
            .find(|w| w.chars().next().is_some_and(|c| c.is_ascii_uppercase()))
            .unwrap_or(spelled)
            .to_string(),
    }
}

fn load_header(path: &Path) -> Header {
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let out = std::process::Command::new(&cc)
        .args(["-E", "-P", "-x", "c"])
        .arg(path)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cc}: {e}"));
    assert!(out.status.success(), "{cc} -E {} failed", path.display());
    Header::parse(&String::from_utf8_lossy(&out.stdout))
}

/// What the learner's map of a class leaves incomplete: the coded replies
/// refused, crashing, let through only by a pinned count, or spread over
/// several subpackets.
fn map_incomplete(cl: &ClassLearnt) -> Option<&'static str> {
    const INCOMPLETE: &[(&str, &str)] = &[
        (
            "every coded reply was refused",
            "every coded reply refused (a count, length or type tag inside)",
        ),
        (
            "crashed on a",
            "FANUC's library crashes on coded replies (a count inside)",
        ),
        (
            "pinned at reply byte",
            "coded replies let through only with a count pinned (one record mapped)",
        ),
        (
            "more subpackets or frames",
            "several subpackets: the coded reply's offsets run across them",
        ),
    ];
    INCOMPLETE
        .iter()
        .find(|(k, _)| cl.flags.iter().any(|f| f.contains(k)))
        .map(|(_, why)| *why)
}

/// Why a class's reply is not compared byte for byte: the committed entry
/// reads it otherwise than by moving bytes ([`entry_not_clean`]), with what
/// the learner saw. Err: the entry reads plain fields, yet the learner
/// could not map them (a difference, not a reason).
fn reply_not_comparable(
    f: &fwlib32::spec::Func,
    cl: &ClassLearnt,
) -> Result<Option<String>, String> {
    let reads = !f.reply.is_empty() || f.records.is_some() || !f.lookups.is_empty();
    match (entry_not_clean(f), map_incomplete(cl)) {
        (Some(e), Some(seen)) => Ok(Some(format!("{e}; learnt: {seen}"))),
        (Some(e), None) => Ok(Some(e)),
        // a write that reads nothing of its answer: no reply to map
        (None, Some(_)) if !reads => Ok(None),
        (None, Some(seen)) => Err(format!(
            "the entry reads plain fields, the learner could not map them: {seen}"
        )),
        (None, None) => Ok(None),
    }
}

/// The committed entry against the draft: the differences, and per class
/// the reason a reply was not compared.
fn compare(f: &fwlib32::spec::Func, l: &Learnt, hdr: &Header) -> (Vec<String>, Vec<String>) {
    let mut bad = Vec::new();
    let mut not_compared = Vec::new();
    let proto = hdr.proto(f.name).unwrap();
    // committed number index -> C parameter position
    let positions: Vec<usize> = f
        .params
        .iter()
        .enumerate()
        .filter(|(_, p)| {
            matches!(
                p,
                fwlib32::spec::Param::Short(_)
                    | fwlib32::spec::Param::ShortAs(..)
                    | fwlib32::spec::Param::Long(_)
                    | fwlib32::spec::Param::ULong(_)
                    | fwlib32::spec::Param::UShort(_)
                    | fwlib32::spec::Param::Char(_)
                    | fwlib32::spec::Param::Count(_)
                    | fwlib32::spec::Param::LongCount(_)
                    | fwlib32::spec::Param::Io(_)
            )
        })
        .map(|(i, _)| i)
        .collect();
    for (cname, cl) in &l.per_class {
        let (s16, s15) = match *cname {
            "S30" => (false, false),
            "S16" => (true, false),
            _ => (true, true),
        };
        // An exchange before the function's own request on this class
        // (a write block's attributes read, a parameter per record): the
        // last request compared.
        let exchange = f
            .block
            .and_then(|b| b.attributes)
            .is_some_and(|c| c.matches(s16, s15))
            || f.each.iter().any(|e| e.classes.matches(s16, s15));
        let learnt_form = match (&cl.own_form, exchange) {
            (Some(o), true) => {
                not_compared.push(format!(
                    "request on {cname}: an exchange goes first ({:#06x}, {}), the function's own request compared",
                    cl.form.as_ref().map_or(0, |x| x.cmd),
                    if f.each.is_empty() { "Block::attributes" } else { "Func::each" }
                ));
                Some(o.clone())
            }
            _ => cl.form.clone(),
        };
        match (committed_words(f, s16, s15), &learnt_form) {
            (Some(mut c), Some(learnt)) => {
                for w in &mut c.2 {
                    let pos = |i: &usize| positions.get(*i).copied().unwrap_or(usize::MAX);
                    match w {
                        WordSrc::Arg(i) => *w = WordSrc::Arg(pos(i)),
                        WordSrc::Nonzero(i, k) => *w = WordSrc::Nonzero(pos(i), *k),
                        _ => {}
                    }
                }
                // a count capped by the entry's max: the same word for
                // every value tried is constant, not the argument
                let mut learnt = learnt.clone();
                for (k, w) in learnt.words.iter_mut().enumerate() {
                    if let (WordSrc::Const(_), WordSrc::Arg(i)) = (&*w, &c.2[k])
                        && f.count().and_then(|n| positions.get(n)) == Some(i)
                    {
                        *w = WordSrc::Arg(*i);
                    }
                }
                if let Err(e) = same_form(&learnt, &c) {
                    bad.push(format!("request on {cname}: {e}"));
                }
            }
            // a local answer: no form, the entry's learnt figures written
            (None, None) => {
                let local = f.local.filter(|l| l.classes.matches(s16, s15));
                match (local, &cl.local) {
                    (Some(lo), Some(got)) => {
                        let fields = f.reply.iter().filter(|x| x.to.is_some());
                        for (fld, what) in fields.zip(lo.values) {
                            let want = match what {
                                fwlib32::spec::Learnt::PmcUnit => 1,
                                fwlib32::spec::Learnt::MaxSpindles => {
                                    not_compared.push(format!(
                                        "local answer on {cname}: the CNC's maximum spindles (learnt at connect)"
                                    ));
                                    continue;
                                }
                            };
                            let pos = f
                                .outs()
                                .nth(usize::from(fld.out))
                                .and_then(|(n, _)| f.params.iter().position(|p| p.name() == n));
                            let path = fld.to.unwrap_or("");
                            let learnt = got
                                .iter()
                                .find(|(o, p, _)| Some(*o) == pos && member_name(p) == path)
                                .map(|x| fld.c.cut(x.2));
                            if learnt != Some(want) {
                                bad.push(format!(
                                    "local answer on {cname}: {path:?} learnt {learnt:?}, committed {want}"
                                ));
                            }
                        }
                    }
                    _ => bad.push(format!(
                        "request on {cname}: none learnt (a local answer), the entry's local answer {}",
                        if local.is_some() { "learnt no output" } else { "does not cover this class" }
                    )),
                }
            }
            (c, _) => bad.push(format!("request on {cname}: committed {c:?}")),
        }
        let convs: Vec<fn(i64) -> i32> = proto.params[1..]
            .iter()
            .map(|p| match &p.0 {
                Ty::Ptr(t) => conv_of(t),
                t => conv_of(t),
            })
            .collect();
        // value by value as observed (a sweep that is not one range has
        // no learnt check, yet each value's answer is known): the committed
        // entry's answer on this class for the plain call with that one
        // argument changed (its checks, an order check included, the ends
        // of its ranges; traffic where its first request goes)
        let at = |p: usize, v: i64| convs.get(p).map_or(v as i32, |c| c(v));
        let mut plain: Vec<i32> = positions
            .iter()
            .map(|&p| cl.base.get(p).map_or(0, |v| at(p, *v)))
            .collect();
        // the input members a request word carries, as the plain call's
        // input held them (the call's arguments after its numbers)
        if let Some((n, _)) = f.input() {
            let pos = f.params.iter().position(|p| p.name() == n);
            let fill = pos.and_then(|p| cl.base_fill.get(p).cloned().flatten());
            let ty = pos.and_then(|p| match &proto.params.get(p + 1)?.0 {
                Ty::Ptr(t) => Some((**t).clone()),
                _ => None,
            });
            for (m, c) in f.inputs() {
                let v = match (&fill, &ty) {
                    (Some(b), Some(t)) => member(t, m)
                        .and_then(|(o, mt)| b.get(o..o + mt.size()))
                        .map_or(0, |b| c.cut(le_value(b, true)) as i32),
                    // filled with 0xCC
                    _ => c.cut(le_value(&[0xCC; 4], true)) as i32,
                };
                plain.push(v);
            }
        }
        // the input's record size (its records' member's element)
        let room_elem = f
            .input()
            .and_then(|(n, _)| f.params.iter().position(|p| p.name() == n))
            .and_then(|p| match &proto.params.get(p + 1)?.0 {
                Ty::Ptr(t) => Some((**t).clone()),
                _ => None,
            })
            .and_then(|t| member(&t, f.payload_in))
            .map_or(0, |(_, t)| match t {
                Ty::Array(e, _) => e.size(),
                t => t.size(),
            });
        let answer = |p: usize, v: i64| {
            let mut a = plain.clone();
            if let Some(k) = positions.iter().position(|&q| q == p) {
                a[k] = at(p, v);
            }
            // The checks before a first request (First::after), then it.
            let early = f.first.map_or(0, |fr| usize::from(fr.after));
            if let Some(code) = f.checks_fail(early, &a, true) {
                Some(code)
            } else if f.sends_first(&a, s16, s15) {
                None
            } else if let Some(code) = f.refusal(&a, s16, s15, true) {
                Some(code)
            } else if f.pages.is_some() && f.count().and_then(|c| a.get(c)).is_some_and(|n| *n <= 0)
            {
                // a paging function with no records to do sends nothing
                // (src/ffi/described/pages.rs) and returns EW_OK
                Some(0)
            } else {
                // a range write's room before its first request
                // (Pages::room: head + the first page's records, the
                // input's element size each, within the caller's bytes)
                let pg = f.pages?;
                let (r, head) = pg.room?;
                let k = f.span_cut(&a, s16, s15)?.min(f.per_page()?);
                let room = a.get(usize::from(r)).copied()?;
                (usize::from(head) + k * room_elem > room.max(0) as usize)
                    .then_some(fwlib32::ew::EW_LENGTH)
            }
        };
        if let Err(e) = same_answers_by(&cl.observed, answer) {
            bad.push(format!("checks on {cname}: {e}"));
        }

        // The reply: what the committed entry moves for the same payload.
        // Lookups: the bytes outside their members are compared.
        let (why, lookups_only) = match reply_not_comparable(f, cl) {
            Ok(w) => {
                let lo = w.is_some() && !f.lookups.is_empty() && map_incomplete(cl).is_none();
                (w, lo)
            }
            Err(e) => {
                bad.push(format!("reply on {cname}: {e}"));
                (Some(String::new()), false)
            }
        };
        if let Some(w) = why.as_ref().filter(|w| !w.is_empty()) {
            let rest = if lookups_only {
                "; the bytes outside them compared"
            } else {
                ""
            };
            not_compared.push(format!("reply on {cname}: {w}{rest}"));
        }
        let compare_reply = why.is_none() || lookups_only;
        if compare_reply && cl.reply_len > 0 {
            // each committed output's element type and C position
            let outs: Vec<(usize, Ty)> = f
                .outs()
                .filter_map(|(n, _)| {
                    let pos = f.params.iter().position(|p| p.name() == n)?;
                    let t = match &proto.params.get(pos + 1)?.0 {
                        Ty::Ptr(t) => match &**t {
                            Ty::Void => Ty::Int {
                                size: 1,
                                signed: false,
                            },
                            t => t.clone(),
                        },
                        t => t.clone(),
                    };
                    Some((pos, t))
                })
                .collect();
            let elems: Vec<Ty> = outs.iter().map(|o| o.1.clone()).collect();
            let asked = if f.count().is_some() {
                cl.asked
            } else {
                usize::MAX
            };
            match expected(f, &elems, cl.reply_len, asked) {
                Ok(mut e) => {
                    for p in &mut e {
                        p.out = outs.get(p.out).map_or(usize::MAX, |o| o.0);
                    }
                    // Without a count the caller's room is one pointee:
                    // what FANUC's library writes past it is flagged, and
                    // how many records a CNC sends is the CNC's.
                    // With a count, the caller's array holds what was asked.
                    // A committed `char[N]` or `text[N]` output: N elements.
                    let n = if f.count().is_some() { cl.asked } else { 1 };
                    let elems_of = |pos: usize| {
                        let t = f.params.get(pos).and_then(|p| match p {
                            fwlib32::spec::Param::Out(_, t) => Some(*t),
                            _ => None,
                        });
                        t.and_then(|t| t.strip_suffix(']'))
                            .and_then(|t| t.rsplit_once('['))
                            .and_then(|(_, k)| k.parse::<usize>().ok())
                            .unwrap_or(1)
                    };
                    let room = |m: &(usize, usize, Src)| {
                        outs.iter().find(|o| o.0 == m.0).is_some_and(|o| {
                            // a `char *` the entry reads as `char[N]`
                            let k = if matches!(o.1, Ty::Int { .. }) {
                                elems_of(o.0)
                            } else {
                                1
                            };
                            m.1 < n * k * o.1.size()
                        })
                    };
                    let spans = if lookups_only {
                        outs.first()
                            .map(|(p, t)| (*p, lookup_spans(f, t)))
                            .unwrap_or((usize::MAX, Vec::new()))
                    } else {
                        (usize::MAX, Vec::new())
                    };
                    let looked_up = |m: &(usize, usize, Src)| {
                        m.0 == spans.0 && spans.1.iter().any(|(o, k)| (*o..o + k).contains(&m.1))
                    };
                    let room = |m: &(usize, usize, Src)| room(m) && !looked_up(m);
                    let mut me: Vec<_> = moves(&e).into_iter().filter(room).collect();
                    let mut ml: Vec<_> = moves(&cl.reply).into_iter().filter(room).collect();
                    // A member zeroed on a condition of another (the coded
                    // value decides): each of its bytes learnt as
                    // committed or as 0, then left out on both sides.
                    if let Some(z) = &f.zero_unless {
                        let zb = outs.first().and_then(|(p, t)| {
                            let (o, mt) = member(t, z.zero)?;
                            Some((*p, o, mt.size()))
                        });
                        if let Some((p, o, n)) = zb {
                            let inside =
                                |m: &(usize, usize, Src)| m.0 == p && (o..o + n).contains(&m.1);
                            let learnt_ok = ml
                                .iter()
                                .filter(|m| inside(m))
                                .all(|m| m.2 == Src::Const(0) || me.iter().any(|c| c == m));
                            if learnt_ok {
                                me.retain(|m| !inside(m));
                                ml.retain(|m| !inside(m));
                            }
                        }
                    }
                    if me != ml {
                        let first = me
                            .iter()
                            .zip(&ml)
                            .find(|(a, b)| a != b)
                            .map(|(a, b)| format!("committed {a:?}, learnt {b:?}"))
                            .unwrap_or_else(|| {
                                format!("{} bytes committed, {} learnt", me.len(), ml.len())
                            });
                        bad.push(format!("reply on {cname}: {first}"));
                    }
                    // Bytes written as 0 off the wire (a string's NUL, a
                    // text member's rest): the entry's zero fields. A
                    // member zeroed on a condition is left out.
                    let zu = f.zero_unless.as_ref().and_then(|z| {
                        let (p, t) = outs.first()?;
                        let (o, mt) = member(t, z.zero)?;
                        Some((*p, o, mt.size()))
                    });
                    let keep = |z: &(usize, usize)| {
                        room(&(z.0, z.1, Src::Kept))
                            && zu.is_none_or(|(p, o, n)| !(z.0 == p && (o..o + n).contains(&z.1)))
                    };
                    match committed_zeros(f, &elems, cl.reply_len, asked) {
                        Ok(cz) => {
                            let mut cz: Vec<(usize, usize)> = cz
                                .into_iter()
                                .map(|(o, b)| (outs.get(o).map_or(usize::MAX, |x| x.0), b))
                                .filter(keep)
                                .collect();
                            let mut lz: Vec<(usize, usize)> =
                                cl.zeros.iter().copied().filter(keep).collect();
                            cz.sort();
                            lz.sort();
                            if cz != lz {
                                let only = |a: &[(usize, usize)], b: &[(usize, usize)]| {
                                    a.iter()
                                        .filter(|x| !b.contains(x))
                                        .take(4)
                                        .copied()
                                        .collect::<Vec<_>>()
                                };
                                bad.push(format!(
                                    "zeroed bytes on {cname}: {} committed, {} learnt (committed only {:?}, learnt only {:?}; (argument, byte))",
                                    cz.len(),
                                    lz.len(),
                                    only(&cz, &lz),
                                    only(&lz, &cz)
                                ));
                            }
                        }
                        Err(e) => bad.push(format!("zeroed bytes on {cname}: {e}")),
                    }
                }
                Err(e) => bad.push(format!("reply on {cname}: committed entry unreadable: {e}")),
            }
        } else if why.is_none() && cl.form.is_some() && (!f.reply.is_empty() || f.records.is_some())
        {
            bad.push(format!("reply on {cname}: not mapped"));
        }
        // Arguments written back into outputs (the zero fields compared
        // above; the last number answered, `LAST`, as no argument).
        if cl.reply_len > 0 && compare_reply {
            let out_pos = |o: u8| {
                f.outs()
                    .nth(o as usize)
                    .and_then(|(n, _)| f.params.iter().position(|p| p.name() == n))
            };
            let mut want: Vec<(Option<usize>, String, Option<usize>)> = f
                .reply
                .iter()
                .filter_map(|x| {
                    let a = x.arg.filter(|a| *a != fwlib32::spec::ZERO)?;
                    Some((
                        out_pos(x.out),
                        x.to.unwrap_or("").to_string(),
                        positions.get(a as usize).copied(),
                    ))
                })
                .collect();
            let mut got: Vec<(Option<usize>, String, Option<usize>)> = cl
                .echoes
                .iter()
                .map(|(o, path, _, k)| {
                    (
                        Some(*o),
                        member_name(path),
                        Some(*k).filter(|k| *k != LAST_ECHO),
                    )
                })
                .collect();
            want.sort();
            got.sort();
            // the last number answered: the first number plus the records
            // the entry reads from the coded reply, less one
            let has_last = f.reply.iter().any(|x| x.arg == Some(fwlib32::spec::LAST));
            if let (true, Some(plus), Some(r)) = (has_last, cl.last_plus, &f.records) {
                let fixed: usize = f.reply.iter().map(|x| x.wire_len()).sum();
                let n = (cl.reply_len.saturating_sub(fixed) / r.wire_len().max(1))
                    .min(usize::from(r.max));
                if plus + 1 != n as i64 {
                    bad.push(format!(
                        "last number answered on {cname}: learnt the first number + {plus}, the entry reads {n} records"
                    ));
                }
            }
            if want != got {
                bad.push(format!(
                    "echoed arguments on {cname}: committed {want:?}, learnt {got:?}"
                ));
            }
        }
        // The payload: the bytes of one input record sent.
        let text_input = f
            .payload
            .as_ref()
            .is_some_and(|p| p.count == fwlib32::spec::TEXT);
        if let Some((_, ty)) = f.input().filter(|_| !text_input) {
            let pos = f
                .params
                .iter()
                .position(|p| p.name() == f.input().unwrap().0);
            let elem = pos
                .and_then(|p| proto.params.get(p + 1))
                .map(|p| match &p.0 {
                    Ty::Ptr(t) => (**t).clone(),
                    t => t.clone(),
                });
            let values = f.payload.as_ref().is_some_and(|p| {
                p.fields
                    .iter()
                    .any(|x| x.wire == fwlib32::spec::Int::BaseExp)
            });
            let computed = !f.codes.is_empty();
            if values || computed {
                not_compared.push(format!(
                    "payload on {cname}: {}",
                    if values {
                        "value records: digits and decimal places converted, not bytes moved"
                    } else {
                        "fields computed from the input (Func::codes), not bytes moved"
                    }
                ));
            } else {
                match elem.ok_or("no input").and_then(|e| {
                    expected_payload(f, &e).map_err(|_| "committed payload unreadable")
                }) {
                    Ok(e) => {
                        let (me, ml) = (payload_moves(&e), payload_moves(&cl.payload));
                        if me != ml {
                            bad.push(format!(
                                "payload on {cname}: committed {} bytes, learnt {} ({ty})",
                                me.len(),
                                ml.len()
                            ));
                        }
                    }
                    Err(e) => bad.push(format!("payload on {cname}: {e}")),
                }
            }
        }
        // Text fields: each C string's bytes from its field's offset, as
        // many as the field holds (the learner's string is STRING long).
        let mut want_texts = Vec::new();
        let mut at = 0;
        for (n, size) in f.texts() {
            let pos = f.params.iter().position(|p| p.name() == n);
            want_texts.push((pos.unwrap_or(usize::MAX), at, size.min(STRING)));
            at += size;
        }
        // an input whose payload is one C string (`count: TEXT`)
        if let (Some(pl), Some((n, _))) = (&f.payload, f.input())
            && pl.count == fwlib32::spec::TEXT
        {
            let pos = f.params.iter().position(|p| p.name() == n);
            let size: usize = pl.fields.iter().map(|x| x.wire_len()).sum();
            want_texts.push((pos.unwrap_or(usize::MAX), at, size.min(STRING)));
        }
        if want_texts != cl.texts {
            bad.push(format!(
                "text fields on {cname}: committed {want_texts:?}, learnt {:?} (argument, payload offset, bytes)",
                cl.texts
            ));
        }
    }
    (bad, not_compared)
}

fn reason(e: &str) -> String {
    let cut = e
        .find(|c: char| c.is_ascii_digit() || c == '(' || c == ':')
        .unwrap_or(e.len());
    e[..cut].trim().to_string()
}

/// What kind of thing a flag leaves unsettled (the counts per function).
fn category(flag: &str) -> &'static str {
    const KINDS: &[(&str, &str)] = &[
        ("timed out", "calls timed out"),
        ("crashed on a", "crashes on a coded reply"),
        (
            "every coded reply was refused",
            "coded replies refused (count, length or type tag)",
        ),
        ("pinned at reply byte", "a count pinned to map the reply"),
        (
            "replies refused until argument",
            "a length or room argument",
        ),
        ("written past the pointee", "writes past the pointee"),
        ("maps otherwise on", "reply differs per class"),
        ("local checks differ on", "local checks differ per class"),
        ("check:", "local checks not one range"),
        ("more subpackets or frames", "several subpackets or frames"),
        ("computed:", "request word computed"),
        ("goes in word", "input field in a request word"),
        ("input ", "input bytes not a plain integer"),
        ("echo", "argument echoed into the output"),
        ("float", "floating-point fields"),
        ("no output written", "no output written, no input read"),
        ("punch press", "learnt on a punch press"),
        ("a local answer on that class", "no request on some class"),
        ("state kept between calls", "state kept between calls"),
        ("reply:", "computed or constant output bytes"),
    ];
    KINDS
        .iter()
        .find(|k| flag.contains(k.0))
        .map_or("other", |k| k.1)
}

pub fn run(o: &Opts, probe_exe: &Path) -> i32 {
    let hdr = load_header(&o.header);
    eprintln!(
        "learn: {} prototypes, {} types in the header",
        hdr.protos.len(),
        hdr.types.len()
    );
    let names: Vec<String> = if o.check {
        fwlib32::spec::FUNCS
            .iter()
            .map(|f| f.name.to_string())
            .filter(|n| o.only.is_empty() || o.only.contains(n))
            .collect()
    } else if o.unexported {
        let ours: Vec<&str> = fwlib32::ffi::exports::EXPORTS
            .iter()
            .map(|e| e.name)
            .collect();
        let mut v: Vec<String> = hdr
            .protos
            .iter()
            .map(|p| p.name.clone())
            .filter(|n| {
                (n.starts_with("cnc_") || n.starts_with("pmc_")) && !ours.contains(&n.as_str())
            })
            .filter(|n| o.only.is_empty() || o.only.contains(n))
            .collect();
        v.sort();
        v.dedup();
        v
    } else {
        o.only.clone()
    };
    let mut text = String::new();
    let (mut agree, mut compared, mut partly, mut absent) = (0, 0, 0, 0);
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    let mut flag_reasons: BTreeMap<String, usize> = BTreeMap::new();
    let mut lines = Vec::new();
    let mut calls = 0;
    let mut further = 0;
    let started = std::time::Instant::now();
    for name in &names {
        let mut got = learn(probe_exe, &o.lib, &hdr, name, &mut calls);
        let mut from = String::new();
        for (lib, exe) in &o.more {
            if !matches!(&got, Err(e) if e.starts_with("not in FANUC's library")) {
                break;
            }
            got = learn(exe, lib, &hdr, name, &mut calls);
            if got.is_ok() {
                further += 1;
            }
            from = if crate::probe::elf32(lib) {
                " (checked against the 32-bit build)".into()
            } else {
                format!(" (checked against {})", lib.display())
            };
        }
        match got {
            Ok(l) => {
                let t = l.draft.text();
                lines.push(t.lines().count());
                text.push_str(&t);
                text.push('\n');
                let kind = if l.draft.flags.is_empty() {
                    "clean"
                } else {
                    "flagged"
                };
                *counts.entry(kind.into()).or_default() += 1;
                let kinds: std::collections::BTreeSet<&str> =
                    l.draft.flags.iter().map(|f| category(f)).collect();
                for k in kinds {
                    *flag_reasons.entry(k.to_string()).or_default() += 1;
                }
                if o.check {
                    let f = fwlib32::spec::find(name).unwrap();
                    compared += 1;
                    let (bad, not_compared) = compare(f, &l, &hdr);
                    let notes: String = not_compared
                        .iter()
                        .map(|n| format!("\n  not compared: {n}"))
                        .collect();
                    if !bad.is_empty() {
                        println!("DIFFER {name}{from}\n  {}{notes}", bad.join("\n  "));
                    } else if !not_compared.is_empty() {
                        // requests and checks agree; the reply not comparable
                        partly += 1;
                        println!(
                            "NOT COMPARABLE {name}{from} (requests and local checks agree){notes}"
                        );
                    } else {
                        agree += 1;
                        println!("AGREE {name}{from}");
                    }
                } else {
                    println!("{kind} {name} ({} flags)", l.draft.flags.len());
                }
            }
            // a described function FANUC's header does not declare (an
            // alias of ours): nothing to learn it from
            Err(e) if o.check && e == "not in the header" => {
                absent += 1;
                println!("ABSENT {name}: not in FANUC's header, nothing to learn it from");
            }
            Err(e) => {
                println!("FAILED {name}{from}: {e}");
                *counts.entry(format!("failed: {}", reason(&e))).or_default() += 1;
                if o.check {
                    compared += 1;
                }
            }
        }
    }
    if let Some(out) = &o.out {
        if let Some(d) = out.parent() {
            let _ = std::fs::create_dir_all(d);
        }
        std::fs::write(out, &text).expect("write the drafts");
        eprintln!("learn: drafts written to {}", out.display());
    } else if !o.check && !o.unexported {
        print!("{text}");
    }
    println!(
        "learn: {} functions, {calls} calls, {:.0?}",
        names.len(),
        started.elapsed()
    );
    for (k, n) in &counts {
        println!("  {k}: {n}");
    }
    if !flag_reasons.is_empty() {
        println!(
            "  flagged functions by what is unsettled (one function may count under several):"
        );
        for (k, n) in &flag_reasons {
            println!("    {k}: {n}");
        }
    }
    let missing = counts
        .iter()
        .filter(|(k, _)| k.contains("not in FANUC's library"))
        .map(|(_, n)| n)
        .sum::<usize>();
    println!(
        "  in FANUC's library: {} ({further} of them only in a further --lib)",
        names.len() - missing
    );
    if !lines.is_empty() {
        lines.sort();
        println!(
            "  draft entry lines: median {}, mean {:.1}, max {}",
            lines[lines.len() / 2],
            lines.iter().sum::<usize>() as f64 / lines.len() as f64,
            lines.last().unwrap()
        );
    }
    if o.check {
        println!(
            "learn --check: {agree} of {compared} described functions agree; {partly} more agree on requests and local checks, their reply not comparable (reasons above); {} differ or failed; {absent} not in FANUC's header",
            compared - agree - partly
        );
        return i32::from(agree + partly != compared);
    }
    0
}
