/* atomic_file.c (chapter 1): temporary file, then rename. See atomic_file.h. */
#include "atomic_file.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

int atomic_open(AtomicFile *out, const char *path)
{
    if (strlen(path) >= sizeof out->final_path) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(out->final_path, path);
    snprintf(out->temp_path, sizeof out->temp_path, "%s.tmp.%ld", path, (long)getpid());
    out->file = fopen(out->temp_path, "wb");
    return out->file ? 0 : -1;
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
        if (rename(out->temp_path, out->final_path) == 0)
            return 0;
        reason = errno;
    }
    remove(out->temp_path);
    errno = reason ? reason : EIO;
    return -1;
}
