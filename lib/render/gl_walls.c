/* The caustics on the pool's walls as the texture the liquid's
 * shader reads, and the light in the water the objects under it are lit
 * by (ms_gl_open_upload). The walls: ms_caustics_walls (texture unit 3), the tracer's four wall
 * strips stacked (caustics.c, ms_caustics.walls), and ms_pool_depth, the
 * still water's depth over the floor (m) they span; 0 when they were not
 * traced (no caustics pass), so a shader lights the walls as before. */
#include "core/core_internal.h"
#include "render/gl_internal.h"

ms_status ms_gl_walls_upload(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    const ms_caustics *c = &r->caustics;
    if (c->wall_rows <= 0)
        return MS_OK;
    if (!gl->walls_tex) {
        glGenTextures(1, &gl->walls_tex);
        glBindTexture(GL_TEXTURE_2D, gl->walls_tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glBindTexture(GL_TEXTURE_2D, gl->walls_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (gl->walls_n != c->n || gl->walls_rows != c->wall_rows) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, c->n, 4 * c->wall_rows, 0, GL_RED, GL_FLOAT,
                     c->walls);
        gl->walls_n = c->n;
        gl->walls_rows = c->wall_rows;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, c->n, 4 * c->wall_rows, GL_RED, GL_FLOAT, c->walls);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    return MS_OK;
}

void ms_gl_walls_bind(const ms_renderer *r, const ms_shader_uniforms *u)
{
    const ms_gl *gl = r->gl;
    const int on = r->trace_caustics && gl->walls_tex && r->caustics.wall_rows > 0;
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_2D, on ? gl->walls_tex : gl->caustics_tex);
    glActiveTexture(GL_TEXTURE0);
    u->set_int(u->ctx, "ms_caustics_walls", 3);
    u->set_float(u->ctx, "ms_pool_depth", on ? r->desc.water_level - r->desc.pool_min[2] : 0.0f);
    u->set_float(u->ctx, "ms_caustics_wall_rows", on ? (float)r->caustics.wall_rows : 0.0f);
}

ms_status ms_gl_open_upload(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    const ms_caustics *c = &r->caustics;
    if (c->nlayers <= 0)
        return MS_OK;
    const int n = c->layer_n, slices = c->nlayers + 1;
    if (!gl->open_tex) {
        glGenTextures(1, &gl->open_tex);
        glBindTexture(GL_TEXTURE_2D, gl->open_tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glBindTexture(GL_TEXTURE_2D, gl->open_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (gl->open_n != n || gl->open_slices != slices) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, n, slices * n, 0, GL_RED, GL_FLOAT, NULL);
        gl->open_n = n;
        gl->open_slices = slices;
    }
    /* the floor as the light reaches it before the objects' shadow, then
     * the layers above it */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, n, slices * n, GL_RED, GL_FLOAT, c->layers);
    glBindTexture(GL_TEXTURE_2D, 0);
    return MS_OK;
}

GLuint ms_gl_open_texture(const ms_renderer *r, int *slices)
{
    const int on = r->caustics.nlayers > 0 && r->gl->open_tex;
    *slices = on ? r->caustics.nlayers + 1 : 1;
    return on ? r->gl->open_tex : r->gl->caustics_tex;
}
