//! Keeps the documentation true: the function table (docs/functions.md)
//! lists exactly the exported functions but the rows of
//! src/spec/table/absent/ (declared by FANUC's header, on no Ethernet
//! library: COMPATIBILITY.md lists them), and CI runs the README's test
//! command.

use std::collections::BTreeSet;
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn exported() -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    // src/ffi/*.rs and the area folders under it (src/ffi/described/).
    let mut files: Vec<PathBuf> = Vec::new();
    let mut dirs = vec![root().join("src/ffi")];
    while let Some(d) = dirs.pop() {
        for e in std::fs::read_dir(d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                dirs.push(p)
            } else {
                files.push(p)
            }
        }
    }
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        for line in text.lines() {
            if let Some(rest) = line.trim_start().split("extern \"C\" fn ").nth(1) {
                let name = rest.split('(').next().unwrap().trim();
                if ["cnc_", "pmc_", "fwlib_"]
                    .iter()
                    .any(|p| name.starts_with(p))
                {
                    out.insert(name.to_string());
                }
            }
        }
    }
    // The functions described as data (src/spec/table/): build.rs writes their exports.
    out.extend(fwlib32::spec::FUNCS.iter().map(|f| f.name.to_string()));
    out
}

#[test]
fn function_table_matches_the_exports() {
    let section = std::fs::read_to_string(root().join("docs/functions.md")).unwrap();
    let listed: BTreeSet<String> = section
        .lines()
        .filter_map(|l| l.strip_prefix("| "))
        .map(|l| l.split(' ').next().unwrap().to_string())
        .filter(|n| n.starts_with("cnc_") || n.starts_with("pmc_") || n.starts_with("fwlib_"))
        .collect();
    let exported = exported();
    assert!(exported.len() >= 13);
    assert_eq!(
        listed, exported,
        "docs/functions.md's table vs exported functions"
    );
}

#[test]
fn ci_runs_the_readme_test_command() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let ci = std::fs::read_to_string(root().join(".ci/run")).unwrap();
    let after = readme
        .split("Run all tests:")
        .nth(1)
        .expect("README names its test command");
    let cmd = after
        .lines()
        .skip_while(|l| !l.starts_with("```"))
        .nth(1)
        .expect("a command in a code block")
        .trim();
    assert!(
        ci.lines()
            .map(str::trim)
            .any(|l| l == cmd || l.starts_with(&format!("{cmd} "))),
        "CI (.ci/run) must run the README's test command {cmd:?}"
    );
}
