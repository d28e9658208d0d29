#!/bin/sh
# sandbox.sh BOX GRADER COMMAND [ARG...]: run COMMAND in a sandbox made with bubblewrap.
#
# Inside, BOX (the grader's private copy of a student's tree) is /work, the current
# folder, writable (SANDBOX_READ_ONLY=1: read-only; SANDBOX_OBJECTS, a folder of the
# grader's, is bound at /work/check/build alike); GRADER (what the build needs of the
# grader's: its makefile, the bench's headers and objects) is /grader, read-only; /usr is
# read-only, with /etc's compiler links and the loader's cache; /tmp an empty 128 MiB
# tmpfs; /proc the sandbox's own (no other process in sight), /dev a minimal one. Nothing
# else of the machine is there (no home, no checkout, no build folder, no judge, no
# reference). No network, a session of its own, killed with its parent. Run as root, it
# runs as nobody (root's processes are not counted against a limit). Limits per process:
#     SANDBOX_MEMORY MiB of address space (default 4096, a sixth of this machine's memory),
#     SANDBOX_CPU seconds of processor time (default 300), SANDBOX_FILE MiB per file
#     written (default 64: an object or the probe is a few MiB), SANDBOX_PROCESSES
#     processes of its user (default: 256 more than it runs now: a fork bomb stops there).
# The environment inside is PATH, HOME=/work, LC_ALL=C and the variables SANDBOX_ENV
# names; bubblewrap itself, whose environment is there to read in /proc/1, gets PATH
# alone. With the address sanitizer, ASAN_OPTIONS gets the memory limit, which RLIMIT_AS
# cannot be (the sanitizer reserves terabytes it never uses). Descriptors are inherited.
# Exit status: COMMAND's (128 + N when it is killed by signal N); bubblewrap's 1 and its
# words on stderr when the sandbox cannot be made; 125 for a bad limit or no bubblewrap.
set -u
box=$1 grader=$2
shift 2
memory=${SANDBOX_MEMORY:-4096} cpu=${SANDBOX_CPU:-300} file=${SANDBOX_FILE:-64}
for value in "$memory" "$cpu" "$file" "${SANDBOX_PROCESSES:-1}"; do
    case $value in '' | *[!0-9]* | 0*)
        echo "sandbox.sh: a limit of \"$value\" is not a whole number >= 1" >&2; exit 125 ;;
    esac
done
command -v bwrap > /dev/null 2>&1 || { echo "sandbox.sh: bubblewrap (bwrap) is not installed" >&2; exit 125; }

user=""
[ "$(id -u)" = 0 ] && user="setpriv --reuid=65534 --regid=65534 --clear-groups"
uid=$(id -u)
[ -n "$user" ] && uid=65534
if [ -n "${SANDBOX_PROCESSES:-}" ]; then
    processes=$SANDBOX_PROCESSES
else
    running=$(awk -v uid="$uid" '$1 == "Uid:" && $2 == uid { n++ } END { print n + 0 }' \
        /proc/[0-9]*/status 2> /dev/null)
    processes=$((${running:-0} + 256))
fi

set -- -- "$@"
for name in ${SANDBOX_ENV:-}; do
    case $name in '' | *[!A-Za-z0-9_]* | [0-9]*) echo "sandbox.sh: SANDBOX_ENV names \"$name\"" >&2; exit 125 ;; esac
    eval "value=\${$name-}"
    set -- --setenv "$name" "$value" "$@"
done
bind=--bind
[ "${SANDBOX_READ_ONLY:-0}" = 1 ] && bind=--ro-bind
address=$((memory * 1048576))
case " ${CFLAGS:-} ${LDFLAGS:-} " in *-fsanitize=*address*)
    address=unlimited
    asan=$(printf '%s\n' "${ASAN_OPTIONS:-}" | sed 's/:*max_allocation_size_mb=[0-9]*//')
    set -- --setenv ASAN_OPTIONS "${asan:+$asan:}max_allocation_size_mb=$memory:allocator_may_return_null=1" "$@" ;;
esac

# shellcheck disable=SC2086 # the words of $user, on purpose
exec env -i PATH=/usr/bin:/bin prlimit --as="$address" --cpu="$cpu" --fsize=$((file * 1048576)) \
    --nproc="$processes" --core=0 -- $user \
    bwrap --unshare-all --die-with-parent --new-session \
    --ro-bind /usr /usr --symlink usr/bin /bin --symlink usr/sbin /sbin \
    --symlink usr/lib /lib --symlink usr/lib64 /lib64 \
    --ro-bind-try /etc/alternatives /etc/alternatives --ro-bind-try /etc/ld.so.cache /etc/ld.so.cache \
    --proc /proc --dev /dev --size 134217728 --tmpfs /tmp \
    "$bind" "$box" /work ${SANDBOX_OBJECTS:+"$bind"} ${SANDBOX_OBJECTS:+"$SANDBOX_OBJECTS"} \
    ${SANDBOX_OBJECTS:+/work/check/build} --ro-bind "$grader" /grader --chdir /work \
    --clearenv --setenv PATH /usr/bin:/bin --setenv HOME /work --setenv LC_ALL C "$@"
