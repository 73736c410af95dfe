/* Shader plugin "water" (the paper's section 3.6): reflection and
 * refraction looked up in the environment cubemap and mixed by the Fresnel
 * equations (Schlick's approximation), the refracted ray lit where it meets
 * the pool floor or a wall by the caustics light map, light absorbed along its path
 * under water, and a sun highlight. Seen from below the surface: Snell's
 * window (the sky within asin(1 / ior) of the normal) and total internal
 * reflection outside it. Foam (the sim's spray, ms_foam) lies white over
 * the water seen from above.
 *
 * Parameters: {"color": [0.02, 0.28, 0.33], "ior": 1.333, "caustics": 1.2,
 *              "clarity": 1.5}
 *   color     what deep water looks like (linear RGB, 0..1);
 *   ior       refractive index (1.333 for water);
 *   caustics  strength of the caustics light map (0 = none);
 *   clarity   path length (m) over which light under water falls to 1/e;
 *   parallax  where the refracted ray is looked up, from 0 to 1: 0 along
 *             its direction (the paper's cubemap lookup, section 3.6), 1
 *             through the point where it meets the floor or a wall.
 * The cubemap's lower half is drawn from the eye's virtual image (gl_env.c),
 * ~1.5 m from the floor in the shipped scenes: looked up along the ray, a
 * slope's bend moves the floor seen by that distance times the bend, where
 * the water moves it by its depth times the bend (12 cm in stir). Ripples
 * on shallow water show well along the ray; a churned pool shows its floor
 * only through the point (stir's paddle scrambled the tiles into a flat
 * blue). parallax 1 is what the water does; 0 is the paper's look.
 */
#include "../common/shader_params.h"
#include "modesplit/plugin.h"

static const char fragment_source[] =
    "#version 120\n" SHADER_TONEMAP_SOURCE SHADER_NORMAL_SOURCE "uniform vec3 ms_eye;\n"
    "uniform vec3 ms_light_dir;\n"
    "uniform vec3 ms_light_color;\n"
    "uniform samplerCube ms_env;\n"
    "uniform vec3 ms_env_refracted_eye;\n"
    "uniform sampler2D ms_caustics;\n"
    "uniform vec4 ms_pool;\n"
    "uniform float ms_floor_z;\n"
    "uniform sampler2D ms_caustics_walls;\n"
    "uniform float ms_pool_depth;\n"
    "uniform float ms_caustics_wall_rows;\n"
    "uniform vec3 water_color;\n"
    "uniform float water_ior;\n"
    "uniform float water_caustics;\n"
    "uniform float water_clarity;\n"
    "uniform float water_parallax;\n"
    "uniform sampler2D ms_foam;\n"
    "uniform vec4 ms_foam_field;\n"
    "uniform float ms_foam_on;\n"
    "void main()\n"
    "{\n"
    "    vec3 n = ms_surface_normal();\n"
    "    vec3 v = normalize(v_pos - ms_eye);\n"
    /* seen from below (the eye under the surface): light leaves the water, n1 = ior > n2 =
     * 1; Snell's window, total internal reflection outside it. Both sides share one
     * refracted lookup, picked by selects: llvmpipe runs both arms of an if on every
     * pixel, so a branch with its own lookups costs them everywhere */
    "    bool under = dot(n, v) > 0.0;\n"
    "    n = under ? -n : n;\n"
    "    float r0 = (1.0 - water_ior) / (1.0 + water_ior);\n"
    "    r0 *= r0;\n"
    "    vec3 reflected = textureCube(ms_env, reflect(v, n)).rgb;\n"
    "    vec3 t = refract(v, n, under ? water_ior : 1.0 / water_ior);\n"
    "    bool tir = dot(t, t) == 0.0;\n"
    /* Schlick from the denser side takes the angle in air */
    "    float c = under ? clamp(-dot(t, n), 0.0, 1.0) : clamp(-dot(v, n), 0.0, 1.0);\n"
    "    float fresnel = tir ? 1.0 : r0 + (1.0 - r0) * pow(1.0 - c, 5.0);\n"
    "    float len = max(v_pos.z - ms_floor_z, 0.0) / max(-t.z, 0.05);\n"
    "    vec2 uv = (v_pos.xy + len * t.xy - ms_pool.xy) / ms_pool.zw;\n"
    "    float focus = texture2D(ms_caustics, uv).r;\n"
    /* a ray that leaves the floor's square meets a wall first: the walls' strips (-x, +x,
     * -y, +y) of the light map */
    "    vec2 out_lo = -uv, out_hi = uv - 1.0;\n"
    "    float off_floor = step(0.0, max(max(out_lo.x, out_lo.y), max(out_hi.x, out_hi.y)))\n"
    "                    * step(1e-6, ms_pool_depth);\n"
    /* no branch: a texture read inside one costs llvmpipe the whole shader's speed (fig1
     * drew 12-21 % slower) */
    "    vec2 wall = ms_pool.xy + step(0.0, t.xy) * ms_pool.zw;\n"
    "    vec2 tt = vec2(abs(t.x) < 1e-6 ? 1e-6 : t.x, abs(t.y) < 1e-6 ? 1e-6 : t.y);\n"
    "    vec2 s = (wall - v_pos.xy) / tt;\n"
    "    float xwall = step(s.x, s.y);\n"
    "    float to_wall = max(min(s.x, s.y), 0.0);\n"
    "    vec3 q = v_pos + to_wall * t;\n"
    "    float strip = mix(2.0 + step(0.0, t.y), step(0.0, t.x), xwall);\n"
    "    float along = mix((q.x - ms_pool.x) / ms_pool.z, (q.y - ms_pool.y) / ms_pool.w, xwall);\n"
    "    float half_texel = 0.5 / max(ms_caustics_wall_rows, 1.0);\n"
    "    float height = clamp((q.z - ms_floor_z) / max(ms_pool_depth, 1e-6), half_texel,\n"
    "                         1.0 - half_texel);\n"
    "    float on_wall = texture2D(ms_caustics_walls, vec2(along, (strip + height) / 4.0)).r;\n"
    "    focus = mix(focus, on_wall, off_floor);\n"
    "    len = mix(len, to_wall, off_floor);\n"
    /* parallax: towards the point the refracted ray meets, from where ms_env's lower half
     * was drawn (see the parameters above) */
    "    vec3 hit = v_pos + len * t - ms_env_refracted_eye;\n"
    "    hit = dot(hit, hit) < 1e-12 ? t : normalize(hit);\n"
    "    vec4 seen = textureCube(ms_env, under || water_parallax <= 0.0 ? t\n"
    "                                                    : mix(t, hit, water_parallax));\n"
    "    vec3 refracted = seen.rgb;\n"
    /* from below: the sky in Snell's window; the reflected ray runs back down through the
     * water */
    "    vec3 seen_under = mix(tir ? vec3(0.0) : refracted, mix(water_color, reflected, 0.8),\n"
    "                          fresnel);\n"
    /* alpha 0: an object under the water, lit through the light map where the sun's
     * refracted rays meet it (ms_env, plugin.h) */
    "    float light = mix(1.0, 0.55 + water_caustics * focus, seen.a);\n"
    "    vec3 below = refracted * light;\n"
    "    below = mix(water_color, below, exp(-len / water_clarity));\n"
    "    vec3 h = normalize(ms_light_dir - v);\n"
    "    vec3 spec = ms_light_color * pow(max(dot(n, h), 0.0), 400.0) * fresnel * 4.0;\n"
    "    vec3 seen_above = mix(below, reflected, fresnel) + spec;\n"
    /* foam: a white, rough layer lit by the sun and the sky, over the water seen from
     * above, covering it as the sim's cover says (sharpened: thin foam is streaks) */
    "    float foam = ms_foam_on * texture2D(ms_foam, (v_pos.xy - ms_foam_field.xy)\n"
    "                                                 * ms_foam_field.zw).r;\n"
    "    vec3 white = vec3(0.85) * (0.55 + 0.45 * max(dot(n, ms_light_dir), 0.0))\n"
    "               * (0.6 + 0.4 * ms_light_color);\n"
    "    seen_above = mix(seen_above, white, smoothstep(0.0, 0.8, foam) * 0.85);\n"
    "    gl_FragColor = vec4(ms_tonemap(under ? seen_under : seen_above), 1.0);\n"
    "}\n";

/* The scene keys; uniform "water_<key>" each (plugins/common/shader_params.h). */
static const shader_param water_params[] = {
    {"color", 3, {0.02f, 0.28f, 0.33f}, 0.0, 1.0, ""},
    {"ior", 1, {1.333f}, 1.0, 3.0, ""},
    {"caustics", 1, {1.2f}, 0.0, 10.0, ""},
    {"clarity", 1, {1.5f}, 1e-3, 1e3, "m"},
    {"parallax", 1, {0.0f}, 0.0, 1.0, ""},
    {NULL, 0, {0}, 0, 0, NULL},
};

static int water_create(const char *json, void **out, char *err, size_t err_size)
{
    return shader_params_create(water_params, json, out, err, err_size);
}

static void water_set_uniforms(const void *self, const ms_shader_uniforms *u)
{
    shader_params_set("water", water_params, self, u);
}

static const ms_shader_vtable water_vtable = {
    .size = sizeof(ms_shader_vtable),
    .passes = MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION | MS_SHADER_NEEDS_CAUSTICS,
    .vertex_source = SHADER_VERTEX_SOURCE,
    .fragment_source = fragment_source,
    .create = water_create,
    .destroy = shader_free,
    .set_uniforms = water_set_uniforms,
};

static const ms_plugin_info water_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "water",
    .version = "1.0",
    .kind = MS_PLUGIN_SHADER,
    .description = "clear water: Fresnel mix of cubemap reflection and refraction, caustics",
    .vtable = &water_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &water_info;
}
