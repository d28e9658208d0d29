/* fuzz_scene_file.c (bench, chapter 1): libFuzzer target for the scene reader
 * (scene_file.h, docs/scene-format.md).
 *
 * Bad input must be a clear error, never a crash, a hang or a leak. Any bytes go to
 * scene_parse; `make fuzz` builds this with AddressSanitizer and
 * UndefinedBehaviorSanitizer. Besides not crashing, the reader must keep its promises,
 * checked here so the fuzzer finds inputs that break them: a failure leaves the scene
 * empty (no camera either) and names the file, in printable ASCII only (no raw byte of
 * the input); a success has a camera (an image plane of non-zero size), a finite
 * positive scale, the hash of the bytes and a line count, every material found by its
 * name (the first of that name: the reader refuses a second), emission within its
 * bound, and only finite triangles of positive area, with unit normals and materials
 * that exist.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_loaded(const Scene *scene, const SceneFileInfo *info, const uint8_t *data,
                         size_t size)
{
    if (!(vec3_length(scene->camera.right) > 0.0 && vec3_length(scene->camera.up) > 0.0) ||
        (scene->triangle_count + scene->sphere_count > 0 && scene->bvh.node_count == 0) ||
        info->hash != scene_hash(SCENE_HASH_START, data, size) || info->line_count < 1)
        abort();
    for (int i = 0; i < scene->material_count; i++)
        if (scene_file_material(scene, scene->materials[i].name) != i ||
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
    SceneFileInfo info;
    char error[512];
    if (scene_parse((const char *)data, size, "fuzz", &scene, &info, error, sizeof error) == 0)
        check_loaded(&scene, &info, data, size);
    else if (strncmp(error, "fuzz:", 5) != 0 || !is_printable(error) || scene.materials ||
             scene.triangles || scene.spheres || scene.point_lights || scene.material_count ||
             scene.triangle_count || vec3_length(scene.camera.right) != 0.0 ||
             vec3_length(scene.camera.up) != 0.0)
        abort();
    scene_free(&scene);
    return 0;
}
