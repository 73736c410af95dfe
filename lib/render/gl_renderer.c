/* Making and unmaking the GL side of a renderer: the context, the sRGB
 * image framebuffer, the shader plugin's program, the sky, the pool, the
 * refraction cubemap and the caustics texture (only for the passes the
 * shader asks for). */
#include <stdio.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

/* Side of the environment cubemap's faces: about the image's longer side
 * (a face spans 90 degrees, wider than most views, so this keeps the pool
 * seen through the water about as sharp as the image), a power of two in
 * [128, 1024]. */
static int env_size_for(int w, int h)
{
    int want = MS_MAX(w, h), n = 128;
    while (n < want && n < 1024)
        n *= 2;
    return n;
}

static ms_status make_framebuffer(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    const int w = r->desc.width, h = r->desc.height;
    glGenFramebuffers(1, &gl->fbo);
    glGenRenderbuffers(1, &gl->color_rb);
    glGenRenderbuffers(1, &gl->depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, gl->color_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_SRGB8_ALPHA8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, gl->depth_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, gl->fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, gl->color_rb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, gl->depth_rb);
    GLenum fs = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (fs != GL_FRAMEBUFFER_COMPLETE)
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "render: OpenGL cannot draw a %d x %d sRGB image (framebuffer status "
                       "0x%04x)",
                       w, h, (unsigned)fs);
    return ms_gl_check("making the image framebuffer");
}

static ms_status make_caustics_texture(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    glGenTextures(1, &gl->caustics_tex);
    glBindTexture(GL_TEXTURE_2D, gl->caustics_tex);
    const float one = 1.0f;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, 1, 1, 0, GL_RED, GL_FLOAT, &one);
    gl->caustics_n = 1;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return ms_gl_check("making the caustics texture");
}

static ms_status build(ms_renderer *r, const ms_cubemap *sky)
{
    ms_gl *gl = r->gl;
    ms_status st;
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    if ((st = make_framebuffer(r)) != MS_OK)
        return st;
    char what[96];
    snprintf(what, sizeof what, "shader \"%.40s\"", r->desc.shader);
    const ms_shader_vtable *vt = r->shader.vt;
    if ((st = ms_gl_program_build(what, vt->vertex_source, vt->fragment_source, &gl->liquid)) !=
            MS_OK ||
        (st = ms_gl_sky_create(r, sky)) != MS_OK || (st = ms_gl_pool_create(r)) != MS_OK)
        return st;
    gl->liquid_clips = strstr(vt->vertex_source, "gl_ClipVertex") != NULL;
    if (r->passes & (MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION)) {
        gl->env_size = env_size_for(r->desc.width, r->desc.height);
        if ((st = ms_gl_env_create(r)) != MS_OK)
            return st;
    } else {
        gl->env_tex = gl->sky_tex;
    }
    if ((vt->passes & MS_SHADER_NEEDS_CAUSTICS) && (st = make_caustics_texture(r)) != MS_OK)
        return st;
    glGenBuffers(1, &gl->mesh_vbo);
    glGenBuffers(1, &gl->mesh_ibo);
    return ms_gl_check("making the renderer");
}

ms_status ms_gl_create(ms_renderer *r, const ms_cubemap *sky)
{
    ms_gl *gl = ms_alloc(sizeof *gl);
    if (!gl)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for the GL state");
    r->gl = gl;
    r->in_context = ms_gl_borrow_requested();
    ms_status st = r->in_context ? ms_gl_context_borrow(&gl->context)
                                 : ms_gl_context_create(&gl->context, r->desc.backend);
    if (st != MS_OK)
        return st;
    r->stats.backend = gl->context.backend->name;
    if ((st = ms_gl_context_begin(&gl->context)) != MS_OK)
        return st;
    st = build(r, sky);
    ms_gl_context_end();
    return st;
}

ms_status ms_gl_camera_moved(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    if (gl->env_tex == gl->sky_tex)
        return MS_OK; /* the plain sky: no viewpoint */
    ms_status st = ms_gl_context_begin(&gl->context);
    if (st != MS_OK)
        return st;
    st = ms_gl_env_create(r);
    ms_gl_context_end();
    return st;
}

void ms_gl_destroy(ms_gl *gl)
{
    if (!gl)
        return;
    /* the context takes its objects with it; a borrowed one stays */
    if (gl->context.borrowed)
        ms_gl_delete_objects(gl);
    ms_gl_context_destroy(&gl->context);
    ms_free(gl->vertices);
    ms_free(gl->coarse);
    ms_free(gl->gradients);
    ms_free(gl);
}
