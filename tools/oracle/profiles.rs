//! The oracle's machine profiles by name: the simulator's built-in 30i
//! mill and its 16i, Series 15, two-path and write-enabled forms (the
//! token after the word in a case name: `rdparam_v2_a1_1320` ran on `v2`).
//! Shared by tools/oracle/main.rs and tests/compat.rs.

use fwlib32::sim::Profile;

/// The profiles by name: the built-in 30i mill and its 16i, Series 15 and
/// two-path forms, the 16i forms with 8 axes per path, and the
/// write-enabled forms (parameter write enable on, MDI mode; `s15w` only
/// for tests/compat.rs, which measures writes on every class).
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
        other => panic!("unknown profile {other}"),
    };
    Profile::parse(&text).unwrap_or_else(|e| panic!("profile {name}: {e}"))
}
