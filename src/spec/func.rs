//! What a [`Func`] entry implies: its parameters by kind, its probe word,
//! the counts and shares of its reply (read by every layer, as the entry).
//!
//! Compiled into build.rs too (`#[path]`), beside src/spec/types.rs.

use super::types::*;

impl Func {
    /// The probe word the oracle and the vectors call this function by.
    pub fn word(&self) -> &'static str {
        self.name.strip_prefix("cnc_").unwrap_or(self.name)
    }
    /// The code a function answers on every call without traffic (its
    /// first check [`ALWAYS`] fails, and it has no form), if it does.
    pub fn answers(&self) -> Option<i16> {
        let c = self.checks.first().filter(|c| c.arg == ALWAYS)?;
        self.forms.is_empty().then_some(c.code)
    }
    /// The number parameters, in order (the values a caller passes).
    pub fn numbers(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.params.iter().filter_map(|p| match *p {
            Param::Short(n)
            | Param::Long(n)
            | Param::ULong(n)
            | Param::UShort(n)
            | Param::Char(n)
            | Param::ShortAs(n, _)
            | Param::Count(n)
            | Param::LongCount(n)
            | Param::Io(n) => Some(n),
            Param::Out(..) | Param::In(..) | Param::InOut(..) | Param::Text(..) => None,
        })
    }
    /// The [`Param::Text`] parameters, in order: (name, field size).
    pub fn texts(&self) -> impl Iterator<Item = (&'static str, usize)> + '_ {
        self.params.iter().filter_map(|p| match *p {
            Param::Text(n, size) => Some((n, usize::from(size))),
            _ => None,
        })
    }
    /// Whether the request carries a payload (text fields or records),
    /// its length in the fifth word.
    pub fn sends_payload(&self) -> bool {
        self.payload.is_some() || self.texts().next().is_some()
    }
    /// The [`Param::Count`] parameter, if any: its index among the number
    /// parameters.
    pub fn count(&self) -> Option<usize> {
        self.numbers().position(|n| {
            self.params.contains(&Param::Count(n)) || self.params.contains(&Param::LongCount(n))
        })
    }
    /// Whether the count is a [`Param::LongCount`] (4 bytes by pointer),
    /// not a [`Param::Count`]'s `short`.
    pub fn long_count(&self) -> bool {
        self.params.iter().any(|p| matches!(p, Param::LongCount(_)))
    }
    /// The [`Param::In`] (or [`Param::InOut`]) parameter, if any: (name,
    /// C type).
    pub fn input(&self) -> Option<(&'static str, &'static str)> {
        self.params.iter().find_map(|p| match *p {
            Param::In(n, t) | Param::InOut(n, t) => Some((n, t)),
            _ => None,
        })
    }
    /// The input members sent as request words ([`Word::Input`]), each
    /// once, in the order the forms name them: the call's arguments after
    /// its number parameters.
    pub fn inputs(&self) -> impl Iterator<Item = (&'static str, Int)> + '_ {
        let all = self.forms.iter().flat_map(|f| f.words.iter());
        all.clone().enumerate().filter_map(move |(k, w)| match *w {
            Word::Input(m, c) if !all.clone().take(k).any(|x| *x == *w) => Some((m, c)),
            _ => None,
        })
    }
    /// The index in the call's arguments (numbers, then [`Func::inputs`])
    /// a request word carries, if any: `Arg(i)` is `i`, `Asked` the count.
    pub fn word_arg(&self, w: &Word) -> Option<usize> {
        match *w {
            Word::Arg(i) => Some(usize::from(i)),
            Word::Asked => self.count(),
            Word::Upto(_, e, _, _) => Some(usize::from(e)),
            Word::Const(_) | Word::Nonzero(..) | Word::Last(_) | Word::Plus(..) => None,
            Word::Input(m, _) => self
                .inputs()
                .position(|(x, _)| x == m)
                .map(|k| self.numbers().count() + k),
        }
    }
    /// The records a range asks for ([`Func::span`]), from the call's
    /// arguments (0 for one asked backwards); None without a range.
    pub fn span_len(&self, args: &[i32]) -> Option<usize> {
        let (s, e) = self.span?;
        let at = |i: u8| i64::from(args.get(usize::from(i)).copied().unwrap_or(0));
        Some(usize::try_from(at(e) - at(s) + 1).unwrap_or(0))
    }
    /// The records a range write ([`Pages`] without a count) sends: its
    /// span `s..=e` ([`Func::span`]) with `e` cut to the end of `s`'s
    /// range ([`Func::ends`]) on a CNC of the 16i class (`s16`) or Series
    /// 15 (`s15`); 0 for one backwards, None without a span.
    pub fn span_cut(&self, args: &[i32], s16: bool, s15: bool) -> Option<usize> {
        let (s, e) = self.span?;
        let at = |i: u8| args.get(usize::from(i)).copied().unwrap_or(0);
        let (s, mut e) = (at(s), at(e));
        if let Some(End::At(end)) = self.end_of(s, s16, s15) {
            e = e.min(end);
        }
        Some(usize::try_from(i64::from(e) - i64::from(s) + 1).unwrap_or(0))
    }
    /// The [`Ends`] entry of start `s` on a CNC of the 16i class (`s16`)
    /// or Series 15 (`s15`), if any.
    pub fn end_of(&self, s: i32, s16: bool, s15: bool) -> Option<End> {
        self.ends
            .iter()
            .find(|x| x.classes.matches(s16, s15) && (x.lo..=x.hi).contains(&s))
            .map(|x| x.end)
    }
    /// The word a [`Word::Upto`]`(s, e, n)` sends for start `s` and end
    /// `e` on a CNC of the 16i class (`s16`) or Series 15 (`s15`).
    pub fn upto(&self, s: i32, e: i32, n: i32, s16: bool, s15: bool) -> i32 {
        let e = match self.end_of(s, s16, s15) {
            Some(End::At(end)) => e.min(end),
            _ => e,
        };
        // As FANUC's library counts: in 32 bits, wrapping.
        if e.wrapping_sub(s).wrapping_add(1) > n.wrapping_add(1) {
            s.wrapping_add(n)
        } else {
            e
        }
    }
    /// Whether the call's number arguments `args` send [`Func::first`]'s
    /// request on a CNC of the 16i class (`s16`) or Series 15 (`s15`).
    pub fn sends_first(&self, args: &[i32], s16: bool, s15: bool) -> bool {
        self.first.is_some_and(|f| {
            let v = args.get(usize::from(f.arg)).copied().unwrap_or(0);
            f.classes.matches(s16, s15) && f.ranges.iter().any(|r| (r.0..=r.1).contains(&v))
        })
    }
    /// The EW_* code FANUC's library returns for the call's number
    /// arguments `args` on a CNC of the 16i class (`s16`) or Series 15
    /// (`s15`) without sending its own request, if any: its checks (the
    /// FOCAS option's: `option` says whether the CNC has it) and the ends
    /// of its ranges ([`End::Alone`]). They come after a
    /// [`Func::first`] request.
    pub fn refusal(&self, args: &[i32], s16: bool, s15: bool, option: bool) -> Option<i16> {
        self.refusal_detail(args, s16, s15, option).map(|r| r.0)
    }
    /// [`Func::refusal`] with the detail code a [`Rule`] of a number
    /// parameter sets (its checks first, then its number rules).
    pub fn refusal_detail(
        &self,
        args: &[i32],
        s16: bool,
        s15: bool,
        option: bool,
    ) -> Option<(i16, Option<i16>)> {
        if let Some(c) = self.check_refusal(args, s16, s15, option) {
            return Some((c, None));
        }
        let at = |i: u8| i64::from(args.get(usize::from(i)).copied().unwrap_or(0));
        self.rule_refusal(
            |of| match of {
                Of::Arg(i) => Some(at(i)),
                Of::Field(_) => None,
            },
            at,
            s16,
            s15,
            i64::from(AXES),
        )
        .map(|(c, d)| (c, Some(d)))
    }
    /// The first [`Rule`] that refuses, of the targets `value` gives a value
    /// for (`when` reads `key`), on a CNC of the 16i class (`s16`) or
    /// Series 15 (`s15`) whose path has `axes` axes: (code, detail).
    pub fn rule_refusal(
        &self,
        value: impl Fn(Of) -> Option<i64>,
        key: impl Fn(u8) -> i64,
        s16: bool,
        s15: bool,
        axes: i64,
    ) -> Option<(i16, i16)> {
        let mut done: Vec<Of> = Vec::new();
        for r in self.rules {
            let Some(v) = value(r.of) else { continue };
            let applies = r.classes.matches(s16, s15)
                && r.when
                    .is_none_or(|(k, lo, hi)| (i64::from(lo)..=i64::from(hi)).contains(&key(k)));
            if !applies || done.contains(&r.of) {
                continue;
            }
            done.push(r.of);
            let hi = |h: i32| if h == AXES { axes } else { i64::from(h) };
            if !r
                .ok
                .iter()
                .any(|&(lo, h)| (i64::from(lo)..=hi(h)).contains(&v))
            {
                return Some((r.code, r.detail));
            }
        }
        None
    }
    /// The [`Each`] exchange of a payload record (`rec`: its payload
    /// fields' integers as read) on a CNC of the 16i class (`s16`) or
    /// Series 15 (`s15`), if any.
    pub fn each_of(&self, rec: &[i64], s16: bool, s15: bool) -> Option<&'static Each> {
        self.each.iter().find(|e| {
            let k = rec.get(usize::from(e.when.0)).copied().unwrap_or(0);
            e.classes.matches(s16, s15) && (i64::from(e.when.1)..=i64::from(e.when.2)).contains(&k)
        })
    }
    /// A payload record's integers (`rec`, as read) with [`Func::codes`]
    /// applied: `args` the call's numbers, `value` the record's [`Each`]
    /// value. Err: EW_DATA, a key outside its table.
    pub fn coded(&self, rec: &mut [i64], args: &[i32], value: Option<i64>) -> Result<(), i16> {
        let read = rec.to_vec();
        let at = |k: u8| read.get(usize::from(k)).copied().unwrap_or(0);
        let mut done: Vec<u8> = Vec::new();
        for c in self.codes {
            let applies = c
                .when
                .is_none_or(|(k, lo, hi)| (i64::from(lo)..=i64::from(hi)).contains(&at(k)));
            if !applies || done.contains(&c.field) || usize::from(c.field) >= rec.len() {
                continue;
            }
            done.push(c.field);
            let mut v = match c.value {
                CodeValue::Arg(a) => i64::from(args.get(usize::from(a)).copied().unwrap_or(0)),
                CodeValue::Table(t) => {
                    match usize::try_from(at(c.field)).ok().and_then(|i| t.get(i)) {
                        Some(v) => i64::from(*v),
                        None => return Err(crate::ew::EW_DATA),
                    }
                }
            };
            if c.negate && value.is_some_and(|e| e > 0 && e % 2 == 0) {
                v = -v;
            }
            rec[usize::from(c.field)] = v;
        }
        Ok(())
    }
    fn check_refusal(&self, args: &[i32], s16: bool, s15: bool, option: bool) -> Option<i16> {
        let at = |i: i32| args.get(i as usize).copied().unwrap_or(0);
        if let Some(code) = self.checks_fail(self.checks.len(), args, option) {
            return Some(code);
        }
        let upto = self.forms.iter().filter(|f| f.classes.matches(s16, s15));
        let spans = upto
            .flat_map(|f| f.words.iter())
            .take(5)
            .filter_map(|w| match *w {
                Word::Upto(s, e, _, _) => Some((s, e)),
                _ => None,
            })
            // A range write's span (Pages) ends as a range read's.
            .chain(self.span.filter(|_| self.pages.is_some()));
        for (s, e) in spans {
            let (s, e) = (at(i32::from(s)), at(i32::from(e)));
            if self.end_of(s, s16, s15) == Some(End::Alone) && e > s {
                return Some(crate::ew::EW_NUMBER);
            }
        }
        None
    }
    /// The code of the first of the function's first `n` checks that the
    /// call's number arguments `args` fail (the FOCAS option's: `option`
    /// says whether the CNC has it), if any: [`Func::refusal`]'s, and those
    /// made before a [`Func::first`] request ([`First::after`]).
    pub fn checks_fail(&self, n: usize, args: &[i32], option: bool) -> Option<i16> {
        let at = |i: i32| args.get(i as usize).copied().unwrap_or(0);
        self.checks.iter().take(n).find_map(|c| {
            let bad = match c.arg {
                ALWAYS => true,
                ORDERED => at(c.lo) > at(c.hi),
                OPTION => !(c.lo..=c.hi).contains(&i32::from(option)),
                // lo above hi: the range wraps (Check).
                a if c.lo > c.hi => (c.hi + 1..c.lo).contains(&at(i32::from(a))),
                a => !(c.lo..=c.hi).contains(&at(i32::from(a))),
            };
            bad.then_some(c.code)
        })
    }
    /// The output parameters ([`Param::Out`], [`Param::InOut`]), in
    /// order: (name, C type).
    pub fn outs(&self) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
        self.params.iter().filter_map(|p| match *p {
            Param::Out(n, t) | Param::InOut(n, t) => Some((n, t)),
            _ => None,
        })
    }
    /// The records one request of a paging function ([`Func::pages`])
    /// carries at most: its byte budget over one record's wire bytes (the
    /// payload's, else the reply records'); None for another function.
    pub fn per_page(&self) -> Option<usize> {
        let pg = self.pages?;
        let size: usize = match (&self.payload, &self.records) {
            (Some(p), _) => p.fields.iter().map(Field::wire_len).sum(),
            (None, Some(r)) => r.fields.iter().map(Field::wire_len).sum(),
            (None, None) => 0,
        };
        Some(usize::from(pg.bytes) / size.max(1))
    }
    /// The reply payload's length in bytes (of every subpacket's answer).
    pub fn reply_len(&self) -> usize {
        self.reply.iter().map(Field::wire_len).sum()
    }
    /// The reply fields subpacket `i`'s answer carries (all of them
    /// without [`Func::more`]).
    pub fn share(&self, i: usize) -> &'static [Field] {
        let n = self.reply.len() / (1 + self.more.len());
        let at = (i * n).min(self.reply.len());
        &self.reply[at..(at + n).min(self.reply.len())]
    }
}
