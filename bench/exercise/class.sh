#!/bin/sh
# class.sh CHAPTER CLASS OUT CHECK...: grade every tree of a class, for a teacher.
#
# Each folder of CLASS (a student's submitted tree, named after the student) is graded
# by the command CHECK... with STUDENT=TREE and OUT=FOLDER in its environment (make
# check-exercise-chapterN: bench/exercise/check.sh), each in its own sandbox, its
# verdicts, pictures and log written into FOLDER, OUT/trees/K-NAME/,
# outside every tree (a tree's own check/ folder is neither written nor read). Then
# OUT/verdicts.csv, one line per student per exercise (student, chapter, exercise,
# verdict PASS or FAIL, the verdict's first line), and OUT/summary.txt, also printed.
# Exit status: 0 once every tree is graded (whatever the verdicts), 2 when one cannot be.
set -u
set -f
chapter=$1 class=$2 out=$3
shift 3
refuse() { echo "class.sh: $1" >&2; exit 2; }
[ -d "$class" ] || refuse "DIR=$class is not a folder of submitted trees"
[ -n "$out" ] || refuse "OUT is empty"
[ -L "$out" ] && refuse "OUT=$out is a symbolic link"
mkdir -p -- "$out/trees" || refuse "cannot make $out"
class_real=$(cd -P -- "$class" && pwd -P) out_real=$(cd -P -- "$out" && pwd -P)
case $out_real/ in "$class_real"/*) refuse "OUT=$out is inside DIR=$class, where a tree could reach it" ;; esac

# A CSV field: in double quotes, each inner double quote doubled.
field() { printf '"%s"' "$(printf '%s' "$1" | sed 's/"/""/g')"; }

csv='student,chapter,exercise,verdict,reason
'
summary='' trees=0 graded=0
names=$(cd -- "$class" && find . -mindepth 1 -maxdepth 1 \( -type d -o -type l \) | sed 's|^\./||' | LC_ALL=C sort)
old_ifs=$IFS
IFS='
'
for name in $names; do
    IFS=$old_ifs
    trees=$((trees + 1))
    tree=$class/$name
    folder=$out/trees/$trees-$(printf '%s' "$name" | tr -c 'A-Za-z0-9._-' '_')
    rm -rf -- "$folder" && mkdir -p -- "$folder" || refuse "cannot make $folder"
    # The grader's words, on its stdout, are the record; check.sh writes them whole there.
    verdicts=$(STUDENT=$tree OUT=$folder "$@" 2> "$folder/errors.txt")
    lines=$(printf '%s\n' "$verdicts" | grep '^exercise [0-9.]* (')
    # Why a tree was not graded whole: the grader's words (make's own line left out).
    why=$({ grep -v '^make: ' "$folder/errors.txt"; printf '%s\n' "$verdicts"; } | grep . | head -n 1)
    if [ -z "$lines" ]; then
        csv="$csv$(field "$name"),$chapter,,FAIL,$(field "not graded: $why")
"
        summary="$summary$name: not graded ($why)
"
        continue
    fi
    graded=$((graded + 1))
    passed=0 total=0
    IFS='
'
    for line in $lines; do
        id=${line#exercise } id=${id%% *}
        verdict=${line#*): }
        total=$((total + 1))
        case $verdict in
            pass) passed=$((passed + 1)) word=PASS reason='' ;;
            *) word=FAIL reason=${verdict#FAIL: } ;;
        esac
        csv="$csv$(field "$name"),$chapter,$id,$word,$(field "$reason")
"
    done
    IFS=$old_ifs
    printf '%s\n' "$verdicts" | grep -q "^chapter $chapter: [0-9]* of [0-9]* exercises pass (" ||
        summary="$summary$name: the grader stopped before its summary: $(grep -v '^make: ' "$folder/errors.txt" | head -n 1)
"
    summary="$summary$name: $passed of $total exercises pass
"
done
IFS=$old_ifs
summary="chapter $chapter: $graded of $trees trees graded (verdicts.csv, trees/K-NAME/ in $out)
$summary"
status=0
printf '%s' "$csv" > "$out/verdicts.csv.tmp" && mv -f -- "$out/verdicts.csv.tmp" "$out/verdicts.csv" || {
    echo "class.sh: cannot write $out/verdicts.csv; the verdicts, here:" >&2
    printf '%s' "$csv"
    status=2
}
printf '%s' "$summary" > "$out/summary.txt.tmp" && mv -f -- "$out/summary.txt.tmp" "$out/summary.txt" || {
    echo "class.sh: cannot write $out/summary.txt" >&2
    status=2
}
printf '%s' "$summary"
exit $status
