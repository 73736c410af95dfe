/* The GL side of the renderer (compiled only with OSMesa or EGL): what the
 * gl_*.c files share. One context per renderer (OSMesa or EGL, behind
 * ms_gl_backend), made current for each call and released after it;
 * drawing goes to an sRGB framebuffer object of the image's size, read
 * back at the end of the frame. */
#ifndef MS_RENDER_GL_INTERNAL_H
#define MS_RENDER_GL_INTERNAL_H

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include "render/render_internal.h"

/* Column-major 4 x 4 matrices, as OpenGL takes them. */
void ms_mat4_look_at(const float eye[3], const float target[3], const float up[3], float m[16]);
void ms_mat4_perspective(float fov_y_deg, float aspect, float znear, float zfar, float m[16]);
/* A view from eye along the basis right, up, forward (world vectors;
 * the eye looks along forward). */
void ms_mat4_basis_view(const float eye[3], const float right[3], const float up[3],
                        const float forward[3], float m[16]);

typedef struct ms_gl_program {
    GLuint prog;
} ms_gl_program;

/* A program from GLSL sources; `what` names it in the error sentence, which
 * carries the compiler's or linker's log. MS_ERR_PLUGIN on failure. */
ms_status ms_gl_program_build(const char *what, const char *vs, const char *fs, ms_gl_program *out);
/* Delete a program (a borrowed window context outlives the renderer, so
 * the renderer deletes what it made there). */
void ms_gl_program_free(ms_gl_program *p);
/* The table a shader plugin sets its uniforms through (bound program). */
ms_shader_uniforms ms_gl_uniform_table(ms_gl_program *p);

/* Mesa keeps some allocations for the life of the process (OSMesa's
 * framebuffers, EGL's display state): under AddressSanitizer the leak
 * checker looks away while Mesa makes them. */
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define MS_MESA_LEAKS_BEGIN() __lsan_disable()
#define MS_MESA_LEAKS_END() __lsan_enable()
#else
#define MS_MESA_LEAKS_BEGIN() ((void)0)
#define MS_MESA_LEAKS_END() ((void)0)
#endif

/* The GL context (gl_context.c) and its backends: one file each
 * (gl_context_osmesa.c, gl_context_egl.c); another (a window's context)
 * slots in with the same four calls. */
typedef struct ms_gl_context ms_gl_context;
typedef struct ms_gl_backend {
    const char *name; /* the render.backend value that picks it */
    /* makes c->impl; MS_ERR_UNSUPPORTED with a sentence when it cannot */
    ms_status (*create)(ms_gl_context *c);
    ms_status (*begin)(ms_gl_context *c); /* current in this thread */
    void (*end)(ms_gl_context *c);        /* released */
    void (*destroy)(ms_gl_context *c);
} ms_gl_backend;
#if MS_HAVE_OSMESA
extern const ms_gl_backend ms_gl_backend_osmesa;
#endif
#if MS_HAVE_EGL
extern const ms_gl_backend ms_gl_backend_egl;
#endif

struct ms_gl_context {
    const ms_gl_backend *backend; /* NULL until created */
    void *impl;                   /* the backend's */
    int borrowed;                 /* 1: the caller's current context (context_current.c) */
    GLuint target_fbo;            /* borrowed: the framebuffer a frame is copied to */
};

/* The backends of this build, as a list for sentences. */
const char *ms_gl_backends_built(void);
/* want: "auto" (or NULL: the built backends in turn, OSMesa first),
 * "osmesa" or "egl"; MS_ERR_UNSUPPORTED naming why when none can. */
ms_status ms_gl_context_create(ms_gl_context *c, const char *want);
/* Makes c current in this thread; MS_ERR_UNSUPPORTED if the backend refuses. */
ms_status ms_gl_context_begin(ms_gl_context *c);
/* Releases the thread's current context. */
void ms_gl_context_end(void);
void ms_gl_context_destroy(ms_gl_context *c);

/* context_current.c: a context borrowed from the caller
 * (ms_renderer_create_in_context). borrow_requested: the renderer being
 * created asks for it; context_borrow: c becomes the caller's context
 * (a backend of its own: begin remembers where frames go, end leaves it
 * current); present: the frame into the caller's framebuffer; delete_objects:
 * the renderer's GL objects (a borrowed context outlives the renderer). */
int ms_gl_borrow_requested(void);
ms_status ms_gl_context_borrow(ms_gl_context *c);

void ms_gl_present(ms_renderer *r);
void ms_gl_delete_objects(ms_gl *gl);

/* Floats per pool vertex: position 3, normal 3, texture coordinate 2,
 * colour 3. */
#define MS_POOL_STRIDE 11

struct ms_gl {
    ms_gl_context context;
    GLuint fbo, color_rb, depth_rb; /* the image */
    GLuint sky_tex;                 /* the sky cubemap */
    GLuint env_tex;                 /* ms_env: the sky, or the sky with the pool (refraction) */
    int env_size;
    GLuint tiles_tex;     /* the tile pattern */
    GLuint caustics_tex;  /* ms_caustics: the light map, or 1 x 1 of 1 */
    int caustics_n;       /* its size as uploaded */
    ms_gl_program liquid; /* the shader plugin's */
    int liquid_clips;     /* 1: its vertex program writes gl_ClipVertex (dry cells cut) */
    ms_gl_program pool;   /* tiles: floor, walls, deck */
    ms_gl_program sky;    /* the background */
    GLuint pool_vbo;
    int pool_count;       /* vertices (triangles x 3) */
    int pool_apron_count; /* the same with the apron under water (gl_pool.c) */
    GLuint discs_vbo;     /* the floating discs (ms_renderer_set_discs) */
    int discs_count;      /* their vertices */
    int glass_first;      /* discs_vbo from here on: the container, blended (objects.c) */
    GLuint mesh_vbo, mesh_ibo;
    int mesh_nx, mesh_ny;     /* the grid the index buffer is for */
    float *vertices;          /* mesh vertices, CPU side */
    size_t vertices_cap;      /* floats */
    float *coarse;            /* the field averaged to the mesh's step */
    size_t coarse_cap;        /* floats */
    GLuint normal_tex;        /* ms_normal_map: the full field's gradient (RG32F) */
    int normal_nx, normal_ny; /* its size as uploaded */
    ms_grid normal_field;     /* the grid it covers (ms_field in the shaders) */
    float *gradients;         /* its texels, CPU side */
    size_t gradients_cap;     /* floats */
    /* objects in the environment (gl_env.c): env_static is the
     * pool and the sky as ms_gl_env_create draws them; env_live a copy
     * with the boat and the obstacles drawn in each frame (ms_env is
     * env_live while there are objects, else env_static) */
    GLuint env_static, env_live;
    GLuint env_fbo, env_depth;           /* the per-frame pass into env_live */
    int env_rect[2][6][4];               /* per half, face: the level-0 texels the objects cover */
    int env_live_fresh;                  /* 0: env_live must be copied from env_static first */
    int env_copy_checked;                /* 1: glCopyImageSubData exists, -1: not, 0: not asked */
    unsigned long long env_objects_hash; /* what the objects in env_live were drawn from */
    int objects_first;       /* discs_vbo from here on: the boat, the obstacles, the glass */
    ms_gl_program glass;     /* gl_glass.c */
    GLuint walls_tex;        /* ms_caustics_walls (gl_walls.c) */
    int walls_n, walls_rows; /* its size as uploaded: n x 4 rows */
    GLuint open_tex;         /* the light in the water, in slices (gl_walls.c) */
    int open_n, open_slices; /* its size as uploaded: n x slices n */
    GLuint side_vbo;         /* the liquid's side in the glass (gl_glass.c) */
    GLuint foam_tex;         /* ms_foam (gl_spray.c): 1 x 1 of 0 until foam is set */
    int foam_nx, foam_ny;    /* its size as uploaded */
    ms_gl_program spray;     /* the droplets (gl_spray.c), made at the first */
    GLuint spray_vbo;
};

/* gl_pool.c: the pool's geometry into gl->pool_vbo; the pool program. */
ms_status ms_gl_pool_create(ms_renderer *r);
/* Draws the pool with the current matrices; sun_under = 0 lights the parts
 * under still water by the sky only; keep = +1 draws only what is above
 * the still water, -1 only what is below (with an apron of floor around
 * the pool), 0 all, and then the floating discs too. */
void ms_gl_pool_draw(const ms_renderer *r, float sun_under, float keep);
/* The discs' triangles into gl->discs_vbo (after ms_renderer_set_discs). */
ms_status ms_gl_discs_upload(ms_renderer *r);
/* gl_sky.c: the sky program, the sky cubemap texture from faces. */
ms_status ms_gl_sky_create(ms_renderer *r, const ms_cubemap *sky);
/* Draws the sky behind everything for a camera looking along forward
 * with the given right / up vectors scaled to the view's half-extents at
 * unit distance. */
void ms_gl_sky_draw(const ms_renderer *r, const float forward[3], const float right[3],
                    const float up[3]);
/* gl_env.c: ms_env for a shader with reflection or refraction: the sky
 * and the pool, split by the water plane and seen from the eye's mirror
 * and refracted images. */
/* Where the environment's reflected (mirror) and refracted (virt) halves
 * are drawn from: the eye's mirror image under the still water and its
 * virtual image above it (gl_env.c's comment). */
void ms_gl_env_viewpoints(const ms_renderer_desc *d, float mirror[3], float virt[3]);
ms_status ms_gl_env_create(ms_renderer *r);
/* gl_env.c: the boat and the obstacles (from objects_first in discs_vbo)
 * into ms_env: their parts above the water into the reflection half,
 * under it into the refraction half, redrawn only where they were or are. */
ms_status ms_gl_env_objects(ms_renderer *r);
/* gl_pool.c: the boat and the obstacles (discs_vbo from objects_first),
 * then the glass, lit and clipped as ms_gl_pool_draw's sun_under and keep
 * say, seen from eye; for the environment's pass. */
void ms_gl_objects_draw(const ms_renderer *r, const float eye[3], float sun_under, float keep);
/* gl_glass.c: the glass program (made once, when a glass is drawn), and
 * the glass (discs_vbo from glass_first) drawn with it, seen from eye,
 * blended over what is drawn, writing no depth; keep as ms_gl_pool_draw. */
ms_status ms_gl_glass_create(ms_renderer *r);
/* gl_walls.c: the caustics on the pool's walls (r->caustics.walls) into
 * their texture after a trace; bound with their uniforms for the liquid. */
ms_status ms_gl_walls_upload(ms_renderer *r);
/* gl_walls.c: the light in the water after a trace with layers, as one
 * texture of layer_n^2 slices stacked along t (ms_caustics.layers: the
 * floor before the objects' shadow, then the planes above it);
 * the objects under the water take their light from it (gl_pool.c).
 * ms_gl_open_texture gives it and its slices (the floor map alone, 1, when
 * no layers were traced). */
ms_status ms_gl_open_upload(ms_renderer *r);
GLuint ms_gl_open_texture(const ms_renderer *r, int *slices);
void ms_gl_walls_bind(const ms_renderer *r, const ms_shader_uniforms *u);
void ms_gl_glass_draw(const ms_renderer *r, const float eye[3], float keep);
/* gl_glass.c: the side of the liquid in the glass (r->cavity), drawn with
 * the liquid's program and its vertex arrays enabled (draw_liquid). */
void ms_gl_liquid_side_draw(ms_renderer *r, const ms_shader_uniforms *u);
/* gl_renderer.c: after r->desc's camera changed: ms_env drawn again. */
ms_status ms_gl_camera_moved(ms_renderer *r);

/* gl_spray.c: the foam cover into ms_foam (made at the first call, 1 x 1
 * of 0 without foam), bound for the liquid's shader with ms_foam_field
 * and ms_foam_on; the spray drawn as lit droplets with the view matrix
 * view (column-major) current. */
ms_status ms_gl_foam_upload(ms_renderer *r);
void ms_gl_foam_bind(const ms_renderer *r, const ms_shader_uniforms *u);
void ms_gl_spray_draw(ms_renderer *r, const float view[16]);

/* A sentence for the first pending GL error, "" if none (clears them). */
ms_status ms_gl_check(const char *doing);

#endif /* MS_RENDER_GL_INTERNAL_H */
