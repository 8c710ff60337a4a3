"""FocasError: a FOCAS call that did not return EW_OK."""

from __future__ import annotations

from typing import Any, Dict, Optional, Tuple

# code: (name, meaning); the first name of a shared code (EW_FUNC/EW_NOPMC ...).
EW: Dict[int, Tuple[str, str]] = {
    -17: ("EW_PROTOCOL", "protocol error: the CNC's answer is not valid FOCAS2"),
    -16: ("EW_SOCKET", "socket error: no connection, or it broke or timed out"),
    -15: ("EW_NODLL", "library for this CNC not found"),
    -14: ("EW_INIERR", "error in the library's initial value file"),
    -13: ("EW_ITLOW", "low temperature alarm of the intelligent terminal"),
    -12: ("EW_ITHIGHT", "high temperature alarm of the intelligent terminal"),
    -11: ("EW_BUS", "bus error"),
    -10: ("EW_SYSTEM2", "system error"),
    -9: ("EW_HSSB", "HSSB communication error"),
    -8: ("EW_HANDLE", "library handle error"),
    -7: ("EW_VERSION", "CNC or PMC version mismatch: not available on this CNC"),
    -6: ("EW_UNEXP", "abnormal error"),
    -5: ("EW_SYSTEM", "system error"),
    -4: ("EW_PARITY", "shared RAM parity error"),
    -3: ("EW_MMCSYS", "emm386 or mmcsys install error"),
    -2: ("EW_RESET", "reset or stop occurred"),
    -1: ("EW_BUSY", "busy: the CNC or the connection is doing something else"),
    0: ("EW_OK", "no error"),
    1: ("EW_FUNC", "function not available on this CNC (command prepare error)"),
    2: ("EW_LENGTH", "data block length error"),
    3: ("EW_NUMBER", "data number error: no such number"),
    4: ("EW_ATTRIB", "data attribute error: wrong type or axis"),
    5: ("EW_DATA", "data error"),
    6: ("EW_NOOPT", "option not installed"),
    7: ("EW_PROT", "write protected"),
    8: ("EW_OVRFLOW", "memory overflow"),
    9: ("EW_PARAM", "CNC parameter not correct"),
    10: ("EW_BUFFER", "buffer empty or full"),
    11: ("EW_PATH", "no such path"),
    12: ("EW_MODE", "not possible in the CNC's current mode"),
    13: ("EW_REJECT", "execution rejected by the CNC"),
    14: ("EW_DTSRVR", "data server error"),
    15: ("EW_ALARM", "the CNC is in alarm"),
    16: ("EW_STOP", "the CNC is not running"),
    17: ("EW_PASSWD", "protected: parameter write or password needed"),
    18: ("EW_PMC", "error reported by the PMC"),
    19: ("EW_PMCHANDLE", "PMC handle error"),
    20: ("EW_RD_OVWSTP", "overwrite stop in program read"),
    21: ("EW_RD_RSTFIN", "reset interrupt in program read"),
}


def ew_name(code: int) -> str:
    """The EW_* name of a result code ("EW_NUMBER" for 3), "EW_?" if unknown."""
    return EW.get(code, ("EW_?", ""))[0]


class FocasError(Exception):
    """A FOCAS call failed: the one exception class of this package.

    Attributes:
        function: the FOCAS function that failed, e.g. "cnc_rdparam".
        code: its EW_* result code (an int, e.g. 3).
        name: the code's name, e.g. "EW_NUMBER".
        meaning: what the code means, in words.
        detail: the detail words (err_no, err_dtno) cnc_getdtailerr (for
            pmc_* functions pmc_getdtailerr) reported after the call, or
            None where there is no handle to ask (a failed connect).
        message: extra words of our own on a check made in Python, else "".
    """

    function: str
    code: int
    name: str
    meaning: str
    detail: Optional[Tuple[int, int]]
    message: str

    def __init__(self, function: str, code: int,
                 detail: Optional[Tuple[int, int]] = None, message: str = "") -> None:
        self.function = function
        self.code = code
        self.name, self.meaning = EW.get(code, ("EW_?", "unknown result code"))
        self.detail = detail
        self.message = message
        text = f"{function}: {self.name} ({code}): {self.meaning}"
        if message:
            text += f": {message}"
        if detail is not None and detail != (0, 0):
            text += f" [detail {detail[0]}/{detail[1]}]"
        super().__init__(text)

    def __reduce__(self) -> Any:
        return (FocasError, (self.function, self.code, self.detail, self.message))
