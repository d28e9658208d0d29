/* scene_file.h (chapter 1): reading the scene format, version 1 (SPEC §4, a contract).
 *
 * Introduced in chapter 1. Line-oriented text; `#` starts a comment; tokens are
 * separated by white space; numbers are decimal floats. Keywords: camera, material
 * (lambert, oren_nayar, mirror, glass, light), triangle, quad, sphere, box,
 * tetrahedron, point_light; see README.md for the grammar.
 *
 * Every error is reported as "FILE:LINE: what is wrong" and nothing is half-built:
 * on failure the scene is freed and left empty. Beyond the checks SPEC §4 lists:
 *   - scales: numbers are limited to magnitude 1e50 and shapes to at least 1e-50
 *     across, where the geometry's products (up to size^4) stay in double range; in
 *     between the renderer works at any scale. Flatness (zero area, a non-planar or
 *     non-convex quad, zero volume, a degenerate camera) is judged relative to each
 *     shape's size, so a scene scaled by 1e-12 or 1e12 reads the same;
 *   - emission and point lights' intensity are at most 1e20, so radiance stays finite;
 *   - a file is at most 64 MiB, read once (a pipe or a FIFO too); scene->source_hash
 *     is the hash of its bytes, for naming it without reading it again;
 *   - layout: a UTF-8 byte order mark at the start is skipped; lines end in \n, \r\n
 *     or a lone \r; outside comments the text is ASCII, and any other character is
 *     named by its code point (U+00A0, a no-break space), never printed raw;
 *   - a name too long for the error buffer is shortened in its middle, so the message
 *     always keeps ":LINE: what is wrong".
 * A sphere cannot be a light: area lights are sampled by triangle.
 */
#ifndef SCENE_FILE_H
#define SCENE_FILE_H

#include <stddef.h>

#include "scene.h"

/* Lines longer than this (in bytes, without the line end) are an error. */
#define SCENE_LINE_MAX 1024

/* Read and prepare (scene_prepare) the scene in file `path`; `scene` need not be
 * initialised, and what it held is not freed. Returns 0, or -1 with the message
 * "PATH:LINE: what is wrong" in error[error_size] (PATH shortened to fit). A file that
 * cannot be read, or is larger than 64 MiB, is reported at line 0, a missing camera at
 * the last line. The file is read once, whatever it is. */
int scene_load(const char *path, Scene *scene, char *error, size_t error_size);

/* The bytes of file `path`, read once (a pipe or a FIFO too), at most 64 MiB: *text is
 * malloc'ed (the caller frees it), *length its size. Returns 0, or -1 with the message
 * "PATH:0: what is wrong" in error[error_size]. scene_load is this, then scene_parse. */
int scene_file_read(const char *path, char **text, size_t *length, char *error,
                    size_t error_size);

/* The same from `length` bytes of text in memory (the last line may lack its end);
 * `name` stands for the file name in messages and scene->source. */
int scene_parse(const char *text, size_t length, const char *name, Scene *scene,
                char *error, size_t error_size);

#endif
