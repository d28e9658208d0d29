# student.mk: builds a student's tree into its check/build/ folder; run by check.sh as
#     make -C STUDENT -f REPO/bench/exercise/student.mk REPO=... CHAPTER=N PROBE_FILES=...
#          BENCH_OBJECTS=...
# The student's lib/ and the probe (PROBE_FILES: bench/exercise/probe.c, the chapter's
# graders and what they share) are compiled here, the student's lib/ first on the include
# path, so the graders see the student's headers (an inline exercise too); the rest of the bench is linked as the solution built
# it (BENCH_OBJECTS, the chapter's bench objects: the student writes function bodies, not
# the headers' types, and no bench file calls an exercise's inline function). Objects are
# rebuilt when their source or a header they include changes (-MMD), so a second check
# compiles only what changed. Warnings are shown but do not stop the build: a
# half-written exercise is still graded.
OBJ        := check/build
STUDENT_FLAGS = -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wpedantic \
                -Wno-unused-parameter -Wno-unused-function -pthread $(PKG_CFLAGS) $(CFLAGS)
LIB_OBJS    := $(patsubst %.c,$(OBJ)/%.o,$(wildcard lib/*.c))
PROBE_OBJS  := $(patsubst $(REPO)/%.c,$(OBJ)/%.o,$(PROBE_FILES))

$(OBJ)/probe: $(LIB_OBJS) $(PROBE_OBJS) $(BENCH_OBJECTS)
	$(CC) $^ $(LDFLAGS) $(LIBS) -o $@

$(OBJ)/lib/%.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(STUDENT_FLAGS) -DCHAPTER=$(CHAPTER) -Ilib -I$(REPO)/bench -MMD -MP -c $< -o $@

$(OBJ)/bench/%.o: $(REPO)/bench/%.c
	@mkdir -p $(@D)
	$(CC) $(STUDENT_FLAGS) -DCHAPTER=$(CHAPTER) -Ilib -I$(REPO)/bench -MMD -MP -c $< -o $@

-include $(LIB_OBJS:.o=.d) $(PROBE_OBJS:.o=.d)
