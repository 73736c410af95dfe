/* The builtin environment cubemap: a procedural sky (a blue gradient, soft
 * value-noise clouds, the sun), a plain ground below the horizon. World
 * directions, z up; texels are made in linear RGB and stored sRGB-encoded.
 * Deterministic: the noise is an integer hash, no RNG state. */
#include <math.h>
#include <stdint.h>

#include "core/core_internal.h"
#include "render/render_internal.h"

void ms_cubemap_free(ms_cubemap *c)
{
    if (!c)
        return;
    for (int f = 0; f < 6; ++f) {
        ms_free(c->face[f]);
        c->face[f] = NULL;
    }
    c->size = 0;
}

/* OpenGL's table (major axis, sc, tc): for +x the texel (s, t) looks along
 * (1, -t, -s), and so on. */
void ms_cubemap_direction(int f, float s, float t, float dir[3])
{
    switch (f) {
    case 0:
        dir[0] = 1, dir[1] = -t, dir[2] = -s;
        break;
    case 1:
        dir[0] = -1, dir[1] = -t, dir[2] = s;
        break;
    case 2:
        dir[0] = s, dir[1] = 1, dir[2] = t;
        break;
    case 3:
        dir[0] = s, dir[1] = -1, dir[2] = -t;
        break;
    case 4:
        dir[0] = s, dir[1] = -t, dir[2] = 1;
        break;
    default:
        dir[0] = -s, dir[1] = -t, dir[2] = -1;
        break;
    }
}

static unsigned char srgb_byte(float linear)
{
    float v = MS_CLAMP(linear, 0.0f, 1.0f);
    float e = v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
    return (unsigned char)lrintf(255.0f * e);
}

static float hash01(int32_t x, int32_t y)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return (float)(h >> 8) * (1.0f / 16777216.0f);
}

/* Value noise with a smooth (cubic Hermite) fade, in [0, 1). */
static float value_noise(float x, float y)
{
    float fx = floorf(x), fy = floorf(y);
    int32_t ix = (int32_t)fx, iy = (int32_t)fy;
    float u = x - fx, v = y - fy;
    u = u * u * (3 - 2 * u);
    v = v * v * (3 - 2 * v);
    float a = hash01(ix, iy), b = hash01(ix + 1, iy);
    float c = hash01(ix, iy + 1), d = hash01(ix + 1, iy + 1);
    return (a + (b - a) * u) + ((c + (d - c) * u) - (a + (b - a) * u)) * v;
}

static float fbm(float x, float y)
{
    float sum = 0, amp = 0.5f;
    for (int o = 0; o < 4; ++o) {
        sum += amp * value_noise(x, y);
        x = 2.03f * x + 17.1f;
        y = 2.03f * y + 5.7f;
        amp *= 0.5f;
    }
    return sum / 0.9375f;
}

static float smoothstepf(float a, float b, float x)
{
    float t = MS_CLAMP((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
}

/* Linear RGB of the sky in unit direction d; sun = unit vector to the sun.
 * Above the horizon: a zenith-to-horizon gradient that warms as the sun
 * sinks, clouds on a plane above (value-noise fbm, lit on the sun's side),
 * the sun's glow and disc. Below: a lawn with patches and a dark tree line
 * along the horizon, so reflections and the frame's background carry an
 * environment, not one colour. texel: the angle (radians) one texel spans. */
static void sky_color(const float d[3], const float sun[3], float texel, float rgb[3])
{
    static const float zenith[3] = {0.08f, 0.22f, 0.62f}, horizon[3] = {0.52f, 0.68f, 0.88f};
    static const float dusk[3] = {0.95f, 0.55f, 0.30f};
    static const float grass[3] = {0.10f, 0.20f, 0.05f}, dry[3] = {0.24f, 0.26f, 0.10f};
    static const float trees[3] = {0.03f, 0.07f, 0.03f};
    const float z = d[2];
    const float low = 1.0f - smoothstepf(0.05f, 0.45f, sun[2]); /* 1: the sun near the horizon */
    const float az = atan2f(d[1], d[0]);
    /* the tree line: its top wanders between 1 and 4 degrees, with crowns
     * (value noise of about a degree, taken around the circle so that the
     * line has no seam at az = +-pi) */
    const float ca = cosf(az), sa = sinf(az);
    const float tree_top = 0.016f + 0.04f * fbm(3.0f * ca + 7.0f, 3.0f * sa + 3.0f) +
                           0.012f * value_noise(45.0f * ca + 1.3f, 45.0f * sa + 2.9f) +
                           0.005f * value_noise(140.0f * ca + 4.1f, 140.0f * sa + 0.7f);
    if (z >= 0) {
        float k = powf(1.0f - z, 2.5f);
        float cs = d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2];
        float warm = low * powf(MS_MAX(cs, 0.0f), 3.0f) * k;
        for (int c = 0; c < 3; ++c) {
            rgb[c] = zenith[c] + (horizon[c] - zenith[c]) * k;
            rgb[c] += (dusk[c] - rgb[c]) * warm;
        }
        if (z > 0.02f) {
            /* clouds on a plane above: denser patches, thinning at the horizon */
            float px = 1.5f * d[0] / z, py = 1.5f * d[1] / z;
            float dens = smoothstepf(0.5f, 0.78f, fbm(px, py)) * smoothstepf(0.02f, 0.25f, z);
            float lit = 0.75f + 0.25f * MS_MAX(cs, 0.0f);
            for (int c = 0; c < 3; ++c) {
                float cloud = lit * (0.9f + (dusk[c] - 0.9f) * 0.6f * low);
                rgb[c] += (cloud - rgb[c]) * 0.85f * dens;
            }
        }
        /* the trees cover the part of the texel below their top: a hard
         * edge steps from texel to texel (blocks in the reflection) */
        float cover = smoothstepf(tree_top + texel, tree_top - texel, z);
        if (cover > 0) {
            for (int c = 0; c < 3; ++c) {
                float leaf =
                    trees[c] * (0.8f + 0.4f * value_noise(60.0f * ca + 40.0f * sa, 40.0f * z));
                rgb[c] += (leaf - rgb[c]) * cover;
            }
        }
    } else {
        /* the lawn seen on a plane below: patches, fading into haze far off */
        float px = 2.0f * d[0] / -z, py = 2.0f * d[1] / -z;
        float patch = fbm(px, py), haze = expf(-8.0f * -z);
        for (int c = 0; c < 3; ++c) {
            float g = grass[c] + (dry[c] - grass[c]) * patch;
            rgb[c] = g + (0.35f * horizon[c] - g) * 0.5f * haze;
        }
    }
    if (sun[2] > 0 && z > 0) {
        float cs = d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2];
        if (cs > 0) {
            float glow = 0.5f * powf(cs, 64.0f) + (cs > 0.99985f ? 4.0f : 0.0f);
            rgb[0] += glow;
            rgb[1] += (0.92f - 0.25f * low) * glow;
            rgb[2] += (0.75f - 0.4f * low) * glow;
        }
    }
}

ms_status ms_sky_builtin(int size, const float light_dir[3], ms_cubemap *out)
{
    out->size = 0;
    for (int f = 0; f < 6; ++f)
        out->face[f] = NULL;
    float sun[3] = {-light_dir[0], -light_dir[1], -light_dir[2]};
    float ls = sqrtf(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
    for (int k = 0; k < 3; ++k)
        sun[k] /= ls;
    for (int f = 0; f < 6; ++f) {
        unsigned char *p = ms_alloc_array((size_t)size * (size_t)size, 4);
        if (!p) {
            ms_cubemap_free(out);
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for the sky");
        }
        out->face[f] = p;
        for (int j = 0; j < size; ++j) {
            float t = 2.0f * ((float)j + 0.5f) / (float)size - 1.0f;
            for (int i = 0; i < size; ++i, p += 4) {
                float s = 2.0f * ((float)i + 0.5f) / (float)size - 1.0f, d[3], rgb[3];
                ms_cubemap_direction(f, s, t, d);
                float l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (int k = 0; k < 3; ++k)
                    d[k] /= l;
                sky_color(d, sun, 2.0f / (float)size, rgb);
                p[0] = srgb_byte(rgb[0]);
                p[1] = srgb_byte(rgb[1]);
                p[2] = srgb_byte(rgb[2]);
                p[3] = 255;
            }
        }
    }
    out->size = size;
    return MS_OK;
}
