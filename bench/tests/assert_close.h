/* assert_close.h (bench, chapter 1): comparing doubles in the bench's tests (include
 * after cmocka.h).
 *
 * assert_close compares doubles and, unlike cmocka's float-only assert_float_equal,
 * prints both values at full precision when it fails (the lesson's tests have the same
 * macro in tests/check.h; the bench's tests do not reach into the lesson's).
 */
#ifndef ASSERT_CLOSE_H
#define ASSERT_CLOSE_H

#include <math.h>

#define assert_close(a, b, tol)                                                                \
    do {                                                                                       \
        double a_ = (a), b_ = (b);                                                             \
        if (!(fabs(a_ - b_) <= (tol)))                                                         \
            fail_msg("%s = %.17g, expected %.17g within %.3g", #a, a_, b_, (double)(tol));     \
    } while (0)

#endif
