/* font_fixture.h (bench, chapter 1): the figures' font, loaded once per test program (include
 * after cmocka.h), for the tests of the text, figure and plot files (chapter 1).
 *
 * load_font and free_font are a cmocka group's setup and teardown; a missing font
 * fails the whole group with font_load's message, which names the Debian package.
 */
#ifndef FONT_FIXTURE_H
#define FONT_FIXTURE_H

#include <stdio.h>

#include "font.h"

static Font font;

static int load_font(void **state)
{
    char error[4400];
    if (font_load(&font, FONT_PATH, error, sizeof error) != 0) {
        fprintf(stderr, "%s\n", error);
        return -1;
    }
    return 0;
}

static int free_font(void **state)
{
    font_free(&font);
    return 0;
}

#endif
