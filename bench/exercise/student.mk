# student.mk: builds the private copy of a student's tree into its check/build/ folder; run
# by check.sh, in the sandbox, from the copy's top folder, as
#     make -r -f REPO/student.mk REPO=... CHAPTER=N PROBE_FILES=... BENCH_OBJECTS=...
# where REPO is the grader's read-only folder (the bench's headers, the probe's sources
# PROBE_FILES and the solution's bench objects BENCH_OBJECTS, both relative to REPO). The
# student's lib/ and the probe (bench/exercise/probe.c, the chapter's graders and what
# they share) are compiled here, the student's lib/ first on the include path, so the
# graders see the student's headers (an inline exercise too); the rest of the bench is
# linked as the solution built it (the student writes function bodies, not the headers'
# types, and no bench file calls an exercise's inline function). Nothing of the student's
# tree but lib/*.c and lib/*.h is read; the .d files included are this build's own.
# Warnings are shown but do not stop the build: a half-written exercise is still graded.
# GRADER_LDFLAGS: the linker's wraps the chapter's graders need (the Makefile's grader_wraps).
OBJ        := check/build
STUDENT_FLAGS = -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wpedantic \
                -Wno-unused-parameter -Wno-unused-function -pthread $(PKG_CFLAGS) $(CFLAGS)
LIB_OBJS    := $(patsubst %.c,$(OBJ)/%.o,$(wildcard lib/*.c))
PROBE_OBJS  := $(patsubst %.c,$(OBJ)/%.o,$(PROBE_FILES))

$(OBJ)/probe: $(LIB_OBJS) $(PROBE_OBJS) $(addprefix $(REPO)/,$(BENCH_OBJECTS))
	$(CC) $^ $(LDFLAGS) $(GRADER_LDFLAGS) $(LIBS) -o $@

$(OBJ)/lib/%.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(STUDENT_FLAGS) -DCHAPTER=$(CHAPTER) -Ilib -I$(REPO)/bench -MMD -MP -c $< -o $@

$(OBJ)/bench/%.o: $(REPO)/bench/%.c
	@mkdir -p $(@D)
	$(CC) $(STUDENT_FLAGS) -DCHAPTER=$(CHAPTER) -Ilib -I$(REPO)/bench -MMD -MP -c $< -o $@

-include $(LIB_OBJS:.o=.d) $(PROBE_OBJS:.o=.d)
