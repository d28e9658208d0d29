/* font.h (bench, chapter 1): anti-aliased text for the figures' captions and the plots.
 *
 * A presentation file, not part of the renderer: the figures show what each setting
 * cost and bought, and the text that says so must be readable on a projector. Glyphs
 * come from a TrueType font (DejaVu Sans, Debian's fonts-dejavu-core) rasterised by
 * stb_truetype, which gives each pixel the fraction a of it that the glyph's outline
 * covers. The text is blended into the linear image by that coverage:
 *     pixel = (1 - a) pixel + a colour.
 *
 * Sizes are in pixels per em (the font's design square, like a CSS font size): at 16
 * pixels DejaVu Sans' capitals are about 12 pixels tall and a line is about 19 pixels
 * (font_line_height). Text is UTF-8; a byte sequence that is not valid UTF-8, a
 * control character (a '\n' too: callers split lines) or a character the font lacks is
 * drawn as '?'.
 */
#ifndef FONT_H
#define FONT_H

#include <stddef.h>

#include <stb_truetype.h>

#include "image.h"

/* Where Debian's package puts the font; elsewhere build with -DFONT_PATH=... */
#ifndef FONT_PATH
#define FONT_PATH "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif
#define FONT_PACKAGE "fonts-dejavu-core"

/* A loaded font; the caller owns it and frees it with font_free. */
typedef struct {
    unsigned char *data; /* the whole font file, which info points into */
    stbtt_fontinfo info;
} Font;

/* Loads the TrueType font at `path` (FONT_PATH for the figures). Returns 0, or -1 with
 * "cannot ...: why" and the Debian package that ships the figures' font in
 * error[error_size]. */
int font_load(Font *font, const char *path, char *error, int error_size);
void font_free(Font *font);

/* pixel = (1 - a) pixel + a colour, the coverage blend (plot.c blends its lines so too);
 * (col, row) must be inside the image. */
static inline void font_blend(Image *image, int col, int row, Vec3 colour, double a)
{
    Vec3 old = image_get(image, col, row);
    image_set(image, col, row, vec3_add(vec3_scale(old, 1.0 - a), vec3_scale(colour, a)));
}

/* The distance from one baseline to the next, and from a line's top to its baseline,
 * in pixels, at `size` pixels per em. */
double font_line_height(const Font *font, double size);
double font_ascent(const Font *font, double size);

/* The advance width in pixels of the first `length` bytes of `text` (kerning
 * included): where the next character would start. */
double font_width(const Font *font, const char *text, size_t length, double size);

/* Draws the first `length` bytes of `text` with the left end of its baseline at
 * (x, baseline) (pixels, fractions allowed), blended by coverage; whatever falls
 * outside the image is cut off. */
void font_draw(Image *image, const Font *font, const char *text, size_t length, double x,
               double baseline, double size, Vec3 colour);

#endif
