# nxtmap: the front door. Every target installs what it needs first (see scripts/deps.sh).
#   make demo   - the firmware in the emulated brick, driven from the PC console (live map, goal, house saved)
#   make test   - every test (host build with sanitizers + ARM7TDMI cross-build of common/ + make size)
#   make firmware / make size - the brick image and its enforced budgets
#   make bench  - speed and quality targets, measured against their targets
SHELL := /bin/bash
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)
BUILD ?= build
HOST_DIR  := $(BUILD)/host
SAN_DIR   := $(BUILD)/host-san
ARM_DIR   := $(BUILD)/arm-common
FW_DIR    := $(BUILD)/firmware
CMAKE_GEN := -G Ninja

.PHONY: all deps host host-san host-e2e arm-common firmware size test demo bench clean help fuzz format

all: host

help:
	@echo "make demo   - the firmware in the emulated brick with the PC console: explore, goal, save, export"
	@echo "make test   - build with sanitizers, run all tests, cross-build common/ for the ARM7TDMI"
	@echo "make bench  - benchmarks, measured against their targets"
	@echo "make firmware - the brick images: build/firmware/nxtmap.{elf,bin} (flash), nxtmap-ram.{elf,bin} (fwexec), nxtmap-sim.elf"
	@echo "make size   - the brick image's flash/RAM budgets, enforced"
	@echo "make deps   - install the missing Debian packages of every target (make test etc. install their own)"
	@echo "make fuzz   - fuzz the radio protocol decoder with libFuzzer (FUZZ_SECONDS=600)"
	@echo "make format - clang-format every C++ file in git (the style is .clang-format)"

# The packages for the goals asked for (make test: build + test; make deps alone: every target's).
DEPS_GOALS := $(filter test demo bench fuzz format,$(MAKECMDGOALS))
deps:
	@bash scripts/deps.sh $(if $(DEPS_GOALS),$(DEPS_GOALS),build test demo bench fuzz)

$(HOST_DIR)/build.ninja: | deps
	cmake -S . -B $(HOST_DIR) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release

$(SAN_DIR)/build.ninja: | deps
	cmake -S . -B $(SAN_DIR) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Debug -DNXTMAP_SANITIZE=ON

$(ARM_DIR)/build.ninja: | deps
	cmake -S toolchain/arm-check -B $(ARM_DIR) $(CMAKE_GEN) \
	  -DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/toolchain/arm-none-eabi.cmake

$(FW_DIR)/build.ninja: | deps
	cmake -S firmware -B $(FW_DIR) $(CMAKE_GEN) -DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/toolchain/arm-none-eabi.cmake

firmware: deps $(FW_DIR)/build.ninja
	cmake --build $(FW_DIR) -j $(JOBS)

size: firmware
	@bash toolchain/fw-size.sh $(FW_DIR)

host: deps $(HOST_DIR)/build.ninja
	cmake --build $(HOST_DIR) -j $(JOBS)

# make test's Release pass runs only the end-to-end and adversarial suites: build just what they need.
E2E_TARGETS := nxtmap test_adversarial test_emu test_link
host-e2e: deps $(HOST_DIR)/build.ninja
	cmake --build $(HOST_DIR) -j $(JOBS) --target $(E2E_TARGETS)

host-san: deps $(SAN_DIR)/build.ninja
	cmake --build $(SAN_DIR) -j $(JOBS)

arm-common: deps $(ARM_DIR)/build.ninja
	cmake --build $(ARM_DIR) -j $(JOBS)
	@echo "common/ cross-compiled for the ARM7TDMI (-mcpu=arm7tdmi -mthumb, freestanding): OK"

test: host-san arm-common size host-e2e
	cd $(SAN_DIR) && ctest --output-on-failure -j $(JOBS)
	@# The emulated brick's 18-room acceptance runs at full speed from the Release build (skipped under ASan);
	@# the adversarial suite runs in both builds (a bad input must be refused the same way without sanitizers).
	cd $(HOST_DIR) && ctest --output-on-failure -j $(JOBS) -R 'EndToEnd|Adversarial'

demo: host firmware
	BUILD=$(BUILD) bash scripts/demo.sh

format: deps
	git ls-files '*.cpp' '*.hpp' '*.h' ':!toolchain/' | xargs clang-format -i

bench: host firmware
	NXTMAP_PEER_DIR=$(BUILD)/peer $(HOST_DIR)/host/bench/nxtmap-bench

# libFuzzer on the protocol decoder (clang). New finds are merged into fuzz/corpus (kept in git,
# replayed by make test); a crash leaves its input in $(FUZZ_DIR)/crash-*.
FUZZ_DIR     := $(BUILD)/fuzz
FUZZ_SECONDS ?= 600
FUZZ_SOURCES := fuzz/ProtocolFuzz.cpp $(wildcard common/protocol/*.cpp common/grid/*.cpp) common/check/Check.cpp \
                host/link/Session.cpp host/link/MirrorMap.cpp
$(FUZZ_DIR)/protocol-fuzz: $(FUZZ_SOURCES) $(wildcard fuzz/*.hpp common/protocol/*.hpp host/link/*.hpp) | deps
	@mkdir -p $(FUZZ_DIR)
	clang++ -std=c++17 -g -O1 -I. -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
	  $(FUZZ_SOURCES) -o $@

fuzz: $(FUZZ_DIR)/protocol-fuzz
	@mkdir -p $(FUZZ_DIR)/found
	cd $(FUZZ_DIR) && ./protocol-fuzz -max_total_time=$(FUZZ_SECONDS) -max_len=512 -print_final_stats=1 \
	  found $(CURDIR)/fuzz/corpus 2>&1 | tail -n 25
	$(FUZZ_DIR)/protocol-fuzz -merge=1 fuzz/corpus $(FUZZ_DIR)/found 2>&1 | tail -n 2
	@echo "fuzz: $(FUZZ_SECONDS) s without a crash; corpus: $$(ls fuzz/corpus | wc -l) inputs in fuzz/corpus"

clean:
	rm -rf $(BUILD)
