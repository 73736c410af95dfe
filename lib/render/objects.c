/* The scene's obstacles and container (the glass) as lit meshes.
 *
 * The shapes give only a signed distance (ms_shape_distance), so each one
 * is meshed once, in its own frame, by surface nets over a lattice on its
 * bounds (mesh_shape). Each frame the mesh is moved by the shape's pose:
 * placed as the sim places it (ms_sim_shape_place: path, the engine's
 * moves and turns), so it is drawn where it blocks the water. The GL side
 * draws obstacles opaque, the glass as glass (gl_glass.c), and both into
 * the environment cubemap too (gl_env.c), so the liquid's shader shows
 * them refracted under the surface and reflected above it. Unbounded
 * shapes (a plane) are not drawn: the pool's floor shows them. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/render_internal.h"
#include "shape/shape_internal.h"
#include "sim/sim_internal.h"

/* Cells along the largest extent of the shape's bounds, and at least
 * MIN_CELLS along the others: the glass of data/scenes/glass.json (16 cm
 * tall) gets 4 mm cells, 2.5 across its 1 cm wall (60 made 2.3x the
 * triangles for no visible gain). */
#define OBJ_CELLS 40
#define MIN_CELLS 12

/* Linear RGB: obstacles a light stone, the glass a pale blue-white. */
static const float stone[3] = {0.55f, 0.53f, 0.50f};
static const float glass_tint[3] = {0.70f, 0.80f, 0.85f};

/* (x, y, z) moved onto the surface along the distance's gradient. */
static void project(const ms_shape *s, float p[3])
{
    for (int k = 0; k < 4; ++k) {
        float n[3];
        float d = ms_shape_distance(s, p, n);
        p[0] -= d * n[0], p[1] -= d * n[1], p[2] -= d * n[2];
    }
}

/* The sampling lattice: n[k] + 1 points along axis k from o[k], c[k] apart. */
typedef struct lattice {
    int n[3];
    float o[3], c[3];
    float *d;  /* signed distances at the points, x fastest */
    int *cell; /* per cell: its vertex (or -1) */
} lattice;

static size_t point(const lattice *L, int i, int j, int k)
{
    return ((size_t)k * (L->n[1] + 1) + (size_t)j) * (L->n[0] + 1) + (size_t)i;
}

static size_t cell(const lattice *L, int i, int j, int k)
{
    return ((size_t)k * L->n[1] + (size_t)j) * L->n[0] + (size_t)i;
}

/* The local mesh of s (at the origin, unturned), 6 floats a vertex, by
 * surface nets (Gibson 1998): a vertex in each lattice cell the surface
 * crosses, at the mean of the crossings on the cell's edges, moved onto
 * the surface, with the distance's gradient as its normal; a quad across
 * each lattice edge the surface crosses, joining the four cells around
 * it. Smooth and watertight for any shape whose features are a few cells
 * wide (the glass's wall, a box's thickness); before, two height maps
 * (top and bottom) left the vertical walls to stretched triangles whose
 * normals ran from the rim's to the wall's, which showed as streaks. */
static ms_status mesh_shape(ms_render_object *ob)
{
    const ms_shape *s = ob->shape;
    float lo[3], hi[3];
    ms_shape_bounds(s, lo, hi);
    for (int k = 0; k < 3; ++k)
        if (!isfinite(lo[k]) || !isfinite(hi[k]) || hi[k] - lo[k] > 1e3f || hi[k] <= lo[k])
            return MS_OK; /* unbounded: not drawn */
    const float ext = MS_MAX(hi[0] - lo[0], MS_MAX(hi[1] - lo[1], hi[2] - lo[2]));
    lattice L = {{0}, {0}, {0}, NULL, NULL};
    for (int k = 0; k < 3; ++k) {
        const float e = hi[k] - lo[k];
        L.c[k] = MS_MIN(ext / OBJ_CELLS, e / MIN_CELLS);
        L.n[k] = (int)ceilf(e / L.c[k]) + 2; /* a cell of margin each side */
        L.o[k] = 0.5f * (lo[k] + hi[k]) - 0.5f * (float)L.n[k] * L.c[k];
    }
    const size_t npts = (size_t)(L.n[0] + 1) * (L.n[1] + 1) * (L.n[2] + 1);
    const size_t ncells = (size_t)L.n[0] * L.n[1] * L.n[2];
    L.d = ms_alloc_array(npts, sizeof *L.d);
    L.cell = ms_alloc_array(ncells, sizeof *L.cell);
    float *verts = ms_alloc_array(ncells, 6 * sizeof(float)); /* at most one a cell */
    size_t nquads = 0;
    if (!L.d || !L.cell || !verts)
        goto oom;
    for (int k = 0; k <= L.n[2]; ++k)
        for (int j = 0; j <= L.n[1]; ++j)
            for (int i = 0; i <= L.n[0]; ++i) {
                const float p[3] = {L.o[0] + (float)i * L.c[0], L.o[1] + (float)j * L.c[1],
                                    L.o[2] + (float)k * L.c[2]};
                L.d[point(&L, i, j, k)] = ms_shape_distance(s, p, NULL);
            }
    int nv = 0;
    for (int k = 0; k < L.n[2]; ++k)
        for (int j = 0; j < L.n[1]; ++j)
            for (int i = 0; i < L.n[0]; ++i) {
                float sum[3] = {0, 0, 0};
                int crossings = 0;
                for (int e = 0; e < 12; ++e) {
                    /* edge e: axis e / 4, the other two corners' offsets e % 4 */
                    const int ax = e / 4, u = e & 1, v = (e >> 1) & 1;
                    int a[3], b[3];
                    a[ax] = 0, a[(ax + 1) % 3] = u, a[(ax + 2) % 3] = v;
                    memcpy(b, a, sizeof b);
                    b[ax] = 1;
                    const float da = L.d[point(&L, i + a[0], j + a[1], k + a[2])];
                    const float db = L.d[point(&L, i + b[0], j + b[1], k + b[2])];
                    if ((da <= 0) == (db <= 0))
                        continue;
                    const float t = da / (da - db);
                    for (int q = 0; q < 3; ++q)
                        sum[q] += ((float)((q == 0   ? i
                                            : q == 1 ? j
                                                     : k) +
                                           a[q]) +
                                   (q == ax ? t : 0.0f)) *
                                      L.c[q] +
                                  L.o[q];
                    ++crossings;
                }
                L.cell[cell(&L, i, j, k)] = crossings ? nv : -1;
                if (!crossings)
                    continue;
                float *o = verts + 6 * (size_t)nv++;
                for (int q = 0; q < 3; ++q)
                    o[q] = sum[q] / (float)crossings;
                float p[3] = {o[0], o[1], o[2]};
                project(s, p);
                /* keep it in its cell's neighbourhood (a thin feature's far side) */
                for (int q = 0; q < 3; ++q)
                    if (fabsf(p[q] - o[q]) < L.c[q])
                        o[q] = p[q];
                ms_shape_distance(s, o, o + 3);
            }
    /* quads: each interior lattice edge with a crossing */
    for (int pass = 0; pass < 2; ++pass) {
        size_t q = 0;
        for (int k = 1; k < L.n[2]; ++k)
            for (int j = 1; j < L.n[1]; ++j)
                for (int i = 1; i < L.n[0]; ++i) {
                    const float d0 = L.d[point(&L, i, j, k)];
                    for (int ax = 0; ax < 3; ++ax) {
                        int b[3] = {i, j, k};
                        b[ax]++;
                        if (b[ax] > L.n[ax])
                            continue;
                        const float d1 = L.d[point(&L, b[0], b[1], b[2])];
                        if ((d0 <= 0) == (d1 <= 0))
                            continue;
                        /* the four cells around the edge from (i, j, k) along ax */
                        const int u = (ax + 1) % 3, v = (ax + 2) % 3;
                        int c4[4];
                        static const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
                        for (int m = 0; m < 4; ++m) {
                            int c[3] = {i, j, k};
                            c[u] -= du[m], c[v] -= dv[m];
                            c4[m] = L.cell[cell(&L, c[0], c[1], c[2])];
                        }
                        if (c4[0] < 0 || c4[1] < 0 || c4[2] < 0 || c4[3] < 0)
                            continue;
                        if (pass == 1) {
                            /* counter-clockwise seen from outside (d > 0) */
                            const int flip = d0 <= 0;
                            static const int order[2][6] = {{0, 1, 2, 0, 2, 3}, {0, 2, 1, 0, 3, 2}};
                            for (int m = 0; m < 6; ++m)
                                memcpy(ob->local + 6 * (6 * q + (size_t)m),
                                       verts + 6 * (size_t)c4[order[flip][m]], 6 * sizeof(float));
                        }
                        ++q;
                    }
                }
        if (pass == 0) {
            nquads = q;
            ob->local = ms_alloc_array(nquads ? 6 * nquads : 1, 6 * sizeof(float));
            if (!ob->local)
                goto oom;
        }
    }
    ms_free(L.d);
    ms_free(L.cell);
    ms_free(verts);
    ob->nverts = (int)(6 * nquads);
    return MS_OK;
oom:
    ms_free(L.d);
    ms_free(L.cell);
    ms_free(verts);
    return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for an obstacle's mesh");
}

void ms_render_objects_free(ms_renderer *r)
{
    for (int i = 0; i < r->nobjects; ++i) {
        ms_shape_destroy(r->objects[i].shape);
        ms_free(r->objects[i].local);
    }
    ms_free(r->objects);
    ms_free(r->object_verts);
    r->objects = NULL, r->object_verts = NULL;
    r->nobjects = 0, r->object_nverts = 0, r->object_scene = NULL;
    r->cavity.probed = NULL; /* the container's cavity is probed again (glass_fill.c) */
}

/* One mesh per obstacle then the container (the sim's order). */
static ms_status make_objects(ms_renderer *r, const ms_scene *sc)
{
    ms_render_objects_free(r);
    r->object_scene = sc;
    const int n = sc->nobstacles + (sc->has_container ? 1 : 0);
    if (n == 0)
        return MS_OK;
    r->objects = ms_alloc_array((size_t)n, sizeof *r->objects);
    if (!r->objects)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %d obstacles", n);
    r->nobjects = n;
    size_t total = 0;
    for (int i = 0; i < n; ++i) {
        ms_render_object *ob = &r->objects[i];
        ob->spec = i < sc->nobstacles ? &sc->obstacles[i] : &sc->container;
        const int is_glass = i >= sc->nobstacles;
        memcpy(ob->color, is_glass ? glass_tint : stone, sizeof ob->color);
        ms_status st = ms_shape_create(ob->spec->kind, ob->spec->params_json, &ob->shape);
        if (st == MS_OK)
            st = mesh_shape(ob);
        if (st != MS_OK)
            return st;
        total += (size_t)ob->nverts;
    }
    r->object_verts = ms_alloc_array(total ? total : 1, MS_RENDER_OBJECT_STRIDE * sizeof(float));
    if (!r->object_verts)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for the obstacles' meshes");
    return MS_OK;
}

ms_status ms_render_objects_update(ms_renderer *r, const ms_scene *sc, const ms_sim *sim, double t)
{
    if (!sc) {
        if (r->nobjects)
            r->discs_changed = 1;
        ms_render_objects_free(r);
        return MS_OK;
    }
    ms_status st;
    if (sc != r->object_scene && (st = make_objects(r, sc)) != MS_OK) {
        ms_render_objects_free(r);
        return st;
    }
    int n = 0;
    r->object_glass = -1;
    for (int i = 0; i < r->nobjects; ++i) {
        ms_render_object *ob = &r->objects[i];
        if (ob->spec == &sc->container && r->object_glass < 0)
            r->object_glass = n; /* last: the container */
        if (ob->nverts == 0)
            continue;
        /* where the sim has it (moved or turned by the engine), else where
         * the scene puts it at t */
        ms_sim_shape own = {.spec = ob->spec};
        const ms_sim_shape *sh = sim && i < sim->nshapes ? &sim->shapes[i] : &own;
        if ((st = ms_sim_shape_place(sh, ob->shape, t)) != MS_OK)
            return st;
        const ms_shape *s = ob->shape;
        for (int v = 0; v < ob->nverts; ++v) {
            const float *l = ob->local + 6 * (size_t)v;
            float *o = r->object_verts + MS_RENDER_OBJECT_STRIDE * (size_t)n++;
            ms_rigid_to_world(s->rot, l, o);
            ms_rigid_to_world(s->rot, l + 3, o + 3);
            for (int k = 0; k < 3; ++k)
                o[k] += s->pos[k];
            memcpy(o + 6, ob->color, sizeof ob->color);
        }
    }
    r->object_nverts = n;
    if (r->object_glass < 0)
        r->object_glass = n;
    r->discs_changed = 1;
    return MS_OK;
}
