#!/bin/sh
# false_alarms.sh CHAPTER SEEDS TREE: grade the solution's tree TREE of chapter CHAPTER under
# SEEDS seeds, GRADE_SEED = FIRST_SEED (default 1) and on (make check-exercise-chapterN
# SEED=s), and count the exercises that fail: each is a false alarm, the course's rate
# being at most COURSE_FALSE_ALARM over all its checks (grading.h). Prints each seed's failures, then the count; exit 0 when none
# failed, 1 otherwise, 2 on bad use.
set -u
chapter=$1 seeds=$2 tree=$3
case $seeds in '' | *[!0-9]* | 0*) echo "false_alarms.sh: SEEDS=$seeds is not a whole number >= 1" >&2; exit 2 ;; esac
case ${FIRST_SEED:-1} in *[!0-9]*) echo "false_alarms.sh: FIRST_SEED=$FIRST_SEED is not a whole number" >&2; exit 2 ;; esac
[ -d "$tree/lib" ] || { echo "false_alarms.sh: $tree is not a chapter's tree" >&2; exit 2; }
make=${MAKE:-make}
failed=0 graded=0 seed=${FIRST_SEED:-1} out=$(mktemp -d) || exit 2
trap 'rm -rf -- "$out"' EXIT
while [ "$seed" -lt "$((${FIRST_SEED:-1} + seeds))" ]; do
    env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL "$make" --no-print-directory -s \
        check-exercise-chapter"$chapter" STUDENT="$tree" SEED="$seed" OUT="$out/$seed" > "$out/log" 2>&1
    # graded: the summary line is there (make's status is 2 for a FAIL as for an error)
    grep -q "^chapter $chapter: [0-9]* of [0-9]* exercises pass" "$out/log" ||
        { cat "$out/log" >&2; echo "false_alarms.sh: seed $seed could not be graded" >&2; exit 2; }
    fails=$(grep -c '^exercise .*: FAIL' "$out/log")
    total=$(grep -c '^exercise ' "$out/log")
    graded=$((graded + total))
    if [ "$fails" -gt 0 ]; then
        failed=$((failed + fails))
        echo "seed $seed:"
        grep '^exercise .*: FAIL' "$out/log" | sed 's/^/    /'
    fi
    rm -rf -- "${out:?}/$seed"
    seed=$((seed + 1))
done
echo "chapter $chapter: $failed FAIL of $graded verdicts on the solution under $seeds seeds (from $((${FIRST_SEED:-1})))"
[ "$failed" -eq 0 ]
