/* atomic_file.h (bench, chapter 1): writing an output file whole or not at all.
 *
 * Introduced in chapter 1. The data goes to "PATH.tmp.PID" in the same directory; only
 * when every byte is written and the file closed without error is it renamed over
 * PATH, which POSIX makes atomic. A failure leaves no PATH (or the old one) and removes
 * the temporary file.
 *
 * A signal that ends the program (SIGTERM, SIGHUP, a second SIGINT: render.h) must not
 * leave a temporary file behind either. So every temporary file is listed, from just
 * before it is created until it is renamed or removed, in a small table that
 * atomic_remove_temporaries() can walk from inside a signal handler. Only SIGKILL (or a
 * crash) leaves a temporary file, named after the dead process.
 */
#ifndef ATOMIC_FILE_H
#define ATOMIC_FILE_H

#include <stdio.h>

/* How many files may be being written at once (in one process). */
#define ATOMIC_OPEN_MAX 16

typedef struct {
    FILE *file;
    int slot; /* its entry in the table of temporary files */
    /* Tests only: called between the close and the rename, with the temporary file
     * complete, closed and still listed. atomic_open sets it to NULL. */
    void (*before_rename)(void);
    char final_path[4096];
    char temp_path[4200];
} AtomicFile;

/* Open the temporary file for `path`. Returns 0, or -1 with errno set (EMFILE when
 * ATOMIC_OPEN_MAX files are already being written). */
int atomic_open(AtomicFile *out, const char *path);

/* Close and rename into place; `failed` non-zero (or a write error) discards instead.
 * Returns 0 when the file is in place, else -1 with errno set: to the caller's errno
 * when `failed` is given, else to that of the failed write, flush or rename. */
int atomic_close(AtomicFile *out, int failed);

/* Remove every temporary file still being written, without closing it: for a signal
 * handler about to end the program. Async-signal-safe (it only calls unlink). */
void atomic_remove_temporaries(void);

#endif
