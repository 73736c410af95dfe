/* The leading `size` field of the public structs (Win32's cbSize, Vulkan's
 * sType): how a library tells an older caller's smaller struct from the
 * current one, so that "descs only grow at the end" is a promise it keeps.
 *
 * A struct the caller passes in (a desc) is read by ms_struct_in: its size
 * must be one the library knows, and only that many bytes are copied, over
 * the library's defaults, so the fields an older caller does not know keep
 * their defaults. A struct the library fills (stats, info) is written by
 * ms_struct_out: only the caller's .size bytes. */
#include <string.h>

#include "core/core_internal.h"

/* The sizes a caller's compiler can give a struct that ends at `end`: the
 * end itself plus up to 7 bytes of tail padding (alignment <= 8), in steps
 * of 4 (every public struct holds 4-byte fields). */
static int size_of_layout(size_t size, size_t end)
{
    return size >= end && size < end + 8 && size % 4 == 0;
}

static int known(const ms_struct_sizes *k, size_t size)
{
    return size == k->current || (size <= k->current && size_of_layout(size, k->v1_end));
}

static uint32_t read_size(const void *p)
{
    uint32_t size;
    memcpy(&size, p, sizeof size);
    return size;
}

ms_status ms_struct_in(const void *user, void *local, ms_struct_sizes k, const char *part)
{
    if (!user)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "%s: desc is NULL (an %s from %s)", part, k.name,
                       k.init);
    uint32_t size = read_size(user);
    if (size == 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "%s: %s.size is 0: start from %s, which sets it",
                       part, k.name, k.init);
    if (!known(&k, size))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "%s: %s.size %u is not a size this library (%s) knows: %zu (current) "
                       "or %zu..%zu (version 0.1); %s",
                       part, k.name, (unsigned)size, MS_VERSION_STRING, k.current, k.v1_end,
                       MS_MIN(k.v1_end + 7, k.current),
                       size > k.current ? "a header newer than the library?"
                                        : "start from the desc_default() function");
    memcpy(local, user, size);
    uint32_t current = (uint32_t)k.current;
    memcpy(local, &current, sizeof current);
    return MS_OK;
}

size_t ms_struct_out(const void *user, ms_struct_sizes k, const char *part)
{
    if (!user)
        return 0;
    uint32_t size = read_size(user);
    if (size == 0) {
        ms_fail(MS_ERR_INVALID_ARGUMENT,
                "%s: %s.size is 0, nothing was written: set it to sizeof (%s)", part, k.name,
                k.init);
        return 0;
    }
    if (!known(&k, size)) {
        ms_fail(MS_ERR_INVALID_ARGUMENT,
                "%s: %s.size %u is not a size this library (%s) knows (%zu current), nothing "
                "was written",
                part, k.name, (unsigned)size, MS_VERSION_STRING, k.current);
        return 0;
    }
    return size;
}

void ms_struct_write(void *user, const void *full, size_t size)
{
    /* bytes after the leading size only: the caller's .size stays as set */
    if (size > sizeof(uint32_t))
        memcpy((char *)user + sizeof(uint32_t), (const char *)full + sizeof(uint32_t),
               size - sizeof(uint32_t));
}
