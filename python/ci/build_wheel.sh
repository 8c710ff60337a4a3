#!/usr/bin/env bash
# python/ci/build_wheel.sh DIR (CI, .ci/run; from the repository root):
# builds the fwlib32 wheel as a user does (`pip wheel ./python`) with the
# venv DIR/build (made by the caller) into DIR/dist, tags it
# manylinux_X_Y_<arch> only as `auditwheel show` finds it complies (else it
# stays linux_<arch>), checks it with check_wheel.py, and prints its path.
# The environment reaches cargo (setup.py: CARGO, FWLIB32_CARGO_ARGS,
# FWLIB32_PLAT, STRIP). Everything but the path goes to stderr.
set -euo pipefail
dir=$1
bin=$dir/build/bin
"$bin/pip" -q install auditwheel wheel >&2
rm -rf python/build  # setuptools' build folder: nothing of another build
"$bin/pip" -q wheel --no-deps -w "$dir/dist" ./python >&2
wheel=$(ls "$dir"/dist/fwlib32-*.whl)
tag=$({ "$bin/auditwheel" show "$wheel" 2>/dev/null || true; } | tr '\n' ' ' |
      sed -n 's/.*platform tag: "\(manylinux_[0-9]*_[0-9]*_[a-z0-9_]*\)".*/\1/p')
if [ -n "$tag" ]; then
    "$bin/wheel" tags --remove --platform-tag "$tag" "$wheel" >/dev/null
    wheel=$(ls "$dir"/dist/fwlib32-*.whl)
fi
"$bin/python" python/ci/check_wheel.py "$wheel" >&2
echo "$wheel"
