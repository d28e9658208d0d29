/* atomic_file.c (bench, chapter 1): temporary file, then rename. See atomic_file.h.
 *
 * The table of temporary files is the one mutable global of the library, because a
 * signal handler can reach nothing else: it gets no argument, and may call only
 * async-signal-safe functions (no malloc, no locks). So the table is fixed: a state per
 * slot and a path buffer per slot. A writer claims a free slot (compare and swap, so
 * that threads may write files at once), copies the path into it, and only then marks
 * it listed and creates the file; once the file is renamed or removed it frees the
 * slot. The handler unlinks the path of every listed slot. Between the rename (or
 * removal) and the freeing, it unlinks a name that is gone: harmless. The states are
 * lock-free atomics, which a signal handler may read (C11 7.14.1.1).
 */
#include "atomic_file.h"

#include <errno.h>
#include <stdatomic.h>
#include <string.h>
#include <unistd.h>

#if ATOMIC_INT_LOCK_FREE != 2
#error "the table of temporary files needs lock-free atomic int for its signal handler"
#endif

enum {
    SLOT_FREE,
    SLOT_CLAIMED,
    SLOT_LISTED
};

static atomic_int slot_state[ATOMIC_OPEN_MAX];
static char slot_path[ATOMIC_OPEN_MAX][sizeof((AtomicFile *)0)->temp_path];

/* List `temp_path` in a free slot; returns the slot, or -1 when all are taken. */
static int list_temporary(const char *temp_path)
{
    for (int slot = 0; slot < ATOMIC_OPEN_MAX; slot++) {
        int expected = SLOT_FREE;
        if (atomic_compare_exchange_strong(&slot_state[slot], &expected, SLOT_CLAIMED)) {
            strcpy(slot_path[slot], temp_path);
            atomic_store(&slot_state[slot], SLOT_LISTED);
            return slot;
        }
    }
    return -1;
}

static void unlist_temporary(int slot) { atomic_store(&slot_state[slot], SLOT_FREE); }

void atomic_remove_temporaries(void)
{
    for (int slot = 0; slot < ATOMIC_OPEN_MAX; slot++)
        if (atomic_load(&slot_state[slot]) == SLOT_LISTED)
            unlink(slot_path[slot]);
}

int atomic_open(AtomicFile *out, const char *path)
{
    if (strlen(path) >= sizeof out->final_path) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(out->final_path, path);
    snprintf(out->temp_path, sizeof out->temp_path, "%s.tmp.%ld", path, (long)getpid());
    out->before_rename = NULL;
    out->slot = list_temporary(out->temp_path);
    if (out->slot < 0) {
        errno = EMFILE;
        return -1;
    }
    out->file = fopen(out->temp_path, "wb");
    if (!out->file) {
        int reason = errno;
        unlist_temporary(out->slot);
        errno = reason;
        return -1;
    }
    return 0;
}

int atomic_close(AtomicFile *out, int failed)
{
    /* The first failure names the errno: the caller's (its errno on entry), a write
     * error (the errno the failed write left), the final flush, or the rename. */
    int reason = errno;
    failed = failed || ferror(out->file);
    if (fclose(out->file) != 0 && !failed) {
        failed = 1;
        reason = errno;
    }
    out->file = NULL;
    if (!failed) {
        if (out->before_rename)
            out->before_rename();
        if (rename(out->temp_path, out->final_path) == 0) {
            unlist_temporary(out->slot);
            return 0;
        }
        reason = errno;
    }
    remove(out->temp_path);
    unlist_temporary(out->slot);
    errno = reason ? reason : EIO;
    return -1;
}
