#!/bin/sh
# check.sh CHAPTER STUDENT SOLUTION REFERENCES [ID...]: grade a student's tree.
#
# Builds STUDENT (a copy of make exercise-chapterN's tree) into STUDENT/check/build/probe
# with bench/exercise/student.mk (PROBE_FILES, BENCH_OBJECTS, CC, CFLAGS, PKG_CFLAGS,
# LDFLAGS, LIBS from the environment). SOLUTION, the grader built from the solution,
# lists the exercises, renders the references into REFERENCES (again whenever it is newer
# than them) and grades every exercise (or the IDs given): it runs the student's program
# under watch, TIME_LIMIT seconds at most (default 60), and decides from its answers
# alone (bench/exercise/supervise.h). The verdicts go to stdout, and whole, whatever
# happens to stdout, to STUDENT/check/verdicts.txt; the pictures beside them. Exit
# status: 0 when every exercise passes, 1 otherwise, 2 for bad use.
set -u
set -f
# A reader that stops early (| head -1) must not stop the check: its verdicts file is
# still written whole.
trap '' PIPE
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM
chapter=$1 student=$2 solution=$3 references=$4
shift 4
repo=$(pwd)
limit=${TIME_LIMIT:-60}

case $limit in
    '' | *[!0-9]* | 0*) echo "check.sh: TIME_LIMIT=$limit is not a whole number of seconds >= 1" >&2; exit 2 ;;
esac
[ -d "$student/lib" ] || { echo "check.sh: $student is not a chapter's tree (it has no lib/)" >&2; exit 2; }
case $student in -*) student=./$student ;; esac # no command takes it for an option
out=$student/check
mkdir -p -- "$out" "$references" || exit 2

# Every line of the verdicts, kept here (beyond the student's code's reach) until the
# file is written whole; each is printed as it comes, a failed print ignored.
verdicts=''
say() {
    verdicts="$verdicts$1
"
    printf '%s\n' "$1" 2> /dev/null
}
finish() {
    mkdir -p -- "$out" && printf '%s' "$verdicts" > "$out/verdicts.txt.tmp" &&
        mv -f -- "$out/verdicts.txt.tmp" "$out/verdicts.txt"
    exit "$1"
}

list=$("$solution" --list) || exit 2
all_ids=$(printf '%s\n' "$list" | awk 'NF == 2 { print $1 }')
if [ $# -gt 0 ]; then
    wanted=''
    for id in "$@"; do
        line=$(printf '%s\n' "$list" | awk -v id="$id" '$1 == id')
        [ -n "$line" ] || { echo "check.sh: chapter $chapter has no exercise $id" >&2; exit 2; }
        wanted="$wanted$line
"
    done
    list=$wanted
fi
entries=$(printf '%s\n' "$list" | awk 'NF == 2 { print $1 ":" $2 }')
rm -f -- "$out/verdicts.txt" # until this check's is whole

say "chapter $chapter: checking $student"
if ! make --no-print-directory -s -C "$student" -f "$repo/bench/exercise/student.mk" REPO="$repo" \
        CHAPTER="$chapter" > "$out/build.log" 2>&1; then
    say "the tree does not compile; the compiler says:"
    say "$(grep -E 'error|undefined reference|No rule' "$out/build.log" | head -n 20 | sed 's/^/    /')"
    for entry in $entries; do
        say "exercise ${entry%%:*} (${entry#*:}): FAIL: the tree does not compile (above; all of it in $out/build.log)"
    done
    finish 1
fi
if grep -q 'warning' "$out/build.log"; then
    say "the compiler warns:"
    say "$(grep 'warning' "$out/build.log" | head -n 10 | sed 's/^/    /')"
fi
# The program the grader runs, copied where the student's code does not look for it (it
# may delete its check/ folder).
copy=$(mktemp -d) || exit 2
trap 'rm -rf -- "$copy"' EXIT
program=$copy/probe
cp -- "$out/build/probe" "$program" || exit 2

# Every exercise's reference (of those graded by a render): a grader grades first the
# exercises it uses.
for id in $all_ids; do
    reference=$references/exercise-$id-reference.pfm
    if [ ! -e "$reference" ] || [ "$solution" -nt "$reference" ]; then
        "$solution" --reference "$id" "$references" || { echo "check.sh: the solution's reference for $id failed" >&2; exit 2; }
    fi
done

status=0
passed=0 total=0
for entry in $entries; do
    id=${entry%%:*} function=${entry#*:}
    total=$((total + 1))
    result=$("$solution" --judge "$id" "$out" "$references" "$program" "$limit")
    code=$?
    case $code in
        0) passed=$((passed + 1)) ;;
        1) status=1 ;;
        2) echo "check.sh: the grader could not grade exercise $id" >&2; exit 2 ;;
        *) status=1 # only the student's code signals it while the check goes on
           result="FAIL: the grader was stopped (exit status $code): does your code send signals to other processes?" ;;
    esac
    say "exercise $id ($function): $(printf '%s\n' "$result" | head -n 1)"
    numbers=$(printf '%s\n' "$result" | tail -n +2 | sed 's/^/    /')
    [ -z "$numbers" ] || say "$numbers"
done
say "chapter $chapter: $passed of $total exercises pass (verdicts and pictures in $out/)"
finish $status
