/* figure.h (chapter 1): the side-by-side comparison figure, laid out like the report's figures.
 *
 * Introduced in chapter 1. Panels of equal size stand in one row with a gap between
 * them; under each, its caption (the panel's settings, possibly several lines
 * separated by '\n') is drawn in white on dark grey with the stb_easy_font bitmap font,
 * scaled up with the panel so it stays readable. Panels are tone mapped as in image.h.
 *
 * Layout, for n panels of W x H pixels:
 *   - text scale s = sqrt(W / 50) rounded, clamped to [1, 4] (2 for 200 pixels, 3 for
 *     400, 4 from 613 up): each unit of the font (letters are about 5 x 7 units, lines
 *     12 units apart) is an s x s square of pixels;
 *   - the gap between panels is 4 s pixels, so the figure is n W + (n - 1) 4 s wide;
 *   - each caption line is centred under its panel and kept s pixels from its sides:
 *     a line too long is wrapped at spaces (runs of spaces become one); if a word alone
 *     is too long, s goes down for all captions, and at s = 1 such words break;
 *   - the caption band under the panels is s' (12 L + 4) pixels high, where s' is the
 *     final text scale and L (at least 1) the most lines of any caption, so the figure
 *     is H + s' (12 L + 4) high. Text is never drawn outside its panel's columns.
 * Characters other than printable ASCII and '\n' are drawn as '?'. A NULL caption is
 * an empty one.
 */
#ifndef FIGURE_H
#define FIGURE_H

#include "image.h"

/* Write the figure as a PNG (whole or not at all). Returns 0, or -1 with errno set. */
int figure_write_png(const char *path, const Image *panels, const char *const *captions,
                     int panel_count, double exposure);

#endif
