# make [build]                 cargo build --release (the library, focas-sim and focas)
# make install [PREFIX=/usr/local] [DESTDIR=]
# make uninstall [PREFIX=/usr/local] [DESTDIR=]
#
# Installs, under $(DESTDIR)$(PREFIX):
#   lib/libfwlib32.so.$(VERSION)        stripped, with a .gnu_debuglink
#   lib/libfwlib32.so.$(MAJOR)          -> libfwlib32.so.$(VERSION) (the soname)
#   lib/libfwlib32.so                   -> libfwlib32.so.$(MAJOR) (for -lfwlib32)
#   lib/libfwlib32.a                    debug sections stripped
#   lib/pkgconfig/fwlib32.pc
#   include/fwlib32.h, include/fwlib32_ext.h
#   bin/focas-sim                       stripped, with a .gnu_debuglink
#   bin/focas                           the command-line client, likewise
#   lib/debug/<installed path>.debug    the debug info (zlib-compressed), kept
#                                       apart as distributions do, and
#   lib/debug/.build-id/xx/yyyy.debug   -> it, for gdb and debuginfod
#
# gdb finds the debug files with `set debug-file-directory $(PREFIX)/lib/debug`
# (its default, /usr/lib/debug, for PREFIX=/usr).
#
# TARGET=aarch64-unknown-linux-gnu builds and installs for that target (set
# STRIP, OBJCOPY and READELF to its binutils, e.g. aarch64-linux-gnu-strip).
# NO_BUILD=1 installs what is already built (e.g. `sudo make install NO_BUILD=1`
# after `make` as yourself).
#
# STD=slim (the default when rustup's rust-src component is installed:
# `rustup component add rust-src`) builds the library against a standard
# library compiled from source without its backtrace symboliser (gimli,
# addr2line, miniz, rustc-demangle: about 190 KB the library never uses; a
# panic is still caught at the C boundary and answered with an EW_* code).
# That needs cargo's -Zbuild-std, unstable: RUSTC_BOOTSTRAP=1 is set for that
# one build. STD=prebuilt links the toolchain's std as `cargo build` does
# (a stripped library of about 1.13 MB instead of 0.93 MB on x86-64).
#
# OPT=z (the default) builds the installed library for size (rustc's
# opt-level; 3 is cargo's release default): 0.98 MB instead of 1.03 MB with
# 268 functions, STD=slim, x86-64. A call's time is the network's and the
# CNC's, not the codec's (docs/benchmarks.md measures cargo's release build).
#
# Today's installed library (STD=slim, OPT=z, x86-64): 984,752 bytes
# stripped with 1,089 exports, 724 of them the functions no Ethernet library
# of FANUC's has (a naked jump each, about 60 bytes with its symbol); 879,776
# with 284 functions before those (997,152 before the relaxed relocations,
# FWLIB32_SLIM and ffi::described's one `run`). tests/artifacts/install.rs holds
# it to 1,000,000; docs/benchmarks.md, "Library size", says where it goes.

PREFIX     ?= /usr/local
DESTDIR    ?=
BINDIR     ?= $(PREFIX)/bin
LIBDIR     ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
DEBUGDIR   ?= $(LIBDIR)/debug

CARGO      ?= cargo
OPT        ?= z
CARGO_TARGET_DIR ?= target
TARGET     ?= $(CARGO_BUILD_TARGET)
STRIP      ?= strip
OBJCOPY    ?= objcopy
READELF    ?= readelf
INSTALL    ?= install

VERSION := $(shell sed -n 's/^version *= *"\([^"]*\)".*/\1/p' Cargo.toml | head -n 1)
MAJOR   := $(firstword $(subst ., ,$(VERSION)))
SONAME  := libfwlib32.so.$(MAJOR)
REALNAME := libfwlib32.so.$(VERSION)

ifeq ($(TARGET),)
OUT := $(CARGO_TARGET_DIR)/release
TARGET_FLAG :=
else
OUT := $(CARGO_TARGET_DIR)/$(TARGET)/release
TARGET_FLAG := --target $(TARGET)
endif

RUSTC    ?= rustc
comma := ,
HOST     := $(shell $(RUSTC) -vV 2>/dev/null | sed -n 's/^host: //p')
RUST_SRC := $(shell $(RUSTC) --print sysroot 2>/dev/null)/lib/rustlib/src/rust/library/std
ifeq ($(STD),)
STD := $(if $(wildcard $(RUST_SRC)),slim,prebuilt)
endif
# Either build sets FWLIB32_SLIM=1: the library's table of described
# functions leaves out their documentation, the oracle's sweeps and the
# learner's notes, which no call reads (build.rs, src/spec/table/mod.rs):
# 29 KB on x86-64 with 135 entries.
ifeq ($(STD),slim)
# The library is built without the simulator and the command line
# (--no-default-features: libfwlib32.a holds no tokio), in its own target
# directory: `cargo build --bins` builds the library's artifacts too, with the
# default features, and would overwrite these.
LIB_TARGET := $(if $(TARGET),$(TARGET),$(HOST))
LIB_OUT := $(CARGO_TARGET_DIR)/slim-std/$(LIB_TARGET)/release
# For size, also unstable (the same RUSTC_BOOTSTRAP): panics name no source
# location (-Zlocation-detail=none; the C boundary still catches them), std's
# optimize_for_size, and for a native build the toolchain's own lld folding
# identical functions (--icf=all): 0.997 MB instead of 1.04 MB with 284
# functions, x86-64. -Zrelax-elf-relocations=yes lets the linker turn a call
# or address through the GOT (rustc's default without a PLT) into a direct one
# where the target is in the library, as every Rust function of it is: no GOT
# slot and dynamic relocation per function (1,456 of them, 47 KB on x86-64;
# the static library's objects then need binutils 2.26 or later to link).
LLD_DIR := $(shell $(RUSTC) --print sysroot 2>/dev/null)/lib/rustlib/$(HOST)/bin/gcc-ld
SLIM_FLAGS := -Zlocation-detail=none -Zrelax-elf-relocations=yes $(if $(and $(if $(TARGET),,native),$(wildcard $(LLD_DIR)/ld.lld)),\
    -Clink-arg=-B$(LLD_DIR) -Clink-arg=-fuse-ld=lld -Clink-arg=-Wl$(comma)--icf=all)
LIB_BUILD := RUSTC_BOOTSTRAP=1 FWLIB32_SLIM=1 CARGO_PROFILE_RELEASE_OPT_LEVEL=$(OPT) \
    RUSTFLAGS="$(strip $(RUSTFLAGS) $(SLIM_FLAGS))" \
    $(CARGO) build --release --locked --lib --no-default-features \
    --target $(LIB_TARGET) --target-dir $(CARGO_TARGET_DIR)/slim-std \
    -Zbuild-std=std,panic_unwind -Zbuild-std-features=panic-unwind,optimize_for_size
else ifeq ($(STD),prebuilt)
LIB_OUT := $(CARGO_TARGET_DIR)/lib-only/$(if $(TARGET),$(TARGET)/)release
LIB_BUILD := FWLIB32_SLIM=1 CARGO_PROFILE_RELEASE_OPT_LEVEL=$(OPT) \
    $(CARGO) build --release --locked --lib --no-default-features $(TARGET_FLAG) \
    --target-dir $(CARGO_TARGET_DIR)/lib-only
else
$(error STD=$(STD): slim or prebuilt)
endif

# What the static library needs besides libc (`rustc --print native-static-libs`).
LIBS_PRIVATE := -lgcc_s -lutil -lrt -lpthread -lm -ldl -lc

D := $(DESTDIR)

.PHONY: all build install uninstall print-std

all: build

# Which standard library `make` links (tests/artifacts/install.rs reads it).
print-std:
	@echo $(STD)

build:
ifeq ($(NO_BUILD),)
	@echo "std: $(STD)"
	$(LIB_BUILD)
	$(CARGO) build --release --locked --bins $(TARGET_FLAG)
endif
	@test -n "$(VERSION)" || { echo "no version in Cargo.toml" >&2; exit 1; }
	@for f in $(LIB_OUT)/libfwlib32.so $(LIB_OUT)/libfwlib32.a $(OUT)/focas-sim $(OUT)/focas; do \
	    test -f "$$f" || { echo "$$f is missing: run make first (with the same STD)" >&2; exit 1; }; \
	done

# $(call strip_install,SOURCE,DEST,MODE): DEST gets SOURCE stripped, its debug
# info goes to $(DEBUGDIR)/DEST.debug (DEST without DESTDIR), with a build-id link.
define strip_install
	$(INSTALL) -d "$(D)$(dir $(2))" "$(D)$(DEBUGDIR)$(dir $(2))"
	$(OBJCOPY) --only-keep-debug --compress-debug-sections=zlib "$(1)" "$(D)$(DEBUGDIR)$(2).debug"
	chmod 644 "$(D)$(DEBUGDIR)$(2).debug"
	$(STRIP) --strip-unneeded --remove-section=.comment -o "$(D)$(2).tmp" "$(1)"
	$(OBJCOPY) --add-gnu-debuglink="$(D)$(DEBUGDIR)$(2).debug" "$(D)$(2).tmp"
	chmod $(3) "$(D)$(2).tmp"
	mv -f "$(D)$(2).tmp" "$(D)$(2)"
	@id=$$($(READELF) -n "$(D)$(2)" | sed -n 's/.*Build ID: *\([0-9a-f]*\).*/\1/p'); \
	if [ -n "$$id" ]; then \
	    dir="$(D)$(DEBUGDIR)/.build-id/$$(echo $$id | cut -c1-2)"; \
	    link="$$dir/$$(echo $$id | cut -c3-).debug"; \
	    echo "ln -sf ../..$(2).debug $$link"; \
	    $(INSTALL) -d "$$dir" && ln -sf "../..$(2).debug" "$$link"; \
	fi
endef

install: build
	$(call strip_install,$(LIB_OUT)/libfwlib32.so,$(LIBDIR)/$(REALNAME),755)
	ln -sf $(REALNAME) "$(D)$(LIBDIR)/$(SONAME)"
	ln -sf $(SONAME) "$(D)$(LIBDIR)/libfwlib32.so"
	$(INSTALL) -m 644 "$(LIB_OUT)/libfwlib32.a" "$(D)$(LIBDIR)/libfwlib32.a"
	$(STRIP) --strip-debug "$(D)$(LIBDIR)/libfwlib32.a"
	$(INSTALL) -d "$(D)$(INCLUDEDIR)" "$(D)$(PKGCONFIGDIR)"
	$(INSTALL) -m 644 include/fwlib32.h include/fwlib32_ext.h "$(D)$(INCLUDEDIR)/"
	printf '%s\n' \
	    'prefix=$(PREFIX)' \
	    'libdir=$(LIBDIR)' \
	    'includedir=$(INCLUDEDIR)' \
	    '' \
	    'Name: fwlib32' \
	    'Description: FOCAS2 Ethernet library (fwlib32-rs, a replacement for FANUC'"'"'s libfwlib32)' \
	    'Version: $(VERSION)' \
	    'Libs: -L$${libdir} -lfwlib32' \
	    'Libs.private: $(LIBS_PRIVATE)' \
	    'Cflags: -I$${includedir}' \
	    > "$(D)$(PKGCONFIGDIR)/fwlib32.pc"
	chmod 644 "$(D)$(PKGCONFIGDIR)/fwlib32.pc"
	$(call strip_install,$(OUT)/focas-sim,$(BINDIR)/focas-sim,755)
	$(call strip_install,$(OUT)/focas,$(BINDIR)/focas,755)
	@if [ -z "$(DESTDIR)" ] && [ -w /etc/ld.so.cache ] && command -v ldconfig >/dev/null; then \
	    echo ldconfig; ldconfig; \
	fi

uninstall:
	@for f in "$(LIBDIR)/$(REALNAME)" "$(BINDIR)/focas-sim" "$(BINDIR)/focas"; do \
	    id=$$($(READELF) -n "$(D)$$f" 2>/dev/null | sed -n 's/.*Build ID: *\([0-9a-f]*\).*/\1/p'); \
	    if [ -n "$$id" ]; then \
	        l="$(D)$(DEBUGDIR)/.build-id/$$(echo $$id | cut -c1-2)/$$(echo $$id | cut -c3-).debug"; \
	        echo "rm -f $$l"; rm -f "$$l"; \
	        rmdir "$$(dirname "$$l")" 2>/dev/null || true; \
	    fi; \
	done
	rm -f "$(D)$(LIBDIR)/$(REALNAME)" "$(D)$(LIBDIR)/$(SONAME)" "$(D)$(LIBDIR)/libfwlib32.so" \
	    "$(D)$(LIBDIR)/libfwlib32.a" "$(D)$(PKGCONFIGDIR)/fwlib32.pc" \
	    "$(D)$(INCLUDEDIR)/fwlib32.h" "$(D)$(INCLUDEDIR)/fwlib32_ext.h" \
	    "$(D)$(BINDIR)/focas-sim" "$(D)$(BINDIR)/focas" \
	    "$(D)$(DEBUGDIR)$(LIBDIR)/$(REALNAME).debug" "$(D)$(DEBUGDIR)$(BINDIR)/focas-sim.debug" \
	    "$(D)$(DEBUGDIR)$(BINDIR)/focas.debug"
	@if [ -z "$(DESTDIR)" ] && [ -w /etc/ld.so.cache ] && command -v ldconfig >/dev/null; then \
	    echo ldconfig; ldconfig; \
	fi
