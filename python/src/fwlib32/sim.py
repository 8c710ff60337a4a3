"""`python -m fwlib32.sim [ARGS]`: runs the bundled focas-sim CNC simulator
with ARGS (`--help` lists them: --listen, --profile, --fleet, --fault ...)."""

from ._bin import run

if __name__ == "__main__":
    run("focas-sim")
