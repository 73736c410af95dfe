/* Aligned, zeroed allocation: 64 bytes so hot loops start on a cache line. */
#include <stdlib.h>
#include <string.h>

#include "core/internal.h"

void *ms_alloc(size_t n)
{
    if (n == 0)
        n = 1;
    size_t rounded = (n + 63) & ~(size_t)63;
    if (rounded < n)
        return NULL;
    void *p = aligned_alloc(64, rounded);
    if (p)
        memset(p, 0, rounded);
    return p;
}

void *ms_alloc_array(size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    return ms_alloc(count * size);
}

void ms_free(void *p)
{
    free(p);
}
