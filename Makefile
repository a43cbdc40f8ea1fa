# brash: top-level entry points. A user needs two: `make run` and `make test`.
BUILD_DIR ?= build
JOBS      ?= $(shell nproc)
CASE      ?= cases/jbc_quick

# Every Debian package the project needs (installed with --no-install-recommends: Debian's liggghts
# recommends ParaView, which conflicts with libvtk9-dev).
DEB_PACKAGES := g++ make cmake ninja-build pkg-config \
  libeigen3-dev nlohmann-json3-dev libcli11-dev libyaml-cpp-dev libfmt-dev \
  libgtest-dev libgmock-dev libbenchmark-dev valgrind \
  liggghts libliggghts-dev openmpi-bin libopenmpi-dev \
  libode-dev libvtk9-dev gnuplot-nox python3-meshio python3-numpy python3-pandas python3-yaml python3-vtk9 jq \
  clang libclang-rt-14-dev \
  yade pybind11-dev python3-dev

.PHONY: deps build test run bench study validation reference install clean

deps:
	@missing=""; for p in $(DEB_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "brash: installing Debian packages:$$missing"; \
	  SUDO=""; [ "$$(id -u)" -eq 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -q && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -q --no-install-recommends $$missing; \
	else echo "brash: all Debian packages present"; fi

$(BUILD_DIR)/build.ninja:
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo

build: deps $(BUILD_DIR)/build.ninja
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) --timeout 1500

run: build
	./scripts/brash-run $(CASE)

# The headline benchmarks in minutes with one summary table (scripts/brash-bench); long studies: bash bench/<name>.sh.
bench: build
	./scripts/brash-bench

# A study, run by brash-study from the study file study/$(STUDY).yaml (full: paper case + sweeps, days; short:
# sweeps on jbc_bench, ~1 h; smoke: 3 tiny runs) -> runs/study-$(STUDY)/study.md. STUDY_DOC / STUDY_WORK redirect
# the document and the work dir; STUDY_PAPER=1, STUDY_ENSEMBLES=1, STUDY_YADE=1 add the paper runs, the ensembles,
# YADE; complete paper runs and ensemble summaries are archived in evidence/.
STUDY ?= full
study: build
	$(BUILD_DIR)/bin/brash-study --study study/$(STUDY).yaml

# The validation page, generated from the curated report files in evidence/ (evidence/README.md).
validation: build
	BRASH_BIN=$(abspath $(BUILD_DIR))/bin ./scripts/brash-validation

# The reference page: every command's --help and every LIGGGHTS fix's syntax (scripts/brash-reference).
reference: build
	BRASH_BIN=$(abspath $(BUILD_DIR))/bin ./scripts/brash-reference

# The tools, the core library (find_package(brash): brash::core), the cases, hull data, study files and doc pages
# into $(PREFIX) (README.md "Install"); the installed tree finds its data relative to its bin/ folder.
PREFIX ?= /usr/local
install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD_DIR)
