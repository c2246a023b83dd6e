# The two set-up commands of hyst (see README.md):
#   make demo   install missing Debian packages, build, run the demo (writes out/demo/)
#   make test   the same set-up, then every test, a short run of every benchmark, the C++
#               tests again under AddressSanitizer + UndefinedBehaviorSanitizer, and 20 s of
#               every libFuzzer target (clang, see fuzz/ and docs/reliability.md).

BUILD      ?= build
# One clang build serves the sanitizer tests and the fuzz targets: everything in it is compiled
# with AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer's coverage instrumentation
# (-fsanitize=fuzzer-no-link); the tests link the sanitizers' runtime, the fuzz targets libFuzzer's
# main. Line tables are enough for the sanitizers' stack traces and cost less than full -g.
CHECK_BUILD ?= build-check
# Seconds each fuzz target runs in `make test` (docs/reliability.md has the counts of a run), from
# a fixed seed: a run explores the same inputs in the same order on every machine (a faster one
# gets further), so that a CI run repeats what a longer local run with that seed has explored.
FUZZ_SECONDS ?= 20
FUZZ_SEED    ?= 1
FUZZ_TARGETS := fuzz_csv fuzz_mat_file fuzz_model_file fuzz_instrument_files fuzz_json_entry_points \
  fuzz_numpy_file fuzz_cli_arguments
JOBS       ?= $(shell nproc)
DEMO_OUT   ?= out/demo

# Debian 12 packages the build and the tests need.
DEBIAN_PACKAGES := cmake make gcc g++ pkg-config \
  libfmt-dev libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev \
  libmatio-dev zlib1g-dev libzip-dev libpugixml-dev nlohmann-json3-dev libcli11-dev libceres-dev libnlopt-dev libnlopt-cxx-dev libboost-dev \
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-mypy python3-matplotlib \
  python3-nbclient python3-nbformat python3-ipykernel python3-tqdm python3-distributed gnuplot-nox \
  libjs-chart.js clang libclang-rt-14-dev chromium

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build demo test test-cpp test-python bench-smoke check-build test-sanitize test-fuzz format format-check clean

all: build

# apt-get update and install run only when a package is missing.
deps:
	@missing=""; \
	for p in $(DEBIAN_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing missing Debian packages:$$missing"; \
	  $(SUDO) apt-get update && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $$missing; \
	else \
	  echo "all Debian packages present"; \
	fi

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/apps/hyst_demo --data ../shared/data --out $(DEMO_OUT)

test: build
	$(MAKE) test-cpp bench-smoke test-sanitize test-fuzz

test-cpp:
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# The Python module's tests and examples alone (make test runs them too, through ctest), with
# Debian's interpreter, which the module is built for.
test-python: build
	PYTHONPATH=$(BUILD)/python /usr/bin/python3 -m pytest -q -p no:cacheprovider python/tests
	@set -e; for e in examples/*.py; do \
	  echo "== $$e"; PYTHONPATH=$(BUILD)/python /usr/bin/python3 $$e; \
	done

# Proves every benchmark runs; it does not time anything (see docs/performance.md for that).
bench-smoke:
	@set -e; for b in $(BUILD)/bench/bench_*; do \
	  echo "== $$b"; $$b --benchmark_min_time=0.001 > /dev/null; \
	done; \
	echo "== bench/batch_throughput.py"; \
	PYTHONPATH=$(BUILD)/python /usr/bin/python3 bench/batch_throughput.py --cases pi:300:10 \
	  > /dev/null; \
	echo "benchmarks ran"

check-build: deps
	CXX=clang++ cmake -S . -B $(CHECK_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
	  -DHYST_SANITIZE=ON -DHYST_BUILD_FUZZERS=ON \
	  -DHYST_BUILD_BENCHMARKS=OFF -DHYST_BUILD_EXAMPLES=OFF -DHYST_BUILD_PYTHON=OFF
	cmake --build $(CHECK_BUILD) -j $(JOBS)

# Left to the Release run (make test-cpp): tests whose worth is not what the sanitizers look at and
# that are slow under them (docs/reliability.md has the times): killing a run in the middle of its
# output (timing, not memory), the fits to measured FORCs, whose code the simulated-FORC fit
# checks under the sanitizers too, and the CLI fit of the butterfly with creep to the 60 s record
# (60 s under the sanitizers), whose fit the synthetic butterfly-creep test checks there too.
SANITIZE_SKIP := ^(cli_output_set_killed|cli_output_set_actuator_killed|cli_atomic_output_killed|cli_fit_forc|FitPreisachForcData\..*|cli_butterfly_creep)$$

test-sanitize: check-build
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir $(CHECK_BUILD) --output-on-failure -j $(JOBS) -E '$(SANITIZE_SKIP)'

# Every libFuzzer target (fuzz/) for FUZZ_SECONDS from its committed seed corpus (fuzz/corpus/),
# from the clang build above. New inputs go to $(CHECK_BUILD)/corpus/, crashes to
# $(CHECK_BUILD)/crashes/; the last line of each log has the number of executions. The folders are
# absolute paths: fuzz_cli_arguments works in a scratch folder of its own.
test-fuzz: check-build
	@set -e; for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(CHECK_BUILD)/corpus/$$t $(CHECK_BUILD)/crashes/$$t; \
	  echo "== $$t ($(FUZZ_SECONDS) s)"; \
	  if ! ASAN_OPTIONS=detect_leaks=1 \
	    UBSAN_OPTIONS=print_stacktrace=1 \
	    $(CHECK_BUILD)/fuzz/$$t -max_total_time=$(FUZZ_SECONDS) -seed=$(FUZZ_SEED) -rss_limit_mb=2048 \
	      -timeout=10 \
	      -artifact_prefix=$(CURDIR)/$(CHECK_BUILD)/crashes/$$t/ -print_final_stats=1 \
	      $(CURDIR)/$(CHECK_BUILD)/corpus/$$t $(CURDIR)/fuzz/corpus/$$t > $(CHECK_BUILD)/$$t.log 2>&1; then \
	    tail -n 60 $(CHECK_BUILD)/$$t.log; echo "$$t found a failure: see $(CHECK_BUILD)/crashes/$$t"; \
	    exit 1; \
	  fi; \
	  grep -E '^(stat::number_of_executed_units|Done)' $(CHECK_BUILD)/$$t.log || true; \
	done; echo "fuzz targets ran without failure"

format:
	git ls-files '*.hpp' '*.cpp' | xargs clang-format -i

format-check:
	git ls-files '*.hpp' '*.cpp' | xargs clang-format --dry-run --Werror

clean:
	rm -rf $(BUILD) $(CHECK_BUILD) out
