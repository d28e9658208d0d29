/* json.h (bench, chapter 8): the lab's answers to its page, as JSON text.
 *
 * A buffer that grows as text is appended. Numbers are written with 17 significant
 * digits, which read back as the same double, so that the page sees exactly what the
 * C code computed, and a native program and the WebAssembly module that compute the
 * same numbers write the same text; a number that is not finite is written as null.
 */
#ifndef JSON_H
#define JSON_H

#include <stddef.h>

#include "vec.h"

typedef struct {
    char *text; /* NUL-terminated; NULL until something is written */
    size_t length;
    size_t capacity;
    int failed; /* memory ran out: the text is incomplete */
} Json;

void json_init(Json *json);
void json_free(Json *json);

/* Start again from empty text (the buffer is kept). */
void json_clear(Json *json);

/* Append printf-style text. */
void json_text(Json *json, const char *format, ...);

/* Append a number, or null when it is not finite. */
void json_number(Json *json, double value);

/* Append [x,y,z]. */
void json_vec3(Json *json, Vec3 v);

/* Append a string in quotes, with '"', '\' and control characters escaped. */
void json_string(Json *json, const char *text);

#endif
