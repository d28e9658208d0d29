/* run_command.h (bench, chapter 8): running a shell command from a bench test (include
 * after cmocka.h), for the tests that grade exercises through make.
 */
#ifndef RUN_COMMAND_H
#define RUN_COMMAND_H

#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>

/* Run a shell command; its output into *out (malloc'd). Returns its exit status, or -1
 * when it did not exit. */
static int run_command(const char *command, char **out)
{
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    size_t size = 0, capacity = 4096;
    char *text = malloc(capacity);
    assert_non_null(text);
    size_t n;
    while ((n = fread(text + size, 1, capacity - size - 1, pipe)) > 0) {
        size += n;
        if (capacity - size < 2) {
            capacity *= 2;
            text = realloc(text, capacity);
            assert_non_null(text);
        }
    }
    text[size] = '\0';
    int status = pclose(pipe);
    *out = text;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

#endif
