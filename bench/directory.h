/* directory.h (bench, chapter 1): making folders and checking that they take a file, for
 * --out and for the reference cache: found out before any time is spent rendering.
 */
#ifndef DIRECTORY_H
#define DIRECTORY_H

#include <stddef.h>

/* mkdir -p; returns 0, or -1 with errno set and the failing directory in failed[size]. */
int directory_make(const char *path, char *failed, size_t size);

/* Whether a file can be written into `directory` (created if needed): 0, or -1 with
 * errno set and the folder that failed in failed[size]. A full disk is found by writing
 * a little. */
int directory_writable(const char *directory, char *failed, size_t size);

#endif
