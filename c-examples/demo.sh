#!/usr/bin/env bash
# The main job: build the library and the simulator, start focas-sim with its
# built-in profile (a 31i mill running program O1234) on a free loopback port,
# build the C examples against include/fwlib32.h and libfwlib32.so, and run
# them against the simulator: status.c (connect, status, id), then adapter.c
# (the MTConnect adapter's calls, polling the running machine 4 times).
set -euo pipefail
cd "$(dirname "$0")/.."

cargo build --release --quiet
out=target/c-examples
mkdir -p "$out"
# A program linked with -lfwlib32 asks the loader for the SONAME libfwlib32.so.1.
ln -sf libfwlib32.so target/release/libfwlib32.so.1
for ex in status adapter; do
    cc -std=c99 -Wall -Wextra -Werror -I include "c-examples/$ex.c" \
       -L target/release -lfwlib32 -Wl,-rpath,"$PWD/target/release" -o "$out/$ex"
done

coproc SIM { exec target/release/focas-sim --listen 127.0.0.1:0; }
sim_pid=$SIM_PID
trap 'kill "$sim_pid" 2>/dev/null || true' EXIT
read -r -t 30 line <&"${SIM[0]}"        # "listening on 127.0.0.1:PORT"
echo "focas-sim: $line"
port=${line##*:}

"$out/status" 127.0.0.1 "$port"
echo
"$out/adapter" 127.0.0.1 "$port" 4 700
