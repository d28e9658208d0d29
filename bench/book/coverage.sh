#!/bin/sh
# coverage.sh (bench, chapter 1): do a chapter page's listings show every line the chapter adds
# to lib/?
#
#   usage: sh bench/book/coverage.sh N SOURCE PREVIOUS RANGES
# SOURCE is chapter N's clean source (build/source/chapterN), PREVIOUS chapter N-1's ("" for
# chapter 1), RANGES the "FILE FIRST LAST" lines its listings showed (bench/book/book.lua).
# The lines added: every line of a file new in chapter N, and the new side of `diff` for
# the others. Exempt: blank lines, and a header's closing "#endif" of its include guard.
# Prints "chapter N: K listings, C / A lines added to lib/ shown" and then every line not
# shown as FILE:LINE: TEXT; fails when there is one.
set -eu
n=$1 source=$2 previous=$3 ranges=$4
[ -f "$ranges" ] || : > "$ranges"
listings=$(grep -c '^listing$' "$ranges" || true)
for f in "$source"/lib/*; do
    name=lib/${f##*/}
    if [ -n "$previous" ] && [ -e "$previous/$name" ]; then
        diff --old-line-format= --unchanged-line-format= --new-line-format='%dn
' "$previous/$name" "$f" || true
    else
        awk '{ print NR }' "$f"
    fi | awk -v name="$name" -v ranges="$ranges" -v file="$f" '
        BEGIN {
            while ((getline line < ranges) > 0) {
                split(line, r, " ")
                if (r[1] == name) for (i = r[2]; i <= r[3]; i++) shown[i] = 1
            }
            while ((getline line < file) > 0) text[++count] = line
            for (last = count; last > 0 && text[last] !~ /[^ \t]/; last--) ;
        }
        {
            line = $1
            if (text[line] !~ /[^ \t]/) next
            if (name ~ /\.h$/ && line == last && text[line] ~ /^#endif/) next
            added++
            if (line in shown) covered++
            else printf "uncovered %s:%d: %s\n", name, line, text[line]
        }
        END { printf "count %d %d\n", added, covered }'
done | awk -v n="$n" -v listings="$listings" '
    /^count / { added += $2; covered += $3; next }
    { sub(/^uncovered /, "    "); missing[++m] = $0 }
    END {
        printf "chapter %s: %d listings, %d / %d lines added to lib/ shown\n", n, listings, covered, added
        for (i = 1; i <= m; i++) print missing[i]
        exit m > 0
    }'
