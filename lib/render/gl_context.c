/* The renderer's OSMesa context (Mesa's llvmpipe: OpenGL on the CPU).
 *
 * Each renderer owns a context; every call makes it current in the calling
 * thread and releases it after, so a renderer may move between threads
 * (one at a time). OSMesa keeps a process-wide list of the framebuffers it
 * makes for MakeCurrent; a mutex guards creation, MakeCurrent and
 * destruction so renderers in different threads do not race on it. Mesa
 * keeps that framebuffer after the context is destroyed (one per pixel
 * format, reused): under AddressSanitizer the leak checker is told to look
 * away while Mesa allocates it, as it is not ours to report. */
#include <pthread.h>

#include "core/internal.h"
#include "render/gl_internal.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define MESA_LEAKS_BEGIN() __lsan_disable()
#define MESA_LEAKS_END() __lsan_enable()
#else
#define MESA_LEAKS_BEGIN() ((void)0)
#define MESA_LEAKS_END() ((void)0)
#endif

static pthread_mutex_t osmesa_lock = PTHREAD_MUTEX_INITIALIZER;

ms_status ms_gl_context_create(ms_gl_context *c)
{
    pthread_mutex_lock(&osmesa_lock);
    MESA_LEAKS_BEGIN();
    /* RGBA, no depth/stencil/accum in the context's own buffer: drawing
     * goes to framebuffer objects */
    c->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    MESA_LEAKS_END();
    pthread_mutex_unlock(&osmesa_lock);
    if (!c->ctx)
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "render: OSMesa cannot make an RGBA context (is Mesa's llvmpipe "
                       "installed?)");
    return MS_OK;
}

ms_status ms_gl_context_begin(ms_gl_context *c)
{
    if (c->borrowed)
        return ms_gl_borrowed_begin(c);
    pthread_mutex_lock(&osmesa_lock);
    MESA_LEAKS_BEGIN();
    GLboolean ok = OSMesaMakeCurrent(c->ctx, c->buffer, GL_UNSIGNED_BYTE, 16, 16);
    MESA_LEAKS_END();
    pthread_mutex_unlock(&osmesa_lock);
    if (!ok)
        return ms_fail(MS_ERR_UNSUPPORTED, "render: OSMesa cannot make the context current");
    return MS_OK;
}

void ms_gl_context_end(void)
{
    if (ms_gl_borrowed_end())
        return;
    pthread_mutex_lock(&osmesa_lock);
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
    pthread_mutex_unlock(&osmesa_lock);
}

void ms_gl_context_destroy(ms_gl_context *c)
{
    if (!c->ctx)
        return;
    pthread_mutex_lock(&osmesa_lock);
    OSMesaDestroyContext(c->ctx);
    pthread_mutex_unlock(&osmesa_lock);
    c->ctx = NULL;
}
