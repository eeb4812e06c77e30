# Thin wrapper: every target installs what is missing, configures and builds first.
BUILD      ?= build
JOBS       ?= $(shell nproc)
SUDO       := $(if $(filter 0,$(shell id -u)),,sudo)
# What the modules link (docs/architecture.md, "Modules"), the compiler tool chain, and what the tests use.
PACKAGES   := build-essential cmake pkg-config \
              libopencv-dev libv4l-dev v4l-utils libusb-1.0-0-dev libhdf5-dev libeigen3-dev \
              libfftw3-dev libpugixml-dev zlib1g-dev libjpeg-dev nlohmann-json3-dev libvalijson-dev libboost-math-dev \
              libcli11-dev libsndfile1-dev libasound2-dev gnuplot-nox libgtest-dev libgmock-dev libbenchmark-dev \
              python3-h5py python3-numpy python3-pil python3-scipy python3-venv chromium \
              pulseaudio pulseaudio-utils libasound2-plugins
BENCH_PACKAGES := python3-opencv python3-torch python3-torchaudio hyperfine
HAPTEX     := $(BUILD)/haptex
DEMO       := $(BUILD)/demo

.PHONY: all deps build test demo bench golden install clean

all: build

deps:
	@missing=$$(for p in $(PACKAGES) $(EXTRA_PACKAGES); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing $$missing"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) --timeout 600

# The whole pipeline on the built-in synthetic materials: data, checks, both models, the evaluation.
# It builds the binary (and its codecs plugin) only; the test programs are make test's.
demo: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target haptex
	@rm -rf $(DEMO) && mkdir -p $(DEMO)
	examples/demo/run.sh $(HAPTEX) $(DEMO)
	@echo "make demo: done; open $(DEMO)/report/report.html to read and listen (the same as text: $(DEMO)/report/report.md)"

# The binary, the modules' headers and static libraries, the CMake package and haptex.pc (docs/library.md).
PREFIX ?= /usr/local
install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

bench:
	$(MAKE) deps EXTRA_PACKAGES="$(BENCH_PACKAGES)"
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DHAPTEX_BUILD_BENCH=ON $(CMAKE_ARGS)
	cmake --build $(BUILD) -j $(JOBS)
	bench/run_bench.sh $(BUILD)

# Regenerates the reference values under tests/golden with Debian's python3-scipy.
golden:
	$(MAKE) deps
	cd tests/golden && for s in *.py; do /usr/bin/python3 $$s || exit 1; done

clean:
	rm -rf $(BUILD)
