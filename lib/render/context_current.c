/* A renderer that draws with the caller's current GL context (a window's,
 * an engine's) instead of an OSMesa context of its own:
 * ms_renderer_create_in_context (render.h). Compiled in every build; without
 * a GL backend the call says the build has no OpenGL. Used by `modesplit view`, whose
 * SDL window has a GLX context: the renderer's GL code then draws into the
 * window, not into a second renderer's buffer.
 *
 * How it works with the same GL code: Mesa's libOSMesa and its GLX driver
 * share one dispatch (libglapi), so the gl* calls the renderer makes go to
 * whichever Mesa context is current in the thread. The renderer still
 * draws into its own sRGB framebuffer object of the desc's size; at the
 * end of a frame, instead of reading the pixels back, it copies them
 * (glBlitFramebuffer, no sRGB conversion: the encoded bytes) into the
 * framebuffer that was bound for drawing when ms_renderer_draw was called
 * (0: the window's back buffer), at (0, 0). The caller swaps buffers.
 *
 * A borrowed context is not made current or released by the renderer, and
 * it is not destroyed with it: ms_renderer_destroy deletes the GL objects
 * the renderer made, so call it with the context still current (after the
 * context is gone, e.g. lost, the deletions do nothing). */
#include "core/core_internal.h"
#include "render/render_internal.h"

#if MS_HAVE_GL
#include "render/gl_internal.h"

/* Set while ms_renderer_create_in_context runs ms_renderer_create_desc,
 * so the create path stays one (ms_gl_create reads it); per thread. */
static _Thread_local int borrow_next;

int ms_gl_borrow_requested(void)
{
    return borrow_next;
}

/* The borrowed context as a backend of gl_context.c (ms_gl_backend): it is
 * the caller's, so it is never made current, released or destroyed here;
 * begin checks it is current and remembers where the frame goes. */
static ms_status borrowed_create(ms_gl_context *c)
{
    (void)c;
    return MS_OK;
}

static ms_status borrowed_begin(ms_gl_context *c)
{
    if (!glGetString(GL_VERSION))
        return ms_fail(MS_ERR_STATE, "render: the renderer draws with the caller's OpenGL "
                                     "context, and none is current in this thread");
    GLint fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    c->target_fbo = (GLuint)fbo;
    return MS_OK;
}

static void borrowed_end(ms_gl_context *c)
{
    (void)c; /* the caller's context stays current */
}

static void borrowed_destroy(ms_gl_context *c)
{
    (void)c; /* the caller's; ms_gl_delete_objects deleted what the renderer made */
}

static const ms_gl_backend backend_borrowed = {
    .name = "window",
    .create = borrowed_create,
    .begin = borrowed_begin,
    .end = borrowed_end,
    .destroy = borrowed_destroy,
};

ms_status ms_gl_context_borrow(ms_gl_context *c)
{
    c->backend = &backend_borrowed;
    c->impl = NULL;
    c->borrowed = 1;
    c->target_fbo = 0;
    /* with no context current, Mesa's dispatch answers NULL */
    if (!glGetString(GL_VERSION))
        return ms_fail(MS_ERR_STATE, "render: no OpenGL context is current in this thread; "
                                     "make the window's context current before "
                                     "ms_renderer_create_in_context");
    return MS_OK;
}

void ms_gl_present(ms_renderer *r)
{
    const ms_gl *gl = r->gl;
    const int w = r->desc.width, h = r->desc.height;
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, gl->fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gl->context.target_fbo);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, gl->context.target_fbo);
}

void ms_gl_delete_objects(ms_gl *gl)
{
    if (!glGetString(GL_VERSION))
        return; /* the context is gone and its objects with it */
    GLuint tex[5] = {gl->sky_tex, gl->env_static, gl->tiles_tex, gl->caustics_tex, gl->normal_tex};
    glDeleteTextures(5, tex);
    glDeleteTextures(1, &gl->env_live);
    glDeleteTextures(1, &gl->walls_tex);
    glDeleteTextures(1, &gl->open_tex);
    glDeleteFramebuffers(1, &gl->env_fbo);
    glDeleteRenderbuffers(1, &gl->env_depth);
    glDeleteTextures(1, &gl->foam_tex);
    GLuint buf[5] = {gl->pool_vbo, gl->discs_vbo, gl->mesh_vbo, gl->mesh_ibo, gl->spray_vbo};
    glDeleteBuffers(5, buf);
    GLuint rb[2] = {gl->color_rb, gl->depth_rb};
    glDeleteRenderbuffers(2, rb);
    glDeleteFramebuffers(1, &gl->fbo);
    ms_gl_program_free(&gl->liquid);
    ms_gl_program_free(&gl->pool);
    ms_gl_program_free(&gl->sky);
    ms_gl_program_free(&gl->glass);
    ms_gl_program_free(&gl->spray);
}

ms_status ms_renderer_create_in_context(const ms_renderer_desc *d, ms_renderer **out)
{
    borrow_next = 1;
    ms_status st = ms_renderer_create_desc(d, out);
    borrow_next = 0;
    return st;
}
#else
ms_status ms_renderer_create_in_context(const ms_renderer_desc *d, ms_renderer **out)
{
    (void)d;
    if (out)
        *out = NULL;
    return ms_fail(MS_ERR_UNSUPPORTED,
                   "render: this build of libmodesplit has no OpenGL (OSMesa or EGL); "
                   "install libegl-dev (or libosmesa6-dev) and rebuild to draw into a window");
}
#endif
