/* atomic_file.h (chapter 1): writing an output file whole or not at all (SPEC §9).
 *
 * Introduced in chapter 1. The data goes to "PATH.tmp.PID" in the same directory; only
 * when every byte is written and the file closed without error is it renamed over
 * PATH, which POSIX makes atomic. A failure, or a crash halfway, leaves no PATH (or
 * the old one) and removes the temporary file where it can.
 */
#ifndef ATOMIC_FILE_H
#define ATOMIC_FILE_H

#include <stdio.h>

typedef struct {
    FILE *file;
    char final_path[4096];
    char temp_path[4200];
} AtomicFile;

/* Open the temporary file for `path`. Returns 0, or -1 with errno set. */
int atomic_open(AtomicFile *out, const char *path);

/* Close and rename into place; `failed` non-zero (or a write error) discards instead.
 * Returns 0 when the file is in place, else -1 with errno set: to the caller's errno
 * when `failed` is given, else to that of the failed write, flush or rename. */
int atomic_close(AtomicFile *out, int failed);

#endif
