//! tests/c/collectors_pmcdata.c: the PMC long tail a collector reads (the
//! title's long fields, the program's type, the message functions)
//! through the .so, against the profile (unit 1 and unit 2).

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

#[test]
fn pmc_data_functions_follow_the_profile_and_state() {
    let p = Profile::parse(DEFAULT_PROFILE).expect("profile");
    let [u1, u2] = [&p.pmc.info[0], &p.pmc.info[1]];
    let (kv, _sim) = run_c_test("collectors_pmcdata", p.clone());

    // pmc_rdpmctitle2: the texts, program number and version to 8
    // characters, the rest of each member zeroed; unit 2 its own.
    let cut = |t: &str, n: usize| t.chars().take(n).collect::<String>();
    assert_eq!(kv["title.machine"], u1.title[1]);
    assert_eq!(kv["title.prgno"], cut(&u1.title[3], 8));
    assert_eq!(kv["title.prgvers"], cut(&u1.title[4], 8));
    assert_eq!(kv["title.remarks"], u1.title[9]);
    assert_eq!(kv["title.zeroed"], "1");
    assert!(
        u2.title[3].len() > 4 && u2.title[4].len() > 2,
        "longer than pmc_rdpmctitle's"
    );
    assert_eq!(kv["unit2.machine"], u2.title[1]);
    assert_eq!(kv["unit2.prgno"], cut(&u2.title[3], 8));
    assert_eq!(kv["unit2.prgvers"], cut(&u2.title[4], 8));
    assert_eq!(kv["unit2.zeroed"], "1");

    // pmc_read_seq_program_and_memory_type.
    let t = &u1.program_type;
    assert_eq!(kv["type.system"], t.system.to_string());
    assert_eq!(kv["type.system_attribute"], t.system_attribute.to_string());
    assert_eq!(kv["type.target"], t.target.to_string());
    assert_eq!(kv["type.target_attribute"], t.target_attribute.to_string());
    assert_eq!(kv["type.system_name"], t.system_name);
    assert_eq!(kv["type.target_name"], t.target_name);

    // The message functions: EW_FUNC.
    for f in ["rdmsg", "crdmsg", "wrmsg", "cwrmsg"] {
        assert_eq!(kv[f], "1", "{f}");
    }
}
