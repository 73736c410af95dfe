/* Shape plugin "plane": the half-space below a plane (a floor, a wall).
 * Parameters: {"normal": [0, 0, 1], "offset": 0}: the surface is
 * normal . p = offset (m), the solid lies where normal . p < offset; the
 * normal is normalised. Exact signed distance normal . p - offset. */
#include <math.h>
#include <stdlib.h>

#include "../common/host.h"
#include "../common/params.h"
#include "modesplit/plugin.h"

#define FAR 1e30f

typedef struct plane {
    float n[3];   /* unit */
    float offset; /* m */
} plane;

static int plane_create(const char *json, void **out, char *err, size_t err_size)
{
    static const char *const keys[] = {"normal", "offset", NULL};
    static const float up[3] = {0, 0, 1};
    params pm;
    plane s = {{0, 0, 1}, 0};
    if (params_open(&pm, json, keys, err, err_size) == MS_PLUGIN_OK) {
        params_vec(&pm, "normal", 3, s.n, up, -1e6, 1e6, "");
        s.offset = params_number(&pm, "offset", 0.0f, -1e6, 1e6, "m");
    }
    double l = sqrt((double)s.n[0] * s.n[0] + (double)s.n[1] * s.n[1] + (double)s.n[2] * s.n[2]);
    if (pm.rc == MS_PLUGIN_OK && !(l > 1e-12))
        params_fail(&pm, MS_PLUGIN_ERR_INVALID_ARGUMENT,
                    "normal [%g, %g, %g] has length 0; it must be a direction", s.n[0], s.n[1],
                    s.n[2]);
    int rc = params_close(&pm);
    if (rc != MS_PLUGIN_OK)
        return rc;
    for (int k = 0; k < 3; ++k)
        s.n[k] = (float)(s.n[k] / l);
    plane *p = plugin_alloc(sizeof *p);
    if (!p) {
        snprintf(err, err_size, "out of memory");
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    }
    *p = s;
    *out = p;
    return MS_PLUGIN_OK;
}

static void plane_destroy(void *self)
{
    plugin_free(self);
}

static float plane_distance(const void *self, const float p[3], float n[3])
{
    const plane *s = self;
    if (n) {
        n[0] = s->n[0];
        n[1] = s->n[1];
        n[2] = s->n[2];
    }
    return s->n[0] * p[0] + s->n[1] * p[1] + s->n[2] * p[2] - s->offset;
}

/* Unbounded, except along an axis the plane is perpendicular to. */
static void plane_bounds(const void *self, float lo[3], float hi[3])
{
    const plane *s = self;
    for (int k = 0; k < 3; ++k) {
        lo[k] = -FAR;
        hi[k] = FAR;
    }
    for (int k = 0; k < 3; ++k) {
        if (fabsf(s->n[k]) != 1.0f)
            continue;
        if (s->n[k] > 0)
            hi[k] = s->offset;
        else
            lo[k] = -s->offset;
    }
}

static int plane_height_at(const void *self, float x, float y, float *top)
{
    const plane *s = self;
    if (s->n[2] > 0.0f) {
        *top = (s->offset - s->n[0] * x - s->n[1] * y) / s->n[2];
        return 1;
    }
    if (s->n[2] < 0.0f || s->n[0] * x + s->n[1] * y < s->offset) {
        *top = FAR; /* solid up to the sky */
        return 1;
    }
    return 0;
}

static const ms_shape_vtable plane_vtable = {
    .size = sizeof(ms_shape_vtable),
    .create = plane_create,
    .destroy = plane_destroy,
    .distance = plane_distance,
    .bounds = plane_bounds,
    .height_at = plane_height_at,
};

static const ms_plugin_info plane_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "plane",
    .version = "1.0",
    .kind = MS_PLUGIN_SHAPE,
    .description = "half-space below the plane normal . p = offset (m)",
    .vtable = &plane_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &plane_info;
}
