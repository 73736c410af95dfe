/* Shape plugin "sphere": a ball of radius r centred on the local origin.
 * Parameters: {"radius": 0.1}  (m). Exact signed distance |p| - r; the
 * normal is p/|p| (no edges to smooth). */
#include <math.h>
#include <stdlib.h>

#include "../common/host.h"
#include "../common/params.h"
#include "modesplit/plugin.h"

typedef struct sphere {
    float r; /* m */
} sphere;

static int sphere_create(const char *json, void **out, char *err, size_t err_size)
{
    static const char *const keys[] = {"radius", NULL};
    params pm;
    sphere s = {0.1f};
    if (params_open(&pm, json, keys, err, err_size) == MS_PLUGIN_OK)
        s.r = params_number(&pm, "radius", s.r, 1e-6, 1e6, "m");
    int rc = params_close(&pm);
    if (rc != MS_PLUGIN_OK)
        return rc;
    sphere *p = plugin_alloc(sizeof *p);
    if (!p) {
        snprintf(err, err_size, "out of memory");
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    }
    *p = s;
    *out = p;
    return MS_PLUGIN_OK;
}

static void sphere_destroy(void *self)
{
    plugin_free(self);
}

static float sphere_distance(const void *self, const float p[3], float n[3])
{
    const sphere *s = self;
    float l = sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (n) {
        if (l > 0.0f) {
            n[0] = p[0] / l;
            n[1] = p[1] / l;
            n[2] = p[2] / l;
        } else { /* the centre: any direction; up */
            n[0] = n[1] = 0.0f;
            n[2] = 1.0f;
        }
    }
    return l - s->r;
}

static void sphere_bounds(const void *self, float lo[3], float hi[3])
{
    const sphere *s = self;
    for (int k = 0; k < 3; ++k) {
        lo[k] = -s->r;
        hi[k] = s->r;
    }
}

static int sphere_height_at(const void *self, float x, float y, float *top)
{
    const sphere *s = self;
    float q = s->r * s->r - x * x - y * y;
    if (q < 0.0f)
        return 0;
    *top = sqrtf(q);
    return 1;
}

static const ms_shape_vtable sphere_vtable = {
    .size = sizeof(ms_shape_vtable),
    .create = sphere_create,
    .destroy = sphere_destroy,
    .distance = sphere_distance,
    .bounds = sphere_bounds,
    .height_at = sphere_height_at,
};

static const ms_plugin_info sphere_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "sphere",
    .version = "1.0",
    .kind = MS_PLUGIN_SHAPE,
    .description = "ball of radius r (m) around the local origin",
    .vtable = &sphere_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &sphere_info;
}
