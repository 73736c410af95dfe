/* The glass (the scene's container) as glass: mostly clear face-on, a
 * mirror at grazing angles. Each fragment of its mesh (objects.c) mixes
 * what lies behind it (the blend's destination) with the environment
 * reflected about its normal by Schlick's Fresnel term for glass
 * (n = 1.5, 4 % at normal incidence), adds the sun's highlight, and a
 * faint green-grey absorption along the path through the wall, which
 * grows as 1 / cos of the angle to the normal (Beer-Lambert, thin wall).
 * So the walls seen edge-on (the outline) are bright and the glass seen
 * through is nearly clear; before, a constant 30 % of a lit pale colour
 * made it milky and showed the mesh's overlapping wall triangles as
 * vertical streaks. Premultiplied alpha, blended in linear light. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

/* How much of the side's own normal across the view tilts its shading
 * normal (side_normal): 0 looks straight through, 1 bends as one face. */
#define SIDE_LENS 0.3f

static void normalize3(float v[3])
{
    const float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0)
        v[0] /= l, v[1] /= l, v[2] /= l;
}

static const char glass_vs[] = "#version 120\n"
                               "varying vec3 v_pos;\n"
                               "varying vec3 v_normal;\n"
                               "void main()\n"
                               "{\n"
                               "    v_pos = gl_Vertex.xyz;\n"
                               "    v_normal = gl_Normal;\n"
                               "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
                               "}\n";

static const char glass_fs[] =
    "#version 120\n"
    "uniform samplerCube u_env;\n"
    "uniform vec3 u_eye;\n"
    "uniform vec3 u_light_to;\n"
    "uniform vec3 u_light_color;\n"
    "uniform float u_water_level;\n"
    "uniform float u_keep;\n"
    "varying vec3 v_pos;\n"
    "varying vec3 v_normal;\n"
    "const vec3 tint = vec3(0.55, 0.68, 0.64); /* what the wall keeps: linear RGB */\n"
    "void main()\n"
    "{\n"
    "    if (u_keep * (v_pos.z - u_water_level) < 0.0)\n"
    "        discard;\n"
    "    vec3 v = normalize(u_eye - v_pos);\n"
    "    vec3 n = normalize(v_normal);\n"
    "    if (dot(n, v) < 0.0)\n"
    "        n = -n; /* the wall's inner side */\n"
    "    float c = clamp(dot(n, v), 0.0, 1.0);\n"
    "    float fresnel = 0.04 + 0.96 * pow(1.0 - c, 5.0);\n"
    "    /* absorbed along the wall: 6 % face-on, more obliquely */\n"
    "    float absorbed = min(0.06 / max(c, 0.1), 0.5);\n"
    "    vec3 reflected = textureCube(u_env, reflect(-v, n)).rgb;\n"
    "    vec3 hv = normalize(v + u_light_to);\n"
    "    float sun = pow(max(dot(n, hv), 0.0), 400.0) * step(0.0, dot(n, u_light_to));\n"
    "    vec3 lit = u_light_color * (0.4 + 0.6 * max(dot(n, u_light_to), 0.0));\n"
    "    float t = 1.0 - fresnel;\n"
    "    vec3 color = fresnel * reflected + 2.0 * sun * u_light_color\n"
    "               + t * absorbed * tint * lit;\n"
    "    gl_FragColor = vec4(color, fresnel + t * absorbed);\n"
    "}\n";

ms_status ms_gl_glass_create(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    if (gl->glass.prog)
        return MS_OK;
    return ms_gl_program_build("the glass program", glass_vs, glass_fs, &gl->glass);
}

void ms_gl_glass_draw(const ms_renderer *r, const float eye[3], float keep)
{
    const ms_gl *gl = r->gl;
    if (gl->discs_count <= gl->glass_first || !gl->glass.prog)
        return;
    /* with liquid in it (glass_fill.c), the glass is left out of ms_env's
     * refracted half: that half shows the pool from the eye's virtual image
     * above the water, so the liquid inside would see the glass's own outer
     * walls at grazing angles, mirror-bright (pale bands down the column,
     * streaks on its floor) where it should see through them */
    if (keep < 0 && r->cavity.active)
        return;
    const GLsizei stride = MS_POOL_STRIDE * sizeof(float);
    GLuint p = gl->glass.prog;
    glUseProgram(p);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, gl->env_static ? gl->env_static : gl->sky_tex);
    glUniform1i(glGetUniformLocation(p, "u_env"), 0);
    glUniform3fv(glGetUniformLocation(p, "u_eye"), 1, eye);
    glUniform3fv(glGetUniformLocation(p, "u_light_to"), 1, r->light_to);
    glUniform3fv(glGetUniformLocation(p, "u_light_color"), 1, r->desc.light_color);
    glUniform1f(glGetUniformLocation(p, "u_water_level"), r->desc.water_level);
    glUniform1f(glGetUniformLocation(p, "u_keep"), keep);
    glBindBuffer(GL_ARRAY_BUFFER, gl->discs_vbo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, stride, (const void *)0);
    glNormalPointer(GL_FLOAT, stride, (const void *)(3 * sizeof(float)));
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_TRIANGLES, gl->glass_first, gl->discs_count - gl->glass_first);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

/* The normal the side's vertex at p shades with, seen from eye. A water
 * column's two vertical faces give a view ray back its elevation, and
 * ms_env's refracted half is drawn for rays through the flat top from
 * virt: the side's own horizontal normal sent the lookups up to the deck
 * beyond the pool (beige-yellow bands and spots). So the
 * normal is the one that refracts the view ray (1 / ior) towards what
 * lies behind the column on the floor as seen from virt, tilted sideways
 * by the side's own normal's part across the view (a lens's sideways
 * bend, and Fresnel's brighter edges where the column turns away). */
static void side_normal(const float p[3], const float nh[3], const float eye[3],
                        const float virt[3], float floor_z, float eta, float out[3])
{
    float v[3], b[3], w[3];
    for (int k = 0; k < 3; ++k)
        v[k] = p[k] - eye[k];
    normalize3(v);
    const float run = MS_MAX(p[2] - floor_z, 0.0f) / MS_MAX(-v[2], 0.05f);
    for (int k = 0; k < 3; ++k) {
        b[k] = p[k] + run * v[k];
        w[k] = b[k] - virt[k];
    }
    normalize3(w);
    float hx = v[0], hy = v[1], hl = sqrtf(hx * hx + hy * hy);
    hx = hl > 0 ? hx / hl : 1, hy = hl > 0 ? hy / hl : 0;
    const float along = nh[0] * hx + nh[1] * hy;
    const float across[3] = {nh[0] - along * hx, nh[1] - along * hy, 0};
    for (int k = 0; k < 3; ++k)
        out[k] = eta * v[k] - w[k] + SIDE_LENS * across[k];
    normalize3(out);
}

/* The side of the liquid column in the glass (glass_fill.c's quads),
 * drawn by the liquid's program while it is bound (draw_liquid) with
 * ms_side = 1: the shipped programs then shade with the normals given here
 * (side_normal) instead of the height field's (plugins/common/shader.h). */
void ms_gl_liquid_side_draw(ms_renderer *r, const ms_shader_uniforms *u)
{
    ms_gl *gl = r->gl;
    const ms_render_cavity *c = &r->cavity;
    if (!c->active || c->side_verts == 0)
        return;
    const ms_renderer_desc *d = &r->desc;
    float virt[3];
    float mirror[3];
    ms_gl_env_viewpoints(d, mirror, virt);
    float *o = r->cavity.side_draw;
    for (int i = 0; i < c->side_verts; ++i) {
        const float *q = c->side + 6 * (size_t)i;
        memcpy(o + 6 * (size_t)i, q, 3 * sizeof(float));
        side_normal(q, q + 3, d->eye, virt, d->pool_min[2], 1.0f / d->ior, o + 6 * (size_t)i + 3);
    }
    if (!gl->side_vbo)
        glGenBuffers(1, &gl->side_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, gl->side_vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)c->side_verts * 6 * sizeof(float)), o,
                 GL_STREAM_DRAW);
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), (const void *)0);
    glNormalPointer(GL_FLOAT, 6 * sizeof(float), (const void *)(3 * sizeof(float)));
    u->set_float(u->ctx, "ms_side", 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, c->side_verts);
    u->set_float(u->ctx, "ms_side", 0.0f);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}
