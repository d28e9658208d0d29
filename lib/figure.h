/* figure.h: the side-by-side comparison figure, laid out like the report's figures.
 *
 * Introduced in chapter 1. Panels of equal size stand in one row with a gap between
 * them; under each, its caption (the panel's settings, possibly several lines
 * separated by '\n') is drawn in white on dark grey with the stb_easy_font bitmap font,
 * scaled up with the panel so it stays readable. Panels are tone mapped as in image.h.
 */
#ifndef FIGURE_H
#define FIGURE_H

#include "image.h"

/* Write the figure as a PNG (whole or not at all). Returns 0, or -1 with errno set. */
int figure_write_png(const char *path, const Image *panels, const char *const *captions,
                     int panel_count, double exposure);

#endif
