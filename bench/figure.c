/* figure.c (bench, chapter 1): the side-by-side comparison figure with its captions. See
 * figure.h for the layout.
 *
 * The report's figures (section 4, Figures 8 to 12) set two renderings side by side
 * with a caption naming each one's settings; ours add what each setting cost (seconds)
 * and bought (error). Each caption is drawn into a linear image of its own (the band
 * under its panel) with font.h, then tone mapped beside the panels at exposure 1.
 */
#include "figure.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum {
    MIN_SIZE = 8,
    NOMINAL_MIN = 12,
    NOMINAL_MAX = 24
};

/* Linear radiance of the caption band and of its text: sRGB codes 40 and 241. */
static const Vec3 BACKGROUND = {0.0212, 0.0212, 0.0212}, TEXT = {0.88, 0.88, 0.88};

/* The text grows with the panel: W / 50 pixels per em, from 12 to 24. */
static int nominal_size(int panel_width)
{
    long size = lround(panel_width / 50.0);
    return size < NOMINAL_MIN ? NOMINAL_MIN : size > NOMINAL_MAX ? NOMINAL_MAX : (int)size;
}

/* Where the UTF-8 character after text[i] starts (continuation bytes are 10xxxxxx). */
static size_t next_character(const char *text, size_t i, size_t length)
{
    do
        i++;
    while (i < length && ((unsigned char)text[i] & 0xC0) == 0x80);
    return i;
}

/* Copies `caption` into `out` (room for 2 strlen(caption) + 1 characters) with '\n'
 * inserted so that no line is wider than `width` pixels: a word moves to the next line
 * when it does not fit (runs of spaces become one). A word wider than a whole line is
 * broken between characters when break_words is set; otherwise the answer is -1.
 * Returns the number of lines. */
static int wrap_caption(const Font *font, const char *caption, int size, double width,
                        int break_words, char *out)
{
    int lines = 1;
    double used = 0.0; /* pixels used on the current line */
    size_t n = 0;
    const double space = font_width(font, " ", 1, size);
    for (const char *p = caption; *p;) {
        if (*p == ' ' || *p == '\n') {
            if (*p == '\n') {
                out[n++] = '\n';
                lines++;
                used = 0.0;
            }
            p++;
            continue;
        }
        size_t length = strcspn(p, " \n");
        double word = font_width(font, p, length, size);
        if (used > 0.0 && used + space + word > width) {
            out[n++] = '\n';
            lines++;
            used = 0.0;
        } else if (used > 0.0) {
            out[n++] = ' ';
            used += space;
        }
        if (used == 0.0 && word > width && !break_words)
            return -1;
        for (size_t i = 0, next; i < length; i = next) {
            next = next_character(p, i, length);
            double advance = font_width(font, p + i, next - i, size);
            if (used > 0.0 && used + advance > width) {
                out[n++] = '\n';
                lines++;
                used = 0.0;
            }
            memcpy(out + n, p + i, next - i);
            n += next - i;
            used += advance;
        }
        p += length;
    }
    out[n] = '\0';
    return lines;
}

/* Each line of a wrapped caption centred in the band, the first line's top `margin`
 * pixels down, lines `pitch` apart. */
static void draw_caption(Image *band, const Font *font, const char *wrapped, int size,
                         int margin, int pitch)
{
    double baseline = margin + font_ascent(font, size);
    for (const char *line = wrapped;; line++, baseline += pitch) {
        size_t length = strcspn(line, "\n");
        double x = 0.5 * (band->width - font_width(font, line, length, size));
        font_draw(band, font, line, length, x, baseline, size, TEXT);
        line += length;
        if (*line == '\0')
            return;
    }
}

/* The largest text size, from the nominal one down, at which every caption fits its
 * panel by wrapping at spaces (at MIN_SIZE words may break too); *lines is then the
 * most lines of any caption. `scratch` has room for any caption's wrapped copy. */
static int choose_size(const Font *font, const char *const *captions, int count,
                       double line_width, int nominal, char *scratch, int *lines)
{
    for (int size = nominal;; size--) {
        int most = 1, fits = 1;
        for (int i = 0; i < count && fits; i++) {
            int n = wrap_caption(font, captions[i] ? captions[i] : "", size, line_width,
                                 size <= MIN_SIZE, scratch);
            fits = n > 0;
            most = n > most ? n : most;
        }
        if (fits) {
            *lines = most;
            return size;
        }
    }
}

static int panels_match(const Image *panels, int count)
{
    for (int i = 0; i < count; i++)
        if (!panels[i].pixels || panels[i].width != panels[0].width ||
            panels[i].height != panels[0].height)
            return 0;
    return 1;
}

/* The caption band of panel i, tone mapped into the picture under it. */
static void draw_band(Image *band, const Font *font, const char *caption, int size, int margin,
                      int pitch, char *scratch, uint8_t *rgb, long stride)
{
    for (int row = 0; row < band->height; row++)
        for (int col = 0; col < band->width; col++)
            image_set(band, col, row, BACKGROUND);
    wrap_caption(font, caption ? caption : "", size, band->width - 2 * margin, size <= MIN_SIZE,
                 scratch);
    draw_caption(band, font, scratch, size, margin, pitch);
    image_tonemap_rgb8(band, 1.0, rgb, stride);
}

int figure_write_png(const char *path, const Font *font, const Image *panels,
                     const char *const *captions, int panel_count, double exposure)
{
    if (panel_count < 1 || !panels_match(panels, panel_count)) {
        errno = EINVAL;
        return -1;
    }
    size_t longest = 0;
    for (int i = 0; i < panel_count; i++)
        if (captions[i] && strlen(captions[i]) > longest)
            longest = strlen(captions[i]);
    char *scratch = malloc(2 * longest + 1);
    if (!scratch) {
        errno = ENOMEM;
        return -1;
    }
    int panel_width = panels[0].width, panel_height = panels[0].height, lines;
    int nominal = nominal_size(panel_width), margin = nominal / 2, gap = nominal / 2;
    int size = choose_size(font, captions, panel_count, panel_width - 2 * margin, nominal,
                           scratch, &lines);
    int pitch = (int)ceil(font_line_height(font, size));
    long long width = (long long)panel_count * (panel_width + gap) - gap;
    long long band_height = (long long)lines * pitch + 2 * margin;
    long long height = panel_height + band_height;
    if (width > INT_MAX / 3 || height > INT_MAX / 3 ||
        (unsigned long long)width * height > SIZE_MAX / 3) {
        free(scratch);
        errno = EINVAL;
        return -1;
    }
    Image band = image_new(panel_width, (int)band_height);
    uint8_t *rgb = malloc(3 * (size_t)width * (size_t)height);
    if (!band.pixels || !rgb) {
        free(rgb);
        image_free(&band);
        free(scratch);
        errno = ENOMEM;
        return -1;
    }
    const uint8_t background[3] = {image_tonemap(BACKGROUND.x, 1.0),
                                   image_tonemap(BACKGROUND.y, 1.0),
                                   image_tonemap(BACKGROUND.z, 1.0)};
    for (long long i = 0; i < width * height; i++)
        memcpy(rgb + 3 * i, background, 3);
    for (int i = 0; i < panel_count; i++) {
        uint8_t *column = rgb + 3 * (long)i * (panel_width + gap);
        image_tonemap_rgb8(&panels[i], exposure, column, 3 * width);
        draw_band(&band, font, captions[i], size, margin, pitch, scratch,
                  column + 3 * width * panel_height, 3 * width);
    }
    int status = image_write_rgb8_png(rgb, (int)width, (int)height, path);
    int saved_errno = errno;
    free(rgb);
    image_free(&band);
    free(scratch);
    errno = saved_errno;
    return status;
}
