/* scene_file.h: reading the scene format, version 1 (SPEC §4, a contract).
 *
 * Introduced in chapter 1. Line-oriented text; `#` starts a comment; tokens are
 * separated by white space; numbers are decimal floats. Keywords: camera, material
 * (lambert, oren_nayar, mirror, glass, light), triangle, quad, sphere, box,
 * tetrahedron, point_light; see README.md for the grammar.
 *
 * Every error is reported as "FILE:LINE: what is wrong" and nothing is half-built:
 * on failure the scene is freed and left empty.
 */
#ifndef SCENE_FILE_H
#define SCENE_FILE_H

#include <stddef.h>

#include "scene.h"

/* Lines longer than this (in bytes, without the newline) are an error. */
#define SCENE_LINE_MAX 1024

/* Read and prepare the scene in file `path`. Returns 0, or -1 with the message
 * "PATH:LINE: what is wrong" in error[error_size]. */
int scene_load(const char *path, Scene *scene, char *error, size_t error_size);

/* The same from text in memory; `name` stands for the file name in messages. */
int scene_parse(const char *text, size_t length, const char *name, Scene *scene,
                char *error, size_t error_size);

#endif
