/* test_figure.c (chapter 1): the side-by-side comparison figure (figure.h, chapter 1).
 *
 * Each figure is written, decoded again with stb_image, and checked against the layout
 * figure.h documents: its size for 1, 2 and 3 panels and for each text scale, panels
 * that are exactly the tone-mapped images, captions that are really drawn (lit pixels
 * in each band) and never outside their panel, wrapping and shrinking of long captions,
 * and refusal of panels that do not match.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image.h>

#include "figure.h"

static char figure_dir[64], figure_path[128];

static int make_dir(void **state)
{
    (void)state;
    strcpy(figure_dir, "/tmp/test_figure_XXXXXX");
    if (!mkdtemp(figure_dir))
        return -1;
    snprintf(figure_path, sizeof figure_path, "%s/figure.png", figure_dir);
    return 0;
}

static int remove_dir(void **state)
{
    (void)state;
    remove(figure_path);
    return rmdir(figure_dir);
}

typedef struct {
    unsigned char *rgb;
    int width, height;
} Decoded;

/* The radiance of panel i at (col, row) of a width x height panel: a different gradient
 * in each, so that a misplaced panel cannot pass. */
static Vec3 panel_radiance(int i, int col, int row, int width, int height)
{
    return vec3((double)col / width, (double)row / height, 0.2 * i);
}

/* Writes the figure of `count` gradient panels of width x height with these captions,
 * then reads it back. */
static Decoded figure_of(int count, int width, int height, const char *const *captions,
                         double exposure)
{
    Image panels[3] = {{0, 0, NULL}, {0, 0, NULL}, {0, 0, NULL}};
    for (int i = 0; i < count; i++) {
        panels[i] = image_new(width, height);
        assert_non_null(panels[i].pixels);
        for (int row = 0; row < height; row++)
            for (int col = 0; col < width; col++)
                image_set(&panels[i], col, row, panel_radiance(i, col, row, width, height));
    }
    assert_int_equal(figure_write_png(figure_path, panels, captions, count, exposure), 0);
    for (int i = 0; i < count; i++)
        image_free(&panels[i]);
    Decoded figure;
    int channels;
    figure.rgb = stbi_load(figure_path, &figure.width, &figure.height, &channels, 3);
    assert_non_null(figure.rgb);
    return figure;
}

static const unsigned char *pixel_at(const Decoded *figure, int x, int y)
{
    return figure->rgb + 3 * ((long)y * figure->width + x);
}

/* Caption text is light on a dark band: a pixel is lit when every channel is bright. */
static int lit(const Decoded *figure, int x, int y)
{
    const unsigned char *p = pixel_at(figure, x, y);
    return p[0] > 128 && p[1] > 128 && p[2] > 128;
}

/* Lit pixels from row `top` to the bottom, in columns [left, right). */
static int lit_in(const Decoded *figure, int top, int left, int right)
{
    int count = 0;
    for (int y = top; y < figure->height; y++)
        for (int x = left; x < right; x++)
            count += lit(figure, x, y);
    return count;
}

/* The documented size: n W + (n - 1) 4 s wide, H + s (12 L + 4) high, with s =
 * sqrt(W / 50) rounded and clamped to [1, 4]; here for 1, 2 and 3 panels at each scale
 * (and either side of where it changes), for captions of one and two lines (short
 * enough never to wrap). */
static void test_dimensions(void **state)
{
    (void)state;
    const struct {
        int width, scale;
    } sizes[] = {{64, 1}, {112, 1}, {113, 2}, {200, 2}, {312, 2}, {313, 3},
                 {400, 3}, {612, 3}, {613, 4}, {800, 4}, {1200, 4}};
    const char *one_line[] = {"a", "b", "c"}, *two_lines[] = {"a\nb", "c", "d"};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (int count = 1; count <= 3; count++)
            for (int lines = 1; lines <= 2; lines++) {
                Decoded figure = figure_of(count, sizes[s].width, 10,
                                           lines == 1 ? one_line : two_lines, 1.0);
                int scale = sizes[s].scale;
                assert_int_equal(figure.width,
                                 count * sizes[s].width + (count - 1) * 4 * scale);
                assert_int_equal(figure.height, 10 + scale * (12 * lines + 4));
                stbi_image_free(figure.rgb);
            }
}

/* Every pixel of every panel is the tone map (with the figure's exposure) of that
 * panel's radiance, at the documented place. */
static void test_panels_are_tone_mapped(void **state)
{
    (void)state;
    const char *captions[] = {"left", "middle", "right"};
    const double exposure = 1.7;
    Decoded figure = figure_of(3, 200, 150, captions, exposure);
    for (int i = 0; i < 3; i++)
        for (int row = 0; row < 150; row++)
            for (int col = 0; col < 200; col++) {
                const unsigned char *p = pixel_at(&figure, i * (200 + 8) + col, row);
                Vec3 radiance = panel_radiance(i, col, row, 200, 150);
                assert_int_equal(p[0], image_tonemap((float)radiance.x, exposure));
                assert_int_equal(p[1], image_tonemap((float)radiance.y, exposure));
                assert_int_equal(p[2], image_tonemap((float)radiance.z, exposure));
            }
    stbi_image_free(figure.rgb);
}

/* Each caption band holds text (lit pixels) inside its own panel's columns, kept s
 * pixels from the sides; the gaps between panels and the band around the text are dark.
 * The realistic captions of a chapter figure are used. */
static void test_captions_are_drawn_in_their_band(void **state)
{
    (void)state;
    const char *captions[] = {"1 spp, sub-pixels\n0.21 s, RMSE 0.031",
                              "4 spp, random\n0.83 s, RMSE 0.016", ""};
    Decoded figure = figure_of(3, 200, 100, captions, 1.0);
    const int scale = 2, gap = 8;
    for (int i = 0; i < 3; i++) {
        int left = i * (200 + gap);
        int inside = lit_in(&figure, 100, left + scale, left + 200 - scale);
        assert_int_equal(lit_in(&figure, 100, left, left + 200), inside);
        if (i < 2)
            assert_true(inside > 200); /* some 30 letters of several 2 x 2 squares each */
        else
            assert_int_equal(inside, 0); /* an empty caption draws nothing */
        if (i > 0)
            assert_int_equal(lit_in(&figure, 0, left - gap, left), 0);
    }
    /* The band's first rows (the padding above the text) are the dark background. */
    const unsigned char *corner = pixel_at(&figure, 0, 100);
    assert_true(corner[0] < 64 && corner[1] < 64 && corner[2] < 64);
    stbi_image_free(figure.rgb);
}

/* Long captions on two 200 x 50 panels: lit pixels of the first band inside its panel,
 * none in the gap; returns the band's height. */
static int band_of_long_caption(const char *caption)
{
    const char *captions[] = {caption, "b"};
    Decoded figure = figure_of(2, 200, 50, captions, 1.0);
    assert_int_equal(figure.width, 2 * 200 + 8); /* the gap keeps the nominal scale */
    assert_true(lit_in(&figure, 50, 1, 199) > 0);
    assert_int_equal(lit_in(&figure, 50, 200, 208), 0);
    stbi_image_free(figure.rgb);
    return figure.height - 50;
}

/* A caption too long for one line wraps at spaces and keeps its scale: the band is
 * 2 (12 L + 4) pixels high for several lines L. */
static void test_long_caption_wraps(void **state)
{
    (void)state;
    int band = band_of_long_caption("one two three four five six seven eight nine ten eleven");
    assert_int_equal(band % 2, 0);
    assert_int_equal((band / 2 - 4) % 12, 0);
    assert_true((band / 2 - 4) / 12 >= 3);
}

/* A word too long for a line at scale 2 but not at scale 1 shrinks the text instead of
 * breaking the word: one line at scale 1, a band of 12 + 4 pixels. */
static void test_long_word_shrinks_text(void **state)
{
    (void)state;
    assert_int_equal(band_of_long_caption("supersampling_with_jitter"), 16);
}

/* On tiny panels even scale 1 is too wide for a word: it breaks between letters, over
 * several lines, and still stays inside its panel. Characters the font lacks (control
 * and non-ASCII bytes) and a NULL caption are drawn safely. */
static void test_tiny_panels_break_words(void **state)
{
    (void)state;
    const char *captions[] = {"unbreakable_word", "tab\there \x01\x7f\xff", NULL};
    Decoded figure = figure_of(3, 20, 20, captions, 1.0);
    assert_int_equal(figure.width, 3 * 20 + 2 * 4);
    assert_true(figure.height - 20 >= 12 * 4 + 4); /* 16 letters of ~6 px at <= 3 a line */
    assert_true(lit_in(&figure, 20, 0, 20) > 0);
    assert_true(lit_in(&figure, 20, 24, 44) > 0);
    assert_int_equal(lit_in(&figure, 20, 20, 24), 0);
    assert_int_equal(lit_in(&figure, 20, 44, 48), 0);
    assert_int_equal(lit_in(&figure, 20, 48, 68), 0);
    stbi_image_free(figure.rgb);

    /* Panels 4 pixels wide are narrower than one letter: the letter is cut at the
     * panel's edges, and the 4-pixel gaps stay dark. */
    const char *wide_letters[] = {"MW", "MW"};
    figure = figure_of(2, 4, 4, wide_letters, 1.0);
    assert_true(lit_in(&figure, 4, 0, 4) > 0);
    assert_int_equal(lit_in(&figure, 4, 4, 8), 0);
    assert_true(lit_in(&figure, 4, 8, 12) > 0);
    stbi_image_free(figure.rgb);
}

/* Panels of different sizes, none at all, or one without pixels: EINVAL, no file. */
static void test_refuses_mismatched_panels(void **state)
{
    (void)state;
    const char *captions[] = {"a", "b"};
    Image panels[2] = {image_new(20, 10), image_new(10, 20)};
    char path[160];
    snprintf(path, sizeof path, "%s/refused.png", figure_dir);
    errno = 0;
    assert_int_equal(figure_write_png(path, panels, captions, 2, 1.0), -1);
    assert_int_equal(errno, EINVAL);
    errno = 0;
    assert_int_equal(figure_write_png(path, panels, captions, 0, 1.0), -1);
    assert_int_equal(errno, EINVAL);
    image_free(&panels[1]);
    errno = 0;
    assert_int_equal(figure_write_png(path, panels, captions, 2, 1.0), -1);
    assert_int_equal(errno, EINVAL);
    struct stat info;
    assert_int_equal(stat(path, &info), -1);
    image_free(&panels[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dimensions),
        cmocka_unit_test(test_panels_are_tone_mapped),
        cmocka_unit_test(test_captions_are_drawn_in_their_band),
        cmocka_unit_test(test_long_caption_wraps),
        cmocka_unit_test(test_long_word_shrinks_text),
        cmocka_unit_test(test_tiny_panels_break_words),
        cmocka_unit_test(test_refuses_mismatched_panels),
    };
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
