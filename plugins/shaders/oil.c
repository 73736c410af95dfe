/* Shader plugin "oil": a dark, opaque, glossy liquid (motor oil, crude):
 * almost black body colour, the environment reflected by the Fresnel
 * equations (Schlick, oil's index 1.47), a sharp sun highlight; no
 * refraction, no caustics.
 *
 * Parameters: {"color": [0.03, 0.025, 0.015], "ior": 1.47, "shininess": 600}
 *   color      body colour, linear RGB 0..1;
 *   ior        refractive index (sets the Fresnel reflectance);
 *   shininess  Blinn-Phong exponent of the highlight (higher = sharper).
 */
#include "../common/shader_params.h"
#include "modesplit/plugin.h"

static const char fragment_source[] =
    "#version 120\n" SHADER_TONEMAP_SOURCE SHADER_NORMAL_SOURCE "uniform vec3 ms_eye;\n"
    "uniform vec3 ms_light_dir;\n"
    "uniform vec3 ms_light_color;\n"
    "uniform samplerCube ms_env;\n"
    "uniform vec3 oil_color;\n"
    "uniform float oil_ior;\n"
    "uniform float oil_shininess;\n"
    "void main()\n"
    "{\n"
    "    vec3 n = ms_surface_normal();\n"
    "    vec3 v = normalize(v_pos - ms_eye);\n"
    "    if (dot(n, v) > 0.0)\n"
    "        n = -n;\n"
    "    float cosi = clamp(-dot(v, n), 0.0, 1.0);\n"
    "    float r0 = (1.0 - oil_ior) / (1.0 + oil_ior);\n"
    "    r0 *= r0;\n"
    "    float fresnel = r0 + (1.0 - r0) * pow(1.0 - cosi, 5.0);\n"
    "    vec3 body = oil_color * (0.2 + 0.8 * max(dot(n, ms_light_dir), 0.0)) * ms_light_color;\n"
    "    vec3 env = textureCube(ms_env, reflect(v, n)).rgb;\n"
    "    vec3 h = normalize(ms_light_dir - v);\n"
    "    float norm = (oil_shininess + 8.0) / 25.0;\n"
    "    vec3 spec = ms_light_color * norm * pow(max(dot(n, h), 0.0), oil_shininess);\n"
    "    gl_FragColor = vec4(ms_tonemap(mix(body, env, fresnel) + spec * fresnel * 2.0), 1.0);\n"
    "}\n";

/* The scene keys; uniform "oil_<key>" each (plugins/common/shader_params.h). */
static const shader_param oil_params[] = {
    {"color", 3, {0.03f, 0.025f, 0.015f}, 0.0, 1.0, ""},
    {"ior", 1, {1.47f}, 1.0, 3.0, ""},
    {"shininess", 1, {600.0f}, 1.0, 1e5, ""},
    {NULL, 0, {0}, 0, 0, NULL},
};

static int oil_create(const char *json, void **out, char *err, size_t err_size)
{
    return shader_params_create(oil_params, json, out, err, err_size);
}

static void oil_set_uniforms(const void *self, const ms_shader_uniforms *u)
{
    shader_params_set("oil", oil_params, self, u);
}

static const ms_shader_vtable oil_vtable = {
    .size = sizeof(ms_shader_vtable),
    .passes = MS_SHADER_NEEDS_REFLECTION,
    .vertex_source = SHADER_VERTEX_SOURCE,
    .fragment_source = fragment_source,
    .create = oil_create,
    .destroy = shader_free,
    .set_uniforms = oil_set_uniforms,
};

static const ms_plugin_info oil_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "oil",
    .version = "1.0",
    .kind = MS_PLUGIN_SHADER,
    .description = "dark, opaque, glossy oil: Fresnel reflection, sharp highlight",
    .vtable = &oil_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &oil_info;
}
