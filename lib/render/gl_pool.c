/* The pool around and under the liquid: a tiled floor, four inner walls up
 * to the rim, a deck around the rim and its outer side, lit by the sun
 * (Lambert) and the sky (a constant share). Static: built once. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/gl_internal.h"

#define AMBIENT 0.4f /* the sky's share of the light on the pool */
/* An object under the water with caustics is lit as the water shader
 * (plugins/shaders/water.c) lights the sky-lit floor it sees through the
 * water, AMBIENT (SKY + SUN focus), with its default strength, so a stone
 * and a tile of one colour at one depth look alike */
#define CAUSTIC_SKY 0.55f
#define CAUSTIC_SUN 1.2f
#define TILE_TEXELS 64

static const char pool_vs[] = "#version 120\n"
                              "varying vec3 v_pos;\n"
                              "varying vec3 v_normal;\n"
                              "varying vec2 v_uv;\n"
                              "varying vec3 v_color;\n"
                              "void main()\n"
                              "{\n"
                              "    v_pos = gl_Vertex.xyz;\n"
                              "    v_normal = gl_Normal;\n"
                              "    v_uv = gl_MultiTexCoord0.xy;\n"
                              "    v_color = gl_Color.rgb;\n"
                              "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
                              "}\n";

static const char pool_fs[] =
    "#version 120\n"
    "uniform sampler2D u_tiles;\n"
    "uniform sampler2D u_caustics;\n"
    "uniform vec3 u_light_to;\n"
    "uniform vec3 u_light_color;\n"
    "uniform float u_water_level;\n"
    "uniform float u_sun_under;\n"
    "uniform float u_ambient;\n"
    "uniform float u_keep;\n"
    "uniform float u_textured;\n"
    "uniform float u_caustic_lit;\n"
    "uniform vec3 u_refracted;\n"
    "uniform vec4 u_pool;\n"
    "uniform float u_floor_z;\n"
    "uniform vec2 u_caustic_light;\n"
    "uniform float u_slices;\n"
    "uniform float u_slice_texels;\n"
    "varying vec3 v_pos;\n"
    "varying vec3 v_normal;\n"
    "varying vec2 v_uv;\n"
    "varying vec3 v_color;\n"
    "void main()\n"
    "{\n"
    "    if (u_keep * (v_pos.z - u_water_level) < 0.0)\n"
    "        discard;\n"
    "    vec3 albedo = v_color * mix(1.0, texture2D(u_tiles, v_uv).r, u_textured);\n"
    "    vec3 n = normalize(v_normal);\n"
    "    float sun = max(dot(n, u_light_to), 0.0);\n"
    "    if (v_pos.z < u_water_level)\n"
    "        sun *= u_sun_under;\n"
    "    /* an object under the water with caustics: the sun that reaches it\n"
    "     * refracted (u_refracted, flat water's, downwards, for its angle on\n"
    "     * the face), focused as the light in the water is at its point\n"
    "     * (the tracer's slices at heights depth k / u_slices, the floor's\n"
    "     * first, interpolated in height); alpha 0 tells the liquid's\n"
    "     * shader it is lit already */\n"
    "    float lit = u_caustic_lit * step(v_pos.z, u_water_level);\n"
    "    float depth = max(u_water_level - u_floor_z, 1e-6);\n"
    "    float slice = clamp((v_pos.z - u_floor_z) / depth, 0.0, 1.0) * u_slices;\n"
    "    float s0 = min(floor(slice), u_slices - 1.0);\n"
    "    float s1 = min(s0 + 1.0, u_slices - 1.0);\n"
    "    vec2 uv = clamp((v_pos.xy - u_pool.xy) / u_pool.zw, 0.0, 1.0);\n"
    "    float half_texel = 0.5 / u_slice_texels;\n"
    "    float t = clamp(uv.y, half_texel, 1.0 - half_texel);\n"
    "    float f0 = texture2D(u_caustics, vec2(uv.x, (s0 + t) / u_slices)).r;\n"
    "    float f1 = texture2D(u_caustics, vec2(uv.x, (s1 + t) / u_slices)).r;\n"
    "    /* past the top slice towards the surface, where no rays have\n"
    "     * converged yet: 1 */\n"
    "    f1 = mix(f1, 1.0, step(u_slices - 0.5, s0 + 1.0));\n"
    "    float focus = mix(f0, f1, clamp(slice - s0, 0.0, 1.0));\n"
    "    float caustic = max(dot(n, -u_refracted), 0.0) * focus;\n"
    "    float under = u_ambient * (u_caustic_light.x + u_caustic_light.y * caustic);\n"
    "    vec3 light = u_light_color * mix(u_ambient + (1.0 - u_ambient) * sun, under, lit);\n"
    "    gl_FragColor = vec4(albedo * light, 1.0 - lit);\n"
    "}\n";

typedef struct builder {
    float *v;
    int n; /* vertices written */
    float tile;
} builder;

static void vertex(builder *b, const float p[3], const float nrm[3], const float color[3])
{
    float *o = b->v + (size_t)b->n * MS_POOL_STRIDE;
    float u, v;
    if (fabsf(nrm[2]) > 0.5f)
        u = p[0], v = p[1];
    else if (fabsf(nrm[0]) > 0.5f)
        u = p[1], v = p[2];
    else
        u = p[0], v = p[2];
    o[0] = p[0], o[1] = p[1], o[2] = p[2];
    o[3] = nrm[0], o[4] = nrm[1], o[5] = nrm[2];
    o[6] = u / b->tile, o[7] = v / b->tile;
    o[8] = color[0], o[9] = color[1], o[10] = color[2];
    b->n++;
}

/* Two triangles, wound counter-clockwise seen from the side nrm points to. */
static void quad(builder *b, float p[4][3], const float nrm[3], const float color[3])
{
    float e1[3], e2[3];
    for (int k = 0; k < 3; ++k)
        e1[k] = p[1][k] - p[0][k], e2[k] = p[2][k] - p[0][k];
    float c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0]};
    int flip = c[0] * nrm[0] + c[1] * nrm[1] + c[2] * nrm[2] < 0;
    static const int fwd[6] = {0, 1, 2, 0, 2, 3}, rev[6] = {0, 2, 1, 0, 3, 2};
    for (int i = 0; i < 6; ++i)
        vertex(b, p[flip ? rev[i] : fwd[i]], nrm, color);
}

/* An axis-aligned horizontal rectangle at height z. */
static void rect(builder *b, float xa, float ya, float xb, float yb, float z, const float col[3])
{
    static const float up[3] = {0, 0, 1};
    float p[4][3] = {{xa, ya, z}, {xb, ya, z}, {xb, yb, z}, {xa, yb, z}};
    quad(b, p, up, col);
}

/* A vertical wall along x = const (axis 0) or y = const (axis 1) from
 * (a0 .. a1) along the other axis, z from z0 to z1, facing dir (+1, -1). */
static void wall(builder *b, int axis, float at, float a0, float a1, float z0, float z1, float dir,
                 const float col[3])
{
    float nrm[3] = {0, 0, 0};
    nrm[axis] = dir;
    float p[4][3];
    const float as[4] = {a0, a1, a1, a0}, zs[4] = {z0, z0, z1, z1};
    for (int i = 0; i < 4; ++i) {
        p[i][axis] = at;
        p[i][1 - axis] = as[i];
        p[i][2] = zs[i];
    }
    quad(b, p, nrm, col);
}

ms_status ms_gl_pool_create(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    ms_status st = ms_gl_program_build("the pool program", pool_vs, pool_fs, &gl->pool);
    if (st != MS_OK)
        return st;

    unsigned char texels[TILE_TEXELS * TILE_TEXELS];
    ms_tile_texture(TILE_TEXELS, texels);
    glGenTextures(1, &gl->tiles_tex);
    glBindTexture(GL_TEXTURE_2D, gl->tiles_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, TILE_TEXELS, TILE_TEXELS, 0, GL_RED, GL_UNSIGNED_BYTE,
                 texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glGenerateMipmap(GL_TEXTURE_2D);

    const ms_renderer_desc *d = &r->desc;
    const float x0 = d->pool_min[0], y0 = d->pool_min[1], zf = d->pool_min[2];
    const float x1 = d->pool_max[0], y1 = d->pool_max[1], zr = r->rim_z;
    const float deck = 0.3f * MS_MAX(x1 - x0, y1 - y0); /* m */
    const float X0 = x0 - deck, Y0 = y0 - deck, X1 = x1 + deck, Y1 = y1 + deck;
    static const float stone[3] = {0.50f, 0.45f, 0.36f}, side[3] = {0.36f, 0.33f, 0.27f};
    const float *tiles = d->floor_color;

    enum { QUADS = 1 + 4 + 4 + 4 + 4 };
    float v[QUADS * 6 * MS_POOL_STRIDE];
    builder b = {v, 0, r->tile_size};
    rect(&b, x0, y0, x1, y1, zf, tiles);        /* floor */
    wall(&b, 0, x0, y0, y1, zf, zr, +1, tiles); /* inner walls */
    wall(&b, 0, x1, y0, y1, zf, zr, -1, tiles);
    wall(&b, 1, y0, x0, x1, zf, zr, +1, tiles);
    wall(&b, 1, y1, x0, x1, zf, zr, -1, tiles);
    b.tile = 2 * r->tile_size; /* the deck's larger slabs */
    rect(&b, X0, Y0, x0, Y1, zr, stone);
    rect(&b, x1, Y0, X1, Y1, zr, stone);
    rect(&b, x0, Y0, x1, y0, zr, stone);
    rect(&b, x0, y1, x1, Y1, zr, stone);
    wall(&b, 0, X0, Y0, Y1, zf, zr, -1, side); /* its outer side */
    wall(&b, 0, X1, Y0, Y1, zf, zr, +1, side);
    wall(&b, 1, Y0, X0, X1, zf, zr, -1, side);
    wall(&b, 1, Y1, X0, X1, zf, zr, +1, side);
    gl->pool_count = b.n;
    /* an apron of floor tiles around the pool, drawn only into the
     * refraction half of the environment cubemap: a refracted lookup that
     * misses the pool (its viewpoint is exact only for the ray to the
     * view's target) then still finds tiled floor, not the sky's ground */
    const float A = MS_MAX(x1 - x0, y1 - y0);
    b.tile = r->tile_size;
    rect(&b, x0 - A, y0 - A, x0, y1 + A, zf, tiles);
    rect(&b, x1, y0 - A, x1 + A, y1 + A, zf, tiles);
    rect(&b, x0, y0 - A, x1, y0, zf, tiles);
    rect(&b, x0, y1, x1, y1 + A, zf, tiles);
    gl->pool_apron_count = b.n;

    glGenBuffers(1, &gl->pool_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, gl->pool_vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)b.n * MS_POOL_STRIDE * sizeof(float)), v,
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return ms_gl_check("making the pool");
}

/* Vertices of the boat's hull (gl_pool.c's triangles) */
#define HULL_POINTS 7
#define HULL_VERTICES (HULL_POINTS * 3 + HULL_POINTS * 6)

/* The boat as a small hull: a pointed deck outline (bow along heading), a
 * wooden deck at the freeboard, white sides down to below the water line,
 * lit like the pool. */
static void hull(builder *b, const ms_renderer *r)
{
    static const float white[3] = {0.85f, 0.83f, 0.78f}, wood[3] = {0.45f, 0.28f, 0.12f};
    static const float up[3] = {0, 0, 1};
    /* the deck outline in (forward, left) units of (half length, half beam) */
    static const float outline[HULL_POINTS][2] = {{1.0f, 0.0f},  {0.35f, 1.0f},  {-0.85f, 0.85f},
                                                  {-1.0f, 0.7f}, {-1.0f, -0.7f}, {-0.85f, -0.85f},
                                                  {0.35f, -1.0f}};
    const float L = r->boat_radius, B = 0.42f * L, H = 0.35f * L, D = 0.2f * L;
    const float f[2] = {r->boat_heading[0], r->boat_heading[1]}, l[2] = {-f[1], f[0]};
    const float *c = r->boat_pos;
    float top[HULL_POINTS][3], bot[HULL_POINTS][3];
    for (int i = 0; i < HULL_POINTS; ++i) {
        const float u = outline[i][0] * L, v = outline[i][1] * B;
        top[i][0] = c[0] + u * f[0] + v * l[0];
        top[i][1] = c[1] + u * f[1] + v * l[1];
        top[i][2] = c[2] + H;
        bot[i][0] = c[0] + 0.85f * (u * f[0] + v * l[0]);
        bot[i][1] = c[1] + 0.85f * (u * f[1] + v * l[1]);
        bot[i][2] = c[2] - D;
    }
    const float mid[3] = {c[0] - 0.1f * L * f[0], c[1] - 0.1f * L * f[1], c[2] + H};
    for (int i = 0; i < HULL_POINTS; ++i) {
        const int j = (i + 1) % HULL_POINTS;
        vertex(b, mid, up, wood);
        vertex(b, top[i], up, wood);
        vertex(b, top[j], up, wood);
        /* the side between outline points i and j: its outward normal */
        float ex = top[j][0] - top[i][0], ey = top[j][1] - top[i][1];
        float ln = sqrtf(ex * ex + ey * ey);
        float nrm[3] = {ln > 0 ? -ey / ln : 0, ln > 0 ? ex / ln : 0, 0};
        /* the outline runs counter-clockwise seen from above: outward is
         * to the right of the edge */
        nrm[0] = -nrm[0], nrm[1] = -nrm[1];
        vertex(b, top[i], nrm, white);
        vertex(b, bot[i], nrm, white);
        vertex(b, bot[j], nrm, white);
        vertex(b, top[i], nrm, white);
        vertex(b, bot[j], nrm, white);
        vertex(b, top[j], nrm, white);
    }
}

/* A floating leaf (the sim's floaters, Fig. 10): a pointed blade of
 * length 2 radius and half that width, turned and tinted by a hash of its
 * index (deterministic): LEAF_SEGMENTS triangles about its centre. */
#define LEAF_SEGMENTS 12
static void leaf(builder *b, const float ctr[3], float radius, const float color[3], unsigned i)
{
    static const float up[3] = {0, 0, 1};
    unsigned hsh = i * 2654435761u;
    hsh ^= hsh >> 15;
    const float turn = 6.2831853f * (float)(hsh & 1023u) / 1024.0f;
    const float tint = 0.8f + 0.4f * (float)((hsh >> 10) & 255u) / 255.0f;
    const float col[3] = {MS_MIN(color[0] * tint, 1.0f), MS_MIN(color[1] * tint, 1.0f),
                          MS_MIN(color[2] * tint, 1.0f)};
    const float ca = cosf(turn), sa = sinf(turn);
    float p[LEAF_SEGMENTS][3];
    for (int s = 0; s < LEAF_SEGMENTS; ++s) {
        const float a = 6.2831853f * (float)s / LEAF_SEGMENTS;
        /* pointed at both tips: the width goes as |sin a|^1.5 */
        const float x = radius * cosf(a), sn = sinf(a);
        const float y = 0.5f * radius * sn * sqrtf(fabsf(sn));
        p[s][0] = ctr[0] + ca * x - sa * y;
        p[s][1] = ctr[1] + sa * x + ca * y;
        p[s][2] = ctr[2];
    }
    for (int s = 0; s < LEAF_SEGMENTS; ++s) {
        const int t = (s + 1) % LEAF_SEGMENTS;
        vertex(b, ctr, up, col);
        vertex(b, p[s], up, col);
        vertex(b, p[t], up, col);
    }
}

ms_status ms_gl_discs_upload(ms_renderer *r)
{
    ms_gl *gl = r->gl;
    r->discs_changed = 0;
    gl->discs_count = 0;
    gl->glass_first = 0;
    gl->objects_first = 0;
    if (r->ndiscs == 0 && !r->has_boat && r->object_nverts == 0)
        return MS_OK;
    enum { SEGMENTS = 10 };
    const size_t per = 3 * (size_t)MS_MAX((int)SEGMENTS, LEAF_SEGMENTS);
    const size_t verts =
        (size_t)r->ndiscs * per + (r->has_boat ? HULL_VERTICES : 0) + (size_t)r->object_nverts;
    float *v = ms_alloc_array(verts, MS_POOL_STRIDE * sizeof(float));
    if (!v)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %d discs", r->ndiscs);
    static const float up[3] = {0, 0, 1};
    builder b = {v, 0, 1.0f};
    for (int i = 0; i < r->ndiscs; ++i) {
        const ms_render_disc *c = &r->discs[i];
        const float lift = 0.02f * c->radius; /* m: clear of the water it floats on */
        const float ctr[3] = {c->pos[0], c->pos[1], c->pos[2] + lift};
        if (i < r->nleaves) {
            leaf(&b, ctr, c->radius, c->color, (unsigned)i);
            continue;
        }
        for (int s = 0; s < SEGMENTS; ++s) {
            const float a0 = 6.2831853f * (float)s / SEGMENTS;
            const float a1 = 6.2831853f * (float)(s + 1) / SEGMENTS;
            const float p0[3] = {ctr[0] + c->radius * cosf(a0), ctr[1] + c->radius * sinf(a0),
                                 ctr[2]};
            const float p1[3] = {ctr[0] + c->radius * cosf(a1), ctr[1] + c->radius * sinf(a1),
                                 ctr[2]};
            vertex(&b, ctr, up, c->color);
            vertex(&b, p0, up, c->color);
            vertex(&b, p1, up, c->color);
        }
    }
    gl->objects_first = b.n; /* what the environment shows (gl_env.c) */
    if (r->has_boat)
        hull(&b, r);
    for (int i = 0; i < r->object_nverts; ++i) { /* the obstacles (objects.c) */
        const float *o = r->object_verts + MS_RENDER_OBJECT_STRIDE * (size_t)i;
        if (i == r->object_glass)
            gl->glass_first = b.n;
        vertex(&b, o, o + 3, o + 6);
    }
    if (!gl->discs_vbo)
        glGenBuffers(1, &gl->discs_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, gl->discs_vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)b.n * MS_POOL_STRIDE * sizeof(float)), v,
                 GL_DYNAMIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    ms_free(v);
    gl->discs_count = b.n;
    if (r->object_glass >= r->object_nverts)
        gl->glass_first = b.n;
    if (gl->glass_first < b.n)
        return ms_gl_glass_create(r); /* gl_glass.c */
    return MS_OK;
}

/* Flat water's refracted sun (Snell's law, vector form, as caustics.c),
 * travelling down. */
static void refracted_sun(const ms_renderer *r, float t[3])
{
    const float *L = r->light_to, eta = 1.0f / r->desc.ior; /* L: towards the sun */
    const float cosi = MS_MAX(L[2], 0.0f);
    const float k = MS_MAX(1.0f - eta * eta * (1.0f - cosi * cosi), 1e-6f);
    t[0] = -eta * L[0], t[1] = -eta * L[1], t[2] = -sqrtf(k);
}

/* The pool program bound with its uniforms and the vertex arrays of vbo
 * (MS_POOL_STRIDE layout) enabled; caustic_lit 1: what lies under the
 * water takes the sun through the caustics light map (the objects in the
 * environment's refraction half, gl_env.c). */
static void pool_program(const ms_renderer *r, GLuint vbo, float sun_under, float keep,
                         float textured, float caustic_lit)
{
    const ms_gl *gl = r->gl;
    const ms_renderer_desc *d = &r->desc;
    const GLsizei stride = MS_POOL_STRIDE * sizeof(float);
    GLuint p = gl->pool.prog;
    glUseProgram(p);
    int slices;
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, ms_gl_open_texture(r, &slices)); /* not in their own shadow */
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, gl->tiles_tex);
    glUniform1i(glGetUniformLocation(p, "u_tiles"), 0);
    glUniform1i(glGetUniformLocation(p, "u_caustics"), 1);
    glUniform3fv(glGetUniformLocation(p, "u_light_to"), 1, r->light_to);
    glUniform3fv(glGetUniformLocation(p, "u_light_color"), 1, d->light_color);
    glUniform1f(glGetUniformLocation(p, "u_water_level"), d->water_level);
    glUniform1f(glGetUniformLocation(p, "u_sun_under"), sun_under);
    glUniform1f(glGetUniformLocation(p, "u_ambient"), AMBIENT);
    glUniform1f(glGetUniformLocation(p, "u_keep"), keep);
    glUniform1f(glGetUniformLocation(p, "u_textured"), textured);
    float t[3];
    refracted_sun(r, t);
    glUniform1f(glGetUniformLocation(p, "u_caustic_lit"), caustic_lit);
    glUniform3fv(glGetUniformLocation(p, "u_refracted"), 1, t);
    glUniform4f(glGetUniformLocation(p, "u_pool"), d->pool_min[0], d->pool_min[1],
                d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    glUniform1f(glGetUniformLocation(p, "u_floor_z"), d->pool_min[2]);
    glUniform2f(glGetUniformLocation(p, "u_caustic_light"), CAUSTIC_SKY, CAUSTIC_SUN);
    glUniform1f(glGetUniformLocation(p, "u_slices"), (float)slices);
    glUniform1f(glGetUniformLocation(p, "u_slice_texels"),
                (float)MS_MAX(slices > 1 ? r->caustics.layer_n : r->caustics.n, 1));
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, stride, (const void *)0);
    glNormalPointer(GL_FLOAT, stride, (const void *)(3 * sizeof(float)));
    glTexCoordPointer(2, GL_FLOAT, stride, (const void *)(6 * sizeof(float)));
    glColorPointer(3, GL_FLOAT, stride, (const void *)(8 * sizeof(float)));
}

static void pool_program_end(void)
{
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ms_gl_pool_draw(const ms_renderer *r, float sun_under, float keep)
{
    const ms_gl *gl = r->gl;
    pool_program(r, gl->pool_vbo, sun_under, keep, 1.0f, 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, keep < 0 ? gl->pool_apron_count : gl->pool_count);
    pool_program_end();
    if (keep == 0 && gl->discs_count > 0) {
        /* the floating discs: untextured, lifted off the water by the
         * depth offset */
        pool_program(r, gl->discs_vbo, sun_under, keep, 0.0f, 0.0f);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(-1.0f, -4.0f);
        glDisable(GL_CULL_FACE);
        glDrawArrays(GL_TRIANGLES, 0, gl->glass_first);
        glDisable(GL_POLYGON_OFFSET_FILL);
        pool_program_end();
        ms_gl_glass_draw(r, r->desc.eye, keep); /* gl_glass.c */
    }
}

void ms_gl_objects_draw(const ms_renderer *r, const float eye[3], float sun_under, float keep)
{
    const ms_gl *gl = r->gl;
    if (gl->discs_count <= gl->objects_first)
        return;
    /* under the water with the caustics traced: lit through the light map */
    const float caustic_lit = keep < 0 && r->trace_caustics ? 1.0f : 0.0f;
    pool_program(r, gl->discs_vbo, sun_under, keep, 0.0f, caustic_lit);
    glDisable(GL_CULL_FACE);
    glDrawArrays(GL_TRIANGLES, gl->objects_first, gl->glass_first - gl->objects_first);
    pool_program_end();
    ms_gl_glass_draw(r, eye, keep);
}
