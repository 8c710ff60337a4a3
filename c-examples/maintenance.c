/*
 * maintenance.c - a small health report for one machine: tool life left,
 * spindle load and servo current, servo figures, the periodic maintenance
 * items and how much of their life is left, the PMC's alarm messages, the
 * last operations, operator messages and alarms from the CNC's histories.
 *
 *   cc -Wall -Wextra -Werror -I../include maintenance.c -L../target/release -lfwlib32 -o maintenance
 *   ./maintenance [host [port]]
 *
 * Written against the FOCAS2 API as FANUC documents it: the same source
 * builds against FANUC's fwlib32.h. Output: one `key=value` line each.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

static void tool_life(unsigned short h)
{
    ODBTLIFE2 groups;
    ODBTLIFE3 life, used;
    long n, g;
    short ret = cnc_rdngrp(h, &groups);
    if (ret != EW_OK) {
        printf("tool_groups=error %d\n", ret);
        return;
    }
    n = (long)groups.data;
    printf("tool_groups=%ld\n", n);
    for (g = 1; g <= n && g <= 5; g++)
        if (cnc_rdlife(h, (short)g, &life) == EW_OK && cnc_rdcount(h, (short)g, &used) == EW_OK)
            printf("tool_group%ld=life %ld used %ld left %ld\n", g, (long)life.data, (long)used.data,
                   (long)life.data - (long)used.data);
}

static void loads(unsigned short h)
{
    ODBSPLOAD sp[4];
    short current[MAX_AXIS];
    short n = 4, i;
    if (cnc_rdspmeter(h, -1, &n, sp) == EW_OK)
        for (i = 0; i < n; i++)
            printf("spindle%d=load %ld%% speed %ld\n", i + 1, (long)sp[i].spload.data,
                   (long)sp[i].spspeed.data);
    memset(current, 0, sizeof current);
    if (cnc_rdcurrent(h, current) == EW_OK)
        printf("current=%d %d %d\n", current[0], current[1], current[2]);
}

static void servo_spindle(unsigned short h)
{
    ODBAXIS delay, skip;
    long gain[MAX_AXIS];
    char alarm[8];
    short i;
    memset(gain, 0, sizeof gain);
    if (cnc_rdloopgain(h, gain) == EW_OK && cnc_srvdelay(h, ALL_AXES, sizeof delay, &delay) == EW_OK &&
        cnc_accdecdly(h, ALL_AXES, sizeof skip, &skip) == EW_OK) {
        /* 4-byte words, whatever the size of long (FANUC's layout). */
        const int *g = (const int *)gain;
        for (i = 0; i < 3; i++)
            printf("servo%d=gain %d delay %ld accdec %ld\n", i + 1, g[i], (long)delay.data[i],
                   (long)skip.data[i]);
    }
    if (cnc_skip(h, 1, 8, &skip) == EW_OK)
        printf("skip1=%ld\n", (long)skip.data[0]);
    memset(alarm, 0, sizeof alarm);
    if (cnc_rdspdlalm(h, alarm) == EW_OK)
        printf("spindle_alarm=%d\n", alarm[0]);
}

static void maintenance_items(unsigned short h)
{
    static IODBPMAINTE item[10];
    short n = 10, i, used = 0, ret = cnc_rdpm_item(h, 1, &n, item);
    if (ret != EW_OK) {
        printf("maintenance=error %d\n", ret);
        return;
    }
    for (i = 0; i < n; i++) {
        if (!item[i].name[0])
            continue; /* an empty slot */
        used++;
        printf("item%d=%.62s left %ld of %ld min%s\n", used, item[i].name, (long)item[i].remain,
               (long)item[i].total, item[i].stat ? " DUE" : "");
    }
    printf("maintenance=%d\n", used);
}

static void pmc_alarms(unsigned short h)
{
    static ODBPMCALM msg[8];
    short n = 8, exist = 0, i, ret = pmc_rdalmmsg(h, 1, &n, &exist, msg);
    if (ret != EW_OK) {
        printf("pmc_alarms=error %d\n", ret);
        return;
    }
    printf("pmc_alarms=%d\n", n);
    for (i = 0; i < n; i++)
        printf("pmc_alarm%d=%.128s\n", i + 1, msg[i].almmsg);
}

static void operations(unsigned short h)
{
    ODBHIS his;
    unsigned short n = 0;
    short i, ret;
    if (cnc_rdophisno(h, &n) != EW_OK || n == 0) {
        printf("operations=0\n");
        return;
    }
    ret = cnc_rdophistry(h, 1, n < 10 ? n : 10, sizeof his, &his);
    if (ret != EW_OK) {
        printf("operations=error %d\n", ret);
        return;
    }
    printf("operations=%u\n", (unsigned)(his.e_no - his.s_no + 1));
    for (i = 0; i <= his.e_no - his.s_no; i++) {
        switch (his.data[i].rec_alm.rec_type) {
        case 0:
            printf("op%d=key %02x\n", i + 1, (unsigned char)his.data[i].rec_mdi.key_code);
            break;
        case 1:
            printf("op%d=signal %d.%d %02x->%02x\n", i + 1, his.data[i].rec_sgn.sig_name,
                   his.data[i].rec_sgn.sig_no, (unsigned char)his.data[i].rec_sgn.sig_old,
                   (unsigned char)his.data[i].rec_sgn.sig_new);
            break;
        case 2:
            printf("op%d=alarm %d\n", i + 1, his.data[i].rec_alm.alm_no);
            break;
        case 3:
            printf("op%d=date %02d-%02d-%02d\n", i + 1, his.data[i].rec_date.year,
                   his.data[i].rec_date.month, his.data[i].rec_date.day);
            break;
        case 4:
            printf("op%d=time %02d:%02d:%02d\n", i + 1, his.data[i].rec_time.hour,
                   his.data[i].rec_time.minute, his.data[i].rec_time.second);
            break;
        default:
            printf("op%d=type %d\n", i + 1, his.data[i].rec_alm.rec_type);
        }
    }
}

static void messages(unsigned short h)
{
    static ODBOMHIS2 om;
    short i, ret = cnc_rdomhistry2(h, 1, 5, sizeof om, &om);
    if (ret != EW_OK) {
        printf("messages=error %d\n", ret);
        return;
    }
    printf("messages=%d\n", om.e_no - om.s_no + 1);
    for (i = 0; i <= om.e_no - om.s_no; i++)
        printf("msg%d=%d %04d-%02d-%02d %s\n", i + 1, om.opm_his[i].om_no, om.opm_his[i].year,
               om.opm_his[i].month, om.opm_his[i].day, om.opm_his[i].ope_msg);
}

static void alarms(unsigned short h)
{
    static ODBAHIS5 ah;
    short i, ret = cnc_rdalmhistry5(h, 1, 3, sizeof ah, &ah);
    if (ret != EW_OK) {
        printf("alarms=error %d\n", ret);
        return;
    }
    printf("alarms=%d\n", ah.e_no - ah.s_no + 1);
    for (i = 0; i <= ah.e_no - ah.s_no; i++)
        printf("alarm%d=%d %04d-%02d-%02d %02d:%02d:%02d %.*s\n", i + 1, ah.alm_his[i].alm_no,
               ah.alm_his[i].year, ah.alm_his[i].month, ah.alm_his[i].day, ah.alm_his[i].hour,
               ah.alm_his[i].minute, ah.alm_his[i].second, ah.alm_his[i].len_msg,
               ah.alm_his[i].alm_msg);
}

int main(int argc, char **argv)
{
    const char *host = argc > 1 ? argv[1] : "127.0.0.1";
    unsigned short port = (unsigned short)(argc > 2 ? atoi(argv[2]) : 8193);
    unsigned short h = 0;
    short ret = cnc_allclibhndl3(host, port, 10, &h);
    if (ret != EW_OK) {
        fprintf(stderr, "cnc_allclibhndl3(%s:%u) failed: %d\n", host, port, ret);
        return 1;
    }
    tool_life(h);
    loads(h);
    servo_spindle(h);
    maintenance_items(h);
    pmc_alarms(h);
    operations(h);
    messages(h);
    alarms(h);
    cnc_freelibhndl(h);
    return 0;
}
