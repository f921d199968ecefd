# Entry points for newcomers and CI. Every target installs what is missing first.
#   make test    - install, build (release preset), run ctest (default labels; slow cases excluded)
#   make report  - install, build, write build/report/index.html
#   make test-all, make asan, make format
#   make fuzz    - libFuzzer (clang) on the scene parser and the command-line number parsing
PRESET ?= release
JOBS   ?= $(shell nproc)
# ccache, where installed, makes a rebuild of unchanged sources a cache hit (optional: the
# build does not need it; export CMAKE_CXX_COMPILER_LAUNCHER= to turn it off)
export CMAKE_CXX_COMPILER_LAUNCHER ?= $(shell command -v ccache 2>/dev/null)
BUILD_DIR = $(if $(filter release,$(PRESET)),build,build-$(PRESET))

.PHONY: all deps configure build test test-all report asan format clean fuzz
all: build

deps:
	@./scripts/install-deps.sh

configure: deps
	@cmake --preset $(PRESET) >/dev/null

build: configure
	@cmake --build --preset $(PRESET) -j $(JOBS)

test: build
	ctest --preset $(PRESET) -j $(JOBS)

test-all: build
	ctest --preset $(PRESET)-all -j $(JOBS)

report: build
	./$(BUILD_DIR)/app/ivv report --out $(BUILD_DIR)/report

asan:
	$(MAKE) test PRESET=asan

# libFuzzer (clang) on every target for FUZZ_SECONDS each, from the committed corpus; new
# inputs go to build-fuzz/corpus/<target>, crashes to build-fuzz/findings/. A finding fails.
FUZZ_SECONDS ?= 120
FUZZ_TARGETS = scene_parser cli_args
fuzz: deps
	@cmake --preset fuzz >/dev/null
	@cmake --build --preset fuzz -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_TARGETS))
	@mkdir -p build-fuzz/findings
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p build-fuzz/corpus/$$t; \
	  echo "fuzz: $$t for $(FUZZ_SECONDS) s"; \
	  build-fuzz/fuzz/fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -max_len=4096 -rss_limit_mb=2048 \
	    -artifact_prefix=build-fuzz/findings/$$t- build-fuzz/corpus/$$t fuzz/corpus/$$t || exit 1; \
	done

format:
	@git ls-files '*.h' '*.cc' | xargs clang-format -i

clean:
	rm -rf build build-*
