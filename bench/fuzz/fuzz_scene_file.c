/* fuzz_scene_file.c (bench, chapter 1): libFuzzer target for the scene reader (scene_file.h, SPEC §4).
 *
 * Bad input must be a clear error, never a crash, a hang or a leak (SPEC §4). Any
 * bytes go to scene_parse; `make fuzz` builds this with AddressSanitizer and
 * UndefinedBehaviorSanitizer. Besides not crashing, the reader must keep its promises,
 * checked here so the fuzzer finds inputs that break them: a failure leaves the scene
 * empty and names the file, in printable ASCII only (no raw byte of the input); a
 * success has a camera, a finite positive scale, the hash of the bytes, every material
 * found by its name, emission within its bound, and only finite triangles of positive
 * area, with unit normals and materials that exist.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_loaded(const Scene *scene, const uint8_t *data, size_t size)
{
    if (!scene->has_camera || !(scene->scale > 0.0 && isfinite(scene->scale)) ||
        scene->source_hash != scene_hash(SCENE_HASH_START, data, size))
        abort();
    for (int i = 0; i < scene->material_count; i++)
        if (scene_find_material(scene, scene->materials[i].name) != i ||
            !(vec3_max_component(scene->materials[i].emission) <= 1e20))
            abort();
    for (int i = 0; i < scene->triangle_count; i++) {
        const Triangle *t = &scene->triangles[i];
        if (!(t->area > 0.0 && isfinite(t->area)) || !vec3_is_finite(t->normal) ||
            fabs(vec3_length(t->normal) - 1.0) > 1e-9 || t->material < 0 ||
            t->material >= scene->material_count)
            abort();
    }
    for (int i = 0; i < scene->sphere_count; i++)
        if (!(scene->spheres[i].radius > 0.0) || scene->spheres[i].material < 0 ||
            scene->spheres[i].material >= scene->material_count)
            abort();
}

static int is_printable(const char *message)
{
    for (const char *p = message; *p; p++)
        if ((unsigned char)*p < 0x20 || (unsigned char)*p >= 0x7F)
            return 0;
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Scene scene;
    char error[512];
    if (scene_parse((const char *)data, size, "fuzz", &scene, error, sizeof error) == 0)
        check_loaded(&scene, data, size);
    else if (strncmp(error, "fuzz:", 5) != 0 || !is_printable(error) || scene.materials ||
             scene.triangles || scene.spheres || scene.point_lights || scene.source ||
             scene.material_count || scene.triangle_count || scene.has_camera)
        abort();
    scene_free(&scene);
    return 0;
}
