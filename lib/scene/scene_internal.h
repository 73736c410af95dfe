/* The parsed scene, as the sim (lib/sim) and the renderer (lib/render)
 * read it. Internal: never installed. Every value here has been checked
 * (type, finite, range) by the parser, with the defaults of
 * data/scenes/README.md filled in for absent keys. A section that is absent
 * has its has_* flag 0 and costs nothing.
 */
#ifndef MS_SCENE_INTERNAL_H
#define MS_SCENE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "modesplit/scene.h"
#include "modesplit/surface.h"
#include "modesplit/volume.h"

#define MS_SCENE_MAX_OBSTACLES 64
#define MS_SCENE_MAX_PATH_POINTS 4096
#define MS_SCENE_MAX_FILLS 64
#define MS_SCENE_MAX_DROPS 4096
#define MS_SCENE_MAX_FLOATERS 100000

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

typedef struct ms_scene_render {
    int width, height; /* pixels */
    char *shader;      /* shader plugin name */
    char *cubemap;     /* "builtin" or a path resolved against the scene's directory */
    int has_caustics;
    int caustics_resolution;        /* light map texels per side */
    float caustics_intensity;       /* 1 = physical */
    float light_dir[3];             /* unit vector, towards where the light goes */
    float eye[3], target[3], up[3]; /* m, camera */
    float fov;                      /* degrees, vertical */
    int backend;                    /* index in ms_scene_render_backends: the GL context */
} ms_scene_render;

/* render.backend's names: "auto", "osmesa", "egl" (NULL-terminated). */
extern const char *const ms_scene_render_backends[];

struct ms_scene {
    char *text; /* the JSON text, NUL-terminated */
    size_t text_len;
    char *path; /* "" when parsed from memory */
    char *name;

    double duration; /* s */
    float frame_dt;  /* s */
    uint64_t seed;
    int threads;                        /* 1 or 2 */
    float domain_min[3], domain_max[3]; /* m */

    /* volume: SPH (absent: no particles, no SPH work) */
    int has_volume;
    struct {
        float spacing;          /* m */
        float smoothing_length; /* m */
        float rest_density;     /* kg/m^3 */
        float gas_constant;     /* m^2/s^2 */
        float viscosity;        /* Pa s */
        float gravity[3];       /* m/s^2 */
        ms_pressure pressure;
        int max_particles; /* 0 = what the fill boxes need */
        /* NAN / 0: the solver's default */
        float sound_speed; /* m/s, Tait's c0 */
        float courant;     /* CFL number */
        int max_substeps;
        int threads;         /* threads inside the SPH step */
        int smooth_steps;    /* eq. 18 smoothing passes (-1 = default) */
        float smooth_energy; /* J/kg, eq. 18 threshold */
        /* MS_PRESSURE_DFSPH's stop rule and caps (NAN / -1: the solver's) */
        float max_density_error;    /* average predicted compression */
        float max_divergence_error; /* average dt (D rho/Dt) / rho0 */
        int max_density_iterations;
        int max_divergence_iterations;
    } volume;
    int nfill;
    float fill_lo[MS_SCENE_MAX_FILLS][3], fill_hi[MS_SCENE_MAX_FILLS][3]; /* m */
    int field_nx, field_ny; /* X_SPH x Y_SPH (eq. 20); 0 = derived */

    /* surface: wave equation (absent: the SPH field alone is the surface) */
    int has_surface;
    struct {
        int nx, ny;       /* X_WE x Y_WE */
        float dx;         /* m, square cells over the domain's x-y extent */
        float wave_speed; /* m/s */
        float damping;    /* (0, 1], velocity kept per second */
        ms_boundary boundary;
        int max_substeps;
        ms_surface_model model; /* wave (eq. 2) or dispersive */
    } surface;
    float level; /* m above domain_min z: still water when there is no volume */

    /* coupling (3.4, 3.5) */
    int n_time; /* eq. 19; 0 = derived from the CFL bound */
    float couple_surface_from_volume, couple_volume_from_surface;

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

    int has_render;
    ms_scene_render render;

    unsigned output_fields; /* MS_FIELD_* */
    int output_every;
    int output_deflate;          /* 0..9 */
    int output_checkpoint_every; /* written frames per checkpoint, 0 = none */
};

#endif /* MS_SCENE_INTERNAL_H */
