#!/bin/sh
# unused.sh TREE N [EARLIER]: the names chapter N's lesson adds but chapter N does not use.
#
# TREE is chapter N's clean source (make source-chapterN), EARLIER chapter N-1's. A name
# chapter N's lib/ declares that chapter N-1's does not (a function, prototype, macro,
# type, enumerator, global or struct field) is used when chapter N's code names it other
# than where it is declared: its lib/, its program, its tests, or the bench built for it
# (which reads scene files into the lesson's structs and reports its counts); a field,
# when some code names it after "." or "->". A type declared but defined nowhere in the
# lesson is unused too. A name that only a later chapter uses is a socket for that
# chapter: the later chapter should add it, or replace the block, instead.
set -eu
tree=$1
n=$2
earlier=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The bench files that chapter N builds (their first line names the chapter), as built.
mkdir -p "$work/bench"
for f in bench/*.c bench/*.h bench/tests/*.c bench/tests/*.h; do
    tag=$(sed -n '1s/^\/\* [^ ]* (bench, chapter \([0-9]*\)).*/\1/p' "$f")
    if [ -n "$tag" ] && [ "$tag" -le "$n" ]; then
        unifdef -x2 -DCHAPTER="$n" -o "$work/bench/${f##*/}" "$f" || exit 2
    fi
done

# The code without comments and string literals, as one list of words; and the names
# written after "." or "->".
for f in "$tree"/lib/*.[ch] "$tree"/chapters/ch$(printf %02d "$n")_*.c "$tree"/tests/*.[ch] "$work"/bench/*; do
    gcc -fpreprocessed -dD -E -P -x c "$f" 2>/dev/null | sed 's/"\([^"\\]\|\\.\)*"//g'
done >"$work/code"
grep -oE '[A-Za-z_][A-Za-z0-9_]*' "$work/code" | sort | uniq -c >"$work/words"
grep -oE '(\.|->)[[:space:]]*[A-Za-z_][A-Za-z0-9_]*' "$work/code" | sed 's/^\(\.\|->\)[[:space:]]*//' |
    sort | uniq -c >"$work/fields"

# What lib/ declares (name, kind, line, file), and which of those names chapter N-1's has.
declared() {
    ctags -x --_xformat='%N %K %n %F' --kinds-C=fpdtevxm "$1"/lib/*.c "$1"/lib/*.h |
        grep -v '^__anon'
}
declared "$tree" >"$work/declared"
: >"$work/earlier"
if [ -n "$earlier" ]; then
    declared "$earlier" | awk '{ sub(/.*\//, "", $4); print $1, $2, $4 }' | sort -u >"$work/earlier"
fi

awk -v words="$work/words" -v fields="$work/fields" -v earlier="$work/earlier" -v n="$n" '
    BEGIN {
        while ((getline line < words) > 0) { split(line, w, " "); word[w[2]] = w[1] }
        while ((getline line < fields) > 0) { split(line, w, " "); field[w[2]] = w[1] }
        while ((getline line < earlier) > 0) old[line] = 1
    }
    {
        name[NR] = $1; kind[NR] = $2; where[NR] = $4 ":" $3; file = $4; sub(/.*\//, "", file)
        key[NR] = $1 " " $2 " " file
        if ($2 != "member")
            sites[$1]++
    }
    END {
        for (i = 1; i <= NR; i++) {
            k = name[i]
            if (key[i] in old)
                continue
            if (kind[i] == "member" ? field[k] > 0 : word[k] > sites[k])
                continue
            if (!(k in shown))
                printf "%s: %s %s is declared but chapter %s does not use it\n", where[i],
                       kind[i], k, n
            shown[k] = 1
            unused++
        }
        exit unused > 0
    }' "$work/declared" || status=1

# A type declared but defined nowhere in the lesson: only a later chapter completes it.
for f in "$tree"/lib/*.h; do
    sed -n 's/^typedef struct \([A-Za-z_][A-Za-z0-9_]*\) \1;.*/\1/p' "$f" | while read -r type; do
        if ! grep -q "^struct $type {\|^typedef struct $type {" "$tree"/lib/*.h "$tree"/lib/*.c; then
            echo "$f: struct $type is declared but chapter $n never defines it"
            exit 1
        fi
    done || status=1
done
exit "${status:-0}"
