//! Names for what crosses the wire: which FOCAS functions send a command,
//! and the `EW_*` name of a result code. Read by the simulator's trace and
//! fault injection (a fault can name a function instead of a command).
//!
//! The functions described as data (src/spec/table/) name their own
//! commands; [`COMMANDS`] lists the hand-written ones. A command several
//! functions send (0x0026 positions: `cnc_absolute`, `cnc_rddynamic2` ...)
//! lists them all, the one that sends it alone first.

use super::packet::{CLASS_CNC, CLASS_PMC, ReqSub};
use crate::spec::Word;

/// (subpacket class, command, the functions sending it, space-separated).
pub const COMMANDS: &[(u16, u16, &str)] = &[
    (CLASS_CNC, 0x0006, "cnc_rdprogdir cnc_rdprogdir3"),
    (CLASS_CNC, 0x0008, "cnc_rdtofs cnc_rdtofsr"),
    (CLASS_CNC, 0x0009, "cnc_wrtofs"),
    (CLASS_CNC, 0x000b, "cnc_rdzofs cnc_rdzofsr"),
    (CLASS_CNC, 0x000c, "cnc_wrzofs"),
    (CLASS_CNC, 0x000e, "cnc_rdparam cnc_rdparar cnc_rdparam_ext"),
    (CLASS_CNC, 0x000f, "cnc_wrparam cnc_wrparas"),
    (
        CLASS_CNC,
        0x0010,
        "cnc_rdparainfo cnc_wrparam cnc_rdparam_ext",
    ),
    (CLASS_CNC, 0x0011, "cnc_rdparanum"),
    (CLASS_CNC, 0x0015, "cnc_rdmacro cnc_rdmacror"),
    (CLASS_CNC, 0x0016, "cnc_wrmacro cnc_wrmacror"),
    (CLASS_CNC, 0x0018, "cnc_sysinfo cnc_allclibhndl3"),
    (CLASS_CNC, 0x0019, "cnc_statinfo"),
    (
        CLASS_CNC,
        0x001a,
        "cnc_alarm cnc_alarm2 cnc_rddynamic2 cnc_rddynamic",
    ),
    (CLASS_CNC, 0x001b, "cnc_getfigure"),
    (
        CLASS_CNC,
        0x001c,
        "cnc_rdprgnum cnc_rddynamic2 cnc_rddynamic",
    ),
    (
        CLASS_CNC,
        0x001d,
        "cnc_rdseqnum cnc_rddynamic2 cnc_rddynamic",
    ),
    (CLASS_CNC, 0x0020, "cnc_rdexecprog"),
    (CLASS_CNC, 0x0021, "cnc_modal"),
    (CLASS_CNC, 0x0022, "cnc_modal"),
    (
        CLASS_CNC,
        0x0023,
        "cnc_rdalmmsg cnc_rdalmmsg2 cnc_rdalminfo",
    ),
    (
        CLASS_CNC,
        0x0024,
        "cnc_actf cnc_rddynamic2 cnc_rddynamic cnc_rdspeed",
    ),
    (
        CLASS_CNC,
        0x0025,
        "cnc_acts cnc_rddynamic2 cnc_rddynamic cnc_rdspeed",
    ),
    (
        CLASS_CNC,
        0x0026,
        "cnc_absolute cnc_absolute2 cnc_machine cnc_relative cnc_relative2 cnc_distance \
         cnc_rddynamic2 cnc_rddynamic cnc_rdposition cnc_rdaxisdata",
    ),
    (CLASS_CNC, 0x0030, "cnc_diagnoss cnc_rddiag cnc_rddiag_ext"),
    (CLASS_CNC, 0x0031, "cnc_rddiaginfo cnc_rddiag_ext"),
    (CLASS_CNC, 0x0032, "cnc_rddiagnum"),
    (CLASS_CNC, 0x0034, "cnc_rdopmsg"),
    (
        CLASS_CNC,
        0x0040,
        "cnc_acts2 cnc_rdspmeter cnc_rdspload cnc_rdspmaxrpm cnc_rdspgear cnc_rdaxisdata",
    ),
    (CLASS_CNC, 0x0045, "cnc_gettimer"),
    (CLASS_CNC, 0x0046, "cnc_settimer"),
    (CLASS_CNC, 0x004d, "cnc_rdtoolgrp"),
    (CLASS_CNC, 0x0056, "cnc_rdsvmeter cnc_rdaxisdata"),
    (CLASS_CNC, 0x0057, "cnc_rdopmode"),
    (CLASS_CNC, 0x006b, "cnc_rdalmhisno"),
    (CLASS_CNC, 0x006c, "cnc_rdalmhistry cnc_rdalmhistry2"),
    (
        CLASS_CNC,
        0x0088,
        "cnc_rdposition cnc_rdspeed cnc_rdaxisdata cnc_rdsvmeter cnc_rdspmeter",
    ),
    (
        CLASS_CNC,
        0x0089,
        "cnc_rdaxisname cnc_rdposition cnc_rdsvmeter",
    ),
    (
        CLASS_CNC,
        0x008a,
        "cnc_rdspdlname cnc_rdspmeter cnc_rdspeed",
    ),
    (CLASS_CNC, 0x008b, "cnc_rdtoolgrp"),
    (CLASS_CNC, 0x008c, "cnc_allclibhndl3 cnc_rdposition"),
    (
        CLASS_CNC,
        0x008d,
        "cnc_rdparam cnc_rdparam_ext cnc_rdparar cnc_allclibhndl3",
    ),
    (CLASS_CNC, 0x008e, "cnc_wrparam cnc_wrparas"),
    (CLASS_CNC, 0x008f, "cnc_rdparainfo cnc_rdparam_ext"),
    (CLASS_CNC, 0x0093, "cnc_diagnoss cnc_rddiag cnc_rddiag_ext"),
    (CLASS_CNC, 0x0094, "cnc_rddiaginfo cnc_rddiag_ext"),
    (CLASS_CNC, 0x0095, "cnc_rdspeed"),
    (CLASS_CNC, 0x0098, "cnc_statinfo cnc_statinfo2"),
    (CLASS_CNC, 0x009a, "cnc_rdtlctldata"),
    (CLASS_CNC, 0x00a0, "cnc_wrparam cnc_rdparam_ext"),
    (CLASS_CNC, 0x00a2, "cnc_rddiag_ext"),
    (CLASS_CNC, 0x00a3, "cnc_rdaxisdata"),
    (
        CLASS_CNC,
        0x00a4,
        "cnc_acts2 cnc_rdaxisdata cnc_rdsvmeter cnc_rdspmeter cnc_rdposition",
    ),
    (CLASS_CNC, 0x00a5, "cnc_rdaxisdata"),
    (CLASS_CNC, 0x00a7, "cnc_rdmacror2"),
    (CLASS_CNC, 0x00a8, "cnc_wrmacror2"),
    (CLASS_CNC, 0x00cf, "cnc_exeprgname"),
    (CLASS_CNC, 0x00e1, "cnc_statinfo cnc_statinfo2"),
    (CLASS_CNC, 0x00e2, "cnc_statinfo2"),
    (CLASS_CNC, 0x00e8, "cnc_rdcncid"),
    (CLASS_CNC, 0x00fc, "cnc_exeprgname2"),
    (CLASS_PMC, 0x8001, "pmc_rdpmcrng"),
    (CLASS_PMC, 0x8002, "pmc_wrpmcrng"),
    (CLASS_PMC, 0x8003, "pmc_rdpmcinfo"),
    (CLASS_PMC, 0x800b, "pmc_rdpmctitle"),
    (CLASS_PMC, 0x8010, "pmc_rdalmmsg"),
    (CLASS_PMC, 0x804a, "pmc_get_timer_type"),
    (CLASS_PMC, 0x804b, "pmc_set_timer_type"),
];

/// The function a request subpacket stands for, as a trace names it: a
/// described function whose form on this CNC class (`s16`, `s15`) is this
/// command with these constant words, else the first of [`COMMANDS`].
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
    COMMANDS
        .iter()
        .filter(move |(c, k, _)| *c == class && *k == cmd)
        .flat_map(|(_, _, names)| names.split_whitespace())
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
                            Word::Arg(_) | Word::Asked => true,
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
            .filter(|(_, _, names)| {
                let mut it = names.split_whitespace();
                let all: Vec<&str> = names.split_whitespace().collect();
                all.contains(&name)
                    && (!only || all.len() == 1)
                    && (!first || it.next() == Some(name))
            })
            .map(|(c, k, _)| (*c, *k))
            .collect()
    };
    let mut out = listed(true, false);
    if out.is_empty() {
        out = listed(false, true);
    }
    if out.is_empty() {
        out = listed(false, false);
    }
    if let Some(f) = crate::spec::find(name) {
        for form in f.forms {
            if !out.contains(&(form.class, form.cmd)) {
                out.push((form.class, form.cmd));
            }
        }
    }
    out
}

/// `EW_*` names of the codes a CNC answers or the library returns (the
/// first name where FANUC's header gives a code two).
const EW_NAMES: &[(i16, &str)] = &[
    (-17, "EW_PROTOCOL"),
    (-16, "EW_SOCKET"),
    (-15, "EW_NODLL"),
    (-8, "EW_HANDLE"),
    (-7, "EW_VERSION"),
    (-6, "EW_UNEXP"),
    (-5, "EW_SYSTEM"),
    (-2, "EW_RESET"),
    (-1, "EW_BUSY"),
    (0, "EW_OK"),
    (1, "EW_FUNC"),
    (2, "EW_LENGTH"),
    (3, "EW_NUMBER"),
    (4, "EW_ATTRIB"),
    (5, "EW_DATA"),
    (6, "EW_NOOPT"),
    (7, "EW_PROT"),
    (8, "EW_OVRFLOW"),
    (9, "EW_PARAM"),
    (10, "EW_BUFFER"),
    (11, "EW_PATH"),
    (12, "EW_MODE"),
    (13, "EW_REJECT"),
    (14, "EW_DTSRVR"),
    (15, "EW_ALARM"),
    (16, "EW_STOP"),
    (17, "EW_PASSWD"),
    (18, "EW_PMC"),
    (19, "EW_PMCHANDLE"),
];

/// The `EW_*` name of `code`, if it has one here.
pub fn ew_name(code: i16) -> Option<&'static str> {
    EW_NAMES.iter().find(|(c, _)| *c == code).map(|(_, n)| *n)
}

/// The code named `name` (`"EW_NOOPT"`, or without the prefix: `"noopt"`).
pub fn ew_code(name: &str) -> Option<i16> {
    let up = name.trim().to_ascii_uppercase();
    let full = if up.starts_with("EW_") {
        up
    } else {
        format!("EW_{up}")
    };
    EW_NAMES.iter().find(|(_, n)| *n == full).map(|(c, _)| *c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_exported_data_function_in_the_table_is_known() {
        for (_, _, names) in COMMANDS {
            for n in names.split_whitespace() {
                assert!(n.starts_with("cnc_") || n.starts_with("pmc_"), "{n}");
            }
        }
        assert_eq!(function_commands("cnc_statinfo"), vec![(CLASS_CNC, 0x0019)]);
        assert_eq!(
            function_commands("cnc_statinfo2"),
            vec![(CLASS_CNC, 0x00e2)]
        );
        assert_eq!(
            function_commands("cnc_rdparam"),
            vec![(CLASS_CNC, 0x000e), (CLASS_CNC, 0x008d)]
        );
        assert_eq!(function_commands("cnc_rddynamic2").len(), 6);
        assert_eq!(function_commands("pmc_rdpmcrng"), vec![(CLASS_PMC, 0x8001)]);
        assert_eq!(function_commands("pmc_rdalmmsg"), vec![(CLASS_PMC, 0x8010)]);
        assert_eq!(
            function_commands("cnc_wrpm_item"),
            vec![(CLASS_CNC, 0x00bf)]
        );
        assert_eq!(function_commands("cnc_rdtimer"), vec![(CLASS_CNC, 0x0120)]);
        assert!(function_commands("cnc_nothing").is_empty());
    }

    #[test]
    fn requests_are_named_by_their_command_and_constant_words() {
        let s = ReqSub::cnc(0x0019, &[]);
        assert_eq!(request_name(&s, false, false), Some("cnc_statinfo"));
        let s = ReqSub::cnc(0x0120, &[1]);
        assert_eq!(request_name(&s, false, false), Some("cnc_rdtimer"));
        assert_eq!(
            command_name(CLASS_CNC, 0x008d, false, false),
            Some("cnc_rdparam")
        );
        assert_eq!(command_name(CLASS_CNC, 0x7777, false, false), None);
    }

    #[test]
    fn codes_by_name() {
        assert_eq!(ew_code("EW_NOOPT"), Some(6));
        assert_eq!(ew_code("busy"), Some(-1));
        assert_eq!(ew_name(-16), Some("EW_SOCKET"));
        assert_eq!(ew_code("EW_NOTHING"), None);
    }
}
