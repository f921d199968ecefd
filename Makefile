# Entry points for newcomers and CI. Every target installs what is missing first.
#   make test    - install, build (release preset), run ctest (default labels; slow cases excluded)
#   make report  - install, build, write build/report/index.html
#   make test-all, make asan, make format
PRESET ?= release
JOBS   ?= $(shell nproc)
BUILD_DIR = $(if $(filter release,$(PRESET)),build,build-$(PRESET))

.PHONY: all deps configure build test test-all report asan format clean
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

format:
	@git ls-files '*.h' '*.cc' | xargs clang-format -i

clean:
	rm -rf build build-*
