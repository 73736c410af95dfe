/* One frame: the height field's mesh (and, if the shader asks for it, the
 * caustics light map) uploaded, then the sky, the pool and the liquid
 * drawn into the sRGB image, read back top row first. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

/* Heights between the floor and the still water at which the caustics
 * are traced too for the objects under the water: 3 (a quarter of the
 * depth apart), the light between them interpolated (gl_pool.c) */
#define MS_CAUSTICS_LAYERS 3

#ifndef BAND_VERTICES
#define BAND_VERTICES 4096
#endif

static void normalize3(float v[3])
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l, v[1] /= l, v[2] /= l;
}

static ms_status upload_mesh(ms_renderer *r, const float *h, const ms_grid *full)
{
    ms_gl *gl = r->gl;
    /* room for the field averaged at any step >= 2 */
    size_t cells = (size_t)MS_MAX(full->nx / 2, 2) * (size_t)MS_MAX(full->ny / 2, 2);
    if (gl->coarse_cap < cells) {
        ms_free(gl->coarse);
        gl->coarse = ms_alloc_array(cells, sizeof(float));
        gl->coarse_cap = gl->coarse ? cells : 0;
        if (!gl->coarse)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for the mesh of a %d x %d field", full->nx,
                           full->ny);
    }
    int step = r->desc.mesh_step > 0 ? r->desc.mesh_step
                                     : ms_mesh_auto_step(&r->desc, h, full, gl->coarse);
    step = MS_MIN(step, MS_MIN(full->nx, full->ny) / 2);
    ms_grid coarse;
    const ms_grid *g = full;
    if (step > 1) {
        ms_mesh_coarsen(h, full, step, gl->coarse, &coarse);
        h = gl->coarse;
        g = &coarse;
    }
    const size_t nv = (size_t)g->nx * (size_t)g->ny, floats = nv * 6;
    if (gl->vertices_cap < floats) {
        ms_free(gl->vertices);
        gl->vertices = ms_alloc_array(floats, sizeof(float));
        gl->vertices_cap = gl->vertices ? floats : 0;
        if (!gl->vertices)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for the mesh of a %d x %d field", g->nx, g->ny);
    }
    ms_mesh_build(h, g, r->desc.pool_min[2], gl->vertices);
    /* display only: the liquid never above the pool's rim, where it would
     * be drawn over the deck (the field itself is not changed) */
    for (size_t k = 0; k < nv; ++k)
        gl->vertices[6 * k + 2] = MS_MIN(gl->vertices[6 * k + 2], r->rim_z);
    ms_status st = ms_render_cavity_cut(r, gl->vertices, g->nx, g->ny); /* glass_fill.c */
    if (st != MS_OK)
        return st;
    r->stats.mesh_nx = g->nx;
    r->stats.mesh_ny = g->ny;
    glBindBuffer(GL_ARRAY_BUFFER, gl->mesh_vbo);
    if (gl->mesh_nx != g->nx || gl->mesh_ny != g->ny)
        glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(floats * sizeof(float)), gl->vertices,
                     GL_DYNAMIC_DRAW);
    else
        glBufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)(floats * sizeof(float)), gl->vertices);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    if (gl->mesh_nx != g->nx || gl->mesh_ny != g->ny) {
        size_t ni = 6 * (size_t)(g->nx - 1) * (size_t)(g->ny - 1);
        unsigned *idx = ms_alloc_array(ni, sizeof *idx);
        if (!idx)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for the triangles of a %d x %d field", g->nx,
                           g->ny);
        ms_mesh_indices(g->nx, g->ny, idx);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl->mesh_ibo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(ni * sizeof *idx), idx, GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        ms_free(idx);
        gl->mesh_nx = g->nx;
        gl->mesh_ny = g->ny;
    }
    return MS_OK;
}

/* The full field's gradient as the texture ms_normal_map (texel (i, j) at
 * cell (i, j)'s centre, bilinear between them), so a shader's normals
 * keep every cell's ripple whatever step the mesh has. */
static ms_status upload_normals(ms_renderer *r, const float *h, const ms_grid *g)
{
    ms_gl *gl = r->gl;
    const size_t floats = 2 * (size_t)g->nx * (size_t)g->ny;
    if (gl->gradients_cap < floats) {
        ms_free(gl->gradients);
        gl->gradients = ms_alloc_array(floats, sizeof(float));
        gl->gradients_cap = gl->gradients ? floats : 0;
        if (!gl->gradients)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for the normals of a %d x %d field", g->nx,
                           g->ny);
    }
    ms_mesh_gradients(h, g, gl->gradients);
    if (!gl->normal_tex) {
        glGenTextures(1, &gl->normal_tex);
        glBindTexture(GL_TEXTURE_2D, gl->normal_tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glBindTexture(GL_TEXTURE_2D, gl->normal_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (gl->normal_nx != g->nx || gl->normal_ny != g->ny) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, g->nx, g->ny, 0, GL_RG, GL_FLOAT, gl->gradients);
        gl->normal_nx = g->nx;
        gl->normal_ny = g->ny;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, g->nx, g->ny, GL_RG, GL_FLOAT, gl->gradients);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    gl->normal_field = *g;
    return MS_OK;
}

static ms_status upload_caustics(ms_renderer *r, const float *h, const ms_grid *g)
{
    ms_gl *gl = r->gl;
    const ms_renderer_desc *d = &r->desc;
    ms_caustics_desc cd = {
        .pool = {d->pool_min[0], d->pool_min[1], d->pool_max[0] - d->pool_min[0],
                 d->pool_max[1] - d->pool_min[1]},
        .floor_z = d->pool_min[2],
        .light_dir = {d->light_dir[0], d->light_dir[1], d->light_dir[2]},
        .ior = d->ior,
        .intensity = d->caustics_intensity,
        .resolution = d->caustics_resolution,
        .depth = d->water_level - d->pool_min[2], /* the walls too (gl_walls.c) */
        /* the obstacles shade the floor (not the glass: it lets light through) */
        .occluders = r->object_glass > 0 ? r->object_verts : NULL,
        .occluder_verts = r->object_glass,
        .occluder_stride = MS_RENDER_OBJECT_STRIDE,
        /* the light in the water for the obstacles (gl_pool.c); not for the
         * boat alone: its hull reaches 0.2 of its length under the water,
         * where the floor's light interpolated to 1 at the surface does,
         * and the layers cost 2.7 times the floor's trace (measured) */
        .layers = r->object_glass > 0 ? MS_CAUSTICS_LAYERS : 0,
    };
    ms_status st = ms_caustics_trace(&r->caustics, &cd, h, g);
    if (st != MS_OK)
        return st;
    const int n = r->caustics.n;
    glBindTexture(GL_TEXTURE_2D, gl->caustics_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (gl->caustics_n != n) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, n, n, 0, GL_RED, GL_FLOAT, r->caustics.map);
        gl->caustics_n = n;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, n, GL_RED, GL_FLOAT, r->caustics.map);
    }
    if ((st = ms_gl_open_upload(r)) != MS_OK)
        return st;
    return ms_gl_walls_upload(r);
}

/* Near and far planes that hold the pool and its deck. */
static void depth_range(const ms_renderer *r, float *znear, float *zfar)
{
    const ms_renderer_desc *d = &r->desc;
    const float deck =
        0.3f * MS_MAX(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    const float lo[3] = {d->pool_min[0] - deck, d->pool_min[1] - deck, d->pool_min[2]};
    const float hi[3] = {d->pool_max[0] + deck, d->pool_max[1] + deck,
                         d->pool_max[2] + 2 * (d->pool_max[2] - d->pool_min[2])};
    double far2 = 0, near2 = 0; /* squared distances to the farthest corner, to the box */
    for (int c = 0; c < 8; ++c) {
        double s = 0;
        for (int k = 0; k < 3; ++k) {
            double p = (c >> k) & 1 ? hi[k] : lo[k];
            s += (p - d->eye[k]) * (p - d->eye[k]);
        }
        far2 = MS_MAX(far2, s);
    }
    for (int k = 0; k < 3; ++k) {
        double e = d->eye[k], q = e < lo[k] ? lo[k] - e : e > hi[k] ? e - hi[k] : 0;
        near2 += q * q;
    }
    *zfar = (float)(1.05 * sqrt(far2));
    *znear = MS_MAX(0.5f * (float)sqrt(near2), 1e-4f * *zfar);
}

static void draw_liquid(ms_renderer *r, double time)
{
    ms_gl *gl = r->gl;
    const ms_renderer_desc *d = &r->desc;
    const unsigned want = r->shader.vt->passes;
    glUseProgram(gl->liquid.prog);
    if (want & (MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION)) {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_CUBE_MAP, gl->env_tex);
    }
    if (want & MS_SHADER_NEEDS_CAUSTICS) {
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, gl->caustics_tex);
    }
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, gl->normal_tex);
    glActiveTexture(GL_TEXTURE0);
    ms_shader_uniforms u = ms_gl_uniform_table(&gl->liquid);
    u.set_vec3(u.ctx, "ms_eye", d->eye[0], d->eye[1], d->eye[2]);
    u.set_vec3(u.ctx, "ms_light_dir", r->light_to[0], r->light_to[1], r->light_to[2]);
    u.set_vec3(u.ctx, "ms_light_color", d->light_color[0], d->light_color[1], d->light_color[2]);
    u.set_float(u.ctx, "ms_time", (float)time);
    u.set_vec4(u.ctx, "ms_viewport", (float)d->width, (float)d->height, 1.0f / (float)d->width,
               1.0f / (float)d->height);
    u.set_int(u.ctx, "ms_env", 0);
    {
        float mirror[3], virt[3];
        ms_gl_env_viewpoints(d, mirror, virt);
        u.set_vec3(u.ctx, "ms_env_refracted_eye", virt[0], virt[1], virt[2]);
    }
    u.set_float(u.ctx, "ms_floor_z", d->pool_min[2]);
    u.set_vec4(u.ctx, "ms_pool", d->pool_min[0], d->pool_min[1], d->pool_max[0] - d->pool_min[0],
               d->pool_max[1] - d->pool_min[1]);
    u.set_int(u.ctx, "ms_caustics", 1);
    {
        const ms_grid *f = &gl->normal_field;
        u.set_int(u.ctx, "ms_normal_map", 2);
        u.set_vec4(u.ctx, "ms_field", f->origin[0], f->origin[1], 1.0f / ((float)f->nx * f->dx),
                   1.0f / ((float)f->ny * f->dy));
    }
    ms_gl_walls_bind(r, &u);
    ms_gl_foam_bind(r, &u);
    if (r->shader.vt->set_uniforms)
        r->shader.vt->set_uniforms(r->shader.self, &u);

    /* dry cells: the plane z = floor + MS_RENDER_DRY_DEPTH in world
     * coordinates (given under the identity, so gl_ClipVertex = gl_Vertex
     * is compared with it as is) cuts the surface along the contour of
     * that depth; a plugin whose vertex program does not write
     * gl_ClipVertex is drawn whole (plugin.h) */
    const int clip = gl->liquid_clips;
    if (clip) {
        const GLdouble plane[4] = {0, 0, 1, -((double)d->pool_min[2] + MS_RENDER_DRY_DEPTH)};
        glPushMatrix();
        glLoadIdentity();
        glClipPlane(GL_CLIP_PLANE0, plane);
        glPopMatrix();
        glEnable(GL_CLIP_PLANE0);
    }
    glDisable(GL_CULL_FACE);
    glBindBuffer(GL_ARRAY_BUFFER, gl->mesh_vbo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gl->mesh_ibo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), (const void *)0);
    glNormalPointer(GL_FLOAT, 6 * sizeof(float), (const void *)(3 * sizeof(float)));
    {
        const int quads_row = gl->mesh_nx - 1, rows = gl->mesh_ny - 1;
        const int band = MS_MAX(1, BAND_VERTICES / gl->mesh_nx);
        for (int j = 0; j < rows; j += band) {
            int nrows = MS_MIN(band, rows - j);
            size_t first = 6 * (size_t)quads_row * (size_t)j;
            glDrawRangeElements(GL_TRIANGLES, (GLuint)(j * gl->mesh_nx),
                                (GLuint)((j + nrows + 1) * gl->mesh_nx - 1), 6 * quads_row * nrows,
                                GL_UNSIGNED_INT, (const void *)(first * sizeof(unsigned)));
        }
    }
    ms_gl_liquid_side_draw(r, &u); /* the liquid's side in a glass (gl_glass.c) */
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    if (clip)
        glDisable(GL_CLIP_PLANE0);
}

static void draw_scene(ms_renderer *r, double time)
{
    ms_gl *gl = r->gl;
    const ms_renderer_desc *d = &r->desc;
    const float aspect = (float)d->width / (float)d->height;
    float znear, zfar, proj[16], view[16];
    depth_range(r, &znear, &zfar);
    ms_mat4_perspective(d->fov, aspect, znear, zfar, proj);
    ms_mat4_look_at(d->eye, d->target, d->up, view);

    glBindFramebuffer(GL_FRAMEBUFFER, gl->fbo);
    glViewport(0, 0, d->width, d->height);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(proj);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(view);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    /* front to back, so llvmpipe's early depth test skips hidden fragments */
    draw_liquid(r, time);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    ms_gl_pool_draw(r, 1.0f, 0.0f);
    glDisable(GL_CULL_FACE);
    ms_gl_spray_draw(r, view);

    /* the sky: the camera's basis from the view matrix's rows, scaled to
     * the view's half-extents at unit distance */
    const float ty = tanf(0.5f * d->fov * 3.14159265358979f / 180.0f), tx = ty * aspect;
    float right[3] = {view[0], view[4], view[8]}, up[3] = {view[1], view[5], view[9]};
    float fwd[3] = {-view[2], -view[6], -view[10]};
    normalize3(fwd);
    for (int k = 0; k < 3; ++k)
        right[k] *= tx, up[k] *= ty;
    ms_gl_sky_draw(r, fwd, right, up);
    glDisable(GL_FRAMEBUFFER_SRGB);
}

/* Reads the image back and turns it top row first. */
static void read_back(ms_renderer *r)
{
    const int w = r->desc.width, h = r->desc.height;
    const size_t row = (size_t)w * 4;
    unsigned char *px = r->pixels;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    unsigned char tmp[4096];
    for (int y = 0; y < h / 2; ++y) {
        unsigned char *a = px + (size_t)y * row, *b = px + (size_t)(h - 1 - y) * row;
        for (size_t off = 0; off < row; off += sizeof tmp) {
            size_t n = MS_MIN(sizeof tmp, row - off);
            memcpy(tmp, a + off, n);
            memcpy(a + off, b + off, n);
            memcpy(b + off, tmp, n);
        }
    }
}

static ms_status frame(ms_renderer *r, const float *h, const ms_grid *g, double time)
{
    double t0 = ms_now();
    ms_status st = upload_mesh(r, h, g);
    if (st != MS_OK || (st = upload_normals(r, h, g)) != MS_OK)
        return st;
    double t1 = ms_now();
    if (r->trace_caustics && (st = upload_caustics(r, h, g)) != MS_OK)
        return st;
    if (r->discs_changed && (st = ms_gl_discs_upload(r)) != MS_OK)
        return st;
    if ((!r->gl->foam_tex || r->foam_changed) && (st = ms_gl_foam_upload(r)) != MS_OK)
        return st;
    r->foam_changed = 0;
    double t2 = ms_now();
    if ((st = ms_gl_env_objects(r)) != MS_OK) /* the objects refracted and reflected */
        return st;
    draw_scene(r, time);
    if ((st = ms_gl_check("drawing the spray")) != MS_OK)
        return st;
    glFinish();
    double t3 = ms_now();
    if (r->gl->context.borrowed)
        ms_gl_present(r);
    else
        read_back(r);
    double t4 = ms_now();
    if ((st = ms_gl_check("drawing a frame")) != MS_OK)
        return st;
    r->stats.mesh_ms = 1e3 * (t1 - t0);
    r->stats.caustics_ms = r->trace_caustics ? 1e3 * (t2 - t1) : 0;
    r->stats.draw_ms = 1e3 * (t3 - t2);
    r->stats.readback_ms = 1e3 * (t4 - t3);
    return MS_OK;
}

ms_status ms_gl_draw(ms_renderer *r, const float *h, const ms_grid *g, double time)
{
    ms_status st = ms_gl_context_begin(&r->gl->context);
    if (st != MS_OK)
        return st;
    st = frame(r, h, g, time);
    ms_gl_context_end();
    return st;
}
