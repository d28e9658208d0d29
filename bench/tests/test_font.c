/* test_font.c (bench, chapter 1): anti-aliased TrueType text (font.h).
 *
 * Text is drawn into small images and read back: a glyph lights pixels where its
 * outline is and nowhere else, with coverage between 0 and 1 at its edges (it is
 * anti-aliased) and the exact colour inside; the blend is pixel = (1 - a) pixel +
 * a colour; widths add up, grow with the text and scale with the size; bytes the font
 * cannot draw become '?'; text off the image is cut, not a crash; and a missing or
 * broken font file is an error that names the file and the Debian package to install.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "assert_close.h"
#include "font_fixture.h"
#include "font.h"

static Image filled(int width, int height, Vec3 colour)
{
    Image image = image_new(width, height);
    assert_non_null(image.pixels);
    for (int row = 0; row < height; row++)
        for (int col = 0; col < width; col++)
            image_set(&image, col, row, colour);
    return image;
}

static int same_colour(Vec3 a, Vec3 b)
{
    return fabs(a.x - b.x) < 1e-6 && fabs(a.y - b.y) < 1e-6 && fabs(a.z - b.z) < 1e-6;
}

static void draw(Image *image, const char *text, double x, double baseline, double size,
                 Vec3 colour)
{
    font_draw(image, &font, text, strlen(text), x, baseline, size, colour);
}

/* Red "A" at 32 pixels per em on blue: some pixels change, all of them inside the box
 * from the pen to its advance and from the baseline up by the ascent; each changed
 * pixel is the blend (a, 0, 1 - a) of the two; some are fully covered (a = 1), and
 * some partly (0 < a < 1: anti-aliased edges). */
static void test_glyph_draws_blended_pixels(void **state)
{
    const Vec3 blue = {0, 0, 1}, red = {1, 0, 0};
    Image image = filled(64, 64, blue);
    const double x = 10.0, baseline = 44.0, size = 32.0;
    draw(&image, "A", x, baseline, size, red);
    double advance = font_width(&font, "A", 1, size), ascent = font_ascent(&font, size);
    int changed = 0, full = 0, partial = 0;
    for (int row = 0; row < 64; row++)
        for (int col = 0; col < 64; col++) {
            Vec3 p = image_get(&image, col, row);
            if (same_colour(p, blue))
                continue;
            changed++;
            assert_close(p.y, 0.0, 1e-6);
            assert_close(p.x + p.z, 1.0, 1e-6);
            full += p.x > 1.0 - 1e-6;
            partial += p.x > 1e-3 && p.x < 1.0 - 1e-3;
            assert_true(col >= x - 1 && col <= x + advance + 1);
            assert_true(row >= baseline - ascent - 1 && row <= baseline);
        }
    assert_true(changed > 60); /* an A of about 23 pixels high, strokes 3 wide */
    assert_true(full > 20);
    assert_true(partial > 20);
    image_free(&image);
}

/* A space lights nothing, and empty text leaves the image alone. */
static void test_space_and_empty_text_draw_nothing(void **state)
{
    const Vec3 white = {1, 1, 1};
    Image image = filled(40, 30, white);
    draw(&image, " ", 5, 20, 16, vec3(0, 0, 0));
    draw(&image, "", 5, 20, 16, vec3(0, 0, 0));
    for (int row = 0; row < 30; row++)
        for (int col = 0; col < 40; col++)
            assert_true(same_colour(image_get(&image, col, row), white));
    image_free(&image);
}

/* Widths: 0 for no text; growing with each letter added; the sum of the letters'
 * advances (within the font's kerning, under a tenth of an em per pair); and
 * proportional to the size. The length argument counts bytes: a prefix is measured. */
static void test_width_grows_with_text(void **state)
{
    const char *text = "RMSE 0.031 at 4 spp";
    assert_close(font_width(&font, text, 0, 16), 0.0, 0.0);
    double previous = 0.0, letters = 0.0;
    for (size_t n = 1; n <= strlen(text); n++) {
        double width = font_width(&font, text, n, 16);
        assert_true(width > previous);
        letters += font_width(&font, text + n - 1, 1, 16);
        assert_close(width, letters, 0.1 * 16 * (double)n);
        previous = width;
    }
    double small = font_width(&font, text, strlen(text), 12);
    double large = font_width(&font, text, strlen(text), 24);
    assert_close(large, 2.0 * small, 1e-3 * large);
    assert_true(font_width(&font, "W", 1, 16) > font_width(&font, "i", 1, 16));
}

/* The vertical sizes scale with the size, and a line is taller than its ascent. */
static void test_line_height_scales(void **state)
{
    assert_close(font_line_height(&font, 32), 2.0 * font_line_height(&font, 16), 1e-3);
    assert_close(font_ascent(&font, 32), 2.0 * font_ascent(&font, 16), 1e-3);
    assert_true(font_line_height(&font, 16) > font_ascent(&font, 16));
    assert_true(font_line_height(&font, 16) >= 16.0);
}

/* Draws `text` black on white and returns the image. */
static Image black_on_white(const char *text)
{
    Image image = filled(80, 30, vec3(1, 1, 1));
    draw(&image, text, 4, 22, 20, vec3(0, 0, 0));
    return image;
}

static int images_equal(const Image *a, const Image *b)
{
    return memcmp(a->pixels, b->pixels, 3 * sizeof(float) * (size_t)a->width * a->height) == 0;
}

/* A control character, a '\n', invalid UTF-8 (a lone continuation byte, a truncated
 * sequence, an overlong form, a surrogate, a code point above U+10FFFF: one '?' per
 * byte) and a character DejaVu Sans lacks (U+E000, private use) are all drawn and
 * measured as '?'; a valid two-byte character (e acute) is its own glyph. */
static void test_undrawable_characters_become_question_marks(void **state)
{
    const struct {
        const char *text, *drawn_as;
    } odd[] = {{"\x01", "?"},
               {"\n", "?"},
               {"\x80", "?"},
               {"\xc3", "?"},
               {"\xc0\xbf", "??"},
               {"\xed\xa0\x80", "???"},
               {"\xf4\x90\x80\x80", "????"},
               {"\xee\x80\x80", "?"},
               {"a\tb", "a?b"}};
    for (size_t i = 0; i < sizeof odd / sizeof odd[0]; i++) {
        Image image = black_on_white(odd[i].text), expected = black_on_white(odd[i].drawn_as);
        if (!images_equal(&image, &expected))
            fail_msg("text %zu is not drawn as \"%s\"", i, odd[i].drawn_as);
        assert_close(font_width(&font, odd[i].text, strlen(odd[i].text), 20),
                     font_width(&font, odd[i].drawn_as, strlen(odd[i].drawn_as), 20), 1e-9);
        image_free(&image);
        image_free(&expected);
    }
    Image accent = black_on_white("\xc3\xa9"), question = black_on_white("?");
    assert_false(images_equal(&accent, &question));
    image_free(&accent);
    image_free(&question);
}

/* Text partly or wholly off the image, on every side, is cut off: the part inside is
 * drawn, nothing is written outside (the sanitizer run checks that). */
static void test_text_off_the_image_is_cut(void **state)
{
    const double places[][2] = {{-8, 15}, {30, 15}, {5, 4}, {5, 34}, {-500, 15}, {5, 500}};
    for (size_t i = 0; i < sizeof places / sizeof places[0]; i++) {
        Image image = filled(36, 30, vec3(1, 1, 1));
        draw(&image, "Wg", places[i][0], places[i][1], 24, vec3(0, 0, 0));
        int changed = 0;
        for (int row = 0; row < 30; row++)
            for (int col = 0; col < 36; col++)
                changed += image_get(&image, col, row).x < 1.0;
        if (i < 4)
            assert_true(changed > 0);
        else
            assert_int_equal(changed, 0);
        image_free(&image);
    }
}

/* A missing font file: -1, and a message naming the file and the package that ships
 * the figures' font; the Font is left empty. A file that is not a font: the same,
 * saying so. */
static void test_missing_font_is_a_clear_error(void **state)
{
    Font missing;
    char error[4400];
    const char *path = "/nonexistent/fonts/DejaVuSans.ttf";
    assert_int_equal(font_load(&missing, path, error, sizeof error), -1);
    assert_non_null(strstr(error, path));
    assert_non_null(strstr(error, "No such file"));
    assert_non_null(strstr(error, "fonts-dejavu-core"));
    assert_null(missing.data);

    char not_font[] = "/tmp/test_font_XXXXXX";
    int fd = mkstemp(not_font);
    assert_true(fd >= 0);
    const char text[] = "this is not a TrueType font, only text";
    assert_int_equal(write(fd, text, sizeof text), (ssize_t)sizeof text);
    close(fd);
    assert_int_equal(font_load(&missing, not_font, error, sizeof error), -1);
    assert_non_null(strstr(error, "not a TrueType font"));
    assert_non_null(strstr(error, "fonts-dejavu-core"));
    assert_null(missing.data);
    remove(not_font);

    /* A short error buffer still gets a terminated message. */
    char tiny[8];
    assert_int_equal(font_load(&missing, path, tiny, sizeof tiny), -1);
    assert_int_equal(strlen(tiny), sizeof tiny - 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_glyph_draws_blended_pixels),
        cmocka_unit_test(test_space_and_empty_text_draw_nothing),
        cmocka_unit_test(test_width_grows_with_text),
        cmocka_unit_test(test_line_height_scales),
        cmocka_unit_test(test_undrawable_characters_become_question_marks),
        cmocka_unit_test(test_text_off_the_image_is_cut),
        cmocka_unit_test(test_missing_font_is_a_clear_error),
    };
    return cmocka_run_group_tests(tests, load_font, free_font);
}
