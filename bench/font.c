/* font.c (bench, chapter 1): anti-aliased TrueType text blended into an image. See font.h.
 *
 * Each glyph is rasterised by stb_truetype at the pen's sub-pixel position (so letters
 * are spaced as the font designs them, not rounded to whole pixels) into a small
 * coverage bitmap, then blended into the image pixel by pixel.
 */
#include "font.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum {
    MAX_FONT_BYTES = 64 << 20,
    GLYPH_SIDE = 160 /* coverage bitmap per glyph; larger glyphs are cut off */
};

static int fail(char *error, int error_size, const char *path, const char *why)
{
    snprintf(error, (size_t)error_size,
             "cannot read the font %s: %s (the figures' font comes with Debian's %s: "
             "sudo apt-get install %s)",
             path, why, FONT_PACKAGE, FONT_PACKAGE);
    return -1;
}

/* The whole file in a malloc'ed buffer, or NULL with errno set. */
static unsigned char *read_file(const char *path, long *size)
{
    FILE *file = fopen(path, "rb");
    if (!file)
        return NULL;
    unsigned char *data = NULL;
    if (fseek(file, 0, SEEK_END) == 0 && (*size = ftell(file)) > 0 && *size <= MAX_FONT_BYTES &&
        fseek(file, 0, SEEK_SET) == 0) {
        data = malloc((size_t)*size);
        if (data && fread(data, 1, (size_t)*size, file) != (size_t)*size) {
            free(data);
            data = NULL;
            errno = EIO;
        }
    } else {
        errno = EINVAL;
    }
    fclose(file);
    return data;
}

int font_load(Font *font, const char *path, char *error, int error_size)
{
    memset(font, 0, sizeof *font);
    long size = 0;
    errno = 0;
    unsigned char *data = read_file(path, &size);
    if (!data)
        return fail(error, error_size, path, errno ? strerror(errno) : "empty file");
    /* stb_truetype trusts its input: accept only files that start like a TrueType
     * (version 1.0 or "true") or OpenType ("OTTO") font. */
    int offset = stbtt_GetFontOffsetForIndex(data, 0);
    if (size < 12 ||
        (memcmp(data, "\0\1\0\0", 4) != 0 && memcmp(data, "true", 4) != 0 &&
         memcmp(data, "OTTO", 4) != 0) ||
        offset < 0 || !stbtt_InitFont(&font->info, data, offset)) {
        free(data);
        memset(font, 0, sizeof *font);
        return fail(error, error_size, path, "not a TrueType font");
    }
    font->data = data;
    return 0;
}

void font_free(Font *font)
{
    free(font->data);
    memset(font, 0, sizeof *font);
}

static double scale_for(const Font *font, double size)
{
    return stbtt_ScaleForMappingEmToPixels(&font->info, (float)size);
}

double font_line_height(const Font *font, double size)
{
    int ascent, descent, line_gap;
    stbtt_GetFontVMetrics(&font->info, &ascent, &descent, &line_gap);
    return (ascent - descent + line_gap) * scale_for(font, size);
}

double font_ascent(const Font *font, double size)
{
    int ascent, descent, line_gap;
    stbtt_GetFontVMetrics(&font->info, &ascent, &descent, &line_gap);
    return ascent * scale_for(font, size);
}

/* The character starting text[0] as a Unicode code point, its bytes in *used: a valid
 * UTF-8 sequence (shortest form, at most U+10FFFF, no surrogate), else -1 and 1 byte. */
static long next_code_point(const unsigned char *text, size_t length, size_t *used)
{
    static const long smallest[5] = {0, 0, 0x80, 0x800, 0x10000};
    unsigned char lead = text[0];
    size_t n = lead < 0x80             ? 1
               : (lead & 0xE0) == 0xC0 ? 2
               : (lead & 0xF0) == 0xE0 ? 3
               : (lead & 0xF8) == 0xF0 ? 4
                                       : 0;
    *used = 1;
    if (n == 0 || n > length)
        return -1;
    long code = n == 1 ? lead : lead & (0x7F >> n);
    for (size_t i = 1; i < n; i++) {
        if ((text[i] & 0xC0) != 0x80)
            return -1;
        code = code << 6 | (text[i] & 0x3F);
    }
    if (code < smallest[n] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
        return -1;
    *used = n;
    return code;
}

/* The glyph that draws the character at text[0], or '?''s glyph (see font.h). */
static int next_glyph(const Font *font, const char *text, size_t length, size_t *used)
{
    long code = next_code_point((const unsigned char *)text, length, used);
    int control = code < 0x20 || (code >= 0x7F && code < 0xA0);
    int glyph = control ? 0 : stbtt_FindGlyphIndex(&font->info, (int)code);
    return glyph ? glyph : stbtt_FindGlyphIndex(&font->info, '?');
}

/* Calls `visit` for each glyph of the text with its pen position (pixels from the
 * text's start) and returns the total advance. */
typedef void (*GlyphVisit)(const Font *font, int glyph, double pen, void *context);

static double walk_glyphs(const Font *font, const char *text, size_t length, double size,
                          GlyphVisit visit, void *context)
{
    double scale = scale_for(font, size), pen = 0.0;
    size_t used;
    for (size_t i = 0; i < length; i += used) {
        int glyph = next_glyph(font, text + i, length - i, &used);
        if (visit)
            visit(font, glyph, pen, context);
        int advance, left_bearing;
        stbtt_GetGlyphHMetrics(&font->info, glyph, &advance, &left_bearing);
        pen += advance * scale;
        if (i + used < length) {
            size_t next_used;
            int next = next_glyph(font, text + i + used, length - i - used, &next_used);
            pen += stbtt_GetGlyphKernAdvance(&font->info, glyph, next) * scale;
        }
    }
    return pen;
}

double font_width(const Font *font, const char *text, size_t length, double size)
{
    return walk_glyphs(font, text, length, size, NULL, NULL);
}

typedef struct {
    Image *image;
    double x, baseline, scale;
    Vec3 colour;
} DrawContext;

/* Blends the glyph into the image by the coverage of each of its pixels. */
static void draw_glyph(const Font *font, int glyph, double pen, void *context)
{
    DrawContext *draw = context;
    float scale = (float)draw->scale;
    double x = draw->x + pen;
    int left = (int)floor(x), top = (int)floor(draw->baseline);
    float shift_x = (float)(x - left), shift_y = (float)(draw->baseline - top);
    int x0, y0, x1, y1;
    stbtt_GetGlyphBitmapBoxSubpixel(&font->info, glyph, scale, scale, shift_x, shift_y, &x0,
                                    &y0, &x1, &y1);
    int width = x1 - x0 < GLYPH_SIDE ? x1 - x0 : GLYPH_SIDE;
    int height = y1 - y0 < GLYPH_SIDE ? y1 - y0 : GLYPH_SIDE;
    Image *image = draw->image;
    if (width <= 0 || height <= 0 || left + x1 <= 0 || top + y1 <= 0 ||
        left + x0 >= image->width || top + y0 >= image->height)
        return;
    unsigned char coverage[GLYPH_SIDE * GLYPH_SIDE];
    stbtt_MakeGlyphBitmapSubpixel(&font->info, coverage, width, height, width, scale, scale,
                                  shift_x, shift_y, glyph);
    for (int row = 0; row < height; row++) {
        int y = top + y0 + row;
        for (int col = 0; col < width && y >= 0 && y < image->height; col++) {
            int px = left + x0 + col;
            double a = coverage[row * width + col] / 255.0;
            if (px < 0 || px >= image->width || a == 0.0)
                continue;
            font_blend(image, px, y, draw->colour, a);
        }
    }
}

void font_draw(Image *image, const Font *font, const char *text, size_t length, double x,
               double baseline, double size, Vec3 colour)
{
    DrawContext context = {image, x, baseline, scale_for(font, size), colour};
    walk_glyphs(font, text, length, size, draw_glyph, &context);
}
