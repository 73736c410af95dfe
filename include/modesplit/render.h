/* ms_renderer: OSMesa off-screen rendering of the combined height field
 * (paper section 3.6): cubemap reflection and refraction mixed by Fresnel,
 * a caustics light map from Snell's law, shader plugins (water, milk, oil).
 * The GL context is OSMesa's or EGL's (desc.backend); every call returns
 * MS_ERR_UNSUPPORTED in a build with neither.
 *
 *     ms_renderer *r;
 *     if (ms_renderer_create_from_scene(scene, &r) != MS_OK) // its `render`
 *         fprintf(stderr, "%s\n", ms_last_error());
 *     for (...) {
 *         ms_sim_step(sim, dt);
 *         ms_renderer_draw(r, sim);                       // the combined field
 *         ms_renderer_write_png(r, "frame_0001.png");     // or ms_renderer_pixels
 *     }
 *     ms_renderer_destroy(r);
 *
 * An engine or a test that has no scene file fills an ms_renderer_desc
 * (ms_renderer_desc_default, then the fields it cares about) and hands
 * ms_renderer_draw_field any height field with its grid.
 *
 * What is drawn: the height field as a mesh (normals by central
 * differences) shaded by the shader plugin; a tiled pool (floor, inner
 * walls, a deck at the rim) under and around it; the sky cubemap behind.
 * The renderer runs only the passes the shader's flags ask for. ms_env is
 * the sky with the pool drawn into it, split by the still water plane (the
 * paper's cubemap reflection and refraction; lib/render/gl_env.c), drawn
 * at create and again when the camera moves:
 *   MS_SHADER_NEEDS_REFLECTION  its upper half: the pool above the water,
 *       the deck and the sky, seen from the eye's mirror image;
 *   MS_SHADER_NEEDS_REFRACTION  its lower half: the pool under the water,
 *       seen from the eye's refracted image (the floor where it lies);
 *   (a half no flag asks for is the plain sky)
 *   MS_SHADER_NEEDS_CAUSTICS    with `caustics` on, the light map ms_caustics
 *       is traced each frame on the CPU (Snell's law, light carried by rays
 *       from the surface to the floor); with it off, a map of 1 (unfocused).
 * With _CAUSTICS the part of ms_env under water holds the pool's colour
 * lit by the sky only (the shader adds the sun through the light map);
 * without it, lit by the sun too.
 *
 * Colours: shaders work in linear RGB; the image is sRGB-encoded, 8 bits.
 * The same field, desc and build give the same bytes (llvmpipe rasterises
 * each tile in one thread; any LP_NUM_THREADS gives the same image).
 *
 * Threads: a renderer is used by one thread at a time (any thread: each
 * call makes its GL context current and releases it again).
 */
#ifndef MODESPLIT_RENDER_H
#define MODESPLIT_RENDER_H

#include "core.h"
#include "scene.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest image side (pixels), and largest cubemap face / light map side.
 * An image also has at most MS_RENDER_MAX_PIXELS pixels (32 Mpixel: 128 MB
 * of RGBA8, as much again on the GL side). */
#define MS_RENDER_MAX_SIDE 8192
#define MS_RENDER_MAX_PIXELS (1L << 25)
#define MS_RENDER_MAX_CAUSTICS 4096

typedef struct ms_renderer_desc {
    uint32_t size;      /* sizeof, set by ms_renderer_desc_default() (core.h: struct sizes) */
    int width, height;  /* pixels, [16, MS_RENDER_MAX_SIDE]; default 950 x 950 */
    const char *shader; /* shader plugin name; default "water" */
    const char *shader_params; /* its parameters as a JSON object text; NULL = defaults */
    /* "builtin" (a procedural sky), a directory holding six PNG faces
     * px.png nx.png py.png ny.png pz.png nz.png (or posx.png ... negz.png),
     * or one PNG holding the six square faces stacked top to bottom in
     * that order (height = 6 x width). Faces are named by world axes (z up)
     * and laid out as OpenGL cube map faces. Default "builtin". */
    const char *cubemap;
    int caustics; /* 1: trace the caustics light map (if the shader uses it); default 1 */
    int caustics_resolution;  /* light map texels per side, [16, MS_RENDER_MAX_CAUSTICS]; 512 */
    float caustics_intensity; /* contrast of the light map, [0, 100]; 1 = physical */
    float light_dir[3];       /* direction the sun's light travels (not all 0); [0.3, 0.2, -1] */
    float light_color[3];     /* linear RGB, each [0, 100]; default [1, 1, 1] */
    float ior;                /* refractive index used to trace caustics, [1, 3]; 1.333 */
    float eye[3], target[3], up[3]; /* camera, m; default: from the -y side, above the pool */
    float fov;                      /* degrees, vertical, [1, 179]; default 45 */
    /* The pool: pool_min = x, y of one corner and z of the floor; pool_max =
     * x, y of the other corner and z of the rim (top of the walls). The
     * height field's values are heights above the floor (the scene's
     * heights above domain.min z). Default [0, 0, 0] .. [1, 1, 0.3]. */
    float pool_min[3], pool_max[3]; /* m */
    float water_level;              /* m (world z) of still water, in [floor, rim]; default 0.25 */
    float tile_size;      /* m, edge of a floor tile, >= 0; 0 = 1/12 of the shorter side */
    float floor_color[3]; /* linear RGB of the tiles, each [0, 1]; [0.30, 0.52, 0.60] */
    /* The mesh has a vertex every mesh_step cells (heights averaged over
     * the step x step block), [0, 64]. 0 = automatic, a screen-space-error
     * LOD: vertices at most 32 pixels apart where the water is nearest the
     * eye, and a smaller step while the mesh's heights leave the field's by
     * more than 2 pixels there (the shading normals always come from the
     * full field). The caustics always trace the full field. Default 0. */
    int mesh_step;
    /* The GL context: "osmesa" (Mesa's off-screen library, gone from Mesa
     * 25.1 on), "egl" (an EGL context without a surface: surfaceless Mesa,
     * or a GPU's EGL) or "auto" (OSMesa, then EGL: the first this build
     * has that works). NULL = "auto". */
    const char *backend;
} ms_renderer_desc;

MS_API ms_renderer_desc ms_renderer_desc_default(void);
/* What a cubemap path (the desc's `cubemap`) must be, checked without
 * decoding, as ms_renderer_create checks it and as a scene's check does:
 * "builtin"; a directory holding six faces px nx py ny pz nz (.png, or
 * posx ... negz) as regular files; or one regular file (a PNG strip).
 * FIFOs, devices and sockets are refused before they are opened (a FIFO
 * would block, /dev/zero never ends). Absolute paths are allowed: the
 * files are read with the rights of the user who runs the scene. */
MS_API ms_status ms_cubemap_check_path(const char *path);
/* The desc of a scene: its `render` section (defaults where it has none)
 * and its pool: domain.min / domain.max x-y, the floor at domain.min z, the
 * still water at surface.level, the rim a little above. The strings point
 * into the scene: valid while it lives. out is filled up to its .size
 * (core.h: struct sizes): start from ms_renderer_desc_default(). */
MS_API ms_status ms_renderer_desc_from_scene(const ms_scene *sc, ms_renderer_desc *out);
/* The same, named as its siblings ms_scene_volume_desc,
 * ms_scene_surface_desc and ms_scene_sim_desc: the scene holds this desc
 * (made when it was read); every scene has one. */
MS_API ms_status ms_scene_renderer_desc(const ms_scene *sc, ms_renderer_desc *out);
/* Validates every field (MS_ERR_INVALID_ARGUMENT naming it), loads the
 * shader plugin (MS_ERR_PLUGIN; a GLSL compile or link error carries the
 * info log), the cubemap (MS_ERR_IO, MS_ERR_PARSE), makes the GL context
 * (MS_ERR_UNSUPPORTED without OSMesa or EGL, or when the backend asked for
 * is not built or cannot make a context). */
MS_API ms_status ms_renderer_create_desc(const ms_renderer_desc *d, ms_renderer **out);
/* The checks ms_renderer_create_desc makes before it needs a GL context:
 * every field, and a cubemap's files (they exist, are PNGs, their headers
 * give faces of at most 4096 texels, square and of one size, and every
 * row decodes: a face cut short is refused here as creating refuses it),
 * with one row of a face in memory at a time. Works in a build without
 * OpenGL. */
MS_API ms_status ms_renderer_desc_check(const ms_renderer_desc *d);
/* ms_renderer_desc_from_scene + ms_renderer_create_desc; a scene without a
 * `render` section is refused (it asks for no image). */
MS_API ms_status ms_renderer_create_from_scene(const ms_scene *sc, ms_renderer **out);
/* Names (one pattern for every handle: ms_X_create(desc) and
 * ms_X_create_from_scene(scene), ms_X_get_info for what it is and
 * ms_X_get_stats for what it did): ms_renderer_create(scene) is the old
 * name of ms_renderer_create_from_scene, kept for this release; in the
 * next, ms_renderer_create takes the desc (today ms_renderer_create_desc). */
MS_DEPRECATED("use ms_renderer_create_from_scene")
MS_API ms_status ms_renderer_create(const ms_scene *sc, ms_renderer **out);
MS_API void ms_renderer_destroy(ms_renderer *r);
/* A renderer that draws with the calling thread's current OpenGL context
 * (a window's, e.g. SDL's or GLX's on Mesa; compatibility profile 2.1 with
 * framebuffer objects and sRGB) instead of an off-screen context of its
 * own. Every later call on it, ms_renderer_destroy included, must be made
 * with that context current. ms_renderer_draw draws as usual, then copies
 * the width x height image (sRGB-encoded) into the framebuffer bound for
 * drawing at the call (0: the window's back buffer) at (0, 0); the caller
 * swaps buffers. No pixels are read back: ms_renderer_pixels returns NULL
 * and ms_renderer_write_png is refused (MS_ERR_STATE); read the window's
 * framebuffer. GL state (program, bindings, enables) is left as the draw
 * left it. MS_ERR_STATE when no context is current, MS_ERR_UNSUPPORTED
 * in a build without OpenGL. For a new window size, make a new renderer. */
MS_API ms_status ms_renderer_create_in_context(const ms_renderer_desc *d, ms_renderer **out);

/* Draws the sim's combined field (ms_sim_height, ms_sim_field_grid of
 * MS_FIELD_COMBINED) at ms_sim_time, with the sim's floaters (the first
 * MS_RENDER_MAX_DISCS) as leaf discs, replacing any set by
 * ms_renderer_set_discs, and the scene's boat as a small hull on its path
 * (bow along its velocity). Where the sim up-samples an SPH field (eq. 20)
 * the SPH part is shown by Catmull-Rom instead of bilinear interpolation
 * (display only: no kinks at the SPH cells' edges). MS_ERR_STATE before the sim's first
 * step. The views it reads are the sim's: call it between steps. */
MS_API ms_status ms_renderer_draw(ms_renderer *r, const ms_sim *sim);
/* Draws any height field: h holds g->nx * g->ny heights (m above the pool
 * floor, row-major, x fastest) at the cell centres of grid g; time (s) is
 * the shader's ms_time. A non-finite height is refused. */
MS_API ms_status ms_renderer_draw_field(ms_renderer *r, const float *h, const ms_grid *g,
                                        double time);

/* Draws a stored field (a run file's frame, `modesplit render`) with the
 * objects of the scene it was run from at `time` s: the boat as a hull on
 * its path, bow along its velocity. Floaters are not stored in run files:
 * the discs set by ms_renderer_set_discs are kept. The same checks as
 * ms_renderer_draw_field. */
MS_API ms_status ms_renderer_draw_scene_field(ms_renderer *r, const ms_scene *sc, const float *h,
                                              const ms_grid *g, double time);

/* Moves the camera (the desc's eye, target, up, fov; the same checks). The
 * environment cubemap is drawn again for the new eye: about the cost of a
 * frame. */
MS_API ms_status ms_renderer_set_camera(ms_renderer *r, const float eye[3], const float target[3],
                                        const float up[3], float fov);

/* Things floating on the surface (the paper's leaves and boat, Fig. 10),
 * drawn as flat discs lit by the sun and the sky. */
typedef struct ms_render_disc {
    float pos[3];   /* m, world: the centre, on the surface */
    float radius;   /* m, > 0 */
    float color[3]; /* linear RGB, each [0, 1] */
} ms_render_disc;
/* The discs drawn with the next draws (copied; n = 0 removes them), at
 * most MS_RENDER_MAX_DISCS. ms_renderer_draw sets the sim's floaters and
 * the scene's boat itself. */
#define MS_RENDER_MAX_DISCS 20000
MS_API ms_status ms_renderer_set_discs(ms_renderer *r, const ms_render_disc *discs, int n);

/* Spray (ms_sim_spray) drawn with the next draws as lit droplets of
 * `radius` m (in (0, 1]): n positions, 3n floats x, y, z (m, world;
 * copied), at most MS_RENDER_MAX_SPRAY; n = 0 removes them. Foam
 * (ms_sim_foam over ms_sim_foam_grid): a cover in [0, 1] per cell of g
 * (copied) that shaders reading ms_foam lay over the liquid (water draws
 * it white; the others ignore it); foam NULL removes it. ms_renderer_draw
 * sets both from a sim with spray, the droplets 0.15 particle spacings in
 * radius. */
#define MS_RENDER_MAX_SPRAY 262144
MS_API ms_status ms_renderer_set_spray(ms_renderer *r, const float *xyz, int n, float radius);
MS_API ms_status ms_renderer_set_foam(ms_renderer *r, const float *foam, const ms_grid *g);

/* RGBA8, top row first; view valid until the next draw. */
MS_API const unsigned char *ms_renderer_pixels(const ms_renderer *r, int *w, int *h);
MS_API ms_status ms_renderer_write_png(const ms_renderer *r, const char *path);

/* What the last draw cost and did. */
typedef struct ms_render_stats {
    uint32_t size;        /* sizeof, set by ms_render_stats_init() (core.h: struct sizes) */
    unsigned passes;      /* MS_SHADER_NEEDS_* bits of the passes that run (plugin.h) */
    long frames;          /* draws finished */
    double mesh_ms;       /* normals and vertex upload, last draw */
    double caustics_ms;   /* light map tracing and upload (0 when not run) */
    double draw_ms;       /* GL drawing until finished */
    double readback_ms;   /* pixels read back and flipped */
    double total_ms;      /* the whole last draw */
    int mesh_nx, mesh_ny; /* vertices of the last draw's mesh (mesh_step) */
    const char *backend;  /* the GL context in use: "osmesa" or "egl" (static string) */
} ms_render_stats;
static inline ms_render_stats ms_render_stats_init(void)
{
    ms_render_stats x = MS_ZERO_INIT;
    x.size = (uint32_t)sizeof x;
    return x;
}
MS_API void ms_renderer_get_stats(const ms_renderer *r, ms_render_stats *out);
MS_DEPRECATED("use ms_renderer_get_stats")
MS_API void ms_renderer_stats(const ms_renderer *r, ms_render_stats *out);

/* Writes the builtin procedural sky (the environment a renderer uses when
 * its cubemap is "builtin") for a sun whose light travels along light_dir,
 * as six size x size PNG faces px.png nx.png py.png ny.png pz.png nz.png
 * in dir (created if missing), for a scene's render.cubemap to load or an
 * artist to paint over. size in [16, 4096]. Needs no GL. */
MS_API ms_status ms_sky_write_cubemap(const char *dir, int size, const float light_dir[3]);

/* The caustics light map of the last draw (texels over the pool, row-major
 * from pool_min, 1 = unfocused light); NULL when it was not traced. */
MS_API const float *ms_renderer_caustics(const ms_renderer *r, int *n);

/* Writes w x h RGBA8 pixels (top row first, as ms_renderer_pixels gives
 * them) to path as a PNG, through "<path>.tmp" and a rename: the bytes
 * ms_renderer_write_png writes for the same pixels. Uses no renderer, so a
 * program may encode a copy of one frame in another thread while the
 * renderer draws the next (`modesplit run --png` does). Sides in
 * [1, 16384]; MS_ERR_INVALID_ARGUMENT names a bad one, MS_ERR_IO the file. */
MS_API ms_status ms_image_write_png(const char *path, const unsigned char *rgba, int w, int h);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_RENDER_H */
