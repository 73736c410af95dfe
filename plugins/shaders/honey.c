/* Shader plugin "honey": a thick, amber, see-through liquid. The refracted
 * ray (looked up in the environment cubemap, as the paper does for water)
 * is tinted by Beer-Lambert absorption along its path to the floor, so thin
 * layers glow golden and deep ones go dark amber; Fresnel reflection (index
 * 1.49) and a sharp highlight. No caustics.
 *
 * Parameters: {"color": [1.0, 0.62, 0.12], "ior": 1.49, "density": 25,
 *              "shininess": 300}
 *   color      what 1/density metres of honey pass (linear RGB, 0..1);
 *   ior        refractive index;
 *   density    1/m: how quickly light is absorbed (transmission color^(density len));
 *   shininess  Blinn-Phong exponent of the highlight.
 */
#include "../common/shader_params.h"
#include "modesplit/plugin.h"

static const char fragment_source[] =
    "#version 120\n" SHADER_TONEMAP_SOURCE SHADER_NORMAL_SOURCE "uniform vec3 ms_eye;\n"
    "uniform vec3 ms_light_dir;\n"
    "uniform vec3 ms_light_color;\n"
    "uniform samplerCube ms_env;\n"
    "uniform float ms_floor_z;\n"
    "uniform vec3 honey_color;\n"
    "uniform float honey_ior;\n"
    "uniform float honey_density;\n"
    "uniform float honey_shininess;\n"
    "void main()\n"
    "{\n"
    "    vec3 n = ms_surface_normal();\n"
    "    vec3 v = normalize(v_pos - ms_eye);\n"
    "    if (dot(n, v) > 0.0)\n"
    "        n = -n;\n"
    "    float cosi = clamp(-dot(v, n), 0.0, 1.0);\n"
    "    float r0 = (1.0 - honey_ior) / (1.0 + honey_ior);\n"
    "    r0 *= r0;\n"
    "    float fresnel = r0 + (1.0 - r0) * pow(1.0 - cosi, 5.0);\n"
    "    vec3 t = refract(v, n, 1.0 / honey_ior);\n"
    "    float len = max(v_pos.z - ms_floor_z, 0.0) / max(-t.z, 0.05);\n"
    "    vec3 pass = pow(max(honey_color, vec3(1e-3)), vec3(honey_density * len));\n"
    "    vec3 below = textureCube(ms_env, t).rgb * pass;\n"
    "    below += honey_color * 0.08 * ms_light_color;\n"
    "    vec3 env = textureCube(ms_env, reflect(v, n)).rgb;\n"
    "    vec3 h = normalize(ms_light_dir - v);\n"
    "    float norm = (honey_shininess + 8.0) / 25.0;\n"
    "    vec3 spec = ms_light_color * norm * pow(max(dot(n, h), 0.0), honey_shininess);\n"
    "    gl_FragColor = vec4(ms_tonemap(mix(below, env, fresnel) + spec * fresnel * 2.0), 1.0);\n"
    "}\n";

/* The scene keys; uniform "honey_<key>" each (plugins/common/shader_params.h). */
static const shader_param honey_params[] = {
    {"color", 3, {1.0f, 0.62f, 0.12f}, 0.0, 1.0, ""},
    {"ior", 1, {1.49f}, 1.0, 3.0, ""},
    {"density", 1, {25.0f}, 0.0, 1e4, "1/m"},
    {"shininess", 1, {300.0f}, 1.0, 1e5, ""},
    {NULL, 0, {0}, 0, 0, NULL},
};

static int honey_create(const char *json, void **out, char *err, size_t err_size)
{
    return shader_params_create(honey_params, json, out, err, err_size);
}

static void honey_set_uniforms(const void *self, const ms_shader_uniforms *u)
{
    shader_params_set("honey", honey_params, self, u);
}

static const ms_shader_vtable honey_vtable = {
    .size = sizeof(ms_shader_vtable),
    .passes = MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION,
    .vertex_source = SHADER_VERTEX_SOURCE,
    .fragment_source = fragment_source,
    .create = honey_create,
    .destroy = shader_free,
    .set_uniforms = honey_set_uniforms,
};

static const ms_plugin_info honey_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "honey",
    .version = "1.0",
    .kind = MS_PLUGIN_SHADER,
    .description = "amber, see-through honey: absorbed refraction, Fresnel, sharp highlight",
    .vtable = &honey_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &honey_info;
}
