/* Every allocation of the library, through one pair of functions an
 * engine may replace (ms_set_allocator, as Box2D's b2SetAllocator and
 * sokol's allocator desc). Each block carries a 64-byte header holding its
 * size, so blocks can be grown and freed without the caller knowing their
 * size, and the data starts on a cache line (64 bytes: AVX-512 vectors).
 * The count of live blocks lets ms_set_allocator refuse a change while the
 * library holds memory from the previous allocator. */
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"

#define HEADER 64
#define ALIGN 64

static void *default_alloc(size_t size, size_t alignment, void *user)
{
    (void)user;
    return aligned_alloc(alignment, size);
}

static void default_free(void *p, void *user)
{
    (void)user;
    free(p);
}

static ms_alloc_fn *hook_alloc = default_alloc;
static ms_free_fn *hook_free = default_free;
static void *hook_user;
static atomic_long live_blocks;
static atomic_long total_allocs;

ms_status ms_set_allocator(ms_alloc_fn *alloc_fn, ms_free_fn *free_fn, void *user)
{
    if ((alloc_fn == NULL) != (free_fn == NULL))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "core: ms_set_allocator needs both alloc and free, or both NULL "
                       "(the default)");
    long live = atomic_load(&live_blocks);
    if (live != 0)
        return ms_fail(MS_ERR_STATE,
                       "core: ms_set_allocator while the library holds %ld blocks of the "
                       "previous allocator; set it before creating anything, or after "
                       "destroying everything",
                       live);
    hook_alloc = alloc_fn ? alloc_fn : default_alloc;
    hook_free = free_fn ? free_fn : default_free;
    hook_user = alloc_fn ? user : NULL;
    return MS_OK;
}

long ms_alloc_count(void)
{
    return atomic_load(&total_allocs);
}

long ms_alloc_live(void)
{
    return atomic_load(&live_blocks);
}

void *ms_malloc(size_t n)
{
    size_t rounded = (n + (ALIGN - 1)) & ~(size_t)(ALIGN - 1);
    if (rounded < n || rounded > SIZE_MAX - HEADER)
        return NULL;
    unsigned char *b = hook_alloc(rounded + HEADER, ALIGN, hook_user);
    if (!b)
        return NULL;
    memcpy(b, &n, sizeof n);
    atomic_fetch_add(&live_blocks, 1);
    atomic_fetch_add(&total_allocs, 1);
    return b + HEADER;
}

void *ms_alloc(size_t n)
{
    void *p = ms_malloc(n);
    if (p) /* the padding to the cache line too: vector loops may read it */
        memset(p, 0, (n + (ALIGN - 1)) & ~(size_t)(ALIGN - 1));
    return p;
}

void *ms_alloc_array(size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    return ms_alloc(count * size);
}

void *ms_realloc(void *p, size_t n)
{
    if (!p)
        return ms_malloc(n);
    size_t old;
    memcpy(&old, (unsigned char *)p - HEADER, sizeof old);
    void *q = ms_malloc(n);
    if (!q)
        return NULL; /* p stays valid, as realloc leaves it */
    memcpy(q, p, MS_MIN(old, n));
    ms_free(p);
    return q;
}

char *ms_strdup(const char *s)
{
    if (!s)
        return NULL;
    size_t n = strlen(s) + 1;
    char *p = ms_malloc(n);
    if (p)
        memcpy(p, s, n);
    return p;
}

char *ms_strndup(const char *s, size_t n)
{
    char *p = ms_malloc(n + 1);
    if (p) {
        memcpy(p, s, n);
        p[n] = '\0';
    }
    return p;
}

void ms_free(void *p)
{
    if (!p)
        return;
    atomic_fetch_sub(&live_blocks, 1);
    hook_free((unsigned char *)p - HEADER, hook_user);
}
