/* The parsed scene, as the sim (lib/sim) and the renderer (lib/render)
 * read it. Internal: never installed. Every value here has been checked:
 * its type by the parser, its range by the part whose desc holds it (the
 * scene's own keys by the parser), with the defaults of the descs (and
 * data/scenes/README.md) filled in for absent keys. A section that is absent
 * has its has_* flag 0 and costs nothing.
 */
#ifndef MS_SCENE_INTERNAL_H
#define MS_SCENE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "modesplit/render.h"
#include "modesplit/scene.h"
#include "modesplit/sim.h"
#include "modesplit/surface.h"
#include "modesplit/volume.h"

#define MS_SCENE_MAX_OBSTACLES 64
#define MS_SCENE_MAX_PATH_POINTS 4096
#define MS_SCENE_MAX_FILLS 64
#define MS_SCENE_MAX_DROPS 4096
#define MS_SCENE_MAX_FLOATERS 100000
/* the largest spray budget a scene may ask for: 2^18 particles of 28
 * bytes (7 floats), 7 MiB, and a frame's ballistic pass over them stays
 * well below the SPH step of the scenes' 2000 to 32000 particles */
#define MS_SCENE_MAX_SPRAY 262144

/* A scripted motion along a polyline at constant speed (m/s), starting at
 * time `start` (s). dim = 2 (x, y) or 3 (x, y, z); npoints = 0: no path. */
typedef struct ms_scene_motion {
    int npoints;
    int dim;
    float *points; /* npoints * dim floats, m */
    float speed;   /* m/s */
    int loop;      /* 1: back to the first point and round again */
    float start;   /* s */
} ms_scene_motion;

/* Where a path puts its mover at time t (s): position (m) and velocity
 * (m/s), dim components each. Before `start` it waits at the first point;
 * a path that does not loop stops at its last point. */
void ms_scene_motion_eval(const ms_scene_motion *p, double t, float *pos, float *vel);

/* A collision shape of the scene (obstacle or container). */
typedef struct ms_scene_shape {
    char *kind;           /* shape plugin name */
    char *params_json;    /* its parameters as JSON object text ("{}" if none) */
    float position[3];    /* m */
    float velocity[3];    /* m/s, used when there is no path */
    float orientation[4]; /* quaternion (w, x, y, z) at t = 0, not normalised */
    float spin[3];        /* rad/s, world axes: it turns at this rate */
    ms_scene_motion path;
    int surface_mask; /* 1: its footprint at the water level blocks waves */
} ms_scene_shape;

typedef struct ms_scene_drop {
    float time;      /* s */
    float x, y;      /* m */
    float radius;    /* m */
    float amplitude; /* m */
} ms_scene_drop;

struct ms_scene {
    char *text; /* the JSON text, NUL-terminated */
    size_t text_len;
    char *path; /* "" when parsed from memory */
    char *name;

    double duration; /* s */
    float frame_dt;  /* s */
    uint64_t seed;
    float domain_min[3], domain_max[3]; /* m */

    /* The parts' descs, each started from its *_desc_default() and set by
     * the keys of its section; each part's desc check owns the defaults'
     * ranges (sections.c names a refusal at the key). */
    /* volume: SPH (absent: no particles, no SPH work) */
    int has_volume;
    ms_volume_desc volume;
    int nfill;
    float settle; /* s of ms_volume_settle after the fills; 0: the lattice as filled */
    float fill_lo[MS_SCENE_MAX_FILLS][3], fill_hi[MS_SCENE_MAX_FILLS][3]; /* m */

    /* surface: wave equation (absent: the SPH field alone is the surface) */
    int has_surface;
    ms_surface_desc surface;
    float level; /* m above domain_min z: still water when there is no volume */

    /* the coupler (threads; coupling 3.4, 3.5; volume.field): volume and
     * surface point at the descs above, NULL when the section is absent */
    ms_sim_desc sim;

    int nobstacles;
    ms_scene_shape *obstacles;

    /* effects */
    int has_rain;
    ms_rain rain;
    int has_boat;
    ms_scene_motion boat_path;
    float boat_radius, boat_depth; /* m */
    int ndrops;
    ms_scene_drop *drops;
    int has_floaters;
    int nfloaters;
    float *floater_xy;   /* 2 * nfloaters, m, start positions */
    float floater_drag;  /* 1/s: how fast a floater takes the flow's velocity */
    float floater_slope; /* 1: slides down wave slopes under full gravity */
    int has_drag;
    ms_scene_motion drag_path;
    float drag_radius;   /* m */
    float drag_depth;    /* m below the surface */
    float drag_strength; /* 1/s: how fast the water takes the pointer's velocity */
    int has_container;
    ms_scene_shape container;
    /* spray and foam (lib/sim/spray.c): emission after Ihmsen et al. 2012,
     * n = phi_k (k_ta phi_ta + k_wc phi_wc) dt per particle, each phi a
     * clamped ramp over [lo, hi] */
    int has_spray;
    int spray_budget;           /* spray particles alive at most */
    float spray_kinetic[2];     /* J/kg: kinetic energy ramp */
    float spray_trapped_air[2]; /* m/s: speed relative to the cell's surface flow */
    float spray_wave_crest[2];  /* m/s: upward speed of a surface particle */
    float spray_rate[2];        /* 1/s: k_ta, k_wc */
    float foam_lifetime;        /* s: foam fades as exp(-t / lifetime) */
    float foam_deposit;         /* foam cover a landing or breaking particle adds to its cell */

    /* the renderer's desc (render section over ms_renderer_desc_default(),
     * the pool from the domain and the level); always made, so a scene
     * without a render section still gives a camera and a pool */
    int has_render;
    ms_renderer_desc render;
    char *render_shader, *render_cubemap; /* owned: render.shader, .cubemap point here */
    char *render_shader_params;           /* owned: render.shader_params points here */

    unsigned output_fields; /* MS_FIELD_* */
    int output_every;
    int output_deflate;          /* 0..9 */
    int output_checkpoint_every; /* written frames per checkpoint, 0 = none */
};

#endif /* MS_SCENE_INTERNAL_H */
