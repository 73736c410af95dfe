/* lib/render: the off-screen renderer of the paper's section 3.6 (internal).
 *
 * Owns: the renderer desc and its checks (render.c), the CPU parts that
 * need no GL (caustics.c: the caustics light map traced by Snell's law;
 * mesh.c: the height-field mesh and its normals by central differences;
 * sky.c: the builtin procedural sky; cubemap_file.c: cubemap faces from PNG
 * files; tiles.c: the pool's tile texture; png_out.c: the PNG writer), and
 * the GL side, compiled only with OSMesa or EGL (gl_*.c: context, programs, the
 * pool and sky geometry, the refraction cubemap, the frame).
 *
 * Implements: Snell's law (n1 sin t1 = n2 sin t2) in vector form for the
 * caustics rays, Schlick's approximation of the Fresnel equations for
 * their transmission (the shaders use it for the reflection/refraction
 * mix). The paper gives these in words (section 3.6), not as numbered
 * equations.
 */
#ifndef MS_RENDER_INTERNAL_H
#define MS_RENDER_INTERNAL_H

#include <stddef.h>

#include "modesplit/plugin.h"
#include "modesplit/render.h"
#include "plugin/plugin_internal.h"

/* The ranges of every ms_renderer_desc field (render.c), without the
 * cubemap's files (ms_renderer_desc_check probes those): the scene's render
 * section checks its desc with it and names the refused field's key. */
ms_status ms_renderer_desc_check_fields(const ms_renderer_desc *d);

/* ---- cubemaps (CPU) ---------------------------------------------------- */

/* Six square faces of sRGB-encoded RGBA8 texels, in OpenGL order
 * (+x, -x, +y, -y, +z, -z), each row-major from the first row GL takes. */
typedef struct ms_cubemap {
    int size;               /* texels per side */
    unsigned char *face[6]; /* size * size * 4 bytes each, ms_alloc'd */
} ms_cubemap;

void ms_cubemap_free(ms_cubemap *c);
/* The world direction (unit not needed) of texel centre (i, j) of face f,
 * OpenGL's cube map convention: s = column, t = row, both in (-1, 1). */
void ms_cubemap_direction(int f, float s, float t, float dir[3]);
/* The builtin sky: a blue gradient with soft clouds, a sun disc towards
 * -light_dir, a grey-green ground below the horizon. Deterministic. */
ms_status ms_sky_builtin(int size, const float light_dir[3], ms_cubemap *out);
/* Loads "path": a directory of six faces or one PNG strip (render.h). */
ms_status ms_cubemap_load(const char *path, ms_cubemap *out);
/* The refusals of ms_cubemap_load (existence, PNG, face sizes from the
 * headers, every row decoded) with one row in memory, not the faces. */
ms_status ms_cubemap_probe(const char *path);

/* ---- tiles (CPU) -------------------------------------------------------- */

/* One square tile with its grout, size x size luminance texels in [0, 255]
 * (1 = tile, darker = grout), to repeat. */
void ms_tile_texture(int size, unsigned char *texels);

/* ---- mesh (CPU) --------------------------------------------------------- */

/* The index of the first non-finite value of h[0 .. n), or -1. */
long ms_field_nonfinite(const float *h, size_t n);
/* Interleaved vertices of the height field, 6 floats each: x, y, z (world,
 * m) and the unit normal. Vertex (i, j) sits at the centre of cell (i, j),
 * except that the outermost row and column sit on the grid's edge, so the
 * mesh meets the walls. */
void ms_mesh_build(const float *h, const ms_grid *g, float floor_z, float *restrict vertices);
/* The gradient (dh/dx, dh/dy) of every cell of h (as ms_mesh_build's
 * normals), 2 floats per cell, row by row: the shaders' normal map. */
void ms_mesh_gradients(const float *h, const ms_grid *g, float *restrict out);
/* The automatic mesh step (a screen-space-error LOD): vertices at most
 * MS_MESH_AUTO_PIXELS apart where the water is nearest the eye, and the
 * step lowered while the mesh's heights (block averages, interpolated)
 * leave the field's by more than MS_MESH_AUTO_ERROR_PX pixels there. The
 * shading normals come from the full field's gradient texture, so the
 * vertices only carry the height. llvmpipe shades whole 4 x 4 pixel
 * blocks along every triangle's edges, so small triangles cost far more
 * than their pixels (fig1: a 50^2 mesh draws in 0.65 of the time of
 * 133^2, the same picture to 0.1 %). */
#define MS_MESH_AUTO_PIXELS 32.0
#define MS_MESH_AUTO_ERROR_PX 2.0
/* The field averaged over blocks of about step x step cells: out gets
 * (nx / step) x (ny / step) heights over the same extent (*out_g). */
void ms_mesh_coarsen(const float *h, const ms_grid *g, int step, float *restrict out,
                     ms_grid *out_g);
/* The automatic mesh step (render.h, mesh_step = 0) for field h on grid g
 * seen by a camera of desc d; scratch holds g's cells (ms_mesh_coarsen's
 * out for any step). */
int ms_mesh_auto_step(const ms_renderer_desc *d, const float *h, const ms_grid *g, float *scratch);
/* The largest height difference (m) between field h and the surface a
 * mesh of `step` draws: at every cell centre, the field against the
 * bilinear interpolation of the block averages at the coarse vertices
 * (ms_mesh_build's positions: block centres, the outermost on the edge);
 * coarse gets the block averages. */
double ms_mesh_height_error(const float *h, const ms_grid *g, int step, float *coarse);
/* Triangle indices of an nx x ny vertex grid: 6 (nx-1)(ny-1) of them. */
void ms_mesh_indices(int nx, int ny, unsigned *restrict indices);

/* ---- caustics (CPU) ----------------------------------------------------- */

typedef struct ms_caustics_desc {
    float pool[4];      /* x0, y0, size x, size y (m): where the map lies */
    float floor_z;      /* m, world */
    float light_dir[3]; /* unit, the direction light travels (z < 0) */
    float ior;          /* refractive index of the liquid */
    float intensity;    /* 1 = physical contrast, 0 = flat */
    int resolution;     /* texels per side */
    float depth;        /* m: still water over the floor; > 0 also traces the walls */
    /* what blocks the light on its way to the floor, as
     * triangles (3 vertices each, x y z first of `occluder_stride` floats
     * a vertex, world); NULL: nothing */
    const float *occluders;
    int occluder_verts;
    int occluder_stride;
    /* the light also at `layers` heights between the floor and
     * the still water (needs depth > 0), for the objects under the water */
    int layers;
} ms_caustics_desc;

/* Scratch and result of the tracer (reused frame to frame). */
typedef struct ms_caustics {
    int n;            /* resolution */
    float *map;       /* n * n, 1 = unfocused light */
    float *tmp;       /* n * n, the blur's scratch */
    float *gx, *gy;   /* field gradients */
    size_t field_cap; /* cells gx, gy hold */
    float *row;       /* scratch of one row of rays: 3 field rows, 3 ray rows */
    int *col0;        /* per ray column: the field node left of it */
    float *colf;      /* and the fraction towards the next */
    size_t row_cap;   /* floats row holds / 6; ints col0 holds */
    /* the pool's walls under the water: 4 strips of n x
     * wall_rows texels, bottom row first, stacked -x, +x, -y, +y (along
     * the x-walls u runs with y, along the y-walls with x; v from the
     * floor up to the still water), in the floor map's unit: the light a
     * floor texel gets under flat water, per area. 0 rows: not traced. */
    int wall_rows;
    float *walls, *walls_tmp;
    /* n * n: 1 where the occluders leave the floor in the sun, 0 in their
     * shadow; map is multiplied by it, open is map before that:
     * the light the occluders themselves take (gl_pool.c). NULL and
     * unused without occluders */
    float *lit, *open;
    int shaded; /* 1: the last trace had occluders (lit, open hold it) */
    /* the light in the water the objects are lit from: nlayers + 1 slices
     * of layer_n^2 texels (n / 2, at least 8) over the pool, bottom first:
     * slice 0 the floor's before any shadow (map resampled), slice k the
     * light crossing the plane depth k / (nlayers + 1) over the floor, in
     * map's unit. NULL when no layers were asked for */
    int nlayers, layer_n;
    float *layers;
} ms_caustics;

/* Rows of each wall strip for d (0 when d->depth is 0): as tall as
 * flat water's refracted sun spreads the rays of two texels, at least 4. */
int ms_caustics_wall_rows(const ms_caustics_desc *d);
/* Traces light through the surface h (heights above floor_z over grid g)
 * to the floor by Snell's law: rays on a lattice over the pool, an integer
 * number per texel and axis, at least as fine as the field's cells, each
 * carrying the light of the patch of surface it starts from, times
 * Schlick's transmission over the flat water's; the rays' light is splat bilinearly onto the floor, blurred by
 * [1 2 1]/4, and scaled so flat water gives 1 everywhere. Rays that leave
 * the floor's square meet a wall (d->depth > 0): they are splat there, in
 * c->walls, the same way. Occluders (d->occluders) shade the floor where
 * flat water's refracted sun meets them first (c->lit). */
ms_status ms_caustics_trace(ms_caustics *c, const ms_caustics_desc *d, const float *h,
                            const ms_grid *g);
void ms_caustics_free(ms_caustics *c);

/* ---- PNG ---------------------------------------------------------------- */

/* Writes w x h RGBA8 pixels, top row first, to path (through "path.tmp"
 * and a rename). */
ms_status ms_png_write_rgba(const char *path, const unsigned char *rgba, int w, int h);

/* ---- the renderer ------------------------------------------------------- */

/* Depth (m) below which the liquid counts as dry: the surface is cut along
 * this depth's contour (linear between the mesh's vertices) and nothing of
 * it is drawn where it is shallower, so dry floor is seen directly instead
 * of through a zero-depth sheet. Above the wave field's residual
 * ripples on a dry floor (0.6 mm in data/scenes/glass.json at frame 60). */
#define MS_RENDER_DRY_DEPTH 1e-3f

typedef struct ms_gl ms_gl; /* the GL side (gl_*.c) */

/* The liquid inside the scene's container (glass_fill.c): the
 * container's cavity found once from its signed distance (per angle about
 * its local z axis: where the inner wall starts and the outer wall ends,
 * and the cavity's floor), then each frame, for display only, the field
 * filled to the inner wall at the liquid's level, the mesh cut along the
 * inner wall, and the side of the liquid column as a vertical wall. */
#define MS_CAVITY_ANGLES 128
#define MS_CAVITY_SEGMENTS 128
#define MS_CAVITY_SIDE_ROWS 6
#define MS_CAVITY_SIDE_FLOATS (MS_CAVITY_SEGMENTS * MS_CAVITY_SIDE_ROWS * 6 * 6)
typedef struct ms_render_cavity {
    const void *probed;            /* the object the tables below are for */
    int found;                     /* 1: the container has a cavity about its axis */
    float r_in[MS_CAVITY_ANGLES];  /* m, local: the inner wall per angle */
    float r_out[MS_CAVITY_ANGLES]; /* m, local: the outer wall's outside */
    float z_probe, z_floor;        /* m, local: where the radii were taken; the cavity's floor */
    /* this frame (set by ms_render_cavity_fill, cleared after the draw) */
    int active;           /* 1: the field drawn is filled and the mesh is cut */
    float pos[3], rot[9]; /* the container's pose (local -> world) */
    float tail;           /* m: how far past the inner wall the field may be wet */
    float plane_z;        /* m, world: the plane the cavity is taken on (the level) */
    const float *field;   /* the filled field (r->fill) over grid */
    ms_grid grid;
    float side[MS_CAVITY_SIDE_FLOATS];      /* the column's side: x, y, z, normal */
    float side_draw[MS_CAVITY_SIDE_FLOATS]; /* the same with the normals it is shaded with */
    int side_verts;
    unsigned char *flags; /* the mesh cut's scratch */
    size_t flags_cap;
} ms_render_cavity;

/* An obstacle or the container drawn as a mesh (objects.c). */
typedef struct ms_render_object {
    const struct ms_scene_shape *spec; /* the scene's, not owned */
    ms_shape *shape;                   /* the renderer's own instance, placed each frame */
    float *local;                      /* nverts * 6: position, normal in the shape's frame */
    int nverts;                        /* 0: not drawn (unbounded) */
    float color[3];                    /* linear RGB */
} ms_render_object;

/* World vertices of the objects: position, normal, colour. */
#define MS_RENDER_OBJECT_STRIDE 9

struct ms_renderer {
    ms_renderer_desc desc; /* checked; strings below are owned copies */
    char *shader_name, *shader_params, *cubemap_path, *backend_name;
    float light_to[3]; /* unit vector towards the light */
    float rim_z;       /* m */
    float tile_size;   /* m, resolved */
    ms_shader_instance shader;
    unsigned passes;    /* MS_SHADER_NEEDS_* that run */
    int trace_caustics; /* 1: the caustics pass runs */
    ms_caustics caustics;
    ms_render_disc *discs; /* floating things, ms_renderer_set_discs */
    int ndiscs, discs_cap;
    int discs_changed;     /* the GL side must rebuild their vertices (and the boat's) */
    int nleaves;           /* the first nleaves discs are the sim's floaters: drawn as leaves */
    int has_boat;          /* the scene's boat is drawn as a hull (draw_sim.c) */
    float boat_pos[3];     /* m, world: its centre at the water line */
    float boat_heading[2]; /* unit, x-y: where its bow points */
    float boat_radius;     /* m: half its length */
    float *spray;          /* 3 * nspray: droplets, ms_renderer_set_spray */
    int nspray, spray_cap;
    float spray_radius; /* m */
    float *foam;        /* foam_grid's cells, ms_renderer_set_foam */
    size_t foam_cap;    /* floats */
    ms_grid foam_grid;
    int has_foam;
    int foam_changed;                    /* the GL side must upload it */
    const struct ms_scene *object_scene; /* the scene objects were meshed for */
    ms_render_object *objects;
    int nobjects;
    float *object_verts; /* object_nverts * MS_RENDER_OBJECT_STRIDE, world */
    int object_nverts;
    int object_glass;   /* object_verts from here on are the container's: see-through */
    float *display;     /* the field drawn by ms_renderer_draw (draw_sim.c) and scratch */
    size_t display_cap; /* floats */
    float *fill;        /* the field filled to the container's inner wall (glass_fill.c) */
    size_t fill_cap;    /* floats */
    ms_render_cavity cavity;
    unsigned char *pixels; /* width * height * 4, top row first */
    int have_frame;
    ms_render_stats stats;
    ms_gl *gl;
    int in_context; /* 1: the caller's GL context (context_current.c) */
};

/* objects.c: the obstacles and container of scene sc (NULL: none) posed
 * at time t as sim has them (NULL: as the scene has them) into
 * object_verts; meshed when sc is new. */
ms_status ms_render_objects_update(ms_renderer *r, const struct ms_scene *sc, const ms_sim *sim,
                                   double t);
void ms_render_objects_free(ms_renderer *r);

/* glass_fill.c. For the frame at hand: when the scene's container holds
 * liquid in a cavity, *out is h (over g, heights above the floor) with the
 * liquid's surface carried to the inner wall (coarse_dx: the SPH cell, m,
 * 0 if unknown) and cavity.active is set; else *out = h. */
ms_status ms_render_cavity_fill(ms_renderer *r, const float *h, const ms_grid *g, float coarse_dx,
                                const float **out);
/* The mesh vertices (ms_mesh_build's, nx x ny) cut along the inner wall:
 * those just outside it moved onto it, those over the wall and beyond it
 * sunk under the floor (the dry clip removes them). */
ms_status ms_render_cavity_cut(ms_renderer *r, float *vertices, int nx, int ny);
void ms_render_cavity_free(ms_renderer *r);

/* render.c: *buf holds at least need floats (grown, old contents dropped,
 * never shrunk; *cap counts them); MS_ERR_OUT_OF_MEMORY naming `what`. */
ms_status ms_render_reserve(float **buf, size_t *cap, size_t need, const char *what);

#if MS_HAVE_GL
/* gl_renderer.c: make the GL side for r (desc checked, shader and passes
 * set); on failure r->gl stays NULL and the error is set. */
ms_status ms_gl_create(ms_renderer *r, const ms_cubemap *sky);
void ms_gl_destroy(ms_gl *gl);
/* gl_renderer.c: the environment drawn again for r->desc's new camera. */
ms_status ms_gl_camera_moved(ms_renderer *r);
/* gl_frame.c: one frame of h over g into r->pixels. */
ms_status ms_gl_draw(ms_renderer *r, const float *h, const ms_grid *g, double time);
#endif

#endif /* MS_RENDER_INTERNAL_H */
