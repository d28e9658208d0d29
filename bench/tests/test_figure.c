/* test_figure.c (bench, chapter 1): the side-by-side comparison figure (figure.h, chapter 1).
 *
 * Each figure is written, decoded again with stb_image, and checked against the layout
 * figure.h documents: its size for 1, 2 and 3 panels and for each text size, panels
 * that are exactly the tone-mapped images, captions that are really drawn (lit pixels
 * in each band), centred, growing with the panel and never outside their panel,
 * wrapping and shrinking of long captions, and refusal of panels that do not match.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb_image.h>

#include "assert_close.h"
#include "figure.h"
#include "font_fixture.h"

static char figure_dir[64], figure_path[128];

static int make_dir(void **state)
{
    if (load_font(state) != 0)
        return -1;
    strcpy(figure_dir, "/tmp/test_figure_XXXXXX");
    if (!mkdtemp(figure_dir))
        return -1;
    snprintf(figure_path, sizeof figure_path, "%s/figure.png", figure_dir);
    return 0;
}

static int remove_dir(void **state)
{
    free_font(state);
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
    assert_int_equal(figure_write_png(figure_path, &font, panels, captions, count, exposure),
                     0);
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

/* The layout's numbers as figure.h gives them, for panels `width` wide: the nominal
 * text size, the gap and margin, and the line pitch at text size `size`. */
static int nominal_size(int width)
{
    int size = (int)lround(width / 50.0);
    return size < 12 ? 12 : size > 24 ? 24 : size;
}

static int pitch_at(int size) { return (int)ceil(font_line_height(&font, size)); }

/* The documented size: n W + (n - 1) (s / 2) wide, H + L p + 2 (s / 2) high, with
 * s = W / 50 rounded and clamped to [12, 24]; here for 1, 2 and 3 panels at sizes either
 * side of where s changes and where it is clamped, for captions of one and two lines
 * (short enough never to wrap). Worked by hand: s is 12 up to 624, 13 from 625, 16 at
 * 800, 24 from 1175 up. */
static void test_dimensions(void **state)
{
    const struct {
        int width, size;
    } sizes[] = {{64, 12},  {200, 12},  {624, 12},  {625, 13},
                 {800, 16}, {1174, 23}, {1175, 24}, {1600, 24}};
    const char *one_line[] = {"a", "b", "c"}, *two_lines[] = {"a\nb", "c", "d"};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        assert_int_equal(nominal_size(sizes[s].width), sizes[s].size);
        for (int count = 1; count <= 3; count++)
            for (int lines = 1; lines <= 2; lines++) {
                Decoded figure = figure_of(count, sizes[s].width, 10,
                                           lines == 1 ? one_line : two_lines, 1.0);
                int size = sizes[s].size, half = size / 2;
                assert_int_equal(figure.width, count * sizes[s].width + (count - 1) * half);
                assert_int_equal(figure.height, 10 + lines * pitch_at(size) + 2 * half);
                stbi_image_free(figure.rgb);
            }
    }
}

/* Every pixel of every panel is the tone map (with the figure's exposure) of that
 * panel's radiance, at the documented place. */
static void test_panels_are_tone_mapped(void **state)
{
    const char *captions[] = {"left", "middle", "right"};
    const double exposure = 1.7;
    Decoded figure = figure_of(3, 200, 150, captions, exposure);
    for (int i = 0; i < 3; i++)
        for (int row = 0; row < 150; row++)
            for (int col = 0; col < 200; col++) {
                const unsigned char *p = pixel_at(&figure, i * (200 + 6) + col, row);
                Vec3 radiance = panel_radiance(i, col, row, 200, 150);
                assert_int_equal(p[0], image_tonemap((float)radiance.x, exposure));
                assert_int_equal(p[1], image_tonemap((float)radiance.y, exposure));
                assert_int_equal(p[2], image_tonemap((float)radiance.z, exposure));
            }
    stbi_image_free(figure.rgb);
}

/* The lit columns and rows of the band under panel i: their bounding box. */
typedef struct {
    int count, left, right, top, bottom; /* inclusive */
} Ink;

static Ink ink_under(const Decoded *figure, int top, int left, int right)
{
    Ink ink = {0, INT_MAX, -1, INT_MAX, -1};
    for (int y = top; y < figure->height; y++)
        for (int x = left; x < right; x++)
            if (lit(figure, x, y)) {
                ink.count++;
                ink.left = x < ink.left ? x : ink.left;
                ink.right = x > ink.right ? x : ink.right;
                ink.top = y < ink.top ? y : ink.top;
                ink.bottom = y > ink.bottom ? y : ink.bottom;
            }
    return ink;
}

/* Each caption band holds text (lit pixels) inside its own panel's columns, kept the
 * margin (6 pixels at size 12) from the sides (a pixel of slack for glyphs that reach
 * past their advance), centred under its panel; the gaps between panels and the band's
 * top margin are dark. The realistic captions of a chapter figure are used. */
static void test_captions_are_drawn_in_their_band(void **state)
{
    const char *captions[] = {"1 spp, sub-pixels\n0.21 s, RMSE 0.031",
                              "4 spp, random\n0.83 s, RMSE 0.016", ""};
    Decoded figure = figure_of(3, 200, 100, captions, 1.0);
    const int margin = 6, gap = 6;
    for (int i = 0; i < 3; i++) {
        int left = i * (200 + gap);
        Ink ink = ink_under(&figure, 100, left, left + 200);
        if (i < 2) {
            assert_true(ink.count > 150); /* some 30 letters */
            assert_true(ink.left >= left + margin - 1 && ink.right <= left + 200 - margin);
            assert_close(0.5 * (ink.left + ink.right), left + 100, 3.0);
            assert_true(ink.top >= 100 + margin); /* two lines below the margin */
            assert_true(ink.bottom - ink.top > pitch_at(12));
        } else {
            assert_int_equal(ink.count, 0); /* an empty caption draws nothing */
        }
        if (i > 0)
            assert_int_equal(lit_in(&figure, 0, left - gap, left), 0);
    }
    /* The band's first rows (the margin above the text) are the dark background. */
    const unsigned char *corner = pixel_at(&figure, 0, 100);
    assert_true(corner[0] < 64 && corner[1] < 64 && corner[2] < 64);
    stbi_image_free(figure.rgb);
}

/* Anti-aliased text: the band holds grey levels between the background and the text,
 * not only the two. */
static void test_captions_are_anti_aliased(void **state)
{
    const char *captions[] = {"Figure 9, right: 4 spp, RMSE 0.4017"};
    Decoded figure = figure_of(1, 400, 20, captions, 1.0);
    int levels[256] = {0}, distinct = 0;
    for (int y = 20; y < figure.height; y++)
        for (int x = 0; x < figure.width; x++)
            levels[pixel_at(&figure, x, y)[0]]++;
    for (int v = 64; v < 224; v++)
        distinct += levels[v] > 0;
    assert_true(distinct > 40);
    stbi_image_free(figure.rgb);
}

/* The text grows with the panel: the ink of one line of capitals is taller under an
 * 800-pixel panel (16 pixels per em, capitals about 12 high) than under a 200-pixel
 * one (12 per em, about 9). */
static void test_text_grows_with_the_panel(void **state)
{
    const char *captions[] = {"EHT"};
    Decoded small = figure_of(1, 200, 10, captions, 1.0);
    Decoded large = figure_of(1, 800, 10, captions, 1.0);
    Ink small_ink = ink_under(&small, 10, 0, 200), large_ink = ink_under(&large, 10, 0, 800);
    int small_height = small_ink.bottom - small_ink.top + 1;
    int large_height = large_ink.bottom - large_ink.top + 1;
    assert_true(small_height >= 8 && small_height <= 10);
    assert_true(large_height >= 11 && large_height <= 13);
    stbi_image_free(small.rgb);
    stbi_image_free(large.rgb);
}

/* Long captions on two 200 x 50 panels: lit pixels of the first band inside its panel,
 * none in the gap; returns the band's height. */
static int band_of_long_caption(const char *caption)
{
    const char *captions[] = {caption, "b"};
    Decoded figure = figure_of(2, 200, 50, captions, 1.0);
    assert_int_equal(figure.width, 2 * 200 + 6); /* the gap keeps the nominal size */
    assert_true(lit_in(&figure, 50, 5, 195) > 0);
    assert_int_equal(lit_in(&figure, 50, 0, 5), 0);
    assert_int_equal(lit_in(&figure, 50, 195, 206), 0);
    stbi_image_free(figure.rgb);
    return figure.height - 50;
}

/* The lines a greedy wrap at spaces gives `caption` (single spaces between words) in
 * lines `width` pixels wide at `size`: a word goes on the line if it fits after a
 * space. */
static int lines_wrapped_at_spaces(const char *caption, double width, int size)
{
    int lines = 1;
    double used = 0.0, space = font_width(&font, " ", 1, size);
    for (const char *p = caption; *p;) {
        size_t length = strcspn(p, " ");
        double word = font_width(&font, p, length, size);
        if (used > 0.0 && used + space + word > width) {
            lines++;
            used = word;
        } else {
            used += (used > 0.0 ? space : 0.0) + word;
        }
        p += length + (p[length] == ' ');
    }
    return lines;
}

/* A caption too long for one line wraps at spaces, never inside a word, and keeps its
 * size: the band is L p + 12 pixels high, L the lines of a wrap at spaces into lines of
 * 200 - 2 * 6 pixels (4 here; breaking inside words would pack them into 3). */
static void test_long_caption_wraps(void **state)
{
    const char *caption = "rendered_with_jitter shadow_rays_thirty russian_roulette_alpha "
                          "seconds_and_error";
    int lines = lines_wrapped_at_spaces(caption, 188, 12);
    assert_int_equal(lines, 4);
    int band = band_of_long_caption(caption);
    assert_int_equal(band, lines * pitch_at(12) + 12);
}

/* A word too long for a line at size 12 but not at a smaller size shrinks the text
 * instead of breaking the word: one line at a smaller size. */
static void test_long_word_shrinks_text(void **state)
{
    int band = band_of_long_caption("supersampling_with_jittered_positions");
    assert_true(band - 12 < pitch_at(12));
    assert_true(band - 12 >= pitch_at(8));
}

/* On tiny panels even size 8 is too wide for a word: it breaks between characters,
 * over several lines, and still stays inside its panel. Characters the font lacks
 * (control and non-ASCII bytes) and a NULL caption are drawn safely; a multi-byte
 * character is never split. */
static void test_tiny_panels_break_words(void **state)
{
    const char *captions[] = {"unbreakable_word",
                              "tab\there \x01\x7f\xff \xce\xb1\xce\xb1\xce\xb1", NULL};
    Decoded figure = figure_of(3, 20, 20, captions, 1.0);
    assert_int_equal(figure.width, 3 * 20 + 2 * 6);
    assert_true(figure.height - 20 >= 4 * pitch_at(8) + 12); /* 16 letters, <= 3 a line */
    assert_true(lit_in(&figure, 20, 0, 20) > 0);
    assert_true(lit_in(&figure, 20, 26, 46) > 0);
    assert_int_equal(lit_in(&figure, 20, 20, 26), 0);
    assert_int_equal(lit_in(&figure, 20, 46, 52), 0);
    assert_int_equal(lit_in(&figure, 20, 52, 72), 0);
    stbi_image_free(figure.rgb);

    /* Panels 4 pixels wide are narrower than one letter: the letter is cut at the
     * panel's edges, and the gaps stay dark. */
    const char *wide_letters[] = {"MW", "MW"};
    figure = figure_of(2, 4, 4, wide_letters, 1.0);
    assert_true(lit_in(&figure, 4, 0, 4) > 0);
    assert_int_equal(lit_in(&figure, 4, 4, 10), 0);
    assert_true(lit_in(&figure, 4, 10, 14) > 0);
    stbi_image_free(figure.rgb);
}

/* Panels of different sizes, none at all, or one without pixels: EINVAL, no file. */
static void test_refuses_mismatched_panels(void **state)
{
    const char *captions[] = {"a", "b"};
    Image panels[2] = {image_new(20, 10), image_new(10, 20)};
    char path[160];
    snprintf(path, sizeof path, "%s/refused.png", figure_dir);
    errno = 0;
    assert_int_equal(figure_write_png(path, &font, panels, captions, 2, 1.0), -1);
    assert_int_equal(errno, EINVAL);
    errno = 0;
    assert_int_equal(figure_write_png(path, &font, panels, captions, 0, 1.0), -1);
    assert_int_equal(errno, EINVAL);
    image_free(&panels[1]);
    errno = 0;
    assert_int_equal(figure_write_png(path, &font, panels, captions, 2, 1.0), -1);
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
        cmocka_unit_test(test_captions_are_anti_aliased),
        cmocka_unit_test(test_text_grows_with_the_panel),
        cmocka_unit_test(test_long_caption_wraps),
        cmocka_unit_test(test_long_word_shrinks_text),
        cmocka_unit_test(test_tiny_panels_break_words),
        cmocka_unit_test(test_refuses_mismatched_panels),
    };
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
