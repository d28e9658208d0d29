/* figure.h (bench, chapter 1): the side-by-side comparison figure, laid out like the report's
 * figures.
 *
 * Introduced in chapter 1. Panels of equal size stand in one row with a gap between
 * them; under each, its caption (the panel's settings, possibly several lines
 * separated by '\n') is drawn in light text on dark grey with an anti-aliased TrueType
 * font (font.h), its size growing with the panel so that it stays readable when the
 * figure is shown whole on a projector. Panels are tone mapped as in image.h.
 *
 * Layout, for n panels of W x H pixels:
 *   - text size s = W / 50 pixels per em, rounded, clamped to [12, 24] (12 up to 624
 *     pixels, 16 at 800, 24 from 1175 up);
 *   - the gap between panels, and the margin m around each caption, are s / 2 pixels
 *     (integer division), so the figure is n W + (n - 1) (s / 2) wide;
 *   - each caption line is centred under its panel and kept m pixels from its sides:
 *     a line too long is wrapped at spaces (runs of spaces become one); if a word alone
 *     is too long, the size goes down a pixel at a time for all captions, to 8 at the
 *     least, and at 8 such words break between characters;
 *   - lines are p = ceil(font_line_height) pixels apart at the final size, and the
 *     caption band under the panels is L p + 2 m high, where L (at least 1) is the most
 *     lines of any caption; the figure is H + L p + 2 m high. Text is never drawn
 *     outside its panel's columns.
 * A NULL caption is an empty one. Characters are drawn as font.h says.
 */
#ifndef FIGURE_H
#define FIGURE_H

#include "font.h"
#include "image.h"

/* Write the figure as a PNG (whole or not at all). Returns 0, or -1 with errno set. */
int figure_write_png(const char *path, const Font *font, const Image *panels,
                     const char *const *captions, int panel_count, double exposure);

#endif
