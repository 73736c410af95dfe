/* GLSL programs: compiled and linked with the compiler's log in the error
 * sentence (a shader plugin's mistake must read like one), and the table
 * of callbacks through which a shader plugin sets its uniforms
 * (plugin.h's ms_shader_uniforms). */
#include <stdio.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

/* The log without its trailing newlines, at most n - 1 bytes. */
static void clean_log(char *log)
{
    size_t n = strlen(log);
    while (n > 0 && (log[n - 1] == '\n' || log[n - 1] == ' '))
        log[--n] = '\0';
    for (char *p = log; *p; ++p)
        if (*p == '\n')
            *p = ' ';
}

static ms_status compile(const char *what, GLenum type, const char *src, GLuint *out)
{
    GLuint s = glCreateShader(type);
    if (!s)
        return ms_fail(MS_ERR_UNSUPPORTED, "render: %s: OpenGL cannot make a shader object", what);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        clean_log(log);
        glDeleteShader(s);
        return ms_fail(MS_ERR_PLUGIN, "render: %s: the %s shader does not compile: %s", what,
                       type == GL_VERTEX_SHADER ? "vertex" : "fragment", log[0] ? log : "(no log)");
    }
    *out = s;
    return MS_OK;
}

ms_status ms_gl_program_build(const char *what, const char *vs, const char *fs, ms_gl_program *out)
{
    out->prog = 0;
    if (!vs || !fs)
        return ms_fail(MS_ERR_PLUGIN, "render: %s has no %s shader source", what,
                       vs ? "fragment" : "vertex");
    GLuint v, f;
    ms_status st = compile(what, GL_VERTEX_SHADER, vs, &v);
    if (st != MS_OK)
        return st;
    if ((st = compile(what, GL_FRAGMENT_SHADER, fs, &f)) != MS_OK) {
        glDeleteShader(v);
        return st;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v); /* freed with the program */
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[1024] = "";
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        clean_log(log);
        glDeleteProgram(p);
        return ms_fail(MS_ERR_PLUGIN, "render: %s: the program does not link: %s", what,
                       log[0] ? log : "(no log)");
    }
    out->prog = p;
    return MS_OK;
}

void ms_gl_program_free(ms_gl_program *p)
{
    if (p->prog)
        glDeleteProgram(p->prog);
    p->prog = 0;
}

/* A name the program lacks has location -1, which glUniform ignores. */
static void set_float(void *ctx, const char *name, float v)
{
    glUniform1f(glGetUniformLocation(((ms_gl_program *)ctx)->prog, name), v);
}
static void set_vec3(void *ctx, const char *name, float x, float y, float z)
{
    glUniform3f(glGetUniformLocation(((ms_gl_program *)ctx)->prog, name), x, y, z);
}
static void set_int(void *ctx, const char *name, int v)
{
    glUniform1i(glGetUniformLocation(((ms_gl_program *)ctx)->prog, name), v);
}
static void set_vec4(void *ctx, const char *name, float x, float y, float z, float w)
{
    glUniform4f(glGetUniformLocation(((ms_gl_program *)ctx)->prog, name), x, y, z, w);
}

ms_shader_uniforms ms_gl_uniform_table(ms_gl_program *p)
{
    ms_shader_uniforms u = {sizeof u, p, set_float, set_vec3, set_int, set_vec4};
    return u;
}

ms_status ms_gl_check(const char *doing)
{
    GLenum e = glGetError(), first = e;
    for (int i = 0; i < 32 && e != GL_NO_ERROR; ++i) /* clear the others */
        e = glGetError();
    if (first == GL_NO_ERROR)
        return MS_OK;
    return ms_fail(MS_ERR_UNSUPPORTED, "render: OpenGL error 0x%04x while %s", (unsigned)first,
                   doing);
}
