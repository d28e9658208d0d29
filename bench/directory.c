/* directory.c (bench, chapter 1): making folders and checking that they take a file. See
 * directory.h. */
#include "directory.h"

#include <errno.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

int directory_make(const char *path, char *failed, size_t size)
{
    char directory[4096];
    if (snprintf(directory, sizeof directory, "%s", path) >= (int)sizeof directory) {
        errno = ENAMETOOLONG;
        snprintf(failed, size, "%s", path);
        return -1;
    }
    for (char *p = directory + 1;; p++) {
        int end = *p == '\0';
        if (*p == '/' || end) {
            *p = '\0';
            struct stat status;
            if (mkdir(directory, 0777) != 0 &&
                (errno != EEXIST || stat(directory, &status) != 0 ||
                 !S_ISDIR(status.st_mode))) {
                if (errno == EEXIST)
                    errno = ENOTDIR;
                snprintf(failed, size, "%s", directory);
                return -1;
            }
            if (end)
                return 0;
            *p = '/';
        }
    }
}

int directory_writable(const char *directory, char *failed, size_t size)
{
    if (directory_make(directory, failed, size) != 0)
        return -1;
    char probe[4200], block[4096] = {0};
    snprintf(failed, size, "%s", directory);
    snprintf(probe, sizeof probe, "%s/.write-test.%ld", directory, (long)getpid());
    FILE *file = fopen(probe, "wb");
    int ok = file && fwrite(block, 1, sizeof block, file) == sizeof block;
    int saved_errno = errno;
    if (file && fclose(file) != 0 && ok) {
        ok = 0;
        saved_errno = errno;
    }
    if (file)
        remove(probe);
    errno = saved_errno;
    return ok ? 0 : -1;
}
