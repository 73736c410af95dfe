/* The OSMesa context backend (Mesa's llvmpipe: OpenGL on the CPU, no
 * display). OSMesa keeps a process-wide list of the framebuffers it makes
 * for MakeCurrent; a mutex guards creation, MakeCurrent and destruction so
 * renderers in different threads do not race on it. Mesa keeps that
 * framebuffer after the context is destroyed (one per pixel format,
 * reused): under AddressSanitizer the leak checker is told to look away
 * while Mesa allocates it, as it is not ours to report. OSMesa left Mesa
 * in 25.1; gl_context_egl.c is the path for newer systems. */
#include <GL/osmesa.h>
#include <pthread.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

typedef struct osmesa_impl {
    OSMesaContext ctx;
    unsigned char buffer[16 * 16 * 4]; /* the context's own (unused) framebuffer */
} osmesa_impl;

static pthread_mutex_t osmesa_lock = PTHREAD_MUTEX_INITIALIZER;

static ms_status osmesa_create(ms_gl_context *c)
{
    osmesa_impl *o = ms_alloc(sizeof *o);
    if (!o)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for an OSMesa context");
    pthread_mutex_lock(&osmesa_lock);
    MS_MESA_LEAKS_BEGIN();
    /* RGBA, no depth/stencil/accum in the context's own buffer: drawing
     * goes to framebuffer objects */
    o->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    MS_MESA_LEAKS_END();
    pthread_mutex_unlock(&osmesa_lock);
    if (!o->ctx) {
        ms_free(o);
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "render: OSMesa cannot make an RGBA context (is Mesa's llvmpipe "
                       "installed?)");
    }
    c->impl = o;
    return MS_OK;
}

static ms_status osmesa_begin(ms_gl_context *c)
{
    osmesa_impl *o = c->impl;
    pthread_mutex_lock(&osmesa_lock);
    MS_MESA_LEAKS_BEGIN();
    GLboolean ok = OSMesaMakeCurrent(o->ctx, o->buffer, GL_UNSIGNED_BYTE, 16, 16);
    MS_MESA_LEAKS_END();
    pthread_mutex_unlock(&osmesa_lock);
    if (!ok)
        return ms_fail(MS_ERR_UNSUPPORTED, "render: OSMesa cannot make the context current");
    return MS_OK;
}

static void osmesa_end(ms_gl_context *c)
{
    (void)c;
    pthread_mutex_lock(&osmesa_lock);
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
    pthread_mutex_unlock(&osmesa_lock);
}

static void osmesa_destroy(ms_gl_context *c)
{
    osmesa_impl *o = c->impl;
    if (!o)
        return;
    pthread_mutex_lock(&osmesa_lock);
    OSMesaDestroyContext(o->ctx);
    pthread_mutex_unlock(&osmesa_lock);
    ms_free(o);
    c->impl = NULL;
}

const ms_gl_backend ms_gl_backend_osmesa = {
    "osmesa", osmesa_create, osmesa_begin, osmesa_end, osmesa_destroy,
};
