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
#include <string.h>

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
void ms_gl_env_viewpoints(const ms_renderer_desc *d, float mirror[3], float virt[3])
{
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

/* An n x n sRGB cube map with room for all its mipmap levels. */
static GLuint env_texture(int n)
{
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    for (int level = 0, m = n; m >= 1; ++level, m /= 2)
        for (int f = 0; f < 6; ++f)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, level, GL_SRGB8_ALPHA8, m, m,
                         0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    return tex;
}

/* The projection of the environment's faces: 90 degrees, far enough for
 * the pool and its deck seen from either viewpoint. */
static void env_projection(const ms_renderer *r, float eyes[2][3], float proj[16])
{
    const ms_renderer_desc *d = &r->desc;
    ms_gl_env_viewpoints(&r->desc, eyes[0], eyes[1]);
    const float ext = MS_MAX(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    double far2 = 0;
    for (int h = 0; h < 2; ++h)
        for (int k = 0; k < 3; ++k) {
            double c = 0.5 * ((double)d->pool_min[k] + d->pool_max[k]);
            far2 += (eyes[h][k] - c) * (eyes[h][k] - c);
        }
    const float zfar = (float)(sqrt(far2) + 3.0 * ext);
    ms_mat4_perspective(90.0f, 1.0f, 1e-4f * zfar, zfar, proj);
}

ms_status ms_gl_env_create(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    const int n = gl->env_size;
    if (!gl->env_static)
        gl->env_static = env_texture(n);

    GLuint fbo, depth;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, n, n);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);

    float eyes[2][3], proj[16], view[16];
    env_projection(r, eyes, proj);
    const float sun_under = (r->shader.vt->passes & MS_SHADER_NEEDS_CAUSTICS) ? 0.0f : 1.0f;
    const int draw_pool[2] = {(r->passes & MS_SHADER_NEEDS_REFLECTION) != 0,
                              (r->passes & MS_SHADER_NEEDS_REFRACTION) != 0};
    ms_status st = MS_OK;
    glViewport(0, 0, n, n);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_SCISSOR_TEST);
    for (int f = 0; f < 6 && st == MS_OK; ++f) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, gl->env_static, 0);
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
    glBindTexture(GL_TEXTURE_CUBE_MAP, gl->env_static);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    /* the objects go in with the next frame (ms_gl_env_objects) */
    gl->env_tex = gl->env_static;
    gl->env_live_fresh = 0;
    return ms_gl_check("drawing the pool into the environment cubemap");
}

/* ---- the objects in the environment ------------------------------------
 *
 * The boat, the obstacles and the glass move every frame, and drawing the
 * whole environment costs more than a frame (about 200 ms at 1024^2 faces
 * on llvmpipe, the mipmaps alone 80-150 ms). So ms_env is then a second
 * cube map, env_live: env_static copied once, and each frame, in each face
 * and half, only the rectangle the objects covered last frame or cover now
 * is copied back from env_static (glCopyImageSubData), the objects are
 * drawn into it from the half's viewpoint (their parts above the water
 * plane into the reflection half, under it into the refraction half), and
 * the coarser mipmap levels of that rectangle are made again from the
 * finer (a bilinear lookup at the centre of 2 x 2 texels is their mean,
 * in linear light as the sRGB texture decodes it). The liquid's shader
 * then sees them by the same lookups as the pool: an object under the
 * water refracted, above it reflected. */

/* A hash of what the objects were drawn from (FNV-1a). */
static unsigned long long objects_hash(const ms_renderer *r)
{
    unsigned long long h = 1469598103934665603ull;
    const unsigned char *p = (const unsigned char *)r->object_verts;
    const size_t n =
        r->object_verts ? (size_t)r->object_nverts * MS_RENDER_OBJECT_STRIDE * sizeof(float) : 0;
    for (size_t i = 0; i < n; ++i)
        h = (h ^ p[i]) * 1099511628211ull;
    const float boat[7] = {(float)r->has_boat, r->boat_pos[0],     r->boat_pos[1], r->boat_pos[2],
                           r->boat_heading[0], r->boat_heading[1], r->boat_radius};
    p = (const unsigned char *)boat;
    for (size_t i = 0; i < sizeof boat; ++i)
        h = (h ^ p[i]) * 1099511628211ull;
    return h | 1; /* never 0: 0 is "nothing drawn" */
}

/* The world box of the objects (the boat's hull within its radius). */
static int objects_bounds(const ms_renderer *r, float lo[3], float hi[3])
{
    int any = 0;
    for (int k = 0; k < 3; ++k)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (int v = 0; v < r->object_nverts; ++v, any = 1)
        for (int k = 0; k < 3; ++k) {
            const float x = r->object_verts[MS_RENDER_OBJECT_STRIDE * (size_t)v + k];
            lo[k] = MS_MIN(lo[k], x), hi[k] = MS_MAX(hi[k], x);
        }
    if (r->has_boat) {
        const float L = r->boat_radius; /* the hull: 0.35 L above, 0.2 L below */
        for (int k = 0; k < 2; ++k) {
            lo[k] = MS_MIN(lo[k], r->boat_pos[k] - L);
            hi[k] = MS_MAX(hi[k], r->boat_pos[k] + L);
        }
        lo[2] = MS_MIN(lo[2], r->boat_pos[2] - 0.25f * L);
        hi[2] = MS_MAX(hi[2], r->boat_pos[2] + 0.4f * L);
        any = 1;
    }
    return any;
}

/* The texels of face f (n x n, from eye) the box lo..hi covers, as
 * x0, y0, x1, y1 (x1 <= x0: none), padded and widened to multiples of 4
 * texels so the next two mipmap levels' rectangles are exact halves. */
static void face_rect(int f, int n, const float eye[3], const float lo[3], const float hi[3],
                      int out[4])
{
    float R[3], U[3], F[3];
    face_basis(f, R, U, F);
    float s0 = INFINITY, s1 = -INFINITY, t0 = INFINITY, t1 = -INFINITY;
    int behind = 0, front = 0;
    for (int c = 0; c < 8; ++c) {
        float v[3];
        for (int k = 0; k < 3; ++k)
            v[k] = ((c >> k) & 1 ? hi[k] : lo[k]) - eye[k];
        const float z = v[0] * F[0] + v[1] * F[1] + v[2] * F[2];
        const float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (z <= 1e-3f * len) {
            behind = 1;
            continue;
        }
        front = 1;
        const float s = (v[0] * R[0] + v[1] * R[1] + v[2] * R[2]) / z;
        const float t = (v[0] * U[0] + v[1] * U[1] + v[2] * U[2]) / z;
        s0 = MS_MIN(s0, s), s1 = MS_MAX(s1, s), t0 = MS_MIN(t0, t), t1 = MS_MAX(t1, t);
    }
    out[0] = out[1] = out[2] = out[3] = 0;
    if (!front)
        return;
    if (behind) /* the box straddles the face's plane: all of it */
        s0 = t0 = -1, s1 = t1 = 1;
    const float half = 0.5f * (float)n;
    const float x0 = half * (MS_MAX(s0, -1.0f) + 1) - 2, x1 = half * (MS_MIN(s1, 1.0f) + 1) + 2;
    const float y0 = half * (MS_MAX(t0, -1.0f) + 1) - 2, y1 = half * (MS_MIN(t1, 1.0f) + 1) + 2;
    if (x1 <= x0 || y1 <= y0 || s0 > 1 || t0 > 1 || s1 < -1 || t1 < -1)
        return;
    out[0] = MS_MAX(0, ((int)floorf(x0)) & ~3);
    out[1] = MS_MAX(0, ((int)floorf(y0)) & ~3);
    out[2] = MS_MIN(n, ((int)ceilf(x1) + 3) & ~3);
    out[3] = MS_MIN(n, ((int)ceilf(y1) + 3) & ~3);
}

static int rect_empty(const int a[4])
{
    return a[2] <= a[0] || a[3] <= a[1];
}

/* a = a n b; b = the half rectangle as x, y, width, height */
static void rect_clip(int a[4], const int b[4])
{
    a[0] = MS_MAX(a[0], b[0]), a[1] = MS_MAX(a[1], b[1]);
    a[2] = MS_MIN(a[2], b[0] + b[2]), a[3] = MS_MIN(a[3], b[1] + b[3]);
    if (rect_empty(a))
        a[0] = a[1] = a[2] = a[3] = 0;
}

/* Levels 1.. of face f of env_live made again over rect (level 0 texels)
 * from the level above each: the sky program reads env_live restricted to
 * level l - 1 while level l is drawn. */
static void remake_mipmaps(ms_renderer *r, int f, const int rect[4])
{
    ms_gl *gl = r->gl;
    float R[3], U[3], F[3];
    face_basis(f, R, U, F);
    const GLuint sky = gl->sky_tex;
    gl->sky_tex = gl->env_live;
    for (int level = 1; (gl->env_size >> level) >= 1; ++level) {
        const int m = gl->env_size >> level;
        const int x0 = rect[0] >> level, y0 = rect[1] >> level;
        const int x1 = MS_MIN(m, (rect[2] + (1 << level) - 1) >> level);
        const int y1 = MS_MIN(m, (rect[3] + (1 << level) - 1) >> level);
        glBindTexture(GL_TEXTURE_CUBE_MAP, gl->env_live);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, level - 1);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, level - 1);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, gl->env_live, level);
        glViewport(0, 0, m, m);
        glScissor(x0, y0, x1 - x0, y1 - y0);
        glClear(GL_DEPTH_BUFFER_BIT);
        ms_gl_sky_draw(r, F, R, U);
    }
    gl->sky_tex = sky;
    glBindTexture(GL_TEXTURE_CUBE_MAP, gl->env_live);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 1000);
}

ms_status ms_gl_env_objects(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    const int n = gl->env_size;
    if (!gl->env_static)
        return MS_OK; /* the shader looks up the plain sky */
    float lo[3], hi[3];
    if (gl->discs_count <= gl->objects_first || !objects_bounds(r, lo, hi)) {
        gl->env_tex = gl->env_static;
        gl->env_live_fresh = 0;
        return MS_OK;
    }
    if (!gl->env_copy_checked) {
        /* glCopyImageSubData is GL 4.3 (or ARB_copy_image): Mesa's
         * llvmpipe has 4.5; without it the objects stay out of ms_env */
        GLint major = 0, minor = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        glGetIntegerv(GL_MINOR_VERSION, &minor);
        int ok = major > 4 || (major == 4 && minor >= 3);
        GLint n_ext = 0;
        if (!ok)
            glGetIntegerv(GL_NUM_EXTENSIONS, &n_ext);
        for (GLint i = 0; !ok && i < n_ext; ++i)
            ok = !strcmp((const char *)glGetStringi(GL_EXTENSIONS, (GLuint)i), "GL_ARB_copy_image");
        gl->env_copy_checked = ok ? 1 : -1;
    }
    if (gl->env_copy_checked < 0) {
        gl->env_tex = gl->env_static;
        return MS_OK;
    }
    const unsigned long long hash = objects_hash(r);
    /* nothing moved, and no caustics play on the objects under the water */
    if (gl->env_live_fresh && gl->env_tex == gl->env_live && hash == gl->env_objects_hash &&
        !r->trace_caustics)
        return MS_OK;
    if (!gl->env_live) {
        gl->env_live = env_texture(n);
        glGenFramebuffers(1, &gl->env_fbo);
        glGenRenderbuffers(1, &gl->env_depth);
        glBindRenderbuffer(GL_RENDERBUFFER, gl->env_depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, n, n);
    }
    if (!gl->env_live_fresh) {
        for (int level = 0; (n >> level) >= 1; ++level)
            glCopyImageSubData(gl->env_static, GL_TEXTURE_CUBE_MAP, level, 0, 0, 0, gl->env_live,
                               GL_TEXTURE_CUBE_MAP, level, 0, 0, 0, n >> level, n >> level, 6);
        memset(gl->env_rect, 0, sizeof gl->env_rect);
        gl->env_live_fresh = 1;
    }
    gl->env_tex = gl->env_live;
    gl->env_objects_hash = hash;

    float eyes[2][3], proj[16], view[16];
    env_projection(r, eyes, proj);
    /* as the pool: with a caustics shader, lit by the sky alone under the
     * water, and the sun through the caustics light map where it reaches
     * them (gl_pool.c: alpha 0 marks them lit, for the liquid's shader) */
    const float sun_under = (r->shader.vt->passes & MS_SHADER_NEEDS_CAUSTICS) ? 0.0f : 1.0f;
    const int pass[2] = {(r->passes & MS_SHADER_NEEDS_REFLECTION) != 0,
                         (r->passes & MS_SHADER_NEEDS_REFRACTION) != 0};
    const float level = r->desc.water_level;
    glBindFramebuffer(GL_FRAMEBUFFER, gl->env_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, gl->env_depth);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_SCISSOR_TEST);
    for (int h = 0; h < 2; ++h) {
        /* the part of the box on this half's side of the water plane */
        float blo[3] = {lo[0], lo[1], h == 0 ? MS_MAX(lo[2], level) : lo[2]};
        float bhi[3] = {hi[0], hi[1], h == 0 ? hi[2] : MS_MIN(hi[2], level)};
        const int any = pass[h] && bhi[2] > blo[2];
        for (int f = 0; f < 6; ++f) {
            int half[4], now[4] = {0, 0, 0, 0}, dirty[4];
            if (!half_rect(f, n, h == 0, half))
                continue;
            if (any) {
                face_rect(f, n, eyes[h], blo, bhi, now);
                rect_clip(now, half);
            }
            const int *was = gl->env_rect[h][f];
            if (rect_empty(was) && rect_empty(now))
                continue;
            memcpy(dirty, rect_empty(was) ? now : was, sizeof dirty);
            if (!rect_empty(was) && !rect_empty(now)) {
                dirty[0] = MS_MIN(was[0], now[0]), dirty[1] = MS_MIN(was[1], now[1]);
                dirty[2] = MS_MAX(was[2], now[2]), dirty[3] = MS_MAX(was[3], now[3]);
            }
            /* back to the pool and the sky where the objects were */
            glCopyImageSubData(gl->env_static, GL_TEXTURE_CUBE_MAP, 0, dirty[0], dirty[1], f,
                               gl->env_live, GL_TEXTURE_CUBE_MAP, 0, dirty[0], dirty[1], f,
                               dirty[2] - dirty[0], dirty[3] - dirty[1], 1);
            if (!rect_empty(now)) {
                float R[3], U[3], F[3];
                face_basis(f, R, U, F);
                glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                       GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, gl->env_live, 0);
                glViewport(0, 0, n, n);
                glScissor(now[0], now[1], now[2] - now[0], now[3] - now[1]);
                glClear(GL_DEPTH_BUFFER_BIT);
                ms_mat4_basis_view(eyes[h], R, U, F, view);
                glMatrixMode(GL_PROJECTION);
                glLoadMatrixf(proj);
                glMatrixMode(GL_MODELVIEW);
                glLoadMatrixf(view);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LEQUAL);
                ms_gl_objects_draw(r, eyes[h], sun_under, h == 0 ? +1.0f : -1.0f);
            }
            remake_mipmaps(r, f, dirty);
            memcpy(gl->env_rect[h][f], now, sizeof now);
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return ms_gl_check("drawing the objects into the environment cubemap");
}
