/* Shape plugin "box": an axis-aligned box centred on the local origin,
 * with rounded edges, and a normal smoothed around its edges as in the
 * paper's Fig. 5, so that shapes built of several basic objects collide
 * correctly (eq. 15: the force follows the normal).
 *
 * Parameters: {"size": [sx, sy, sz], "radius": 0, "smooth": ...}
 *   size    full extents (m), default [1, 1, 1];
 *   radius  edge and corner rounding (m), 0 <= radius <= min(size)/2;
 *   smooth  width (m) of the band around edges where the normal turns
 *           from one face's normal to the next; radius <= smooth <=
 *           min(size)/2, default max(radius, min(size)/10).
 *
 * Distance: exact for the rounded box, d = |max(q, 0)| + min(max_i q_i, 0) - r
 * with q = |p| - (h - r), h the half extents.
 * Normal: the gradient of the box rounded by `smooth` (h - smooth = the
 * core): n = normalize(p - clamp(p, -core, core)), which is the exact
 * gradient of the distance when smooth == radius, continuous wherever p is
 * outside the core. Inside the core (deeper than `smooth` below every
 * face) each face's normal is weighted by how close p is to it relative to
 * its depth m below the nearest face, w_i = max(0, 1 - (t_i - m) / m), so
 * the normal turns continuously across the diagonal planes where the
 * nearest face changes and tends to the face normal at the core's faces.
 * The only discontinuity left is on the core's edges, deep inside.
 */
#include <math.h>
#include <stdlib.h>

#include "../common/host.h"
#include "../common/params.h"
#include "modesplit/plugin.h"

typedef struct box {
    float h[3];     /* half extents, m */
    float r;        /* rounding radius, m */
    float core[3];  /* h - r, m */
    float ncore[3]; /* h - smooth: the normal's core, m */
} box;

static int box_create(const char *json, void **out, char *err, size_t err_size)
{
    static const char *const keys[] = {"size", "radius", "smooth", NULL};
    static const float one[3] = {1, 1, 1};
    params pm;
    float size[3] = {1, 1, 1}, r = 0, smooth = 0;
    if (params_open(&pm, json, keys, err, err_size) == MS_PLUGIN_OK) {
        params_vec(&pm, "size", 3, size, one, 1e-6, 1e6, "m");
        float hmin = 0.5f * fminf(size[0], fminf(size[1], size[2]));
        r = params_number(&pm, "radius", 0.0f, 0.0, hmin, "m");
        /* the bound allows for radius having been rounded to float */
        smooth = params_number(&pm, "smooth", fmaxf(r, 0.2f * hmin), r * (1 - 1e-6), hmin, "m");
        smooth = fmaxf(smooth, r);
    }
    int rc = params_close(&pm);
    if (rc != MS_PLUGIN_OK)
        return rc;
    box *b = plugin_alloc(sizeof *b);
    if (!b) {
        snprintf(err, err_size, "out of memory");
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    }
    for (int k = 0; k < 3; ++k) {
        b->h[k] = 0.5f * size[k];
        b->core[k] = b->h[k] - r;
        b->ncore[k] = b->h[k] - smooth;
    }
    b->r = r;
    *out = b;
    return MS_PLUGIN_OK;
}

static void box_destroy(void *self)
{
    plugin_free(self);
}

static void box_normal(const box *b, const float p[3], float n[3])
{
    float g[3], a[3], s[3];
    double gg = 0;
    for (int k = 0; k < 3; ++k) {
        a[k] = fabsf(p[k]);
        s[k] = p[k] < 0.0f ? -1.0f : 1.0f;
        g[k] = s[k] * fmaxf(a[k] - b->ncore[k], 0.0f);
        gg += (double)g[k] * g[k];
    }
    if (gg > 1e-24) { /* outside the core: gradient of the smoothed box */
        float l = (float)sqrt(gg);
        for (int k = 0; k < 3; ++k)
            n[k] = g[k] / l;
        return;
    }
    /* inside the core: blend the faces by relative depth */
    float t[3], m;
    for (int k = 0; k < 3; ++k)
        t[k] = b->ncore[k] - a[k];
    m = fminf(t[0], fminf(t[1], t[2]));
    double ww = 0;
    for (int k = 0; k < 3; ++k) {
        float w = m > 0.0f ? fmaxf(0.0f, 1.0f - (t[k] - m) / m) : (t[k] <= m ? 1.0f : 0.0f);
        g[k] = s[k] * w;
        ww += (double)w * w;
    }
    float l = (float)sqrt(ww);
    for (int k = 0; k < 3; ++k)
        n[k] = g[k] / l;
}

static float box_distance(const void *self, const float p[3], float n[3])
{
    const box *b = self;
    float q[3];
    double out2 = 0;
    for (int k = 0; k < 3; ++k) {
        q[k] = fabsf(p[k]) - b->core[k];
        float o = fmaxf(q[k], 0.0f);
        out2 += (double)o * o;
    }
    float inside = fminf(fmaxf(q[0], fmaxf(q[1], q[2])), 0.0f);
    if (n)
        box_normal(b, p, n);
    return (float)sqrt(out2) + inside - b->r;
}

static void box_bounds(const void *self, float lo[3], float hi[3])
{
    const box *b = self;
    for (int k = 0; k < 3; ++k) {
        lo[k] = -b->h[k];
        hi[k] = b->h[k];
    }
}

/* The top of the rounded box over column (x, y) (m, local). */
static int box_height_at(const void *self, float x, float y, float *top)
{
    const box *b = self;
    float ex = fmaxf(fabsf(x) - b->core[0], 0.0f), ey = fmaxf(fabsf(y) - b->core[1], 0.0f);
    float e2 = ex * ex + ey * ey;
    if (e2 > b->r * b->r || fabsf(x) > b->h[0] || fabsf(y) > b->h[1])
        return 0;
    *top = b->core[2] + sqrtf(b->r * b->r - e2);
    return 1;
}

static const ms_shape_vtable box_vtable = {
    .size = sizeof(ms_shape_vtable),
    .create = box_create,
    .destroy = box_destroy,
    .distance = box_distance,
    .bounds = box_bounds,
    .height_at = box_height_at,
};

static const ms_plugin_info box_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "box",
    .version = "1.0",
    .kind = MS_PLUGIN_SHAPE,
    .description = "box of full extents size (m), rounded edges, normals smoothed at edges",
    .vtable = &box_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &box_info;
}
