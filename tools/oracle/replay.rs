//! Replaying a recorded case to a library through the probe: the replay
//! server plays the recorded CNC frames (and checks every request byte),
//! the probe makes the recorded calls. Used by `oracle verify` (FANUC's
//! library or ours) and by tests/recorded/oracle.rs (ours, in `cargo test`).

use super::common::{Case, Replay};
use super::probe::{Answer, Probe, buffer_names};
use std::path::Path;
use std::process::Command;

/// Port in a recorded `alloc T 127.0.0.1 1`: nothing listens there, so the
/// connection is refused (the refused-connection cases).
pub const DEAD_PORT: &str = "1";

/// The differences between the library's behaviour and the recorded case;
/// empty when they agree.
pub fn replay_case(probe: impl Fn() -> Command, lib: &Path, case: &Case) -> Vec<String> {
    let mut server = Replay::start();
    let mut probe = Probe::spawn(probe(), lib, server.port);
    let mut out = Vec::new();
    for (i, call) in case.calls.iter().enumerate() {
        let label = format!(
            "{}/{} call {} `{}`",
            case.function,
            case.name,
            i + 1,
            call.probe_cmd
        );
        server.begin(&label, call.frames.clone());
        let answer = probe.call(&call.probe_cmd);
        out.extend(server.end());
        out.extend(compare(&label, call, &answer));
        if server.broken() || matches!(answer, Answer::Crashed(_)) {
            break;
        }
    }
    probe.finish();
    out.extend(server.finish());
    out
}

/// The recorded call against what the library answered.
pub fn compare(label: &str, call: &super::common::Call, answer: &Answer) -> Vec<String> {
    let mut out = Vec::new();
    let (ret, fields, b0, b1) = match answer {
        Answer::Done {
            ret,
            fields,
            b0,
            b1,
        } => (ret, fields, b0, b1),
        Answer::Missing(f) => return vec![format!("{label}: the library lacks {f}")],
        Answer::Crashed(why) => return vec![format!("{label}: {why}")],
    };
    if call.ret.map(i64::from) != Some(*ret) {
        out.push(format!("{label}: returned {ret}, recorded {:?}", call.ret));
    }
    for (name, v) in fields {
        if let Some(want) = call.fields.get(name)
            && want != v
        {
            out.push(format!("{label}: {name} = {v}, recorded {want}"));
        }
    }
    let (n0, n1) = buffer_names(call.word());
    for (name, got) in [(n0, b0), (n1, b1)] {
        let want = call
            .outputs
            .get(name)
            .map(|o| o.hex.as_slice())
            .unwrap_or(&[]);
        if want != got.as_slice() {
            out.push(format!(
                "{label}: output {name} differs\n    recorded {}\n    got      {}",
                super::common::hex(want),
                super::common::hex(got)
            ));
        }
    }
    out
}
