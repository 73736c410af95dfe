/* The EGL context backend: an OpenGL (compatibility profile) context
 * without any surface, on EGL_MESA_platform_surfaceless (Mesa's llvmpipe
 * on a machine without a GPU, the GPU's driver on one with), or on the
 * default display when that platform is missing (a GPU vendor's EGL).
 * Drawing goes to framebuffer objects as with OSMesa, so nothing else of
 * the renderer knows which backend it runs on.
 *
 * EGL displays are per process: the display is initialised by the first
 * context (under a mutex) and kept for the process's life, as OSMesa keeps
 * its framebuffers: eglTerminate would pull it from under other renderers,
 * and Mesa's surfaceless driver leaks 128 bytes per eglTerminate (seen by
 * LeakSanitizer), while a display left initialised frees everything at
 * exit. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <pthread.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

typedef struct egl_impl {
    EGLContext ctx;
} egl_impl;

static pthread_mutex_t egl_lock = PTHREAD_MUTEX_INITIALIZER;
static EGLDisplay egl_display = EGL_NO_DISPLAY;

static int has_extension(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return 1;
    return 0;
}

/* The display, initialised (egl_lock held); EGL_NO_DISPLAY with the error
 * set when there is none. */
static EGLDisplay display_locked(void)
{
    if (egl_display != EGL_NO_DISPLAY)
        return egl_display;
    EGLDisplay d = EGL_NO_DISPLAY;
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (get_platform_display && has_extension(client, "EGL_MESA_platform_surfaceless"))
        d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (d == EGL_NO_DISPLAY)
        d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    EGLint major = 0, minor = 0;
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, &major, &minor)) {
        ms_fail(MS_ERR_UNSUPPORTED,
                "render: EGL has no display to render on (error 0x%04x; is Mesa's "
                "libegl-mesa0 installed?)",
                (unsigned)eglGetError());
        return EGL_NO_DISPLAY;
    }
    egl_display = d;
    return d;
}

static ms_status egl_create(ms_gl_context *c)
{
    egl_impl *e = ms_alloc(sizeof *e);
    if (!e)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for an EGL context");
    ms_status st = MS_OK;
    pthread_mutex_lock(&egl_lock);
    MS_MESA_LEAKS_BEGIN();
    EGLDisplay d = display_locked();
    if (d == EGL_NO_DISPLAY) {
        st = MS_ERR_UNSUPPORTED; /* the sentence is set */
    } else if (!has_extension(eglQueryString(d, EGL_EXTENSIONS), "EGL_KHR_no_config_context") ||
               !has_extension(eglQueryString(d, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        st =
            ms_fail(MS_ERR_UNSUPPORTED, "render: this EGL cannot make a context without a surface "
                                        "(EGL_KHR_no_config_context, EGL_KHR_surfaceless_context)");
    } else if (!eglBindAPI(EGL_OPENGL_API)) {
        st = ms_fail(MS_ERR_UNSUPPORTED, "render: this EGL has no desktop OpenGL (error 0x%04x)",
                     (unsigned)eglGetError());
    } else {
        /* no version asked: the highest compatibility profile, which the
         * renderer's GLSL 1.20 programs and client arrays need */
        static const EGLint attribs[] = {EGL_NONE};
        e->ctx = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
        if (e->ctx == EGL_NO_CONTEXT)
            st = ms_fail(MS_ERR_UNSUPPORTED,
                         "render: EGL cannot make an OpenGL context (error 0x%04x)",
                         (unsigned)eglGetError());
    }
    MS_MESA_LEAKS_END();
    pthread_mutex_unlock(&egl_lock);
    if (st != MS_OK) {
        ms_free(e);
        return st;
    }
    c->impl = e;
    return MS_OK;
}

static ms_status egl_begin(ms_gl_context *c)
{
    egl_impl *e = c->impl;
    MS_MESA_LEAKS_BEGIN();
    EGLBoolean ok = eglBindAPI(EGL_OPENGL_API) &&
                    eglMakeCurrent(egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx);
    MS_MESA_LEAKS_END();
    if (!ok)
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "render: EGL cannot make the context current "
                       "(error 0x%04x)",
                       (unsigned)eglGetError());
    return MS_OK;
}

static void egl_end(ms_gl_context *c)
{
    (void)c;
    eglMakeCurrent(egl_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

static void egl_destroy(ms_gl_context *c)
{
    egl_impl *e = c->impl;
    if (!e)
        return;
    eglDestroyContext(egl_display, e->ctx);
    ms_free(e);
    c->impl = NULL;
}

const ms_gl_backend ms_gl_backend_egl = {
    "egl", egl_create, egl_begin, egl_end, egl_destroy,
};
