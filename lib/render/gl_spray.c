/* Spray and foam (the sim's effects.spray, ms_renderer_set_spray and
 * ms_renderer_set_foam): the foam cover as a texture the liquid's shader
 * may read (ms_foam, ms_foam_field, ms_foam_on; the water shader lays it
 * white over the water, plugin.h), and the spray as lit droplets: point
 * sprites of the droplet's radius seen at its distance, shaded as small
 * spheres by the sun and the sky, depth-tested against the pool and the
 * liquid. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

/* Point size in pixels = ms_spray_scale / distance: ms_spray_scale is the
 * droplet's diameter (m) times the image's pixels per metre at 1 m. At
 * least 1.5 pixels, so a far droplet stays a dot and not a flicker. */
static const char spray_vs[] = "#version 120\n"
                               "uniform float ms_spray_scale;\n"
                               "uniform vec3 ms_eye;\n"
                               "void main()\n"
                               "{\n"
                               "    gl_Position = ftransform();\n"
                               "    float d = max(length(gl_Vertex.xyz - ms_eye), 1e-3);\n"
                               "    gl_PointSize = max(ms_spray_scale / d, 1.5);\n"
                               "}\n";

/* A sphere's normal from the sprite's coordinate: Lambert from the sun,
 * the sky's blue from above, and a highlight; water drops are mostly the
 * light they reflect, so a pale blue-white. Tone mapped as the liquid is
 * not: the frame buffer is sRGB and the values stay below 1. */
static const char spray_fs[] =
    "#version 120\n"
    "uniform vec3 ms_light_dir;\n"
    "uniform vec3 ms_light_color;\n"
    "uniform vec3 ms_view_right;\n"
    "uniform vec3 ms_view_up;\n"
    "uniform vec3 ms_view_back;\n"
    "void main()\n"
    "{\n"
    "    vec2 c = gl_PointCoord * 2.0 - 1.0;\n"
    "    c.y = -c.y;\n"
    "    float r2 = dot(c, c);\n"
    "    if (r2 > 1.0)\n"
    "        discard;\n"
    "    vec3 n = c.x * ms_view_right + c.y * ms_view_up + sqrt(1.0 - r2) * ms_view_back;\n"
    "    float sun = max(dot(n, ms_light_dir), 0.0);\n"
    "    float sky = 0.5 + 0.5 * n.z;\n"
    "    vec3 h = normalize(ms_light_dir + ms_view_back);\n"
    "    float spec = pow(max(dot(n, h), 0.0), 60.0);\n"
    "    vec3 col = vec3(0.80, 0.86, 0.90) * (0.35 * sun * ms_light_color + 0.45 * sky)\n"
    "             + 0.5 * spec * ms_light_color;\n"
    "    gl_FragColor = vec4(min(col, vec3(1.0)), 1.0);\n"
    "}\n";

ms_status ms_gl_foam_upload(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    if (!gl->foam_tex) {
        glGenTextures(1, &gl->foam_tex);
        glBindTexture(GL_TEXTURE_2D, gl->foam_tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        const float zero = 0.0f;
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, 1, 1, 0, GL_RED, GL_FLOAT, &zero);
        gl->foam_nx = gl->foam_ny = 1;
    }
    if (!r->has_foam)
        return MS_OK;
    const ms_grid *g = &r->foam_grid;
    glBindTexture(GL_TEXTURE_2D, gl->foam_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (gl->foam_nx != g->nx || gl->foam_ny != g->ny) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, g->nx, g->ny, 0, GL_RED, GL_FLOAT, r->foam);
        gl->foam_nx = g->nx;
        gl->foam_ny = g->ny;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, g->nx, g->ny, GL_RED, GL_FLOAT, r->foam);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    return ms_gl_check("uploading the foam");
}

void ms_gl_foam_bind(const ms_renderer *r, const ms_shader_uniforms *u)
{
    const ms_gl *gl = r->gl;
    const ms_grid *g = &r->foam_grid;
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_2D, gl->foam_tex);
    glActiveTexture(GL_TEXTURE0);
    u->set_int(u->ctx, "ms_foam", 4);
    u->set_float(u->ctx, "ms_foam_on", r->has_foam ? 1.0f : 0.0f);
    if (r->has_foam)
        u->set_vec4(u->ctx, "ms_foam_field", g->origin[0], g->origin[1],
                    1.0f / ((float)g->nx * g->dx), 1.0f / ((float)g->ny * g->dy));
    else
        u->set_vec4(u->ctx, "ms_foam_field", 0, 0, 1, 1);
}

void ms_gl_spray_draw(ms_renderer *r, const float view[16])
{
    ms_gl *gl = r->gl;
    const ms_renderer_desc *d = &r->desc;
    if (r->nspray <= 0)
        return;
    if (!gl->spray.prog) {
        /* made at the first droplet: a scene without spray builds nothing */
        if (ms_gl_program_build("spray", spray_vs, spray_fs, &gl->spray) != MS_OK)
            return; /* the liquid and pool are drawn; the error stays set */
        glGenBuffers(1, &gl->spray_vbo);
    }
    glBindBuffer(GL_ARRAY_BUFFER, gl->spray_vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)r->nspray * 3 * sizeof(float)), r->spray,
                 GL_STREAM_DRAW);
    glUseProgram(gl->spray.prog);
    ms_shader_uniforms u = ms_gl_uniform_table(&gl->spray);
    const float px_per_m = (float)d->height / (2.0f * tanf(0.5f * d->fov * 3.14159265f / 180.0f));
    u.set_float(u.ctx, "ms_spray_scale", 2.0f * r->spray_radius * px_per_m);
    u.set_vec3(u.ctx, "ms_eye", d->eye[0], d->eye[1], d->eye[2]);
    u.set_vec3(u.ctx, "ms_light_dir", r->light_to[0], r->light_to[1], r->light_to[2]);
    u.set_vec3(u.ctx, "ms_light_color", d->light_color[0], d->light_color[1], d->light_color[2]);
    /* the camera's basis: the view matrix's rows */
    u.set_vec3(u.ctx, "ms_view_right", view[0], view[4], view[8]);
    u.set_vec3(u.ctx, "ms_view_up", view[1], view[5], view[9]);
    u.set_vec3(u.ctx, "ms_view_back", view[2], view[6], view[10]);
    glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
    glEnable(GL_POINT_SPRITE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 3 * sizeof(float), (const void *)0);
    glDrawArrays(GL_POINTS, 0, r->nspray);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_POINT_SPRITE);
    glDisable(GL_VERTEX_PROGRAM_POINT_SIZE);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
}
