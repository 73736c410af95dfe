/* The host's allocator for the plugins shipped with libmodesplit (ABI
 * 1.1, header-only like params.h): every block a plugin keeps comes from
 * the host, so an engine's allocator (ms_set_allocator) sees it. The
 * loader calls the plugin's set_host (plugin_set_host) before any create;
 * each plugin lists it in its ms_plugin_info:
 *
 *     .set_host = plugin_set_host,
 *
 * Without a host (a program that calls ms_plugin_entry itself and not
 * set_host) plugin_alloc returns NULL: create then fails with
 * MS_PLUGIN_ERR_OUT_OF_MEMORY, never falls back to malloc. */
#ifndef MS_PLUGINS_HOST_H
#define MS_PLUGINS_HOST_H

#include <stdint.h>
#include <string.h>

#include "modesplit/plugin.h"

static const ms_plugin_host *plugin_host;

static void plugin_set_host(const ms_plugin_host *host)
{
    plugin_host = host;
}

/* n bytes, or NULL */
static inline void *plugin_alloc(size_t n)
{
    return plugin_host ? plugin_host->alloc_fn(n) : NULL;
}

/* count * size zeroed bytes, or NULL (also when the product overflows) */
static inline void *plugin_calloc(size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    void *p = plugin_alloc(count * size);
    if (p)
        memset(p, 0, count * size);
    return p;
}

static inline void plugin_free(void *p)
{
    if (p && plugin_host)
        plugin_host->free_fn(p);
}

#endif
