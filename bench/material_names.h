/* material_names.h (bench, chapter 1): the scene reader's materials by name.
 *
 * An open-addressing hash table of material indices (-1: empty slot), at most half
 * full, so that a lookup compares a name or two however many materials a scene
 * declares: the reader looks up the material of every shape it reads.
 */
#ifndef MATERIAL_NAMES_H
#define MATERIAL_NAMES_H

#include "scene.h"

typedef struct {
    int *slots;
    int size; /* a power of two, or 0 */
} MaterialNames;

void material_names_init(MaterialNames *names);
void material_names_free(MaterialNames *names);

/* List material `index` of the scene under its name (which must not be listed yet).
 * Returns 0, or -1 when memory runs out. */
int material_names_add(MaterialNames *names, const Scene *scene, int index);

/* The index of the material called `name`, or -1; with `comparisons`, the number of
 * names compared to find it is added there. */
int material_names_find(const MaterialNames *names, const Scene *scene, const char *name,
                        int *comparisons);

#endif
