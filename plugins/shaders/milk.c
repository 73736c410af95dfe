/* Shader plugin "milk" (the paper's Fig. 9b): an opaque, soft liquid. Light
 * wraps around the surface (a cheap stand-in for the scattering inside
 * milk), a faint, broad sheen of the environment at grazing angles; no
 * refraction, no caustics.
 *
 * Parameters: {"color": [0.93, 0.92, 0.88], "softness": 0.3, "sheen": 0.35,
 *              "relief": 8}
 *   color     linear RGB, 0..1;
 *   softness  how far light wraps past the terminator, 0 (hard) .. 1;
 *   sheen     strength of the environment's reflection at grazing angles;
 *   relief    how much the slopes shade the diffuse light, 0 .. 20 (1 =
 *             physical; the default 8 lets millimetre ripples show on an
 *             opaque liquid, as in the paper's Fig. 9b: at 3 fig9b's frame
 *             60 was a flat white, its liquid's luma varying by 1.9 levels
 *             (sd), now 4.6).
 */
#include "../common/shader_params.h"
#include "modesplit/plugin.h"

static const char fragment_source[] =
    "#version 120\n" SHADER_TONEMAP_SOURCE SHADER_NORMAL_SOURCE "uniform vec3 ms_eye;\n"
    "uniform vec3 ms_light_dir;\n"
    "uniform vec3 ms_light_color;\n"
    "uniform samplerCube ms_env;\n"
    "uniform vec3 milk_color;\n"
    "uniform float milk_softness;\n"
    "uniform float milk_sheen;\n"
    "uniform float milk_relief;\n"
    "void main()\n"
    "{\n"
    "    vec3 n = ms_surface_normal();\n"
    "    vec3 v = normalize(v_pos - ms_eye);\n"
    "    if (dot(n, v) > 0.0)\n"
    "        n = -n;\n"
    "    /* the slopes scaled by milk_relief for the diffuse light only: an\n"
    "     * opaque liquid shows its ripples by shading alone */\n"
    "    vec3 nd = normalize(vec3(n.xy * milk_relief, n.z));\n"
    "    float wrap = (dot(nd, ms_light_dir) + milk_softness) / (1.0 + milk_softness);\n"
    "    /* milk's albedo under the sun (wrapped Lambert) and the sky, kept\n"
    "     * near the tone map's knee (0.6) so the slopes of the ripples show:\n"
    "     * its shoulder flattened them at 0.75 + 0.25 */\n"
    "    vec3 diffuse = milk_color * ms_light_color * 0.62 * clamp(wrap, 0.0, 1.0);\n"
    "    vec3 ambient = milk_color * 0.22;\n"
    "    float cosi = clamp(-dot(v, n), 0.0, 1.0);\n"
    "    /* Schlick with milk's index (about 1.35), broadened by milk_sheen */\n"
    "    float fresnel = 0.022 + 0.978 * pow(1.0 - cosi, 5.0);\n"
    "    float sheen = clamp(fresnel * (1.0 + 8.0 * milk_sheen), 0.0, 1.0);\n"
    "    vec3 env = textureCube(ms_env, reflect(v, n)).rgb;\n"
    "    vec3 h = normalize(ms_light_dir - v);\n"
    "    vec3 spec = ms_light_color * 0.5 * pow(max(dot(n, h), 0.0), 24.0);\n"
    "    gl_FragColor = vec4(ms_tonemap(mix(ambient + diffuse, env, sheen) + spec), 1.0);\n"
    "}\n";

/* The scene keys; uniform "milk_<key>" each (plugins/common/shader_params.h). */
static const shader_param milk_params[] = {
    {"color", 3, {0.93f, 0.92f, 0.88f}, 0.0, 1.0, ""},
    {"softness", 1, {0.3f}, 0.0, 1.0, ""},
    {"sheen", 1, {0.35f}, 0.0, 1.0, ""},
    {"relief", 1, {8.0f}, 0.0, 20.0, ""},
    {NULL, 0, {0}, 0, 0, NULL},
};

static int milk_create(const char *json, void **out, char *err, size_t err_size)
{
    return shader_params_create(milk_params, json, out, err, err_size);
}

static void milk_set_uniforms(const void *self, const ms_shader_uniforms *u)
{
    shader_params_set("milk", milk_params, self, u);
}

static const ms_shader_vtable milk_vtable = {
    .size = sizeof(ms_shader_vtable),
    .passes = MS_SHADER_NEEDS_REFLECTION,
    .vertex_source = SHADER_VERTEX_SOURCE,
    .fragment_source = fragment_source,
    .create = milk_create,
    .destroy = shader_free,
    .set_uniforms = milk_set_uniforms,
};

static const ms_plugin_info milk_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "milk",
    .version = "1.0",
    .kind = MS_PLUGIN_SHADER,
    .description = "opaque, soft milk: wrapped diffuse light, grazing sheen, no refraction",
    .vtable = &milk_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &milk_info;
}
