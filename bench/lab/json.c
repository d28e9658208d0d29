/* json.c (bench, chapter 8): JSON text in a growing buffer. See json.h. */
#include "json.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void json_init(Json *json) { *json = (Json){NULL, 0, 0, 0}; }

void json_free(Json *json)
{
    free(json->text);
    json_init(json);
}

void json_clear(Json *json)
{
    json->length = 0;
    json->failed = 0;
    if (json->text)
        json->text[0] = '\0';
}

/* Room for `more` bytes and the NUL after them. */
static int reserve(Json *json, size_t more)
{
    if (json->failed)
        return -1;
    if (json->length + more + 1 <= json->capacity)
        return 0;
    size_t capacity = json->capacity ? json->capacity : 256;
    while (capacity < json->length + more + 1)
        capacity *= 2;
    char *grown = realloc(json->text, capacity);
    if (!grown) {
        json->failed = 1;
        return -1;
    }
    json->text = grown;
    json->capacity = capacity;
    return 0;
}

void json_text(Json *json, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    int needed = vsnprintf(NULL, 0, format, args);
    va_end(args);
    if (needed < 0 || reserve(json, (size_t)needed) != 0)
        return;
    va_start(args, format);
    vsnprintf(json->text + json->length, (size_t)needed + 1, format, args);
    va_end(args);
    json->length += (size_t)needed;
}

void json_number(Json *json, double value)
{
    if (isfinite(value))
        json_text(json, "%.17g", value);
    else
        json_text(json, "null");
}

void json_vec3(Json *json, Vec3 v)
{
    json_text(json, "[");
    json_number(json, v.x);
    json_text(json, ",");
    json_number(json, v.y);
    json_text(json, ",");
    json_number(json, v.z);
    json_text(json, "]");
}

void json_string(Json *json, const char *text)
{
    json_text(json, "\"");
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) {
        if (*c == '"' || *c == '\\')
            json_text(json, "\\%c", *c);
        else if (*c < 0x20)
            json_text(json, "\\u%04x", *c);
        else
            json_text(json, "%c", *c);
    }
    json_text(json, "\"");
}
