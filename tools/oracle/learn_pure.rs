//! The learner's pure logic (tools/oracle/learn.rs runs it on FANUC's
//! library): a C header's types and prototypes, position-coded bytes and
//! where they land, request diffs, the local checks a sweep shows, a draft
//! table entry, and the comparison of a draft with a committed entry of
//! src/spec/table. Nothing here runs a library: tests/recorded/learn.rs feeds it
//! synthetic data.

use fwlib32::spec::{self, Func, Int};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::rc::Rc;

// ---------------------------------------------------------------- C types

/// A C type as FANUC's x86-64 library lays it out: `long` is 4 bytes (the
/// library reads and writes 4-byte `long` fields), pointers 8, natural
/// alignment.
#[derive(Debug, Clone, PartialEq)]
pub enum Ty {
    Int { size: usize, signed: bool },
    Float(usize),
    Void,
    Ptr(Box<Ty>),
    Array(Box<Ty>, usize),
    Struct(Rc<Layout>),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    pub union: bool,
    pub size: usize,
    pub align: usize,
    /// (name, offset, type)
    pub members: Vec<(String, usize, Ty)>,
}

impl Ty {
    pub fn size(&self) -> usize {
        match self {
            Ty::Int { size, .. } | Ty::Float(size) => *size,
            Ty::Void => 1,
            Ty::Ptr(_) => 8,
            Ty::Array(t, n) => t.size() * n,
            Ty::Struct(l) => l.size,
        }
    }
    pub fn align(&self) -> usize {
        match self {
            Ty::Int { size, .. } | Ty::Float(size) => *size,
            Ty::Void => 1,
            Ty::Ptr(_) => 8,
            Ty::Array(t, _) => t.align(),
            Ty::Struct(l) => l.align,
        }
    }
    /// The table's integer for a C integer of this type.
    pub fn int(&self) -> Option<Int> {
        match self {
            Ty::Int { size: 1, signed } => Some(if *signed { Int::I8 } else { Int::U8 }),
            Ty::Int { size: 2, signed } => Some(if *signed { Int::I16 } else { Int::U16 }),
            Ty::Int { size: 4, signed } => Some(if *signed { Int::I32 } else { Int::U32 }),
            _ => None,
        }
    }
}

/// A scalar inside a type: its member path (`a.b[2]`), offset, type.
#[derive(Debug, Clone, PartialEq)]
pub struct Leaf {
    pub path: String,
    pub off: usize,
    pub ty: Ty,
}

/// Every scalar of `ty` from `off` on, arrays element by element.
pub fn leaves(ty: &Ty, off: usize, path: &str, out: &mut Vec<Leaf>) {
    match ty {
        Ty::Struct(l) => {
            for (name, o, t) in &l.members {
                let p = if path.is_empty() {
                    name.clone()
                } else {
                    format!("{path}.{name}")
                };
                leaves(t, off + o, &p, out);
            }
        }
        Ty::Array(t, n) => {
            for i in 0..*n {
                leaves(t, off + i * t.size(), &format!("{path}[{i}]"), out);
            }
        }
        t => out.push(Leaf {
            path: path.to_string(),
            off,
            ty: t.clone(),
        }),
    }
}

/// The member `path` (`a.b`, no indices) of `ty`: offset and type.
pub fn member(ty: &Ty, path: &str) -> Option<(usize, Ty)> {
    if path.is_empty() {
        return Some((0, ty.clone()));
    }
    let (head, rest) = path.split_once('.').unwrap_or((path, ""));
    let Ty::Struct(l) = ty else { return None };
    let (_, o, t) = l.members.iter().find(|m| m.0 == head)?;
    let (o2, t2) = member(t, rest)?;
    Some((o + o2, t2))
}

/// A prototype of the header.
#[derive(Debug, Clone, PartialEq)]
pub struct Proto {
    pub name: String,
    pub ret: Ty,
    /// (type, its spelling in the header)
    pub params: Vec<(Ty, String)>,
}

#[derive(Debug, Default)]
pub struct Header {
    pub types: BTreeMap<String, Ty>,
    pub protos: Vec<Proto>,
    /// What could not be parsed (a declaration's first words).
    pub skipped: Vec<String>,
}

fn tokens(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_whitespace() {
            i += 1;
        } else if c == b'#' {
            // a line marker or pragma left by the preprocessor
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if c.is_ascii_alphanumeric() || c == b'_' {
            let s = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            out.push(text[s..i].to_string());
        } else if c == b'"' {
            let s = i;
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += 1;
            }
            i += 1;
            out.push(text[s..i.min(b.len())].to_string());
        } else {
            out.push((c as char).to_string());
            i += 1;
        }
    }
    out
}

struct P<'a> {
    t: &'a [String],
    i: usize,
    h: &'a mut Header,
    anon: usize,
}

fn number(s: &str) -> Option<i64> {
    let s = s.trim_end_matches(['u', 'U', 'l', 'L']);
    match s.strip_prefix("0x").or_else(|| s.strip_prefix("0X")) {
        Some(h) => i64::from_str_radix(h, 16).ok(),
        None => s.parse().ok(),
    }
}

impl P<'_> {
    fn peek(&self) -> &str {
        self.t.get(self.i).map(String::as_str).unwrap_or("")
    }
    fn next(&mut self) -> String {
        let s = self.peek().to_string();
        self.i += 1;
        s
    }
    fn eat(&mut self, s: &str) -> bool {
        if self.peek() == s {
            self.i += 1;
            true
        } else {
            false
        }
    }
    fn done(&self) -> bool {
        self.i >= self.t.len()
    }
    /// A constant expression up to `]`: + - * / and parentheses.
    fn expr(&mut self) -> Option<i64> {
        let mut v = self.term()?;
        loop {
            if self.eat("+") {
                v += self.term()?;
            } else if self.eat("-") {
                v -= self.term()?;
            } else {
                return Some(v);
            }
        }
    }
    fn term(&mut self) -> Option<i64> {
        let mut v = self.atom()?;
        loop {
            if self.eat("*") {
                v *= self.atom()?;
            } else if self.eat("/") {
                v /= self.atom()?.max(1);
            } else {
                return Some(v);
            }
        }
    }
    fn atom(&mut self) -> Option<i64> {
        if self.eat("(") {
            let v = self.expr();
            self.eat(")");
            v
        } else if self.eat("-") {
            Some(-self.atom()?)
        } else {
            number(&self.next())
        }
    }
    /// A type specifier (base type, struct or union with or without body,
    /// typedef name); None when the words are not one.
    fn spec(&mut self) -> Option<Ty> {
        let (mut unsigned, mut short, mut char_, mut any) = (false, false, false, false);
        loop {
            match self.peek() {
                "const" | "volatile" | "extern" | "static" | "register" | "WINAPI" => self.i += 1,
                "unsigned" => (unsigned, any, self.i) = (true, true, self.i + 1),
                "signed" => (any, self.i) = (true, self.i + 1),
                "short" => (short, any, self.i) = (true, true, self.i + 1),
                "long" | "int" => (any, self.i) = (true, self.i + 1),
                "char" => (char_, any, self.i) = (true, true, self.i + 1),
                "float" if !any => {
                    self.i += 1;
                    return Some(Ty::Float(4));
                }
                "double" if !any => {
                    self.i += 1;
                    return Some(Ty::Float(8));
                }
                "void" if !any => {
                    self.i += 1;
                    return Some(Ty::Void);
                }
                "struct" | "union" if !any => return self.record(),
                w if !any && w.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') => {
                    let t = self.h.types.get(w)?.clone();
                    self.i += 1;
                    return Some(t);
                }
                _ => break,
            }
        }
        any.then(|| {
            let size = if char_ {
                1
            } else if short {
                2
            } else {
                4 // int, long (4 bytes in FANUC's x86-64 library)
            };
            // plain char: signed on x86-64
            Ty::Int {
                size,
                signed: !unsigned,
            }
        })
    }
    fn record(&mut self) -> Option<Ty> {
        let union = self.next() == "union";
        let mut tag = None;
        if self.peek() != "{" {
            tag = Some(format!(
                "{} {}",
                if union { "union" } else { "struct" },
                self.next()
            ));
        }
        if !self.eat("{") {
            return tag.and_then(|t| self.h.types.get(&t).cloned());
        }
        let mut members = Vec::new();
        while !self.eat("}") {
            if self.done() {
                return None;
            }
            let base = self.spec()?;
            loop {
                let (name, ty) = self.declarator(base.clone())?;
                members.push((name, ty));
                if self.eat(",") {
                    continue;
                }
                self.eat(";");
                break;
            }
        }
        let ty = Ty::Struct(Rc::new(layout(union, members)));
        if let Some(t) = tag {
            self.h.types.insert(t, ty.clone());
        } else {
            self.anon += 1;
        }
        Some(ty)
    }
    /// `*`s, a name (or none) and array dimensions.
    fn declarator(&mut self, base: Ty) -> Option<(String, Ty)> {
        let mut ty = base;
        loop {
            if self.eat("*") {
                ty = Ty::Ptr(Box::new(ty));
            } else if self.eat("const") {
            } else {
                break;
            }
        }
        // `(*name)[N]`: a pointer to arrays
        let mut ptr_to = false;
        if self.peek() == "(" && self.t.get(self.i + 1).is_some_and(|t| t == "*") {
            self.i += 2;
            ptr_to = true;
        }
        let name = if self
            .peek()
            .starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        {
            self.next()
        } else {
            String::new()
        };
        if ptr_to {
            self.eat(")");
        }
        let mut dims = Vec::new();
        while self.eat("[") {
            if self.eat("]") {
                dims.push(0);
                continue;
            }
            dims.push(self.expr()? as usize);
            self.eat("]");
        }
        for d in dims.into_iter().rev() {
            ty = if d == 0 {
                Ty::Ptr(Box::new(ty))
            } else {
                Ty::Array(Box::new(ty), d)
            };
        }
        if ptr_to {
            ty = Ty::Ptr(Box::new(ty));
        }
        Some((name, ty))
    }
    fn skip_to_semicolon(&mut self) {
        let mut depth = 0i32;
        while !self.done() {
            match self.next().as_str() {
                "{" | "(" => depth += 1,
                "}" | ")" => depth -= 1,
                ";" if depth <= 0 => return,
                _ => {}
            }
        }
    }
    fn top(&mut self) {
        let start = self.i;
        let typedef = self.eat("typedef");
        let Some(base) = self.spec() else {
            self.i = start;
            let w = self.t[start..(start + 4).min(self.t.len())].join(" ");
            self.h.skipped.push(w);
            self.skip_to_semicolon();
            return;
        };
        if self.eat(";") {
            return;
        }
        loop {
            let Some((name, ty)) = self.declarator(base.clone()) else {
                self.skip_to_semicolon();
                return;
            };
            if !typedef && self.eat("(") {
                let mut params = Vec::new();
                while !self.eat(")") {
                    if self.done() {
                        return;
                    }
                    let s = self.i;
                    let Some(pb) = self.spec() else {
                        self.skip_to_semicolon();
                        return;
                    };
                    let Some((_, pt)) = self.declarator(pb) else {
                        self.skip_to_semicolon();
                        return;
                    };
                    let text = self.t[s..self.i].join(" ");
                    if pt != Ty::Void {
                        params.push((pt, text));
                    }
                    self.eat(",");
                }
                self.h.protos.push(Proto {
                    name,
                    ret: ty,
                    params,
                });
            } else if typedef {
                self.h.types.insert(name, ty);
            }
            if self.eat(",") {
                continue;
            }
            self.skip_to_semicolon();
            return;
        }
    }
}

fn layout(union: bool, members: Vec<(String, Ty)>) -> Layout {
    let (mut off, mut size, mut align) = (0usize, 0usize, 1usize);
    let mut out = Vec::new();
    for (name, ty) in members {
        let a = ty.align().max(1);
        align = align.max(a);
        if union {
            out.push((name, 0, ty.clone()));
            size = size.max(ty.size());
        } else {
            off = off.div_ceil(a) * a;
            out.push((name, off, ty.clone()));
            off += ty.size();
            size = off;
        }
    }
    Layout {
        union,
        size: size.div_ceil(align) * align,
        align,
        members: out,
    }
}

impl Header {
    /// Parses preprocessed C text (`cc -E -P` of the header).
    pub fn parse(text: &str) -> Header {
        let t = tokens(text);
        let mut h = Header::default();
        let mut p = P {
            t: &t,
            i: 0,
            h: &mut h,
            anon: 0,
        };
        while !p.done() {
            if p.eat(";") || p.eat("}") {
                continue;
            }
            p.top();
        }
        h
    }
    pub fn proto(&self, name: &str) -> Option<&Proto> {
        self.protos.iter().find(|p| p.name == name)
    }
}

// ------------------------------------------------------ position coding

/// Byte `i` of a position-coded buffer in pass 0 (`i % 251 + 1`), pass 1
/// (`i / 251 + 1`) or pass 2 (`(i + 7) % 241 + 1`, a check: a constant byte
/// reads as a position in the first two passes alone): never 0, and the
/// passes give back `i`.
pub fn code(i: usize, pass: usize) -> u8 {
    match pass {
        0 => (i % 251 + 1) as u8,
        1 => (i / 251 % 251 + 1) as u8,
        _ => ((i + 7) % 241 + 1) as u8,
    }
}

/// The passes of position coding.
pub const PASSES: usize = 3;

pub fn coded(len: usize, pass: usize) -> Vec<u8> {
    (0..len).map(|i| code(i, pass)).collect()
}

/// The position the passes' bytes stand for.
pub fn decode(v: [u8; PASSES]) -> Option<usize> {
    let [v0, v1, v2] = v;
    if !(1..=251).contains(&v0) || !(1..=251).contains(&v1) {
        return None;
    }
    let p = (v1 as usize - 1) * 251 + (v0 as usize - 1);
    (code(p, 2) == v2).then_some(p)
}

/// Where one destination byte comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Src {
    /// Left as the caller's fill.
    Kept,
    /// Source byte `p`.
    At(usize),
    /// The sign of source byte `p` (0x00 or 0xFF).
    Sign(usize),
    /// Always this value.
    Const(u8),
    /// Something else (a computed value).
    Computed,
}

/// One destination buffer as six calls left it: `obs[pass][fill]`, the
/// three passes of the position code, fills 0xCC and 0x33 (a buffer
/// shorter than another reads as its fill past its end).
pub fn map_bytes(obs: &[[Vec<u8>; 2]; PASSES]) -> Vec<Src> {
    let len = obs.iter().flatten().map(Vec::len).max().unwrap_or(0);
    let at = |p: usize, f: usize, i: usize| -> u8 {
        obs[p][f]
            .get(i)
            .copied()
            .unwrap_or(if f == 0 { 0xCC } else { 0x33 })
    };
    let mut out = Vec::with_capacity(len);
    for i in 0..len {
        let kept = (0..PASSES).all(|p| at(p, 0, i) == 0xCC && at(p, 1, i) == 0x33);
        if kept {
            out.push(Src::Kept);
            continue;
        }
        // a byte written in one fill but not the other equals that fill
        let val = |p: usize| {
            let (a, b) = (at(p, 0, i), at(p, 1, i));
            if a == b {
                Some(a)
            } else if a == 0xCC && b != 0x33 {
                Some(b)
            } else if b == 0x33 && a != 0xCC {
                Some(a)
            } else {
                None
            }
        };
        out.push(match (val(0), val(1), val(2)) {
            (Some(a), Some(b), Some(c)) => match decode([a, b, c]) {
                Some(p) => Src::At(p),
                None if a == b && b == c => Src::Const(a),
                None => Src::Computed,
            },
            _ => Src::Computed,
        });
    }
    // sign bytes: a constant 0/0xff or varying byte above a decoded byte
    for i in 0..out.len() {
        if matches!(out[i], Src::Computed | Src::Const(0) | Src::Const(0xff)) {
            let q = (1..=3).filter(|k| *k <= i).find_map(|k| match out[i - k] {
                Src::At(p) => Some(p),
                _ => None,
            });
            if let Some(q) = q {
                let sign = |p: usize| if code(q, p) >= 0x80 { 0xffu8 } else { 0 };
                let same = (0..PASSES).all(|p| at(p, 0, i) == sign(p) || at(p, 1, i) == sign(p));
                if same && (0..PASSES).any(|p| code(q, p) >= 0x80) {
                    out[i] = Src::Sign(q);
                }
            }
        }
    }
    out
}

// ------------------------------------------------------------- requests

/// One request subpacket: class, path, command, five words, payload.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Sub {
    pub class: u16,
    pub path: u16,
    pub cmd: u16,
    pub words: [i32; 5],
    pub payload: Vec<u8>,
}

/// The subpackets of a data request frame (type 0x2101), or None.
pub fn subs(frame: &[u8]) -> Option<Vec<Sub>> {
    if frame.len() < 12 || frame[6..8] != [0x21, 0x01] {
        return None;
    }
    let body = &frame[10..];
    let n = u16::from_be_bytes([body[0], body[1]]) as usize;
    let mut at = 2;
    let mut out = Vec::new();
    for _ in 0..n {
        let h = body.get(at..at + 28)?;
        let len = u16::from_be_bytes([h[0], h[1]]) as usize;
        let be = |o: usize| u16::from_be_bytes([h[o], h[o + 1]]);
        let mut words = [0i32; 5];
        for (k, w) in words.iter_mut().enumerate() {
            *w = i32::from_be_bytes(h[8 + 4 * k..12 + 4 * k].try_into().unwrap());
        }
        let payload = body.get(at + 28..at + len.max(28))?.to_vec();
        out.push(Sub {
            class: be(2),
            path: be(4),
            cmd: be(6),
            words,
            payload,
        });
        at += len.max(28);
    }
    Some(out)
}

/// What a request word is, learnt from calls that vary one argument each.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum WordSrc {
    /// Number argument `i` (as the C parameter's type converts it).
    Arg(usize),
    Const(i32),
    /// The payload's length.
    Len,
    /// Changes, not as any argument: the values seen.
    Computed(Vec<i32>),
    /// A member of the write's input (committed entries' `Word::Input`;
    /// learnt when an input's position-coded member lands in a word the
    /// plain call saw constant).
    Input(String),
    /// `.1` when number argument `.0` is not 0, else 0 (committed entries'
    /// `Word::Nonzero`: a flag sent for a nonzero argument).
    Nonzero(usize, i32),
}

/// One run for [`learn_words`]: the number arguments as passed, the first
/// request subpacket's words and the payload length.
#[derive(Debug, Clone)]
pub struct WordRun {
    pub args: Vec<i64>,
    pub words: [i32; 5],
    pub payload_len: usize,
}

/// Each of the five words' source, from runs that vary one argument at a
/// time (`runs[0]` the plain call). `conv[i]` is how C converts argument
/// i to the word (a short wraps to 16 bits).
pub fn learn_words(runs: &[WordRun], conv: &[fn(i64) -> i32]) -> Vec<WordSrc> {
    (0..5)
        .map(|w| {
            let vals: Vec<i32> = runs.iter().map(|r| r.words[w]).collect();
            if vals.iter().all(|v| *v == vals[0]) {
                // constant, unless it is the payload length
                if runs[0].payload_len > 0 && w == 4 && vals[0] as usize == runs[0].payload_len {
                    return WordSrc::Len;
                }
                return WordSrc::Const(vals[0]);
            }
            if w == 4 && runs.iter().all(|r| r.words[4] as usize == r.payload_len) {
                return WordSrc::Len;
            }
            for (i, c) in conv.iter().enumerate() {
                if runs
                    .iter()
                    .all(|r| r.args.get(i).is_some_and(|a| c(*a) == r.words[w]))
                    && runs.iter().any(|r| r.args[i] != runs[0].args[i])
                {
                    return WordSrc::Arg(i);
                }
            }
            // a flag: one value for a nonzero argument, 0 for 0
            for (i, c) in conv.iter().enumerate() {
                let arg = |r: &WordRun| r.args.get(i).map(|a| c(*a));
                let Some(k) = runs
                    .iter()
                    .find(|r| arg(r).is_some_and(|a| a != 0))
                    .map(|r| r.words[w])
                else {
                    continue;
                };
                let fits = runs
                    .iter()
                    .all(|r| arg(r).is_some_and(|a| r.words[w] == if a != 0 { k } else { 0 }));
                if k != 0 && fits && runs.iter().any(|r| arg(r) == Some(0)) {
                    return WordSrc::Nonzero(i, k);
                }
            }
            let mut v = vals;
            v.dedup();
            WordSrc::Computed(v)
        })
        .collect()
}

// ---------------------------------------------------------------- checks

/// A no-traffic range: number argument `arg` outside `lo..=hi` returns
/// `code` (inclusive bounds; i64 so that unsigned longs fit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LearntCheck {
    pub arg: usize,
    pub lo: i64,
    pub hi: i64,
    pub code: i16,
}

/// From a sweep of one argument (`value`, `Some(code)` when the call
/// returned without traffic, None when it sent a request), the accepted
/// range and the code outside it; None without any refusal. Values
/// refused inside the accepted range (holes) give `Err`.
pub fn learn_check(
    arg: usize,
    sweep: &[(i64, Option<i16>)],
) -> Result<Option<LearntCheck>, String> {
    let ok: Vec<i64> = sweep
        .iter()
        .filter(|s| s.1.is_none())
        .map(|s| s.0)
        .collect();
    let bad: Vec<(i64, i16)> = sweep.iter().filter_map(|s| s.1.map(|c| (s.0, c))).collect();
    if bad.is_empty() {
        return Ok(None);
    }
    if ok.is_empty() {
        return Err(format!("argument {arg}: no value tried sent anything"));
    }
    let (lo_ok, hi_ok) = (*ok.iter().min().unwrap(), *ok.iter().max().unwrap());
    if let Some(h) = bad.iter().find(|b| b.0 > lo_ok && b.0 < hi_ok) {
        return Err(format!(
            "argument {arg}: {} refused inside the accepted values",
            h.0
        ));
    }
    let codes: Vec<i16> = bad.iter().map(|b| b.1).collect();
    if codes.iter().any(|c| *c != codes[0]) {
        return Err(format!("argument {arg}: several codes {codes:?}"));
    }
    let below = bad.iter().filter(|b| b.0 < lo_ok).map(|b| b.0).max();
    let above = bad.iter().filter(|b| b.0 > hi_ok).map(|b| b.0).min();
    Ok(Some(LearntCheck {
        arg,
        lo: below.map_or(i64::MIN, |b| b + 1),
        hi: above.map_or(i64::MAX, |a| a - 1),
        code: codes[0],
    }))
}

// ------------------------------------------------------------- layouts

/// One integer as the draft writes it: `wire` bytes at reply offset `at`
/// into output `out`'s leaf `path` (a C integer `c`).
#[derive(Debug, Clone, PartialEq)]
pub struct Placed {
    pub at: usize,
    pub wire: Int,
    pub out: usize,
    pub off: usize,
    pub path: String,
    pub c: Int,
}

/// The integers the byte map shows: for each integer leaf of an output
/// whose low bytes are consecutive source bytes, most significant first
/// (a big-endian integer of the wire), with the bytes above them its sign
/// or zeros. Leaves written otherwise are reported in `odd`.
pub fn placed(out: usize, map: &[Src], lv: &[Leaf], odd: &mut Vec<String>) -> Vec<Placed> {
    let mut v = Vec::new();
    for l in lv {
        let s = l.ty.size();
        let Some(bytes) = map.get(l.off..l.off + s) else {
            continue;
        };
        if bytes.iter().all(|b| *b == Src::Kept) {
            continue;
        }
        let Some(c) = l.ty.int() else {
            odd.push(format!("out {out} {}: a {}-byte float written", l.path, s));
            continue;
        };
        let Src::At(p0) = bytes[0] else {
            odd.push(format!("out {out} {}: {:?}", l.path, bytes));
            continue;
        };
        let mut w = 1;
        while w < s && bytes[w] == Src::At(p0.wrapping_sub(w)) && p0 >= w {
            w += 1;
        }
        let rest = &bytes[w..];
        let signed = rest.iter().any(|b| matches!(b, Src::Sign(_)));
        let fine = rest
            .iter()
            .all(|b| matches!(b, Src::Sign(_) | Src::Const(0)));
        if !fine {
            odd.push(format!("out {out} {}: {:?}", l.path, bytes));
            continue;
        }
        let wire = match (
            w,
            signed || matches!(c, Int::I8 | Int::I16 | Int::I32) && w == s,
        ) {
            (1, true) => Int::I8,
            (1, false) => Int::U8,
            (2, true) => Int::I16,
            (2, false) => Int::U16,
            (_, true) => Int::I32,
            (_, false) => Int::U32,
        };
        if w == 3 {
            odd.push(format!("out {out} {}: 3 wire bytes", l.path));
            continue;
        }
        v.push(Placed {
            at: p0 + 1 - w,
            wire,
            out,
            off: l.off,
            path: l.path.clone(),
            c,
        });
    }
    v
}

/// The committed entry's reply as [`Placed`] integers for a payload of
/// `len` bytes and `asked` records, its member paths resolved in `outs`
/// (each output's type).
pub fn expected(f: &Func, outs: &[Ty], len: usize, asked: usize) -> Result<Vec<Placed>, String> {
    let mut v = Vec::new();
    let mut at = 0;
    let put = |v: &mut Vec<Placed>, at: usize, fld: &spec::Field, base: usize, ty: &Ty| {
        let Some(m) = fld.to else { return Ok(()) };
        if fld.arg.is_some() {
            return Ok(());
        }
        // `name[i]`: from element i of array member `name` on.
        let (name, i) = match m.strip_suffix(']').and_then(|p| p.rsplit_once('[')) {
            Some((name, i)) => (name, i.parse::<usize>().map_err(|_| format!("{m:?}"))?),
            None => (m, 0),
        };
        let (off, mt) = member(ty, name).ok_or_else(|| format!("no member {m:?}"))?;
        let elem = match &mt {
            Ty::Array(t, _) => t.size(),
            _ => fld.c.size(),
        };
        let off = off + i * elem;
        for k in 0..fld.n as usize {
            let o = base + off + k * elem;
            let mut lv = Vec::new();
            leaves(ty, 0, "", &mut lv);
            let path = lv
                .iter()
                .find(|l| l.off == o)
                .map(|l| l.path.clone())
                .unwrap_or_else(|| m.to_string());
            v.push(Placed {
                at: at + k * fld.wire.size(),
                wire: fld.wire,
                out: fld.out as usize,
                off: o,
                path,
                c: fld.c,
            });
        }
        Ok::<(), String>(())
    };
    for fld in f.reply {
        if at + fld.wire_len() > len {
            break;
        }
        // a field read into no output (skipped, or not on the wire) needs none
        if fld.to.is_some() && fld.arg.is_none() {
            let ty = outs.get(fld.out as usize).ok_or("no output")?;
            put(&mut v, at, fld, 0, ty)?;
        }
        at += fld.wire_len();
    }
    if let Some(r) = &f.records {
        let ty = outs.get(r.out as usize).ok_or("no output")?;
        let (base, stride, elem_ty) = records_at(r, ty)?;
        let rl = r.wire_len();
        let n = ((len - at.min(len)) / rl.max(1))
            .min(r.max as usize)
            .min(asked);
        for k in 0..n {
            let mut rat = at + k * rl;
            for fld in r.fields {
                let mut one = Vec::new();
                put(&mut one, rat, fld, 0, &elem_ty)?;
                for mut p in one {
                    p.off += base + k * stride;
                    p.out = r.out as usize;
                    p.path = format!("[{k}].{}", p.path);
                    v.push(p);
                }
                rat += fld.wire_len();
            }
        }
    }
    Ok(v)
}

/// Where a [`spec::Records`]' records go in its output `ty`: the first's
/// offset, the stride, one record's type. `elem` spelled `T[N]`: each
/// record an N-element array from the member on (consecutive `char
/// name[N]` members, one a record).
pub fn records_at(r: &spec::Records, ty: &Ty) -> Result<(usize, usize, Ty), String> {
    let arr = r
        .elem
        .strip_suffix(']')
        .and_then(|e| e.rsplit_once('['))
        .and_then(|(_, n)| n.parse::<usize>().ok());
    Ok(if r.to.is_empty() {
        (0, ty.size(), ty.clone())
    } else {
        let (o, t) = member(ty, r.to).ok_or("no records member")?;
        match (t, arr) {
            // (a two-dimensional member's rows are the records already)
            (Ty::Array(e, _), Some(n)) if !matches!(*e, Ty::Array(..)) => {
                (o, n * e.size(), Ty::Array(e, n))
            }
            (Ty::Array(e, _), _) => (o, e.size(), *e),
            (t, _) => (o, t.size(), t),
        }
    })
}

/// Placed integers as the bytes they move: (out, out byte) ← reply byte,
/// plus the sign bytes, the form both sides are compared in (a narrowing
/// and a skipped word followed by the low half move the same bytes).
pub fn moves(p: &[Placed]) -> Vec<(usize, usize, Src)> {
    let mut v = Vec::new();
    for x in p {
        let (w, c) = (x.wire.size(), x.c.size());
        for b in 0..c {
            let src = if b < w {
                Src::At(x.at + w - 1 - b)
            } else if matches!(x.wire, Int::I8 | Int::I16 | Int::I32) {
                Src::Sign(x.at)
            } else {
                Src::Const(0)
            };
            v.push((x.out, x.off + b, src));
        }
    }
    v.sort_by_key(|m| (m.0, m.1));
    v
}

// ------------------------------------------------------------- records

/// A repeat in placed integers: the fields from index `first` on repeat
/// every `per` fields, `wire` bytes further on the reply and `out` bytes
/// further in the output, `n` times.
#[derive(Debug, Clone, PartialEq)]
pub struct Repeat {
    pub first: usize,
    pub per: usize,
    pub wire: usize,
    pub out: usize,
    pub n: usize,
}

/// The longest tail of `p` (sorted by reply offset) that is one group of
/// fields repeated at a fixed reply and output stride, at least twice.
pub fn repeat(p: &[Placed]) -> Option<Repeat> {
    let mut best: Option<Repeat> = None;
    for first in 0..p.len() {
        for per in 1..=(p.len() - first) / 2 {
            let (a, b) = (&p[first], &p[first + per]);
            if b.at <= a.at || b.off <= a.off || a.out != b.out {
                continue;
            }
            let (ws, os) = (b.at - a.at, b.off - a.off);
            let mut n = 1;
            'grp: while first + (n + 1) * per <= p.len() {
                for k in 0..per {
                    let (x, y) = (&p[first + k], &p[first + n * per + k]);
                    if y.at != x.at + n * ws
                        || y.off != x.off + n * os
                        || y.wire != x.wire
                        || y.c != x.c
                        || y.out != x.out
                    {
                        break 'grp;
                    }
                }
                n += 1;
            }
            if n >= 2 && first + n * per == p.len() {
                let r = Repeat {
                    first,
                    per,
                    wire: ws,
                    out: os,
                    n,
                };
                if best.as_ref().is_none_or(|b| r.first < b.first) {
                    best = Some(r);
                }
            }
        }
        if best.is_some() {
            break;
        }
    }
    best
}

// --------------------------------------------------------------- drafts

/// A learnt C parameter after the handle.
#[derive(Debug, Clone, PartialEq)]
pub enum DParam {
    Short(String),
    Long(String),
    Out(String, String),
    Count(String),
    In(String, String),
}

/// A request form learnt on some classes (`classes`: the table's
/// `Classes` variant name).
#[derive(Debug, Clone, PartialEq)]
pub struct DForm {
    pub classes: &'static str,
    pub class: u16,
    pub cmd: u16,
    pub words: Vec<WordSrc>,
    /// More than one subpacket or frame: only the first is described.
    pub more: usize,
}

/// The argument of a learnt echo that is the last number answered (the
/// table's `last`: number argument 0 plus the records written, less one).
pub const LAST_ECHO: usize = usize::MAX - 1;

/// A draft table entry.
#[derive(Debug, Clone, Default)]
pub struct Draft {
    pub name: String,
    pub params: Vec<DParam>,
    pub checks: Vec<LearntCheck>,
    pub forms: Vec<DForm>,
    /// Fixed reply fields, sorted by reply offset.
    pub reply: Vec<Placed>,
    /// Records: the placed fields of the first record, the repeat, how many
    /// were written for the payload sent.
    pub records: Option<(Vec<Placed>, Repeat)>,
    /// Payload fields of an input (write), as placed integers read from the
    /// input (`at`: request payload offset).
    pub payload: Vec<Placed>,
    /// Number arguments written back into an output: (output, leaf,
    /// C integer, number argument).
    pub echoes: Vec<(usize, String, Int, usize)>,
    /// Leaves written as 0 off the wire (zero fields): (output, leaf, C
    /// integer).
    pub zeros: Vec<(usize, String, Int)>,
    /// What the learner could not settle.
    pub flags: Vec<String>,
}

fn int_name(i: Int) -> &'static str {
    match i {
        Int::I8 => "I8",
        Int::Char => "Char",
        Int::U8 => "U8",
        Int::I16 => "I16",
        Int::U16 => "U16",
        Int::I32 => "I32",
        Int::U32 => "U32",
        Int::BaseExp => "BaseExp",
        Int::IdChar => "IdChar",
        Int::F64 => "F64",
    }
}

/// `path` as the table's member: indices left out (`data[3].x` → `data`
/// for the first element; later elements are counted into `n`).
pub fn member_name(path: &str) -> String {
    member_of(path)
}

fn member_of(path: &str) -> String {
    let mut s = String::new();
    let mut depth = 0;
    for c in path.chars() {
        match c {
            '[' => depth += 1,
            ']' => depth -= 1,
            _ if depth == 0 => s.push(c),
            _ => {}
        }
    }
    s.trim_start_matches('.').to_string()
}

/// Placed fields as the table's `Field` list: gaps in the reply as skips,
/// runs of one member's elements as one field with `n`.
pub fn fields_text(p: &[Placed], from: usize, indent: &str) -> String {
    let mut s = String::new();
    let mut at = from;
    let mut i = 0;
    while i < p.len() {
        let x = &p[i];
        while at < x.at {
            let gap = x.at - at;
            let w = if gap >= 4 && at.is_multiple_of(4) {
                "I32"
            } else if gap >= 2 && at.is_multiple_of(2) {
                "I16"
            } else {
                "U8"
            };
            let _ = writeln!(s, "{indent}skip({w}),");
            at += match w {
                "I32" => 4,
                "I16" => 2,
                _ => 1,
            };
        }
        if x.at < at {
            let _ = writeln!(
                s,
                "{indent}// overlaps: {} from reply byte {}",
                x.path, x.at
            );
            i += 1;
            continue;
        }
        let m = member_of(&x.path);
        let mut n = 1;
        while let Some(y) = p.get(i + n) {
            if member_of(&y.path) == m
                && y.out == x.out
                && y.wire == x.wire
                && y.c == x.c
                && y.at == x.at + n * x.wire.size()
                && y.off == x.off + n * x.c.size()
            {
                n += 1;
            } else {
                break;
            }
        }
        let first_elem = x.path.split('[').skip(1).all(|k| k.starts_with("0]"));
        let note = if first_elem {
            ""
        } else {
            " // not from element 0"
        };
        if n == 1 && x.out == 0 {
            let _ = writeln!(
                s,
                "{indent}to({}, {m:?}, {}),{note}",
                int_name(x.wire),
                int_name(x.c)
            );
        } else if n == 1 {
            let _ = writeln!(
                s,
                "{indent}to_out({}, {}, {m:?}, {}),{note}",
                x.out,
                int_name(x.wire),
                int_name(x.c)
            );
        } else {
            let _ = writeln!(
                s,
                "{indent}Field {{ wire: {}, n: {n}, out: {}, to: Some({m:?}), c: {}, arg: None }},{note}",
                int_name(x.wire),
                x.out,
                int_name(x.c)
            );
        }
        at = x.at + n * x.wire.size();
        i += n;
    }
    s
}

fn word_text(w: &WordSrc) -> String {
    match w {
        WordSrc::Arg(i) => format!("Word::Arg({i})"),
        WordSrc::Const(c) => format!("Word::Const({c})"),
        WordSrc::Len => "Word::Const(0) /* the payload's length */".into(),
        WordSrc::Computed(v) => format!("Word::Const({}) /* computed: {v:?} */", v[0]),
        WordSrc::Input(m) => format!("Word::Input({m:?}, I16)"),
        WordSrc::Nonzero(i, k) => format!("Word::Nonzero({i}, {k})"),
    }
}

impl Draft {
    /// The entry in the syntax of src/spec/table, marked as learnt, with
    /// what could not be settled as a comment block above it.
    pub fn text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "    // LEARNT by tools/oracle/learn.rs from FANUC's library: a draft to review."
        );
        if self.flags.is_empty() {
            let _ = writeln!(s, "    // Nothing left unsettled.");
        } else {
            let _ = writeln!(s, "    // Not settled:");
            for f in &self.flags {
                let _ = writeln!(s, "    // - {f}");
            }
        }
        let _ = writeln!(s, "    Func {{");
        let _ = writeln!(s, "        name: {:?},", self.name);
        let _ = writeln!(s, "        doc: \"Learnt: review.\",");
        let _ = writeln!(s, "        params: &[");
        for p in &self.params {
            let _ = writeln!(
                s,
                "            {},",
                match p {
                    DParam::Short(n) => format!("Param::Short({n:?})"),
                    DParam::Long(n) => format!("Param::Long({n:?})"),
                    DParam::Count(n) => format!("Param::Count({n:?})"),
                    DParam::Out(n, t) => format!("Param::Out({n:?}, {t:?})"),
                    DParam::In(n, t) => format!("Param::In({n:?}, {t:?})"),
                }
            );
        }
        let _ = writeln!(s, "        ],");
        if !self.checks.is_empty() {
            let _ = writeln!(s, "        checks: &[");
            for c in &self.checks {
                let _ = writeln!(
                    s,
                    "            Check {{ arg: {}, lo: {}, hi: {}, code: {} }},",
                    c.arg,
                    c.lo.clamp(i32::MIN as i64, i32::MAX as i64),
                    c.hi.clamp(i32::MIN as i64, i32::MAX as i64),
                    c.code
                );
            }
            let _ = writeln!(s, "        ],");
        }
        let _ = writeln!(s, "        forms: &[");
        for f in &self.forms {
            let mut words: Vec<String> = f.words.iter().map(word_text).collect();
            while words.last().is_some_and(|w| w == "Word::Const(0)") {
                words.pop();
            }
            let _ = writeln!(
                s,
                "            Form {{ classes: Classes::{}, class: {}, cmd: {:#06x}, words: &[{}] }},{}",
                f.classes,
                f.class,
                f.cmd,
                words.join(", "),
                if f.more > 0 {
                    format!(" // and {} more subpackets or frames", f.more)
                } else {
                    String::new()
                }
            );
        }
        let _ = writeln!(s, "        ],");
        if !self.reply.is_empty() || !self.echoes.is_empty() || !self.zeros.is_empty() {
            let _ = writeln!(s, "        reply: &[");
            for (o, path, c, k) in &self.echoes {
                let o = if *o == 0 {
                    String::new()
                } else {
                    format!(" /* output {o} */")
                };
                if *k == LAST_ECHO {
                    let _ = writeln!(
                        s,
                        "            last({:?}, {}),{o}",
                        member_of(path),
                        int_name(*c)
                    );
                    continue;
                }
                let _ = writeln!(
                    s,
                    "            echo({k}, {:?}, {}),{o}",
                    member_of(path),
                    int_name(*c)
                );
            }
            s.push_str(&fields_text(&self.reply, 0, "            "));
            // zero fields, runs of one member's elements as one
            let mut k = 0;
            while k < self.zeros.len() {
                let (o, path, c) = &self.zeros[k];
                let m = member_of(path);
                let run = self.zeros[k..]
                    .iter()
                    .take_while(|(o2, p2, c2)| o2 == o && c2 == c && member_of(p2) == m)
                    .count();
                let o = if *o == 0 {
                    String::new()
                } else {
                    format!(" /* output {o} */")
                };
                if run == 1 {
                    let _ = writeln!(s, "            zero({path:?}, {}),{o}", int_name(*c));
                } else {
                    let _ = writeln!(
                        s,
                        "            Field {{ n: {run}, ..zero({path:?}, {}) }},{o}",
                        int_name(*c)
                    );
                }
                k += run;
            }
            let _ = writeln!(s, "        ],");
        }
        if let Some((rec, r)) = &self.records {
            let from = rec.first().map_or(0, |x| x.at);
            let _ = writeln!(s, "        records: Some(&Records {{");
            let _ = writeln!(s, "            fields: &[");
            let mut local: Vec<Placed> = rec.clone();
            let base_off = local.first().map_or(0, |x| x.off);
            for x in &mut local {
                x.at -= from;
                x.path = x
                    .path
                    .rsplit_once("].")
                    .map_or(String::new(), |p| p.1.to_string());
            }
            s.push_str(&fields_text(&local, 0, "                "));
            let _ = writeln!(s, "            ],");
            let to = rec
                .first()
                .map(|x| member_of(x.path.rsplit_once('[').map_or("", |p| p.0)))
                .unwrap_or_default();
            let _ = writeln!(
                s,
                "            out: {}, to: {to:?} /* from byte {base_off} */, elem: \"?\" /* {} bytes */,",
                rec.first().map_or(0, |x| x.out),
                r.out
            );
            let _ = writeln!(
                s,
                "            max: {} /* written for the payload sent; {} reply bytes each */,",
                r.n, r.wire
            );
            let _ = writeln!(s, "            count: None, room: None,");
            let _ = writeln!(s, "        }}),");
        }
        if !self.payload.is_empty() {
            let _ = writeln!(s, "        payload: Some(&Payload {{");
            let _ = writeln!(s, "            fields: &[");
            s.push_str(&fields_text(&self.payload, 0, "                "));
            let _ = writeln!(s, "            ],");
            let _ = writeln!(s, "            elem: \"?\", count: 0, max: 1,");
            let _ = writeln!(s, "        }}),");
        }
        // The learner's open points travel with the entry (a reviewer
        // words them as settled); COMPATIBILITY.md shows them.
        let _ = writeln!(s, "        learnt: Some(&[");
        for f in &self.flags {
            let _ = writeln!(s, "            {f:?},");
        }
        let _ = writeln!(s, "        ]),");
        let _ = writeln!(s, "        ..COMMAND");
        let _ = writeln!(s, "    }},");
        s
    }
}

// ----------------------------------------------------------- comparing

/// The committed entry's words on a class as [`WordSrc`]: `Asked` is the
/// count argument, the payload's length word when there is a payload.
pub fn committed_words(f: &Func, s16: bool, s15: bool) -> Option<(u16, u16, Vec<WordSrc>)> {
    let form = f.form(s16, s15)?;
    let mut w: Vec<WordSrc> = (0..5)
        .map(|k| match form.words.get(k) {
            Some(spec::Word::Arg(i)) => WordSrc::Arg(*i as usize),
            Some(spec::Word::Const(c)) => WordSrc::Const(*c),
            Some(spec::Word::Asked) => WordSrc::Arg(f.count().unwrap_or(usize::MAX)),
            Some(spec::Word::Input(m, _)) => WordSrc::Input(m.to_string()),
            Some(spec::Word::Upto(_, e, _, _)) => WordSrc::Arg(*e as usize),
            Some(spec::Word::Nonzero(i, k)) => WordSrc::Nonzero(*i as usize, *k),
            // The first number plus the count, less one: computed from two
            // arguments, as the learner reports such a word.
            Some(spec::Word::Last(_)) | Some(spec::Word::Plus(..)) => WordSrc::Computed(Vec::new()),
            None => WordSrc::Const(0),
        })
        .collect();
    // text fields, records or a written block: the payload's length in
    // the fifth word
    if f.sends_payload() || f.block.is_some_and(|b| b.attributes.is_some()) {
        w[4] = WordSrc::Len;
    }
    Some((form.class, form.cmd, w))
}

/// Do a learnt form and the committed one agree? Words the committed entry
/// leaves 0 may be anything learnt as constant 0; an `Asked` word is
/// learnt as the count argument or as a constant (a count capped by the
/// entry's max gives the same word for every value tried); a `Last` or
/// `Plus` word as any computed word.
pub fn same_form(learnt: &DForm, committed: &(u16, u16, Vec<WordSrc>)) -> Result<(), String> {
    if learnt.class != committed.0 || learnt.cmd != committed.1 {
        return Err(format!(
            "({},{:#06x}) learnt, ({},{:#06x}) committed",
            learnt.class, learnt.cmd, committed.0, committed.1
        ));
    }
    for (k, (l, c)) in learnt.words.iter().zip(&committed.2).enumerate() {
        // A committed `Word::Last` or `Word::Plus` (no values of its own)
        // is any word the learner saw computed.
        let last = matches!((l, c), (WordSrc::Computed(_), WordSrc::Computed(v)) if v.is_empty());
        if l != c && !last {
            return Err(format!("word {k}: {l:?} learnt, {c:?} committed"));
        }
    }
    Ok(())
}

/// Do the committed checks answer each swept value as observed?
/// `observed[i]`: argument i's values (as the C parameter holds them) and
/// what each did (`Some(code)` without traffic, None a request sent).
/// (`oracle learn --check` asks the whole entry, [`same_answers_by`].)
#[allow(dead_code)] // tests/recorded/learn.rs
pub fn same_answers(
    observed: &[Vec<(i64, Option<i16>)>],
    committed: &[spec::Check],
    conv: &[fn(i64) -> i32],
) -> Result<(), String> {
    same_answers_by(observed, |i, v| {
        let cv = conv.get(i).map_or(v as i32, |c| c(v));
        committed
            .iter()
            .find(|c| c.arg as usize == i && (cv < c.lo || cv > c.hi))
            .map(|c| c.code)
    })
}

/// Does `answer(i, v)` (the committed entry's answer with argument i, by
/// C position, at `v`: `Some(code)` without traffic, None a request sent)
/// answer each swept value as observed? `observed[i]`: argument i's values
/// and what each did.
pub fn same_answers_by(
    observed: &[Vec<(i64, Option<i16>)>],
    answer: impl Fn(usize, i64) -> Option<i16>,
) -> Result<(), String> {
    for (i, vals) in observed.iter().enumerate() {
        for (v, l) in vals {
            let c = answer(i, *v);
            if *l != c {
                return Err(format!("argument {i} = {v}: learnt {l:?}, committed {c:?}"));
            }
        }
    }
    Ok(())
}

/// The committed entry's payload for one record as [`Placed`] integers
/// (`at`: payload offset, `off`: the member's offset in the input's
/// element `elem`).
pub fn expected_payload(f: &Func, elem: &Ty) -> Result<Vec<Placed>, String> {
    let Some(pl) = &f.payload else {
        return Ok(Vec::new());
    };
    let mut v = Vec::new();
    let mut at = 0;
    for fld in pl.fields {
        if let Some(m) = fld.to {
            let (off, mt) = member(elem, m).ok_or_else(|| format!("no member {m:?}"))?;
            let step = match &mt {
                Ty::Array(t, _) => t.size(),
                _ => fld.c.size(),
            };
            for k in 0..fld.n as usize {
                v.push(Placed {
                    at: at + k * fld.wire.size(),
                    wire: fld.wire,
                    out: 0,
                    off: off + k * step,
                    path: m.to_string(),
                    c: fld.c,
                });
            }
        }
        at += fld.wire_len();
    }
    Ok(v)
}

/// Payload integers as the bytes they move: payload byte ← input byte
/// (the reverse of [`moves`]: the wire's big-endian bytes from the
/// input's little-endian ones).
pub fn payload_moves(p: &[Placed]) -> Vec<(usize, usize)> {
    let mut v = Vec::new();
    for x in p {
        let w = x.wire.size().min(x.c.size());
        for b in 0..w {
            v.push((x.at + x.wire.size() - 1 - b, x.off + b));
        }
    }
    v.sort();
    v
}

// --------------------------------------------------------- zeroed bytes

/// The offset of `path` in `ty`: a member (`a.b`), an element of an array
/// member (`name[i]`, elements of `elem` bytes) or of the pointee (`[i]`).
pub fn member_at(ty: &Ty, path: &str, elem: usize) -> Option<usize> {
    let (m, i) = match path.strip_suffix(']').and_then(|p| p.rsplit_once('[')) {
        Some((m, i)) => (m, i.parse::<usize>().ok()?),
        None => (path, 0),
    };
    let (off, _) = member(ty, m)?;
    Some(off + i * elem)
}

/// The output bytes the committed entry writes as 0 off the wire (its
/// [`spec::ZERO`] fields: a string's NUL, a text member's rest): (output
/// index among the outputs, byte offset), sorted.
pub fn committed_zeros(
    f: &Func,
    outs: &[Ty],
    len: usize,
    asked: usize,
) -> Result<Vec<(usize, usize)>, String> {
    let mut v = Vec::new();
    let zero = |fld: &spec::Field, ty: &Ty, base: usize, v: &mut Vec<(usize, usize)>| {
        let Some(m) = fld.to.filter(|_| fld.arg == Some(spec::ZERO)) else {
            return Ok(());
        };
        let size = fld.c.size();
        let off = member_at(ty, m, size).ok_or_else(|| format!("no member {m:?}"))?;
        for b in 0..fld.n as usize * size {
            v.push((fld.out as usize, base + off + b));
        }
        Ok::<(), String>(())
    };
    for fld in f.reply {
        if fld.arg == Some(spec::ZERO) {
            zero(
                fld,
                outs.get(fld.out as usize).ok_or("no output")?,
                0,
                &mut v,
            )?;
        }
    }
    // each record's zero fields, for the records the reply holds
    if let Some(r) = &f.records
        && r.fields.iter().any(|x| x.arg == Some(spec::ZERO))
    {
        let ty = outs.get(r.out as usize).ok_or("no output")?;
        let (base, stride, elem_ty) = records_at(r, ty)?;
        let at: usize = f.reply.iter().map(|x| x.wire_len()).sum();
        let n = ((len - at.min(len)) / r.wire_len().max(1))
            .min(r.max as usize)
            .min(asked);
        for k in 0..n {
            for fld in r.fields {
                let mut one = Vec::new();
                zero(fld, &elem_ty, 0, &mut one)?;
                v.extend(
                    one.into_iter()
                        .map(|(_, b)| (r.out as usize, base + k * stride + b)),
                );
            }
        }
    }
    v.sort();
    v.dedup();
    Ok(v)
}

/// A leaf written as 0: its path and C integer.
pub type ZeroLeaf = (String, Int);

/// The leaves of one output (`lv`) its map shows written as 0 whatever the
/// reply (every byte `Const(0)`): the zero fields the library writes off
/// the wire. (path, C integer) each, and their bytes as (out, offset).
pub fn learnt_zeros(out: usize, map: &[Src], lv: &[Leaf]) -> (Vec<ZeroLeaf>, Vec<(usize, usize)>) {
    let (mut leaves, mut bytes) = (Vec::new(), Vec::new());
    for l in lv {
        let b = map.get(l.off..(l.off + l.ty.size()).min(map.len()));
        let (Some(b), Some(c)) = (b, l.ty.int()) else {
            continue;
        };
        if !b.is_empty() && b.iter().all(|x| *x == Src::Const(0)) {
            leaves.push((l.path.clone(), c));
            bytes.extend((l.off..l.off + b.len()).map(|k| (out, k)));
        }
    }
    (leaves, bytes)
}

// ------------------------------------------------ replies that do not map

/// Why the committed entry's reply does not map a reply's bytes to output
/// bytes one for one (what the learner's position-coded replies cannot
/// show), if so: a typed block, value records, lookups, a count in the
/// reply, several subpackets.
pub fn entry_not_clean(f: &Func) -> Option<String> {
    let fields = f
        .reply
        .iter()
        .chain(f.records.iter().flat_map(|r| r.fields.iter()));
    if f.block.is_some() {
        return Some(
            "a typed parameter block: the answer's type word decides each value's kind and size (Func::block)"
                .into(),
        );
    }
    if fields.clone().any(|x| x.wire == Int::BaseExp) {
        return Some("a value record: digits and decimal places converted, not bytes moved".into());
    }
    if !f.lookups.is_empty() {
        let members: Vec<&str> = f.lookups.iter().map(|l| l.to).collect();
        return Some(format!(
            "lookups: {} filled by looking keys up in the reply (Func::lookups), not bytes moved",
            members.join(", ")
        ));
    }
    if let Some(k) = f.counted {
        return Some(format!(
            "a count in the reply (field {k}, Func::counted) decides the records read: a coded reply announces more than it holds"
        ));
    }
    if f.columns.is_some() {
        return Some(
            "columns: each reply field read from its own subpacket (Func::columns)".into(),
        );
    }
    if !f.more.is_empty() {
        return Some(format!(
            "several subpackets: the reply's fields shared over {} answers (Func::more)",
            f.more.len() + 1
        ));
    }
    None
}

/// The bytes of output 0 (`ty`) its [`spec::Lookup`]s fill: (offset, length)
/// from each lookup's member on (its elements' integers, `c` each).
pub fn lookup_spans(f: &Func, ty: &Ty) -> Vec<(usize, usize)> {
    f.lookups
        .iter()
        .filter_map(|l| member_at(ty, l.to, l.c.size()).map(|o| (o, l.values() * l.c.size())))
        .collect()
}
