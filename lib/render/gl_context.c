/* The renderer's GL context: a small backend interface (create, begin,
 * end, destroy; ms_gl_backend in gl_internal.h) with one file per backend:
 * gl_context_osmesa.c (OSMesa), gl_context_egl.c (EGL, surfaceless Mesa).
 * `render.backend` picks one ("osmesa", "egl") or lets the renderer try
 * what this build has ("auto": OSMesa, then EGL).
 *
 * Each renderer owns a context; every call makes it current in the calling
 * thread and releases it after, so a renderer may move between threads
 * (one at a time). */
#include <stdio.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

/* The context current in this thread (between begin and end). */
static _Thread_local ms_gl_context *current;

/* The backends this build has, in the order "auto" tries them. */
static const ms_gl_backend *const backends[] = {
#if MS_HAVE_OSMESA
    &ms_gl_backend_osmesa,
#endif
#if MS_HAVE_EGL
    &ms_gl_backend_egl,
#endif
    NULL,
};

const char *ms_gl_backends_built(void)
{
#if MS_HAVE_OSMESA && MS_HAVE_EGL
    return "\"osmesa\", \"egl\"";
#elif MS_HAVE_OSMESA
    return "\"osmesa\"";
#elif MS_HAVE_EGL
    return "\"egl\"";
#else
    return "none";
#endif
}

ms_status ms_gl_context_create(ms_gl_context *c, const char *want)
{
    int any = !want || !strcmp(want, "auto");
    ms_status st = MS_ERR_UNSUPPORTED;
    char first[512] = "";
    for (int i = 0; backends[i]; ++i) {
        if (!any && strcmp(want, backends[i]->name) != 0)
            continue;
        c->backend = backends[i];
        c->impl = NULL;
        st = backends[i]->create(c);
        if (st == MS_OK)
            return MS_OK;
        if (!first[0])
            snprintf(first, sizeof first, "%s", ms_last_error());
    }
    c->backend = NULL;
    if (first[0])
        return ms_fail(st, "%s", first);
    return ms_fail(MS_ERR_UNSUPPORTED,
                   "render: backend \"%s\" is not in this build of libmodesplit (it has %s)", want,
                   ms_gl_backends_built());
}

ms_status ms_gl_context_begin(ms_gl_context *c)
{
    ms_status st = c->backend->begin(c);
    if (st == MS_OK)
        current = c;
    return st;
}

void ms_gl_context_end(void)
{
    if (current && current->backend)
        current->backend->end(current);
    current = NULL;
}

void ms_gl_context_destroy(ms_gl_context *c)
{
    if (c->backend && c->impl)
        c->backend->destroy(c);
    c->impl = NULL;
}
