/* scene_file.h (chapter 1): reading the scene format, version 1 (SPEC §4, a contract).
 *
 * Introduced in chapter 1. Line-oriented text; `#` starts a comment; tokens are
 * separated by white space; numbers are decimal floats. Keywords: camera, material
 * (lambert, oren_nayar, mirror, glass, light), triangle, quad, sphere, box,
 * tetrahedron, point_light; see README.md for the grammar.
 *
 * Every error is reported as "FILE:LINE: what is wrong" and nothing is half-built:
 * on failure the scene is freed and left empty. Beyond the checks SPEC §4 lists:
 * numbers are limited to magnitude 1e100 (so areas and volumes stay finite), and
 * flatness (zero area, a non-planar or non-convex quad, zero volume, a degenerate
 * camera) is judged relative to each shape's size, so a scene scaled by 1e-3 or 1e3
 * reads the same. A sphere cannot be a light: area lights are sampled by triangle.
 */
#ifndef SCENE_FILE_H
#define SCENE_FILE_H

#include <stddef.h>

#include "scene.h"

/* Lines longer than this (in bytes, without the \n or \r\n) are an error. */
#define SCENE_LINE_MAX 1024

/* Read and prepare (scene_prepare) the scene in file `path`; `scene` need not be
 * initialised, and what it held is not freed. Returns 0, or -1 with the message
 * "PATH:LINE: what is wrong" in error[error_size] (truncated to fit). A file that
 * cannot be read is reported at line 0, a missing camera at the last line. */
int scene_load(const char *path, Scene *scene, char *error, size_t error_size);

/* The same from `length` bytes of text in memory (lines end in \n or \r\n; the last
 * may lack one); `name` stands for the file name in messages and scene->source. */
int scene_parse(const char *text, size_t length, const char *name, Scene *scene,
                char *error, size_t error_size);

#endif
