#!/bin/sh
# Writes the list of FANUC's function names (tools/compat/fanuc-functions.txt)
# from FANUC's header and, for the second column, FANUC's Linux library:
#
#     tools/compat/extract.sh /path/to/fwlib32.h /path/to/libfwlib32.so.1 \
#         > tools/compat/fanuc-functions.txt
#
# Only names are taken: every cnc_* and pmc_* function the header declares
# (`FWLIBAPI short WINAPI name(...)`), and whether the library's dynamic
# symbol table defines it (`nm -D --defined-only`). Nothing else of FANUC's
# files is kept; neither file is committed.
set -eu
[ $# -eq 2 ] || { echo "usage: $0 FWLIB32_H LIBFWLIB32_SO" >&2; exit 2; }
header=$1
lib=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Declarations may be split over lines: join the header into one line first.
tr '\r\n\t' '   ' <"$header" |
    grep -oE 'FWLIBAPI +[A-Za-z_ ]+ +WINAPI +[A-Za-z_0-9]+ *\(' |
    sed -E 's/.*WINAPI +([A-Za-z_0-9]+) *\(/\1/' |
    grep -E '^(cnc|pmc)_' | LC_ALL=C sort -u >"$tmp/declared"
${NM:-nm} -D --defined-only "$lib" | awk '{ print $NF }' | sed 's/@.*//' |
    LC_ALL=C sort -u >"$tmp/exported"
cat <<'HEAD'
# The cnc_* and pmc_* functions FANUC's public fwlib32.h (FOCAS2) declares:
# names only, extracted once from that header by tools/compat/extract.sh;
# nothing else of FANUC's header or library is in this repository.
#
# One function a line, sorted. The second column is "linux" where FANUC's
# Linux x86-64 library (libfwlib32.so.1) exports the function (its dynamic
# symbol table, `nm -D --defined-only`), "-" where it does not.
#
# Read by tests/recorded/compat.rs (COMPATIBILITY.md) and by `focas compat`.
HEAD
LC_ALL=C join -a 1 -o 1.1,2.1 -e - "$tmp/declared" "$tmp/exported" |
    awk '{ print $1, ($2 == "-" ? "-" : "linux") }'
