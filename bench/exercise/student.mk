# student.mk: builds a student's tree into its check/build/ folder; run by check.sh as
#     make -C STUDENT -f REPO/bench/exercise/student.mk REPO=... CHAPTER=N BENCH_FILES=...
# The student's lib/ comes first on the include path, so the bench and the grader see
# the student's headers (an inline exercise too). Objects are rebuilt when their source
# or a header they include changes (-MMD), so a second check compiles only what changed.
# Warnings are shown but do not stop the build: a half-written exercise is still graded.
OBJ        := check/build
STUDENT_FLAGS = -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Wpedantic \
                -Wno-unused-parameter -Wno-unused-function -pthread $(PKG_CFLAGS) $(CFLAGS)
LIB_OBJS   := $(patsubst %.c,$(OBJ)/%.o,$(wildcard lib/*.c))
BENCH_OBJS := $(patsubst $(REPO)/%.c,$(OBJ)/%.o,$(BENCH_FILES))

$(OBJ)/grade: $(LIB_OBJS) $(BENCH_OBJS)
	$(CC) $^ $(LDFLAGS) $(LIBS) -o $@

$(OBJ)/lib/%.o: lib/%.c
	@mkdir -p $(@D)
	$(CC) $(STUDENT_FLAGS) -DCHAPTER=$(CHAPTER) -Ilib -I$(REPO)/bench -MMD -MP -c $< -o $@

$(OBJ)/bench/%.o: $(REPO)/bench/%.c
	@mkdir -p $(@D)
	$(CC) $(STUDENT_FLAGS) -DCHAPTER=$(CHAPTER) -Ilib -I$(REPO)/bench -MMD -MP -c $< -o $@

-include $(LIB_OBJS:.o=.d) $(BENCH_OBJS:.o=.d)
