#!/bin/sh
# check.sh CHAPTER STUDENT SOLUTION REFERENCES [ID...]: grade a student's tree.
#
# STUDENT's lib/ is copied into a private folder and built there with the grader's own
# makefile (bench/exercise/student.mk; PROBE_FILES, BENCH_OBJECTS, CC, CFLAGS, PKG_CFLAGS,
# LDFLAGS, GRADER_LDFLAGS, LIBS from the environment), and every exercise's probe runs there, each in the
# sandbox of bench/exercise/sandbox.sh (TRUSTED=1: none, for one's own tree). SOLUTION, the
# judge, checked against the checksum recorded when it was built, lists the exercises,
# renders the references into REFERENCES (again when their checksums, recorded beside
# them, do not match) and grades every exercise (or the IDs given), TIME_LIMIT seconds at
# most each (default 60), from the probe's answers alone (bench/exercise/supervise.h),
# the random inputs of both from GRADE_SEED (default 0, the fixed seed; grading.h).
# The verdicts go to stdout, whole, and to OUT/verdicts.txt (OUT: default STUDENT/check,
# made afresh), the pictures and the build's log beside them. Exit status: 0 when every
# exercise passes, 1 otherwise, 2 when the tree cannot be graded or a verdict not kept.
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
repo=$(pwd -P)
limit=${TIME_LIMIT:-60}
refuse() { echo "check.sh: $1" >&2; exit 2; }

case $limit in
    '' | *[!0-9]* | 0*) refuse "TIME_LIMIT=$limit is not a whole number of seconds >= 1" ;;
esac
case $student in -*) student=./$student ;; esac # no command takes it for an option
real=$(cd -P -- "$student" 2> /dev/null && pwd -P) || refuse "cannot enter $student"
[ "$real" = / ] && refuse "STUDENT=$student is the whole file system (/), not a chapter's tree"
case $repo/ in "$real"/*) refuse "STUDENT=$student is or holds this repository ($repo), not a chapter's tree" ;; esac
[ -L "$student/lib" ] && refuse "$student/lib is a symbolic link: a tree's lib/ must be its own folder"
[ -d "$student/lib" ] || refuse "$student is not a chapter's tree (it has no lib/)"
case ${GRADE_SEED:-0} in
    *[!0-9]*) refuse "GRADE_SEED=$GRADE_SEED is not a whole number (the grading's seed, default 0)" ;;
esac
# The probe, in its sandbox, draws its random inputs from the judge's seed.
export GRADE_SEED=${GRADE_SEED:-0} SANDBOX_ENV="${SANDBOX_ENV:+$SANDBOX_ENV }GRADE_SEED"
case ${TRUSTED:-} in '' | 0) trusted=0 ;; 1) trusted=1 ;; *) refuse "TRUSTED=$TRUSTED is neither 1 nor 0" ;; esac

# Where the verdicts go: made afresh by the grader, never through a link out of the tree.
if [ -n "${OUT:-}" ]; then
    out=$OUT
    [ -L "$out" ] && refuse "OUT=$out is a symbolic link"
else
    out=$student/check
    for name in check check/build check/build.log check/verdicts.txt; do
        [ -L "$student/$name" ] && refuse "$student/$name is a symbolic link (out of the tree?): remove it, the grader writes $student/check/ itself"
    done
    rm -rf -- "$out" || refuse "cannot remove the earlier $out"
fi
mkdir -p -- "$out" "$references" || refuse "cannot make $out or $references"

# Every line of the verdicts, kept here until the file is written whole; each is printed
# as it comes, a failed print ignored.
verdicts=''
say() {
    verdicts="$verdicts$1
"
    printf '%s\n' "$1" 2> /dev/null
}
# put TEXT PATH: TEXT whole into PATH (through PATH.tmp); on failure, why in $why.
put() {
    why=$({ printf '%s' "$1" | cat > "$2.tmp"; } 2>&1) && mv -f -- "$2.tmp" "$2" 2>/dev/null && return 0
    why=${why:-cannot write $2}
    rm -f -- "$2.tmp"
    return 1
}

private=$(mktemp -d) || refuse "cannot make a private folder (is the disk full?)"
trap 'rm -rf -- "$private"' EXIT
chmod 711 "$private" # the sandbox's user passes through it to box/ and grader/
box=$private/box grader=$private/grader

# The judge, as it was built: copied here first, so that nothing can change it meanwhile.
[ -f "$solution.sha256" ] || refuse "$solution has no checksum ($solution.sha256): build it with make"
judge=$private/judge
cp -- "$solution" "$judge" || refuse "cannot copy the judge $solution"
sum() { sha256sum < "$1" | cut -c 1-64; }
judge_sum=$(sum "$judge")
[ "$judge_sum" = "$(cut -c 1-64 "$solution.sha256")" ] ||
    refuse "$solution is not the judge make built (its checksum differs from $solution.sha256): make builds it again"

list=$("$judge" --list) || exit 2
all_ids=$(printf '%s\n' "$list" | awk 'NF == 2 { print $1 }')
if [ $# -gt 0 ]; then
    wanted=''
    for id in "$@"; do
        line=$(printf '%s\n' "$list" | awk -v id="$id" '$1 == id')
        [ -n "$line" ] || refuse "chapter $chapter has no exercise $id"
        wanted="$wanted$line
"
    done
    list=$wanted
fi
entries=$(printf '%s\n' "$list" | awk 'NF == 2 { print $1 ":" $2 }')

# Every exercise's reference, by content: REFERENCES/exercise-ID.sha256 holds the judge's
# checksum and the reference files'; rendered again when any differs. The judge reads
# copies checked again, in the private folder.
mkdir "$private/references" || refuse "cannot fill the private folder (is the disk full?)"
# matches SUMS FOLDER: every file SUMS lists (after its first line) is in FOLDER, whole.
listed() { tail -n +2 "$1" | grep .; }
matches() {
    [ -z "$(listed "$1")" ] || listed "$1" | (cd "$2" && sha256sum --status -c --strict 2> /dev/null)
}
for id in $all_ids; do
    sums=$references/exercise-$id.sha256
    if ! { [ "$(head -n 1 "$sums" 2> /dev/null)" = "judge $judge_sum" ] && matches "$sums" "$references"; }; then
        rm -f -- "$sums" "$references/exercise-$id-reference"*
        "$judge" --reference "$id" "$references" || refuse "the solution's reference for $id failed"
        files=$(cd "$references" && find . -maxdepth 1 -name "exercise-$id-reference*.pfm" | sed 's|^\./||')
        put "judge $judge_sum
$(cd "$references" && for f in $files; do sha256sum -- "$f"; done)
" "$sums" ||
            refuse "cannot record the references' checksums: $why"
    fi
    for file in $(listed "$sums" | awk '{ print $2 }'); do
        cp -- "$references/$file" "$private/references/$file" || refuse "cannot copy the reference $file"
    done
    matches "$sums" "$private/references" ||
        refuse "the references of $id changed while they were copied: check again"
done

# The private copy of the tree (its lib/ alone: no makefile, no .d file, nothing else of
# it is read), and what the build needs of the grader's: its makefile, the bench's
# headers, the probe's sources and the solution's bench objects (their times kept, so
# that make rebuilds in CACHE, when given, only what changed).
relative() {
    for file; do
        case $file in "$repo"/*) file=${file#"$repo"/} ;; "$PWD"/*) file=${file#"$PWD"/} ;; esac
        printf '%s\n' "$file"
    done
}
probe_files=$(relative ${PROBE_FILES:-}) bench_objects=$(relative ${BENCH_OBJECTS:-})
mkdir -p "$box/check/build" "$grader/objects" && cp -R -p -- "$real/lib" "$box/lib" ||
    refuse "cannot copy $student/lib into a private folder (is the disk full?)"
(cd "$repo" && cp -p --parents -- $(find bench -name '*.h') $probe_files "$grader/" &&
    cp -p --parents -- $bench_objects "$grader/objects/" &&
    cp -p -- bench/exercise/student.mk "$grader/student.mk") || refuse "cannot fill the private folder (is the disk full?)"
bench_objects=$(printf 'objects/%s\n' $bench_objects)
# The objects of this tree's earlier checks (same tree, judge and flags), kept by the
# grader out of the tree's reach: written only by this build's compiler, read-only to
# the probe. (A trusted build sees the private folder by its own changing path: none.)
if [ -n "${CACHE:-}" ] && [ "$trusted" = 0 ]; then
    key=$(printf '%s\n' "$real" "$judge_sum" "${CC:-}" "${CFLAGS:-}" "${LDFLAGS:-}" "${PKG_CFLAGS:-}" \
        "${GRADER_LDFLAGS:-}" |
        sha256sum | cut -c 1-24)
    objects=$CACHE/$key
    mkdir -p -- "$objects" || refuse "cannot make $objects"
else
    objects=$private/objects
    mkdir "$objects" || refuse "cannot fill the private folder (is the disk full?)"
fi
[ "$(id -u)" = 0 ] && chown -R 65534:65534 "$box" "$objects" # the sandbox's user, when root runs it
export SANDBOX_OBJECTS="$objects"

build_limit=${BUILD_LIMIT:-600}
if [ "$trusted" = 1 ]; then
    root=$private
    rmdir "$box/check/build" && ln -s "$objects" "$box/check/build" || refuse "cannot link $objects"
    run() { (cd "$box" && timeout -k 5 "$build_limit" env -i PATH="$PATH" HOME="$box" LC_ALL=C "$@"); }
else
    root=
    run() { timeout -k 5 "$build_limit" sh "$repo/bench/exercise/sandbox.sh" "$box" "$grader" "$@"; }
    why=$(run /bin/true 2>&1) ||
        refuse "the sandbox cannot be made here, so your tree is not graded (bubblewrap: $(printf '%s' "$why" | head -n 1)); to grade your own tree without it: TRUSTED=1"
fi

say "chapter $chapter: checking $student"
[ "$GRADE_SEED" = 0 ] || say "(random inputs from GRADE_SEED=$GRADE_SEED)"
run make --no-print-directory -s -r -f "$root/grader/student.mk" REPO="$root/grader" \
    CHAPTER="$chapter" PROBE_FILES="$probe_files" BENCH_OBJECTS="$bench_objects" \
    CC="${CC:-cc}" CFLAGS="${CFLAGS:-}" PKG_CFLAGS="${PKG_CFLAGS:-}" LDFLAGS="${LDFLAGS:-}" \
    GRADER_LDFLAGS="${GRADER_LDFLAGS:-}" LIBS="${LIBS:-}" > "$private/build.log" 2>&1
built=$?
log="all of it in $out/build.log"
why=$(cp -- "$private/build.log" "$out/build.log" 2>&1) || log="its log could not be written to $out/build.log: $why"
if [ $built -ne 0 ]; then
    say "the tree does not compile; the compiler says:"
    [ $built -eq 124 ] && say "    the build did not end within $build_limit seconds"
    say "$(grep -E 'error|undefined reference|No rule|Killed|limit' "$private/build.log" | head -n 20 | sed 's/^/    /')"
    for entry in $entries; do
        say "exercise ${entry%%:*} (${entry#*:}): FAIL: the tree does not compile (above; $log)"
    done
    passed=0 total=$(printf '%s\n' $entries | wc -l) status=1
else
    if grep -q 'warning' "$private/build.log"; then
        say "the compiler warns:"
        say "$(grep 'warning' "$private/build.log" | head -n 10 | sed 's/^/    /')"
    fi
    if [ "$trusted" = 1 ]; then
        set -- "$box/check/build/probe"
    else
        set -- /bin/sh "$repo/bench/exercise/sandbox.sh" "$box" "$grader" /work/check/build/probe
    fi
    status=0 passed=0 total=0
    for entry in $entries; do
        id=${entry%%:*} function=${entry#*:}
        total=$((total + 1))
        result=$(SANDBOX_READ_ONLY=1 SANDBOX_CPU=$((limit + 1)) \
            "$judge" --judge "$id" "$out" "$private/references" "$limit" "$@")
        code=$?
        case $code in
            0) passed=$((passed + 1)) ;;
            1) status=1 ;;
            2) refuse "the grader could not grade exercise $id" ;;
            *) status=1 # only the student's code signals it while the check goes on
               result="FAIL: the grader was stopped (exit status $code): does your code send signals to other processes?" ;;
        esac
        say "exercise $id ($function): $(printf '%s\n' "$result" | head -n 1)"
        numbers=$(printf '%s\n' "$result" | tail -n +2 | sed 's/^/    /')
        [ -z "$numbers" ] || say "$numbers"
    done
fi

# The summary names only what is there.
pictures=$(find "$out" -maxdepth 1 -name 'exercise-*.png' | wc -l)
beside=""
[ "$pictures" -gt 0 ] && beside=", $pictures picture$([ "$pictures" -gt 1 ] && echo s) beside it"
summary="chapter $chapter: $passed of $total exercises pass"
if put "$verdicts$summary (verdicts in $out/verdicts.txt$beside)
" "$out/verdicts.txt"; then
    say "$summary (verdicts in $out/verdicts.txt$beside)"
    exit $status
fi
say "$summary; $out/verdicts.txt could not be written ($why): the verdicts are only here"
exit 2
