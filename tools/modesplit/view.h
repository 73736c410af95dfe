/* `modesplit view`: the interactive window of the paper's Fig. 1.
 *
 * cmd_view.c     the window (SDL2 + its OpenGL context), the loop, the
 *                renderer drawing into the window (ms_renderer_create_in_context)
 * view_input.c   what a key, a button or the pointer does to the sim and
 *                the camera (independent of SDL: events by name)
 * view_log.c     the input log: written by --record-input, replayed by --script
 * view_camera.c  the orbit camera and the pointer's ray onto the water
 * view_stats.c   the overlay's text (frames/s, ms per stage from ms_sim_stats)
 * view_overlay.c the overlay drawn with GL: a built-in 8 x 15 bitmap font
 * view_png.c     the window's pixels as PNG (F12, --record)
 *
 * The SDL-free parts are also linked into tests/test_view.c. */
#ifndef MS_TOOL_VIEW_H
#define MS_TOOL_VIEW_H

#include <stddef.h>
#include <stdio.h>

#include "modesplit/modesplit.h"

/* ---- events (view_log.c) ---- */

typedef enum {
    VIEW_KEY_DOWN,
    VIEW_KEY_UP,
    VIEW_BUTTON_DOWN,
    VIEW_BUTTON_UP,
    VIEW_MOTION,
    VIEW_WHEEL,
    VIEW_QUIT,
    VIEW_RESIZE,
    VIEW_LOSE_CONTEXT
} view_event_type;

/* One input event, as the loop sees it: keys by SDL's key name ("R",
 * "Space", "Left", "F12"), the pointer in window fractions (0..1 from the
 * top left) so a log replays at any window size. */
typedef struct view_event {
    long frame; /* sim frames finished when it happened */
    view_event_type type;
    char key[32]; /* KEY_*: the key's name */
    int button;   /* BUTTON_*: 1 left, 2 middle, 3 right */
    int shift;    /* BUTTON_DOWN: shift held */
    float x, y;   /* BUTTON_*, MOTION: window fractions */
    float wheel;  /* WHEEL: notches, + = away from the user */
    int w, h;     /* RESIZE: pixels */
} view_event;

#define VIEW_LOG_HEADER "# modesplit view input log 1"
/* Largest input log --script reads (a line is at most 254 characters: about
 * 250 000 events). */
#define VIEW_LOG_MAX_BYTES (64 << 20)
/* One line per event: "FRAME key-down NAME", "FRAME button-down B X Y
 * SHIFT", "FRAME motion X Y", "FRAME wheel D", "FRAME quit", "FRAME resize
 * W H", "FRAME lose-context". */
int view_log_write(FILE *f, const view_event *e);
typedef struct view_script {
    view_event *ev;
    int n, next;
} view_script;
/* Reads a log; 0 on success, else -1 with a sentence naming path:line in
 * err. Frames must not decrease. */
int view_script_load(const char *path, view_script *s, char *err, size_t errlen);
void view_script_free(view_script *s);

/* ---- camera (view_camera.c) ---- */

typedef struct view_camera {
    float target[3];  /* m, the point orbited */
    float yaw, pitch; /* rad: direction from the target to the eye */
    float dist;       /* m */
    float fov;        /* degrees, vertical */
    float min_dist, max_dist;
} view_camera;

void view_camera_from(view_camera *c, const float eye[3], const float target[3], float fov);
void view_camera_eye(const view_camera *c, float eye[3]);
/* Right-drag by (dx, dy) window fractions: turn round the target. */
void view_camera_orbit(view_camera *c, float dx, float dy);
/* Wheel notches: + comes closer. */
void view_camera_zoom(view_camera *c, float notches);
/* Middle-drag: move the target with the pointer. */
void view_camera_pan(view_camera *c, float dx, float dy, float aspect);
/* The world point (x, y) where the ray through window fraction (fx, fy)
 * meets the plane z = plane_z; 0 if it does not (looks away). */
int view_camera_unproject(const view_camera *c, float aspect, float fx, float fy, float plane_z,
                          float out[2]);

/* ---- the overlay's text (view_stats.c) ---- */

typedef struct view_overlay_info {
    const char *scene;
    long frame;
    double time; /* s, sim time */
    double fps;  /* frames/s stepped, wall clock */
    int paced;   /* 1: at frame_dt, 0: as fast as it can */
    int paused;
    double render_ms; /* the renderer's last draw */
    int particles, threads;
    const char *shader;
    int caustics, rain; /* -1: the scene cannot have it */
} view_overlay_info;

/* The overlay's lines into buf ('\n' between): the ms per stage of the
 * last frame are the differences of two ms_sim_stats (before and after its
 * ms_sim_step), N_time from the second. Returns the number of lines. */
int view_overlay_text(const view_overlay_info *in, const ms_stats *before, const ms_stats *after,
                      char *buf, size_t size);
extern const char view_help_text[];

/* ---- what input does (view_input.c) ---- */

enum {
    VIEW_HELD_W,
    VIEW_HELD_A,
    VIEW_HELD_S,
    VIEW_HELD_D,
    VIEW_HELD_Q,
    VIEW_HELD_E,
    VIEW_HELD_UP,
    VIEW_HELD_DOWN,
    VIEW_HELD_LEFT,
    VIEW_HELD_RIGHT,
    VIEW_HELD_N
};

typedef struct view_state {
    ms_sim *sim;
    float frame_dt;         /* s */
    ms_renderer_desc rdesc; /* the renderer as it should be: size, shader, caustics */
    const char *scene_shader, *scene_shader_params;
    view_camera cam;
    int w, h; /* window pixels */
    /* requests for the loop */
    int camera_moved, renderer_stale, screenshot, lose_context, quit;
    int paused, step_once, paced, help;
    /* what the scene has */
    int has_volume, has_surface, has_boat, has_container;
    int rain; /* on/off; -1 without a surface */
    /* the pointer */
    int button[4];      /* held: 1 left, 2 middle, 3 right */
    float px, py;       /* window fractions */
    int dragging;       /* left held on the water */
    float drag_prev[2]; /* m, the drag's point at the last step */
    int drag_moved;     /* drag_prev set */
    int disturber;      /* wave-only drag: the surface disturber, -1 none */
    int held[VIEW_HELD_N];
    float cont_pos[3], cont_quat[4]; /* container: where the keys put it */
    int cont_known;
    int cont_active;  /* W A S D Q E were held at the last step */
    float tilt;       /* rad, about the camera's right axis */
    int boat_steered; /* arrows were held at the last step */
    char status[96];  /* the last action, shown for a while */
} view_state;

/* The state for a sim and the renderer's desc of its scene. */
void view_state_init(view_state *v, ms_sim *sim, const ms_renderer_desc *rd, float frame_dt);
/* An event: flags, the camera, the pointer, held keys; drops and rain act
 * on the sim at once. Returns 0, or -1 after a library error (printed). */
int view_apply_event(view_state *v, const view_event *e);
/* Before each step: the drag, the boat, the container from what is held. */
int view_before_step(view_state *v);

/* ---- PNG (view_png.c) ---- */
/* w x h RGBA8, top row first; 0 or -1 (errno tells). */
int view_png_write(const char *path, const unsigned char *rgba, int w, int h);

#endif /* MS_TOOL_VIEW_H */
