# Monte Carlo ray tracer: a teaching renderer, one concept per file, one chapter per program.
#
#   make figures        render every chapter's figures into build/figures/ (QUICK=1: small)
#   make test           build and run the cmocka tests
#   make chapterN       build and run chapter N (ARGS="--size 200 --spp 4" to change settings)
#   make sanitize       the tests under AddressSanitizer and UndefinedBehaviorSanitizer
#   make fuzz           build the scene reader's libFuzzer target and run it (FUZZ_SECONDS)
#   make bench          the speed benchmark (a benchmark, not a test)
#   make clean
#
# CC, CFLAGS and LDFLAGS are honoured; the flags the project requires are added to them.

CC      ?= cc
CFLAGS  ?= -O2 -g
LDFLAGS ?=
BUILD   ?= build
FIGURES ?= $(BUILD)/figures
ARGS    ?=
QUICK   ?=
FUZZ_SECONDS ?= 60

ifneq ($(QUICK),)
QUICK_ARGS := --quick
endif

# stb's headers are third-party: include them as system headers so -Werror judges only ours.
# Evaluated when used (=, not :=), so after .ci/install-deps has run on a fresh machine.
PKG_CFLAGS  = $(patsubst -I%,-isystem %,$(shell pkg-config --cflags stb cmocka 2>/dev/null))
REQUIRED   := -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wpedantic -Werror -pthread
ALL_CFLAGS  = $(REQUIRED) -Ilib $(PKG_CFLAGS) $(CFLAGS) -MMD -MP
LIBS        = $(shell pkg-config --libs stb 2>/dev/null) -lm -pthread
TEST_LIBS   = $(shell pkg-config --libs cmocka 2>/dev/null) $(LIBS)

LIB_SRC     := $(wildcard lib/*.c)
LIB_OBJ     := $(patsubst lib/%.c,$(BUILD)/lib/%.o,$(LIB_SRC))
LIBRARY     := $(BUILD)/libmc.a
CHAPTER_SRC := $(wildcard chapters/ch*.c)
CHAPTER_BIN := $(patsubst chapters/%.c,$(BUILD)/%,$(CHAPTER_SRC))
TEST_SRC    := $(wildcard tests/test_*.c)
TEST_BIN    := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
DEPS_OK     := $(BUILD)/.deps-ok

.PHONY: all test figures sanitize fuzz bench clean deps
.DEFAULT_GOAL := all

all: $(LIBRARY) $(CHAPTER_BIN) $(TEST_BIN)

deps: $(DEPS_OK)
$(DEPS_OK):
	@sh .ci/install-deps
	@mkdir -p $(@D) && touch $@

$(BUILD)/lib/%.o: lib/%.c | $(DEPS_OK)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(LIBRARY): $(LIB_OBJ)
	$(AR) rcs $@ $^

$(BUILD)/ch%: chapters/ch%.c $(LIBRARY)
	$(CC) $(ALL_CFLAGS) $< $(LIBRARY) $(LDFLAGS) $(LIBS) -o $@

$(BUILD)/tests/%: tests/%.c $(LIBRARY) | $(DEPS_OK)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $< $(LIBRARY) $(LDFLAGS) $(TEST_LIBS) -o $@

# Each test program is run from the top directory (some read scenes/ and run the chapter
# programs). The last line counts the programs that passed and failed.
test: $(TEST_BIN) $(CHAPTER_BIN)
	@passed=0; failed=0; \
	for t in $(TEST_BIN); do \
	    if CHAPTER_DIR=$(BUILD) $$t; then passed=$$((passed+1)); \
	    else failed=$$((failed+1)); echo "FAILED: $$t"; fi; \
	done; \
	echo "test programs: $$passed passed, $$failed failed"; \
	[ $$failed -eq 0 ]

# chapterN: build and run chapter N's program, figures into $(FIGURES).
chapter_bin = $(patsubst chapters/%.c,$(BUILD)/%,$(wildcard chapters/ch0$(1)_*.c))
define CHAPTER_RULE
.PHONY: chapter$(1)
chapter$(1): $(call chapter_bin,$(1))
	$(call chapter_bin,$(1)) --out $(FIGURES) $(QUICK_ARGS) $(ARGS)
endef
CHAPTERS := $(foreach n,1 2 3 4 5 6 7 8,$(if $(wildcard chapters/ch0$(n)_*.c),$(n)))
$(foreach n,$(CHAPTERS),$(eval $(call CHAPTER_RULE,$(n))))

figures:
	@for n in $(CHAPTERS); do $(MAKE) --no-print-directory chapter$$n || exit 1; done

sanitize:
	$(MAKE) --no-print-directory BUILD=$(BUILD)/sanitize \
	    CFLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
	    LDFLAGS="-fsanitize=address,undefined" test

FUZZ_BIN := $(BUILD)/fuzz/fuzz_scene_file
FUZZ_SRC := $(addprefix lib/,scene_file.c scene.c bvh.c triangle.c sphere.c camera.c ray.c vec.c rng.c)
$(FUZZ_BIN): tests/fuzz_scene_file.c $(FUZZ_SRC) | $(DEPS_OK)
	@sh .ci/install-deps clang
	@mkdir -p $(@D) $(BUILD)/fuzz/corpus
	clang $(REQUIRED) -Ilib -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all $^ -lm -o $@

fuzz: $(FUZZ_BIN)
	$(FUZZ_BIN) -max_total_time=$(FUZZ_SECONDS) -timeout=5 -max_len=4096 \
	    $(BUILD)/fuzz/corpus tests/fuzz_corpus scenes

# The benchmark: speed, not correctness (BENCH_ARGS="--size 400" to change it).
BENCH_ARGS ?=
bench: $(BUILD)/tests/bench
	$(BUILD)/tests/bench $(BENCH_ARGS)

clean:
	rm -rf $(BUILD)

-include $(LIB_OBJ:.o=.d) $(CHAPTER_BIN:=.d) $(TEST_BIN:=.d)
