/* mesh.h (bench, chapter 9): a large mesh for measuring speed, generated, not read.
 *
 * A (2, 3) torus knot, a tube around the curve ((R + r cos 3t) cos 2t, (R + r cos 3t)
 * sin 2t, r sin 3t), cut into `segments` rings of `sides` quads, two triangles each:
 * 2 x segments x sides triangles of one material, standing in the plane x = centre.x
 * so that a camera looking along +x sees it face on. Chapter 9 renders the room with
 * it to see what a tree buys where there are many primitives.
 */
#ifndef MESH_H
#define MESH_H

#include "scene.h"

/* Add the knot's triangles to the scene (before scene_prepare). Returns 0, or -1 when
 * memory runs out. */
int mesh_add_torus_knot(Scene *scene, int material, Vec3 centre, double size, int segments,
                        int sides);

#endif
