/* metamorphic_scenes.h (bench, chapter 1): the scenes of the metamorphic tests and the
 * changes that must not change their images (include after cmocka.h; metamorphic.h).
 *
 * A scene is held as its statements (keyword, name, numbers), changed, and written back
 * as text for the scene reader: scaled, moved with its camera, its camera pulled back,
 * given what the view cannot see, its lamps or quads split, its statements reversed,
 * or mirrored with its camera. docs/metamorphic.md lists the cases and why each holds.
 */
#ifndef METAMORPHIC_SCENES_H
#define METAMORPHIC_SCENES_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vec.h"

/* ---- scene text ------------------------------------------------------------------ */

enum {
    STATEMENTS_MAX = 80,
    NUMBERS_MAX = 13
};

/* One statement of a scene file: its keyword, its material's name (geometry) or its own
 * name and kind (a material), and its numbers. */
typedef struct {
    char keyword[16], name[24], kind[16];
    int count;
    double n[NUMBERS_MAX];
} Statement;

typedef struct {
    Statement s[STATEMENTS_MAX];
    int count;
} SceneText;

static inline void scene_text_parse(const char *text, SceneText *scene)
{
    scene->count = 0;
    while (*text) {
        const char *end = strchr(text, '\n');
        size_t length = end ? (size_t)(end - text) : strlen(text);
        char line[512], *save = NULL;
        snprintf(line, sizeof line, "%.*s", (int)length, text);
        text += length + (end != NULL);
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        char *token = strtok_r(line, " \t", &save);
        if (!token)
            continue;
        assert_true(scene->count < STATEMENTS_MAX);
        Statement *s = &scene->s[scene->count++];
        memset(s, 0, sizeof *s);
        snprintf(s->keyword, sizeof s->keyword, "%s", token);
        int named = strcmp(token, "camera") != 0 && strcmp(token, "point_light") != 0;
        if (named)
            snprintf(s->name, sizeof s->name, "%s", strtok_r(NULL, " \t", &save));
        if (strcmp(token, "material") == 0)
            snprintf(s->kind, sizeof s->kind, "%s", strtok_r(NULL, " \t", &save));
        while ((token = strtok_r(NULL, " \t", &save)) != NULL) {
            assert_true(s->count < NUMBERS_MAX);
            s->n[s->count++] = strtod(token, NULL);
        }
    }
}

/* The text, every number with 17 significant digits (read back exactly). */
static inline char *scene_text_write(const SceneText *scene)
{
    size_t size = 600 * (size_t)scene->count + 1, used = 0;
    char *text = malloc(size);
    assert_non_null(text);
    text[0] = '\0';
    for (int i = 0; i < scene->count; i++) {
        const Statement *s = &scene->s[i];
        used += (size_t)snprintf(text + used, size - used, "%s %s %s", s->keyword, s->name,
                                 s->kind);
        for (int k = 0; k < s->count; k++)
            used += (size_t)snprintf(text + used, size - used, " %.17g", s->n[k]);
        used += (size_t)snprintf(text + used, size - used, "\n");
    }
    return text;
}

static inline int is_keyword(const Statement *s, const char *keyword)
{
    return strcmp(s->keyword, keyword) == 0;
}

/* How many points a statement's numbers begin with (a box: its two corners). */
static inline int point_count(const Statement *s)
{
    if (is_keyword(s, "camera") || is_keyword(s, "quad") || is_keyword(s, "tetrahedron"))
        return 4;
    if (is_keyword(s, "triangle"))
        return 3;
    if (is_keyword(s, "box"))
        return 2;
    if (is_keyword(s, "sphere") || is_keyword(s, "point_light"))
        return 1;
    return 0;
}

static inline Vec3 point_of(const Statement *s, int k)
{
    return vec3(s->n[3 * k], s->n[3 * k + 1], s->n[3 * k + 2]);
}

static inline void set_point(Statement *s, int k, Vec3 p)
{
    s->n[3 * k] = p.x;
    s->n[3 * k + 1] = p.y;
    s->n[3 * k + 2] = p.z;
}

/* The kind of the material called `name`. */
static inline const char *material_kind(const SceneText *scene, const char *name)
{
    for (int i = 0; i < scene->count; i++)
        if (is_keyword(&scene->s[i], "material") && strcmp(scene->s[i].name, name) == 0)
            return scene->s[i].kind;
    fail_msg("no material %s", name);
    return "";
}

static inline int is_geometry(const Statement *s)
{
    return !is_keyword(s, "camera") && !is_keyword(s, "material");
}

/* The geometry's bounding box (the camera and point lights left out). */
static inline void geometry_box(const SceneText *scene, Vec3 *lower, Vec3 *upper)
{
    *lower = vec3(INFINITY, INFINITY, INFINITY);
    *upper = vec3(-INFINITY, -INFINITY, -INFINITY);
    for (int i = 0; i < scene->count; i++) {
        const Statement *s = &scene->s[i];
        if (!is_geometry(s) || is_keyword(s, "point_light"))
            continue;
        double r = is_keyword(s, "sphere") ? s->n[3] : 0.0;
        for (int k = 0; k < point_count(s); k++) {
            Vec3 p = point_of(s, k);
            *lower =
                vec3(fmin(lower->x, p.x - r), fmin(lower->y, p.y - r), fmin(lower->z, p.z - r));
            *upper =
                vec3(fmax(upper->x, p.x + r), fmax(upper->y, p.y + r), fmax(upper->z, p.z + r));
        }
    }
}

static inline double scene_size(const SceneText *scene)
{
    Vec3 lower, upper;
    geometry_box(scene, &lower, &upper);
    return vec3_max_component(vec3_sub(upper, lower));
}

static inline Vec3 camera_eye(const SceneText *scene)
{
    for (int i = 0; i < scene->count; i++)
        if (is_keyword(&scene->s[i], "camera"))
            return point_of(&scene->s[i], 0);
    fail_msg("no camera");
    return vec3(0, 0, 0);
}

static inline void append(SceneText *scene, Statement s)
{
    assert_true(scene->count < STATEMENTS_MAX);
    scene->s[scene->count++] = s;
}

static inline Statement quad_of(const char *material, Vec3 a, Vec3 b, Vec3 c, Vec3 d)
{
    Statement s = {.keyword = "quad", .count = 12};
    snprintf(s.name, sizeof s.name, "%s", material);
    set_point(&s, 0, a);
    set_point(&s, 1, b);
    set_point(&s, 2, c);
    set_point(&s, 3, d);
    return s;
}

/* ---- the changes ----------------------------------------------------------------- */

/* Every point p to s p + t, spheres' radii times s (s > 0). Point lights keep their
 * intensity (the reader refuses one above 1e20): the irradiance they give scales by
 * 1 / s^2, and what renders them is compared times s^2 (Case.radiance_factor). */
static inline void move_scene(SceneText *scene, double s, Vec3 t)
{
    for (int i = 0; i < scene->count; i++) {
        Statement *st = &scene->s[i];
        for (int k = 0; k < point_count(st); k++)
            set_point(st, k, vec3_add(vec3_scale(point_of(st, k), s), t));
        if (is_keyword(st, "sphere"))
            st->n[3] *= s;
    }
}

/* The mirror image in the plane z = z0, every triangle and quad's corners in reverse
 * order so that each faces the mirrored way (a reflection turns the cross product
 * (v1 - v0) x (v2 - v0) the other way); a box's z corners swapped; the camera mirrored
 * too, so that the image is the same pixel for pixel. */
static inline void flip_scene(SceneText *scene, double z0)
{
    for (int i = 0; i < scene->count; i++) {
        Statement *st = &scene->s[i];
        int points = point_count(st);
        for (int k = 0; k < points; k++) {
            Vec3 p = point_of(st, k);
            set_point(st, k, vec3(p.x, p.y, 2.0 * z0 - p.z));
        }
        if (is_keyword(st, "box")) {
            double low = st->n[2];
            st->n[2] = st->n[5];
            st->n[5] = low;
        }
        if (is_keyword(st, "triangle") ||
            is_keyword(st, "quad")) { /* v0 kept, the rest reversed */
            for (int k = 1; k < points - k; k++) {
                Vec3 a = point_of(st, k), b = point_of(st, points - k);
                set_point(st, k, b);
                set_point(st, points - k, a);
            }
        }
    }
}

/* The eye moved along the line from the image plane's centre through it, to `distance`
 * from that centre; the image plane stays, so the view of it is kept. */
static inline void camera_back(SceneText *scene, double distance)
{
    for (int i = 0; i < scene->count; i++) {
        Statement *c = &scene->s[i];
        if (!is_keyword(c, "camera"))
            continue;
        Vec3 eye = point_of(c, 0), bottom_left = point_of(c, 1);
        Vec3 centre =
            vec3_add(bottom_left, vec3_scale(vec3_add(vec3_sub(point_of(c, 2), bottom_left),
                                                      vec3_sub(point_of(c, 3), bottom_left)),
                                             0.5));
        Vec3 away = vec3_normalize(vec3_sub(eye, centre));
        set_point(c, 0, vec3_add_scaled(centre, away, distance));
    }
}

/* A grey sphere 1e12 times the scene's size away. Nothing in the closed room sees it. */
static inline void add_far_sphere(SceneText *scene)
{
    double size = scene_size(scene);
    Statement grey = {.keyword = "material",
                      .name = "far_grey",
                      .kind = "lambert",
                      .count = 3,
                      .n = {0.5, 0.5, 0.5}};
    Statement sphere = {.keyword = "sphere",
                        .name = "far_grey",
                        .count = 4,
                        .n = {0.3e12 * size, -0.8e12 * size, 0.52e12 * size, size}};
    append(scene, grey);
    append(scene, sphere);
}

/* The floor (every triangle and quad lying in the geometry's lowest plane z = min)
 * replaced by one quad 2e12 times the scene's size across: the walls stand on it and
 * hide everything beyond them. */
static inline void extend_floor(SceneText *scene)
{
    Vec3 lower, upper;
    geometry_box(scene, &lower, &upper);
    double reach = 1e12 * scene_size(scene);
    char material[24] = "";
    int kept = 0;
    for (int i = 0; i < scene->count; i++) {
        Statement *s = &scene->s[i];
        int flat = is_keyword(s, "triangle") || is_keyword(s, "quad");
        for (int k = 0; flat && k < point_count(s); k++)
            flat = point_of(s, k).z == lower.z;
        if (flat && !material[0])
            snprintf(material, sizeof material, "%s", s->name);
        if (!flat)
            scene->s[kept++] = *s;
    }
    scene->count = kept;
    assert_true(material[0] != '\0');
    Vec3 c = vec3_scale(vec3_add(lower, upper), 0.5);
    append(scene, quad_of(material, vec3(c.x - reach, c.y - reach, lower.z),
                          vec3(c.x + reach, c.y - reach, lower.z),
                          vec3(c.x + reach, c.y + reach, lower.z),
                          vec3(c.x - reach, c.y + reach, lower.z)));
}

/* A copy of the first mirror quad, 1e-7 of the scene's size behind it (away from the
 * eye): hidden by the first, but a plane of its own. */
static inline void add_mirror_behind(SceneText *scene)
{
    Vec3 eye = camera_eye(scene);
    double gap = 1e-7 * scene_size(scene);
    for (int i = 0; i < scene->count; i++) {
        Statement s = scene->s[i];
        if (!is_keyword(&s, "quad") || strcmp(material_kind(scene, s.name), "mirror") != 0)
            continue;
        Vec3 n = vec3_normalize(vec3_cross(vec3_sub(point_of(&s, 1), point_of(&s, 0)),
                                           vec3_sub(point_of(&s, 2), point_of(&s, 0))));
        if (vec3_dot(n, vec3_sub(eye, point_of(&s, 0))) > 0.0)
            n = vec3_neg(n);
        for (int k = 0; k < 4; k++)
            set_point(&s, k, vec3_add_scaled(point_of(&s, k), n, gap));
        append(scene, s);
        return;
    }
    fail_msg("no mirror quad");
}

/* Every lamp quad P0 P1 P2 P3 as two, cut a third of the way from P0 P3 to P1 P2:
 * halves of unequal area, in the same turning order (so facing the same way). */
static inline void split_lamps(SceneText *scene)
{
    int count = scene->count;
    for (int i = 0; i < count; i++) {
        Statement *s = &scene->s[i];
        if (!is_keyword(s, "quad") || strcmp(material_kind(scene, s->name), "light") != 0)
            continue;
        Vec3 p[4] = {point_of(s, 0), point_of(s, 1), point_of(s, 2), point_of(s, 3)};
        Vec3 a = vec3_add_scaled(p[0], vec3_sub(p[1], p[0]), 1.0 / 3.0);
        Vec3 b = vec3_add_scaled(p[3], vec3_sub(p[2], p[3]), 1.0 / 3.0);
        Statement second = quad_of(s->name, a, p[1], p[2], b);
        *s = quad_of(s->name, p[0], a, b, p[3]);
        append(scene, second);
    }
}

/* Every quad that is not a lamp as four triangles around its centre, each turning as
 * the quad does. */
static inline void split_quads(SceneText *scene)
{
    int count = scene->count;
    for (int i = 0; i < count; i++) {
        Statement *s = &scene->s[i];
        if (!is_keyword(s, "quad") || strcmp(material_kind(scene, s->name), "light") == 0)
            continue;
        Vec3 p[4] = {point_of(s, 0), point_of(s, 1), point_of(s, 2), point_of(s, 3)};
        Vec3 centre = vec3_scale(vec3_add(vec3_add(p[0], p[1]), vec3_add(p[2], p[3])), 0.25);
        Statement quad = *s;
        for (int k = 0; k < 4; k++) {
            Statement t = {.keyword = "triangle", .count = 9};
            snprintf(t.name, sizeof t.name, "%s", quad.name);
            set_point(&t, 0, centre);
            set_point(&t, 1, p[k]);
            set_point(&t, 2, p[(k + 1) % 4]);
            if (k == 0)
                *s = t;
            else
                append(scene, t);
        }
    }
}

/* The statements in reverse order, but the camera and the materials first (a material
 * is defined before its use). */
static inline void reverse_statements(SceneText *scene)
{
    SceneText reversed = {.count = 0};
    for (int i = 0; i < scene->count; i++)
        if (!is_geometry(&scene->s[i]))
            append(&reversed, scene->s[i]);
    for (int i = scene->count - 1; i >= 0; i--)
        if (is_geometry(&scene->s[i]))
            append(&reversed, scene->s[i]);
    *scene = reversed;
}

/* ---- the scenes ------------------------------------------------------------------ */

/* The report's room (scenes/room.scene) with its green wall behind the camera made a
 * second mirror, parallel to the mirror wall across the room; lit by its lamp, or, for
 * chapter 1, by the point light of scenes/room_whitted.scene. */
static const char ROOM[] =
    "camera  -1 0 0   0 1 -1   0 -1 -1   0 1 1\n"
    "material white  lambert 0.75 0.75 0.75\n"
    "material red    lambert 0.75 0.15 0.15\n"
    "material green  lambert 0.15 0.75 0.15\n"
    "material blue   lambert 0.15 0.15 0.75\n"
    "material yellow lambert 0.80 0.70 0.25\n"
    "material pink   lambert 0.80 0.35 0.60\n"
    "material mirror mirror  1 1 1\n"
    "material glass  glass   1.5\n"
    "material lamp   light   25 25 25\n"
    "quad     white   0 -6 -5   10 -6 -5   10 6 -5   0 6 -5\n"
    "triangle white  -3 0 -5    0 -6 -5    0 6 -5\n"
    "triangle white  10 -6 -5   13 0 -5    10 6 -5\n"
    "quad     white   0 6 5     10 6 5     10 -6 5   0 -6 5\n"
    "triangle white  -3 0 5     0 6 5      0 -6 5\n"
    "triangle white  10 6 5     13 0 5     10 -6 5\n"
    "quad mirror  -3 0 -5   -3 0 5    0 -6 5    0 -6 -5\n"
    "quad green    0 -6 -5   0 -6 5   10 -6 5   10 -6 -5\n"
    "quad blue    10 -6 -5  10 -6 5   13 0 5    13 0 -5\n"
    "quad mirror  13 0 -5   13 0 5    10 6 5    10 6 -5\n"
    "quad red     10 6 -5   10 6 5     0 6 5     0 6 -5\n"
    "quad red      0 6 -5    0 6 5    -3 0 5    -3 0 -5\n"
    "box         yellow  8 -4.5 -5   10 -2.5 -3\n"
    "tetrahedron pink    5.5 3.5 -5   6.5 5 -5   6.5 2 -5   6.2 3.5 -2.8\n"
    "sphere      glass   7 -1.5 -1   1.25\n"
    "sphere      mirror  8.5 2.5 -4.1   0.9\n";
static const char ROOM_LAMP[] = "quad lamp 4 -1 4.99   4 1 4.99   6 1 4.99   6 -1 4.99\n";
static const char ROOM_POINT_LIGHT[] = "point_light 5 0 4   150 150 150\n";

/* A box on a mirror floor, a glass ball and a wall behind, open to the sky, seen
 * obliquely from above (its camera is pulled back by each case). */
static const char OPEN[] = "camera 9.856 -5.913 4.949   3.044 2.838 -2.331   -1.072 -4.022 "
                           "-2.331   1.072 4.022 5.331\n"
                           "material floor  mirror  0.9 0.9 0.9\n"
                           "material yellow lambert 0.8 0.7 0.25\n"
                           "material white  lambert 0.75 0.75 0.75\n"
                           "material glass  glass   1.5\n"
                           "material lamp   light   25 25 25\n"
                           "quad  floor  -6 -6 0   6 -6 0   6 6 0   -6 6 0\n"
                           "box   yellow -1 -1 0   1 1 2\n"
                           "quad  white  -6 6 0    6 6 0    6 6 5   -6 6 5\n"
                           "sphere glass 2.5 -2 1   1\n";
static const char OPEN_LAMP[] = "quad lamp -1 -1 6   -1 1 6   1 1 6   1 -1 6\n";
static const char OPEN_POINT_LIGHT[] = "point_light 3 -2 6   60 60 60\n";

typedef enum {
    SCENE_ROOM,
    SCENE_OPEN,
    SCENE_SYMMETRIC
} SceneKind;

/* The scene of a case: the room, the open mirror floor, or the room with its light
 * moved over the eye and a second light at that one's point reflection through the
 * eye (the lights' centre is the eye), lamps or (point_lights) point lights. */
static inline void base_scene(SceneKind kind, int point_lights, SceneText *scene)
{
    char text[4096];
    int room = kind != SCENE_OPEN;
    snprintf(text, sizeof text, "%s%s", room ? ROOM : OPEN,
             point_lights ? (room ? ROOM_POINT_LIGHT : OPEN_POINT_LIGHT)
                          : (room ? ROOM_LAMP : OPEN_LAMP));
    scene_text_parse(text, scene);
    if (kind != SCENE_SYMMETRIC)
        return;
    /* A lamp's reflection has its corners in reverse order, to face back into the room. */
    Vec3 eye = camera_eye(scene);
    Statement *light = &scene->s[scene->count - 1];
    Vec3 centre = vec3(0, 0, 0);
    for (int k = 0; k < point_count(light); k++)
        centre = vec3_add(centre, vec3_scale(point_of(light, k), 1.0 / point_count(light)));
    Vec3 shift = vec3(eye.x - centre.x, eye.y - centre.y, 0.0);
    for (int k = 0; k < point_count(light); k++)
        set_point(light, k, vec3_add(point_of(light, k), shift));
    Statement below = *light;
    int points = point_count(light);
    for (int k = 0; k < points; k++) {
        Vec3 p = point_of(light, points == 4 ? (4 - k) % 4 : k);
        set_point(&below, k, vec3_sub(vec3_scale(eye, 2.0), p));
    }
    append(scene, below);
}

/* ---- the cases ------------------------------------------------------------------- */

typedef enum {
    CHANGE_NONE,
    CHANGE_SCALE,
    CHANGE_TRANSLATE,
    CHANGE_CAMERA_BACK,
    CHANGE_FAR_SPHERE,
    CHANGE_FAR_FLOOR,
    CHANGE_MIRROR_BEHIND,
    CHANGE_SPLIT_LAMPS,
    CHANGE_SPLIT_QUADS,
    CHANGE_REVERSE,
    CHANGE_FLIP
} ChangeKind;

typedef struct {
    ChangeKind kind;
    double amount; /* scale factor, translation or camera distance in scene sizes */
} Change;

typedef enum {
    JUDGED_BIT,
    JUDGED_AGREE
} Judged;

typedef struct {
    const char *name;
    SceneKind scene;
    Change base;       /* what the compared image is rendered from (usually nothing) */
    Change changed[2]; /* applied in order to the scene */
    Judged judged;
} Case;

static inline void apply_change(SceneText *scene, Change change)
{
    double size = scene_size(scene);
    switch (change.kind) {
    case CHANGE_NONE:
        break;
    case CHANGE_SCALE:
        move_scene(scene, change.amount, vec3(0, 0, 0));
        break;
    case CHANGE_TRANSLATE:
        move_scene(scene, 1.0, vec3_scale(vec3(0.62, -0.71, 0.33), change.amount * size));
        break;
    case CHANGE_CAMERA_BACK:
        camera_back(scene, change.amount * size);
        break;
    case CHANGE_FAR_SPHERE:
        add_far_sphere(scene);
        break;
    case CHANGE_FAR_FLOOR:
        extend_floor(scene);
        break;
    case CHANGE_MIRROR_BEHIND:
        add_mirror_behind(scene);
        break;
    case CHANGE_SPLIT_LAMPS:
        split_lamps(scene);
        break;
    case CHANGE_SPLIT_QUADS:
        split_quads(scene);
        break;
    case CHANGE_REVERSE:
        reverse_statements(scene);
        break;
    case CHANGE_FLIP:
        flip_scene(scene, camera_eye(scene).z);
        break;
    }
}

/* What the changed image is multiplied by before it is compared: a point light's
 * irradiance scales by 1 / s^2 when the scene does by s (move_scene). */
static inline double radiance_factor(const Case *c, int point_lights)
{
    double factor = 1.0;
    for (int i = 0; i < 2; i++)
        if (point_lights && c->changed[i].kind == CHANGE_SCALE)
            factor *= c->changed[i].amount * c->changed[i].amount;
    return factor;
}

#define NOTHING                                                                                \
    {                                                                                          \
        CHANGE_NONE, 0                                                                         \
    }
static const Case CASES[] = {
    {"scale 2^-40", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 0x1p-40}, NOTHING}, JUDGED_BIT},
    {"scale 2^50", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 0x1p50}, NOTHING}, JUDGED_BIT},
    {"scale 1e-3", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 1e-3}, NOTHING}, JUDGED_AGREE},
    {"scale 1e3", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 1e3}, NOTHING}, JUDGED_AGREE},
    {"scale 1e-12", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 1e-12}, NOTHING}, JUDGED_AGREE},
    {"scale 1e12", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 1e12}, NOTHING}, JUDGED_AGREE},
    {"scale 1e-40", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 1e-40}, NOTHING}, JUDGED_AGREE},
    {"scale 1e40", SCENE_ROOM, NOTHING, {{CHANGE_SCALE, 1e40}, NOTHING}, JUDGED_AGREE},
    {"translate 1e6 sizes",
     SCENE_ROOM,
     NOTHING,
     {{CHANGE_TRANSLATE, 1e6}, NOTHING},
     JUDGED_AGREE},
    {"camera back 1e8 (1e5)",
     SCENE_OPEN,
     {CHANGE_CAMERA_BACK, 1e5},
     {{CHANGE_CAMERA_BACK, 1e8}, NOTHING},
     JUDGED_AGREE},
    {"camera back 1e11 (1e5)",
     SCENE_OPEN,
     {CHANGE_CAMERA_BACK, 1e5},
     {{CHANGE_CAMERA_BACK, 1e11}, NOTHING},
     JUDGED_AGREE},
    {"far sphere", SCENE_ROOM, NOTHING, {{CHANGE_FAR_SPHERE, 0}, NOTHING}, JUDGED_BIT},
    {"floor far beyond the walls",
     SCENE_ROOM,
     NOTHING,
     {{CHANGE_FAR_FLOOR, 0}, NOTHING},
     JUDGED_AGREE},
    {"mirror behind the mirror",
     SCENE_ROOM,
     NOTHING,
     {{CHANGE_MIRROR_BEHIND, 0}, NOTHING},
     JUDGED_AGREE},
    {"lamp in two", SCENE_ROOM, NOTHING, {{CHANGE_SPLIT_LAMPS, 0}, NOTHING}, JUDGED_AGREE},
    {"quads in four triangles",
     SCENE_ROOM,
     NOTHING,
     {{CHANGE_SPLIT_QUADS, 0}, NOTHING},
     JUDGED_AGREE},
    {"statements reversed",
     SCENE_SYMMETRIC,
     NOTHING,
     {{CHANGE_REVERSE, 0}, NOTHING},
     JUDGED_AGREE},
    {"lamps symmetric, flipped",
     SCENE_SYMMETRIC,
     NOTHING,
     {{CHANGE_FLIP, 0}, NOTHING},
     JUDGED_AGREE},
};
#undef NOTHING
enum {
    CASE_COUNT = sizeof CASES / sizeof CASES[0]
};

#endif
