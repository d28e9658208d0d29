/* photon_estimate.c (chapter 8): the photon density estimate of reflected radiance.
 * See photon_estimate.h. */
#include "photon_estimate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diffuse.h"
#include "frame.h"

/* Lambert's f is the same for every photon, so it multiplies their summed power once. */
typedef struct {
    const PhotonMap *map;
    Vec3 n, wo;
    const Material *m;
    int lambert;
    Vec3 sum; /* sum of f * Phi (Lambert: of Phi) over the photons that count */
} Gather;

static void add_photon(int index, double distance2, void *context)
{
    Gather *g = context;
    const Photon *p = &g->map->photons[index];
    if (vec3_dot(p->normal, g->n) < PHOTON_NORMAL_COS || vec3_dot(p->incoming, g->n) <= 0.0)
        return;
    Vec3 weighted = g->lambert
                        ? p->power
                        : vec3_mul(diffuse_brdf(g->m, g->n, p->incoming, g->wo), p->power);
    g->sum = vec3_add(g->sum, weighted);
}

/* The area of the disc of radius r around x, on x's surface, that photons can reach:
 * the share of EDGE_POINTS points spread evenly over it (a sunflower: point i at radius
 * r sqrt((i + 1/2) / K), turned by the golden angle) that a ray from just above x
 * reaches on the same surface (at least one). A wall in the way stops the ray short;
 * past the edge of the surface it goes on. The pattern turns by an angle hashed from
 * x, so that its steps average out over neighbouring points. */
static double reachable_area(const Scene *scene, const Vertex *x, double r)
{
    Vec3 u, v, p = x->hit.point, n = x->normal;
    vec3_basis(n, &u, &v);
    Vec3 above = vec3_add_scaled(p, n, 0.1 * r);
    uint64_t bits[3];
    memcpy(bits, &p, sizeof bits);
    double turn =
        2.0 * PI * (rng_hash(bits[0] ^ rng_hash(bits[1] ^ rng_hash(bits[2]))) >> 11) * 0x1p-53;
    int reached = 0;
    for (int i = 0; i < EDGE_POINTS; i++) {
        double rho = r * sqrt((i + 0.5) / EDGE_POINTS), angle = turn + 2.39996322972865332 * i;
        Vec3 q = vec3_add_scaled(vec3_add_scaled(p, u, rho * cos(angle)), v, rho * sin(angle));
        Vec3 to_q = vec3_sub(q, above);
        double distance = vec3_length(to_q);
        Hit hit;
        reached += scene_intersect(scene, (Ray){above, vec3_scale(to_q, 1.0 / distance)},
                                   1.01 * distance, &hit) &&
                   hit.t > 0.99 * distance && vec3_dot(hit.normal, n) >= PHOTON_NORMAL_COS;
    }
    return PI * r * r * (reached > 0 ? reached : 1) / EDGE_POINTS;
}

Vec3 photon_estimate_radiance(const PhotonMap *map, double radius, Vec3 x, Vec3 n, Vec3 wo,
                              const Material *m)
{
    Gather g = {map, n, wo, m, m->kind == MATERIAL_LAMBERT, vec3(0, 0, 0)};
    point_grid_query_radius(&map->grid, x, radius, add_photon, &g);
    Vec3 sum = g.lambert ? vec3_mul(diffuse_brdf(m, n, wo, wo), g.sum) : g.sum;
    return vec3_scale(sum, 1.0 / (PI * radius * radius));
}

Vec3 photon_estimate_reachable(const Scene *scene, const PhotonMap *map, double radius,
                               const Vertex *x)
{
    Vec3 box =
        photon_estimate_radiance(map, radius, x->hit.point, x->normal, x->wo, x->material);
    if (box.x == 0.0 && box.y == 0.0 && box.z == 0.0)
        return box; /* no photons: no need to know the area */
    return vec3_scale(box, PI * radius * radius / reachable_area(scene, x, radius));
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* How deep the camera's view is: the median depth (along `axis`) of the first hits of
 * VIEW_RAYS^2 rays through the image plane, at least 1e-9 of the image plane's depth
 * and of the largest coordinate of the eye and the hits; if no ray hits, the distance to
 * the farthest lamp corner. */
static double view_depth(const Scene *scene, Vec3 axis, double plane_depth)
{
    const Camera *c = &scene->camera;
    double depths[VIEW_RAYS * VIEW_RAYS], size = fmax(vec3_max_abs(c->eye), plane_depth);
    double farthest = 0.0;
    int n = 0;
    for (int i = 0; i < VIEW_RAYS * VIEW_RAYS; i++) {
        Hit hit;
        Ray ray = camera_ray(c, VIEW_RAYS, VIEW_RAYS, i % VIEW_RAYS, i / VIEW_RAYS, 0.5, 0.5);
        if (scene_intersect(scene, ray, INFINITY, &hit)) {
            depths[n++] = vec3_dot(vec3_sub(hit.point, c->eye), axis);
            size = fmax(size, vec3_max_abs(hit.point));
        }
    }
    if (n > 0) {
        qsort(depths, (size_t)n, sizeof *depths, compare_doubles);
        return fmax(depths[n / 2], 1e-9 * size);
    }
    for (int i = 0; i < scene->light_count; i++) {
        const Triangle *t = &scene->triangles[scene->light_triangles[i]];
        for (int k = 0; k < 3; k++)
            farthest = fmax(farthest,
                            vec3_length(vec3_sub(triangle_point(t, k == 1, k == 2), c->eye)));
    }
    return farthest;
}

double ppm_first_radius(const Scene *scene, double fraction)
{
    const Camera *c = &scene->camera;
    Vec3 axis = vec3_normalize(vec3_cross(c->right, c->up));
    double plane_depth = vec3_dot(vec3_sub(c->bottom_left, c->eye), axis);
    if (plane_depth < 0.0) { /* the axis from the eye towards the image plane */
        axis = vec3_neg(axis);
        plane_depth = -plane_depth;
    }
    return fraction * vec3_length(c->right) * view_depth(scene, axis, plane_depth) /
           plane_depth;
}

double ppm_radius(double first_radius, double alpha, int pass)
{
    return first_radius * sqrt(pow((double)pass, alpha - 1.0));
}
