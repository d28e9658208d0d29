#!/bin/sh
# check.sh CHAPTER STUDENT SOLUTION REFERENCES [ID...]: grade a student's tree.
#
# Builds STUDENT (a copy of make exercise-chapterN's tree) with bench/exercise/student.mk
# (GRADER_FILES, BENCH_OBJECTS, CC, CFLAGS, PKG_CFLAGS, LDFLAGS, LIBS from the
# environment), then runs its grader once per exercise (every exercise of the chapter,
# or the IDs given), each in a process of its own under a time limit of TIME_LIMIT seconds (default 60): a
# crash or a hang is a verdict too. SOLUTION is the grader built from the solution: it
# lists the exercises and renders the references into REFERENCES (again whenever it is
# newer than them). The verdicts go to stdout and STUDENT/check/verdicts.txt, the
# pictures beside them. Exit status: 0 when every exercise passes, 1 otherwise, 2 for
# bad use.
set -u
chapter=$1 student=$2 solution=$3 references=$4
shift 4
repo=$(pwd)
limit=${TIME_LIMIT:-60}

[ -d "$student/lib" ] || { echo "check.sh: $student is not a chapter's tree (it has no lib/)" >&2; exit 2; }
out=$student/check
mkdir -p "$out" "$references"
verdicts=$out/verdicts.txt
: > "$verdicts"
say() { printf '%s\n' "$*" | tee -a "$verdicts"; }

list=$("$solution" --list) || exit 2
if [ $# -gt 0 ]; then
    wanted=""
    for id in "$@"; do
        line=$(echo "$list" | grep "^$id ") || { echo "check.sh: chapter $chapter has no exercise $id" >&2; exit 2; }
        wanted="$wanted$line
"
    done
    list=$wanted
fi

say "chapter $chapter: checking $student"
if ! make --no-print-directory -s -C "$student" -f "$repo/bench/exercise/student.mk" REPO="$repo" \
        CHAPTER="$chapter" > "$out/build.log" 2>&1; then
    say "the tree does not compile; the compiler says:"
    grep -E 'error|undefined reference|No rule' "$out/build.log" | head -n 20 | sed 's/^/    /' | tee -a "$verdicts"
    echo "$list" | while read -r id function; do
        [ -n "$id" ] && say "exercise $id ($function): FAIL: the tree does not compile (above; all of it in $out/build.log)"
    done
    exit 1
fi
grep -q 'warning' "$out/build.log" && { say "the compiler warns:"; grep 'warning' "$out/build.log" | head -n 10 | sed 's/^/    /' | tee -a "$verdicts"; }

status=0
passed=0 total=0
for id in $(echo "$list" | awk '{ print $1 }'); do
    function=$(echo "$list" | awk -v id="$id" '$1 == id { print $2 }')
    total=$((total + 1))
    reference=$references/exercise-$id-reference.pfm
    if [ ! -e "$reference" ] || [ "$solution" -nt "$reference" ]; then
        "$solution" --reference "$id" "$references" || { echo "check.sh: the solution's reference for $id failed" >&2; exit 2; }
    fi
    timeout "$limit" "$out/build/grade" "$id" "$out" "$references" > "$out/$id.txt" 2>&1
    code=$?
    case $code in
        0) verdict="pass"; passed=$((passed + 1)) ;;
        1) verdict=$(head -n 1 "$out/$id.txt") ;;
        124) verdict="FAIL: no answer within $limit seconds: an endless loop (a path that never ends, a loop whose condition never changes)?" ;;
        134) verdict="FAIL: crashed: aborted (an assertion failed, or memory was freed twice?)" ;;
        136) verdict="FAIL: crashed: an arithmetic error (an integer division by zero?)" ;;
        139) verdict="FAIL: crashed: a segmentation fault (an index outside an array, a NULL or uninitialised pointer?)" ;;
        *) verdict="FAIL: crashed (exit status $code)" ;;
    esac
    [ "$code" -eq 0 ] || status=1
    say "exercise $id ($function): $verdict"
    tail -n +2 "$out/$id.txt" | sed 's/^/    /' | tee -a "$verdicts"
done
say "chapter $chapter: $passed of $total exercises pass (verdicts and pictures in $out/)"
exit $status
