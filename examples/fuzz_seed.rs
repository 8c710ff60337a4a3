//! Seeds the fuzz corpora (fuzz/corpus/<target>/, docs/reliability.md "Fuzzing")
//! from what the project already has: the frames of the recorded vectors
//! (tests/vectors/*.json: the CNC's answers for `reply`, the library's
//! requests for `request`) and the profiles (the built-in one, its 16i and
//! Series 15 forms, the TOML examples of README.md and docs/) for `profile`.
//!
//! ```text
//! cargo run --example fuzz_seed            # then: cd fuzz && cargo fuzz cmin <target>
//! ```

#[path = "../fuzz/fuzzing.rs"]
mod fuzzing;

use fuzzing::{ctx_byte, decoder};
use fwlib32::proto::open::CncClass;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::Path;

fn hex(s: &str) -> Vec<u8> {
    (0..s.len() / 2)
        .map(|i| u8::from_str_radix(&s[2 * i..2 * i + 2], 16).unwrap())
        .collect()
}

/// Writes `data` as fuzz/corpus/<target>/seed-<hash>; true if new.
fn put(target: &str, data: &[u8]) -> bool {
    let h = data.iter().fold(0xcbf29ce484222325u64, |h, b| {
        (h ^ u64::from(*b)).wrapping_mul(0x100000001b3)
    });
    let dir = Path::new("fuzz/corpus").join(target);
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(format!("seed-{h:016x}"));
    let new = !p.exists();
    std::fs::write(p, data).unwrap();
    new
}

fn class_of(profile: &str) -> (CncClass, u16) {
    let class = if profile.starts_with("s15") {
        CncClass::Series16 { kind: 2 }
    } else if profile.starts_with("v2") {
        CncClass::Series16 { kind: 1 }
    } else {
        CncClass::Series30
    };
    (class, if profile.contains("a8") { 8 } else { 32 })
}

fn main() {
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    let mut files: Vec<_> = std::fs::read_dir("tests/vectors")
        .expect("run from the repository root")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    for file in files {
        let v: Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
        let function = file.file_stem().unwrap().to_str().unwrap().to_string();
        let word = function.split_once('_').map_or("", |(_, w)| w);
        for case in v["cases"].as_array().into_iter().flatten() {
            let (class, axes) = class_of(case["profile"].as_str().unwrap_or("v3"));
            let sel = match class {
                CncClass::Series30 => 0u8,
                CncClass::Series16 { kind: 2 } => 2,
                CncClass::Series16 { .. } => 1,
            };
            let mut requests: BTreeMap<u64, Vec<u8>> = BTreeMap::new();
            for call in case["calls"].as_array().into_iter().flatten() {
                let cmd = call["probe_cmd"].as_str().unwrap_or("");
                let mut words = cmd.split_whitespace();
                let probe = words.next().unwrap_or("");
                let args: Vec<i16> = words.filter_map(|w| w.parse().ok()).collect();
                let mut replies = Vec::new();
                for f in call["frames"].as_array().into_iter().flatten() {
                    let Some(h) = f["hex"].as_str() else { continue };
                    match f["dir"].as_str() {
                        Some("resp") => replies.extend(hex(h)),
                        Some("req") => requests
                            .entry(f["conn"].as_u64().unwrap_or(0))
                            .or_default()
                            .extend(hex(h)),
                        _ => {}
                    }
                }
                let name = match probe {
                    "alloc" => "cnc_allclibhndl3",
                    p if p == word => function.as_str(),
                    _ => continue,
                };
                let (Some(d), false) = (decoder(name), replies.is_empty()) else {
                    continue;
                };
                let mut input = d.to_be_bytes().to_vec();
                input.push(ctx_byte(class, axes));
                for k in 0..4 {
                    input.extend(args.get(k).copied().unwrap_or(0).to_be_bytes());
                }
                input.extend(replies);
                *counts.entry("reply").or_default() += usize::from(put("reply", &input));
            }
            for frames in requests.into_values() {
                let input = [vec![sel], frames].concat();
                *counts.entry("request").or_default() += usize::from(put("request", &input));
            }
        }
    }
    let base = fwlib32::sim::profile::DEFAULT_PROFILE;
    let mut profiles = vec![base.to_string()];
    for kind in [1, 2, 3] {
        profiles.push(base.replacen(
            "class = \"30i\"",
            &format!("class = \"16i\"\nkind = {kind}"),
            1,
        ));
    }
    let mut docs = vec![std::path::PathBuf::from("README.md")];
    let mut more: Vec<_> = std::fs::read_dir("docs")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    more.sort();
    docs.extend(more);
    let readme: String = docs
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    for block in readme.split("```toml\n").skip(1) {
        let text = block.split("```").next().unwrap_or("");
        profiles.push(text.to_string());
        profiles.push(format!("{base}\n{text}"));
    }
    for p in profiles {
        *counts.entry("profile").or_default() += usize::from(put("profile", p.as_bytes()));
    }
    for (t, n) in counts {
        println!("{t}: {n} new seeds in fuzz/corpus/{t}");
    }
}
