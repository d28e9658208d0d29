/* query_method.h (chapter 9): how the scene's ray queries find their hit.
 *
 * Chapter 9 measures each way on the same renders (scene.h, Scene.query): every
 * primitive tested, chapter 2's binary tree (bvh.h), or the same tree made four-wide
 * (wide_bvh.h), the default from this chapter on. scene.c calls these in place of
 * chapter 2's tree alone; each answers every query as testing every primitive does.
 */
#ifndef QUERY_METHOD_H
#define QUERY_METHOD_H

#include "scene.h"

/* Build (after freeing) and free what the scene's queries go through. queries_prepare
 * returns 0, or -1 when memory runs out. */
int queries_prepare(Scene *scene);
void queries_free(Scene *scene);

/* As bvh_intersect and bvh_occluded (bvh.h), by the method scene->query names. */
int queries_nearest(const Scene *scene, Ray ray, double *tmax);
int queries_any(const Scene *scene, Ray ray, double tmax);

#endif
