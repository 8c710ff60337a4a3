#!/usr/bin/env bash
# The main job: build the library and the simulator, start focas-sim with its
# built-in profile (a 31i mill running program O1234) on a free loopback port,
# build the C examples against include/fwlib32.h and libfwlib32.so, and run
# them against the simulator: status.c (connect, status, id), then adapter.c
# (the MTConnect adapter's calls, polling the running machine 4 times), then
# transfer.c (download a program, select it, start it, watch it run to its
# end, upload it back and compare).
set -euo pipefail
cd "$(dirname "$0")/.."

step() { printf '\n==> %s\n' "$*"; }

step "building the library, focas-sim and focas (release; about 4 minutes on 2 cores the first time)"
cargo build --release
out=target/c-examples
mkdir -p "$out"
# A program linked with -lfwlib32 asks the loader for the SONAME libfwlib32.so.1.
ln -sf libfwlib32.so target/release/libfwlib32.so.1
step "compiling c-examples/status.c, adapter.c and transfer.c against include/fwlib32.h"
for ex in status adapter transfer; do
    cc -std=c99 -Wall -Wextra -Werror -I include "c-examples/$ex.c" \
       -L target/release -lfwlib32 -Wl,-rpath,"$PWD/target/release" -o "$out/$ex"
done

step "starting focas-sim (built-in profile: a 31i mill running O1234) on a free port"
coproc SIM { exec target/release/focas-sim --listen 127.0.0.1:0; }
sim_pid=$SIM_PID
trap 'kill "$sim_pid" 2>/dev/null || true' EXIT
read -r -t 30 line <&"${SIM[0]}"        # "listening on 127.0.0.1:PORT"
echo "focas-sim: $line"
port=${line##*:}

step "status.c: connect, status, CNC id"
"$out/status" 127.0.0.1 "$port"
step "adapter.c: the MTConnect adapter's calls, 4 polls 700 ms apart"
"$out/adapter" 127.0.0.1 "$port" 4 700
step "transfer.c: download O4242, start it, watch it run, upload it back and compare"
printf '%%\nO4242(DEMO)\nN10 G90 G00 X10. Y5.\nN20 G01 X20. F500 S1200 M03\nN30 M05\nN40 M30\n%%' >"$out/O4242.nc"
"$out/transfer" 127.0.0.1 "$port" "$out/O4242.nc"
step "done (focas-sim is stopped on the way out)"
