#!/bin/sh
# run_tests.sh LOGS SECONDS PROGRAM...: run test programs, none longer than SECONDS.
#
# The programs run from the current folder, as many at a time as there are cores, each
# with its output into LOGS/ (made afresh). Each runs under timeout(1) in a process
# group of its own: one that has not ended after SECONDS is sent SIGTERM with everything
# it started (its whole process group), SIGKILL $TEST_KILL_AFTER seconds later (10 by
# default), and counts as failed, with a line saying so. Then every program's output is
# printed in the order given, under a line with its name and the seconds it took, a
# FAILED line after each that failed, and a last line counts them. Exit status: 0 when
# every program passed, 1 otherwise.
set -u
logs=$1 seconds=$2 kill_after=${TEST_KILL_AFTER:-10}
shift 2
rm -rf "$logs" && mkdir -p "$logs" || exit 1
log_of() { echo "$logs/$(echo "$1" | tr / _)"; }
printf '%s\n' "$@" | xargs -P "$(nproc)" -I TEST sh -c '
    log="$1/$(echo "$3" | tr / _)"
    start=$(date +%s)
    timeout -k "$4" "$2" "$3" > "$log" 2>&1
    status=$?
    echo $(($(date +%s) - start)) > "$log.seconds"
    case $status in
        0) echo passed ;;
        124|137) echo "timed out: no end within $2 s, stopped with every process it started" ;;
        *) echo "failed (exit status $status)" ;;
    esac > "$log.result"' run_one "$logs" "$seconds" TEST "$kill_after"
passed=0 failed=0
for t in "$@"; do
    log=$(log_of "$t")
    echo "== $t ($(cat "$log.seconds" 2>/dev/null || echo "?") s)"
    cat "$log"
    result=$(cat "$log.result" 2>/dev/null || echo "failed (no result)")
    if [ "$result" = passed ]; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAILED: $t: $result"
    fi
done
echo "programs: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
