/* Deliberately broken (and one good) plugins for tests/test_plugin.c, which
 * builds one shared object per defect with -D<DEFECT>:
 *   NO_ENTRY  ABI_MAJOR  ABI_NEWER  SIZE_ZERO  SIZE_TRUNC  NULL_INFO
 *   BAD_KIND  BAD_NAME   NO_VTABLE  VT_TRUNC   NO_DISTANCE
 *   (none)    a good shape plugin called NAME (default "testball").
 */
#include <math.h>
#include <stdlib.h>

#include <modesplit/plugin.h>

#ifndef NAME
#define NAME "testball"
#endif

static int tb_create(const char *json, void **out, char *err, size_t n)
{
    (void)json;
    (void)err;
    (void)n;
    *out = NULL;
    return MS_PLUGIN_OK;
}

static void tb_destroy(void *self)
{
    (void)self;
}

static float tb_distance(const void *self, const float p[3], float nrm[3])
{
    (void)self;
    float l = sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (nrm) {
        nrm[0] = l > 0 ? p[0] / l : 0;
        nrm[1] = l > 0 ? p[1] / l : 0;
        nrm[2] = l > 0 ? p[2] / l : 1;
    }
    return l - 1.0f;
}

static void tb_bounds(const void *self, float lo[3], float hi[3])
{
    (void)self;
    for (int k = 0; k < 3; ++k) {
        lo[k] = -1;
        hi[k] = 1;
    }
}

static const ms_shape_vtable vt = {
#ifdef VT_TRUNC
    .size = 4,
#else
    .size = sizeof(ms_shape_vtable),
#endif
    .create = tb_create,
    .destroy = tb_destroy,
#ifndef NO_DISTANCE
    .distance = tb_distance,
#endif
    .bounds = tb_bounds,
};

static const ms_plugin_info info = {
#if defined(ABI_MAJOR)
    .abi = (2u << 16) | 0u,
#elif defined(ABI_NEWER)
    .abi = (MS_PLUGIN_ABI_MAJOR << 16) | (MS_PLUGIN_ABI_MINOR + 7u),
#else
    .abi = MS_PLUGIN_ABI,
#endif
#if defined(SIZE_ZERO)
    .size = 0,
#elif defined(SIZE_TRUNC)
    .size = 8 + sizeof(const char *),
#else
    .size = sizeof(ms_plugin_info),
#endif
#ifdef BAD_NAME
    .name = "Bad Name!",
#else
    .name = NAME,
#endif
    .version = "0.0-test",
#ifdef BAD_KIND
    .kind = 7,
#else
    .kind = MS_PLUGIN_SHAPE,
#endif
    .description = "test plugin",
#ifdef NO_VTABLE
    .vtable = NULL,
#else
    .vtable = &vt,
#endif
};

#ifdef NO_ENTRY
MS_PLUGIN_EXPORT const ms_plugin_info *not_the_entry(void);
const ms_plugin_info *not_the_entry(void)
{
    return &info;
}
#else
const ms_plugin_info *ms_plugin_entry(void)
{
#ifdef NULL_INFO
    (void)info;
    return NULL;
#else
    return &info;
#endif
}
#endif
