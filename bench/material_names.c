/* material_names.c (bench, chapter 1): the materials by name. See material_names.h. */
#include "material_names.h"

#include <stdlib.h>
#include <string.h>

#include "scene_file.h"

void material_names_init(MaterialNames *names)
{
    names->slots = NULL;
    names->size = 0;
}

void material_names_free(MaterialNames *names)
{
    free(names->slots);
    material_names_init(names);
}

/* Linear probing from the name's hash: the slot holding the material called `name`, or
 * the empty slot where it would go. The table is never full, so there is one. */
static size_t probe(const MaterialNames *names, const Scene *scene, const char *name,
                    int *comparisons)
{
    size_t mask = (size_t)names->size - 1;
    size_t slot = (size_t)scene_hash(SCENE_HASH_START, name, strlen(name)) & mask;
    for (;; slot = (slot + 1) & mask) {
        int index = names->slots[slot];
        if (index < 0)
            return slot;
        if (comparisons)
            (*comparisons)++;
        if (strcmp(scene->materials[index].name, name) == 0)
            return slot;
    }
}

/* A table twice the size (at least 16 slots) listing materials 0 .. count - 1. */
static int grow(MaterialNames *names, const Scene *scene, int count)
{
    int size = names->size ? 2 * names->size : 16;
    int *slots = malloc((size_t)size * sizeof *slots);
    if (!slots)
        return -1;
    for (int i = 0; i < size; i++)
        slots[i] = -1;
    free(names->slots);
    names->slots = slots;
    names->size = size;
    for (int i = 0; i < count; i++)
        names->slots[probe(names, scene, scene->materials[i].name, NULL)] = i;
    return 0;
}

int material_names_add(MaterialNames *names, const Scene *scene, int index)
{
    if (2 * (long)(index + 1) > names->size)
        return grow(names, scene, index + 1);
    names->slots[probe(names, scene, scene->materials[index].name, NULL)] = index;
    return 0;
}

int material_names_find(const MaterialNames *names, const Scene *scene, const char *name,
                        int *comparisons)
{
    return names->size ? names->slots[probe(names, scene, name, comparisons)] : -1;
}
