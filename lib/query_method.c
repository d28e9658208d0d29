/* query_method.c (chapter 9): the scene's queries by the method it names. See
 * query_method.h. */
#include "query_method.h"

int queries_prepare(Scene *scene)
{
    scene->query = QUERY_WIDE_TREE;
    if (bvh_build(&scene->bvh, scene_primitives(scene)) != 0)
        return -1;
    return wide_bvh_build(&scene->wide, &scene->bvh, scene_primitives(scene));
}

void queries_free(Scene *scene)
{
    wide_bvh_free(&scene->wide);
    bvh_free(&scene->bvh);
}

/* Every primitive tested, the nearest kept: what the trees must answer. In increasing
 * order, a hit replacing only a farther one: of two at equal t the lower number stays. */
static int every_primitive(const Scene *scene, Ray ray, double *tmax, int any_hit)
{
    int nearest = -1;
    for (int i = 0;
         i < scene->triangle_count + scene->sphere_count && !(any_hit && nearest >= 0); i++) {
        double t =
            i < scene->triangle_count
                ? triangle_intersect(&scene->triangles[i], ray, 0.0, *tmax)
                : sphere_intersect(&scene->spheres[i - scene->triangle_count], ray, 0.0, *tmax);
        if (t < *tmax) {
            *tmax = t;
            nearest = i;
        }
    }
    return nearest;
}

int queries_nearest(const Scene *scene, Ray ray, double *tmax)
{
    if (scene->query == QUERY_EVERY_PRIMITIVE)
        return every_primitive(scene, ray, tmax, 0);
    if (scene->query == QUERY_BINARY_TREE)
        return bvh_intersect(&scene->bvh, scene_primitives(scene), ray, tmax);
    return wide_bvh_intersect(&scene->wide, scene_primitives(scene), ray, tmax);
}

int queries_any(const Scene *scene, Ray ray, double tmax)
{
    if (scene->query == QUERY_EVERY_PRIMITIVE)
        return every_primitive(scene, ray, &tmax, 1) >= 0;
    if (scene->query == QUERY_BINARY_TREE)
        return bvh_occluded(&scene->bvh, scene_primitives(scene), ray, tmax);
    return wide_bvh_occluded(&scene->wide, scene_primitives(scene), ray, tmax);
}
