/* The sky: the environment cubemap as a texture (sRGB, mipmapped,
 * seamless), and the background drawn from it behind everything, last,
 * where nothing else was drawn (so llvmpipe shades no hidden sky). */
#include "core/core_internal.h"
#include "render/gl_internal.h"

static const char sky_vs[] =
    "#version 120\n"
    "uniform vec3 u_forward;\n"
    "uniform vec3 u_right;\n"
    "uniform vec3 u_up;\n"
    "varying vec3 v_dir;\n"
    "void main()\n"
    "{\n"
    "    v_dir = u_forward + gl_Vertex.x * u_right + gl_Vertex.y * u_up;\n"
    "    gl_Position = vec4(gl_Vertex.xy, 1.0, 1.0); /* on the far plane */\n"
    "}\n";

static const char sky_fs[] = "#version 120\n"
                             "uniform samplerCube u_sky;\n"
                             "uniform float u_alpha;\n"
                             "varying vec3 v_dir;\n"
                             "void main()\n"
                             "{\n"
                             "    vec4 c = textureCube(u_sky, v_dir);\n"
                             "    gl_FragColor = vec4(c.rgb, mix(1.0, c.a, u_alpha));\n"
                             "}\n";

ms_status ms_gl_sky_create(ms_renderer *r, const ms_cubemap *sky)
{
    ms_gl *gl = r->gl;
    ms_status st = ms_gl_program_build("the sky program", sky_vs, sky_fs, &gl->sky);
    if (st != MS_OK)
        return st;
    glGenTextures(1, &gl->sky_tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, gl->sky_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; ++f)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_SRGB8_ALPHA8, sky->size,
                     sky->size, 0, GL_RGBA, GL_UNSIGNED_BYTE, sky->face[f]);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    return ms_gl_check("uploading the sky cubemap");
}

void ms_gl_sky_draw(const ms_renderer *r, const float forward[3], const float right[3],
                    const float up[3])
{
    const ms_gl *gl = r->gl;
    /* only where nothing nearer was drawn (depth still the cleared 1) */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glUseProgram(gl->sky.prog);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, gl->sky_tex);
    glUniform1i(glGetUniformLocation(gl->sky.prog, "u_sky"), 0);
    /* the sky is opaque; ms_env's own alpha (the objects' mark, gl_pool.c)
     * goes through when its mipmaps are remade from it (gl_env.c) */
    glUniform1f(glGetUniformLocation(gl->sky.prog, "u_alpha"),
                gl->sky_tex == gl->env_live ? 1.0f : 0.0f);
    glUniform3fv(glGetUniformLocation(gl->sky.prog, "u_forward"), 1, forward);
    glUniform3fv(glGetUniformLocation(gl->sky.prog, "u_right"), 1, right);
    glUniform3fv(glGetUniformLocation(gl->sky.prog, "u_up"), 1, up);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(-1, 1);
    glVertex2f(1, 1);
    glEnd();
    glDepthMask(GL_TRUE);
}
