#!/bin/sh
# build.sh (bench, chapter 1): the book, BUILD/book/ (make book).
#
# One page per chapter, chapterN.html from docs/chapterN.md, with its listings taken from
# chapter N's clean source (BUILD/source/chapterN, make source-chapterN) by the filter
# bench/book/book.lua, its equations as MathML, its figures and tables from FIGURES
# when they are there; every other docs/ page as NAME.html; and index.html. Then each
# chapter's coverage check (bench/book/coverage.sh). Fails when pandoc or a filter fails
# (a directive that finds nothing) or when a chapter's listings miss a line it adds.
#
#   usage: sh bench/book/build.sh BUILD FIGURES "1 2 ... 9"
set -eu
build=$1 figures=$2 chapters=$3
book=$build/book
work=$book/.work
rm -rf "$work"
mkdir -p "$book" "$work"
root=$(realpath -m --relative-to="$book" .)
figures_link=$(realpath -m --relative-to="$book" "$figures")
style=bench/book/style.html

title() { sed -n '1s/^# *//p' "$1"; }

# page MARKDOWN OUT [pandoc options]: one page, written whole or not at all.
page() {
    md=$1 out=$2
    shift 2
    BOOK_ROOT=$root BOOK_FIGURES=$figures BOOK_FIGURES_LINK=$figures_link BOOK_LAB=$build/lab/index.html \
        pandoc "$md" --from markdown --to html5 --standalone --mathml \
        --lua-filter bench/book/book.lua --include-in-header "$style" \
        --metadata pagetitle="$(title "$md")" "$@" -o "$out.tmp"
    mv "$out.tmp" "$out"
}

for md in docs/*.md; do
    name=${md##*/}
    name=${name%.md}
    case $name in chapter[0-9]*) continue ;; esac
    page "$md" "$book/$name.html"
done

failed=""
previous=""
for n in $chapters; do
    md=docs/chapter$n.md
    prev=$((n - 1)) next=$((n + 1))
    {
        printf '<nav class="chapters">'
        if [ -f "docs/chapter$prev.md" ]; then
            printf '<a rel="prev" href="chapter%s.html">&larr; %s</a> · ' "$prev" "$(title "docs/chapter$prev.md")"
        fi
        printf '<a href="index.html">Contents</a>'
        if [ -f "docs/chapter$next.md" ]; then
            printf ' · <a rel="next" href="chapter%s.html">%s &rarr;</a>' "$next" "$(title "docs/chapter$next.md")"
        fi
        printf '</nav>\n'
    } > "$work/nav$n.html"
    ranges=$work/ranges$n
    : > "$ranges"
    BOOK_CHAPTER=$n BOOK_SOURCE=$build/source/chapter$n BOOK_COVERAGE=$ranges \
        page "$md" "$book/chapter$n.html" --toc --toc-depth=2 \
        --include-before-body "$work/nav$n.html" --include-after-body "$work/nav$n.html"
    sh bench/book/coverage.sh "$n" "$build/source/chapter$n" "$previous" "$ranges" || failed="$failed $n"
    previous=$build/source/chapter$n
done

{
    printf '# The book\n\n'
    printf 'A Monte Carlo ray tracer, taught chapter by chapter: each page derives what the '
    printf 'chapter adds, shows every line of code the chapter adds to `lib/` (taken from the '
    printf "chapter's clean source when the book is built), then the experiment, what the tests "
    printf 'check and the exercises.\n\n'
    for n in $chapters; do
        printf '%s. [%s](chapter%s.html)\n' "$n" "$(title "docs/chapter$n.md")" "$n"
    done
    printf '\n## Beside the chapters\n\n'
    if [ -f "$figures/index.html" ]; then
        printf -- '- [The gallery](%s): every figure and table, as `make figures` last made them.\n' \
            "$(realpath -m --relative-to="$book" "$figures/index.html")"
    else
        printf -- '- The gallery: `make figures` (QUICK=1: small) renders every figure into `%s/`.\n' "$figures"
    fi
    if [ -f "$build/lab/index.html" ]; then
        printf -- '- [The lab](../lab/index.html): every chapter live in the browser.\n'
    else
        printf -- '- The lab: `make lab` builds every chapter live in the browser (docs/lab.md).\n'
    fi
    for md in docs/*.md; do
        name=${md##*/}
        name=${name%.md}
        case $name in chapter[0-9]*) continue ;; esac
        printf -- '- [%s](%s.html)\n' "$(title "$md")" "$name"
    done
} > "$work/index.md"
page "$work/index.md" "$book/index.html"

if [ -n "$failed" ]; then
    echo "make book: the listings of chapter(s)$failed do not show every line the chapter adds to lib/" >&2
    exit 1
fi
echo "wrote $book/ (index.html, chapter pages$(for n in $chapters; do printf ' %s' "$n"; done))"
