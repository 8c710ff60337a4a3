//! A program parsed for one path's axes (`Plan`): its blocks with the
//! axis end points and the modal state after each, what the running
//! machine (src/sim/clock.rs) steps through on the simulator's clock.

use super::modal::ProgramModal;
use super::profile::cycle::Cycle;

/// Lines shown by cnc_rdexecprog: the current one and the following.
pub(super) const EXEC_LINES: usize = 8;

/// Where an axis is at the end of a block: fixed by an absolute word, or
/// relative to where the axis was when the pass of the program started.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Pos {
    Abs(i64),
    Rel(i64),
}

/// Programmed positions and pass starts stay within ±2^40 detection
/// units (far past any real axis): the interpolation's sums and
/// differences of them cannot overflow, whatever a program or a profile
/// says (the profile fuzzer found `G91` moves that did).
const POS_LIMIT: i64 = 1 << 40;

fn bound(v: i64) -> i64 {
    v.clamp(-POS_LIMIT, POS_LIMIT)
}

impl Pos {
    pub(super) fn at(self, start: i64) -> i64 {
        match self {
            Pos::Abs(v) => v,
            Pos::Rel(d) => start + d,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// No motion (M, S, T, modal settings only).
    Still,
    Move {
        rapid: bool,
    },
    Dwell,
}

/// One executable block, with the modal state after it.
#[derive(Debug, Clone)]
pub(super) struct Block {
    /// Index in the program's lines.
    pub(super) line: usize,
    /// Modal N number (0: none yet in this pass).
    pub(super) seq: i32,
    pub(super) kind: Kind,
    /// Axis end points (per profile axis of the path).
    pub(super) end: Vec<Pos>,
    /// Modal codes as the pass left them (F, S ...; None: not yet set in
    /// this pass) and spindle on/off (None: inherited from before the pass).
    pub(super) modal: ProgramModal,
    pub(super) spin: Option<bool>,
    /// M30/M02: a part is counted when the block completes.
    pub(super) end_of_program: bool,
    /// Text of this line and the following ones (cnc_rdexecprog).
    pub(super) text: String,
    /// A macro message the block shows (`#3006=n(TEXT)`): its number and
    /// text.
    pub(super) message: Option<(i32, String)>,
}

/// The message of a `#3006=n(TEXT)` block (the macro statement that
/// stops with a message): n and the comment's text.
pub(super) fn macro_message(line: &str) -> Option<(i32, String)> {
    let rest =
        line.trim_start_matches(|c: char| c == 'N' || c == 'n' || c.is_ascii_digit() || c == ' ');
    let rest = rest.strip_prefix("#3006")?.trim_start().strip_prefix('=')?;
    let open = rest.find('(')?;
    let n = rest[..open].trim().parse().ok()?;
    let text = &rest[open + 1..];
    let text = &text[..text.find(')').unwrap_or(text.len())];
    Some((n, text.to_owned()))
}

/// A program parsed for one path's axes.
#[derive(Debug, Clone)]
pub(super) struct Plan {
    pub(super) blocks: Vec<Block>,
    /// Axis increments per mm (10^decimals), per axis.
    pub(super) scale: Vec<f64>,
    pub(super) block_seconds: f64,
    pub(super) repeat: bool,
    /// M30/M02 blocks per pass.
    pub(super) parts_per_pass: i64,
    /// Feed moves (G01/G02/G03) before each block, and in the pass (last).
    pub(super) feed_moves: Vec<u32>,
}

/// The word value in least increments: with a decimal point, millimetres
/// (scaled by 10^decimals); without, increments (FANUC's default).
pub(super) fn axis_value(text: &str, scale: f64) -> Option<i64> {
    let v: f64 = text.parse().ok()?;
    Some(if text.contains('.') {
        (v * scale).round() as i64
    } else {
        v as i64
    })
}

/// The address words of a block: comments "(...)", ';' and spaces removed.
pub(super) fn words(line: &str) -> Vec<(char, String)> {
    let mut clean = String::with_capacity(line.len());
    let mut depth = 0;
    for c in line.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth = (depth - 1).max(0),
            ';' | ' ' | '\t' if depth == 0 => {}
            c if depth == 0 => clean.push(c.to_ascii_uppercase()),
            _ => {}
        }
    }
    let mut out = Vec::new();
    let mut chars = clean.chars().peekable();
    while let Some(c) = chars.next() {
        if !c.is_ascii_alphabetic() {
            continue;
        }
        let mut v = String::new();
        while let Some(&d) = chars.peek() {
            if d.is_ascii_digit() || d == '.' || ((d == '-' || d == '+') && v.is_empty()) {
                v.push(d);
                chars.next();
            } else {
                break;
            }
        }
        out.push((c, v));
    }
    out
}

impl Plan {
    /// Blocks of the plan.
    pub(super) fn len(&self) -> usize {
        self.blocks.len()
    }
    pub(super) fn block_seconds(&self) -> f64 {
        self.block_seconds
    }
    /// Parses `text` for a path with these axes. Lines that are empty, '%'
    /// or the "O1234" program-number line are not blocks. G00/G01 (and
    /// G02/G03, run as straight moves) with G90/G91 move the axes; G04 is
    /// a dwell; G28 returns the named axes to machine zero.
    pub(super) fn parse(text: &str, axes: &[super::profile::Axis], cycle: &Cycle) -> Plan {
        let lines: Vec<&str> = text.lines().collect();
        let scale: Vec<f64> = axes
            .iter()
            .map(|a| 10f64.powi(i32::from(a.decimals.clamp(0, 9))))
            .collect();
        // Machine zero in absolute coordinates: absolute - machine offset.
        let zero: Vec<i64> = axes
            .iter()
            .map(|a| i64::from(a.absolute) - i64::from(a.machine))
            .collect();
        let mut pos: Vec<Pos> = vec![Pos::Rel(0); axes.len()];
        let (mut seq, mut spin, mut modal) = (0, None, ProgramModal::default());
        let (mut rapid, mut incremental) = (true, false);
        let mut blocks = Vec::new();
        for (line, raw) in lines.iter().enumerate() {
            let t = raw.trim();
            if t.is_empty() || t.starts_with('%') || t.starts_with(['O', 'o', ':']) {
                continue;
            }
            let ws = words(t);
            let gs: Vec<i32> = ws
                .iter()
                .filter(|(c, _)| *c == 'G')
                .filter_map(|(_, v)| v.parse::<f64>().ok().map(|g| g as i32))
                .collect();
            let (dwell, home) = (gs.contains(&4), gs.contains(&28));
            for g in &gs {
                modal.set_g(*g);
                match g {
                    0 => rapid = true,
                    1..=3 => rapid = false,
                    90 => incremental = false,
                    91 => incremental = true,
                    _ => {}
                }
            }
            let mut end_of_program = false;
            let mut moved = false;
            for (c, v) in &ws {
                match c {
                    'N' => seq = v.parse().unwrap_or(seq),
                    'F' | 'S' | 'T' | 'D' | 'H' => modal.set_word(*c, v),
                    'M' => {
                        modal.set_word('M', v);
                        match v.parse::<i32>().unwrap_or(-1) {
                            3 | 4 => spin = Some(true),
                            5 => spin = Some(false),
                            2 | 30 => end_of_program = true,
                            _ => {}
                        }
                    }
                    _ if !dwell => {
                        let Some(i) = axes.iter().position(|a| a.name.starts_with(*c)) else {
                            continue;
                        };
                        let Some(x) = axis_value(v, scale[i]) else {
                            continue;
                        };
                        moved = true;
                        pos[i] = if home {
                            Pos::Abs(zero[i])
                        } else if incremental {
                            match pos[i] {
                                Pos::Abs(p) => Pos::Abs(bound(p.saturating_add(x))),
                                Pos::Rel(d) => Pos::Rel(bound(d.saturating_add(x))),
                            }
                        } else {
                            Pos::Abs(bound(x))
                        };
                    }
                    _ => {}
                }
            }
            let kind = if dwell {
                Kind::Dwell
            } else if moved {
                Kind::Move {
                    rapid: rapid || home,
                }
            } else {
                Kind::Still
            };
            let end = (line + EXEC_LINES).min(lines.len());
            blocks.push(Block {
                line,
                seq,
                kind,
                end: pos.clone(),
                modal,
                spin,
                end_of_program,
                text: lines[line..end].join("\n"),
                message: macro_message(t),
            });
        }
        let parts_per_pass = blocks.iter().filter(|b| b.end_of_program).count() as i64;
        let feed_moves = std::iter::once(0)
            .chain(blocks.iter().scan(0, |n, b| {
                *n += u32::from(b.kind == Kind::Move { rapid: false });
                Some(*n)
            }))
            .collect();
        Plan {
            feed_moves,
            blocks,
            scale,
            block_seconds: cycle.block_seconds,
            repeat: cycle.repeat,
            parts_per_pass,
        }
    }

    /// Where axis `i` starts pass `pass` of the program.
    pub(super) fn pass_start(&self, i: usize, pass: u64, base: i64) -> i64 {
        match self.blocks.last().map(|b| b.end[i]) {
            None => base,
            Some(Pos::Abs(v)) => {
                if pass == 0 {
                    base
                } else {
                    v
                }
            }
            Some(Pos::Rel(d)) => bound(base.saturating_add(d.saturating_mul(pass as i64))),
        }
    }
}
