/* Named, size-led records of a snapshot blob (blob.h). */
#include <string.h>

#include "core/blob.h"

#define HEAD (MS_BLOB_NAME + 8)

static size_t pad8(size_t n)
{
    return (n + 7u) & ~(size_t)7u;
}

static void put(ms_blob *b, const char *name, const void *src, size_t bytes)
{
    size_t need = HEAD + pad8(bytes);
    if (b->out && b->len + need <= b->cap) {
        unsigned char *p = b->out + b->len;
        memset(p, 0, need);
        strncpy((char *)p, name, MS_BLOB_NAME - 1);
        uint64_t n = bytes;
        memcpy(p + MS_BLOB_NAME, &n, sizeof n);
        if (bytes)
            memcpy(p + HEAD, src, bytes);
    }
    b->len += need;
}

ms_status ms_blob_peek(const ms_blob *b, const char *name, size_t *bytes)
{
    if (!b->reading)
        return MS_OK;
    if (b->pos > b->len || b->len - b->pos < HEAD)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: the blob ends before record '%s' (at byte %zu of %zu)", name,
                       b->pos, b->len);
    const unsigned char *p = b->in + b->pos;
    char have[MS_BLOB_NAME];
    memcpy(have, p, MS_BLOB_NAME);
    have[MS_BLOB_NAME - 1] = '\0';
    if (strncmp(have, name, MS_BLOB_NAME - 1) != 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record '%s' at byte %zu where this sim expects '%s' (a "
                       "snapshot of another kind of sim)",
                       have, b->pos, name);
    uint64_t n;
    memcpy(&n, p + MS_BLOB_NAME, sizeof n);
    size_t left = b->len - b->pos - HEAD;
    if (n > left || pad8((size_t)n) > left)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record '%s' says %llu bytes but only %zu remain in the blob",
                       name, (unsigned long long)n, left);
    *bytes = (size_t)n;
    return MS_OK;
}

ms_status ms_blob_io(ms_blob *b, const char *name, void *p, size_t bytes)
{
    if (!b->reading) {
        put(b, name, p, bytes);
        return MS_OK;
    }
    size_t have = 0;
    ms_status st = ms_blob_peek(b, name, &have);
    if (st != MS_OK)
        return st;
    if (have != bytes)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record '%s' holds %zu bytes, this sim needs %zu (a snapshot "
                       "of a sim of another size)",
                       name, have, bytes);
    if (bytes)
        memcpy(p, b->in + b->pos + HEAD, bytes);
    b->pos += HEAD + pad8(bytes);
    return MS_OK;
}

ms_status ms_blob_count(ms_blob *b, const char *name, int *n, int max)
{
    ms_status st = ms_blob_io(b, name, n, sizeof *n);
    if (st == MS_OK && b->reading && (*n < 0 || *n > max))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record '%s' is %d, outside [0, %d] for this sim", name, *n, max);
    return st;
}

uint64_t ms_blob_hash(uint64_t h, const void *data, size_t bytes)
{
    /* eight bytes a step (a multiply by an odd constant and an xor-shift,
     * each a bijection of h, so a changed word always changes the result;
     * ~6x faster than byte-wise FNV-1a on a 4 MB blob), the tail FNV-1a */
    const unsigned char *p = data;
    size_t i = 0;
    for (; i + 8 <= bytes; i += 8) {
        uint64_t w;
        memcpy(&w, p + i, sizeof w);
        h = (h ^ w) * 0x9e3779b97f4a7c15ull;
        h ^= h >> 32;
    }
    for (; i < bytes; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

ms_status ms_blob_expect(const ms_blob *b, const char *name, size_t bytes)
{
    size_t have = bytes;
    ms_status st = ms_blob_peek(b, name, &have);
    if (st == MS_OK && have != bytes)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record '%s' holds %zu bytes where its count says %zu (a "
                       "forged or damaged snapshot)",
                       name, have, bytes);
    return st;
}

ms_status ms_blob_check_floats(const char *name, const float *p, size_t count, double lo, double hi,
                               const char *unit)
{
    for (size_t i = 0; i < count; ++i) {
        if (!isfinite(p[i]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "snapshot: record '%s' value %zu is %g; every value must be finite",
                           name, i, (double)p[i]);
        if (p[i] < lo || p[i] > hi)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "snapshot: record '%s' value %zu is %g%s%s, outside [%g, %g]%s%s", name,
                           i, (double)p[i], *unit ? " " : "", unit, lo, hi, *unit ? " " : "", unit);
    }
    return MS_OK;
}

ms_status ms_blob_check_int(const char *name, long v, long lo, long hi)
{
    if (v < lo || v > hi)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record '%s' is %ld, outside [%ld, %ld] for this sim", name, v, lo,
                       hi);
    return MS_OK;
}

ms_status ms_blob_floats(ms_blob *b, const char *name, float *p, size_t count, double lo, double hi,
                         const char *unit)
{
    ms_status st = ms_blob_io(b, name, p, count * sizeof(float));
    if (st == MS_OK && b->reading)
        st = ms_blob_check_floats(name, p, count, lo, hi, unit);
    return st;
}

ms_status ms_blob_double(ms_blob *b, const char *name, double *p, double lo, double hi,
                         const char *unit)
{
    ms_status st = ms_blob_io(b, name, p, sizeof *p);
    if (st == MS_OK && b->reading && (!isfinite(*p) || *p < lo || *p > hi))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record '%s' is %g%s%s, outside [%g, %g]%s%s (finite)", name, *p,
                       *unit ? " " : "", unit, lo, hi, *unit ? " " : "", unit);
    return st;
}
