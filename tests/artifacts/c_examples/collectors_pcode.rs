//! tests/c/collectors_pcode.c: cnc_rdpmacroinfo2, cnc_rdpmacro,
//! cnc_wrpmacro, cnc_rdpmacror, cnc_wrpmacror, cnc_rdpmacror2 and
//! cnc_wrpmacror2 through the .so, compared with the simulator's P-code
//! variable store (on the 30i and the 16i class: binary records there).

use super::run_c_test;
use fwlib32::sim::Profile;
use fwlib32::sim::profile::DEFAULT_PROFILE;

/// The default profile with more P-code variables (#10000-#10199 and the
/// extended #20000-#20049) and a type for each range.
fn profile() -> Profile {
    profile_of(DEFAULT_PROFILE)
}

fn profile_of(base: &str) -> Profile {
    let p = "[path.pmacros]\nranges = [[10000, 10199]]  # cnc_wrpmacror writes 200 in two requests (tools/oracle)\nprotected = []\nv2_type = 0\nv1_type = 0\nv20_type = 0\n";
    assert!(
        base.contains(p),
        "the default profile's [path.pmacros] moved"
    );
    let text = base.replace(
        p,
        "[path.pmacros]\nranges = [[10000, 10199], [20000, 20049]]\nprotected = []\nv2_type = 2\nv1_type = 1\nv20_type = 3\n",
    );
    Profile::parse(&text).expect("profile")
}

#[test]
fn pcode_reads_and_writes_follow_the_store() {
    check(profile());
}

/// The same on a 16i, to which cnc_wrpmacro sends binary records.
#[test]
fn pcode_on_a_16i() {
    let text = DEFAULT_PROFILE.replacen("class = \"30i\"", "class = \"16i\"", 1);
    assert_ne!(text, DEFAULT_PROFILE, "the default profile's class moved");
    let p = profile_of(&text);
    assert_eq!(p.cnc.class, fwlib32::sim::profile::Class::Series16);
    check(p);
}

fn check(p: Profile) {
    let (kv, sim) = run_c_test("collectors_pcode", p.clone());
    let pm = &p.paths[0].pmacros;
    assert_eq!(
        kv["pmacroinfo2"],
        format!("200,50,0,{},{},{}", pm.v1_type, pm.v2_type, pm.v20_type)
    );
    assert_eq!(kv["pmacroinfo2"], "200,50,0,1,2,3");
    for n in 10000..=10002 {
        let (v, d) = pm.vars.values.get(&n).copied().unwrap_or((0, -1));
        assert_eq!(kv[&format!("pmacro.{n}")], format!("{n},{v},{d}"));
    }
    // The profile's "12.5" and "-3"; #10002 vacant.
    assert_eq!(kv["pmacro.10000"], "10000,125,1");
    assert_eq!(kv["pmacro.10001"], "10001,-3,0");
    assert_eq!(kv["pmacro.10002"], "10002,0,-1");
    assert_eq!(kv["pmacro.absent"], fwlib32::ew::EW_NUMBER.to_string());
    // Written from C, read back from C and in the simulator's store.
    assert_eq!(kv["written.10002"], "10002,-475,2");
    assert_eq!(kv["written.10003"], "10003,0,-1");
    // The range after the writes: the profile's, then the written ones.
    let rec = |n: i32| match n {
        10002 => (-475, 2),
        10003 => (0, -1),
        n => pm.vars.values.get(&n).copied().unwrap_or((0, -1)),
    };
    let want: Vec<String> = std::iter::once("10000,10004".to_string())
        .chain((10000..=10004).map(|n| format!("{},{}", rec(n).0, rec(n).1)))
        .collect();
    assert_eq!(kv["range"], want.join(";"));
    assert_eq!(kv["range.short"], fwlib32::ew::EW_LENGTH.to_string());
    assert_eq!(kv["range.backwards"], fwlib32::ew::EW_NUMBER.to_string());
    assert_eq!(kv["wr.local"], fwlib32::ew::EW_NUMBER.to_string());
    assert_eq!(kv["wr.dec"], fwlib32::ew::EW_DATA.to_string());
    assert_eq!(kv["wr.absent"], fwlib32::ew::EW_NUMBER.to_string());
    // The simulator keeps them: read on a connection of its own, after the
    // C program ended; the refused writes changed nothing.
    let read = |n: i32| {
        let mut h = 0u16;
        let ip = std::ffi::CString::new("127.0.0.1").unwrap();
        let rc = unsafe { fwlib32::cnc_allclibhndl3(ip.as_ptr(), sim.port(), 10, &mut h) };
        assert_eq!(rc, fwlib32::ew::EW_OK);
        let mut pm = fwlib32::types::ODBPM::default();
        let rc = unsafe { fwlib32::cnc_rdpmacro(h, std::os::raw::c_long::from(n), &mut pm) };
        fwlib32::cnc_freelibhndl(h);
        assert_eq!(rc, fwlib32::ew::EW_OK);
        (pm.mcr_val, pm.dec_val)
    };
    // cnc_wrpmacror: 200 variables written in one call (two requests),
    // read back from C; a 16i's binary records are kept in their shortest
    // decimal form (20 with 1 place reads back as 2, 0 places).
    let s16 = p.cnc.class == fwlib32::sim::profile::Class::Series16;
    let kept = |v: i32, d: i16| {
        let (mut v, mut d) = (v, d);
        while s16 && d > 0 && v % 10 == 0 {
            v /= 10;
            d -= 1;
        }
        (v, d)
    };
    let first = |i: i32| kept(i * 3 - 100, (i % 4) as i16);
    let list = |f: &dyn Fn(i32) -> (i32, i16)| {
        (0..200)
            .map(|i| {
                let (v, d) = f(i);
                format!("{v},{d}")
            })
            .collect::<Vec<_>>()
            .join(";")
    };
    assert_eq!(kv["wr200"], list(&first));
    // The second write (#10023..#10222): its first request (#10023..#10199)
    // written, the second (#10200.., which the CNC does not have) refused
    // whole.
    assert_eq!(kv["wr200.refused"], fwlib32::ew::EW_NUMBER.to_string());
    let second = |i: i32| {
        if i >= 23 {
            (1000 + i - 23, 0)
        } else {
            first(i)
        }
    };
    assert_eq!(kv["wr200.after"], list(&second));
    assert_eq!(kv["wrr.length"], fwlib32::ew::EW_LENGTH.to_string());
    assert_eq!(kv["wrr.local"], fwlib32::ew::EW_NUMBER.to_string());
    assert_eq!(kv["wrr.backwards"], fwlib32::ew::EW_NUMBER.to_string());
    assert_eq!(kv["wrr.dec"], fwlib32::ew::EW_DATA.to_string());
    assert_eq!(kv["wrr.absent"], fwlib32::ew::EW_NUMBER.to_string());
    // The refused calls changed nothing.
    assert_eq!(kv["wr200.end"], list(&second));
    // cnc_wrpmacror2 / cnc_rdpmacror2: doubles written from C, read back
    // bit-exact from C, and as value records by cnc_rdpmacror (the same
    // store, each double kept with its fewest decimal places).
    assert_eq!(kv["d.wr.num"], "3");
    assert_eq!(kv["d.rd.num"], "3");
    assert_eq!(kv["d.rd"], "2.5;-0.125;1234.5");
    assert_eq!(kv["d.records"], "25,1,-125,3,12345,1");
    assert_eq!(kv["d.wr200.num"], "200");
    assert_eq!(kv["d.rd200.num"], "200");
    assert_eq!(kv["d.rd200.same"], "1");
    // #10190..#10199: the store's last ten.
    let last = (10190..).take_while(|n| pm.vars.exists(*n)).count();
    assert_eq!(kv["d.huge.num"], last.to_string());
    assert_eq!(last, 10);
    assert_eq!(kv["d.zero"], format!("{},0", fwlib32::ew::EW_LENGTH));
    assert_eq!(kv["d.type"], format!("{},3", fwlib32::ew::EW_ATTRIB));
    assert_eq!(kv["d.absent"], format!("{},3", fwlib32::ew::EW_NUMBER));
    // The store holds the 200 doubles (i · 0.25 - 10) after the C program
    // ended; the refused write changed nothing (#10198, #10199).
    for n in [10000, 10001, 10010, 10012, 10190, 10198, 10199] {
        let x = f64::from(n - 10000) * 0.25 - 10.0;
        let want = fwlib32::sim::macros::double_to_decimal(x).expect("a decimal");
        assert_eq!(read(n), (want.0, want.1), "#{n} in the simulator");
    }
    assert_eq!(read(10001), (-975, 2));
}
