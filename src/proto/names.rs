//! Names for what crosses the wire: which FOCAS functions send a command,
//! and the `EW_*` name of a result code (from src/ew.rs). Read by the simulator's trace and
//! fault injection (a fault can name a function instead of a command).
//!
//! Both read the command registry (src/spec/commands.rs): a command several
//! functions send (0x0026 positions: `cnc_absolute`, `cnc_rddynamic2` ...)
//! lists them all, the one that sends it alone first.

use super::packet::ReqSub;
use crate::spec::Word;
use crate::spec::commands::{COMMANDS, find};

/// The function a request subpacket stands for, as a trace names it: a
/// described function whose form on this CNC class (`s16`, `s15`) is this
/// command with these constant words, else the first function the
/// registry names for it.
pub fn request_name(sub: &ReqSub, s16: bool, s15: bool) -> Option<&'static str> {
    described_names(sub.class, sub.cmd, s16, s15, Some(&sub.args))
        .next()
        .or_else(|| table_names(sub.class, sub.cmd).next())
}

/// The name of command `cmd` of subpacket class `class` (a response
/// carries no argument words: the first function that sends it).
pub fn command_name(class: u16, cmd: u16, s16: bool, s15: bool) -> Option<&'static str> {
    table_names(class, cmd)
        .next()
        .or_else(|| described_names(class, cmd, s16, s15, None).next())
}

fn table_names(class: u16, cmd: u16) -> impl Iterator<Item = &'static str> {
    find(class, cmd)
        .into_iter()
        .flat_map(|c| c.senders.iter().copied())
}

fn described_names<'a>(
    class: u16,
    cmd: u16,
    s16: bool,
    s15: bool,
    args: Option<&'a [i32; 5]>,
) -> impl Iterator<Item = &'static str> + 'a {
    crate::spec::FUNCS
        .iter()
        .filter(move |f| {
            f.form(s16, s15).is_some_and(|form| {
                form.class == class
                    && form.cmd == cmd
                    && args.is_none_or(|a| {
                        form.words.iter().zip(a).all(|(w, v)| match w {
                            Word::Const(c) => c == v,
                            Word::Arg(_)
                            | Word::Asked
                            | Word::Input(..)
                            | Word::Upto(..)
                            | Word::Nonzero(..)
                            | Word::Last(_)
                            | Word::Plus(..) => true,
                        })
                    })
            })
        })
        .map(|f| f.name)
}

/// The (class, command) pairs that stand for function `name` (what an
/// error fault naming it answers for), on any CNC class: the commands only
/// it sends; without such, those it is named first for; else every one it
/// sends. Empty for a name no table knows.
pub fn function_commands(name: &str) -> Vec<(u16, u16)> {
    let listed = |only: bool, first: bool| -> Vec<(u16, u16)> {
        COMMANDS
            .iter()
            .filter(|c| {
                c.senders.contains(&name)
                    && (!only || c.senders.len() == 1)
                    && (!first || c.senders.first() == Some(&name))
            })
            .map(|c| (c.class, c.cmd))
            .collect()
    };
    let mut out = listed(true, false);
    if out.is_empty() {
        out = listed(false, true);
    }
    if out.is_empty() {
        out = listed(false, false);
    }
    out
}

/// The `EW_*` name of `code` (src/ew.rs; the first name where FANUC's
/// header gives a code two), if it has one.
pub fn ew_name(code: i16) -> Option<&'static str> {
    crate::ew::CODES
        .iter()
        .find(|(_, c, _)| *c == code)
        .map(|(n, _, _)| *n)
}

/// The code named `name` (`"EW_NOOPT"`, or without the prefix: `"noopt"`).
pub fn ew_code(name: &str) -> Option<i16> {
    let up = name.trim().to_ascii_uppercase();
    let full = if up.starts_with("EW_") {
        up
    } else {
        format!("EW_{up}")
    };
    crate::ew::CODES
        .iter()
        .find(|(n, _, _)| *n == full)
        .map(|(_, c, _)| *c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proto::cmd;
    use crate::proto::packet::{CLASS_CNC, CLASS_PMC};

    #[test]
    fn every_exported_data_function_in_the_table_is_known() {
        for c in COMMANDS {
            for n in c.senders {
                assert!(n.starts_with("cnc_") || n.starts_with("pmc_"), "{n}");
            }
        }
        assert_eq!(
            function_commands("cnc_statinfo"),
            vec![(CLASS_CNC, cmd::STATINFO)]
        );
        assert_eq!(
            function_commands("cnc_statinfo2"),
            vec![(CLASS_CNC, cmd::STATINFO2)]
        );
        assert_eq!(
            function_commands("cnc_rdparam"),
            vec![(CLASS_CNC, cmd::RDPARAM16), (CLASS_CNC, cmd::RDPARAM)]
        );
        assert_eq!(function_commands("cnc_rddynamic2").len(), 6);
        assert_eq!(
            function_commands("pmc_rdpmcrng"),
            vec![(CLASS_PMC, cmd::RDPMCRNG)]
        );
        assert_eq!(
            function_commands("pmc_rdalmmsg"),
            vec![(CLASS_PMC, cmd::PMC_RDALMMSG)]
        );
        assert_eq!(
            function_commands("cnc_wrpm_item"),
            vec![(CLASS_CNC, cmd::WRPM_ITEM)]
        );
        assert_eq!(
            function_commands("cnc_rdtimer"),
            vec![(CLASS_CNC, cmd::RDTIMER)]
        );
        assert!(function_commands("cnc_nothing").is_empty());
    }

    #[test]
    fn requests_are_named_by_their_command_and_constant_words() {
        let s = ReqSub::cnc(cmd::STATINFO, &[]);
        assert_eq!(request_name(&s, false, false), Some("cnc_statinfo"));
        let s = ReqSub::cnc(cmd::RDTIMER, &[1]);
        assert_eq!(request_name(&s, false, false), Some("cnc_rdtimer"));
        assert_eq!(
            command_name(CLASS_CNC, cmd::RDPARAM, false, false),
            Some("cnc_rdparam")
        );
        let unknown = u16::MAX; // no command
        assert_eq!(command_name(CLASS_CNC, unknown, false, false), None);
    }

    #[test]
    fn codes_by_name() {
        assert_eq!(ew_code("EW_NOOPT"), Some(6));
        assert_eq!(ew_code("busy"), Some(-1));
        assert_eq!(ew_name(-16), Some("EW_SOCKET"));
        assert_eq!(ew_code("EW_NOTHING"), None);
    }
}
