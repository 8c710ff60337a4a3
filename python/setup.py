"""Build step of the fwlib32 Python distribution.

`pip wheel ./python` (from the repository root) runs `cargo build --release
--locked` of the repository this folder is in, then copies into the package:

    fwlib32/libfwlib32.so.1     the library (the C ABI of FANUC's fwlib32.h)
    fwlib32/bin/focas-sim       the CNC simulator
    fwlib32/bin/focas           the command-line client

stripped of their debug info when `strip` ($STRIP) is there. The wheel is a
platform wheel for any Python 3 (py3-none-linux_<arch>): the package itself
is pure Python over ctypes, so no Python ABI is involved.

Environment: CARGO (default "cargo"), CARGO_TARGET_DIR as cargo reads it,
FWLIB32_CARGO_ARGS (more `cargo build` arguments: "--target
aarch64-unknown-linux-gnu" cross-builds), FWLIB32_PLAT (the wheel's platform
tag then, "linux_aarch64"), STRIP (default "strip").
"""

import json
import os
import shlex
import shutil
import subprocess
from pathlib import Path

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

try:
    from setuptools.command.bdist_wheel import bdist_wheel
except ImportError:  # setuptools < 70.1
    from wheel.bdist_wheel import bdist_wheel  # type: ignore[no-redef]

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def cargo_build() -> dict:
    """Builds the release artifacts; returns {name: path} of the three files."""
    if not (ROOT / "Cargo.toml").is_file():
        raise SystemExit(
            f"fwlib32: no Cargo.toml in {ROOT}: the Python package is built from "
            "the fwlib32-rs repository (pip wheel ./python at its root)"
        )
    cargo = os.environ.get("CARGO", "cargo")
    cmd = [cargo, "build", "--release", "--locked", "--lib", "--bins",
           "--message-format=json-render-diagnostics"]
    cmd += shlex.split(os.environ.get("FWLIB32_CARGO_ARGS", ""))
    print("fwlib32:", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, check=False)
    if proc.returncode != 0:
        raise SystemExit(f"fwlib32: cargo build failed (exit status {proc.returncode})")
    found = {}
    for line in proc.stdout.decode().splitlines():
        try:
            msg = json.loads(line)
        except ValueError:
            continue
        if msg.get("reason") != "compiler-artifact":
            continue
        target = msg["target"]
        if target["name"] == "fwlib32" and "cdylib" in target["kind"]:
            for f in msg["filenames"]:
                if f.endswith(".so"):
                    found["libfwlib32.so.1"] = f
        elif "bin" in target["kind"] and target["name"] in ("focas-sim", "focas"):
            found[target["name"]] = msg["executable"]
    missing = {"libfwlib32.so.1", "focas-sim", "focas"} - found.keys()
    if missing:
        raise SystemExit(f"fwlib32: cargo built no {', '.join(sorted(missing))}")
    return found


def install(src: str, dest: Path, mode: int) -> None:
    """Copies `src` to `dest`, stripped when strip is on PATH."""
    dest.parent.mkdir(parents=True, exist_ok=True)
    strip = os.environ.get("STRIP", "strip")
    if shutil.which(strip):
        subprocess.run([strip, "--strip-unneeded", "--remove-section=.comment",
                        "-o", str(dest), src], check=True)
    else:
        shutil.copyfile(src, dest)
    dest.chmod(mode)


class BuildPy(build_py):
    """build_py, then the Rust artifacts into the package."""

    def run(self) -> None:
        super().run()
        built = cargo_build()
        pkg = Path(self.build_lib) / "fwlib32"
        install(built["libfwlib32.so.1"], pkg / "libfwlib32.so.1", 0o755)
        install(built["focas-sim"], pkg / "bin" / "focas-sim", 0o755)
        install(built["focas"], pkg / "bin" / "focas", 0o755)


class BinaryDistribution(Distribution):
    """Has binaries: a platform wheel, installed into platlib."""

    def has_ext_modules(self) -> bool:
        return True


class BdistWheel(bdist_wheel):
    """A platform wheel for every Python 3: py3-none-<platform>."""

    def get_tag(self):
        _, _, plat = super().get_tag()
        # A cross build (FWLIB32_CARGO_ARGS="--target ...") names its platform.
        return "py3", "none", os.environ.get("FWLIB32_PLAT", plat)


setup(cmdclass={"build_py": BuildPy, "bdist_wheel": BdistWheel}, distclass=BinaryDistribution)
