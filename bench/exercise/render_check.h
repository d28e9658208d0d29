/* render_check.h (bench, chapter 2): grading an estimator by its image, pixel by pixel,
 * against the solution's.
 *
 * The student's code renders a small scene; the solution (the lesson as it stands,
 * linked into the grader built from the chapter's own library) renders the same
 * scene with the same estimator and many more samples, once, as the reference. After
 * Mitsuba 3's render tests, each pixel and channel gives
 *     z = (x - r) / sqrt(se_x^2 + se_r^2),   p = erfc(|z| / sqrt 2),
 * se_x at least se_r sqrt(reference spp / spp) (what the solution's noise would be),
 * and the images agree when every p is at least Sidak's 1 - (1 - level)^(1 / N) over
 * the N values, and their means agree within 4 standard errors. The picture
 * OUT/exercise-ID-zmap.png shows the image, the reference and the z-map: red where
 * the image is brighter, blue where darker, yellow where a pixel fails.
 */
#ifndef RENDER_CHECK_H
#define RENDER_CHECK_H

#include "grading.h"

struct RenderCheck {
    const char *scene; /* the scene file's text */
    Estimator estimate;
    const void *settings; /* the estimator's settings */
    int width;            /* pixels; the height follows the camera */
    int spp, reference_spp;
};

/* A closed room with a large ceiling lamp, a red and a green wall and a sphere: seen
 * from the front, every pixel sees light after a bounce or two. */
extern const char render_check_room[];

/* Render the reference of exercise `e` (its solution) into
 * FOLDER/exercise-ID-reference.pfm and its standard errors into ...-reference-se.pfm.
 * Returns 0, or -1 with a message in error[size]. */
int render_check_reference(const Exercise *e, const char *folder, char *error, size_t size);

/* Render with the student's code and compare with the reference at significance level
 * `level`. Returns 1 when they agree; else the exercise fails, naming how the image
 * differs, then `hint`. */
int grading_render(Grading *g, const RenderCheck *check, double level, const char *hint);

#endif
