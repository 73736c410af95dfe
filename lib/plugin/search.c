/* The plugin search path: MODESPLIT_PLUGIN_PATH, then the install's
 * lib/modesplit/plugins (found from where libmodesplit's code was loaded,
 * with dladdr), then the build tree (MS_BUILD_PLUGIN_DIR from the Makefile)
 * -- the build tree only when the code was loaded from inside it, so an
 * installed tool or library never picks up plugins of a build directory
 * that happens to still exist. */
#define _GNU_SOURCE /* dladdr */
#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/core_internal.h"
#include "plugin/plugin_internal.h"

typedef struct buf {
    char *s;
    size_t len, cap;
    int oom;
} buf;

static void put(buf *b, const char *s, size_t n)
{
    if (b->oom)
        return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = (b->len + n + 1) * 2;
        char *t = ms_realloc(b->s, cap);
        if (!t) {
            b->oom = 1;
            return;
        }
        b->s = t;
        b->cap = cap;
    }
    memcpy(b->s + b->len, s, n);
    b->len += n;
    b->s[b->len] = '\0';
}

static void put_dir(buf *b, const char *dir, size_t n)
{
    if (n == 0)
        return;
    if (b->len)
        put(b, ":", 1);
    put(b, dir, n);
}

char *ms_plugin_compose_search_path(const char *env, const char *object_path, const char *build_dir)
{
    buf b = {0};
    put(&b, "", 0);
    for (const char *p = env; p && *p;) {
        const char *colon = strchr(p, ':');
        size_t n = colon ? (size_t)(colon - p) : strlen(p);
        put_dir(&b, p, n);
        p += n + (colon != NULL);
    }
    if (object_path && *object_path) {
        const char *slash = strrchr(object_path, '/');
        const char *base = slash ? slash + 1 : object_path;
        if (b.len)
            put(&b, ":", 1);
        if (slash)
            put(&b, object_path, (size_t)(slash - object_path)); /* "" for a file in / */
        else
            put(&b, ".", 1);
        if (strstr(base, ".so"))
            put(&b, "/modesplit/plugins", strlen("/modesplit/plugins"));
        else
            put(&b, "/../lib/modesplit/plugins", strlen("/../lib/modesplit/plugins"));
    }
    if (build_dir)
        put_dir(&b, build_dir, strlen(build_dir));
    if (b.oom) {
        ms_free(b.s);
        return NULL;
    }
    return b.s;
}

/* A data object of this library: dladdr names the file it was loaded from. */
static const char anchor = 0;

char *ms_plugin_default_search_path(void)
{
    Dl_info dl;
    const char *object = NULL;
    char exe[4096];
    if (dladdr((const void *)&anchor, &dl) && dl.dli_fname && strstr(dl.dli_fname, ".so")) {
        object = dl.dli_fname; /* libmodesplit.so: <libdir>/modesplit/plugins */
    } else {
        /* linked statically: the code is in the executable */
        ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0) {
            exe[n] = '\0';
            object = exe;
        } else if (dladdr((const void *)&anchor, &dl) && dl.dli_fname) {
            object = dl.dli_fname;
        }
    }
    const char *build = NULL;
#ifdef MS_BUILD_PLUGIN_DIR
    /* MS_BUILD_PLUGIN_DIR is "<build>/plugins": is the object under <build>/? */
    const char *dir = MS_BUILD_PLUGIN_DIR;
    const char *slash = strrchr(dir, '/');
    char resolved[PATH_MAX];
    const char *real = object ? realpath(object, resolved) : NULL;
    if (slash && real && !strncmp(real, dir, (size_t)(slash - dir)) && real[slash - dir] == '/')
        build = dir;
#endif
    return ms_plugin_compose_search_path(getenv("MODESPLIT_PLUGIN_PATH"), object, build);
}
