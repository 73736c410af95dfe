/* ms_env: the environment the liquid's shader looks up by direction. The
 * paper's cubemap reflection and refraction (section 3.6, after Sousa
 * 2005): the scene is split by the still water surface, and each half is
 * drawn into the half of the cubemap its rays look up:
 *   - upward directions (reflected rays) see the pool above the water, the
 *     deck and the sky from the eye's mirror image under the water plane,
 *     which is exact for flat water (a plane mirror); waves bend the
 *     lookups as they bend the reflected rays;
 *   - downward directions (refracted rays) see the pool under the water
 *     from the eye's virtual image above it: a ray refracted at the plane
 *     seems to come from a point straight above the eye at the height
 *     L + H tan(i) / tan(t) (H the eye's height over the water, i and t the
 *     angles of incidence and refraction by Snell's law, taken for the ray
 *     to the view's target; n H when looking straight down), so for flat
 *     water the floor under each pixel is where the lookup finds it.
 * A shader that needs no reflection (refraction) gets the plain sky in that
 * half. Drawn at create and again when the camera moves. With a
 * caustics shader the pool under water is lit by the sky alone: the shader
 * brings the sun through the caustics light map. */
#include <math.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

/* Face f looks along F; texel (s, t) along F + s R + t U (OpenGL's cube
 * map convention, ms_cubemap_direction). */
static void face_basis(int f, float R[3], float U[3], float F[3])
{
    float o[3], sx[3], ty[3];
    ms_cubemap_direction(f, 0, 0, o);
    ms_cubemap_direction(f, 1, 0, sx);
    ms_cubemap_direction(f, 0, 1, ty);
    for (int k = 0; k < 3; ++k) {
        F[k] = o[k];
        R[k] = sx[k] - o[k];
        U[k] = ty[k] - o[k];
    }
}

/* The texels of face f (n x n) whose directions point up (upper = 1) or
 * down, as a scissor rectangle; 0 if none. Directions on the horizon go to
 * the upper half. */
static int half_rect(int f, int n, int upper, int rect[4])
{
    int h = n / 2;
    switch (f) {
    case 0: /* +x: z = -s: up on the left columns */
        rect[0] = upper ? 0 : h, rect[1] = 0, rect[2] = upper ? h : n - h, rect[3] = n;
        return 1;
    case 1: /* -x: z = s */
        rect[0] = upper ? h : 0, rect[1] = 0, rect[2] = upper ? n - h : h, rect[3] = n;
        return 1;
    case 2: /* +y: z = t: up on the upper rows */
        rect[0] = 0, rect[1] = upper ? h : 0, rect[2] = n, rect[3] = upper ? n - h : h;
        return 1;
    case 3: /* -y: z = -t */
        rect[0] = 0, rect[1] = upper ? 0 : h, rect[2] = n, rect[3] = upper ? h : n - h;
        return 1;
    case 4: /* +z: all up */
        rect[0] = 0, rect[1] = 0, rect[2] = n, rect[3] = n;
        return upper;
    default: /* -z: all down */
        rect[0] = 0, rect[1] = 0, rect[2] = n, rect[3] = n;
        return !upper;
    }
}

/* Where the two halves are seen from (see the file's comment). */
static void viewpoints(const ms_renderer *r, float mirror[3], float virt[3])
{
    const ms_renderer_desc *d = &r->desc;
    const float L = d->water_level, H = d->eye[2] - L;
    const float ext = MS_MAX(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    if (!(H > 1e-4f * ext)) {
        /* the eye at or under the water: both from the pool's centre */
        mirror[0] = virt[0] = 0.5f * (d->pool_min[0] + d->pool_max[0]);
        mirror[1] = virt[1] = 0.5f * (d->pool_min[1] + d->pool_max[1]);
        mirror[2] = virt[2] = L;
        return;
    }
    /* the angle of incidence of the ray to the target, where it meets the
     * water (straight down if it never does) */
    double v[3], horiz = 0, len = 0;
    for (int k = 0; k < 3; ++k)
        v[k] = (double)d->target[k] - d->eye[k];
    double sin_i = 0;
    if (v[2] < 0) {
        horiz = sqrt(v[0] * v[0] + v[1] * v[1]);
        len = sqrt(horiz * horiz + v[2] * v[2]);
        sin_i = horiz / len;
    }
    double n = d->ior, k = n;
    if (sin_i > 1e-6) {
        double sin_t = sin_i / n, cos_i = sqrt(1 - sin_i * sin_i), cos_t = sqrt(1 - sin_t * sin_t);
        k = (sin_i / cos_i) / (sin_t / cos_t); /* tan i / tan t */
    }
    mirror[0] = virt[0] = d->eye[0];
    mirror[1] = virt[1] = d->eye[1];
    mirror[2] = L - H;
    virt[2] = (float)(L + k * H);
}

ms_status ms_gl_env_create(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    const ms_renderer_desc *d = &r->desc;
    const int n = gl->env_size;
    if (!gl->env_tex) {
        glGenTextures(1, &gl->env_tex);
        glBindTexture(GL_TEXTURE_CUBE_MAP, gl->env_tex);
        for (int f = 0; f < 6; ++f)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_SRGB8_ALPHA8, n, n, 0,
                         GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    }

    GLuint fbo, depth;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, n, n);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);

    float eyes[2][3];
    viewpoints(r, eyes[0], eyes[1]);
    const float ext = MS_MAX(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    double far2 = 0;
    for (int h = 0; h < 2; ++h)
        for (int k = 0; k < 3; ++k) {
            double c = 0.5 * ((double)d->pool_min[k] + d->pool_max[k]);
            far2 += (eyes[h][k] - c) * (eyes[h][k] - c);
        }
    const float zfar = (float)(sqrt(far2) + 3.0 * ext);
    float proj[16], view[16];
    ms_mat4_perspective(90.0f, 1.0f, 1e-4f * zfar, zfar, proj);
    const float sun_under = (r->shader.vt->passes & MS_SHADER_NEEDS_CAUSTICS) ? 0.0f : 1.0f;
    const int draw_pool[2] = {(r->passes & MS_SHADER_NEEDS_REFLECTION) != 0,
                              (r->passes & MS_SHADER_NEEDS_REFRACTION) != 0};
    ms_status st = MS_OK;
    glViewport(0, 0, n, n);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_SCISSOR_TEST);
    for (int f = 0; f < 6 && st == MS_OK; ++f) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, gl->env_tex, 0);
        GLenum fs = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (fs != GL_FRAMEBUFFER_COMPLETE) {
            st = ms_fail(MS_ERR_UNSUPPORTED,
                         "render: OpenGL cannot draw into a %d x %d sRGB cube map face "
                         "(framebuffer status 0x%04x)",
                         n, n, (unsigned)fs);
            break;
        }
        float R[3], U[3], F[3];
        face_basis(f, R, U, F);
        for (int h = 0; h < 2; ++h) { /* 0: upper half (reflection), 1: lower */
            int rect[4];
            if (!half_rect(f, n, h == 0, rect) || rect[2] <= 0 || rect[3] <= 0)
                continue;
            glScissor(rect[0], rect[1], rect[2], rect[3]);
            glClearColor(0, 0, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            if (draw_pool[h]) {
                ms_mat4_basis_view(eyes[h], R, U, F, view);
                glMatrixMode(GL_PROJECTION);
                glLoadMatrixf(proj);
                glMatrixMode(GL_MODELVIEW);
                glLoadMatrixf(view);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LEQUAL);
                glDisable(GL_CULL_FACE);
                /* only the pool on this half's side of the water plane */
                ms_gl_pool_draw(r, sun_under, h == 0 ? +1.0f : -1.0f);
            }
            ms_gl_sky_draw(r, F, R, U);
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    if (st != MS_OK)
        return st;
    glBindTexture(GL_TEXTURE_CUBE_MAP, gl->env_tex);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    return ms_gl_check("drawing the pool into the environment cubemap");
}
