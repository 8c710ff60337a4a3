// Command focas-status reads a CNC's status, positions, alarms and
// parameters through libfwlib32 (cgo; the flags come from pkg-config).
//
//	go build -o focas-status . && ./focas-status HOST [PORT]
//
// Output is one key=value per line, as the Python example's. Exit status 0 on
// success, 1 when a call fails (the failing function and its EW_* code are
// printed on stderr), 2 on bad usage.
//
// The structures are include/fwlib32.h's: FANUC's `long` fields are LONG, 32
// bits on every platform (C.LONG, an int32_t). C.char is signed on x86-64 and
// unsigned on aarch64: text fields are read with C.GoStringN or as bytes.
package main

/*
#cgo pkg-config: fwlib32
#include <stdlib.h>
#include <fwlib32.h>
*/
import "C"

import (
	"flag"
	"fmt"
	"os"
	"strconv"
	"unsafe"
)

var ewNames = map[C.short]string{
	-17: "EW_PROTOCOL", -16: "EW_SOCKET", -15: "EW_NODLL", -8: "EW_HANDLE",
	-7: "EW_VERSION", -6: "EW_UNEXP", -2: "EW_RESET", -1: "EW_BUSY", 0: "EW_OK",
	1: "EW_FUNC", 2: "EW_LENGTH", 3: "EW_NUMBER", 4: "EW_ATTRIB", 5: "EW_DATA",
	6: "EW_NOOPT", 7: "EW_PROT", 9: "EW_PARAM", 10: "EW_BUFFER", 11: "EW_PATH",
	12: "EW_MODE", 13: "EW_REJECT", 15: "EW_ALARM", 16: "EW_STOP",
	17: "EW_PASSWD",
}

var modes = []string{"MDI", "MEM", "****", "EDIT", "HND", "JOG", "TJOG", "THND", "INC", "REF", "RMT"}
var runStates = []string{"RESET", "STOP", "HOLD", "START", "MSTR"}

// focasError is a FOCAS function's EW_* code other than EW_OK.
type focasError struct {
	function string
	code     C.short
}

func (e focasError) Error() string {
	name, ok := ewNames[e.code]
	if !ok {
		name = "EW_?"
	}
	return fmt.Sprintf("%s failed: %s (%d)", e.function, name, int(e.code))
}

// check turns a FOCAS return code into an error.
func check(function string, ret C.short) error {
	if ret != C.EW_OK {
		return focasError{function, ret}
	}
	return nil
}

// fixed formats value * 10^-decimals with `decimals` places, exactly.
func fixed(value int64, decimals int) string {
	if decimals <= 0 {
		for ; decimals < 0; decimals++ {
			value *= 10
		}
		return strconv.FormatInt(value, 10)
	}
	sign := ""
	if value < 0 {
		sign, value = "-", -value
	}
	scale := int64(1)
	for i := 0; i < decimals; i++ {
		scale *= 10
	}
	return fmt.Sprintf("%s%d.%0*d", sign, value/scale, decimals, value%scale)
}

func pick(names []string, i C.short) string {
	if i >= 0 && int(i) < len(names) {
		return names[i]
	}
	return "?"
}

func report(h C.ushort) error {
	var sys C.ODBSYS
	if err := check("cnc_sysinfo", C.cnc_sysinfo(h, &sys)); err != nil {
		return err
	}
	fmt.Printf("cnc_type=%s\n", C.GoStringN(&sys.cnc_type[0], 2))
	fmt.Printf("mt_type=%s\n", C.GoStringN(&sys.mt_type[0], 2))
	fmt.Printf("series=%s\n", C.GoStringN(&sys.series[0], 4))
	fmt.Printf("version=%s\n", C.GoStringN(&sys.version[0], 4))

	var st C.ODBST
	if err := check("cnc_statinfo", C.cnc_statinfo(h, &st)); err != nil {
		return err
	}
	fmt.Printf("aut=%d (%s)\n", st.aut, pick(modes, st.aut))
	fmt.Printf("run=%d (%s)\n", st.run, pick(runStates, st.run))
	fmt.Printf("motion=%d\nmstb=%d\nemergency=%d\nalarm=%d\nedit=%d\n",
		st.motion, st.mstb, st.emergency, st.alarm, st.edit)

	// Axis names and decimal places, then every axis's positions in one call.
	var names [C.MAX_AXIS]C.ODBAXISNAME
	count := C.short(C.MAX_AXIS) // in: room, out: axes named
	if err := check("cnc_rdaxisname", C.cnc_rdaxisname(h, &count, &names[0])); err != nil {
		return err
	}
	naxes := int(count)
	var figures C.short
	var decIn, decOut [C.MAX_AXIS]C.short
	if err := check("cnc_getfigure", C.cnc_getfigure(h, 0, &figures, &decIn[0], &decOut[0])); err != nil {
		return err
	}
	var dyn C.ODBDY2
	if err := check("cnc_rddynamic2", C.cnc_rddynamic2(h, C.ALL_AXES, C.short(unsafe.Sizeof(dyn)), &dyn)); err != nil {
		return err
	}
	fmt.Printf("program=O%d\nsequence=N%d\nfeed=%d\nspindle_speed=%d\n",
		dyn.prgnum, dyn.seqnum, dyn.actf, dyn.acts)
	fmt.Printf("axes=%d\n", naxes)
	// cgo shows a C union as bytes: pos holds the all-axes form here.
	pos := (*C.ODBDY_FAXIS)(unsafe.Pointer(&dyn.pos))
	axisNames := make([]string, naxes)
	for i := 0; i < naxes; i++ {
		name := string(rune(byte(names[i].name)))
		if names[i].suff != 0 {
			name += string(rune(byte(names[i].suff)))
		}
		axisNames[i] = name
		dec := 0
		if i < int(figures) {
			dec = int(decIn[i])
		}
		fmt.Printf("%s.absolute=%s\n", name, fixed(int64(pos.absolute[i]), dec))
		fmt.Printf("%s.machine=%s\n", name, fixed(int64(pos.machine[i]), dec))
		fmt.Printf("%s.relative=%s\n", name, fixed(int64(pos.relative[i]), dec))
		fmt.Printf("%s.distance=%s\n", name, fixed(int64(pos.distance[i]), dec))
	}

	// Active alarms (type -1: all), up to 10.
	var alarms [10]C.ODBALMMSG2
	count = C.short(len(alarms)) // in: room, out: alarms read
	if err := check("cnc_rdalmmsg2", C.cnc_rdalmmsg2(h, -1, &count, &alarms[0])); err != nil {
		return err
	}
	fmt.Printf("alarms=%d\n", count)
	for i := 0; i < int(count); i++ {
		a := &alarms[i]
		n := int(a.msg_len)
		if n < 0 || n > len(a.alm_msg) {
			n = len(a.alm_msg)
		}
		fmt.Printf("alarm%d=%d (type %d, axis %d) %s\n", i+1, a.alm_no, a._type, a.axis,
			C.GoStringN(&a.alm_msg[0], C.int(n)))
	}

	// Parameter 6711, the part counter: one 2-word value (4 + 4 bytes).
	var prm C.IODBPSD
	if err := check("cnc_rdparam", C.cnc_rdparam(h, 6711, 0, 4+4, &prm)); err != nil {
		return err
	}
	fmt.Printf("param6711=%d\n", *(*C.LONG)(unsafe.Pointer(&prm.u)))

	// Parameter 1320, stored stroke limit +: one real value per axis.
	prm = C.IODBPSD{}
	length := C.short(4 + unsafe.Sizeof(C.REALPRM{})*C.MAX_AXIS)
	if err := check("cnc_rdparam", C.cnc_rdparam(h, 1320, C.ALL_AXES, length, &prm)); err != nil {
		return err
	}
	reals := (*[C.MAX_AXIS]C.REALPRM)(unsafe.Pointer(&prm.u))
	for i := 0; i < naxes; i++ {
		r := reals[i]
		fmt.Printf("param1320.%s=%s\n", axisNames[i][:1], fixed(int64(r.prm_val), int(r.dec_val)))
	}
	return nil
}

func run() int {
	timeout := flag.Int("timeout", 10, "connect timeout, seconds")
	flag.Usage = func() {
		fmt.Fprintf(flag.CommandLine.Output(), "usage: %s [-timeout S] HOST [PORT]\n", os.Args[0])
		flag.PrintDefaults()
	}
	flag.Parse()
	if flag.NArg() < 1 || flag.NArg() > 2 {
		flag.Usage()
		return 2
	}
	host, port := flag.Arg(0), 8193
	if flag.NArg() == 2 {
		p, err := strconv.ParseUint(flag.Arg(1), 10, 16)
		if err != nil {
			fmt.Fprintf(os.Stderr, "bad port %q\n", flag.Arg(1))
			return 2
		}
		port = int(p)
	}

	// FANUC's Linux library needs this call before any other; ours does not.
	logName := C.CString("focas.log")
	defer C.free(unsafe.Pointer(logName))
	C.cnc_startupprocess(0, logName)
	defer C.cnc_exitprocess()

	cHost := C.CString(host)
	defer C.free(unsafe.Pointer(cHost))
	var h C.ushort
	if err := check("cnc_allclibhndl3", C.cnc_allclibhndl3(cHost, C.ushort(port), C.long(*timeout), &h)); err != nil {
		fmt.Fprintf(os.Stderr, "cannot connect to %s:%d: %v\n", host, port, err)
		return 1
	}
	fmt.Printf("connected=%s:%d\n", host, port)

	status := 0
	if err := report(h); err != nil {
		fmt.Fprintln(os.Stderr, err)
		status = 1
	}
	if err := check("cnc_freelibhndl", C.cnc_freelibhndl(h)); err != nil {
		fmt.Fprintln(os.Stderr, err)
		status = 1
	}
	return status
}

func main() {
	os.Exit(run())
}
