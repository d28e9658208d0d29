/* embed.c (bench, chapter 8): files as a JavaScript object of strings, for the lab's page.
 *
 * A page opened from disk (file://) may not read other files with a script, nor start
 * a worker from a file; it may load scripts. So the build writes what the page needs
 * to read (the scenes, the WebAssembly module's script, the worker's script) into
 * scripts: "embed NAME FILE..." prints
 *     var NAME = {"BASENAME": "the file's text", ...};
 * each text a JSON string (quotes, backslashes and control characters escaped; other
 * bytes as they are, so a UTF-8 file stays UTF-8). Exit status 1 if a file cannot be read.
 */
#include <stdio.h>
#include <string.h>

static int write_string(FILE *in)
{
    putchar('"');
    int c;
    while ((c = getc(in)) != EOF) {
        if (c == '"' || c == '\\')
            printf("\\%c", c);
        else if (c == '\n')
            fputs("\\n", stdout);
        else if (c < 0x20 || c == 0x7f)
            printf("\\u%04x", c);
        else
            putchar(c);
    }
    putchar('"');
    return ferror(in) ? -1 : 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs("usage: embed NAME FILE...\n", stderr);
        return 2;
    }
    printf("var %s = {", argv[1]);
    for (int i = 2; i < argc; i++) {
        FILE *in = fopen(argv[i], "rb");
        const char *slash = strrchr(argv[i], '/');
        if (!in) {
            fprintf(stderr, "embed: cannot read %s\n", argv[i]);
            return 1;
        }
        printf("%s\n\"%s\": ", i > 2 ? "," : "", slash ? slash + 1 : argv[i]);
        int status = write_string(in);
        fclose(in);
        if (status != 0) {
            fprintf(stderr, "embed: cannot read %s\n", argv[i]);
            return 1;
        }
    }
    puts("};");
    return 0;
}
