#!/bin/sh
# browser_gallery.sh: the gallery page in a real browser (bench/gallery.h).
#
# Opens DIR/index.html (default build/figures) from disk in headless Chromium (Debian's
# chromium package) and checks that every image loaded (complete, naturalWidth > 0), that
# nothing failed to load, that the page wrote nothing on the console, and that the page
# itself carries no script. Saves a screenshot: build/gallery_screenshot.png.
#
# How: the page has no script, so the check runs in a copy of it, build/browser_test/
# check.html, with a <base> pointing at DIR and a small script injected at the top of
# <head> (before any image starts loading). The script records every error event (a
# failed image load is one) and every console.error or console.warn, and on load writes
# what it found into <pre id="browser-check">, which --dump-dom prints
# (--virtual-time-budget lets the page finish loading first). Chromium's log on stderr
# also names each console message a page makes ("CONSOLE"); the check wants none.
# The same check runs first on a copy with one image's name spoiled and a console.error
# added: unless it reports both, the check itself is broken and the test fails.
#
#   usage: sh bench/browser_gallery.sh [DIR]      (make browser-test)
set -eu
dir=${1:-build/figures}
page=$dir/index.html
work=build/browser_test
screenshot=build/gallery_screenshot.png

fail() { echo "browser_gallery: $*" >&2; exit 1; }
[ -f "$page" ] || fail "no $page: run make figures QUICK=1 (or make gallery) first"
command -v chromium >/dev/null || fail "chromium is not installed: apt-get install -y chromium"
if grep -qi '<script' "$page"; then fail "$page carries a script"; fi

mkdir -p "$work"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
# As file URLs: absolute, with the characters a URL cannot hold as they are escaped.
url() { printf 'file://%s' "$(cd "$1" && pwd | sed 's/%/%25/g; s/ /%20/g; s/#/%23/g; s/?/%3F/g')"; }
figures_url=$(url "$dir")
work_url=$(url "$work")

browse() {
    timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --disable-dev-shm-usage --user-data-dir="$profile" --allow-file-access-from-files \
        --hide-scrollbars \
        --enable-logging=stderr --v=0 "$@"
}

cat > "$work/inject.html" <<EOF
<base href="$figures_url/">
<script>
var problems = [];
window.addEventListener('error', function (event) {
    var target = event.target;
    problems.push('error: ' + (target && target.src ? target.src : event.message));
}, true);
['error', 'warn'].forEach(function (level) {
    var original = console[level];
    console[level] = function () {
        problems.push('console.' + level + ': ' + Array.prototype.join.call(arguments, ' '));
        original.apply(console, arguments);
    };
});
window.addEventListener('load', function () {
    var images = document.images;
    for (var i = 0; i < images.length; i++)
        if (!(images[i].complete && images[i].naturalWidth > 0))
            problems.push('not loaded: ' + images[i].src);
    var out = document.createElement('pre');
    out.id = 'browser-check';
    out.textContent = 'images=' + images.length + ' problems=' + problems.length + '\n' +
                      problems.join('\n');
    document.body.appendChild(out);
});
</script>
EOF
sed '/<head>/r '"$work/inject.html" "$page" > "$work/check.html"
awk '!spoiled && sub(/<img src="/, "<img src=\"no-such-") { spoiled = 1 } { print }
     /<body>/ { print "<script>console.error(\"canary\")</script>" }' \
    "$work/check.html" > "$work/broken.html"

# check NAME: open NAME.html; what the script found goes to NAME.result, the log to NAME.log.
check() {
    browse --virtual-time-budget=10000 --dump-dom "$work_url/$1.html" > "$work/$1.dom" \
        2> "$work/$1.log" || fail "chromium failed on $work/$1.html (see $work/$1.log)"
    sed -n '/<pre id="browser-check">/,/<\/pre>/p' "$work/$1.dom" | sed 's/<[^>]*>//g' \
        > "$work/$1.result"
    [ -s "$work/$1.result" ] || fail "the check did not run in $work/$1.html"
}
count() { sed -n "1s/.*$1=\([0-9]*\).*/\1/p" "$2"; }

check broken
grep -q 'not loaded: .*no-such-' "$work/broken.result" &&
    grep -q 'console.error: canary' "$work/broken.result" &&
    grep -q 'CONSOLE.*canary' "$work/broken.log" ||
    fail "the check missed a broken image or a console error in $work/broken.html:
$(cat "$work/broken.result")"

check check
images=$(count images "$work/check.result")
problems=$(count problems "$work/check.result")
expected=$(grep -o '<img ' "$page" | wc -l)
[ "$images" -gt 0 ] || fail "no image on $page"
[ "$images" -eq "$expected" ] || fail "the browser saw $images images, the page has $expected"
[ "$problems" -eq 0 ] || fail "$problems problems on $page:
$(sed 1d "$work/check.result")"
if grep -q 'CONSOLE' "$work/check.log"; then
    fail "console messages on $page:
$(grep 'CONSOLE' "$work/check.log")"
fi

rm -f "$screenshot"
browse --window-size=1280,2400 --screenshot="$(pwd)/$screenshot" "$figures_url/index.html" \
    > "$work/screenshot.log" 2>&1 || fail "no screenshot (see $work/screenshot.log)"
[ -s "$screenshot" ] || fail "no screenshot (see $work/screenshot.log)"
echo "browser_gallery: $page in Chromium: $images images, all loaded; no console message;" \
    "a broken image and a console error were caught on a spoiled copy; screenshot $screenshot"
