//! The oracle's machine profiles by name: the simulator's built-in 30i
//! mill and its 16i, Series 15, two-path and write-enabled forms (the
//! token after the word in a case name: `rdparam_v2_a1_1320` ran on `v2`).
//! Shared by tools/oracle/main.rs and tests/recorded/compat.rs.

use fwlib32::sim::Profile;

/// The profiles by name: the built-in 30i mill and its 16i, Series 15 and
/// two-path forms, the 16i forms with 8 axes per path, and the
/// write-enabled forms (parameter write enable on, MDI mode; `s15w` only
/// for tests/recorded/compat.rs, which measures writes on every class).
pub fn profile(name: &str) -> Profile {
    let base = fwlib32::sim::profile::DEFAULT_PROFILE;
    let class16 = |kind: u16| {
        base.replacen(
            "class = \"30i\"",
            &format!("class = \"16i\"\nkind = {kind}"),
            1,
        )
    };
    let second_path = "\n[[path]]\nmachine = \"lathe\"\nfeed = 200\n[path.status]\naut = 0\nrun = 0\n\
                       [[path.axis]]\nname = \"X\"\ndecimals = 3\nabsolute = 1000\n\
                       [[path.axis]]\nname = \"Z\"\ndecimals = 3\nabsolute = -2000\n";
    let writable = |t: String| {
        t.replacen("param_write_enable = false", "param_write_enable = true", 1)
            .replacen("aut = 1  ", "aut = 0  ", 1)
    };
    let axes8 = |t: String| t.replacen("max_axes = 32", "max_axes = 8", 1);
    // A punch press (cnc_rdtooldata, cnc_rdtoolinfo): path 1's tool data.
    let punch =
        |t: String| t.replacen("machine = \"mill\"", "machine = \"punch\"", 1) + PUNCH_TOOLS;
    let text = match name {
        "v3w" => writable(base.to_string()),
        "v2w" => writable(class16(1)),
        "s15w" => writable(class16(2)),
        "v3" => base.to_string(),
        "v2" => class16(1),
        "s15" => class16(2),
        "v3p2" => format!("{base}{second_path}"),
        "v2p2" => format!("{}{second_path}", class16(1)),
        // A 16i with 8 axes per path (cases.rs: `class_profile`).
        "v2a8" => axes8(class16(1)),
        "v2p2a8" => format!("{}{second_path}", axes8(class16(1))),
        "v3pu" => punch(base.to_string()),
        "v2pu" => punch(class16(1)),
        other => panic!("unknown profile {other}"),
    };
    Profile::parse(&text).unwrap_or_else(|e| panic!("profile {name}: {e}"))
}

/// The punch profiles' tool data (appended: path 1 is the only path).
const PUNCH_TOOLS: &str = "
[[path.punch_tool]]
number = 1
x_offset = 1500
y_offset = -2500
turret = 1
punch_count = 1234
life = 50000
shape = 1
size_i = 10000
decimals = 3

[[path.punch_tool]]
number = 12
turret = 2
change = 3
radius = 25000
radius_angle = 45000
shape = 2
size_i = 8000
size_j = 4000
angle = 90000
decimals = 4
angle_decimals = 3
";
