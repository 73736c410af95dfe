/* An out-of-tree shape plugin, as a user would write one: built by
 * tests/test_plugin.c against the INSTALLED headers only,
 *     cc -shared -fPIC $(pkg-config --cflags modesplit) torus.c -o torus.so -lm
 * A torus around the local z axis: {"major": 0.3, "minor": 0.1} (m). No
 * JSON library: it reads its two numbers with sscanf. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <modesplit/plugin.h>

typedef struct torus {
    float major, minor; /* m */
} torus;

static int read_key(const char *json, const char *key, float *v)
{
    const char *p = json ? strstr(json, key) : NULL;
    if (!p)
        return 1;
    p = strchr(p, ':');
    return p && sscanf(p + 1, "%f", v) == 1;
}

static int torus_create(const char *json, void **out, char *err, size_t n)
{
    torus t = {0.3f, 0.1f};
    if (!read_key(json, "\"major\"", &t.major) || !read_key(json, "\"minor\"", &t.minor)) {
        snprintf(err, n, "major and minor must be numbers (m)");
        return MS_PLUGIN_ERR_PARSE;
    }
    if (!(t.minor > 0) || !(t.major > t.minor)) {
        snprintf(err, n, "minor %g m must be > 0 and < major %g m", t.minor, t.major);
        return MS_PLUGIN_ERR_INVALID_ARGUMENT;
    }
    torus *p = malloc(sizeof *p);
    if (!p)
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    *p = t;
    *out = p;
    return MS_PLUGIN_OK;
}

static void torus_destroy(void *self)
{
    free(self);
}

static float torus_distance(const void *self, const float p[3], float nrm[3])
{
    const torus *t = self;
    float rho = sqrtf(p[0] * p[0] + p[1] * p[1]);
    float ux = rho > 0 ? p[0] / rho : 1, uy = rho > 0 ? p[1] / rho : 0;
    float q[3] = {p[0] - t->major * ux, p[1] - t->major * uy, p[2]}; /* from the core circle */
    float l = sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    if (nrm)
        for (int k = 0; k < 3; ++k)
            nrm[k] = l > 0 ? q[k] / l : (k == 2);
    return l - t->minor;
}

static void torus_bounds(const void *self, float lo[3], float hi[3])
{
    const torus *t = self;
    lo[0] = lo[1] = -(t->major + t->minor);
    hi[0] = hi[1] = t->major + t->minor;
    lo[2] = -t->minor;
    hi[2] = t->minor;
}

static const ms_shape_vtable vtable = {
    .size = sizeof(ms_shape_vtable),
    .create = torus_create,
    .destroy = torus_destroy,
    .distance = torus_distance,
    .bounds = torus_bounds,
};

static const ms_plugin_info info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "torus",
    .version = "0.1",
    .kind = MS_PLUGIN_SHAPE,
    .description = "a ring around the z axis (out-of-tree example)",
    .vtable = &vtable,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &info;
}
