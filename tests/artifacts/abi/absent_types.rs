//! The Rust types of the functions FANUC's header declares and no FANUC Ethernet library
//! implements, field by field, against layouts.json (the list of abi.rs, continued).

rust_layouts! {
    absent_layouts;
    // --- src/types/status_ext.rs ---
    ALMINFO2 { u }
    CEXEINFO { cond, cycle, count, time, dummy1, dummy2, dummy3, dummy4 }
    IODBBOOK { param_no, axis, r#type, u }
    IODBIDINF { id_no, drv_no, acc_element, err_general, err_id_no, err_id_name, err_attr, err_unit, err_min_val, err_max_val, id_name_len, id_name_max, id_name, attr, unit_len, unit_max, unit, min_val, max_val }
    IODBMRN { mcr_val, name }
    IODBMRN4 { mcr_val, name }
    ODBACTPTW { mprgno, mblkno, sprgno, sblkno }
    ODBAHIS3 { s_no, e_no, alm_his }
    ODBDLLVERSION { dll }
    ODBDY3 { dummy, axis, alarm, prgnum, prgmnum, seqnum, actf, acts, pos }
    ODBDY3M { dummy, axis, alarm, prgnum, prgmnum, seqnum, actf, acts, pos }
    ODBEXEPRGINFO { before_buffering, after_buffering }
    ODBLALMHIS { s_no, e_no, alm_his }
    ODBM3 { datano, mcr_val, dec_val }
    ODBMDLC { from, dram, sram, pmc, crtc, servo12, servo34, servo56, servo78, sic, pos_lsi, hi_aio, reserve, drmmrc, drmarc, pmcmrc, dmaarc, iopt, hdiio, gm2gr1, crtgr2, gm1gr2, gm2gr2, cmmrb, sv5axs, sv7axs, sicaxs, posaxs, hamaxs, romr64, srmr64, dr1r64, dr2r64, iopio2, hdiio2, cmmrb2, romfap, srmfap, drmfap, drmare, pmcmre, dmaare, frmbgg, drmbgg, asrbgg, edtpsc, slcpsc, reserve2 }
    ODBPMINF3 { use_no1, use_no2, v1_type, v2_type }
    ODBPMVALFLG { exe_type, aux_type, tlk_type }
    ODBPRTCT2 { disp, edit, encd, lock, output, dummy }
    ODBPTIME3 { hour, min, sec, dummy }
    ODBSRCSLYT { spndl, servo, axis_name }
    ODBSRCSST { acc_element, err_general, err_id_no, err_attr, err_op_data }
    ODBSYSC { slot_no_p, slot_no_l, mod_id, soft_id, s_series, s_version, dummy, m_rom, s_rom, svo_soft, pmc_soft, lad_soft, mcr_soft, spl1_soft, spl2_soft, frmmin, drmmin, srmmin, pmcmin, crtmin, sv1min, sv3min, sicmin, posmin, drmmrc, drmarc, pmcmrc, dmaarc, iopt, hdiio, frmsub, drmsub, srmsub, sv5sub, sv7sub, sicsub, possub, hamsub, gm2gr1, crtgr2, gm1gr2, gm2gr2, cmmrb, sv5axs, sv7axs, sicaxs, posaxs, hanaxs, romr64, srmr64, dr1r64, dr2r64, iopio2, hdiio2, cmmrb2, romfap, srmfap, drmfap }
    OPMSGMPS { datano, r#type, char_num, data }
    EXEPRG { length, prep_blk, act_blk, dummy, data }

    // --- src/types/machining.rs ---
    HSPDATA { cdata, idata, ldata, rdata }
    HSPDATAM { cdata, idata, ldata, rdata }
    HSPINFO { prminfo }
    IDBLSWORK { slct, skeyinf, reserve }
    IODBCTPR { data, prm }
    IODBCTPRM { data, prm }
    IODBHPAC { tune }
    IODBHPPR { tune }
    IODBHPST { slct, hpcc, multi, ovr1, ign_f, foward, max_f, ovr2, ovr3, ovr4, reserve }
    IODBPSCD2 { slct, feed, power, freq, duty, g_press, g_kind, g_ready_t, displace, supple, edge_slt, appr_slt, pwr_ctrl, displace2, gap_axis, feed_dec, supple_dec, dsp2_dec, pb_power, reserve }
    IODBRCT_CSTMNAME { grp_num, dummy, grp_name, ptn_name }
    IODBRCT_GRPPTN { grp_num, ptn_num }
    IODBRCT_ITEM { item_num, r#type, axsp_num, ptn_num, dummy, attr, ptn }
    IODBSOCTLDAT { u }
    ODBMCSHEAD { layout, string1, string2 }
    ODBPRESSURE { cmd_val, feedbak_val }
    ODBRCT_SLCTPTNNAME { sl_ptrn_no, sl_nm_slct }
    ODBSOCCUR { mode, table, dummy, ovrr, load, temp, rdtm }
    ODBSOCTLATTR { prm_no, r#type }
    SCDL_1D { file_no, file_name, repeat_num, current_num, dummy }
    CURRDTM { current, threshold, dummy }
    CURTEMP { current, start, end, alarm, dummy }
    CURLOAD { current, effect, target, irregular, dummy }
    CUROVRR { current, minmum, maximum, dummy }

    // --- src/types/tool_mgmt.rs ---
    IDBITD2 { datano, r#type, data }
    IDBTLMGR_ADD_INFO { dsp_info, data_kind }
    IDBTLM_SRCHDT { id_info, srch_cond, add_cond }
    IODBTLGS { data1, data2, tooltype, install, toolname, dummy }
    IODBTLGSEXT2 { data1, data2, data3, data4, data5, data6, data7, data8, data9, data10, tooltype, install, holder, toolname }
    IODBTLLF { T_code_sum, life_count_sum, rem_life_sum, max_life_sum, notice_life_sum, tools_sum, notice_stat_sum, count_type_sum }
    IODBTLLFD { order, tool_num, life_count, rem_life, max_life, notice_life, life_stat, count_type, reserve }
    IODBTLM2 { number, reserve, item }
    IODBTLMAG_SRCHINFO { startInfo, result }
    IODBTLMGR_CHECK { T_code, tool_num, reserve }
    IODBTLMGR_PAGE { info }
    IODBTLMNG_MU_EDGE_DATA { life_count, max_life, rest_life, life_stat, cust_bits, reserve_s, H_code, D_code, spindle_speed, feedrate, G_code, W_code, custom1, custom2, custom3, custom4 }
    IODBTLMNG_SORT { tl_num, reserve, data }
    IODBTLSPWTNAME { sp_name, wt_name }
    IODBTL_RDTYPE { r#type, data_type, renew, reserve }
    IODBTOOL_CAUSENME { cause1, cause2, cause3, cause4, cause5 }
    IODBTOOL_INHIS { tool_no, reserve, date, tool_f2 }
    IODBTOOL_OUTHIS { tool_no, cause, date, tool_f2 }
    ODBOFSLEN { len, dec }
    ODBPOFS { mode, ofsvct }
    ODBTL_FREE_NUM { edge_gp, ofs_h, ofs_d, ofs_g, ofs_w, reserve }
    IODBTOOL_DATE { year, mon, day, hour, min, sec }
    IODBTLMGR_EDG { data_no, edge_no }
    IDBTLM { data_id, item }

    // --- src/types/power_mate.rs ---
    ODBOPDI { axis, u }
    ODBEXEC { dummy, cdata }
    ODBFIN { dummy, cdata }
    IDBPMMGTI { top, num }
    IDBPMMPRP { chanl, group, folder, warn }
    ODBPMMGET { pos, feed, data, number, axis, r#type, alaxis, alnumber, chanl, group }
    ODBPMMIO { chanlnum }
    ODBPMMPRP { data, number, axis, r#type }
    ODBPMMSLV { slvnum, group }
    ODBPMMSYD { system, model, series, edition }

    // --- src/types/robot.rs ---
    IDBRBGROUP { robot_program, nc_program_folder, nc_program_name }
    IODBRBALMMSG { msg }
    IODBRBCOMSET { di_top, do_top, power_on, di_offset, do_offset, property, reserve }
    IODBRBSIGNAL2 { r#type, state, no, name, reserve }
    IODBRBSUMMARY { signal_type, reserve, no }
    ODBRBGRPLIST { select, robot_program, nc_program_folder, nc_program_name, comment }
    ODBRBSIGNAL { r#type, state, no, name }
    IODBRBPOWERSIG { unit_type, adr_type, address, bit, reserve }
    IODBRBTOPSIG { unit_type, adr_type, address }

    // --- src/types/servo.rs ---
    IDBSDTCHAN2 { r#type, chno, axis, shift, io }
    IDBTRQ { datano, r#type, data }
    IODBPMCEXT { type_a, type_d, datano_s, datano_e, err_code, reserved, data }
    IODBRTMIO { adr_type, dummy, no, bit }
    IODBRTMIOR { adr_type, adr_attr, sno, eno }
    IODBSIG2 { datano, r#type, data }
    ODBEXPMCSGNL { inf, exsgnlterm }
    ODBPMCADR { pmc_adr, adr_attr, adr, top, num }
    ODBP_FTRQ_PRM_INF { smpl_enbl, cycle, axis_num, dummy1 }
    ODBSD { chadata, count }
    ODBSVFBACK { dummy, dtype, fback, afback }
    ODBTUNREQ { stat }
    ODBTUNSTAT { stat }
    ODBWVDT2 { channel, u, start, stop, t_cycle, adjust, data }
    TRG_DATA { seq_no, pmc_trg }
    PMC_DATA { unittype, adr, bit, no }
    ODBEXPMCSGNLTERM { data, dummy }
    ODBEXPMCSGNLINF { pmc_no, kind, length, dummy, top_adrs }

    // --- src/types/panel.rs ---
    IDBTPCMD { cmd_id, integer, val, text }
    IDBTPINFO { prg_name, comment, axis, out_nc_prg, reserve }
    IODBWAITMCODE { mcode, pathnum }
    ODBHMPROGSTAT { run, disp, alm_no, reserve, prog_no, block_no }
    ODBKEYINFO { key }
    ODBTPAPRG { format_version, func_version, size, create, edit, convert, attr, name_copy, prg_name, comment, axis, out_nc_prg, reserve }
    ODBTPEDTCMD { cmd_num, cmd, word_num, word }
    ODBTPNLINTF { status, dummy, coord_x, coord_y }
    OUT_STATINF_DMG { dummy, dmg, dummy1 }
    PMCLAD_MESSAGE { message, lines, color_fg, color_bg }

    // --- src/types/compensation.rs ---
    IDBTWPFORM { euler, rpy, p3, vct2, pjct }
    IODBROTVOLC { lin, rot }
    ODB5DHDL { name, data, dec, flag, axis }
    ODB5DPLS { name, data, dec }
    ODBCBI { cb_no, nme_set, shp_no, cd_form }
    ODBCUB { ref_vtx, adj_vtx1, adj_vtx2, adj_vtx3, n_unit, cb_form }
    ODBCYL { sta_pnt, end_pnt, radius, n_unit, cb_form }
    ODBFOFS { mcrval, decval }
    ODBFTRMTX { orgn, rot }
    ODBLRNINFO { name, dummy1, axis, year, month, day, hour, minute, second, comment, dummy2 }
    ODBLRNINFO2 { name, dummy1, axis, year, month, day, hour, minute, second, comment, dummy2 }
    ODBLRNINFOL { axis, name, comment, path, dummy1 }
    ODBLRNPRF { status, comment, path, dummy1 }
    ODBPLN { point, vect, n_unit, cb_form }
    ODBRENPLT { delay_time, data_flag, pos_data }
    ODBSUODATA { data_name, prm_val, frc_dgt }
    ODBSUOVECT { vect_val, frc_dgt }
    ODBTRNS { status, pct, r#type, dummy }
    ODBNME { ob_type, obj_no, nme_no, suffix, name }
    IDBTWP_PJCT_FMT { orign, i, j, k, reserve }
    IDBTWP_2VCT_FMT { orign, vtr1, vtr2, reserve }
    IDBTWP_3P_FMT { p1, p2, p3, sft, rot, reserve }
    IDBTWP_RPY_FMT { orign, i, j, k, turn, reserve0, reserve }
    IDBTWP_EULER_FMT { orign, i, j, k, reserve }

    // --- src/types/storage.rs ---
    IDBUSBFILE { path, offset, req_num, req_attrib, sort, req_comment, req_total, dummy }
    IDBUSBSEARCH { path, s_fname, req_attrib, sort, dummy }
    IODBCPRM { NcApli, Dummy1, HostApli, Dummy2, StatPstv, StatNgtv, Statmask, AlarmStat, PsclHaddr, PsclLaddr, SvcMode1, SvcMode2, FileTout, RemTout }
    IODBDSSET { host_ip, host_uname, host_passwd, host_dir, dtsv_mac, dtsv_ip, dtsv_mask }
    ODBDNCPRG { name, o_num }
    ODBDSDIR { file_num, remainder, data_num, data }
    ODBDSMNT { empty_cnt, total_size, read_ptr, write_ptr }
    ODBEMBEDFINF { used_page, all_page }
    ODBNESTPDF { attrib, comment, prog_name, dummy }
    ODBSRAMIF2 { protect, adrs, size }
    ODBUSBFILE { size, attribute, long_name, year, mon, day, hour, min, sec, dummy, fname, comment }
    ODBUSBINFO { f_num, next_entry, dummy, total }
    ODBUSBSIZE { totalsize_h, totalsize_l, freesize_h, freesize_l }
    ODB_IN_DSFILE_REQ { file, fnum, offset, detail, option }
    ODB_IN_STAT_DSFILE { req_num, size_type }
    OUT_DSFILE { year, mon, day, hour, min, sec, size, attr, file, info }
    OUT_DSINFO { r#type, dummy, fnum, total, remain_h, remain_l, dir }
    OUT_RMTDGNINFO { receipt_num, time, status, err_num, err_msg }

    // --- src/types/ieee64.rs ---
    IDBWRA64 { datano, r#type, dummy, data }
    IDBWRR64 { datano, r#type, dummy, data }
    IODBPSD64 { datano, r#type, axis, dummy, u }
    IODBWCSF64 { dummy1, r#type, dummy2, data }
    IODBZOFS64 { datano, r#type, dummy, data }
    IODBZOR64 { datano_s, r#type, datano_e, dummy, data }
    ODBAXDT64 { name, dummy, data, dec, unit, flag, reserve }
    ODBCMD64 { adrs, num, flag, dec_val, cmd_val }
    ODBDATRNG64 { data_min, data_max, dec, status }
    ODBDGN64 { datano, r#type, axis, dummy, u }
    ODBHOLDATA64 { mes_val1, mes_dp1, mes_val2, mes_dp2, mes_val3, mes_dp3, mes_axis, mes_parl }
    REALDATA { val, dec, dummy }
    REALMES64 { mes_val, dec_val, dummy }

    // --- src/types/axis_ext.rs ---
    IODBAXIS { axnum, data, dp }
    IODBINDEXDAT { pos, inp_width, speed, f_flg, dummy }
    IODBINDEXPOSDAT { min_value, max_value, setting, dummy }
    IODBINDEXPRM { ofs_limit, detect_width, jog_clamp, matrix_single, torque_ovr, ofs_adjust, dummy }
    IODBOVLM { datano, r#type, data }
    IODBOVSTR { mcode, scode, tcode, bcode }
    IODBPALAX { max_pal, data }
    IODBPITCHBLK { group_num, pginf }
    ODBAHDCK { dat_path, info }
    ODBAXIS_EX { counter, r#type, data }
    ODBAXSTS_BG { flag }
    ODBCANCMD { p_data, q_data, r_data, z_data }
    ODBCHOPPING { cur_pos, cur_speed, real_udp, real_ldp, stroke_cnt }
    ODBGRPAXIS { path_num, draw_num }
    ODBGRPPOS { abs, mcn, feed_type, reserved }
    ODBINDEXINFO { mode, nc_ax, inpos_point, ofs_edit_signal }
    ODBIPL { outpt, ipltp, mv, inp }
    ODBPMCAXISINFO { datastatus, axisstatus, commandsignal, statussignal, dummy, instruction, speedsignal, axisctrldata, subinstnum, subinstlength, subinstdata1, subinstdata2, subinstdata3, subinstdata4, subinstdata5, subinstdata6, subinstdata7 }
    ODBPOSFIG { val, dec }
    ODBWACT { data }
    POSVAL { data, dec }
    REALNUM { val, dec }
    CMNDDATA { val, dec, dummy }
    IODBOVMST { adrs, num }

    // --- src/types/fssb.rs ---
    IODBIFSBAXIS { axis_num, axis_name, line, amp_name, pm, cs, tndm }
    ODBIFSBCOMSTATDTL { error_inf, jitter_inf, n_warning, j_warning, reserve }
    ODBIFSBFSSBUNT { slv_unt_num, fssb_unt_num, name }
    ODBIFSBINFO { fssb_line_mnt_st, reserve, card_num, line_info }
    ODBIFSBMNTSP { spdl_num, spdl_name, line, amp_name, amp_series, amp_pwr, amp_edt, amp_spdl_num, amp_spec_num, amp_serial_num }
    ODBIFSBMNTSV { axis_num, axis_name, line, amp_name, amp_series, amp_cur, amp_edt, amp_axis_num, amp_spec_num, amp_serial_num }
    ODBIFSBPLSMDL { slave_num, name, r#type, pcb_id, info }
    ODBIFSBSLUPM { slave_num, axis_num, axis_name }
    ODBIFSBSLUSP { slave_num, spdl_num, spdl_name }
    ODBIFSBSLUSV { slave_num, axis_num, axis_name, tndm, reserve }
    ODBIFSBSLVUNT { slv_unt_num, kind, attrb }
    ODBIFSBSPAMP { slave_num, name, series, pwr, as_spdl_num, as_spdl_name }
    ODBIFSBSVAMP { slave_num, name, series, cur, as_axis_num, as_axis_name }
    ODBIFSBSYSALM { num_sys_alm, error_line, error_slvnum1, error_slvnum2, year, mon, day, hour, min, sec, alarm_cause }
    ODBIFSBWARNHSTMSG { year, month, day, hour, minute, second, dummy, msg_dat }
    ODBIFSBWARNINGMSG { line, slv_src, slv_dst, r#type, wm_typ, wm_pnt }
    ODBIFSBLINE { hrv_ln, ax_num_ln, sp_num_ln, pm_num_ln }

    // --- src/types/diagnosis.rs ---
    IODBMDDEXCEPTPRM { sno, eno }
    IODBMDGINFO { alm_no, r#type, axis, path, reserved }
    ODBLOAD { datano, r#type, data }
    ODBMDDINFO { status, prot, year, month, day, hour, min, sec, reg_code, cur_code, modulate }
    ODBMDGDTMSG { message, imgid }
    ODBMDGFLOW { msgidx, yesidx, noidx, reserved, message, detail, operate }
    ODBMDGMSG { alm_no, msgidx, reserved, r#type, part, level, add_inf, mark, message, cause }
    ODBMDGWVDT { ldata, p_dec, num, channel, axis, kind, interval, t_cycle, unit, sw_alm }
    ODBVIEWGRP2 { sv1, sv2, sv3, sv4, sv5, sv6, sv7, sp1, sp2, sp3, sp4, sp5, sp6, sp7, sp8, lat1 }
    ODBLAT_GRP1 { nnum, prog, year, mon, day, hour, min, sec, reserved }
    ODBSP2_GRP8 { isncr_intp, isncr_com, isncr_wrn, esncr_intp, esncr_com, esncr_wrn, sp_dat1, sp_dat2, sp_dat3, sp_dat4 }
    ODBSP2_GRP7 { iab_amplt, eab_amplt, iab_ofs_a, iab_ofs_b, iab_noise, eab_ofs_a, eab_ofs_b, eab_noise, iab_max_flt, eab_max_flt }
    ODBMDGDT { dt, fp, reserved }
    ODBMDGVAL { lval, ulval, sval, usval, cval, ucval }
    ODBSP2_GRP6 { sp_up_err1, sp_up_err2, sp_lw_err1, sp_lw_err2, sp_up_jt1, sp_up_jt2, sp_lw_jt1, sp_lw_jt2 }
    ODBSP2_GRP5 { ps_dgn, ps_sub_dgn, sp_dgn, ps_int_tmp, ps_sink_tmp, sp_int_tmp, sp_sink_tmp, amp_grp, amp_slv }
    ODBSP2_GRP4 { resistance, detect_res, reserved }
    ODBSP2_GRP3 { ps_vumb, ps_vthd, freq, ps_vrms, ps_cur, dvolt, ps_statf, reserved }
    ODBSP2_GRP2 { pos_err, syn_err, sp_spd, mt_spd, mt_cur, ldmtr, trq_cmd, heat_mt, heat_amp, reserved }
    ODBSP2_GRP1 { motion, cmd_spd, mode, gear, osel, reserved, sig_in, sig_out }
    ODBSIGDIO { sgnl1, sgnl2, sgnl3, sgnl4 }
    ODBSV2_GRP7 { id_intp, id_com, id_wrn, ed_intp, ed_com, ed_wrn, sv_dat1, sv_dat2, sv_dat3, sv_dat4 }
    ODBSV2_GRP6 { sv_up_err1, sv_up_err2, sv_lw_err1, sv_lw_err2, sv_up_jt1, sv_up_jt2, sv_lw_jt1, sv_lw_jt2, sdu_up_err1, sdu_up_err2, sdu_lw_err1, sdu_lw_err2, sdu_up_jt1, sdu_up_jt2, sdu_lw_jt1, sdu_lw_jt2 }
    ODBSV2_GRP5 { ps_dgn, ps_sub_dgn, sv_dgn, ps_int_tmp, ps_sink_tmp, sv_int_tmp, sv_sink_tmp, amp_grp, amp_slv }
    ODBSV2_GRP4 { resistance, detect_res, reserved }
    ODBSV2_GRP3 { ps_vumb, ps_vthd, freq, ps_vrms, ps_cur, dvolt, ps_statf, reserved }
    ODBSV2_GRP2 { mt_cur, trq_cmd, efc_cur, dlvl, heat, opt, opt2 }
    ODBSV2_GRP1 { cmd_pls, fb_pls, refc, pos_err, act_spd, amr, reserved }

    // --- src/types/main_menu.rs ---
    IODBMMCTGRYCSTMSTRING { string, reserve }
    IODBMMICONCSTMSTRING { scrninf, string, reserve }
    IODBMMMCCTGRYDEFDAT { cmsg_id }
    IODBMMMCSCRNDEFDAT { scrninf, icn_id, msg_id }
    ODBMMSCRNINF { scrn_id }

    // --- src/types/restart.rs ---
    IODBRSTINFO { seq_no, c_blck_cnt, t_blck_cnt, call_from_no, call_from_blck, prg_rep, seq_rep, c_blck_rep, nest_lv, prg_name, dummy1, call_from_prg, dummy2, edit_flag, reserve, repeat, wait_m_code }
    IODBRSTINFO2 { seq_no, c_blck_cnt, t_blck_cnt, call_from_no, call_from_blck, prg_rep, seq_rep, c_blck_rep, nest_lv, prg_name, dummy1, call_from_prg, dummy2, edit_flag, reserve, repeat, wait_m_code, time_s, time_m, time_h, time_d, id_no, reserve2 }
    ODBGCD { group, flag, code }
    ODBPRSM { datano, r#type, data_info, rstr_bc, rstr_m, rstr_t, rstr_s, rstr_b, dest, dist }
    ODBPTHIS_AUX { l_value, l_value_e, l_value_sub, l_value_e_sub, repeat_sub, repeat_e_sub, m_code, info1, number, number_sub, table_kind, m_count, master_indx_no_pt, master_indx_no_rel, l_frac, reserve1 }
    ODBPTHIS_AX { l_value, l_value_e, pos_value, pos_value_e, l_value_sub, l_value_e_sub, l_value_cycle, l_value_e_cycle, repeat_sub, repeat_e_sub, info1, number, number_sub, number_cycle, table_kind, name, cs_spdl_idx_pt, cs_spdl_idx_rel, master_indx_no_pt, master_indx_no_rel, pos_frac, l_frac, l_frac_cycle, reserve1 }
    ODBPTHIS_GB { date, reserve1, info1, path_num, reserve2 }
    ODBPTHIS_LOG { issub, kind, number }
    ODBPTHIS_PT { time, dist_err, ov_time, info1, alarm_no, alarm_type, alarm_axis, path_axis_num, path_spdl_num, time_frac, reserve1 }
    ODBPTHIS_SP { l_value, l_value_e, pos_value, pos_value_e, l_value_sub, l_value_e_sub, repeat_sub, repeat_e_sub, srpm, rrpm, sspm, smax, info1, number, number_sub, table_kind, sp_mode, name, ov_sp, reserve1, cs_axis_idx_pt, cs_axis_idx_rel, pos_frac, l_frac, reserve2 }
    ODBRSTLIST { prg_name, dummy, seq_no, c_blck_cnt }
    ODBRSTLIST2 { prg_name, status, dummy, seq_no, wait_m_code, c_blck_cnt, time_s, time_m, time_h, time_d, id_no, reserve }
    ODBRSTMPINFO { u_block_num, mltpiece_all, mltpiece_exe, u_file_name }

    // --- src/types/safety_io.rs ---
    IODBSFSGDSPSTAT { extract, symbol, extend }
    IODBSFSGSIGHIS { sno_sig, len_sig, sno_sig_his, len_sig_his, extract }
    IODBSFSGSIGINF { unittype, number, adr_type, bit }
    ODBSFSGLOGINF { signal_num, sig_his_period, sig_his_count, sig_his_after, alm_detect_time, dummy, sfsg_alm, sfsg_alm_time }
    ODBSFSGSIGINFEX { sfsg_siginf, select, reserve }
    ODBSFSGSIGNALNUM { signal_num_default, signal_num_extract }
    ODBSFSGALMTIME { year, month, date, hour, minute, second }
    ODBSFSGALM { alm_type, alm_no }

    // --- src/types/energy.rs ---
    ODBPOWCCYC { cycletime, powc_axis, powc_spindle, powc_outer }
    ODBPOWCHISALL { powchis }
    ODBPOWCOUTER { ave_pow, ref_ofs, ref_adrs, ref_path }
    ODBPWCMDAT { time, axis_num, spindle_num, all, axis, spindle }
    ODBPWCM { consump, regen, net, present }
    ODBPOWCHIS { get_time, powc_axis, powc_spindle, powc_outer }
}
