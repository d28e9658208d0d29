#!/bin/sh
# items.sh (bench, chapter 1): the listing directives a file of chapter N's clean source
# offers, one a line with the lines each shows (bench/book/book.lua's parse), to write a
# page's listings from; `make book` prints the lines they must cover.
#
#   usage: sh bench/book/items.sh N lib/FILE... [BUILD]   (after make source-chapterN)
set -eu
n=$1
shift
BOOK_CHAPTER=$n BOOK_SOURCE=${BUILD:-build}/source/chapter$n BOOK_ITEMS="$*" \
    pandoc --from markdown --to html5 --lua-filter bench/book/book.lua /dev/null
