//! Structure layouts: every struct/union typedef of include/fwlib32.h, compiled
//! by the C compiler, has the `l32` sizeof/offsetof of FANUC's header recorded
//! in `focas-protocol/layouts.json` (what FANUC's x86-64 library really reads
//! and writes); the Rust types of src/types/ have the same layouts.
//!
//! layouts.json is test data in this repository (tests/focas-protocol, its
//! README.md says where it comes from).

use crate::toolchain;

use serde_json::Value;
use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::process::Command;
use toolchain::{
    cc, header_path, header_text, header_typedefs, manifest_dir, run, scratch, target_command,
};

fn layouts() -> Value {
    let path = manifest_dir().join("tests/focas-protocol/layouts.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "cannot read {}: {e}.\nThe layout check needs tests/focas-protocol/layouts.json.",
            path.display()
        )
    });
    let mut layouts: Value =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    layouts
        .as_object_mut()
        .unwrap()
        .extend(power_mate_d_layouts());
    layouts
}

/// The three structures FANUC's header declares only under `#if defined (PMD)`
/// (Power Mate D/H: cnc_opdi, cnc_refpoint … cnc_setfin), which layouts.json,
/// made from the default variant, lacks: their `l32` layouts by hand, in its form.
fn power_mate_d_layouts() -> serde_json::Map<String, Value> {
    use serde_json::json;
    let field = |name: &str, offset: u64, size: u64, ty: &str| json!({"name": name, "offset": offset, "size": size, "type": ty});
    let chars = |name: &str, offset: u64, count: u64| {
        json!({"name": name, "offset": offset, "size": count, "type": "char",
               "count": count, "elem_size": 1})
    };
    let entry = |size: u64, fields: Vec<Value>| json!({"kind": "struct", "l32": {"size": size, "fields": fields}});
    let mut union = field("u", 4, 4, "union");
    union["fields"] = json!([
        field("cdata", 0, 1, "char"),
        field("idata", 0, 2, "short"),
        field("ldata", 0, 4, "long"),
    ]);
    let mut m = serde_json::Map::new();
    m.insert(
        "ODBOPDI".into(),
        entry(8, vec![field("axis", 0, 2, "short"), union]),
    );
    m.insert(
        "ODBEXEC".into(),
        entry(
            18,
            vec![field("dummy", 0, 2, "short"), chars("cdata", 2, 16)],
        ),
    );
    m.insert(
        "ODBFIN".into(),
        entry(
            10,
            vec![field("dummy", 0, 2, "short"), chars("cdata", 2, 8)],
        ),
    );
    m
}

/// The `pub struct` / `pub union` names of src/types/.
fn rust_type_names() -> BTreeSet<String> {
    let mut text = String::new();
    for e in std::fs::read_dir(manifest_dir().join("src/types")).unwrap() {
        text.push_str(&std::fs::read_to_string(e.unwrap().path()).unwrap());
    }
    text.lines()
        .filter_map(|l| {
            let l = l.trim();
            let rest = l
                .strip_prefix("pub struct ")
                .or_else(|| l.strip_prefix("pub union "))?;
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            Some(name)
        })
        .collect()
}

/// One member (or whole type) to compare: `label` is `TYPE.path.to.member`.
/// Offsets of nested members are relative to the enclosing member (its first
/// element for arrays), as layouts.json records them.
struct Expect {
    label: String,
    field: String,
    size: u64,
    offset: u64,
    /// Element size, for arrays (layouts.json records multi-dimensional arrays
    /// flattened: element = scalar).
    elem: Option<u64>,
}

/// Walks layouts.json fields, appending the C statements that print the
/// same facts (`label size offset elem`, elem 0 for a non-array).
fn emit_fields(
    c: &mut String,
    out: &mut Vec<Expect>,
    fields: &[Value],
    base: &str,
    label: &str,
    header: &str,
) {
    for f in fields {
        let name = f["name"].as_str().unwrap();
        let expr = format!("{base}.{name}");
        let label = format!("{label}.{name}");
        let elem = f.get("count").map(|_| f["elem_size"].as_u64().unwrap());
        out.push(Expect {
            label: label.clone(),
            field: name.to_owned(),
            size: f["size"].as_u64().unwrap(),
            offset: f["offset"].as_u64().unwrap(),
            elem,
        });
        let elem_expr = match elem {
            Some(_) => format!("sizeof({expr}[0])"),
            None => "0".to_owned(),
        };
        writeln!(
            c,
            "    printf(\"{label} %lu %lu %lu\\n\", (unsigned long)sizeof({expr}), \
             (unsigned long)((const char *)&{expr} - (const char *)&{base}), \
             (unsigned long){elem_expr});"
        )
        .unwrap();
        if let Some(sub) = f.get("fields").and_then(Value::as_array) {
            let inner = match elem {
                Some(_) => format!("{expr}{}", "[0]".repeat(struct_array_dims(header, name))),
                None => expr.clone(),
            };
            emit_fields(c, out, sub, &inner, &label, header);
        }
    }
}

/// How many dimensions the header gives the array of structures `field`
/// (`struct T field[2][32];`: 2), so its first element is reached.
fn struct_array_dims(header: &str, field: &str) -> usize {
    let pat = format!(" {field}[");
    header
        .lines()
        .filter(|l| {
            let t = l.trim_start();
            t.starts_with("struct ") || t.starts_with("union ")
        })
        .filter_map(|l| l.split_once(&pat).map(|(_, r)| r.matches('[').count() + 1))
        .max()
        .unwrap_or(1)
}

/// Whether the header declares `field` as a multi-dimensional array somewhere.
fn multi_dimensional(header: &str, field: &str) -> bool {
    let pat = format!(" {field}[");
    header
        .lines()
        .any(|l| l.contains(&pat) && l.split_once(&pat).is_some_and(|(_, r)| r.contains("][")))
}

/// Whether a typedef is used by another one (a named helper type for a nested
/// member, which FANUC's header declares inline and layouts.json does not list).
fn used_elsewhere(header: &str, name: &str) -> bool {
    header.lines().any(|l| {
        let t = l.trim();
        !t.starts_with("typedef ")
            && !t.starts_with('}')
            && !t.contains('(')
            && t.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                .any(|w| w == name)
    })
}

/// Compiles one C program that prints the layout of every header typedef also
/// in layouts.json, runs it, and compares with the `l32` layouts.
#[test]
fn header_structs_match_l32_layouts() {
    let layouts = layouts();
    let header = header_text();
    let typedefs = header_typedefs(&header);
    assert!(
        !typedefs.is_empty(),
        "no `typedef struct X {{` found in include/fwlib32.h"
    );

    let mut globals = String::new();
    let mut body = String::new();
    let mut expected = Vec::new();
    let mut checked = BTreeSet::new();
    let mut unknown = Vec::new();
    for (kind, name) in &typedefs {
        let Some(entry) = layouts.get(name.as_str()) else {
            unknown.push(name.clone());
            continue;
        };
        assert_eq!(
            entry["kind"].as_str(),
            Some(kind.as_str()),
            "{name}: FANUC's is a {}, ours a {kind}",
            entry["kind"]
        );
        let l32 = &entry["l32"];
        let var = format!("v_{name}");
        writeln!(globals, "static {name} {var};").unwrap();
        expected.push(Expect {
            label: name.clone(),
            field: String::new(),
            size: l32["size"].as_u64().unwrap(),
            offset: 0,
            elem: None,
        });
        writeln!(
            body,
            "    printf(\"{name} %lu 0 0\\n\", (unsigned long)sizeof({name}));"
        )
        .unwrap();
        emit_fields(
            &mut body,
            &mut expected,
            l32["fields"].as_array().unwrap(),
            &var,
            name,
            &header,
        );
        checked.insert(name.clone());
    }
    let strangers: Vec<_> = unknown
        .iter()
        .filter(|n| !used_elsewhere(&header, n))
        .collect();
    assert!(
        strangers.is_empty(),
        "include/fwlib32.h declares {strangers:?}, which FANUC's header (layouts.json) does not \
         have and no other structure uses: structures of fwlib32.h keep FANUC's names"
    );
    if !unknown.is_empty() {
        eprintln!("helper types for nested members (checked through their users): {unknown:?}");
    }

    let c = format!(
        "#include <stdio.h>\n#include \"fwlib32.h\"\n\n{globals}\nint main(void)\n{{\n{body}    return 0;\n}}\n"
    );
    let dir = scratch("abi-layouts");
    let src = dir.join("layouts.c");
    let exe = dir.join("layouts");
    std::fs::write(&src, &c).unwrap();
    run(Command::new(cc())
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-o"])
        .arg(&exe)
        .arg("-I")
        .arg(header_path().parent().unwrap())
        .arg(&src));
    let out = run(&mut target_command(&exe));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let actual: Vec<(String, [u64; 3])> = stdout
        .lines()
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            let n = |i: usize| w[i].parse::<u64>().unwrap();
            (w[0].to_owned(), [n(1), n(2), n(3)])
        })
        .collect();
    assert_eq!(actual.len(), expected.len(), "output of {}", exe.display());

    let mut mismatches = Vec::new();
    for (e, (label, [size, offset, elem])) in expected.iter().zip(&actual) {
        assert_eq!(&e.label, label);
        let elem_ok = match e.elem {
            None => true,
            Some(want) => {
                *elem == want
                    || (*elem % want == 0 && *elem > want && multi_dimensional(&header, &e.field))
            }
        };
        if e.size != *size || e.offset != *offset || !elem_ok {
            mismatches.push(format!(
                "  {label}: layouts.json l32 size {} offset {} elem {:?}; fwlib32.h size {size} \
                 offset {offset} elem {elem}",
                e.size, e.offset, e.elem
            ));
        }
    }
    assert!(
        mismatches.is_empty(),
        "structure layouts of include/fwlib32.h differ from FANUC's (l32), see {}:\n{}",
        src.display(),
        mismatches.join("\n")
    );

    // At least today's structures, and every structure of src/types/ that
    // FANUC's header has (the others must be helper types, checked above).
    let mut must: BTreeSet<String> = ["ODBSYS", "ODBST", "ODBST2", "ODBERR"]
        .map(String::from)
        .into();
    must.extend(
        rust_type_names()
            .into_iter()
            .filter(|n| layouts.get(n.as_str()).is_some() || !unknown.contains(n)),
    );
    let missing: Vec<_> = must.difference(&checked).collect();
    assert!(
        missing.is_empty(),
        "not checked (missing from include/fwlib32.h?): {missing:?}; checked: {checked:?}"
    );
    eprintln!("checked {} structures: {checked:?}", checked.len());
}

fn field_size<T, F>(_: fn(&T) -> *const F) -> usize {
    std::mem::size_of::<F>()
}

/// The Rust types, field by field, against the same layouts.
macro_rules! rust_layouts {
    ($name:ident; $($ty:ident { $($field:ident),* $(,)? })*) => {
        pub(super) fn $name() -> Vec<(&'static str, usize, Vec<(&'static str, usize, usize)>)> {
            use fwlib32::types::*;
            vec![$(
                (
                    stringify!($ty),
                    std::mem::size_of::<$ty>(),
                    vec![$((
                        // `r#type` is FANUC's `type`.
                        stringify!($field).trim_start_matches("r#"),
                        std::mem::offset_of!($ty, $field),
                        // A raw pointer: a union's field too, without reading it.
                        $crate::abi::field_size(|v: &$ty| std::ptr::addr_of!(v.$field)),
                    )),*],
                ),
            )*]
        }
    };
}

// The types of the functions no FANUC Ethernet library implements (src/spec/table/absent.rs).
mod absent_types;

// Every structure of src/types/ must be listed here or in abi/absent_types.rs (checked below).
rust_layouts! {
    rust_layouts;
    ODBSYS { addinfo, max_axis, cnc_type, mt_type, series, version, axes }
    ODBSYSH { id1, id2, group_id, hard_id, hard_num, slot_no, id1_format, id2_format }
    ODBSYSS3 { soft_id, soft_series, soft_edition }
    ODBSYSS3_STR { soft_id, soft_name, soft_series, soft_edition, dummy }
    ODBSYSS { slot_no_p, slot_no_l, module_id, soft_id, soft_series, soft_version, soft_inst, boot_ser, boot_ver, servo_ser, servo_ver, pmc_ser, pmc_ver, ladder_ser, ladder_ver, mcrlib_ser, mcrlib_ver, mcrapl_ser, mcrapl_ver, spl1_ser, spl1_ver, spl2_ser, spl2_ver, spl3_ser, spl3_ver, c_exelib_ser, c_exelib_ver, c_exeapl_ser, c_exeapl_ver, int_vga_ser, int_vga_ver, out_vga_ser, out_vga_ver, pmm_ser, pmm_ver, pmc_mng_ser, pmc_mng_ver, pmc_shin_ser, pmc_shin_ver, pmc_shout_ser, pmc_shout_ver, pmc_c_ser, pmc_c_ver, pmc_edit_ser, pmc_edit_ver, lddr_mng_ser, lddr_mng_ver, lddr_apl_ser, lddr_apl_ver, spl4_ser, spl4_ver, mcr2_ser, mcr2_ver, mcr3_ser, mcr3_ver, eth_boot_ser, eth_boot_ver, reserve }
    ODBSYSS2 { slot_no_p, slot_no_l, module_id, soft_id, soft_series, soft_version, soft_inst, boot_ser, boot_ver, servo_ser, servo_ver, pmc_ser, pmc_ver, ladder_ser, ladder_ver, mcrlib_ser, mcrlib_ver, mcrapl_ser, mcrapl_ver, spl1_ser, spl1_ver, spl2_ser, spl2_ver, spl3_ser, spl3_ver, c_exelib_ser, c_exelib_ver, c_exeapl_ser, c_exeapl_ver, int_vga_ser, int_vga_ver, out_vga_ser, out_vga_ver, pmm_ser, pmm_ver, pmc_mng_ser, pmc_mng_ver, pmc_shin_ser, pmc_shin_ver, pmc_shout_ser, pmc_shout_ver, pmc_c_ser, pmc_c_ver, pmc_edit_ser, pmc_edit_ver, lddr_mng_ser, lddr_mng_ver, lddr_apl_ser, lddr_apl_ver, spl4_ser, spl4_ver, mcr2_ser, mcr2_ver, mcr3_ser, mcr3_ver, eth_boot_ser, eth_boot_ver, reserve, embEthe_ser, embEthe_ver, reserve2 }
    ODBCSVID { mt_spc, mt_srn, plc_spc, plc_srn, svm_spc, svm_srn, psm_spc, psm_srn }
    ODBCSPID { mt_spc, mt_srn, sbmt_spc, sbmt_srn, spm_spc, spm_srn, psm_spc, psm_srn }
    ODBCSVID2 {
        mt_spc, mt_srn, plc_spc, plc_srn, svm_spc, svm_srn, psm_spc, psm_srn,
        svs_see, pss_see, pm1_spc, pm1_srn, pm2_spc, pm2_srn,
    }
    ODBCSPID2 { mt_spc, mt_srn, sbmt_spc, sbmt_srn, spm_spc, spm_srn, psm_spc, psm_srn, pss_see }
    ODBFIX { mode, pln_axes, drl_axes, i_pos, r_pos, z_pos, cmd_cnt, act_cnt, cut, shift }
    ODBEXPOS { data, dec, digit }
    IODBTLINTF { inf_tool }
    ODBROT { mode, pln_axes, center, angle }
    ODBST { hdck, tmmode, aut, run, motion, mstb, emergency, alarm, edit }
    ODBST2 {
        hdck, tmmode, aut, run, motion, mstb, emergency, alarm, edit,
        warning, o3dchk, ext_opt, restart,
    }
    ODBERR { err_no, err_dtno }
    IODBSGNL {
        datano, r#type, mode, hndl_ax, hndl_mv, rpd_ovrd, jog_ovrd, feed_ovrd, spdl_ovrd,
        blck_del, sngl_blck, machn_lock, dry_run, mem_prtct, feed_hold,
    }
    IODBGNRL { datano, r#type, sgnal }
    IODBRDNA {
        datano, r#type, sgnl1_name, sgnl2_name, sgnl3_name, sgnl4_name, sgnl5_name, sgnl6_name,
        sgnl7_name, sgnl8_name,
    }
    IODBGNRL2 { datano, r#type, sgnal }
    IODBRDNA2 {
        datano, r#type, sgnl1_name, sgnl2_name, sgnl3_name, sgnl4_name, sgnl5_name, sgnl6_name,
        sgnl7_name, sgnl8_name, sgnl9_name, sgnl10_name, sgnl11_name, sgnl12_name, sgnl13_name,
        sgnl14_name, sgnl15_name, sgnl16_name,
    }
    ODBCSS { srpm, sspm, smax }
    ODBTLINFO { max_group, max_tool, max_minute, max_cycle }

    // --- position ---
    ODBAXISNAME { name, suff }
    ODBSPDLNAME { name, suff1, suff2, suff3 }
    ODBDY2 { dummy, axis, alarm, prgnum, prgmnum, seqnum, actf, acts, pos }
    ODBDY { dummy, axis, alarm, prgnum, prgmnum, seqnum, actf, acts, pos }
    ODBDYO8 { dummy, axis, alarm, prgnum, prgmnum, seqnum, actf, acts, pos }
    ODBACT { dummy, data }
    ODBACT2 { datano, r#type, data }
    SPEEDELM { data, dec, unit, disp, name, suff }
    ODBSPEED { actf, acts }
    LOADELM { data, dec, unit, name, suff1, suff2, reserve }
    ODBSPLOAD { spload, spspeed }
    ODBSVLOAD { svload }
    ODBSPN { datano, r#type, data }
    ODBAXDT { name, data, dec, unit, flag, reserve }
    POSELM { data, dec, unit, disp, name, suff }
    ODBPOS { abs, mach, rel, dist }
    ODBAXIS { dummy, r#type, data }

    // --- program ---
    ODBPRO { dummy, data, mdata }
    ODBPROO8 { dummy, data, mdata }
    ODBSEQ { dummy, data }
    ODBEXEPRG { name, o_num }
    ODBMDL { datano, r#type, modal }
    IODBTIME { minute, msec }
    IODBTIMER { r#type, dummy, data }
    ODBTLIFE3 { datano, dummy, data }
    ODBTLIFE4 { datano, r#type, data }
    PRGDIR { prg_data }
    PRGDIR3 { number, length, page, comment, mdate, cdate }
    PRGDIR2 { number, length, comment, dummy }
    PRGDIR2O8 { number, length, comment, dummy }
    ODBNC { u }
    ODBMDIP { mdiprog, mdipntr, crntprog, crntpntr }
    ODBMDIPO8 { mdiprog, mdipntr, crntprog, crntpntr }
    ODBPDFDRV { max_num, dummy, drive }
    ODBPDFINF { used_page, all_page, used_dir, all_dir }
    ODBPDFNFIL { dir_num, file_num }
    IDBPDFSDIR { path, req_num, dummy }
    ODBPDFSDIR { sub_exist, dummy, d_f }
    IDBPDFADIR { path, req_num, size_kind, r#type, dummy }
    ODBPDFADIR {
        data_kind, year, mon, day, hour, min, sec, dummy, dummy2, size, attr, d_f, comment, o_time,
    }

    // --- alarm ---
    ODBALM { dummy, data }
    ODBALMMSG { alm_no, r#type, axis, dummy, msg_len, alm_msg }
    ODBALMMSG2 { alm_no, r#type, axis, dummy, msg_len, alm_msg }
    ODBALMMSG3 { alm_no, r#type, axis, dummy, msg_len, alm_msg }
    PRGPNT { prog_no, blk_no }
    ALMINFO { u }
    OPMSG { datano, r#type, char_num, data }

    // --- param ---
    REALPRM { prm_val, dec_val }
    REALDGN { dgn_val, dec_val }
    IODBPSD { datano, r#type, u }
    ODBDGN { datano, r#type, u }
    IODBPRM { datano, r#type, axis, info, unit, data }
    ODBPARAIF { info_no, prev_no, next_no, info }
    ODBDIAGIF { info_no, prev_no, next_no, info }
    ODBPARANUM { para_min, para_max, total_no }
    ODBSETNUM { set_min, set_max, total_no }
    ODBDIAGNUM { diag_min, diag_max, total_no }

    // --- macros ---
    ODBM { datano, dummy, mcr_val, dec_val }
    IODBMR { datano_s, dummy, datano_e, data }
    ODBMVINF { use_no1, use_no2 }
    ODBPMINF { use_no1, use_no2, v2_type }

    // --- pmc ---
    IODBPMC { type_a, type_d, datano_s, datano_e, u }
    ODBPMCINF { datano, info }
    ODBPMCTITLE { mtb, machine, r#type, prgno, prgvers, prgdraw, date, design, written, remarks }
    ODBPMCTITLE2 { mtb, machine, r#type, prgno, prgvers, prgdraw, date, design, written, remarks }
    ODBPMCLADMEMTYPE { SystemType, SystemAttribute, TargetType, TargetAttribute, SystemTypeStr, TargetTypeStr }
    ODBPMCALM { almmsg }
    IODBPMAINTE { name, r#type, total, remain, stat }
    ODBPMCERR { err_no, err_dtno }

    // --- offset ---
    ODBTOFS { datano, r#type, data }
    IODBTO { datano_s, r#type, datano_e, u }
    ODBTLINF { ofs_type, use_no }
    IODBZOFS { datano, r#type, data }
    IODBWCSF { datano, r#type, data }
    ODBTLIFE5 { dummy, r#type, data }
    IDBITD { datano, r#type, data }
    IODBZOR { datano_s, r#type, datano_e, data }
    // alarm history (offset helper)
    ODBAHIS { s_no, r#type, e_no, alm_his }
    ODBAHIS2 { s_no, e_no, alm_his }
    ODBHIS { s_no, r#type, e_no, data }
    ODBOMHIS { om_no, year, month, day, hour, minute, second, om_msg }
    ODBOMHIS2 { s_no, e_no, opm_his }
    ODBAHIS5 { s_no, e_no, alm_his }
    IODBPI { datano_s, dummy, datano_e, data }
    ODBPARAIF2 { prm_no, size, array, unit, dim, input, display, others }

    // --- tool ---
    ODBTLIFE3 { datano, dummy, data }
    ODBTG { grp_num, dummy, ntool, life, count, data }
    IODBTGI { s_grp, dummy, e_grp, data }
    ODBUSEGRP { next, r#use, slct, opt_next, opt_use, opt_slct }
    IODBTLMAG { magazine, pot, tool_index }
    IODBTLMAG2 { magazine, pot }
    ODBUSEGR { datano, r#type, next, r#use, slct }
    ODBLFNO { datano, r#type, data }
    IODBTD { datano, r#type, tool_num, h_code, d_code, tool_inf }
    // tool life and offsets, family B
    IODBTD2 { datano, dummy, r#type, tool_num, h_code, d_code, tool_inf }
    IODBTR { datano_s, dummy, datano_e, data }
    ODBTLUSE { s_grp, dummy, e_grp, data }
    IODBTLTOOL { tool_num, h_code, d_code, tool_inf }
    ODBEXGP { grp_no, opt_grpno }
    ODBDATRNG { data_min, data_max, status }
    ODBVOLCOMP { comp }
    ODBTLIFE1 { dummy, r#type, data }
    ODBBTLINF { ofs_type, use_no, sub_no }
    ODBROFS { mode, pln_axes, ofsvct }
    ODB3DTO { mode, ofs_axes, ofsvct }
    ODBTLDATA { tl, tl_dp }
    ODBTLMSINF { t, m, hm, hm_dp, tlofs_no }
    IODBTLMNG {
        T_code, life_count, max_life, rest_life, life_stat, cust_bits, tool_info, H_code, D_code,
        spindle_speed, feedrate, magazine, pot, G_code, W_code, gno, grp, edge, org_magazine,
        org_pot, edge_num, reserve_c, reserved, custom1, custom2, custom3, custom4, custom5,
        custom6, custom7, custom8, custom9, custom10, custom11, custom12, custom13, custom14,
        custom15, custom16, custom17, custom18, custom19, custom20
    }
    IODBTLMNG_F2 {
        T_code, life_count, max_life, rest_life, life_stat, cust_bits, tool_info, H_code, D_code,
        spindle_speed, feedrate, magazine, pot, G_code, W_code, gno, grp, edge, org_magazine,
        org_pot, edge_num, reserve_c, reserved, custom1, custom2, custom3, custom4, custom5,
        custom6, custom7, custom8, custom9, custom10, custom11, custom12, custom13, custom14,
        custom15, custom16, custom17, custom18, custom19, custom20, custom21, custom22, custom23,
        custom24, custom25, custom26, custom27, custom28, custom29, custom30, custom31, custom32,
        custom33, custom34, custom35, custom36, custom37, custom38, custom39, custom40
    }
    IODBTLDT {
        slct, tool_no, x_axis_ofs, y_axis_ofs, turret_pos, chg_tl_no, punch_count, tool_life,
        m_tl_radius, m_tl_angle, tl_shape, tl_size_i, tl_size_j, tl_angle, x_axis_dec, y_axis_dec,
        turret_dec, m_radius_dec, m_angle_dec, tl_size_i_dec, tl_size_j_dec, tl_angle_dec, reserve
    }
    ODBPTLINF { tld_max, mlt_max, reserve, tld_size, mlt_size, reserves }
    ODBTLIFE2 { dummy, data }
    ODBPTIME { num, data }
    ODBOMIF { om_max, om_sum, om_char }
    ODBTLINF2 { ofs_type, use_no, ofs_enable }
    ODBSYSEX {
        max_axis, max_spdl, max_path, max_mchn, ctrl_axis, ctrl_srvo, ctrl_spdl, ctrl_path,
        ctrl_mchn, addinfo, reserved, path,
    }
    IODBTLCTL {
        slct, used_tool, turret_indx, zero_tl_no, t_axis_move, total_punch,
        t_axis_dec, reserve, reserves,
    }

    // --- upload ---
    ODBUP { dummy, data }

    // --- machine data (issue 11) ---
    ODBOPHIS4 { rec_len, rec_type, u }
    OPMSG3 { datano, r#type, char_num, data }
    ODBSPDI { sgnl1, sgnl2, sgnl3, sgnl4 }
    ODBSPDO { sgnl1, sgnl2, sgnl3, sgnl4 }
    ODBPRS { datano, r#type, data_info, rstr_bc, rstr_m, rstr_t, rstr_s, rstr_b, dest, dist }

    // --- the signals the operation history records ---
    IODBSIG { datano, r#type, data }
    IODBSIG3 { datano, r#type, data }

    // --- tool_axis collectors (issue 24) ---
    ODBPSER { poserr1, poserr2 }
    ODBCMD { adrs, num, flag, cmd_val, dec_val }
    ODB3DHDL { axes, data }

    // --- servo data sampling (issue 24) ---
    IDBSDTCHAN { r#type, chno, axis, shift }

    // --- P-code macros and settings (issue 24) ---
    ODBPM { datano, dummy, mcr_val, dec_val }
    ODBPMINF2 { use_no1, use_no2, use_no20, v1_type, v2_type, v20_type }
    IODBPR { datano_s, dummy, datano_e, data }
}

#[test]
fn rust_types_match_l32_layouts() {
    let layouts = layouts();
    let mut listed = rust_layouts();
    listed.extend(absent_types::absent_layouts());
    let names: BTreeSet<String> = listed.iter().map(|t| t.0.to_owned()).collect();
    let in_types = rust_type_names();
    // Helper types for nested members (not in layouts.json) are checked
    // through the structures that use them.
    let unlisted: Vec<_> = in_types
        .difference(&names)
        .filter(|n| layouts.get(n.as_str()).is_some())
        .collect();
    assert!(
        unlisted.is_empty(),
        "add {unlisted:?} (with all their fields) to rust_layouts! in tests/artifacts/abi.rs"
    );
    for (name, size, fields) in listed {
        let l32 = &layouts[name]["l32"];
        assert!(l32.is_object(), "{name} is not in layouts.json");
        assert_eq!(
            size as u64,
            l32["size"].as_u64().unwrap(),
            "size_of::<{name}>()"
        );
        let want = l32["fields"].as_array().unwrap();
        // A field named like a Rust keyword is spelled `r#type` in Rust.
        let got: Vec<&str> = fields
            .iter()
            .map(|f| f.0.trim_start_matches("r#"))
            .collect();
        let want_names: Vec<&str> = want.iter().map(|f| f["name"].as_str().unwrap()).collect();
        assert_eq!(got, want_names, "{name}: fields (names, order)");
        for ((field, offset, fsize), w) in fields.iter().zip(want) {
            assert_eq!(
                *offset as u64,
                w["offset"].as_u64().unwrap(),
                "offset_of!({name}, {field})"
            );
            assert_eq!(
                *fsize as u64,
                w["size"].as_u64().unwrap(),
                "size of {name}.{field}"
            );
        }
    }
}
