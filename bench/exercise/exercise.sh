#!/bin/sh
# exercise.sh CHAPTER SOURCE GRADER OUT: write chapter CHAPTER's exercise tree into OUT.
#
# OUT is a copy of SOURCE (the chapter's clean source, make source-chapterN) in which
# the body of each of the chapter's exercises (GRADER --list: "ID FUNCTION") is
# replaced by GRADER --blank ID: the task as a comment, then a neutral body that
# compiles. An exercise is marked in the lesson by "Exercise ID" at the start of the
# comment that documents its function (before its declaration or its definition); the
# body is the function's definition, from the "{" line to the "}" line at column 0.
# A marker without its function, or a function without its marker, is an error.
set -eu
chapter=$1 source=$2 grader=$3 out=$4

[ -d "$source/lib" ] || { echo "exercise.sh: $source has no lib/ (make source-chapter$chapter)" >&2; exit 2; }
rm -rf "$out"
mkdir -p "$out"
cp -R "$source/." "$out/"

list=$("$grader" --list)
[ -n "$list" ] || { echo "exercise.sh: chapter $chapter has no exercises" >&2; exit 2; }

# Every "Exercise N.k" marker of this chapter must be in the list.
for id in $(grep -ho "Exercise $chapter\.[0-9]*" "$out"/lib/*.[ch] | sed 's/Exercise //' | sort -u); do
    echo "$list" | grep -q "^$id " || {
        echo "exercise.sh: lib/ marks Exercise $id, which bench/exercise/chapter$chapter.c does not grade" >&2
        exit 2
    }
done

echo "$list" | while read -r id function; do
    # The marker: "Exercise ID" opening a comment, which ends within 6 lines and is
    # followed within 3 lines by the function's name and "(".
    marked=$(awk -v id="$id" -v fn="$function" '
        index($0, "/* Exercise " id) == 1 && substr($0, length("/* Exercise " id) + 1, 1) ~ /[:,.]/ {
            start = FNR; stop = 0
        }
        start && !stop && FNR - start <= 6 && index($0, "*/") { stop = FNR }
        stop && FNR > stop && FNR - stop <= 3 && index($0, fn "(") { print FILENAME; exit }
        FNR == 1 { start = 0; stop = 0 }' "$out"/lib/*.h "$out"/lib/*.c)
    [ -n "$marked" ] || {
        echo "exercise.sh: no \"/* Exercise $id\" comment before $function in $out/lib" >&2
        exit 2
    }
    # The definition: a line at column 0 naming the function, whose signature is
    # followed by a "{" line rather than ended by ";", or the whole definition on that
    # line ("... fn(...) { body }", as the formatter writes a short one).
    file=$(awk -v fn="$function" '
        FNR == 1 { state = 0 }
        state == 0 && /^[A-Za-z]/ && index($0, fn "(") && /\) \{ .* \}$/ { print FILENAME; exit }
        state == 0 && /^[A-Za-z]/ && index($0, fn "(") && $0 !~ /^[A-Za-z_]+ *=/ { state = 1 }
        state == 1 && /;[ \t]*$/ { state = 0 }
        state == 1 && $0 == "{" { print FILENAME; exit }' "$out"/lib/*.c "$out"/lib/*.h)
    [ -n "$file" ] || { echo "exercise.sh: no definition of $function in $out/lib" >&2; exit 2; }
    "$grader" --blank "$id" > "$out/.blank"
    awk -v fn="$function" -v blank="$out/.blank" '
        state == 0 && /^[A-Za-z]/ && index($0, fn "(") && /\) \{ .* \}$/ {
            print substr($0, 1, index($0, ") { ")); print "{"
            while ((getline line < blank) > 0) print line
            print "}"; state = 3; next
        }
        state == 0 && /^[A-Za-z]/ && index($0, fn "(") { state = 1 }
        state == 1 && /;[ \t]*$/ { state = 0 }
        state == 1 && $0 == "{" { print; while ((getline line < blank) > 0) print line; state = 2; next }
        state == 2 && $0 == "}" { state = 3 }
        state == 2 { next }
        { print }
        END { if (state != 3) exit 1 }' "$file" > "$file.new" || {
        echo "exercise.sh: the body of $function in $file is not a \"{\" ... \"}\" block at column 0" >&2
        exit 2
    }
    mv "$file.new" "$file"
    rm -f "$out/.blank"
    echo "exercise $id: $function in ${file#"$out"/}"
done
echo "wrote $out/: chapter $chapter with its exercises blank (make check-exercise-chapter$chapter checks them)"
