/* figure.c (chapter 1): the side-by-side comparison figure with its captions. See
 * figure.h for the layout.
 *
 * The report's figures (section 4, Figures 8 to 12) set two renderings side by side
 * with a caption naming each one's settings; ours add what each setting cost (seconds)
 * and bought (error). The captions are drawn with stb_easy_font, a bitmap font whose
 * glyphs come as axis-aligned quads in font units; each unit becomes a square of
 * `scale` x `scale` pixels.
 */
#include "figure.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <stb_easy_font.h>

enum {
    MAX_SCALE = 4,   /* the text scale is sqrt(panel width / 50), from 1 to 4 */
    GAP_UNITS = 4,   /* between panels, in units of that scale */
    LINE_UNITS = 12, /* the font's line pitch */
    PAD_UNITS = 4,   /* above the first line (below the last, its pitch leaves room) */
    MAX_GLYPH_QUADS = 64
};

static const uint8_t BACKGROUND[3] = {40, 40, 40}, TEXT[3] = {240, 240, 240};

/* One vertex of stb_easy_font's output: position (z unused) and a colour we ignore. */
typedef struct {
    float x, y, z;
    unsigned char color[4];
} FontVertex;

typedef struct {
    uint8_t *rgb; /* rows 3 * width bytes apart */
    int width;
} Picture;

typedef struct {
    int left, top, right, bottom; /* right and bottom exclusive */
} Box;

/* The text grows with the panel, but more slowly, so that small panels still get
 * readable captions and large ones room for longer lines. */
static int nominal_scale(int panel_width)
{
    long scale = lround(sqrt(panel_width / 50.0));
    return scale < 1 ? 1 : scale > MAX_SCALE ? MAX_SCALE : (int)scale;
}

/* The font covers printable ASCII; anything else is drawn as '?'. */
static char printable(char c)
{
    return c >= ' ' && c <= '~' ? c : '?';
}

/* A character's advance in pixels. The font leaves one unit between letters; scaled up,
 * one pixel of it is enough, so each letter is one pixel narrower than scale x advance. */
static int advance_pixels(char c, int scale)
{
    char text[2] = {printable(c), '\0'};
    return scale * stb_easy_font_width(text) - (scale > 1);
}

static int text_pixels(const char *text, size_t length, int scale)
{
    int width = 0;
    for (size_t i = 0; i < length; i++)
        width += advance_pixels(text[i], scale);
    return width;
}

/* Copies `caption` into `out` (room for 2 strlen(caption) + 1 characters) with '\n'
 * inserted so that no line is wider than `width` pixels: a word moves to the next line
 * when it does not fit (runs of spaces become one). A word wider than a whole line is
 * broken between letters when break_words is set; otherwise the answer is -1. Returns
 * the number of lines. */
static int wrap_caption(const char *caption, int scale, int width, int break_words, char *out)
{
    int lines = 1, used = 0; /* pixels used on the current line */
    size_t n = 0;
    const int space = advance_pixels(' ', scale);
    for (const char *p = caption; *p;) {
        if (*p == ' ' || *p == '\n') {
            if (*p == '\n') {
                out[n++] = '\n';
                lines++;
                used = 0;
            }
            p++;
            continue;
        }
        size_t length = strcspn(p, " \n");
        int word = text_pixels(p, length, scale);
        if (used > 0 && used + space + word > width) {
            out[n++] = '\n';
            lines++;
            used = 0;
        } else if (used > 0) {
            out[n++] = ' ';
            used += space;
        }
        if (used == 0 && word > width && !break_words)
            return -1;
        for (size_t i = 0; i < length; i++) {
            int advance = advance_pixels(p[i], scale);
            if (used > 0 && used + advance > width) {
                out[n++] = '\n';
                lines++;
                used = 0;
            }
            out[n++] = printable(p[i]);
            used += advance;
        }
        p += length;
    }
    out[n] = '\0';
    return lines;
}

static void fill_box(Picture *picture, Box box, Box clip, const uint8_t color[3])
{
    int left = box.left > clip.left ? box.left : clip.left;
    int right = box.right < clip.right ? box.right : clip.right;
    int top = box.top > clip.top ? box.top : clip.top;
    int bottom = box.bottom < clip.bottom ? box.bottom : clip.bottom;
    for (int y = top; y < bottom; y++)
        for (int x = left; x < right; x++)
            memcpy(picture->rgb + 3 * ((long)y * picture->width + x), color, 3);
}

/* Each quad is an axis-aligned rectangle; its vertices 0 and 2 are opposite corners. */
static void draw_glyph(Picture *picture, char c, int x, int y, int scale, Box clip)
{
    FontVertex quads[4 * MAX_GLYPH_QUADS];
    char text[2] = {printable(c), '\0'};
    int count = stb_easy_font_print(0, 0, text, NULL, quads, (int)sizeof quads);
    for (int q = 0; q < count; q++) {
        const FontVertex *corner = &quads[4 * q], *opposite = &quads[4 * q + 2];
        Box box = {x + scale * (int)corner->x, y + scale * (int)corner->y,
                   x + scale * (int)opposite->x, y + scale * (int)opposite->y};
        fill_box(picture, box, clip, TEXT);
    }
}

/* Each line of a wrapped caption centred in `cell`, nothing drawn outside it. */
static void draw_caption(Picture *picture, const char *wrapped, int scale, Box cell)
{
    int y = cell.top + scale * PAD_UNITS;
    for (const char *line = wrapped;; line++, y += scale * LINE_UNITS) {
        size_t length = strcspn(line, "\n");
        int x = cell.left + (cell.right - cell.left - text_pixels(line, length, scale)) / 2;
        for (size_t i = 0; i < length; i++) {
            draw_glyph(picture, line[i], x, y, scale, cell);
            x += advance_pixels(line[i], scale);
        }
        line += length;
        if (*line == '\0')
            return;
    }
}

/* The largest text scale, from the nominal one down, at which every caption fits its
 * panel by wrapping at spaces (at scale 1 words may break too); *lines is then the most
 * lines of any caption. `scratch` has room for any caption's wrapped copy. */
static int choose_scale(const char *const *captions, int count, int panel_width,
                        char *scratch, int *lines)
{
    for (int scale = nominal_scale(panel_width);; scale--) {
        int width = panel_width - 2 * scale, most = 1, fits = 1;
        for (int i = 0; i < count && fits; i++) {
            int n = wrap_caption(captions[i] ? captions[i] : "", scale, width, scale == 1,
                                 scratch);
            fits = n > 0;
            most = n > most ? n : most;
        }
        if (fits) {
            *lines = most;
            return scale;
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

int figure_write_png(const char *path, const Image *panels, const char *const *captions,
                     int panel_count, double exposure)
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
    int scale = choose_scale(captions, panel_count, panel_width, scratch, &lines);
    int gap = GAP_UNITS * nominal_scale(panel_width);
    long long width = (long long)panel_count * (panel_width + gap) - gap;
    long long height = panel_height + (long long)scale * (LINE_UNITS * lines + PAD_UNITS);
    if (width > INT_MAX / 3 || height > INT_MAX / 3 ||
        (unsigned long long)width * height > SIZE_MAX / 3) {
        free(scratch);
        errno = EINVAL;
        return -1;
    }
    Picture picture = {malloc(3 * (size_t)width * (size_t)height), (int)width};
    if (!picture.rgb) {
        free(scratch);
        errno = ENOMEM;
        return -1;
    }
    Box whole = {0, 0, (int)width, (int)height};
    fill_box(&picture, whole, whole, BACKGROUND);
    for (int i = 0; i < panel_count; i++) {
        int left = i * (panel_width + gap);
        image_tonemap_rgb8(&panels[i], exposure, picture.rgb + 3 * left, 3 * width);
        wrap_caption(captions[i] ? captions[i] : "", scale, panel_width - 2 * scale, scale == 1,
                     scratch);
        Box cell = {left, panel_height, left + panel_width, (int)height};
        draw_caption(&picture, scratch, scale, cell);
    }
    int status = image_write_rgb8_png(picture.rgb, (int)width, (int)height, path);
    int saved_errno = errno;
    free(picture.rgb);
    free(scratch);
    errno = saved_errno;
    return status;
}
