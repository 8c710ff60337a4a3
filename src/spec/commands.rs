//! The command registry: every command of the wire, once. A data request
//! subpacket is a class (1 CNC, 2 PMC), a command number and five argument
//! words; this file names each (class, command) the codec sends or the
//! simulator answers, and the FOCAS functions that send it (the one that
//! sends it alone first, then the others).
//!
//! Everything else names a command by its constant here: the codec's
//! requests (src/proto), the table's forms (src/spec/table), the
//! simulator's dispatch, the trace's names and the faults that name a
//! function (src/proto/names.rs). A test asserts no other source file
//! writes a command number.
//!
//! Compiled into build.rs too (`#[path]`, with the table): plain data only,
//! no `crate::` paths outside the tests.

/// Subpacket class word: the CNC (the handle's path).
pub const CLASS_CNC: u16 = 1;
/// Subpacket class word: the PMC (path 1).
pub const CLASS_PMC: u16 = 2;

/// One command: its subpacket class, number, Rust name and the functions
/// that send it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Command {
    pub class: u16,
    pub cmd: u16,
    /// The constant's name (`STATINFO`).
    pub name: &'static str,
    /// The FOCAS functions sending it: the one that sends it alone first.
    pub senders: &'static [&'static str],
}

/// The command `cmd` of subpacket class `class`.
pub fn find(class: u16, cmd: u16) -> Option<&'static Command> {
    COMMANDS.iter().find(|c| c.class == class && c.cmd == cmd)
}

/// `NAME = CLASS NUMBER [senders];` once per command: a `pub const NAME:
/// u16` each, and [`COMMANDS`].
macro_rules! commands {
    ($($(#[$m:meta])* $name:ident = $class:ident $cmd:literal [$($f:ident)+];)*) => {
        $($(#[$m])* pub const $name: u16 = $cmd;)*
        /// Every command, CNC class by number, then PMC class.
        pub const COMMANDS: &[Command] = &[$(Command {
            class: $class,
            cmd: $cmd,
            name: stringify!($name),
            senders: &[$(stringify!($f)),+],
        },)*];
    };
}

commands! {
    START = CLASS_CNC 0x0001 [cnc_start];
    RESET = CLASS_CNC 0x0002 [cnc_reset];
    SEARCH = CLASS_CNC 0x0003 [cnc_search cnc_searcho8];
    DELALL = CLASS_CNC 0x0004 [cnc_delall];
    DELETE = CLASS_CNC 0x0005 [cnc_delete cnc_deleteo8];
    /// (1,0x0006)[top, count, code]: program directory records (cnc_rdprogdir,
    /// cnc_rdprogdir3).
    RDPROGDIR = CLASS_CNC 0x0006 [cnc_rdprogdir cnc_rdprogdir3];
    /// cnc_rdproginfo: `ProgInfo`.
    RDPROGINFO = CLASS_CNC 0x0007 [cnc_rdproginfo];
    /// Read tool offsets: args [s, e, type]; cnc_rdtofs sends [n, n, 1000 + type].
    RDTOFS = CLASS_CNC 0x0008 [cnc_rdtofs cnc_rdtofsr];
    /// Write one tool offset: args [n, n, 1000 + type, 0, 8] + one record.
    WRTOFS = CLASS_CNC 0x0009 [cnc_wrtofs];
    RDTOFSINFO = CLASS_CNC 0x000a [cnc_rdtofsinfo cnc_rdtofsinfo2];
    /// Read work zero offsets: args [s, e, axis].
    RDZOFS = CLASS_CNC 0x000b [cnc_rdzofs cnc_rdzofsr];
    /// Write one work zero offset: args [n, n, axis, 0, 8 · records] + records.
    WRZOFS = CLASS_CNC 0x000c [cnc_wrzofs];
    RDZOFSINFO = CLASS_CNC 0x000d [cnc_rdzofsinfo];
    /// 16i class: read parameter (also the FOCAS option probe, parameter 9968).
    RDPARAM16 = CLASS_CNC 0x000e [cnc_rdparam cnc_rdparam3 cnc_rdparar cnc_rdparam_ext cnc_sdtsetchnl];
    /// 16i: write one parameter, 40-byte payload.
    WRPARAM16 = CLASS_CNC 0x000f [cnc_wrparam cnc_wrparas];
    /// Both classes: parameter numbers and attributes [s, n] (cnc_rdparainfo;
    /// the 16i cnc_wrparam reads one entry of it first).
    RDPARAINFO = CLASS_CNC 0x0010 [cnc_rdparainfo cnc_wrparam cnc_rdparam_ext cnc_wrset];
    /// cnc_rdparanum: smallest, largest and count of parameter numbers.
    RDPARANUM = CLASS_CNC 0x0011 [cnc_rdparanum];
    RDPITCHR = CLASS_CNC 0x0012 [cnc_rdpitchr];
    RDPITCHINFO = CLASS_CNC 0x0014 [cnc_rdpitchinfo];
    /// Read custom macro variables s..e: args (s, e); payload: one record each.
    RDMACRO = CLASS_CNC 0x0015 [cnc_rdmacro cnc_rdmacror];
    /// Write custom macro variables: args (s, e, 0, 0, payload length) + records.
    WRMACRO = CLASS_CNC 0x0016 [cnc_wrmacro cnc_wrmacror];
    RDMACROINFO = CLASS_CNC 0x0017 [cnc_rdmacroinfo];
    /// cnc_rdsetnum: (1,0x002c) the setting data's smallest and largest
    /// numbers and how many there are.
    RDSETNUM = CLASS_CNC 0x002c [cnc_rdsetnum];
    /// 16i class: read setting data [s, e, axis] (cnc_rdparam's 0x000e
    /// answer: a typed parameter block).
    RDSET16 = CLASS_CNC 0x0029 [cnc_rdset cnc_rdsetr];
    /// 16i class: write one setting data block (cnc_wrparam's 0x000f block).
    WRSET16 = CLASS_CNC 0x002a [cnc_wrset];
    /// 30i class and Series 15: read setting data [s, e, axis] (cnc_rdparam's
    /// 0x008d answer).
    RDSET = CLASS_CNC 0x0090 [cnc_rdset cnc_rdsetr];
    /// 30i class and Series 15: write one setting data block (cnc_wrparam's
    /// 0x008e block).
    WRSET = CLASS_CNC 0x0091 [cnc_wrset];
    SYSINFO = CLASS_CNC 0x0018 [cnc_sysinfo cnc_allclibhndl3];
    STATINFO = CLASS_CNC 0x0019 [cnc_statinfo];
    /// Alarm status bits (cnc_alarm, cnc_alarm2, rddynamic2 `alarm`).
    ALARM = CLASS_CNC 0x001a [cnc_alarm cnc_alarm2 cnc_rddynamic2 cnc_rddynamic];
    /// Input/output figures per axis (cnc_getfigure).
    GETFIGURE = CLASS_CNC 0x001b [cnc_getfigure];
    /// Running and main program numbers (cnc_rdprgnum, rddynamic2).
    PRGNUM = CLASS_CNC 0x001c [cnc_rdprgnum cnc_rdprgnumo8 cnc_rddynamic2 cnc_rddynamic];
    /// Sequence number (cnc_rdseqnum, rddynamic2).
    SEQNUM = CLASS_CNC 0x001d [cnc_rdseqnum cnc_rddynamic2 cnc_rddynamic];
    RDEXECPROG = CLASS_CNC 0x0020 [cnc_rdexecprog];
    MODAL_G = CLASS_CNC 0x0021 [cnc_modal];
    MODAL_AUX = CLASS_CNC 0x0022 [cnc_modal];
    RDALMMSG = CLASS_CNC 0x0023 [cnc_rdalmmsg cnc_rdalmmsg2 cnc_rdalminfo];
    /// Actual feed rate: one value record.
    ACTF = CLASS_CNC 0x0024 [cnc_actf cnc_rddynamic2 cnc_rddynamic cnc_rdspeed];
    /// Actual spindle speed: one value record.
    ACTS = CLASS_CNC 0x0025 [cnc_acts cnc_rddynamic2 cnc_rddynamic cnc_rdspeed];
    /// Axis positions: args [type code, axis]; value records.
    POSITION = CLASS_CNC 0x0026 [cnc_absolute cnc_absolute2 cnc_machine cnc_relative
        cnc_relative2 cnc_distance cnc_skip cnc_srvdelay cnc_accdecdly cnc_rddynamic2
        cnc_rddynamic cnc_rdposition cnc_rdaxisdata cnc_rdprstrinfo];
    /// cnc_rdpmacroinfo: (1,0x002f) the P-code macro variables' counts and type.
    RDPMACROINFO = CLASS_CNC 0x002f [cnc_rdpmacroinfo];
    /// cnc_rdpmacro: (1,0x002d)[s, e] P-code macro variables s..e, one
    /// value record each.
    RDPMACRO = CLASS_CNC 0x002d [cnc_rdpmacro cnc_rdpmacror];
    /// cnc_wrpmacro: (1,0x002e)[s, e, 0, 0, 8] + one value record per
    /// variable s..e.
    WRPMACRO = CLASS_CNC 0x002e [cnc_wrpmacro cnc_wrpmacror];
    /// cnc_rdpmacroinfo2: (1,0x00e7) the P-code macro variables' counts
    /// and types (three ranges).
    RDPMACROINFO2 = CLASS_CNC 0x00e7 [cnc_rdpmacroinfo2];
    /// FANUC's cnc_rdpmacror on the 16i class from #100000 (and on the
    /// 30i class after some 0x00e7 answers): (1,0x012c)[s, s + 715] before
    /// 0x002d, which follows on error 1; its answer's form is not known
    /// (not sent by ours; docs/protocol/macro.md).
    RDPMACRO2 = CLASS_CNC 0x012c [cnc_rdpmacror];
    /// FANUC's cnc_wrpmacror likewise: (1,0x012d)[s, e, 0, 0, 10] + 10
    /// bytes before 0x002e (not sent by ours).
    WRPMACRO2 = CLASS_CNC 0x012d [cnc_wrpmacror];
    /// cnc_rdmacronum: (1,0x029f)[length, 0, 0, 0, length] + the name's
    /// `length` bytes; the answer: u32 number, i16 attribute.
    RDMACRONUM = CLASS_CNC 0x029f [cnc_rdmacronum];
    /// 16i: read diagnosis data [s, e, axis].
    DIAGNOSS16 = CLASS_CNC 0x0030 [cnc_diagnoss cnc_rddiag cnc_rddiag_ext cnc_sdtsetchnl];
    /// Both classes: diagnosis numbers and attributes [s, n].
    RDDIAGINFO = CLASS_CNC 0x0031 [cnc_rddiaginfo cnc_rddiag_ext];
    /// cnc_rddiagnum: the same for diagnosis data.
    RDDIAGNUM = CLASS_CNC 0x0032 [cnc_rddiagnum];
    RDOPMSG = CLASS_CNC 0x0034 [cnc_rdopmsg cnc_rdopmsg3];
    RDBLKCOUNT = CLASS_CNC 0x0035 [cnc_rdblkcount];
    /// cnc_rdmdiprog (answer: the MDI program's text) and cnc_wrmdiprog (the
    /// text as the request's payload).
    RDMDIPROG = CLASS_CNC 0x0036 [cnc_rdmdiprog];
    WRMDIPROG = CLASS_CNC 0x0037 [cnc_wrmdiprog];
    RDMDIPNTR = CLASS_CNC 0x0038 [cnc_rdmdipntr cnc_rdmdipntro8];
    WRMDIPNTR = CLASS_CNC 0x0039 [cnc_wrmdipntr];
    /// Spindle data: args [code, spindle]; value records.
    SPINDLE = CLASS_CNC 0x0040 [cnc_acts2 cnc_rdspmeter cnc_rdspload cnc_rdspmaxrpm cnc_rdspgear
        cnc_rdaxisdata];
    /// cnc_rdsyssoft / cnc_rdsyssoft2: no arguments; a fixed answer of
    /// slot tables, IDs and 4-character series/versions (docs/protocol/machine.md).
    RDSYSSOFT = CLASS_CNC 0x0041 [cnc_rdsyssoft cnc_rdsyssoft2];
    /// cnc_rdprstrinfo: (1,0x0043)\[k\] for k 0..4 (block counter, M, T, S and
    /// B codes), then the position command 0x0026 [13, -1] (restart position)
    /// and [14, -1] (distance to it), in one frame.
    RDPRSTR = CLASS_CNC 0x0043 [cnc_rdprstrinfo];
    GETTIMER = CLASS_CNC 0x0045 [cnc_gettimer];
    SETTIMER = CLASS_CNC 0x0046 [cnc_settimer];
    RDGRPID2 = CLASS_CNC 0x0047 [cnc_rdgrpid2 cnc_rdgrpid];
    /// cnc_rdtlusegrp: the next, in-use and selected groups (no args).
    TLUSEGRP = CLASS_CNC 0x0048 [cnc_rdtlusegrp cnc_rdusegrpid];
    /// (1,0x004a): the number of tool life groups; on the 16i class with
    /// `[0, 0, 0, 0, 0x10000]`, cnc_rdtlinfo's limits after it.
    /// cnc_rdmaxgrp and cnc_rdmaxtool (no args) read the second and third word.
    RDNGRP = CLASS_CNC 0x004a [cnc_rdngrp cnc_rdtlinfo cnc_rdmaxgrp cnc_rdmaxtool];
    /// cnc_wrgrpinfo: args [s, e, 0, 0, payload length] + one
    /// `GroupWrite` per group s..=e.
    WRGRPINFO = CLASS_CNC 0x004c [cnc_wrgrpinfo];
    /// Tools of a group: args [grp, s, e] (cnc_toolnum: [grp, n, n]).
    /// cnc_rd2tlifedata: [grp, n, n], the group, n and tool n's record.
    TLTOOLS = CLASS_CNC 0x004d [cnc_rdtoolgrp cnc_toolnum cnc_rd2tlifedata cnc_rd2length cnc_rd2radius cnc_t2info
        cnc_rdtltool];
    /// cnc_rd1tlifedata: (1,0x004f)[grp, n]: the group, tool n's number, a
    /// word it does not read, its H and D codes and information.
    RD1TLIFEDATA = CLASS_CNC 0x004f [cnc_rd1tlifedata cnc_rd1length cnc_rd1radius cnc_t1info cnc_rd1tlifedat2];
    // Tool offsets, family B (issue 24).
    /// The B-axis tool offsets: memory type, number, cancel sub function.
    RDBTOFSINFO = CLASS_CNC 0x007e [cnc_rdbtofsinfo];
    /// The cutter compensation mode, plane axes and vector.
    RDRADOFS = CLASS_CNC 0x0117 [cnc_rdradofs];
    /// The 3-D tool offset mode, axes and vector.
    RD3DTOFS = CLASS_CNC 0x011e [cnc_rd3dtofs];
    /// The work zero point measurement's TL value and its decimals.
    RDTLDATA = CLASS_CNC 0x0191 [cnc_rdtldata];
    /// The tool length measurement: T, M, the measured value, offset number.
    RDTLMSINFO = CLASS_CNC 0x0194 [cnc_rdtlmsinfo];
    /// Whether `[MEASURE]` / `[MEASURE+]` (tool offset measurement) can be used.
    RDTOFSENBL = CLASS_CNC 0x0195 [cnc_rdtofsenbl];
    /// `[type]`: clears every tool offset of a type.
    CLRTOFS = CLASS_CNC 0x01b7 [cnc_clrtofs];
    DELTLIFEGRP = CLASS_CNC 0x0053 [cnc_deltlifegrp];
    /// Inserts a tool into a group: args [grp, tuse_num, tool number].
    TLINSERT = CLASS_CNC 0x0054 [cnc_instlifedt];
    DELTLIFEDT = CLASS_CNC 0x0055 [cnc_deltlifedt];
    /// Servo load meter: args \[1\]; value records.
    SERVO_LOAD = CLASS_CNC 0x0056 [cnc_rdsvmeter cnc_rdaxisdata cnc_rdloopgain cnc_rdsrvspeed
        cnc_rdcurrent];
    RDOPMODE = CLASS_CNC 0x0057 [cnc_rdopmode];
    /// Position deviations: \[0\] each spindle's (value records), \[1\]
    /// and \[2\] spindle 1's and 2's (cnc_rdposerrs2 sends both in one
    /// request), \[3\] the Z axis's in rigid tapping.
    POSERR = CLASS_CNC 0x0058 [cnc_rdposerrs cnc_rdposerrs2 cnc_rdposerrz];
    RDSPDLALM = CLASS_CNC 0x005a [cnc_rdspdlalm];
    /// cnc_rdctrldi / cnc_rdctrldo: (1,0x005b)\[0\] input signals, \[1\] output.
    RDCTRLSIG = CLASS_CNC 0x005b [cnc_rdctrldi cnc_rdctrldo];
    /// cnc_rdopnlsgnl: (1,0x005d)\[type\] the software operator panel's signals.
    RDOPNLSGNL = CLASS_CNC 0x005d [cnc_rdopnlsgnl];
    /// cnc_wropnlsgnl: (1,0x005e)\[type, 0, 0, 0, 26\] + the 13 signal
    /// words: writes the software operator panel's signals `type` selects.
    WROPNLSGNL = CLASS_CNC 0x005e [cnc_wropnlsgnl];
    /// cnc_rdopnlgnrl: (1,0x005f)\[type\] the panel's general purpose switches.
    RDOPNLGNRL = CLASS_CNC 0x005f [cnc_rdopnlgnrl cnc_rdopnlgnrl2];
    /// cnc_wropnlgnrl: (1,0x0060)\[type & 0xff, 0, 0, 0, 2\] + 0, sgnal.
    WROPNLGNRL = CLASS_CNC 0x0060 [cnc_wropnlgnrl cnc_wropnlgnrl2];
    /// cnc_rdopnlgsname: (1,0x0061)\[type & 0xff\] the general purpose
    /// switches' names, 8 bytes each.
    RDOPNLGSNAME = CLASS_CNC 0x0061 [cnc_rdopnlgsname cnc_rdopnlgsname2];
    /// cnc_wropnlgsname: (1,0x0062)\[type & 0xff, 0, 0, 0, 64\] + 8 names.
    WROPNLGSNAME = CLASS_CNC 0x0062 [cnc_wropnlgsname cnc_wropnlgsname2];
    RDWKCDSHFT = CLASS_CNC 0x0063 [cnc_rdwkcdshft];
    WRWKCDSHFT = CLASS_CNC 0x0064 [cnc_wrwkcdshft];
    STOPOPHIS = CLASS_CNC 0x0067 [cnc_stopophis];
    STARTOPHIS = CLASS_CNC 0x0068 [cnc_startophis];
    RDOPHISNO = CLASS_CNC 0x0069 [cnc_rdophisno];
    RDOPHISTRY = CLASS_CNC 0x006a [cnc_rdophistry];
    /// Number of alarm history entries: one i32 (FANUC keeps its low 16 bits).
    RDALMHISNO = CLASS_CNC 0x006b [cnc_rdalmhisno];
    /// Read the alarm history: args [s, e, 1] (SPEC.md §5.2).
    RDALMHISTRY = CLASS_CNC 0x006c [cnc_rdalmhistry cnc_rdalmhistry2];
    CLEAROPHIS = CLASS_CNC 0x006d [cnc_clearophis];
    STOPOMHIS = CLASS_CNC 0x0070 [cnc_stopomhis];
    STARTOMHIS = CLASS_CNC 0x0071 [cnc_startomhis];
    RDOMHISINFO = CLASS_CNC 0x0072 [cnc_rdomhisinfo];
    RDOMHISTRY = CLASS_CNC 0x0073 [cnc_rdomhistry];
    CLEAROMHIS = CLASS_CNC 0x0074 [cnc_clearomhis];
    RDPROCTIME = CLASS_CNC 0x0075 [cnc_rdproctime];
    CLRALM = CLASS_CNC 0x0087 [cnc_clralm];
    /// Unit words: args \[1\] positions, \[2\] machine positions, \[3\]/\[4\] speeds.
    UNITS = CLASS_CNC 0x0088 [cnc_rdposition cnc_rdspeed cnc_rdaxisdata cnc_rdsvmeter
        cnc_rdspmeter];
    /// Axis names: args \[0\] 4 bytes per axis; [-1] i32 count + 16 bytes per axis.
    RDAXISNAME = CLASS_CNC 0x0089 [cnc_rdaxisname cnc_rdposition cnc_rdsvmeter];
    /// Spindle names: 4 bytes per spindle.
    RDSPDLNAME = CLASS_CNC 0x008a [cnc_rdspdlname cnc_rdspmeter cnc_rdspeed];
    /// Tool life group record: args [grp, grp].
    TLGROUP = CLASS_CNC 0x008b [cnc_rdtoolgrp cnc_rdgrpinfo cnc_rdtlusegrp cnc_rdntool
        cnc_rdlife cnc_rdcount cnc_rdtoolrng];
    /// Series 15 start-up companion of sysinfo.
    SYSINFO15 = CLASS_CNC 0x008c [cnc_allclibhndl3 cnc_rdposition];
    /// 30i class: read parameter (Series 15: option probe, parameter 9153).
    RDPARAM = CLASS_CNC 0x008d [cnc_rdparam cnc_rdparam3 cnc_rdparam_ext cnc_rdparar cnc_allclibhndl3 cnc_sdtsetchnl];
    /// 30i: write one parameter, 264-byte payload.
    WRPARAM = CLASS_CNC 0x008e [cnc_wrparam cnc_wrparas];
    /// Series 15: parameter numbers and attributes [s, n] (cnc_rdparainfo).
    RDPARAINFO15 = CLASS_CNC 0x008f [cnc_rdparainfo cnc_rdparam_ext];
    /// 30i: read diagnosis data [s, e, axis].
    DIAGNOSS = CLASS_CNC 0x0093 [cnc_diagnoss cnc_rddiag cnc_rddiag_ext cnc_sdtsetchnl];
    /// Series 15: diagnosis numbers and attributes [s, n] (cnc_rddiaginfo).
    RDDIAGINFO15 = CLASS_CNC 0x0094 [cnc_rddiaginfo cnc_rddiag_ext];
    /// Series 15: which spindle's name is shown with the speed (1-based; its
    /// entry of 0x8a names the actual speed).
    SPINDLE_SHOWN15 = CLASS_CNC 0x0095 [cnc_rdspeed];
    /// cnc_rdcommand: (1,0x0097)[type, block], records of the commanded
    /// values (address, number, flag, value, decimals).
    RDCOMMAND = CLASS_CNC 0x0097 [cnc_rdcommand];
    TMMODE = CLASS_CNC 0x0098 [cnc_statinfo cnc_statinfo2];
    /// cnc_rdtoolinfo (punch press): no args.
    PTLINFO = CLASS_CNC 0x0099 [cnc_rdtoolinfo];
    /// Punch press tool control data (no args).
    TLCTL = CLASS_CNC 0x009a [cnc_rdtlctldata];
    /// cnc_rdtooldata (punch press): args [0, tool_no, n].
    PTLDATA = CLASS_CNC 0x009c [cnc_rdtooldata];
    /// 30i: the attribute record of one parameter [number, 1] (28 bytes).
    PARAMTYPE = CLASS_CNC 0x00a0 [cnc_wrparam cnc_rdparam_ext cnc_wrset];
    /// 30i: the attribute record of one diagnosis item [number, 1] (28 bytes).
    DIAGTYPE = CLASS_CNC 0x00a2 [cnc_rddiag_ext];
    /// Display flags per axis (u32).
    AXIS_FLAGS = CLASS_CNC 0x00a3 [cnc_rdaxisdata];
    /// Counts: args \[0\] axes, \[1\] spindles, \[2\] servo axes, \[3\] speed display.
    COUNT = CLASS_CNC 0x00a4 [cnc_acts2 cnc_rdaxisdata cnc_rdsvmeter cnc_rdspmeter cnc_rdposition
        cnc_rdnspdl cnc_axisnum];
    /// cnc_rdaxisdata class 5 type 2: a third speed-class value record (its
    /// meaning is not known; FANUC's library names it 'F' and takes its unit
    /// from 0x88\[4\]).
    SPEED_A5 = CLASS_CNC 0x00a5 [cnc_rdaxisdata];
    /// cnc_rdmacror2: (1,0x00a7)[s, n], payload n IEEE doubles big-endian.
    RDMACROR2 = CLASS_CNC 0x00a7 [cnc_rdmacror2];
    /// cnc_wrmacror2: (1,0x00a8)[s, 0, 0, 0, 8n] + n doubles; reply i32 count.
    WRMACROR2 = CLASS_CNC 0x00a8 [cnc_wrmacror2];
    /// cnc_rdpmacror2: (1,0x00a9)[s, n, type], payload n IEEE doubles
    /// big-endian (FANUC's library: cnc_rdmacror2's routine).
    RDPMACROR2 = CLASS_CNC 0x00a9 [cnc_rdpmacror2];
    /// cnc_wrpmacror2: (1,0x00aa)[s, 0, type, 0, 8n] + n doubles; reply
    /// i32 count (cnc_wrmacror2's routine).
    WRPMACROR2 = CLASS_CNC 0x00aa [cnc_wrpmacror2];
    /// Program data folder commands (30i; src/ffi/folder.rs).
    PDF_DRIVE = CLASS_CNC 0x00ae [cnc_rdpdf_drive];
    PDF_INF = CLASS_CNC 0x00af [cnc_rdpdf_inf];
    PDF_RDCURDIR = CLASS_CNC 0x00b0 [cnc_rdpdf_curdir];
    PDF_WRCURDIR = CLASS_CNC 0x00b1 [cnc_wrpdf_curdir];
    PDF_SUBDIR = CLASS_CNC 0x00b2 [cnc_rdpdf_subdir];
    PDF_ALLDIR = CLASS_CNC 0x00b3 [cnc_rdpdf_alldir];
    PDF_SUBDIRN = CLASS_CNC 0x00b4 [cnc_rdpdf_subdirn];
    PDF_ADD = CLASS_CNC 0x00b5 [cnc_pdf_add];
    PDF_DEL = CLASS_CNC 0x00b6 [cnc_pdf_del];
    PDF_RENAME = CLASS_CNC 0x00b7 [cnc_pdf_rename];
    PDF_RDMAIN = CLASS_CNC 0x00b9 [cnc_pdf_rdmain];
    PDF_SLCTMAIN = CLASS_CNC 0x00ba [cnc_pdf_slctmain];
    /// cnc_rdpm_mcnitem: (1,0xbc)[start, n]; 62-byte names.
    RDPM_MCNITEM = CLASS_CNC 0x00bc [cnc_rdpm_mcnitem];
    /// cnc_wrpm_mcnitem: (1,0xbd)[start, 0, 0, 0, bytes] + 62-byte names.
    WRPM_MCNITEM = CLASS_CNC 0x00bd [cnc_wrpm_mcnitem];
    /// cnc_rdpm_item: (1,0xbe)[start, n]; 80-byte items.
    RDPM_ITEM = CLASS_CNC 0x00be [cnc_rdpm_item];
    /// cnc_wrpm_item: (1,0xbf)[reset, start, 0, 0, bytes] + 80-byte items.
    WRPM_ITEM = CLASS_CNC 0x00bf [cnc_wrpm_item];
    EXEPRGNAME = CLASS_CNC 0x00cf [cnc_exeprgname];
    /// cnc_rdopmsg3's command on the 30i class (the 16i class sends
    /// cnc_rdopmsg's 0x0034 \[type\]).
    RDOPMSG3 = CLASS_CNC 0x00d0 [cnc_rdopmsg3];
    /// cnc_rdpm_cncitem: (1,0xd3)[start, n]; 62-byte names.
    RDPM_CNCITEM = CLASS_CNC 0x00d3 [cnc_rdpm_cncitem];
    HDCK = CLASS_CNC 0x00e1 [cnc_statinfo cnc_statinfo2];
    STATINFO2 = CLASS_CNC 0x00e2 [cnc_statinfo2];
    RDCNCID = CLASS_CNC 0x00e8 [cnc_rdcncid];
    PDF_RDLINE = CLASS_CNC 0x00f0 [cnc_rdpdf_line];
    PDF_WRLINE = CLASS_CNC 0x00f1 [cnc_wrpdf_line];
    PDF_DELLINE = CLASS_CNC 0x00f2 [cnc_pdf_delline];
    PDF_DELALL = CLASS_CNC 0x00f3 [cnc_pdf_delall];
    EXEPRGNAME2 = CLASS_CNC 0x00fc [cnc_exeprgname2];
    /// `(1,0x0110)[k]`: the 3D handle's axes (i16 each), k 1 or 2; sent with
    /// `0x0111[k]`, twice, in one request.
    HDL3D_AXES = CLASS_CNC 0x0110 [cnc_rd3dtooltip];
    /// `(1,0x0111)[k]`: the 3D handle's tool tip, a value record per axis.
    HDL3D_TIP = CLASS_CNC 0x0111 [cnc_rd3dtooltip];
    RDTIMER = CLASS_CNC 0x0120 [cnc_rdtimer];
    /// cnc_wrtimer: `(1,0x0121)[type]`, payload the minutes and milliseconds (i32 each).
    WRTIMER = CLASS_CNC 0x0121 [cnc_wrtimer];
    /// Servo data sampling (FANUC's x86 build 1.0.0 exports the senders;
    /// docs/protocol/position.md): `(1,0x0133)[n, 0, 0, 0, 12·n]` + 12
    /// bytes a channel sets the channels (after each axis channel's
    /// parameter 1023 read).
    SDTSETCHNL = CLASS_CNC 0x0133 [cnc_sdtsetchnl];
    /// `(1,0x0134)` clears the channels.
    SDTCLRCHNL = CLASS_CNC 0x0134 [cnc_sdtclrchnl];
    /// `(1,0x0135)[type, long]` starts sampling the channels; the answer's
    /// fourth 16-bit word not 0 lets FANUC's library ask for samples.
    SDTSTARTSMPL = CLASS_CNC 0x0135 [cnc_sdtstartsmpl];
    /// `(1,0x0136)` cancels the sampling.
    SDTCANCELSMPL = CLASS_CNC 0x0136 [cnc_sdtcancelsmpl];
    /// `(1,0x0138)` ends the sampling.
    SDTENDSMPL = CLASS_CNC 0x0138 [cnc_sdtendsmpl];
    /// `(1,0x013a)`: the channels' current values, a u16 each (at most 8).
    SDTREAD1SHOT = CLASS_CNC 0x013a [cnc_sdtread1shot];
    /// cnc_rdtool: tool management data, args [top, n] (n at most
    /// `TOOLS_PER_MNG`).
    TLMNG = CLASS_CNC 0x014b [cnc_rdtool];
    /// cnc_wrmagazine: (1,0x0151)[magazine, pot, tool_index]: puts tool
    /// management data number tool_index in the pot (0: empties it).
    /// cnc_wrtool: (1,0x014c)[tool_no, 0, 0, 0, 156] + one tool management
    /// record, the 39 words cnc_rdtool's answer holds.
    WRTOOL = CLASS_CNC 0x014c [cnc_wrtool];
    WRMAGAZINE = CLASS_CNC 0x0151 [cnc_wrmagazine];
    /// cnc_regtool: (1,0x0149)[top + done, 0, 0, 0, len] + cnc_wrtool's
    /// 156-byte records, 9 per request; the answer's i32 the tools
    /// registered.
    REGTOOL = CLASS_CNC 0x0149 [cnc_regtool];
    /// cnc_regtool_f2: as cnc_regtool, records of 59 words (40 custom
    /// data), 6 per request.
    REGTOOL_F2 = CLASS_CNC 0x0185 [cnc_regtool_f2];
    /// cnc_regmagazine: (1,0x014e)[0, 0, 0, 0, len] + records i32
    /// magazine, pot, tool_index, 118 per request; the answer's i32 the
    /// records registered.
    REGMAGAZINE = CLASS_CNC 0x014e [cnc_regmagazine];
    /// cnc_delmagazine: (1,0x014f)[0, 0, 0, 0, len] + records i32
    /// magazine, pot, 177 per request; the answer's i32 the records deleted.
    DELMAGAZINE = CLASS_CNC 0x014f [cnc_delmagazine];
    /// cnc_rdmagazine: (1,0x0150)[0, 0, 0, 0, len] + records i32 magazine,
    /// pot, 0, 118 per request; the answer: i32 n, then n records i32
    /// magazine, pot, tool_index.
    RDMAGAZINE = CLASS_CNC 0x0150 [cnc_rdmagazine];
    RDSPCSS = CLASS_CNC 0x0158 [cnc_rdspcss];
    RDETHERINFO = CLASS_CNC 0x0159 [cnc_rdetherinfo];
    RDACTPT = CLASS_CNC 0x0162 [cnc_rdactpt];
    /// cnc_rdmultipieceno: no arguments; the answer is an i32.
    RDMULTIPIECENO = CLASS_CNC 0x0171 [cnc_rdmultipieceno];
    PDF_COPY = CLASS_CNC 0x0188 [cnc_pdf_copy];
    PDF_MOVE = CLASS_CNC 0x0189 [cnc_pdf_move];
    /// cnc_rdophistry4's command.
    RDOPHISTRY4 = CLASS_CNC 0x01b0 [cnc_rdophistry4];
    RDHISSGNL3 = CLASS_CNC 0x01b2 [cnc_rdhissgnl3];
    /// cnc_wrhissgnl3: `(1,0x01b3)[n]`, then n 16-byte entries (the layout
    /// of cnc_rdhissgnl3's answer, `SIG3_REC`).
    WRHISSGNL3 = CLASS_CNC 0x01b3 [cnc_wrhissgnl3];
    RDOMHISNO = CLASS_CNC 0x01b4 [cnc_rdomhisno];
    RDOMHISTRY2 = CLASS_CNC 0x01b5 [cnc_rdomhistry2];
    /// cnc_rdsyssoft3: `(1,0x01b8)[s_no, num]`; the answer is `{num, total}`
    /// then `num` 12-byte entries {id, series\[5\], edition\[5\]}.
    RDSYSSOFT3 = CLASS_CNC 0x01b8 [cnc_rdsyssoft3];
    /// cnc_rdsyshard: `(1,0x01b9)[s_no, num]`; the answer is a 32-bit count,
    /// then that many 20-byte boards.
    RDSYSHARD = CLASS_CNC 0x01b9 [cnc_rdsyshard];
    /// cnc_rdsyssoft3_str: `(1,0x022e)[s_no, num]`; the answer is `{num,
    /// total}` then `num` 28-byte entries {id, name\[13\], series\[5\],
    /// edition\[5\], dummy\[3\]}.
    RDSYSSOFT3_STR = CLASS_CNC 0x022e [cnc_rdsyssoft3_str];
    PDF_RDACTPT = CLASS_CNC 0x01ba [cnc_pdf_rdactpt];
    PDF_WRACTPT = CLASS_CNC 0x01bb [cnc_pdf_wractpt];
    /// cnc_rdtlusegrp on the 30i class: the optional group number of group
    /// `g`, args [g, g].
    TLOPTGRP = CLASS_CNC 0x01bf [cnc_rdtlusegrp];
    /// cnc_rdtlinfo on the 30i class: a word, then the tool life limits.
    RDTLINFO = CLASS_CNC 0x01c4 [cnc_rdtlinfo];
    COPYPROG = CLASS_CNC 0x01c6 [cnc_copyprog];
    RENAMEPROG = CLASS_CNC 0x01c7 [cnc_renameprog];
    CONDENSE = CLASS_CNC 0x01c8 [cnc_condense];
    RDALMHISTRY5 = CLASS_CNC 0x01d1 [cnc_rdalmhistry5];
    /// cnc_rdmdiprgstat: no arguments; the answer is a u16 of status bits.
    RDMDIPRGSTAT = CLASS_CNC 0x02a0 [cnc_rdmdiprgstat];
    /// cnc_rdservoid: `(1,0x028e)[axis, slct]`, the 129-byte ODBCSVID answered.
    RDSERVOID = CLASS_CNC 0x028e [cnc_rdservoid];
    /// cnc_rdspindleid: `(1,0x028f)[sp_no, slct]`, the 128-byte ODBCSPID answered.
    RDSPINDLEID = CLASS_CNC 0x028f [cnc_rdspindleid];
    /// cnc_rdfromservoid: `(1,0x0290)[axis]`, as cnc_rdservoid's answer.
    RDFROMSERVOID = CLASS_CNC 0x0290 [cnc_rdfromservoid];
    /// cnc_rdfromspindleid: `(1,0x0291)[sp_no]`, as cnc_rdspindleid's answer.
    RDFROMSPINDLEID = CLASS_CNC 0x0291 [cnc_rdfromspindleid];
    /// cnc_rdservoid2: `(1,0x0292)[axis, slct]`, the 209-byte ODBCSVID2 answered.
    RDSERVOID2 = CLASS_CNC 0x0292 [cnc_rdservoid2];
    /// cnc_rdspindleid2: `(1,0x0293)[sp_no, slct]`, the 137-byte ODBCSPID2 answered.
    RDSPINDLEID2 = CLASS_CNC 0x0293 [cnc_rdspindleid2];
    /// cnc_rdfromservoid2: `(1,0x0294)[axis]`, as cnc_rdservoid2's answer.
    RDFROMSERVOID2 = CLASS_CNC 0x0294 [cnc_rdfromservoid2];
    /// cnc_rdfromspindleid2: `(1,0x0295)[sp_no]`, as cnc_rdspindleid2's answer.
    RDFROMSPINDLEID2 = CLASS_CNC 0x0295 [cnc_rdfromspindleid2];
    // Family A of the long tail: system state, screen and program state.
    /// cnc_rdope_lvl: `(1,0x00c0)`, the operation level (i16).
    RDOPE_LVL = CLASS_CNC 0x00c0 [cnc_rdope_lvl];
    /// cnc_rdprt_lvl: `(1,0x00c5)[kind]`, the read and write protection levels (i16 each).
    RDPRT_LVL = CLASS_CNC 0x00c5 [cnc_rdprt_lvl];
    /// cnc_wrprt_lvl: `(1,0x00c6)[kind, read, write]`.
    WRPRT_LVL = CLASS_CNC 0x00c6 [cnc_wrprt_lvl];
    /// cnc_getlanguage: `(1,0x00dd)`, the display language (i16).
    GETLANGUAGE = CLASS_CNC 0x00dd [cnc_getlanguage];
    /// cnc_chglang: `(1,0x00f4)[language]`.
    CHGLANG = CLASS_CNC 0x00f4 [cnc_chglang];
    /// cnc_rdmenuswitch: `(1,0x0115)`, the menu switches (i32).
    RDMENUSWITCH = CLASS_CNC 0x0115 [cnc_rdmenuswitch];
    /// cnc_wrmenuswitch: `(1,0x0116)[data, mask]`.
    WRMENUSWITCH = CLASS_CNC 0x0116 [cnc_wrmenuswitch];
    /// cnc_rdcoordnum: `(1,0x015b)`, the additional work coordinate systems (i32).
    RDCOORDNUM = CLASS_CNC 0x015b [cnc_rdcoordnum];
    /// cnc_getcncmodel: `(1,0x016f)`, the model code (i32).
    GETCNCMODEL = CLASS_CNC 0x016f [cnc_getcncmodel];
    /// cnc_rdrepeatval: `(1,0x02c6)`, the program's repeats (i32).
    RDREPEATVAL = CLASS_CNC 0x02c6 [cnc_rdrepeatval];
    // Family D of the long tail: histories, timers, machine state.
    /// cnc_rdhissgnl: `(1,0x006e)`, 12-byte records of the signals the
    /// operation history records (the 16i's form).
    RDHISSGNL = CLASS_CNC 0x006e [cnc_rdhissgnl];
    /// cnc_getmacaddress: `(1,0x01b6)`, the Ethernet MAC address's characters.
    GETMACADDRESS = CLASS_CNC 0x01b6 [cnc_getmacaddress];
    /// cnc_rdalmhisno3: `(1,0x00d6)`, the alarm history's entries (i32).
    RDALMHISNO3 = CLASS_CNC 0x00d6 [cnc_rdalmhisno3];
    /// cnc_rdophisno3: `(1,0x00d7)`, the operation history's entries (i32).
    RDOPHISNO3 = CLASS_CNC 0x00d7 [cnc_rdophisno3];
    /// cnc_getrtmrvars: `(1,0x01db)`, the real-time macro non-volatile variables (i32).
    GETRTMRVARS = CLASS_CNC 0x01db [cnc_getrtmrvars];
    /// cnc_getrtmrvar: `(1,0x01de)`, the real-time macro volatile variables (i32).
    GETRTMRVAR = CLASS_CNC 0x01de [cnc_getrtmrvar];
    /// cnc_seqsrch: `(1,0x001e)[seq]`, no answer.
    SEQSRCH = CLASS_CNC 0x001e [cnc_seqsrch];
    /// cnc_rewind: `(1,0x001f)`, no answer.
    REWIND = CLASS_CNC 0x001f [cnc_rewind];
    /// cnc_rdfixcycle: `(1,0x0119)`: four i32 (mode, the plane's two axes,
    /// the drilling axis), the two counts, then six value records.
    RDFIXCYCLE = CLASS_CNC 0x0119 [cnc_rdfixcycle];
    // Axes, modes and settings (the long tail).
    /// cnc_rdmdlconfig2: `(1,0x0042)`, the module configuration bytes (at most 128 read).
    RDMDLCONFIG2 = CLASS_CNC 0x0042 [cnc_rdmdlconfig2];
    /// cnc_rdsynerrsy, cnc_rdsynerrrg: `(1,0x0059)[0 | 1]`, the synchronous
    /// error of the synchronous control (0) or rigid tap (1) mode (i32).
    SYNERR = CLASS_CNC 0x0059 [cnc_rdsynerrsy cnc_rdsynerrrg];
    /// cnc_rdinterference: `(1,0x00ec)`, the interference check's two tools (i16 each).
    RDINTERFERENCE = CLASS_CNC 0x00ec [cnc_rdinterference];
    /// cnc_rdcdrotate: `(1,0x011a)`: mode and plane axes (i32 each), the
    /// center (two value records), the angle.
    RDCDROTATE = CLASS_CNC 0x011a [cnc_rdcdrotate];
    /// cnc_rdenblinfo: `(1,0x018e)`, the `[MEASURE]` key's availability (a byte).
    RDENBLINFO = CLASS_CNC 0x018e [cnc_rdenblinfo];
    /// cnc_rdcenblinfo: `(1,0x018f)`, the `[MEASURE] [CENTER]` key's availability (a byte).
    RDCENBLINFO = CLASS_CNC 0x018f [cnc_rdcenblinfo];
    /// cnc_absolute2_exdgt & co.: `(1,0x02ce)[code]` (0 absolute, 1 machine,
    /// 2 relative, 7 distance to go), a 16-byte record per axis.
    EXDGT = CLASS_CNC 0x02ce [cnc_absolute2_exdgt cnc_machine_exdgt cnc_relative2_exdgt cnc_distance_exdgt];
    RESET2 = CLASS_CNC 0x02c5 [cnc_reset2];
    /// cnc_rdusetlno: `(1,0x0049)[s, e]`, the first group's number, then
    /// the use number of each group's tool in use (i32 each).
    RDUSETLNO = CLASS_CNC 0x0049 [cnc_rdusetlno];
    /// cnc_wr1tlifedata: `(1,0x0050)[grp, n, 0, 0, 16]` + the tool's
    /// number, H and D codes and information (i32 each).
    WR1TLIFEDATA = CLASS_CNC 0x0050 [cnc_wr1tlifedata cnc_wr1tlifedat2];
    /// cnc_rdexchgtgrp: `(1,0x00d4)[n]`, the groups whose tools are to be
    /// exchanged: i32 group and optional group number each.
    RDEXCHGTGRP = CLASS_CNC 0x00d4 [cnc_rdexchgtgrp];
    /// cnc_tofs_rnge: `(1,0x00c8)[number, 0, type]`, the tool offset's
    /// range (i32 minimum, maximum, status).
    TOFS_RNGE = CLASS_CNC 0x00c8 [cnc_tofs_rnge];
    /// cnc_zofs_rnge: `(1,0x00c9)[number, 0, axis]`, as cnc_tofs_rnge.
    ZOFS_RNGE = CLASS_CNC 0x00c9 [cnc_zofs_rnge];
    /// cnc_wksft_rnge: `(1,0x00ca)[axis]`, as cnc_tofs_rnge.
    WKSFT_RNGE = CLASS_CNC 0x00ca [cnc_wksft_rnge];
    /// cnc_rdactfixofs: `(1,0x0129)[axis]`, the fixture offset number in
    /// effect (i32), then a value record per axis.
    RDACTFIXOFS = CLASS_CNC 0x0129 [cnc_rdactfixofs];
    /// cnc_rdvolccomp: `(1,0x00e0)`, the volumetric compensation amount
    /// of each axis (i32 each).
    RDVOLCCOMP = CLASS_CNC 0x00e0 [cnc_rdvolccomp];
    /// Read a PMC range: args (s, e, adr_type, data_type); payload: the bytes.
    RDPMCRNG = CLASS_PMC 0x8001 [pmc_rdpmcrng];
    /// Write a PMC range: args (s, e, adr_type, data_type, n) + n bytes.
    WRPMCRNG = CLASS_PMC 0x8002 [pmc_wrpmcrng];
    /// pmc_rdpmcinfo: (2,0x8003)\[adr_type\]; payload i32 count + 12-byte records.
    RDPMCINFO = CLASS_PMC 0x8003 [pmc_rdpmcinfo];
    /// pmc_rdpmctitle: no arguments.
    RDPMCTITLE = CLASS_PMC 0x800b [pmc_rdpmctitle];
    /// pmc_select_pmc_unit: (2,0x800c)[unit type]; no answer payload.
    SELECT_UNIT = CLASS_PMC 0x800c [pmc_select_pmc_unit];
    PMC_COUNT = CLASS_PMC 0x800e [pmc_get_number_of_pmc];
    /// pmc_get_pmc_unit_types: (2,0x800f)\[most\]; the answer is i32 unit types.
    UNIT_TYPES = CLASS_PMC 0x800f [pmc_get_pmc_unit_types];
    /// pmc_rdalmmsg: (2,0x8010)[s_number, count]; the answer is i32 count,
    /// i32 exist, then count messages of 128 bytes.
    PMC_RDALMMSG = CLASS_PMC 0x8010 [pmc_rdalmmsg];
    /// pmc_get_timer_type: (2,0x804a)[s, e]; the answer is big-endian i16
    /// types.
    GET_TIMER_TYPE = CLASS_PMC 0x804a [pmc_get_timer_type];
    /// pmc_set_timer_type: (2,0x804b)[s, e, 0, 0, bytes] with the types as
    /// big-endian i16.
    SET_TIMER_TYPE = CLASS_PMC 0x804b [pmc_set_timer_type];
    /// pmc_rdcntlgrp: `(2,0x8006)`, the data table's control data group
    /// number (i32, the low 16 bits read).
    RDCNTLGRP = CLASS_PMC 0x8006 [pmc_rdcntlgrp];
    /// pmc_wrcntlgrp: `(2,0x8007)[groups]`, no answer.
    WRCNTLGRP = CLASS_PMC 0x8007 [pmc_wrcntlgrp];
    /// pmc_rdcntl_exrelay_grp: `(2,0x8059)`, the extended relay's control
    /// data group number (i32, the low 16 bits read).
    RDCNTL_EXRELAY_GRP = CLASS_PMC 0x8059 [pmc_rdcntl_exrelay_grp];
    /// pmc_wrcntl_exrelay_grp: `(2,0x805a)[groups]`, no answer.
    WRCNTL_EXRELAY_GRP = CLASS_PMC 0x805a [pmc_wrcntl_exrelay_grp];
    /// pmc_kpmsiz: `(2,0x800a)`, the extended backup memory's size (u32).
    KPMSIZ = CLASS_PMC 0x800a [pmc_kpmsiz];
    /// pmc_get_number_of_ladder: `(2,0x805e)`, how many ladders (i32).
    NUMBER_OF_LADDER = CLASS_PMC 0x805e [pmc_get_number_of_ladder];
    /// pmc_read_seq_program_and_memory_type: `(2,0x804c)`: four u32 codes
    /// and two 32-byte texts.
    SEQ_PROGRAM_TYPE = CLASS_PMC 0x804c [pmc_read_seq_program_and_memory_type];
    /// pmc_rdpmctitle2: `(2,0x8060)`: pmc_rdpmctitle's texts, then the
    /// program number's and version's further characters.
    RDPMCTITLE2 = CLASS_PMC 0x8060 [pmc_rdpmctitle2];
}

#[cfg(test)]
#[path = "commands/tests.rs"]
mod tests;
