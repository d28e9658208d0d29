# Monte Carlo ray tracer: a teaching renderer, one concept per file, one chapter per program.
#
#   make figures          render every chapter's figures into build/figures/ (QUICK=1: small)
#   make test             build every chapter's snapshot and run its tests and a smoke render
#   make chapterN         build chapter N from chapter N's library and run it
#                         (ARGS="--size 200 --spp 4" to change its settings; RUNS=1 to
#                         measure each setting once, in the chapters that take --runs)
#   make diff-chapterN    what chapter N adds to chapter N-1, top down: the lesson first (the
#                         chapter's program, then lib/), then its tests (TESTS=no: the lesson)
#   make source-chapterN  the clean source of chapter N in build/source/chapterN/
#   make exercise-chapterN      chapter N's tree with its exercises blank, in
#                               build/exercise/chapterN/ (README: "Do the chapters yourself")
#   make check-exercise-chapterN  grade it, in a sandbox (STUDENT=DIR: another copy; ONLY="2.1
#                         2.3": some; OUT=DIR: the verdicts there; TRUSTED=1: no sandbox)
#   make grade-class DIR=FOLDER CHAPTER=N   grade every tree in FOLDER, each in its own
#                         sandbox: a CSV and a summary in OUT (docs/exercises.md)
#   make check-exercises  every chapter's check on the solution (all pass) and on the blank
#                         exercises (every one fails)
#   make false-alarms CHAPTER=N SEEDS=200   grade chapter N's solution under SEEDS grading
#                         seeds (SEED=s: one check's seed) and count the FAILs
#   make test-graders     every planted student mistake graded in the sandbox: each caught,
#                         named, and every correct alternative passing (run by CI)
#   make check-sources    every chapter's clean source: compiles alone, no markers left,
#                         no placeholders, the lesson never reaches into the bench
#   make sanitize         the tests under AddressSanitizer and UndefinedBehaviorSanitizer
#   make fuzz             run the libFuzzer targets (scene reader, command line), each for
#                         FUZZ_SECONDS
#   make bench            the speed benchmark (a benchmark, not a test)
#   make gallery          rewrite build/figures/index.html from the figures there
#   make browser-test     open that page in headless Chromium and check every image loads
#   make book             the book: build/book/, a page per chapter from docs/ with every
#                         line of its lib/ in listings (book-test: in headless Chromium)
#   make lab              the lab: build/lab/index.html, every chapter live in the browser
#                         (docs/lab.md); lab-test (in headless Chromium), lab-bench,
#                         lab-references (its references also at the figures' width)
#   make clean
#
# The lesson and the bench. lib/ is the lesson: what the chapters teach. bench/ measures
# and shows it (scene files, images, figures, references, errors, threads, the command
# line); it is in no chapter's source. The first line of every file says which chapter
# introduces it, as "/* NAME (chapter N): ..." (bench files: from which chapter on they
# are built); code that a later chapter adds to an existing file sits in
# "#if CHAPTER >= N". Chapter N's library is every lesson and bench file of chapters
# 1..N compiled with -DCHAPTER=N into build/chapterN/, and chapter N's program links only
# that, so the compiler enforces what a chapter may use. References (bench/measure.h) are
# rendered by build/reference, built from the last chapter's library, and re-rendered
# whenever that program is rebuilt.
#
# CC, CFLAGS and LDFLAGS are honoured; the flags the project requires are added to them.

CC      ?= cc
CFLAGS  ?= -O2 -g
LDFLAGS ?=
BUILD   ?= build
FIGURES ?= $(BUILD)/figures
ARGS    ?=
RUNS    ?=
QUICK   ?=
TESTS   ?= yes
FUZZ_SECONDS ?= 60

ifneq ($(QUICK),)
QUICK_ARGS := --quick
endif

# stb's headers are third-party: include them as system headers so -Werror judges only ours.
# Evaluated when used (=, not :=), so after .ci/install-deps has run on a fresh machine.
# Every estimator takes the arguments the Estimator type gives it, whether it uses them
# or not (Whitted draws no random numbers): unused parameters are not warned about.
PKG_CFLAGS  = $(patsubst -I%,-isystem %,$(shell pkg-config --cflags stb cmocka 2>/dev/null))
REQUIRED   := -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wpedantic -Werror \
              -Wno-unused-parameter -pthread
ALL_CFLAGS  = $(REQUIRED) -Ilib -Ibench $(PKG_CFLAGS) $(CFLAGS) -MMD -MP
LIBS        = $(shell pkg-config --libs stb 2>/dev/null) -lm -pthread
TEST_LIBS   = $(shell pkg-config --libs cmocka 2>/dev/null) $(LIBS)
DEPS_OK     := $(BUILD)/.deps-ok

# ---- which chapter introduces each file -------------------------------------------------
LESSON   := $(wildcard lib/*.c lib/*.h chapters/*.c tests/*.c tests/*.h)
BENCH    := $(wildcard bench/*.c bench/*.h bench/tests/*.c bench/tests/*.h bench/fuzz/*.c \
                      bench/exercise/*.c bench/exercise/*.h bench/lab/*.c bench/lab/*.h)
SOURCES  := $(LESSON) $(BENCH)
TAGS     := $(shell awk 'FNR == 1 && match($$0, /^\/\* [^ ]+ \((bench, )?chapter [0-9]+\)/) { \
                t = substr($$0, RSTART, RLENGTH); sub(/.*chapter /, "", t); gsub(/[^0-9]/, "", t); \
                print FILENAME "=" t }' $(SOURCES))
chapter_of = $(patsubst $(1)=%,%,$(filter $(1)=%,$(TAGS)))
UNTAGGED := $(filter-out $(foreach t,$(TAGS),$(firstword $(subst =, ,$(t)))),$(SOURCES))
ifneq ($(UNTAGGED),)
$(error these files do not say which chapter introduces them on their first line: $(UNTAGGED))
endif
# The files of chapters 1..N among $(2).
upto = $(foreach f,$(2),$(if $(filter $(call chapter_of,$(f)),$(wordlist 1,$(1),1 2 3 4 5 6 7 8 9 10)),$(f)))

PROGRAMS := $(wildcard chapters/ch[0-9][0-9]_*.c)
CHAPTERS := $(foreach p,$(PROGRAMS),$(call chapter_of,$(p)))
FINAL    := $(lastword $(CHAPTERS))
# ch01_ .. ch09_, ch10_: the chapter's number in two digits.
two_digits = $(if $(filter 1 2 3 4 5 6 7 8 9,$(1)),0$(1),$(1))
program_of = $(patsubst chapters/%.c,$(BUILD)/%,$(filter chapters/ch$(call two_digits,$(1))_%,$(PROGRAMS)))

LIB_SOURCES   := $(wildcard lib/*.c)
BENCH_MAINS   := bench/reference.c bench/gallery_main.c bench/bench.c
BENCH_SOURCES := $(filter-out $(BENCH_MAINS),$(wildcard bench/*.c))
TEST_SOURCES  := $(wildcard tests/test_*.c bench/tests/test_*.c)
REFERENCE_BIN := $(BUILD)/reference
GALLERY       := $(BUILD)/gallery

.PHONY: all test test-graders check-sources figures sanitize fuzz bench clean deps gallery check-exercises grade-class false-alarms \
        exercise-solutions
.DEFAULT_GOAL := all
.SECONDARY:

deps: $(DEPS_OK)
$(DEPS_OK):
	@sh .ci/install-deps
	@mkdir -p $(@D) && touch $@

# ---- one library, its program and its tests per chapter ---------------------------------
# The order diff-chapterN shows the lesson in, top down: the chapter's program, then its
# lib/ files, the new ones first, then the lines it changes in earlier ones; each group as
# chapter 1 reads, from what the program calls to what that rests on (the estimator,
# Whitted's, and the optics it uses; one sample and the loop over the image; the scene; the
# camera, the materials and the shapes; chapter 2's tree; rays and the offsets that keep
# them off their surfaces; vectors), then by name, a header before its source.
READING_ORDER := whitted mirror snell schlick render scene camera material sphere triangle bvh ray vec

# $(1): the chapter. Tests of chapter K are built in chapter K and in the final chapter,
# but for the grader's and the exercises' tests (ONCE_TESTS): they grade trees they build
# from each chapter's clean source, so the library they are linked with changes nothing,
# and they run once, in the final chapter.
ONCE_TESTS := bench/tests/test_grader.c bench/tests/test_exercises.c
define CHAPTER_RULES
$(BUILD)/chapter$(1)/%.o: %.c | $(DEPS_OK)
	@mkdir -p $$(@D)
	$$(CC) $$(ALL_CFLAGS) -DCHAPTER=$(1) -c $$< -o $$@

$(BUILD)/chapter$(1)/libmc.a: $(patsubst %.c,$(BUILD)/chapter$(1)/%.o,$(call upto,$(1),$(LIB_SOURCES) $(BENCH_SOURCES)))
	@rm -f $$@
	$$(AR) rcs $$@ $$^

$(call program_of,$(1)): $(BUILD)/chapter$(1)/chapters/$(notdir $(call program_of,$(1))).o $(BUILD)/chapter$(1)/libmc.a
	$$(CC) $$^ $$(LDFLAGS) $$(LIBS) -o $$@

$(BUILD)/chapter$(1)/tests/%: $(BUILD)/chapter$(1)/tests/%.o $(BUILD)/chapter$(1)/libmc.a
	$$(CC) $$^ $$(LDFLAGS) $$(TEST_LIBS) -o $$@

$(BUILD)/chapter$(1)/bench/tests/%: $(BUILD)/chapter$(1)/bench/tests/%.o $(BUILD)/chapter$(1)/libmc.a
	$$(CC) $$^ $$(LDFLAGS) $$(TEST_LIBS) -o $$@

CHAPTER$(1)_TESTS := $(patsubst %.c,$(BUILD)/chapter$(1)/%,$(if $(filter $(1),$(FINAL)),$(call upto,$(1),$(TEST_SOURCES)),$(foreach t,$(filter-out $(ONCE_TESTS),$(TEST_SOURCES)),$(if $(filter $(1),$(call chapter_of,$(t))),$(t)))))
ALL_TESTS += $$(CHAPTER$(1)_TESTS)

.PHONY: chapter$(1) source-chapter$(1) diff-chapter$(1)
chapter$(1): $(call program_of,$(1)) $(REFERENCE_BIN)
	@runs=; if [ -n "$$(RUNS)" ] && $(call program_of,$(1)) --help | grep -q -- '--runs'; then \
	    runs="--runs $$(RUNS)"; fi; \
	echo $(call program_of,$(1)) --out $$(FIGURES) $$(QUICK_ARGS) $$$$runs $$(ARGS); \
	$(call program_of,$(1)) --out $$(FIGURES) $$(QUICK_ARGS) $$$$runs $$(ARGS)

source-chapter$(1): | $(DEPS_OK)
	@sh .ci/install-deps unifdef
	@rm -rf $(BUILD)/source/chapter$(1)
	@for f in $(call upto,$(1),$(filter-out chapters/ch%,$(LESSON)) $(PROGRAMS)); do \
	    mkdir -p $(BUILD)/source/chapter$(1)/$$$$(dirname $$$$f); \
	    unifdef -x2 -DCHAPTER=$(1) -o $(BUILD)/source/chapter$(1)/$$$$f $$$$f || exit 1; \
	done
	@echo "wrote $(BUILD)/source/chapter$(1)/"

diff-chapter$(1): source-chapter$(1) $(if $(filter-out 1,$(1)),source-chapter$(shell echo $$(($(1) - 1))))
	@cd $(BUILD)/source && { \
	    diff -ruN chapter$(shell echo $$(($(1) - 1)))/chapters chapter$(1)/chapters; \
	    for new in 1 0; do \
	        for name in $(READING_ORDER) $$$$(ls chapter$(1)/lib | sed 's/[.][ch]$$$$//' | sort -u); do \
	            printf 'lib/%s.h\nlib/%s.c\n' $$$$name $$$$name; \
	        done | awk '!seen[$$$$0]++' | while read -r f; do \
	            [ -e chapter$(1)/$$$$f ] || continue; \
	            [ -e chapter$(shell echo $$(($(1) - 1)))/$$$$f ] && is_new=0 || is_new=1; \
	            [ $$$$is_new = $$$$new ] && diff -uN chapter$(shell echo $$(($(1) - 1)))/$$$$f chapter$(1)/$$$$f; \
	        done; \
	    done; \
	    if [ "$$(TESTS)" != no ]; then diff -ruN chapter$(shell echo $$(($(1) - 1)))/tests chapter$(1)/tests; fi; \
	    true; } > ../diff-chapter$(1).diff && cat ../diff-chapter$(1).diff
endef
$(foreach n,$(CHAPTERS),$(eval $(call CHAPTER_RULES,$(n))))

# The final chapter's tests keep a short path, build/tests/NAME.
FINAL_TESTS := $(addprefix $(BUILD)/tests/,$(notdir $(CHAPTER$(FINAL)_TESTS)))
$(BUILD)/tests/%: $(BUILD)/chapter$(FINAL)/tests/%
	@mkdir -p $(@D)
	cp $< $@
$(BUILD)/tests/%: $(BUILD)/chapter$(FINAL)/bench/tests/%
	@mkdir -p $(@D)
	cp $< $@
CHAPTER_TESTS := $(filter-out $(CHAPTER$(FINAL)_TESTS),$(ALL_TESTS))

# ---- exercises (README.md, "Do the chapters yourself") ----------------------------------
# Chapter N's exercises are the functions its lesson marks "Exercise N.k"; their graders,
# bench/exercise/chapterN.c, are built into two programs: the judge (grade.c), from the
# solution (chapter N's library), which lists the exercises, renders the references and
# gives every verdict, and the probe (probe.c), which only computes the answers the judge
# judges, built by bench/exercise/check.sh from the student's tree
# (bench/exercise/student.mk) and, to hold it to the project's flags, from the solution.
# A chapter without bench/exercise/chapterN.c has no exercises yet.
EXERCISE_COMMON   := $(wildcard bench/exercise/grade.c bench/exercise/grading.c bench/exercise/answers.c \
                                bench/exercise/supervise.c bench/exercise/render_check.c)
PROBE_COMMON      := $(wildcard bench/exercise/probe.c bench/exercise/grading.c bench/exercise/answers.c \
                                bench/exercise/render_check.c)
EXERCISE_CHAPTERS := $(foreach n,$(CHAPTERS),$(if $(wildcard bench/exercise/chapter$(n).c),$(n)))
EXERCISE_DIR      := $(BUILD)/exercise
# STUDENT, ONLY, OUT, TRUSTED and DIR reach the recipes' shells through their environment,
# never pasted into their text, so that any path works (spaces, quotes, a leading dash).
STUDENT           ?=
SEED              ?=
ONLY              ?=
OUT               ?=
TRUSTED           ?=
DIR               ?=
export STUDENT ONLY OUT TRUSTED DIR
grader_of          = $(BUILD)/chapter$(1)/bench/exercise/grade
probe_of           = $(BUILD)/chapter$(1)/bench/exercise/probe
grader_sources     = $(call upto,$(1),$(EXERCISE_COMMON)) bench/exercise/chapter$(1).c
probe_sources      = $(call upto,$(1),$(PROBE_COMMON)) bench/exercise/chapter$(1).c
# The linker's --wrap=NAME for every __wrap_NAME chapter $(1)'s graders define: calls of NAME
# from other objects reach it, and it calls the original as __real_NAME (chapter 2's records
# the student's cosine directions in the probe and replays them in the judge's paths). The
# judge and the probe, the student's and the solution's, are linked alike.
grader_wraps       = $(shell grep -o '__wrap_[a-z][a-z_0-9]*' bench/exercise/chapter$(1).c | sort -u | sed 's/^__wrap_/-Wl,--wrap=/')
SOLUTION_GRADERS  := $(foreach n,$(EXERCISE_CHAPTERS),$(call grader_of,$(n)) $(call probe_of,$(n)))
# The judge of chapter $(1) as it was built (its checksum, recorded then, in JUDGE.sha256;
# never its time stamp), else built again; then bubblewrap, unless TRUSTED=1.
judge_verified     = if [ "$$(sha256sum < $(call grader_of,$(1)) | cut -c 1-64)" != "$$(cut -c 1-64 $(call grader_of,$(1)).sha256 2> /dev/null)" ]; then \
	    echo "$(call grader_of,$(1)) is not the judge make built (its checksum differs): building it again"; \
	    rm -f $(call grader_of,$(1)) && $(MAKE) --no-print-directory -s $(call grader_of,$(1)) || exit 2; fi; \
	[ "$${TRUSTED:-}" = 1 ] || sh .ci/install-deps bubblewrap || exit 2; set -f;
# What bench/exercise/check.sh builds the student's tree with.
grade_env          = GRADE_SEED="$${GRADE_SEED:-$(SEED)}" CACHE=$(abspath $(EXERCISE_DIR)/cache/chapter$(1)) CC="$(CC)" CFLAGS="$(CFLAGS)" LDFLAGS="$(LDFLAGS)" LIBS="$(LIBS)" PKG_CFLAGS="$(PKG_CFLAGS)" \
	BENCH_OBJECTS="$(addprefix $(CURDIR)/,$(patsubst %.c,$(BUILD)/chapter$(1)/%.o,$(call upto,$(1),$(BENCH_SOURCES))))" \
	PROBE_FILES="$(addprefix $(CURDIR)/,$(call probe_sources,$(1)))" GRADER_LDFLAGS="$(call grader_wraps,$(1))"

define EXERCISE_RULES
.PHONY: exercise-chapter$(1) check-exercise-chapter$(1)
ifneq ($(filter $(1),$(EXERCISE_CHAPTERS)),)
$(call grader_of,$(1)): $(patsubst %.c,$(BUILD)/chapter$(1)/%.o,$(call grader_sources,$(1))) $(BUILD)/chapter$(1)/libmc.a
	$$(CC) $$^ $$(LDFLAGS) $$(call grader_wraps,$(1)) $$(LIBS) -o $$@
	sha256sum < $$@ > $$@.sha256

$(call probe_of,$(1)): $(patsubst %.c,$(BUILD)/chapter$(1)/%.o,$(call probe_sources,$(1))) $(BUILD)/chapter$(1)/libmc.a
	$$(CC) $$^ $$(LDFLAGS) $$(call grader_wraps,$(1)) $$(LIBS) -o $$@

exercise-chapter$(1): source-chapter$(1) $(call grader_of,$(1))
	@sh bench/exercise/exercise.sh $(1) $(BUILD)/source/chapter$(1) $(call grader_of,$(1)) $(EXERCISE_DIR)/chapter$(1)

check-exercise-chapter$(1): $(call grader_of,$(1))
	@student=$$$${STUDENT:-$(EXERCISE_DIR)/chapter$(1)}; \
	if [ ! -d "$$$$student/lib" ]; then echo "no exercise tree in $$$$student: make exercise-chapter$(1) first (or STUDENT=DIR)"; exit 2; fi; \
	$$(call judge_verified,$(1)) \
	$$(call grade_env,$(1)) sh bench/exercise/check.sh $(1) "$$$$student" $(call grader_of,$(1)) $(EXERCISE_DIR)/references/chapter$(1) $$$${ONLY:-}
else
exercise-chapter$(1) check-exercise-chapter$(1):
	@echo "chapter $(1) has no exercises yet (bench/exercise/chapter$(1).c)"; exit 2
endif
endef
$(foreach n,$(CHAPTERS),$(eval $(call EXERCISE_RULES,$(n))))

# A teacher's command: every tree in DIR graded as check-exercise-chapter$(CHAPTER) grades
# one, each in its own sandbox, into OUT (bench/exercise/class.sh).
CHAPTER ?=
grade-class: $(if $(filter $(CHAPTER),$(EXERCISE_CHAPTERS)),$(call grader_of,$(CHAPTER)))
	@if [ -z "$$DIR" ] || [ -z "$(filter $(CHAPTER),$(EXERCISE_CHAPTERS))" ]; then \
	    echo "usage: make grade-class DIR=FOLDER-OF-TREES CHAPTER=N [OUT=FOLDER] [ONLY=IDS] (chapters with exercises: $(strip $(EXERCISE_CHAPTERS)))"; exit 2; fi; \
	sh bench/exercise/class.sh $(CHAPTER) "$$DIR" "$${OUT:-$(EXERCISE_DIR)/class/chapter$(CHAPTER)}" \
	    env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL $(MAKE) --no-print-directory -s BUILD=$(BUILD) \
	    CFLAGS="$(CFLAGS)" LDFLAGS="$(LDFLAGS)" CC="$(CC)" check-exercise-chapter$(CHAPTER)

# The solution of chapter $(CHAPTER) graded under SEEDS grading seeds (GRADE_SEED = 1 .. SEEDS,
# or FIRST_SEED on): every FAIL is a false alarm (bench/exercise/false_alarms.sh).
SEEDS ?= 200
false-alarms: $(if $(filter $(CHAPTER),$(EXERCISE_CHAPTERS)),source-chapter$(CHAPTER) $(call grader_of,$(CHAPTER)))
	@if [ -z "$(filter $(CHAPTER),$(EXERCISE_CHAPTERS))" ]; then \
	    echo "usage: make false-alarms CHAPTER=N [SEEDS=200] (chapters with exercises: $(strip $(EXERCISE_CHAPTERS)))"; exit 2; fi; \
	tree=$(EXERCISE_DIR)/false-alarms/chapter$(CHAPTER); rm -rf $$tree && mkdir -p $(EXERCISE_DIR)/false-alarms && \
	cp -R $(BUILD)/source/chapter$(CHAPTER) $$tree && \
	MAKE="$(MAKE)" sh bench/exercise/false_alarms.sh $(CHAPTER) $(SEEDS) $$tree

# The solution's checks (the clean source: every exercise passes), their verdicts and
# pictures copied into $(FIGURES) as chNN_exercise* for the gallery; then (CI) the blank
# exercises of every chapter, each of which must fail.
exercise-solutions: $(foreach n,$(EXERCISE_CHAPTERS),source-chapter$(n))
	@mkdir -p $(FIGURES); for n in $(EXERCISE_CHAPTERS); do \
	    tree=$(EXERCISE_DIR)/solution/chapter$$n; prefix=$(FIGURES)/$$(printf 'ch%02d' $$n)_; \
	    rm -rf $$tree && mkdir -p $(EXERCISE_DIR)/solution && cp -R $(BUILD)/source/chapter$$n $$tree && \
	    $(MAKE) --no-print-directory check-exercise-chapter$$n STUDENT=$$tree || exit 1; \
	    rm -f $${prefix}exercise*; \
	    sed "s|$$tree/check/||g" $$tree/check/verdicts.txt > $${prefix}exercises.txt; \
	    for picture in $$tree/check/exercise-*.png; do \
	        [ -e "$$picture" ] && cp "$$picture" "$$prefix$$(basename $$picture)"; \
	    done; \
	done; true

check-exercises: exercise-solutions
	@for n in $(EXERCISE_CHAPTERS); do \
	    $(MAKE) --no-print-directory exercise-chapter$$n > /dev/null || exit 1; \
	    $(MAKE) --no-print-directory check-exercise-chapter$$n > $(EXERCISE_DIR)/blank-chapter$$n.txt; \
	    status=$$?; cat $(EXERCISE_DIR)/blank-chapter$$n.txt; \
	    if [ $$status -eq 0 ]; then echo "chapter $$n's blank exercises: the check passes"; exit 1; fi; \
	    total=$$($(call grader_of,$$n) --list | wc -l); \
	    failed=$$(grep -c '^exercise .*: FAIL: ' $(EXERCISE_DIR)/blank-chapter$$n.txt); \
	    if [ "$$failed" -ne "$$total" ]; then \
	        echo "chapter $$n: $$failed of $$total blank exercises fail"; exit 1; fi; \
	done
	@echo "check-exercises: every chapter's solution passes and every blank exercise fails"

# The reference renderer: the final library's best estimator. It links the physics and
# what measures it, not the files that draw figures, plots and tables nor the chapter
# programs' chores (their command line, the reference cache that runs this program), so
# that editing those does not make every reference render again (the cache key holds this
# program's bytes and time).
PRESENTATION    := $(wildcard bench/figure.c bench/plot.c bench/table.c bench/font.c bench/gallery.c \
                              bench/experiment.c bench/reference_cache.c bench/directory.c bench/cli.c)
REFERENCE_OBJS  := $(patsubst %.c,$(BUILD)/chapter$(FINAL)/%.o,$(filter-out $(PRESENTATION),$(call upto,$(FINAL),$(LIB_SOURCES) $(BENCH_SOURCES))))
$(REFERENCE_BIN): $(BUILD)/chapter$(FINAL)/bench/reference.o $(REFERENCE_OBJS)
	$(CC) $^ $(LDFLAGS) $(LIBS) -o $@

CHAPTER_BINS := $(foreach n,$(CHAPTERS),$(call program_of,$(n)))
all: $(CHAPTER_BINS) $(REFERENCE_BIN) $(GALLERY) $(CHAPTER_TESTS) $(FINAL_TESTS) $(SOLUTION_GRADERS)

# Every source file formatted as .clang-format says (Debian's clang-format, installed on
# demand). Every chapter's clean source: no chapter markers left; its lesson (lib/) compiles
# with nothing but its own headers (it never includes the bench, nor a later chapter),
# its program and tests with the bench built for that chapter; its lesson adds no name
# that the chapter does not use, no socket for a later one (bench/unused.sh, with
# Universal Ctags); no placeholder statement "(void) x;" in its lesson; chapter 1's
# lesson and program at most 1,100 lines; at most 40 lines of earlier lib/ files changed
# by any later chapter (each hunk of the diff counts its longer side: a line replaced is
# one line changed, and a block that a later chapter replaces counts as its longer
# version); at most 10 chapter markers in all of lib/*.c; no comment cites a document
# outside the repository or an issue; each lesson file opens with at most 12 comment
# lines.
check-sources: $(foreach n,$(CHAPTERS),source-chapter$(n))
	@sh .ci/install-deps clang-format universal-ctags unifdef
	@unformatted=$$(for f in $(SOURCES); do clang-format --dry-run --Werror $$f >/dev/null 2>&1 || echo $$f; done); \
	if [ -n "$$unformatted" ]; then \
	    echo "not formatted as .clang-format says (clang-format -i FILE):" $$unformatted; exit 1; fi
	@for n in $(CHAPTERS); do \
	    tree=$(BUILD)/source/chapter$$n; \
	    if grep -rln '^#if.*CHAPTER' $$tree; then echo "chapter markers left in $$tree"; exit 1; fi; \
	    if grep -rnE '^\s*\(void\)' $$tree/lib; then echo "a placeholder in $$tree/lib"; exit 1; fi; \
	    for f in $$tree/lib/*.c; do \
	        $(CC) $(REQUIRED) -I$$tree/lib -fsyntax-only $$f || { echo "$$f: the lesson alone does not compile"; exit 1; }; \
	    done; \
	    for f in $$tree/chapters/ch$$(printf %02d $$n)_*.c $$(find $$tree/tests -name '*.c'); do \
	        $(CC) $(REQUIRED) -DCHAPTER=$$n -I$$tree/lib -Ibench $(PKG_CFLAGS) -fsyntax-only $$f || exit 1; \
	    done; \
	    earlier=$(BUILD)/source/chapter$$((n - 1)); [ -d $$earlier ] || earlier=; \
	    sh bench/unused.sh $$tree $$n $$earlier || { echo "chapter $$n's lesson declares what it does not use"; exit 1; }; \
	done; \
	lines=$$(cat $(BUILD)/source/chapter1/lib/*.[ch] $(BUILD)/source/chapter1/chapters/ch01_*.c | wc -l); \
	if [ $$lines -gt 1100 ]; then echo "chapter 1's lesson and program: $$lines lines (at most 1100)"; exit 1; fi; \
	for n in $(wordlist 2,$(words $(CHAPTERS)),$(CHAPTERS)); do \
	    old=$(BUILD)/source/chapter$$((n - 1))/lib; changed=0; \
	    for f in $$old/*; do \
	        changed=$$((changed + $$(diff $$f $(BUILD)/source/chapter$$n/lib/$${f##*/} | \
	            awk '/^[0-9]/ { n += (r > a ? r : a); r = a = 0; next } /^</ { r++ } /^>/ { a++ } \
	                 END { print n + (r > a ? r : a) }'))); \
	    done; \
	    if [ $$changed -gt 40 ]; then echo "chapter $$n changes $$changed lines of earlier lib/ files (at most 40)"; exit 1; fi; \
	done; \
	markers=$$(grep -c '^#if.*CHAPTER' lib/*.c | awk -F: '{ s += $$2 } END { print s }'); \
	if [ $$markers -gt 10 ]; then echo "$$markers chapter markers in lib/*.c (at most 10)"; exit 1; fi; \
	if grep -rnE '\bSPEC\b|[Ii]ssue [0-9]|\.\./shared' lib chapters tests bench scenes docs .ci; then \
	    echo "comments cite documents outside the repository or issues"; exit 1; fi; \
	for f in lib/*.c lib/*.h; do \
	    n=$$(awk 'NR == 1 && !/^\/\*/ { print 0; exit } /\*\// { print NR; exit }' $$f); \
	    if [ "$$n" -gt 12 ]; then echo "$$f: its first comment has $$n lines (at most 12)"; exit 1; fi; \
	done; \
	echo "the clean source of chapters $(CHAPTERS) compiles; chapter 1: $$lines lines; $$markers chapter markers in lib/*.c"

# Each test program is run from the top directory (some read scenes/ and run the chapter
# programs): every chapter's own tests in its own snapshot, and all of them in the final
# one, as many at a time as there are cores (each writes where no other does), each
# under a time limit of TEST_TIMEOUT seconds, past which it is stopped with every process
# it started and fails (bench/run_tests.sh). Their output is then printed in that order,
# and the last line counts the programs that passed and failed.
# The longest start first, so that the cores stay busy to the end. The planted mistakes
# (test_exercises: about a hundred trees graded in the sandbox, three to four minutes of
# processor time) are make test-graders, which CI runs beside make test.
TEST_LOGS := $(BUILD)/test-logs
TEST_TIMEOUT ?= 300
GRADER_TESTS := $(BUILD)/tests/test_exercises
LONGEST_TESTS := $(addprefix $(BUILD)/tests/,test_grader test_interrupt test_chapters)
test: all check-sources
	@CHAPTER_DIR=$(BUILD) CFLAGS="$(CFLAGS)" LDFLAGS="$(LDFLAGS)" \
	    sh bench/run_tests.sh $(TEST_LOGS) $(TEST_TIMEOUT) $(LONGEST_TESTS) \
	    $(CHAPTER_TESTS) $(filter-out $(LONGEST_TESTS) $(GRADER_TESTS),$(FINAL_TESTS))
test-graders: all $(foreach n,$(CHAPTERS),source-chapter$(n))
	@CHAPTER_DIR=$(BUILD) CFLAGS="$(CFLAGS)" LDFLAGS="$(LDFLAGS)" \
	    sh bench/run_tests.sh $(TEST_LOGS)-graders $(TEST_TIMEOUT) $(GRADER_TESTS)

# The gallery (bench/gallery_main.c): $(FIGURES)/index.html, one page with every chapter's
# figures, tables, plots and diff. `make figures` records its run in $(FIGURES)/run.txt
# (start, end, seconds, threads, QUICK), writes each chapter's diff and then the page.
# It builds every program first, nproc compilers at a time, and then runs the chapters
# one after another, so that no render shares the cores it measures its time on;
# `make gallery` rewrites the page from the files there, without rendering;
# `make browser-test` opens it in headless Chromium. DIFFS: the folder with the
# diff-chapterN.diff files to show.
DIFFS   ?= $(BUILD)
# The lab's page (make lab) as the gallery links to it, relative to the figures folder.
LAB_LINK = $(shell realpath -m --relative-to=$(FIGURES) $(BUILD)/lab/index.html)
# The book (make book) as the gallery links to it, relative to the figures folder.
BOOK_LINK = $(shell realpath -m --relative-to=$(FIGURES) $(BUILD)/book)
.PHONY: gallery browser-test
$(GALLERY): $(BUILD)/chapter$(FINAL)/bench/gallery_main.o $(BUILD)/chapter$(FINAL)/libmc.a
	$(CC) $^ $(LDFLAGS) $(LIBS) -o $@
gallery: $(GALLERY)
	$(GALLERY) --out $(FIGURES) --diffs $(DIFFS) --lab $(LAB_LINK) --book $(BOOK_LINK)
figures:
	@start=$$(date +%s); started=$$(date '+%Y-%m-%d %H:%M:%S %z'); \
	$(MAKE) --no-print-directory -j$$(nproc) $(CHAPTER_BINS) $(REFERENCE_BIN) $(GALLERY) || exit 1; \
	mkdir -p $(FIGURES); for n in $(CHAPTERS); do $(MAKE) --no-print-directory chapter$$n || exit 1; done; \
	seconds=$$(($$(date +%s) - start)); \
	printf 'started=%s\nfinished=%s\nseconds=%s\nthreads=%s\nquick=%s\n' "$$started" \
	    "$$(date '+%Y-%m-%d %H:%M:%S %z')" "$$seconds" "$$(nproc)" \
	    "$(if $(QUICK),1,0)" > $(FIGURES)/run.txt.tmp && mv $(FIGURES)/run.txt.tmp $(FIGURES)/run.txt; \
	echo "make figures: $$seconds s"
	@$(MAKE) --no-print-directory exercise-solutions
	@for n in $(CHAPTERS); do $(MAKE) --no-print-directory diff-chapter$$n > /dev/null || exit 1; done
	$(GALLERY) --out $(FIGURES) --diffs $(DIFFS) --lab $(LAB_LINK) --book $(BOOK_LINK)
browser-test: $(GALLERY)
	sh bench/browser_gallery.sh $(FIGURES)

# ---- the book ---------------------------------------------------------------------------
# build/book/: chapterN.html from docs/chapterN.md for every chapter, the other docs/ pages,
# and index.html, made by Debian's pandoc (installed on demand) with the filter
# bench/book/book.lua: each listing directive is filled from chapter N's clean source
# (make source-chapterN) when the page is built, and one that finds nothing fails; the
# equations are MathML; the figures and tables are the gallery's ($(FIGURES)) when they are
# there. Then each chapter's listings must show every line the chapter adds to lib/
# (bench/book/coverage.sh prints what they miss). book-test opens every page in headless
# Chromium (bench/book/browser_book.js).
BOOK := $(BUILD)/book
.PHONY: book book-test
book: $(foreach n,$(CHAPTERS),source-chapter$(n))
	@sh .ci/install-deps pandoc
	sh bench/book/build.sh $(BUILD) $(FIGURES) "$(CHAPTERS)"
book-test: book
	@sh .ci/install-deps chromium nodejs
	@mkdir -p $(BUILD)/book-test && printf '```{.listing file="lib/render.c" function="no_such_function"}\n```\n' > $(BUILD)/book-test/missing.md
	@if BOOK_CHAPTER=1 BOOK_SOURCE=$(BUILD)/source/chapter1 pandoc --lua-filter bench/book/book.lua \
	    $(BUILD)/book-test/missing.md -o /dev/null 2>$(BUILD)/book-test/missing.log; then \
	    echo "a directive naming a missing function did not fail the build"; exit 1; fi; \
	grep -q "no function no_such_function in lib/render.c" $(BUILD)/book-test/missing.log || \
	    { cat $(BUILD)/book-test/missing.log; echo "its message does not name what is missing"; exit 1; }
	node bench/book/browser_book.js $(BOOK) $(BUILD)/book-test $(FIGURES)

# ---- the lab (docs/lab.md) ---------------------------------------------------------------
# build/lab/: the final chapter's lesson (lib/, as it is) and the lab's C (bench/lab/)
# compiled to WebAssembly by Debian's emscripten (installed on demand) into one script
# with the module inside it (SINGLE_FILE), which the page runs in web workers started
# from Blobs, and the page itself: it opens from disk. The lab's programs are linked with
# the recorder's wrappers (bench/lab/record.h: --wrap for every __wrap_NAME it defines);
# the chapter programs are not. lab-native is the same C built natively, for the tests
# and the benchmark; lab-reference (beside build/reference, whose cache it reads) writes
# the references the page can load. NODE_PATH: emscripten's tools need Debian's node
# modules also where `node` is not Debian's. Threads in WebAssembly would need a page
# served with cross-origin isolation: the module has none (-pthread is left out), the
# page's workers are its threads. -msimd128: the compiler may use WebAssembly's 128-bit
# vectors (browsers since 2021), as GCC uses SSE2 natively; -flto: it may inline across
# files, the wrapped calls excepted (the linker keeps them calls; make lab-test checks the
# records). docs/lab.md: what each buys.
LAB           := $(BUILD)/lab
LAB_EMCC       = NODE_PATH=/usr/share/nodejs emcc
LAB_EMCC_FLAGS = $(filter-out -pthread,$(REQUIRED)) -DCHAPTER=$(FINAL) -Ilib -Ibench $(PKG_CFLAGS) -O3 -msimd128 -flto -MMD -MP
LAB_LIB       := $(call upto,$(FINAL),$(LIB_SOURCES))
LAB_BENCH     := bench/scene_file.c bench/material_names.c bench/renderer.c bench/sample_order.c \
                 bench/image.c bench/atomic_file.c bench/stats.c bench/ppm.c
LAB_C         := bench/lab/json.c bench/lab/record.c bench/lab/lab.c
LAB_PAGE      := $(addprefix $(LAB)/,index.html lab.js pool.js plot.js inspector.js)
LAB_WRAPS      = $(shell grep -o '__wrap_[a-z_]*' bench/lab/record.c | sort -u | sed 's/__wrap_/--wrap=/' | paste -sd, -)
PAREN         := (
LAB_EXPORTS    = $(shell grep -o '^[A-Za-z].*[ *]lab_[a-z_]*$(PAREN)' bench/lab/lab.h | grep -o 'lab_[a-z_]*' | sed 's/^/_/' | paste -sd, -),_malloc,_free
LAB_OBJS      := $(patsubst %.c,$(LAB)/wasm/%.o,$(LAB_LIB) $(LAB_BENCH) $(LAB_C))
LAB_NATIVE    := $(LAB)/lab-native
LAB_REFERENCE := $(BUILD)/lab-reference

.PHONY: lab lab-test lab-bench lab-references
$(LAB)/.emscripten: | $(DEPS_OK)
	@sh .ci/install-deps emscripten nodejs
	@mkdir -p $(@D) && touch $@

$(LAB)/wasm/%.o: %.c | $(LAB)/.emscripten
	@mkdir -p $(@D)
	$(LAB_EMCC) $(LAB_EMCC_FLAGS) -c $< -o $@

# stb_image_write's code, which Debian ships as a library, compiled from its header here.
$(LAB)/wasm/bench/image.o: LAB_EMCC_FLAGS += -DSTB_IMAGE_WRITE_IMPLEMENTATION

$(LAB)/wasm/lab_module.js: $(LAB_OBJS) bench/lab/record.c bench/lab/lab.h
	$(LAB_EMCC) -O3 -msimd128 -flto $(LAB_OBJS) -Wl,$(LAB_WRAPS) -sEXPORTED_FUNCTIONS=$(LAB_EXPORTS) \
	    -sEXPORTED_RUNTIME_METHODS=UTF8ToString -sALLOW_MEMORY_GROWTH=1 -sSINGLE_FILE=1 \
	    -sENVIRONMENT=web,worker -sMODULARIZE=1 -sEXPORT_NAME=createLabModule -o $@

$(LAB)/embed: bench/lab/embed.c | $(DEPS_OK)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $< $(LDFLAGS) -o $@

$(LAB)/lab_worker.js: $(LAB)/embed $(LAB)/wasm/lab_module.js bench/lab/worker.js
	$(LAB)/embed LAB_WORKER $(LAB)/wasm/lab_module.js bench/lab/worker.js > $@.tmp && mv $@.tmp $@

# The scenes, and each chapter's program and default scene as its source declares them.
$(LAB)/lab_data.js: $(LAB)/embed $(wildcard scenes/*.scene) $(PROGRAMS) bench/lab/lab.c
	{ $(LAB)/embed LAB_SCENES $(wildcard scenes/*.scene) && \
	  last=$$(sed -n 's/^#define LAB_CHAPTERS \([0-9]*\)/\1/p' bench/lab/lab.c) && \
	  speed=$$(sed -n 's/^#define LAB_SPEED_CHAPTER \([0-9]*\).*/\1/p' bench/lab/lab.c) && \
	  printf 'var LAB_CHAPTERS = [\n' && \
	  for p in $(PROGRAMS); do n=$$(basename $$p | sed 's/^ch0*\([0-9]*\)_.*/\1/'); \
	      [ $$n -le $$last ] && [ $$n -ne $$speed ] || continue; \
	      scene=$$(sed -n 's/.*\.scene = "scenes\/\([^"]*\)".*/\1/p' $$p | head -n 1); \
	      printf '{"number": %s, "program": "%s", "scene": "%s"},\n' $$n $$(basename $$p .c) $$scene; \
	  done && printf '];\n'; } > $@.tmp && mv $@.tmp $@

$(LAB)/%: bench/lab/%
	@mkdir -p $(@D)
	cp $< $@

lab: $(LAB_PAGE) $(LAB)/lab_data.js $(LAB)/lab_worker.js $(LAB_NATIVE) $(LAB)/references/settings.txt
	@{ printf 'var LAB_REFERENCES = ['; for f in $(LAB)/references/*-*.js; do \
	      [ -e "$$f" ] && printf '"%s",' "$$(basename $$f)"; done; printf '];\n'; } \
	    > $(LAB)/references/index.js
	@echo "the lab: $(LAB)/index.html (open it from disk); $$(ls $(LAB)/references | grep -c -- '-.*\.js$$') references"

$(LAB_REFERENCE): $(BUILD)/chapter$(FINAL)/bench/lab/lab_reference.o $(BUILD)/chapter$(FINAL)/libmc.a
	$(CC) $^ $(LDFLAGS) $(LIBS) -o $@

# References for the page (bench/lab/lab_reference.c), one for each comparison the page
# offers (lab.js's PRESETS) and each chapter's own render (docs/lab.md): the room at depth
# 8 (chapters 2-4 and 1 against 30 shadow rays, Schlick's; Schlick against exact Fresnel,
# the exact one) and 64 (6-8; with the exact one, chapter 10 and uniform against adaptive), with the samples the chapter programs give them, so that
# what `make figures` cached is found (a reference not cached is rendered), and chapter 5's
# scene at depth 8 as the scene has it (chapter 5's figure sets a roughness: not shared). `make lab` gets them at the page's width, LAB_WIDTH (rendered once: the
# reference cache keeps them); lab-references also at the widths LAB_SIZES (default 256
# and the figures' width, 800, or 200 with QUICK=1; minutes at 800 pixels).
LAB_WIDTH := 256
LAB_SIZES ?= $(LAB_WIDTH) $(if $(QUICK),200,800)
LAB_REFERENCE_SETTINGS := "--depth 8 --reference-spp 64" "--depth 8 --fresnel exact --reference-spp 128" \
                          "--depth 64 --reference-spp 128" "--depth 64 --fresnel exact --reference-spp 128" \
                          "--scene scenes/oren_nayar.scene --depth 8 --reference-spp 128"
# The settings rendered, as the stamp of what is there (the cache finds any rendered before).
$(LAB)/references/settings.txt: $(LAB_REFERENCE) $(REFERENCE_BIN) $(wildcard scenes/*.scene) Makefile
	@mkdir -p $(@D)
	@for settings in $(LAB_REFERENCE_SETTINGS); do \
	    $(LAB_REFERENCE) --quiet --size $(LAB_WIDTH) $$settings --out $(@D) || exit 1; \
	done
	@printf '%s\n' $(LAB_REFERENCE_SETTINGS) > $@.tmp && mv $@.tmp $@
lab-references: $(LAB_REFERENCE) $(REFERENCE_BIN)
	@for size in $(LAB_SIZES); do for settings in $(LAB_REFERENCE_SETTINGS); do \
	    $(LAB_REFERENCE) --quiet --size $$size $$settings --out $(LAB)/references || exit 1; \
	done; done
	@$(MAKE) --no-print-directory lab

# The page in headless Chromium against the native programs (bench/lab/browser_lab.js).
lab-test: lab $(CHAPTER_BINS) $(REFERENCE_BIN) $(LAB_REFERENCE)
	@sh .ci/install-deps chromium nodejs
	node bench/lab/browser_lab.js $(LAB) $(BUILD) $(BUILD)/lab-test

$(LAB_NATIVE): $(patsubst %.c,$(BUILD)/chapter$(FINAL)/%.o,$(LAB_C) bench/lab/lab_native.c) $(BUILD)/chapter$(FINAL)/libmc.a
	@mkdir -p $(@D)
	$(CC) $^ $(LDFLAGS) -Wl,$(LAB_WRAPS) $(LIBS) -o $@

# The same without the wrappers (each __real_NAME is NAME, so no call is noted), for the
# benchmark: what the recorder costs natively when it is linked in but not recording.
$(LAB_NATIVE)-unwrapped: $(patsubst %.c,$(BUILD)/chapter$(FINAL)/%.o,$(LAB_C) bench/lab/lab_native.c) $(BUILD)/chapter$(FINAL)/libmc.a
	$(CC) $^ $(LDFLAGS) -Wl,$(subst --wrap=,--defsym=__real_,$(shell echo '$(LAB_WRAPS)' | sed 's/--wrap=\([a-z_]*\)/--wrap=\1=\1/g')) $(LIBS) -o $@

# The lab's benchmark (bench/lab/lab_bench.js): WebAssembly's speed per core against the
# native build's, the first image's time, the main thread's longest tasks.
lab-bench: lab $(LAB_NATIVE)-unwrapped
	@sh .ci/install-deps chromium nodejs
	node bench/lab/lab_bench.js $(LAB) $(BUILD)/lab-bench

# The sanitizers make the programs two to three times slower: the time limit grows alike
# (test_exercises grades every planted mistake in the sandbox, about 300 s so built).
SANITIZE_TEST_TIMEOUT ?= 900
sanitize:
	$(MAKE) --no-print-directory BUILD=$(BUILD)/sanitize TEST_TIMEOUT=$(SANITIZE_TEST_TIMEOUT) \
	    CFLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
	    LDFLAGS="-fsanitize=address,undefined" test test-graders

# The libFuzzer targets, under AddressSanitizer and UndefinedBehaviorSanitizer, each for
# FUZZ_SECONDS: fuzz_scene_file gives any bytes to the scene reader; fuzz_argv gives any
# command line to cli_parse, compiled with its exit() renamed so that it jumps back to
# the target instead of ending the process (bench/fuzz/fuzz_argv.c).
FUZZ_DIR       := $(BUILD)/fuzz
FUZZ_SANITIZE  := address,undefined -fno-sanitize-recover=all
FUZZ_FLAGS     := $(REQUIRED) -DCHAPTER=$(FINAL) -Ilib -Ibench -g -O1
FUZZ_SCENE_SRC := bench/scene_file.c bench/material_names.c $(call upto,$(FINAL),$(LIB_SOURCES))

$(FUZZ_DIR)/fuzz_scene_file: bench/fuzz/fuzz_scene_file.c $(FUZZ_SCENE_SRC) | $(DEPS_OK)
	@sh .ci/install-deps clang
	@mkdir -p $(@D)
	clang $(FUZZ_FLAGS) -fsanitize=fuzzer,$(FUZZ_SANITIZE) $^ -lm -o $@

$(FUZZ_DIR)/cli.o: bench/cli.c bench/cli.h | $(DEPS_OK)
	@sh .ci/install-deps clang
	@mkdir -p $(@D)
	clang $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link,$(FUZZ_SANITIZE) -Dexit=fuzz_argv_exit -c $< -o $@

$(FUZZ_DIR)/fuzz_argv: bench/fuzz/fuzz_argv.c $(FUZZ_DIR)/cli.o
	clang $(FUZZ_FLAGS) -fsanitize=fuzzer,$(FUZZ_SANITIZE) $^ -lm -o $@

# New inputs go to the first directory, under $(FUZZ_DIR); the seeds stay in bench/fuzz/.
FUZZ_BINS := $(FUZZ_DIR)/fuzz_scene_file $(FUZZ_DIR)/fuzz_argv
fuzz: $(FUZZ_BINS)
	@mkdir -p $(FUZZ_DIR)/corpus/scene_file $(FUZZ_DIR)/corpus/argv
	$(FUZZ_DIR)/fuzz_scene_file -max_total_time=$(FUZZ_SECONDS) -timeout=5 -max_len=4096 \
	    $(FUZZ_DIR)/corpus/scene_file bench/fuzz/corpus/scene_file scenes
	$(FUZZ_DIR)/fuzz_argv -max_total_time=$(FUZZ_SECONDS) -timeout=5 -max_len=1024 \
	    -close_fd_mask=3 $(FUZZ_DIR)/corpus/argv bench/fuzz/corpus/argv

# The benchmark: speed, not correctness (BENCH_ARGS="--size 400" to change it).
BENCH_ARGS ?=
$(BUILD)/bench: $(BUILD)/chapter$(FINAL)/bench/bench.o $(BUILD)/chapter$(FINAL)/libmc.a
	$(CC) $^ $(LDFLAGS) $(LIBS) -o $@
bench: $(BUILD)/bench $(REFERENCE_BIN)
	$(BUILD)/bench $(BENCH_ARGS)

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD) -name '*.d' -not -path '$(BUILD)/sanitize/*' -not -path '$(BUILD)/exercise/*' 2>/dev/null)
