/* Shape plugin "capsule": the points within `radius` of the segment a-b
 * (a cylinder with hemispherical caps: a swimming body, a rod, a finger).
 * Parameters: {"a": [0, 0, -0.25], "b": [0, 0, 0.25], "radius": 0.1} (m,
 * local). a == b gives a sphere. Exact signed distance |p - c| - r with c
 * the closest point of the segment; the normal (p - c)/|p - c| has no
 * edges to smooth (on the segment itself, any direction perpendicular to
 * it). */
#include <math.h>
#include <stdlib.h>

#include "../common/host.h"
#include "../common/params.h"
#include "modesplit/plugin.h"

typedef struct capsule {
    float a[3], ab[3]; /* m */
    float ab2;         /* |ab|^2, m^2 */
    float r;           /* m */
    float perp[3];     /* a unit vector perpendicular to ab */
} capsule;

static int capsule_create(const char *json, void **out, char *err, size_t err_size)
{
    static const char *const keys[] = {"a", "b", "radius", NULL};
    static const float da[3] = {0, 0, -0.25f}, db[3] = {0, 0, 0.25f};
    params pm;
    float a[3], b[3], r = 0.1f;
    if (params_open(&pm, json, keys, err, err_size) == MS_PLUGIN_OK) {
        params_vec(&pm, "a", 3, a, da, -1e6, 1e6, "m");
        params_vec(&pm, "b", 3, b, db, -1e6, 1e6, "m");
        r = params_number(&pm, "radius", r, 1e-6, 1e6, "m");
    } else {
        for (int k = 0; k < 3; ++k) {
            a[k] = da[k];
            b[k] = db[k];
        }
    }
    int rc = params_close(&pm);
    if (rc != MS_PLUGIN_OK)
        return rc;
    capsule *c = plugin_alloc(sizeof *c);
    if (!c) {
        snprintf(err, err_size, "out of memory");
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    }
    c->ab2 = 0;
    for (int k = 0; k < 3; ++k) {
        c->a[k] = a[k];
        c->ab[k] = b[k] - a[k];
        c->ab2 += c->ab[k] * c->ab[k];
    }
    c->r = r;
    /* perpendicular: ab x (the axis least aligned with ab) */
    int m = 0;
    for (int k = 1; k < 3; ++k)
        if (fabsf(c->ab[k]) < fabsf(c->ab[m]))
            m = k;
    float e[3] = {0, 0, 0};
    e[m] = 1;
    float px = c->ab[1] * e[2] - c->ab[2] * e[1], py = c->ab[2] * e[0] - c->ab[0] * e[2],
          pz = c->ab[0] * e[1] - c->ab[1] * e[0];
    float l = sqrtf(px * px + py * py + pz * pz);
    if (l > 0) {
        c->perp[0] = px / l;
        c->perp[1] = py / l;
        c->perp[2] = pz / l;
    } else {
        c->perp[0] = c->perp[1] = 0;
        c->perp[2] = 1;
    }
    *out = c;
    return MS_PLUGIN_OK;
}

static void capsule_destroy(void *self)
{
    plugin_free(self);
}

static float capsule_distance(const void *self, const float p[3], float n[3])
{
    const capsule *c = self;
    float ap[3] = {p[0] - c->a[0], p[1] - c->a[1], p[2] - c->a[2]};
    float t = 0;
    if (c->ab2 > 0) {
        t = (ap[0] * c->ab[0] + ap[1] * c->ab[1] + ap[2] * c->ab[2]) / c->ab2;
        t = fminf(fmaxf(t, 0.0f), 1.0f);
    }
    float v[3] = {ap[0] - t * c->ab[0], ap[1] - t * c->ab[1], ap[2] - t * c->ab[2]};
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (n) {
        for (int k = 0; k < 3; ++k)
            n[k] = l > 0 ? v[k] / l : c->perp[k];
    }
    return l - c->r;
}

static void capsule_bounds(const void *self, float lo[3], float hi[3])
{
    const capsule *c = self;
    for (int k = 0; k < 3; ++k) {
        float b = c->a[k] + c->ab[k];
        lo[k] = fminf(c->a[k], b) - c->r;
        hi[k] = fmaxf(c->a[k], b) + c->r;
    }
}

static const ms_shape_vtable capsule_vtable = {
    .size = sizeof(ms_shape_vtable),
    .create = capsule_create,
    .destroy = capsule_destroy,
    .distance = capsule_distance,
    .bounds = capsule_bounds,
    .height_at = NULL, /* the library marches the exact distance */
};

static const ms_plugin_info capsule_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "capsule",
    .version = "1.0",
    .kind = MS_PLUGIN_SHAPE,
    .description = "points within radius (m) of the segment a-b",
    .vtable = &capsule_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &capsule_info;
}
