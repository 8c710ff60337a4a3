"""`python -m fwlib32 [ARGS]`: runs the bundled `focas` command-line client."""

from ._bin import run

if __name__ == "__main__":
    run("focas")
