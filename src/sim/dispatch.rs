//! The simulator's one dispatch: every request subpacket is answered by
//! the row of its (class, command) among the areas' `ROUTES`
//! (src/sim/route.rs), gathered once into one sorted table; a command
//! without a row answers EW_FUNC, as a CNC lacking the function does. And
//! the rest of what the server asks of [`Machine`] ([`CncService`]).

use super::Machine;
use super::profile::Class;
use super::route::{Answer, Asked, Route};
use super::service::{CncError, CncService, Reply, respond};
use super::{
    axes, folder, history, macros, magazine, maintenance, memory, offset, operate, param,
    pmc_answers, position, program, sampling, screen, setting, status, tool,
};
use crate::proto::described;
use crate::proto::open::{CncClass, OpenBody};
use crate::proto::packet::{CLASS_CNC, ReqSub, RespSub};
use crate::spec::Func;
use std::sync::OnceLock;

/// Every area's rows.
const AREAS: &[&[Route]] = &[
    status::ROUTES,
    position::ROUTES,
    program::ROUTES,
    operate::ROUTES,
    param::ROUTES,
    macros::ROUTES,
    pmc_answers::ROUTES,
    offset::ROUTES,
    tool::ROUTES,
    magazine::ROUTES,
    history::ROUTES,
    memory::ROUTES,
    folder::ROUTES,
    maintenance::ROUTES,
    sampling::ROUTES,
    setting::ROUTES,
    screen::ROUTES,
    axes::ROUTES,
];

/// The CNC classes a described function's form is chosen by, in the
/// order of [`Row::layouts`].
const CLASSES: [CncClass; 3] = [
    CncClass::Series30,
    CncClass::Series16 { kind: 0 },
    CncClass::Series16 { kind: 2 },
];

/// The index in [`CLASSES`] of a CNC's class.
fn class_index(class: CncClass) -> usize {
    match class {
        CncClass::Series30 => 0,
        CncClass::Series16 { kind: 2 } => 2,
        CncClass::Series16 { .. } => 1,
    }
}

/// A row of the table: the area's route and, for a described command,
/// the function whose reply layout its answer fills on each class (where
/// functions share a command, the one with the longest reply).
#[derive(Clone, Copy)]
pub struct Row {
    pub route: Route,
    pub layouts: [Option<&'static Func>; 3],
}

/// Why the rows do not make a table.
#[derive(Debug, PartialEq, Eq)]
pub enum Conflict {
    /// Two rows claim this (class, command).
    Twice(u16, u16),
    /// A described row's command is no described function's, on any class.
    NoLayout(u16, u16),
}

/// The rows sorted by (class, command), each described command with its
/// layouts, checked: no (class, command) twice, no described row
/// without a function.
pub fn table() -> Result<Vec<Row>, Conflict> {
    table_of(AREAS)
}

fn table_of(areas: &[&[Route]]) -> Result<Vec<Row>, Conflict> {
    let mut all: Vec<Route> = areas.iter().flat_map(|a| a.iter().copied()).collect();
    all.sort_by_key(Route::key);
    if let Some(w) = all.windows(2).find(|w| w[0].key() == w[1].key()) {
        let (class, cmd) = w[0].key();
        return Err(Conflict::Twice(class, cmd));
    }
    all.into_iter()
        .map(|route| {
            let (class, cmd) = route.key();
            let sub = ReqSub {
                class,
                cmd,
                ..ReqSub::default()
            };
            let layouts = CLASSES.map(|c| match route.answer {
                Answer::Values(_) => described::for_request(&sub, c),
                Answer::Bytes(_) => None,
            });
            match route.answer {
                Answer::Values(_) if layouts.iter().all(Option::is_none) => {
                    Err(Conflict::NoLayout(class, cmd))
                }
                _ => Ok(Row { route, layouts }),
            }
        })
        .collect()
}

/// The table, built and checked once: a conflict panics when it is built,
/// as a simulator or fleet starts (or at the first request).
pub fn rows() -> &'static [Row] {
    static ROWS: OnceLock<Vec<Row>> = OnceLock::new();
    ROWS.get_or_init(|| match table() {
        Ok(t) => t,
        Err(c) => panic!("the simulator's routes conflict: {c:?}"),
    })
}

/// The row of a (class, command), if any.
pub fn find(class: u16, cmd: u16) -> Option<&'static Row> {
    let t = rows();
    t.binary_search_by_key(&(class, cmd), |r| r.route.key())
        .ok()
        .map(|i| &t[i])
}

/// Whether a described function's record exchange ([`crate::spec::Each`])
/// sends this subpacket's command on a Series 15 (`class`) that no form of
/// that class sends, the 16i class's forms answering it.
fn each_in_16i_form(sub: &ReqSub, class: CncClass) -> bool {
    class == (CncClass::Series16 { kind: 2 })
        && crate::spec::FUNCS
            .iter()
            .any(|f| (f.each.iter()).any(|e| e.classes.matches(true, true) && e.cmd == sub.cmd))
}

impl Machine {
    /// The CNC's class, as its open body gives it.
    fn cnc_class(&self) -> CncClass {
        let c = &self.profile.cnc;
        match c.class {
            Class::Series30 => CncClass::Series30,
            Class::Series16 => CncClass::Series16 { kind: c.kind },
        }
    }

    /// The answer's bytes: EW_PATH for a CNC subpacket's path the machine
    /// lacks, else its row's; EW_FUNC without one (or, for a described
    /// command, without a function on this class).
    fn answer_bytes(&mut self, sub: &ReqSub) -> Reply<Vec<u8>> {
        let p = sub.path;
        if sub.class == CLASS_CNC && (p == 0 || usize::from(p) > self.profile.paths.len()) {
            return Err(CncError::PATH);
        }
        let row = find(sub.class, sub.cmd).ok_or(CncError::FUNC)?;
        match row.route.answer {
            Answer::Bytes(f) => f(self, sub),
            Answer::Values(f) => {
                let mut class = self.cnc_class();
                if row.layouts[class_index(class)].is_none() && each_in_16i_form(sub, class) {
                    // A Series 15 asked in the 16i form, by a record's
                    // exchange alone (cnc_sdtsetchnl's parameter read):
                    // answered as the 16i class answers it.
                    class = CncClass::Series16 { kind: 0 };
                }
                row.layouts[class_index(class)].ok_or(CncError::FUNC)?;
                let func = described::for_request(sub, class).ok_or(CncError::FUNC)?;
                let args = described::args_of(func, class, sub);
                let payload = described::payload_in(func, class, &sub.payload);
                let asked = Asked {
                    f: func,
                    path: p,
                    args: &args,
                    words: sub.args,
                    payload: &payload,
                    bytes: &sub.payload,
                };
                let v = f(self, &asked)?;
                described::encode_in(func, class, &v).map_err(|_| CncError::FUNC)
            }
        }
    }
}

impl CncService for Machine {
    fn open_body(&self) -> OpenBody {
        self.open_body_of()
    }

    fn max_sessions(&self) -> usize {
        self.profile.cnc.max_sessions
    }

    fn advance(&mut self, now: std::time::Instant) {
        self.advance_to(now);
    }

    fn answer(&mut self, sub: &ReqSub) -> RespSub {
        let r = self.answer_bytes(sub);
        respond(sub, r)
    }

    fn upload(&mut self, req: &crate::proto::upload::StartReq) -> Reply<Vec<u8>> {
        self.upload_text(req)
    }

    fn receive(
        &mut self,
        how: crate::proto::download::Outgoing,
        req: &crate::proto::upload::StartReq,
        text: &[u8],
        done: bool,
    ) -> Reply<()> {
        match how {
            crate::proto::download::DOWNLOAD if done => self.download(req, text),
            crate::proto::download::DOWNLOAD => Ok(()),
            _ => self.dnc(req.path, text, done),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proto::packet::{CLASS_PMC, decode_request};
    use std::collections::BTreeSet;
    use std::path::Path;

    #[test]
    fn no_two_rows_claim_a_command_and_every_described_row_has_a_layout() {
        assert_eq!(table().err(), None);
        // A conflict is found: a command twice, a described row whose
        // command no described function sends.
        let twice = [status::ROUTES, &status::ROUTES[..1]];
        let (class, cmd) = status::ROUTES[0].key();
        assert_eq!(table_of(&twice).err(), Some(Conflict::Twice(class, cmd)));
        let stray = [Route::table(crate::proto::cmd::SYSINFO, |_, _| {
            Ok(Vec::new())
        })];
        assert_eq!(
            table_of(&[&stray]).err(),
            Some(Conflict::NoLayout(CLASS_CNC, crate::proto::cmd::SYSINFO))
        );
        // The classes' order is the index's.
        for (i, c) in CLASSES.iter().enumerate() {
            assert_eq!(class_index(*c), i);
        }
        // Every described row has the layout of a function sending its
        // command, on each class the function has a form for.
        for r in rows() {
            for (c, f) in CLASSES.iter().zip(r.layouts) {
                if let Some(f) = f {
                    let form = described::form(f, *c).expect("a form on this class");
                    assert_eq!((form.class, form.cmd), r.route.key(), "{}", f.name);
                }
            }
        }
    }

    /// Commands FANUC's library sends (in the recorded cases) that the
    /// simulator does not answer: it answers EW_FUNC, as a CNC lacking the
    /// function does.
    const NOT_ANSWERED: &[((u16, u16), &str)] = &[
        (
            (CLASS_CNC, crate::proto::cmd::RDPMACRO2),
            "FANUC's cnc_rdpmacror's 0x012c (16i class from #100000, fuzz cases): its answer's form is not known; error 1 makes FANUC's library read with 0x002d",
        ),
        (
            (CLASS_CNC, crate::proto::cmd::WRPMACRO2),
            "FANUC's cnc_wrpmacror's 0x012d (16i class from #100000, a fuzz case): its payload's and answer's forms are not known; error 1 makes FANUC's library write with 0x002e",
        ),
        (
            (CLASS_CNC, crate::proto::param::RDPARAINFO15),
            "Series 15 parameter information (cnc_rdparainfo): its answer's form is not known",
        ),
        (
            (CLASS_CNC, crate::proto::param::RDDIAGINFO15),
            "Series 15 diagnosis information (cnc_rddiaginfo): its answer's form is not known",
        ),
        (
            (CLASS_CNC, crate::proto::tool::TLCTL),
            "punch press tool control data (cnc_rdtlctldata): the profile has none",
        ),
    ];

    /// The (class, command) of every data request subpacket of the
    /// recorded cases (tests/vectors: what FANUC's library sends).
    fn recorded_commands() -> BTreeSet<(u16, u16)> {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/vectors");
        let mut out = BTreeSet::new();
        let mut files = 0;
        for e in std::fs::read_dir(&dir).expect("tests/vectors") {
            let text = std::fs::read_to_string(e.expect("entry").path()).expect("a case file");
            let v: serde_json::Value = serde_json::from_str(&text).expect("json");
            files += 1;
            let mut stack = vec![&v];
            while let Some(x) = stack.pop() {
                match x {
                    serde_json::Value::Array(a) => stack.extend(a),
                    serde_json::Value::Object(o) => {
                        let is =
                            |k: &str, want: &str| o.get(k).and_then(|t| t.as_str()) == Some(want);
                        if is("dir", "req") && is("type", "2101") {
                            let hex = o["hex"].as_str().expect("hex");
                            let bytes: Vec<u8> = (0..hex.len())
                                .step_by(2)
                                .map(|i| u8::from_str_radix(&hex[i..i + 2], 16).expect("hex"))
                                .collect();
                            // (A few cases record a frame cut short.)
                            if let Ok(subs) = decode_request(&bytes[10..]) {
                                out.extend(subs.iter().map(|s| (s.class, s.cmd)));
                            }
                        }
                        stack.extend(o.values());
                    }
                    _ => {}
                }
            }
        }
        assert!(
            files > 200,
            "the recorded cases are missing ({files} files)"
        );
        out
    }

    #[test]
    fn every_command_the_library_sends_has_a_row_or_is_listed() {
        let recorded = recorded_commands();
        let sent: BTreeSet<(u16, u16)> = recorded
            .iter()
            .copied()
            .chain(crate::proto::cmd::COMMANDS.iter().map(|c| (c.class, c.cmd)))
            .chain(
                crate::spec::FUNCS
                    .iter()
                    .flat_map(|f| f.forms.iter().map(|x| (x.class, x.cmd))),
            )
            .collect();
        let listed: BTreeSet<(u16, u16)> = NOT_ANSWERED.iter().map(|(k, _)| *k).collect();
        let missing: Vec<String> = sent
            .iter()
            .filter(|k| find(k.0, k.1).is_none() && !listed.contains(k))
            .map(|(c, k)| format!("({c}, {k:#06x})"))
            .collect();
        assert!(
            missing.is_empty(),
            "no row and not listed: {}",
            missing.join(" ")
        );
        // A listed command is indeed not answered.
        for ((c, k), why) in NOT_ANSWERED {
            assert!(find(*c, *k).is_none(), "({c}, {k:#06x}) has a row: {why}");
        }
        assert!(recorded.contains(&(CLASS_PMC, crate::proto::pmc::RDPMCRNG)));
    }

    /// Described functions whose command is answered by hand (a layout of
    /// src/proto), not through their own layout: the command's whole
    /// answer is more than one function's layout says.
    const HAND_ANSWERED: &[((u16, u16), &str)] = &[
        (
            (CLASS_CNC, crate::proto::cmd::RDCTRLSIG),
            "one signal word per spindle, as a CNC answers; cnc_rdctrldi's layout reads the first",
        ),
        (
            (CLASS_CNC, crate::proto::position::ACTF),
            "cnc_actf reads the first word of the value record cnc_rddynamic reads whole",
        ),
        (
            (CLASS_CNC, crate::proto::position::ACTS),
            "cnc_acts reads the first word of the value record cnc_rddynamic reads whole",
        ),
        (
            (CLASS_CNC, crate::proto::position::RDAXISNAME),
            "[-1] answers the names per position kind, a form cnc_rdaxisname's layout lacks",
        ),
        (
            (CLASS_CNC, crate::proto::position::COUNT),
            "the counts of the hand-written position functions; cnc_rdnspdl reads the spindles'",
        ),
        (
            (CLASS_CNC, crate::proto::position::SERVO_LOAD),
            "one command, three functions: the record's form follows the code word",
        ),
        (
            (CLASS_CNC, crate::proto::tool::TLUSEGRP),
            "the groups in use and their optional groups (cnc_rdtlusegrp); cnc_rdusegrpid reads the first three",
        ),
        (
            (CLASS_CNC, crate::proto::tool::TLTOOLS),
            "the tools of a group (cnc_rdtoolrng); cnc_toolnum reads one of them",
        ),
        (
            (CLASS_CNC, crate::proto::maintenance::RDPM_CNCITEM),
            "names as 62-byte text fields",
        ),
        (
            (CLASS_CNC, crate::proto::maintenance::RDPM_MCNITEM),
            "names as 62-byte text fields",
        ),
        (
            (CLASS_CNC, crate::proto::maintenance::WRPM_MCNITEM),
            "names as 62-byte text fields",
        ),
        (
            (CLASS_CNC, crate::proto::cmd::HDL3D_AXES),
            "cnc_rd3dtooltip's columns: the axes (0x0110) and their tool tip (0x0111) answer in subpackets of their own, which no one layout encodes",
        ),
        (
            (CLASS_CNC, crate::proto::maintenance::RDPM_ITEM),
            "the item records of src/proto/maintenance.rs (PmItem)",
        ),
        (
            (CLASS_CNC, crate::proto::maintenance::WRPM_ITEM),
            "the item records of src/proto/maintenance.rs (PmItem)",
        ),
    ];

    #[test]
    fn every_described_function_is_answered_through_its_layout_or_listed() {
        let hand: BTreeSet<(u16, u16)> = HAND_ANSWERED.iter().map(|(k, _)| *k).collect();
        let mut wrong = Vec::new();
        for f in crate::spec::FUNCS {
            for form in f.forms {
                let key = (form.class, form.cmd);
                let row = find(key.0, key.1);
                let by_layout = row.is_some_and(|r| matches!(r.route.answer, Answer::Values(_)));
                if !by_layout && !hand.contains(&key) {
                    wrong.push(format!("{} ({:#06x})", f.name, form.cmd));
                }
            }
        }
        assert!(
            wrong.is_empty(),
            "not through their layout, not listed: {}",
            wrong.join(", ")
        );
        // A listed command is answered by hand indeed.
        for ((c, k), why) in HAND_ANSWERED {
            let row = find(*c, *k).expect("a row");
            assert!(
                matches!(row.route.answer, Answer::Bytes(_)),
                "{k:#06x}: {why}"
            );
        }
    }

    #[test]
    fn every_described_answer_fills_its_layout() {
        // A wrong count of integers would answer EW_FUNC, which reads as
        // "not supported": each described row's answer, where it has one,
        // encodes through its layout, on each class.
        let mut answered = 0;
        for (i, class) in CLASSES.iter().enumerate() {
            let mut p = crate::sim::Profile::default();
            (p.cnc.class, p.cnc.kind) = match class {
                CncClass::Series30 => (Class::Series30, 0),
                CncClass::Series16 { kind } => (Class::Series16, *kind),
            };
            let mut m = Machine::new(p);
            for r in rows() {
                let (Answer::Values(f), Some(func)) = (r.route.answer, r.layouts[i]) else {
                    continue;
                };
                for args in [[0; 5], [1; 5], [2, 1, 1, 1, 1]] {
                    let n = func.numbers().count();
                    // The words the function's form sends for these arguments.
                    let mut words = [0; 5];
                    for (w, f) in words
                        .iter_mut()
                        .zip(func.form(i > 0, i == 2).map_or(&[][..], |f| f.words))
                    {
                        *w = match *f {
                            crate::spec::Word::Const(c) => c,
                            crate::spec::Word::Asked | crate::spec::Word::Last(_) => 0,
                            crate::spec::Word::Plus(a, c) => c + args[usize::from(a).min(4)],
                            crate::spec::Word::Upto(_, e, _, _) => {
                                args.get(usize::from(e)).copied().unwrap_or(0)
                            }
                            crate::spec::Word::Nonzero(a, v) => {
                                let set = args.get(usize::from(a)).is_some_and(|x| *x != 0);
                                if set { v } else { 0 }
                            }
                            crate::spec::Word::Arg(_) | crate::spec::Word::Input(..) => func
                                .word_arg(f)
                                .and_then(|a| args.get(a).copied())
                                .unwrap_or(0),
                        };
                    }
                    let q = Asked {
                        f: func,
                        path: 1,
                        args: &args[..n.min(5)],
                        words,
                        payload: &[],
                        bytes: &[],
                    };
                    if let Ok(v) = f(&mut m, &q) {
                        answered += 1;
                        let e = described::encode_in(func, *class, &v);
                        assert!(e.is_ok(), "{} on {class:?}: {} values", func.name, v.len());
                    }
                }
            }
        }
        assert!(answered > 100, "{answered} answers");
    }

    /// The string literals of Rust source (comments and char literals
    /// skipped; raw strings included).
    fn literals(src: &str) -> Vec<String> {
        let b = src.as_bytes();
        let (mut out, mut i) = (Vec::new(), 0);
        while i < b.len() {
            let rest = &src[i..];
            if rest.starts_with("//") {
                i += rest.find('\n').unwrap_or(rest.len());
            } else if rest.starts_with("/*") {
                i += rest.find("*/").map_or(rest.len(), |e| e + 2);
            } else if let Some(r) = rest.strip_prefix("'\\") {
                i += 2 + r.find('\'').map_or(r.len(), |e| e + 1);
            } else if rest.len() > 2 && rest.as_bytes()[0] == b'\'' && rest.as_bytes()[2] == b'\'' {
                i += 3;
            } else if rest.starts_with("r\"") || rest.starts_with("r#\"") {
                let hashes = usize::from(rest.as_bytes()[1] == b'#');
                let open = 2 + hashes;
                let close = format!("\"{}", "#".repeat(hashes));
                let end = rest[open..].find(&close).map_or(rest.len(), |e| open + e);
                out.push(rest[open..end].to_string());
                i += end + close.len();
            } else if b[i] == b'"' {
                let mut j = i + 1;
                while j < b.len() && b[j] != b'"' {
                    j += if b[j] == b'\\' { 2 } else { 1 };
                }
                out.push(src[i + 1..j.min(b.len())].to_string());
                i = j + 1;
            } else {
                i += rest.chars().next().map_or(1, char::len_utf8);
            }
        }
        out
    }

    #[test]
    fn no_answer_is_chosen_by_a_function_name() {
        let names: BTreeSet<&str> = crate::spec::FUNCS
            .iter()
            .map(|f| f.name)
            .chain(
                crate::proto::cmd::COMMANDS
                    .iter()
                    .flat_map(|c| c.senders.iter().copied()),
            )
            .collect();
        assert!(names.contains("cnc_search") && names.contains("cnc_rdparam"));
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/sim");
        let mut dirs = vec![root.clone()];
        let (mut files, mut found) = (0, Vec::new());
        while let Some(d) = dirs.pop() {
            for e in std::fs::read_dir(&d).expect("src/sim") {
                let p = e.expect("entry").path();
                if p.is_dir() {
                    dirs.push(p);
                    continue;
                }
                let rel = p.strip_prefix(&root).expect("under src/sim");
                let rel = rel.to_string_lossy().replace('\\', "/");
                if !rel.ends_with(".rs") {
                    continue;
                }
                files += 1;
                // The code, not its unit tests (which may name functions).
                let src = std::fs::read_to_string(&p).expect("source");
                let code = src.split("\n#[cfg(test)]\nmod tests").next().unwrap_or("");
                for l in literals(code) {
                    if names.contains(l.as_str()) {
                        found.push(format!("{rel}: \"{l}\""));
                    }
                }
            }
        }
        assert!(files > 30, "src/sim has {files} files");
        assert!(
            found.is_empty(),
            "function names in src/sim: {}",
            found.join(", ")
        );
        // The scan finds a name where there is one, and not in a comment.
        let sample = "// \"cnc_search\"\nlet c = '\"'; match f.name { \"cnc_search\" => 1 }";
        assert_eq!(literals(sample), ["cnc_search"]);
    }
}
