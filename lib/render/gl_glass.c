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
#include "core/core_internal.h"
#include "render/gl_internal.h"

static const char glass_vs[] =
    "#version 120\n"
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
