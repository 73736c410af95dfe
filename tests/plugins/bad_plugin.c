/* Deliberately broken (and one good) plugins for tests/test_plugin.c, which
 * builds one shared object per defect with -D<DEFECT>:
 *   NO_ENTRY  ABI_MAJOR  ABI_NEWER  SIZE_ZERO  SIZE_TRUNC  NULL_INFO
 *   BAD_KIND  BAD_NAME   NO_VTABLE  VT_TRUNC   NO_DISTANCE
 *   (none)    a good shape plugin called NAME (default "testball"), of
 *             this ABI: each instance is a block of the host's allocator
 *   ABI_1_0   a good one as a plugin built against ABI 1.0 headers was:
 *             its ms_plugin_info ends at vtable (no set_host) and its
 *             instances come from malloc
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include <modesplit/plugin.h>

#ifndef NAME
#define NAME "testball"
#endif

#ifndef ABI_1_0
static const ms_plugin_host *host;

static void tb_set_host(const ms_plugin_host *h)
{
    host = h;
}
#endif

/* an instance of one float, the radius 1 m the functions below assume */
static int tb_create(const char *json, void **out, char *err, size_t n)
{
    (void)json;
    (void)err;
    (void)n;
#ifdef ABI_1_0
    float *r = malloc(sizeof *r);
#else
    float *r = host ? host->alloc_fn(sizeof *r) : NULL;
#endif
    if (!r)
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    *r = 1.0f;
    *out = r;
    return MS_PLUGIN_OK;
}

static void tb_destroy(void *self)
{
#ifdef ABI_1_0
    free(self);
#else
    host->free_fn(self);
#endif
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

#ifdef ABI_1_0
/* ms_plugin_info as the ABI 1.0 headers declared it */
typedef struct info_1_0 {
    uint32_t abi, size;
    const char *name, *version;
    uint32_t kind;
    const char *description;
    const void *vtable;
} info_1_0;
static const info_1_0 info_old = {.abi = 1u << 16,
                                  .size = sizeof(info_1_0),
                                  .name = NAME,
                                  .version = "0.0-test",
                                  .kind = MS_PLUGIN_SHAPE,
                                  .description = "test plugin of ABI 1.0",
                                  .vtable = &vt};
#endif

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
#ifndef ABI_1_0
    .set_host = tb_set_host,
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
#if defined(NULL_INFO)
    (void)info;
    return NULL;
#elif defined(ABI_1_0)
    (void)info;
    return (const ms_plugin_info *)(const void *)&info_old;
#else
    return &info;
#endif
}
#endif
