/* scene_file.c (bench, chapter 1): the scene format, version 1 (docs/scene-format.md).
 *
 * Each line is a keyword, a fixed number of words (a shape's material, or a new
 * material's name and kind) and a fixed number of decimal numbers; the table `forms`
 * below lists them all. Quads, boxes and tetrahedra become triangles (report §3.6.1).
 * Every check that can fail says where and what, and the scene is freed on failure,
 * so a bad file never becomes a half-built scene or a silently wrong image.
 */
#include "scene_file.h"

#include "material_names.h"

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <stdint.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The scales the reader accepts: numbers within +-NUMBER_MAX, and every shape (and the
 * camera's image plane) at least SIZE_MIN across. The geometry computes up to fourth
 * powers of a shape's size (the squared length of a cross product of two edges), and
 * those must stay well inside double precision's range, 1e-308 to 1e308: 1e77 already
 * overflows, 1e-80 underflows. Within this range the renderer works
 * at any scale (the ray offset is relative to the scene, ray.h). */
#define NUMBER_MAX 1e50
#define SIZE_MIN 1e-50

/* A shape thinner than this fraction of its size is flat: a triangle of zero area, a
 * non-planar quad, a tetrahedron of zero volume, a camera with a degenerate image plane.
 * Relative, so that the same scene scaled by 1e-12 or 1e12 reads the same. */
#define FLAT 1e-9

/* Emitted radiance, and point lights' intensity, above this are refused. A sample is
 * the emission times a gain (reflectances <= 1, a light's area over a squared
 * distance); 1e20 leaves that gain 18 orders of magnitude before the images' 32-bit
 * floats (at most 3.4e38) overflow; 1e100 gave +inf pixels. */
#define EMISSION_MAX 1e20

/* A scene file larger than this is refused, before more is read (/dev/zero gives up
 * at once instead of filling the memory). */
#define SCENE_BYTES_MAX ((size_t)64 << 20)
#define SCENE_BYTES_MAX_TEXT "64 MiB"

/* The kind of an oren_nayar material: a material kind from chapter 5 on; before it the
 * reader checks the line and then says which chapter introduces it. */
#if CHAPTER >= 5
#define OREN_NAYAR MATERIAL_OREN_NAYAR
#else
#define OREN_NAYAR (-1)
#endif

/* The most numbers a line holds (camera, quad, tetrahedron). */
#define NUMBERS_MAX 12

typedef struct {
    const char *name; /* file name, for messages */
    int line;         /* the line being read */
    int camera_line;  /* where the camera was declared, or 0 */
    Scene *scene;
    MaterialNames materials;
    char *error;
    size_t error_size;
} Reader;

typedef struct Form Form;

/* One line, split into what its form says it holds. */
typedef struct {
    const Form *form;
    const char *name; /* the first word: a new material's name, or a shape's material */
    int material;     /* shapes: the index of their material */
    double n[NUMBERS_MAX];
    const char *text[NUMBERS_MAX]; /* the numbers as written, for messages */
} Statement;

struct Form {
    const char *keyword;
    const char *kind_name; /* materials: the kind's name (their third token) */
    int kind;              /* materials: a MaterialKind, or OREN_NAYAR */
    int words;             /* tokens between the keyword and the numbers */
    int numbers;
    int (*read)(Reader *r, const Statement *s);
    const char *usage;
};

/* Write "NAME:LINE: reason" into error[size]. A name too long to leave room for the
 * rest is shortened in its middle, "start...end", so that the line and the reason are
 * always there, however long the path. */
static void write_message(char *error, size_t size, const char *name, int line,
                          const char *reason)
{
    char rest[640];
    int rest_length = snprintf(rest, sizeof rest, ":%d: %s", line, reason);
    size_t name_length = strlen(name), room = size - 1;
    if (rest_length < 0 || name_length + (size_t)rest_length <= room ||
        room < (size_t)rest_length + 3 + 16) {
        snprintf(error, size, "%s%s", name, rest); /* whole, or a buffer too small to help */
        return;
    }
    size_t keep = room - (size_t)rest_length - 3; /* the name's bytes around the "..." */
    size_t head = keep / 3, tail = keep - head;
    snprintf(error, size, "%.*s...%s%s", (int)head, name, name + name_length - tail, rest);
}

/* Report "NAME:LINE: message" into the error buffer. Always returns -1. */
static int fail(Reader *r, const char *format, ...)
{
    char reason[512];
    va_list args;
    va_start(args, format);
    vsnprintf(reason, sizeof reason, format, args);
    va_end(args);
    if (r->error_size > 0)
        write_message(r->error, r->error_size, r->name, r->line, reason);
    return -1;
}

static Vec3 point(const double *n) { return vec3(n[0], n[1], n[2]); }

static double distance(Vec3 a, Vec3 b) { return vec3_length(vec3_sub(b, a)); }

/* The largest distance between any two of `count` points. */
static double size_of(const Vec3 *p, int count)
{
    double size = 0.0;
    for (int i = 0; i < count; i++)
        for (int j = i + 1; j < count; j++)
            size = fmax(size, distance(p[i], p[j]));
    return size;
}

/* A shape's size (the largest distance between two of its `count` corners), with its
 * corners in its own units in unit[]: each corner minus the first, divided by the
 * shape's extent (the largest difference of two corners' coordinates). Lengths, areas
 * and volumes are then near 1, so the flatness tests below are the same at every scale:
 * computed as they stand, a square of a length below about 1e-154 underflows to 0 (a
 * shape of any area would seem flat) and a fourth power above 1e77 overflows. An extent
 * too small to divide by (0, or a subnormal number) is returned as the size: such a shape
 * is a point, or far below SIZE_MIN. */
static double shape_size(const Vec3 *p, int count, Vec3 *unit)
{
    double extent = 0.0;
    for (int i = 0; i < count; i++)
        for (int j = i + 1; j < count; j++)
            extent = fmax(extent, vec3_max_abs(vec3_sub(p[i], p[j])));
    if (!(extent >= DBL_MIN))
        return extent;
    for (int i = 0; i < count; i++)
        unit[i] = vec3_scale(vec3_sub(p[i], p[0]), 1.0 / extent);
    return extent * size_of(unit, count);
}

/* Whether a shape of this size (not 0: that is a degenerate shape) is below SIZE_MIN. */
static int size_too_small(double size) { return size > 0.0 && size < SIZE_MIN; }

static int fail_too_small(Reader *r, const char *what, double size)
{
    return fail(r, "%s %g across is too small: the reader takes sizes from %g to %g", what,
                size, SIZE_MIN, NUMBER_MAX);
}

/* Add triangle (a, b, c), front side (b - a) x (c - a), unless it has no area. */
static int add_triangle(Reader *r, const Statement *s, Vec3 a, Vec3 b, Vec3 c)
{
    Vec3 corners[3] = {a, b, c}, unit[3];
    double size = shape_size(corners, 3, unit);
    if (size_too_small(size))
        return fail_too_small(r, s->form->keyword, size);
    if (size == 0.0)
        return fail(r, "degenerate %s (zero area: its corners are one point)",
                    s->form->keyword);
    double unit_size = size_of(unit, 3);
    double twice_area = vec3_length(vec3_cross(unit[1], unit[2]));
    if (!(twice_area > FLAT * unit_size * unit_size))
        return fail(r, "degenerate %s (zero area)", s->form->keyword);
    if (scene_add_triangle(r->scene, triangle_make(a, b, c, s->material)) < 0)
        return fail(r, "out of memory");
    return 0;
}

/* A quad's two triangles (P0, P1, P2) and (P0, P2, P3). */
static int add_quad(Reader *r, const Statement *s, const Vec3 *p)
{
    if (add_triangle(r, s, p[0], p[1], p[2]) != 0)
        return -1;
    return add_triangle(r, s, p[0], p[2], p[3]);
}

static int read_camera(Reader *r, const Statement *s)
{
    if (r->camera_line > 0)
        return fail(r, "a second camera (the first is on line %d)", r->camera_line);
    Vec3 eye = point(s->n), bl = point(s->n + 3), br = point(s->n + 6), tl = point(s->n + 9);
    Vec3 corners[3] = {bl, br, tl}, unit[3];
    double size = shape_size(corners, 3, unit);
    if (size_too_small(size))
        return fail_too_small(r, "camera: the image plane", size);
    if (size == 0.0)
        return fail(r, "degenerate camera: the image plane's corners are one point");
    Vec3 right = unit[1], up = unit[2], normal = vec3_cross(right, up);
    double unit_size = size_of(unit, 3);
    if (!(vec3_length(normal) > FLAT * unit_size * unit_size))
        return fail(r, "degenerate camera: the image plane's corners are collinear");
    Vec3 eye_unit = vec3_scale(vec3_sub(eye, bl), unit_size / size);
    double eye_height = fabs(vec3_dot(eye_unit, vec3_normalize(normal)));
    if (!(eye_height > FLAT * fmax(unit_size, vec3_length(eye_unit))))
        return fail(r, "degenerate camera: the eye is on the image plane");
    r->camera_line = r->line;
    r->scene->camera = camera_make(eye, bl, br, tl);
    return 0;
}

static int in_unit_interval(Vec3 c)
{
    return c.x >= 0.0 && c.x <= 1.0 && c.y >= 0.0 && c.y <= 1.0 && c.z >= 0.0 && c.z <= 1.0;
}

static int is_non_negative(Vec3 c) { return c.x >= 0.0 && c.y >= 0.0 && c.z >= 0.0; }

static int read_material(Reader *r, const Statement *s)
{
    if (strlen(s->name) >= MATERIAL_NAME_MAX)
        return fail(r, "material name longer than %d bytes", MATERIAL_NAME_MAX - 1);
    if (material_names_find(&r->materials, r->scene, s->name, NULL) >= 0)
        return fail(r, "duplicate material '%s'", s->name);
    Material m;
    memset(&m, 0, sizeof m);
    strcpy(m.name, s->name);
    m.kind = (MaterialKind)s->form->kind;
    Vec3 colour = point(s->n);
    if (m.kind == MATERIAL_GLASS) {
        if (!(s->n[0] > 0.0))
            return fail(r, "index of refraction %.40s must be > 0", s->text[0]);
        m.ior = s->n[0];
    } else if (m.kind == MATERIAL_LIGHT) {
        if (!is_non_negative(colour))
            return fail(r, "negative emission %.40s %.40s %.40s", s->text[0], s->text[1],
                        s->text[2]);
        if (!(vec3_max_component(colour) <= EMISSION_MAX))
            return fail(r,
                        "emission %.40s %.40s %.40s above %g: the image's radiance must stay "
                        "finite",
                        s->text[0], s->text[1], s->text[2], EMISSION_MAX);
        m.emission = colour;
    } else {
        if (!in_unit_interval(colour))
            return fail(r, "reflectance %.40s %.40s %.40s outside [0, 1]", s->text[0],
                        s->text[1], s->text[2]);
        m.reflectance = colour;
    }
    if (s->form->kind == OREN_NAYAR) {
        if (!(s->n[3] >= 0.0))
            return fail(r, "negative sigma %.40s (the roughness is >= 0)", s->text[3]);
#if CHAPTER >= 5
        m.sigma = s->n[3];
#else
        return fail(r, "material '%s' is oren_nayar, which chapter 5 introduces", s->name);
#endif
    }
    int index = scene_add_material(r->scene, m);
    if (index < 0 || material_names_add(&r->materials, r->scene, index) != 0)
        return fail(r, "out of memory");
    return 0;
}

static int read_triangle(Reader *r, const Statement *s)
{
    return add_triangle(r, s, point(s->n), point(s->n + 3), point(s->n + 6));
}

/* A quad must be flat and convex: then its two triangles cover it and face one way. */
static int read_quad(Reader *r, const Statement *s)
{
    Vec3 p[4] = {point(s->n), point(s->n + 3), point(s->n + 6), point(s->n + 9)}, unit[4];
    double size = shape_size(p, 4, unit);
    if (size_too_small(size))
        return fail_too_small(r, "quad", size);
    double unit_size = size_of(unit, 4);
    Vec3 normal = vec3_cross(unit[1], unit[2]);
    if (size == 0.0 || !(vec3_length(normal) > FLAT * unit_size * unit_size))
        return fail(r, "degenerate quad (zero area)");
    normal = vec3_normalize(normal);
    if (!(fabs(vec3_dot(unit[3], normal)) <= FLAT * unit_size))
        return fail(r, "non-planar quad: P3 is off the plane of P0, P1, P2");
    /* Convex: at every corner the boundary turns the same way, about the normal. */
    for (int i = 0; i < 4; i++) {
        Vec3 in = vec3_sub(unit[i], unit[(i + 3) % 4]),
             out = vec3_sub(unit[(i + 1) % 4], unit[i]);
        if (!(vec3_dot(vec3_cross(in, out), normal) > FLAT * unit_size * unit_size))
            return fail(r,
                        "non-convex quad: P%d is not a convex corner "
                        "(the corners must go round the quad in order)",
                        i);
    }
    return add_quad(r, s, p);
}

static int read_sphere(Reader *r, const Statement *s)
{
    if (r->scene->materials[s->material].kind == MATERIAL_LIGHT)
        return fail(r, "a sphere cannot be a light: area lights are triangles, quads, "
                       "boxes or tetrahedra");
    if (!(s->n[3] > 0.0))
        return fail(r, "sphere radius %.40s must be > 0", s->text[3]);
    if (size_too_small(s->n[3]))
        return fail_too_small(r, "sphere: a radius of", s->n[3]);
    Sphere sphere = {point(s->n), s->n[3], s->material};
    if (scene_add_sphere(r->scene, sphere) < 0)
        return fail(r, "out of memory");
    return 0;
}

/* Six faces of two triangles each. The face across `axis` at the `side` (0: min,
 * 1: max) has its corners in the plane of the next two axes b, c = axis + 1, axis + 2
 * (cyclically), and e_b x e_c = e_axis: going round the unit square in the (b, c)
 * plane counter-clockwise faces +axis (outward on the max side), clockwise -axis. */
static int read_box(Reader *r, const Statement *s)
{
    const double *low = s->n, *high = s->n + 3;
    if (!(low[0] < high[0] && low[1] < high[1] && low[2] < high[2]))
        return fail(r, "box needs XMIN < XMAX, YMIN < YMAX and ZMIN < ZMAX");
    static const int square[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int axis = 0; axis < 3; axis++) {
        for (int side = 0; side < 2; side++) {
            Vec3 face[4];
            for (int i = 0; i < 4; i++) {
                const int *corner = square[side ? i : (4 - i) % 4];
                double p[3];
                p[axis] = side ? high[axis] : low[axis];
                p[(axis + 1) % 3] = corner[0] ? high[(axis + 1) % 3] : low[(axis + 1) % 3];
                p[(axis + 2) % 3] = corner[1] ? high[(axis + 2) % 3] : low[(axis + 2) % 3];
                face[i] = point(p);
            }
            if (add_quad(r, s, face) != 0)
                return -1;
        }
    }
    return 0;
}

/* Four faces, each turned away from the vertex it does not contain. */
static int read_tetrahedron(Reader *r, const Statement *s)
{
    Vec3 p[4] = {point(s->n), point(s->n + 3), point(s->n + 6), point(s->n + 9)}, unit[4];
    double size = shape_size(p, 4, unit);
    if (size_too_small(size))
        return fail_too_small(r, "tetrahedron", size);
    double unit_size = size_of(unit, 4);
    double six_volume = vec3_dot(unit[1], vec3_cross(unit[2], unit[3]));
    if (size == 0.0 || !(fabs(six_volume) > FLAT * unit_size * unit_size * unit_size))
        return fail(r, "flat tetrahedron (zero volume)");
    for (int opposite = 0; opposite < 4; opposite++) {
        Vec3 a = unit[(opposite + 1) % 4], b = unit[(opposite + 2) % 4],
             c = unit[(opposite + 3) % 4];
        Vec3 normal = vec3_cross(vec3_sub(b, a), vec3_sub(c, a));
        int faces_opposite = vec3_dot(normal, vec3_sub(unit[opposite], a)) > 0.0;
        Vec3 pa = p[(opposite + 1) % 4], pb = p[(opposite + 2) % 4], pc = p[(opposite + 3) % 4];
        if (add_triangle(r, s, pa, faces_opposite ? pc : pb, faces_opposite ? pb : pc) != 0)
            return -1;
    }
    return 0;
}

static int read_point_light(Reader *r, const Statement *s)
{
    PointLight light = {point(s->n), point(s->n + 3)};
    if (!is_non_negative(light.intensity))
        return fail(r, "negative point_light intensity");
    if (!(vec3_max_component(light.intensity) <= EMISSION_MAX))
        return fail(r,
                    "point_light intensity above %g: the image's radiance must stay "
                    "finite",
                    EMISSION_MAX);
    if (scene_add_point_light(r->scene, light) < 0)
        return fail(r, "out of memory");
    return 0;
}

/* Every form a line can take. */
static const Form forms[] = {
    /* keyword      kind name     kind                 words numbers reader */
    {"camera", NULL, 0, 0, 12, read_camera,
     "camera EX EY EZ  BLX BLY BLZ  BRX BRY BRZ  TLX TLY TLZ"},
    {"material", "lambert", MATERIAL_LAMBERT, 2, 3, read_material,
     "material NAME lambert R G B"},
    {"material", "oren_nayar", OREN_NAYAR, 2, 4, read_material,
     "material NAME oren_nayar R G B SIGMA"},
    {"material", "mirror", MATERIAL_MIRROR, 2, 3, read_material, "material NAME mirror R G B"},
    {"material", "glass", MATERIAL_GLASS, 2, 1, read_material, "material NAME glass IOR"},
    {"material", "light", MATERIAL_LIGHT, 2, 3, read_material, "material NAME light R G B"},
    {"triangle", NULL, 0, 1, 9, read_triangle, "triangle MAT  X0 Y0 Z0  X1 Y1 Z1  X2 Y2 Z2"},
    {"quad", NULL, 0, 1, 12, read_quad, "quad MAT  P0 P1 P2 P3, each X Y Z"},
    {"sphere", NULL, 0, 1, 4, read_sphere, "sphere MAT  CX CY CZ R"},
    {"box", NULL, 0, 1, 6, read_box, "box MAT  XMIN YMIN ZMIN  XMAX YMAX ZMAX"},
    {"tetrahedron", NULL, 0, 1, 12, read_tetrahedron,
     "tetrahedron MAT  P0 P1 P2 P3, each X Y Z"},
    {"point_light", NULL, 0, 0, 6, read_point_light, "point_light  X Y Z  R G B"},
};

#define KIND_NAMES "lambert, oren_nayar, mirror, glass or light"

/* The form of the line tokens[0..count), or NULL after reporting why there is none. */
static const Form *find_form(Reader *r, char **tokens, int count)
{
    int keyword_known = 0;
    for (size_t i = 0; i < sizeof forms / sizeof forms[0]; i++) {
        const Form *form = &forms[i];
        if (strcmp(tokens[0], form->keyword) != 0)
            continue;
        keyword_known = 1;
        if (!form->kind_name || (count > 2 && strcmp(tokens[2], form->kind_name) == 0))
            return form;
    }
    if (!keyword_known)
        fail(r, "unknown keyword '%.40s'", tokens[0]);
    else if (count < 3)
        fail(r, "a material needs a name and a kind (" KIND_NAMES ")");
    else
        fail(r, "unknown material kind '%.40s' (" KIND_NAMES ")", tokens[2]);
    return NULL;
}

/* A decimal number: [+-] digits [. digits] [e [+-] digits], with a digit before or
 * after the point. No "nan", "inf", hexadecimal or trailing characters. */
static int is_decimal(const char *s)
{
    const char *digits = "0123456789";
    s += *s == '+' || *s == '-';
    size_t mantissa = strspn(s, digits);
    s += mantissa;
    if (*s == '.') {
        size_t fraction = strspn(s + 1, digits);
        mantissa += fraction;
        s += 1 + fraction;
    }
    if (mantissa == 0)
        return 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        s += *s == '+' || *s == '-';
        size_t exponent = strspn(s, digits);
        if (exponent == 0)
            return 0;
        s += exponent;
    }
    return *s == '\0';
}

static int read_number(Reader *r, const char *token, double *value)
{
    if (!is_decimal(token))
        return fail(r, "'%.40s' is not a decimal number", token);
    errno = 0;
    *value = strtod(token, NULL);
    if ((errno == ERANGE && fabs(*value) < 1.0) || (*value != 0.0 && fabs(*value) < DBL_MIN))
        return fail(r,
                    "'%.40s' is too small to compute with: below %g, the smallest double "
                    "with all its digits (write 0 for zero)",
                    token, DBL_MIN);
    if (!(fabs(*value) <= NUMBER_MAX))
        return fail(r,
                    "'%.40s' is out of range: numbers are finite and within +-%g "
                    "(the scales the reader takes)",
                    token, NUMBER_MAX);
    return 0;
}

/* One non-blank line, split into tokens[0..count). */
static int read_statement(Reader *r, char **tokens, int count)
{
    Statement s;
    memset(&s, 0, sizeof s);
    s.form = find_form(r, tokens, count);
    if (!s.form)
        return -1;
    int numbers = count - 1 - s.form->words;
    if (numbers != s.form->numbers)
        return fail(r, "expected %d numbers, found %d (%s)", s.form->numbers,
                    numbers < 0 ? 0 : numbers, s.form->usage);
    for (int i = 0; i < numbers; i++) {
        s.text[i] = tokens[1 + s.form->words + i];
        if (read_number(r, s.text[i], &s.n[i]) != 0)
            return -1;
    }
    s.name = s.form->words > 0 ? tokens[1] : NULL;
    s.material = -1;
    /* A shape's one word is the name of its material. */
    if (s.form->words == 1) {
        s.material = material_names_find(&r->materials, r->scene, s.name, NULL);
        if (s.material < 0)
            return fail(r, "unknown material '%.40s' (materials are defined before use)",
                        s.name);
    }
    return s.form->read(r, &s);
}

/* Split `line` in place at white space; the comment is already cut off. Returns the
 * number of tokens. */
static int split(char *line, char **tokens)
{
    int count = 0;
    for (char *p = line; *p;) {
        while (isspace((unsigned char)*p))
            p++;
        if (!*p)
            break;
        tokens[count++] = p;
        while (*p && !isspace((unsigned char)*p))
            p++;
        if (*p)
            *p++ = '\0';
    }
    return count;
}

/* The code point of the UTF-8 sequence at p[0..n), or -1 if it is not one (a stray
 * byte, an overlong form, a surrogate). */
static long utf8_code_point(const unsigned char *p, size_t n)
{
    int length = p[0] >= 0xF0 ? 4 : p[0] >= 0xE0 ? 3 : p[0] >= 0xC0 ? 2 : 0;
    static const long smallest[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (length == 0 || p[0] >= 0xF8 || (size_t)length > n)
        return -1;
    long code = p[0] & (0x7F >> length);
    for (int i = 1; i < length; i++) {
        if ((p[i] & 0xC0) != 0x80)
            return -1;
        code = code << 6 | (p[i] & 0x3F);
    }
    if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
        return -1;
    return code;
}

/* What an editor or a copy from a web page or a word processor puts into text unseen. */
static const char *character_name(long code)
{
    switch (code) {
    case 0x00A0:
        return " (a no-break space?)";
    case 0x2009:
        return " (a thin space?)";
    case 0x200B:
        return " (a zero-width space?)";
    case 0x202F:
        return " (a narrow no-break space?)";
    case 0xFEFF:
        return " (a byte order mark?)";
    case 0x2212:
        return " (a minus sign? write '-')";
    case 0x2013:
        return " (an en dash? write '-')";
    default:
        return "";
    }
}

/* Outside comments a scene is plain ASCII: report the first other byte of line[0..n),
 * by its code point when it starts a UTF-8 character, never as the raw bytes (which
 * may be invisible). Returns 0 when there is none. */
static int check_ascii(Reader *r, const char *line, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)line[i];
        if (c >= 0x20 && c < 0x7F)
            continue;
        if (c == '\t' || c == '\v' || c == '\f')
            continue;
        if (c < 0x80)
            return fail(r, "control character 0x%02X in column %zu", c, i + 1);
        long code = utf8_code_point((const unsigned char *)line + i, n - i);
        if (code < 0)
            return fail(r,
                        "byte 0x%02X in column %zu is not ASCII (nor UTF-8): outside "
                        "comments, a scene file is plain ASCII",
                        c, i + 1);
        return fail(r,
                    "non-ASCII character U+%04lX%s in column %zu: outside comments, a "
                    "scene file is plain ASCII",
                    code, character_name(code), i + 1);
    }
    return 0;
}

/* The length of the line at `start` (ending at \n, \r\n or \r, or at `end`); *next is
 * where the following line begins. */
static size_t line_length(const char *start, const char *end, const char **next)
{
    const char *p = start;
    while (p < end && *p != '\n' && *p != '\r')
        p++;
    *next = p == end ? end : p + 1 + (*p == '\r' && p + 1 < end && p[1] == '\n');
    return (size_t)(p - start);
}

/* Read every line of the text; the scene is complete but not yet checked as a whole.
 * A UTF-8 byte order mark at the very start is skipped (editors on Windows add it). */
static int read_lines(Reader *r, const char *text, size_t length)
{
    char line[SCENE_LINE_MAX + 1];
    char *tokens[SCENE_LINE_MAX / 2 + 1];
    const char *end = text + length;
    const char *start = text;
    if (length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
        start += 3;
    while (start < end) {
        if (r->line == INT_MAX)
            return fail(r, "more than %d lines", INT_MAX);
        r->line++;
        const char *next;
        size_t n = line_length(start, end, &next);
        if (n > SCENE_LINE_MAX)
            return fail(r, "line longer than %d bytes", SCENE_LINE_MAX);
        if (memchr(start, '\0', n))
            return fail(r, "a NUL byte in the text");
        const char *comment = memchr(start, '#', n);
        size_t statement = comment ? (size_t)(comment - start) : n;
        if (check_ascii(r, start, statement) != 0)
            return -1;
        memcpy(line, start, statement);
        line[statement] = '\0';
        int count = split(line, tokens);
        if (count > 0 && read_statement(r, tokens, count) != 0)
            return -1;
        start = next;
    }
    return 0;
}

uint64_t scene_hash(uint64_t hash, const void *data, size_t size)
{
    const unsigned char *bytes = data;
    for (size_t i = 0; i < size; i++) {
        hash ^= bytes[i];
        hash *= 0x100000001b3ULL; /* the 64-bit FNV prime */
    }
    return hash;
}

int scene_parse(const char *text, size_t length, const char *name, Scene *scene,
                SceneFileInfo *info, char *error, size_t error_size)
{
    Reader r = {name, 0, 0, scene, {NULL, 0}, error, error_size};
    scene_init(scene);
    int status = read_lines(&r, text, length);
    if (status == 0 && r.camera_line == 0)
        status = fail(&r, "no camera (a scene declares exactly one)");
    if (status == 0 && scene_prepare(scene) != 0)
        status = fail(&r, "out of memory");
    material_names_free(&r.materials);
    if (status != 0) {
        scene_free(scene);
        return -1;
    }
    if (info) {
        info->hash = scene_hash(SCENE_HASH_START, text, length);
        info->line_count = r.line;
    }
    return 0;
}

int scene_file_material(const Scene *scene, const char *name)
{
    for (int i = 0; i < scene->material_count; i++)
        if (strcmp(scene->materials[i].name, name) == 0)
            return i;
    return -1;
}

/* Read the whole file once, up to SCENE_BYTES_MAX, or report why not at line 0. Pipes,
 * FIFOs and /dev/stdin are read like files: the bytes are kept, never read again. */
int scene_file_read(const char *path, char **text_out, size_t *length_out, char *error,
                    size_t error_size)
{
    Reader r = {path, 0, 0, NULL, {NULL, 0}, error, error_size};
    FILE *file = fopen(path, "rb");
    if (!file)
        return fail(&r, "cannot open: %s", strerror(errno));
    struct stat info;
    int known = fstat(fileno(file), &info) == 0;
    if (known && S_ISDIR(info.st_mode)) {
        fclose(file);
        return fail(&r, "cannot read: %s", strerror(EISDIR));
    }
    if (known && S_ISREG(info.st_mode) && (uintmax_t)info.st_size > SCENE_BYTES_MAX) {
        fclose(file);
        return fail(&r,
                    "larger than " SCENE_BYTES_MAX_TEXT " (%jd bytes), the limit for a "
                    "scene file",
                    (intmax_t)info.st_size);
    }
    char *text = NULL;
    size_t length = 0, capacity = 0;
    int status = 0;
    for (;;) {
        if (length == capacity) {
            if (capacity > SCENE_BYTES_MAX) {
                status = fail(&r, "larger than " SCENE_BYTES_MAX_TEXT
                                  ", the limit for a scene file");
                break;
            }
            /* Doubling, up to one byte beyond the limit: enough to see it passed. */
            capacity = capacity ? 2 * capacity : 4096;
            if (capacity > SCENE_BYTES_MAX)
                capacity = SCENE_BYTES_MAX + 1;
            char *grown = realloc(text, capacity);
            if (!grown) {
                status = fail(&r, "out of memory");
                break;
            }
            text = grown;
        }
        length += fread(text + length, 1, capacity - length, file);
        if (ferror(file)) {
            status = fail(&r, "cannot read: %s", strerror(errno));
            break;
        }
        if (feof(file))
            break;
    }
    fclose(file);
    if (status != 0) {
        free(text);
        return -1;
    }
    *text_out = text;
    *length_out = length;
    return 0;
}

int scene_load(const char *path, Scene *scene, char *error, size_t error_size)
{
    scene_init(scene);
    char *text;
    size_t length;
    if (scene_file_read(path, &text, &length, error, error_size) != 0)
        return -1;
    int status = scene_parse(text, length, path, scene, NULL, error, error_size);
    free(text);
    return status;
}

double scene_file_aspect(const Camera *camera)
{
    return vec3_length(camera->right) / vec3_length(camera->up);
}
