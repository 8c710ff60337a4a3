//! Machine profiles: the TOML file that says what the simulated CNC is and
//! what it holds. Sections grow with the functions the simulator serves.
//! Pure data: the areas' sections are in src/sim/profile/ (and pmc.rs);
//! nothing here knows the running machine.

pub mod axes;
pub mod cycle;
pub mod fault;
pub mod fleet;
pub mod history;
pub mod macros;
pub mod maintenance;
pub mod offset;
pub mod param;
pub mod program;
pub mod system;
pub mod window;

use serde::Deserialize;

pub const DEFAULT_PROFILE: &str = include_str!("default.toml");

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Profile {
    #[serde(default)]
    pub cnc: Cnc,
    #[serde(default, rename = "path")]
    pub paths: Vec<Path>,
    /// Programs stored in memory (src/sim/store.rs).
    #[serde(default, rename = "program")]
    pub programs: Vec<cycle::StoredProgram>,
    /// Scheduled events (src/sim/clock.rs).
    #[serde(default, rename = "event")]
    pub events: Vec<cycle::Event>,
    /// Scheduled network faults (src/sim/faults.rs).
    #[serde(default, rename = "fault")]
    pub faults: Vec<fault::Fault>,
    /// How many machines the profile serves, and whether they differ.
    #[serde(default)]
    pub fleet: fleet::FleetSection,
    // --- position ---

    // --- program ---
    /// cnc_rdtimer counters (src/sim/program.rs).
    #[serde(default)]
    pub timers: program::Timers,
    // --- alarm ---

    // --- param ---
    /// Parameter and diagnosis tables, parameter write enable.
    #[serde(default)]
    pub param: param::Params,
    // --- macros ---

    // --- pmc ---
    /// PMC address areas and their bytes (`[pmc]`, `[pmc.area.R]` ...).
    #[serde(default)]
    pub pmc: super::pmc::Pmc,
    // --- offset ---
    /// The alarm history (src/sim/history.rs).
    #[serde(default)]
    pub alarm_history: history::History,
    /// The operation and operator-message histories (src/sim/history.rs).
    #[serde(default)]
    pub operation_history: history::OperationHistory,
    #[serde(default)]
    pub operator_message_history: history::MessageHistory,
    /// The pitch error compensation table (cnc_rdpitchinfo, cnc_rdpitchr).
    #[serde(default)]
    pub pitch: Pitch,
    /// The periodic maintenance items (src/sim/maintenance.rs).
    #[serde(default)]
    pub maintenance: maintenance::Maintenance,
    /// The software operator panel (src/sim/operate.rs).
    #[serde(default)]
    pub operator_panel: OperatorPanel,
    /// The CNC's boards and software (cnc_rdsyshard, cnc_rdsyssoft3).
    #[serde(default)]
    pub system: system::System,
    // --- tool ---

    // --- upload ---
}

/// `[operator_panel]`: the software operator panel's general purpose
/// switches' names (cnc_rdopnlgsname reads 8, cnc_rdopnlgsname2 16;
/// cnc_wropnlgsname, cnc_wropnlgsname2 change them), at most 8 characters
/// each; switches past the list have no name.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OperatorPanel {
    pub switch_names: Vec<String>,
}

impl Default for OperatorPanel {
    fn default() -> Self {
        OperatorPanel {
            switch_names: ["COOLANT", "CHIP CNV", "WORK LT", "AIR BLOW"]
                .map(String::from)
                .to_vec(),
        }
    }
}

/// `[pitch]`: pitch error compensation points 0..`size`, each an
/// incremental compensation in detection units; points past `values` are 0.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Pitch {
    pub size: i32,
    pub values: Vec<i8>,
}

impl Default for Pitch {
    fn default() -> Self {
        Pitch {
            size: 1024,
            values: Vec::new(),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum Class {
    #[serde(rename = "30i")]
    Series30,
    #[serde(rename = "16i")]
    Series16,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Cnc {
    pub class: Class,
    /// 16i class only: the open response's kind word (1 = 16/18/21/0i, 3 = option forced on).
    pub kind: u16,
    pub cnc_type: String,
    pub series: String,
    pub version: String,
    pub addinfo: u16,
    pub max_axes: u16,
    pub max_spindles: u16,
    pub max_sessions: usize,
    pub cnc_id: Vec<u32>,
    /// FOCAS option flags (30i: open-response word 14; 16i: parameter 9968).
    pub option: u16,
    /// cnc_rdetherinfo: the Ethernet board (0 embedded, 1 Fast Ethernet
    /// board, 2 Data Server) and the device in use (0 embedded, 1 PCMCIA card).
    pub ether_type: i16,
    pub ether_device: i16,
    /// cnc_getmacaddress: the Ethernet MAC address, 12 hexadecimal digits.
    pub mac_address: String,
}

impl Default for Cnc {
    fn default() -> Self {
        Cnc {
            class: Class::Series30,
            kind: 1,
            cnc_type: "31".into(),
            series: "G421".into(),
            version: "08.0".into(),
            addinfo: 1026,
            max_axes: 32,
            max_spindles: 8,
            max_sessions: 5,
            cnc_id: vec![0, 0, 0, 0],
            option: 1,
            ether_type: 0,
            ether_device: 0,
            mac_address: "000000000000".into(),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum MachineKind {
    #[default]
    Mill,
    Lathe,
    /// A punch press (mt_type " P"): cnc_rdtooldata, cnc_rdtoolinfo.
    Punch,
}

#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Path {
    pub machine: MachineKind,
    pub status: StatusWords,
    #[serde(rename = "axis")]
    pub axes: Vec<Axis>,
    #[serde(rename = "spindle")]
    pub spindles: Vec<Spindle>,
    /// The program this path runs (src/sim/clock.rs).
    pub cycle: cycle::Cycle,
    /// Its program memory (src/sim/store.rs).
    pub memory: cycle::Memory,
    /// Alarms active from the start.
    #[serde(rename = "alarm")]
    pub alarms: Vec<cycle::Alarm>,
    // --- position ---
    /// Actual feed rate (cnc_actf, rddynamic2 actf, rdspeed), mm/min, or
    /// inch/min when the first axis is an inch axis (`unit = 1`: cnc_rdspeed
    /// and rdaxisdata report that unit); the program cycle (src/sim/clock.rs)
    /// may change it while running.
    pub feed: i32,
    // --- program ---
    /// Modal codes (cnc_modal) where no program running set them.
    pub modal: program::Modal,
    /// Operation mode word (cnc_rdopmode): by the OPMODE_* names of FANUC's
    /// Windows header the spindle's mode (0 others, 1 normal, 2 orientation,
    /// 3 synchronous, 4 rigid tap, 5 Cs contour, 6 positioning), not the
    /// automatic mode of `status.aut` that `mode` events change.
    pub opmode: i16,
    /// Machining times of programs run before the simulator started, newest
    /// first, as [program, hours, minutes, seconds] (cnc_rdproctime; the
    /// runs the simulated machine completes come before them).
    pub proc_times: Vec<[i32; 4]>,

    // --- alarm ---
    /// Operator messages on display (cnc_rdopmsg).
    #[serde(rename = "opmsg")]
    pub opmsgs: Vec<program::OperatorMessage>,
    // --- param ---

    // --- macros ---
    /// Custom macro variables (`[path.macros]`).
    pub macros: macros::Macros,
    /// P-code macro variables (`[path.pmacros]`).
    pub pmacros: macros::PCodeMacros,
    /// Real-time custom macro variables (`[path.rt_macros]`).
    pub rt_macros: macros::RtMacros,
    // --- pmc ---

    // --- offset ---
    /// Tool and work offsets (src/sim/offset.rs).
    pub offset: offset::Offsets,

    // --- tool ---
    /// Tool life groups (src/sim/offset.rs).
    #[serde(rename = "tool_group")]
    pub tool_groups: Vec<offset::ToolGroupProfile>,
    /// Tool life management's limits (cnc_rdtlinfo).
    pub tool_life: offset::ToolLifeLimits,
    /// Tool management data, data numbers 1, 2, ... (cnc_rdtool).
    #[serde(rename = "managed_tool")]
    pub managed_tools: Vec<offset::ManagedTool>,
    /// A punch press's tool data, data numbers 1, 2, ... (cnc_rdtooldata).
    #[serde(rename = "punch_tool")]
    pub punch_tools: Vec<offset::PunchTool>,

    // --- sampling ---
    /// Servo data sampling channels, channel 1 first (cnc_sdtread1shot,
    /// cnc_sdtstartsmpl; cnc_sdtclrchnl clears them).
    #[serde(rename = "sample_channel")]
    pub sample_channels: Vec<SampleChannel>,
    /// The data codes a cnc_sdtsetchnl channel carries and the figure each
    /// samples (a code not listed: a figure not modelled, read as 0).
    #[serde(rename = "sample_code")]
    pub sample_codes: Vec<SampleCode>,
    /// The canned cycle in force (cnc_rdfixcycle).
    pub fixed_cycle: system::FixedCycle,
    /// The synchronous errors (cnc_rdsynerrsy, cnc_rdsynerrrg).
    pub sync_error: axes::SyncError,
    /// The `[MEASURE]` keys' availability (cnc_rdenblinfo, cnc_rdcenblinfo).
    pub measure: axes::Measure,
    /// The tool interference check's two tools (cnc_rdinterference).
    pub interference: axes::Interference,
    /// The coordinate rotation in force (cnc_rdcdrotate).
    pub rotation: axes::Rotation,
}

#[derive(Debug, Clone, Copy, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct StatusWords {
    pub aut: i16,
    pub run: i16,
    pub motion: i16,
    pub mstb: i16,
    pub emergency: i16,
    pub alarm: i16,
    pub edit: i16,
    pub hdck: i16,
    pub tmmode: i16,
    pub warning: i16,
    pub o3dchk: i16,
    pub ext_opt: i16,
    pub restart: i16,
}

#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Axis {
    pub name: String,
    pub suffix: String,
    pub decimals: i16,
    pub absolute: i32,
    pub machine: i32,
    pub relative: i32,
    pub distance: i32,
    // --- position ---
    /// Servo load meter, % (cnc_rdsvmeter, rdaxisdata class 2).
    pub servo_load: i32,
    /// Rated servo current, A (default 10): rdaxisdata class 2 type 2
    /// answers `servo_load` % of it.
    pub rated_current: Option<f64>,
    /// Position loop gain, 0.01/s (cnc_rdloopgain); default 3000.
    pub loop_gain: Option<i32>,
    /// Ball screw lead, mm per motor turn (default 10): the servo motor speed
    /// (cnc_rdsrvspeed, rpm) is the axis feed divided by it.
    pub lead: Option<f64>,
    /// Servo motor speed, rpm (cnc_rdsrvspeed): set by the running program.
    pub servo_speed: i32,
    /// Skip position (cnc_skip), in the axis's units: where the skip signal
    /// last came.
    pub skip: i32,
    /// Acceleration/deceleration time constant, ms (default 32): the
    /// acc/dec delay (cnc_accdecdly) is the axis's feed over half of it.
    pub accdec_ms: Option<f64>,
    /// Unit of the positions: 0 mm, 1 inch, 2 degree (rdaxisdata / rdposition `unit`).
    pub unit: i16,
    /// Input / output figures (cnc_getfigure); default `decimals`.
    pub input_figures: Option<i16>,
    pub output_figures: Option<i16>,
}

#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Spindle {
    pub name: String,
    pub speed: i32,
    // --- position ---
    /// Spindle load, % (cnc_rdspmeter, rdaxisdata class 3, cnc_rdspload).
    pub load: i32,
    /// Maximum r.p.m. ratio and gear ratio of the serial spindle, as the CNC
    /// reports them (cnc_rdspmaxrpm, cnc_rdspgear).
    pub max_rpm_ratio: i32,
    pub gear_ratio: i32,
    /// Spindle amplifier alarm number, 0 for none (cnc_rdspdlalm).
    pub alarm: i16,
    /// Position loop gain of the spindle's position control, 0.01/s
    /// (default 3000): its position deviation (cnc_rdposerrs,
    /// cnc_rdposerrs2) is its speed over it.
    pub loop_gain: Option<i32>,
    /// Position coder pulses per revolution (default 4096): the unit of
    /// the spindle's position deviation.
    pub pulses_per_rev: Option<i32>,
}

#[derive(Debug, thiserror::Error)]
pub enum ProfileError {
    #[error("cannot read profile {0}: {1}")]
    Io(String, std::io::Error),
    #[error("invalid profile: {0}")]
    Toml(#[from] toml::de::Error),
    #[error("invalid profile: {0}")]
    Invalid(String),
}

impl Profile {
    pub fn parse(text: &str) -> Result<Profile, ProfileError> {
        let p: Profile = toml::from_str(text)?;
        p.validate()?;
        Ok(p)
    }

    pub fn load(path: &std::path::Path) -> Result<Profile, ProfileError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| ProfileError::Io(path.display().to_string(), e))?;
        Profile::parse(&text)
    }

    fn validate(&self) -> Result<(), ProfileError> {
        let bad = |m: String| Err(ProfileError::Invalid(m));
        let c = &self.cnc;
        for (name, v, n) in [
            ("cnc_type", &c.cnc_type, 2),
            ("series", &c.series, 4),
            ("version", &c.version, 4),
        ] {
            if !v.is_ascii() || v.len() > n {
                return bad(format!("cnc.{name} must be at most {n} ASCII characters"));
            }
        }
        if self.paths.is_empty() {
            return bad("at least one [[path]] is required".into());
        }
        self.maintenance.validate().map_err(ProfileError::Invalid)?;
        self.operation_history
            .validate()
            .map_err(ProfileError::Invalid)?;
        if self.paths.len() > 15 {
            return bad("at most 15 paths".into());
        }
        if c.cnc_id.len() > 4 {
            return bad("cnc.cnc_id has at most 4 words".into());
        }
        for (i, p) in self.paths.iter().enumerate() {
            if p.axes.len() > c.max_axes as usize || p.axes.len() > crate::types::MAX_AXIS {
                return bad(format!("path {} has more axes than cnc.max_axes", i + 1));
            }
            if p.spindles.len() > c.max_spindles as usize
                || p.spindles.len() > crate::types::MAX_SPINDLE
            {
                return bad(format!(
                    "path {} has more spindles than cnc.max_spindles",
                    i + 1
                ));
            }
            for a in &p.axes {
                if a.name.is_empty()
                    || a.name.len() > 1
                    || a.suffix.len() > 1
                    || !a.name.is_ascii()
                    || !a.suffix.is_ascii()
                {
                    return bad(format!(
                        "axis name {:?}{:?}: one ASCII letter and an optional one-character suffix",
                        a.name, a.suffix
                    ));
                }
            }
        }
        // --- offset ---
        self.alarm_history
            .validate()
            .map_err(ProfileError::Invalid)?;
        for (i, p) in self.paths.iter().enumerate() {
            p.offset
                .validate(p.axes.len())
                .map_err(|m| ProfileError::Invalid(format!("path {}: {m}", i + 1)))?;
        }
        self.validate_run().map_err(ProfileError::Invalid)?;
        self.validate_fleet().map_err(ProfileError::Invalid)?;
        Ok(())
    }
}

impl Default for Profile {
    fn default() -> Self {
        Profile::parse(DEFAULT_PROFILE).expect("built-in profile is valid")
    }
}

impl Profile {
    /// `[fleet]` and `[[fault]]`.
    fn validate_fleet(&self) -> Result<(), String> {
        let n = self.fleet.machines;
        if !(1..=fleet::MAX_MACHINES).contains(&n) {
            return Err(format!(
                "fleet.machines must be 1 to {}",
                fleet::MAX_MACHINES
            ));
        }
        // The fleet's size may come from the command line: checked again
        // against it when the fleet starts.
        self.check_faults(fleet::MAX_MACHINES)
    }

    /// Checks the `[[fault]]`s for a fleet of `machines`.
    pub fn check_faults(&self, machines: usize) -> Result<(), String> {
        for (k, f) in self.faults.iter().enumerate() {
            f.check(machines)
                .map_err(|m| format!("[[fault]] {} ({:?}): {m}", k + 1, f.kind))?;
        }
        Ok(())
    }

    /// The running-machine sections: programs, cycles, events.
    fn validate_run(&self) -> Result<(), String> {
        for (k, p) in self.programs.iter().enumerate() {
            if !(1..=99_999_999).contains(&p.number) {
                return Err(format!("[[program]] {}: number must be 1..99999999", k + 1));
            }
            if self.programs[..k].iter().any(|q| q.number == p.number) {
                return Err(format!("[[program]] O{:04} is given twice", p.number));
            }
            if !p.text.is_ascii() {
                return Err(format!("[[program]] O{:04}: text must be ASCII", p.number));
            }
            cycle::program_date(p).map_err(|e| format!("[[program]] O{:04}: {e}", p.number))?;
            if usize::from(p.path) > self.paths.len() {
                return Err(format!("[[program]] O{:04}: no path {}", p.number, p.path));
            }
        }
        for (i, p) in self.paths.iter().enumerate() {
            let c = &p.cycle;
            let here = |q: &&cycle::StoredProgram| q.path == 0 || usize::from(q.path) == i + 1;
            if c.program != 0
                && !self
                    .programs
                    .iter()
                    .filter(here)
                    .any(|q| q.number == c.program)
            {
                return Err(format!(
                    "path {}: cycle.program = {} names no [[program]] with that number",
                    i + 1,
                    c.program
                ));
            }
            if !(c.block_seconds.is_finite() && c.block_seconds > 0.0) {
                return Err(format!(
                    "path {}: cycle.block_seconds must be a positive number of seconds",
                    i + 1
                ));
            }
        }
        for (k, e) in self.events.iter().enumerate() {
            let what = format!("[[event]] {} ({:?})", k + 1, e.action);
            if !cycle::ACTIONS.contains(&e.action.as_str()) {
                return Err(format!(
                    "{what}: action must be one of {}",
                    cycle::ACTIONS.join(", ")
                ));
            }
            if usize::from(e.path) > self.paths.len() {
                return Err(format!(
                    "{what}: path {} does not exist (the profile has {} path(s))",
                    e.path,
                    self.paths.len()
                ));
            }
            e.window().check().map_err(|m| format!("{what}: {m}"))?;
            if e.action == "alarm" && e.alarm.is_none() {
                return Err(format!(
                    "{what}: an alarm event needs alarm = {{ number = .., message = .. }}"
                ));
            }
            if e.action != "alarm" && e.alarm.is_some() {
                return Err(format!("{what}: only an \"alarm\" event takes an alarm"));
            }
        }
        Ok(())
    }
}

/// The servo figure a channel samples, of the simulator's model of its axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Datum {
    /// The motor speed, rpm (cnc_rdsrvspeed).
    #[default]
    Speed,
    /// The load meter, % (cnc_rdsvmeter).
    Load,
    /// The motor current, 0.1 A: the load's share of the rated current
    /// (cnc_rdaxisdata class 2 type 2).
    Current,
    /// A figure the simulator does not model (a cnc_sdtsetchnl code the
    /// profile's `sample_code` list does not name, a spindle's): read as 0.
    Other,
}

/// A data code of cnc_sdtsetchnl's channels (its magnitude: the sign
/// follows the axis's parameter 1023) and the figure it samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct SampleCode {
    pub code: i16,
    pub datum: Datum,
}

/// One sampling channel: a figure of an axis of the path (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct SampleChannel {
    pub axis: u16,
    pub datum: Datum,
}
