/* scene_file.h (bench, chapter 1): reading the scene format, version 1, a contract that
 * tools outside the project read too (docs/scene-format.md).
 *
 * Every error is reported as "FILE:LINE: what is wrong" and nothing is half-built: on
 * failure the scene is freed and left empty. Numbers are within 1e50 and shapes at
 * least 1e-50 across; flatness is judged relative to each shape's size, so a scene
 * scaled by 1e-12 or 1e12 reads the same. Emission is at most 1e20. A file is at most
 * 64 MiB, read once (a pipe or a FIFO too). A sphere cannot be a light.
 */
#ifndef SCENE_FILE_H
#define SCENE_FILE_H

#include <stddef.h>
#include <stdint.h>

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

/* What a scene reader knows of the file beyond the scene. */
typedef struct {
    uint64_t hash;  /* scene_hash of its bytes: names it without reading it again */
    int line_count; /* where "missing X" errors point */
} SceneFileInfo;

/* The same from `length` bytes of text in memory (the last line may lack its end);
 * `name` stands for the file name in messages. With info, it is filled in. */
int scene_parse(const char *text, size_t length, const char *name, Scene *scene,
                SceneFileInfo *info, char *error, size_t error_size);

/* The index of the material called `name`, or -1. */
int scene_file_material(const Scene *scene, const char *name);

/* FNV-1a, 64 bits (Fowler, Noll, Vo), over `size` bytes continuing from `hash`; start
 * with SCENE_HASH_START. It names the scene's bytes and the materials' names. */
#define SCENE_HASH_START 0xcbf29ce484222325ULL
uint64_t scene_hash(uint64_t hash, const void *data, size_t size);

/* The image plane's width over its height: a W x H image follows it, H = W / aspect
 * rounded (docs/scene-format.md). */
double scene_file_aspect(const Camera *camera);

#endif
