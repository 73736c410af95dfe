/* What the user's input does, independent of SDL (events by key name and
 * window fractions, so a replayed log does the same): left-drag pulls the
 * water along (ms_sim_drag: the volume flows, its field moves the waves,
 * as in Fig. 1; a scene without a volume gets a moving surface disturber),
 * shift-click drops a drop, the keys switch effects, steer the boat and
 * move and tilt the container (glass.json: tilt it to pour). */
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tool.h"
#include "view.h"

static const char *const shaders[4] = {"water", "milk", "oil", "honey"};
static const char *const held_keys[VIEW_HELD_N] = {"W", "A",  "S",    "D",    "Q",
                                                   "E", "Up", "Down", "Left", "Right"};

static int fail(const char *what)
{
    tool_error("view: %s: %s", what, ms_last_error());
    return -1;
}

void view_state_init(view_state *v, ms_sim *sim, const ms_renderer_desc *rd, float frame_dt)
{
    memset(v, 0, sizeof *v);
    v->sim = sim;
    v->frame_dt = frame_dt;
    v->rdesc = *rd;
    v->scene_shader = rd->shader;
    v->scene_shader_params = rd->shader_params;
    v->w = rd->width;
    v->h = rd->height;
    view_camera_from(&v->cam, rd->eye, rd->target, rd->fov);
    v->paced = 1;
    v->disturber = -1;
    v->has_volume = ms_sim_volume(sim) != NULL;
    v->has_surface = ms_sim_surface(sim) != NULL;
    float p[3], q[4];
    v->has_boat = ms_sim_boat(sim, p) == MS_OK;
    v->has_container = ms_sim_container_pose(sim, p, q) == MS_OK;
    v->rain = -1;
    if (v->has_surface) {
        /* the scene's rain falls from the start: effects.rain.rate > 0 */
        const ms_scene *sc = ms_sim_scene(sim);
        json_t *root = sc ? json_loads(ms_scene_text(sc), 0, NULL) : NULL;
        json_t *rate =
            json_object_get(json_object_get(json_object_get(root, "effects"), "rain"), "rate");
        v->rain = json_is_number(rate) && json_number_value(rate) > 0;
        json_decref(root);
    }
}

static void say(view_state *v, const char *fmt, const char *arg)
{
    snprintf(v->status, sizeof v->status, fmt, arg);
    printf("view: %s\n", v->status); /* the tests and the log read it */
    fflush(stdout);
}

/* The pointer's point on the still water, inside the pool; 0 if none. */
static int on_water(const view_state *v, float xy[2])
{
    const ms_renderer_desc *d = &v->rdesc;
    if (!view_camera_unproject(&v->cam, (float)v->w / (float)v->h, v->px, v->py, d->water_level,
                               xy))
        return 0;
    return xy[0] >= d->pool_min[0] && xy[0] <= d->pool_max[0] && xy[1] >= d->pool_min[1] &&
           xy[1] <= d->pool_max[1];
}

static float pool_side(const view_state *v)
{
    const ms_renderer_desc *d = &v->rdesc;
    return fminf(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
}

static int drop(view_state *v)
{
    float xy[2];
    if (!on_water(v, xy))
        return 0;
    if (!v->has_surface) {
        say(v, "%s", "no waves in this scene to drop a drop into");
        return 0;
    }
    ms_grid g;
    if (ms_sim_field_grid(v->sim, MS_FIELD_SURFACE, &g) != MS_OK)
        return fail("the wave grid");
    /* a drop's dent: 2 % of the pool across, 4 mm deep in a 1 m pool */
    float side = pool_side(v);
    if (ms_surface_add_drop(ms_sim_surface(v->sim), xy[0] - g.origin[0], xy[1] - g.origin[1],
                            0.02f * side, -0.004f * side) != MS_OK)
        return fail("a drop");
    char at[48];
    snprintf(at, sizeof at, "(%.3f, %.3f) m", (double)xy[0], (double)xy[1]);
    say(v, "drop at %s", at);
    return 0;
}

static int key_down(view_state *v, const char *k)
{
    for (int i = 0; i < VIEW_HELD_N; ++i)
        if (!strcmp(k, held_keys[i]))
            v->held[i] = 1;
    if (!strcmp(k, "Escape")) {
        v->quit = 1;
    } else if (!strcmp(k, "Space")) {
        v->paused = !v->paused;
        say(v, "%s", v->paused ? "paused" : "running");
    } else if (!strcmp(k, "N")) {
        v->step_once = 1;
    } else if (!strcmp(k, "F")) {
        v->paced = !v->paced;
        say(v, "%s", v->paced ? "paced at frame_dt" : "as fast as it can");
    } else if (!strcmp(k, "H")) {
        v->help = !v->help;
    } else if (!strcmp(k, "F12")) {
        v->screenshot = 1;
    } else if (!strcmp(k, "C")) {
        v->rdesc.caustics = !v->rdesc.caustics;
        v->renderer_stale = 1;
        say(v, "caustics %s", v->rdesc.caustics ? "on" : "off");
    } else if (!strcmp(k, "R")) {
        if (v->rain < 0) {
            say(v, "%s", "no waves in this scene for rain to fall on");
            return 0;
        }
        if (ms_sim_set_rain(v->sim, !v->rain) != MS_OK)
            return fail("rain");
        v->rain = !v->rain;
        say(v, "rain %s", v->rain ? "on" : "off");
    } else if (k[0] >= '1' && k[0] <= '4' && k[1] == '\0') {
        const char *name = shaders[k[0] - '1'];
        v->rdesc.shader = name;
        /* the scene's parameters belong to the scene's shader */
        v->rdesc.shader_params =
            v->scene_shader && !strcmp(name, v->scene_shader) ? v->scene_shader_params : NULL;
        v->renderer_stale = 1;
        say(v, "shader %s", name);
    } else if ((!strcmp(k, "Up") || !strcmp(k, "Down") || !strcmp(k, "Left") ||
                !strcmp(k, "Right")) &&
               !v->has_boat) {
        say(v, "%s", "this scene has no boat to steer");
    } else if (strlen(k) == 1 && strchr("WASDQE", k[0]) && !v->has_container) {
        say(v, "%s", "this scene has no container to move");
    }
    return 0;
}

static void key_up(view_state *v, const char *k)
{
    for (int i = 0; i < VIEW_HELD_N; ++i)
        if (!strcmp(k, held_keys[i]))
            v->held[i] = 0;
}

static int end_drag(view_state *v)
{
    v->dragging = 0;
    v->drag_moved = 0;
    if (v->disturber >= 0) {
        if (ms_surface_remove_disturber(ms_sim_surface(v->sim), v->disturber) != MS_OK)
            return fail("the drag's disturber");
        v->disturber = -1;
    }
    return 0;
}

int view_apply_event(view_state *v, const view_event *e)
{
    switch (e->type) {
    case VIEW_KEY_DOWN:
        return key_down(v, e->key);
    case VIEW_KEY_UP:
        key_up(v, e->key);
        return 0;
    case VIEW_BUTTON_DOWN: {
        v->px = e->x, v->py = e->y;
        v->button[e->button] = 1;
        float xy[2];
        if (e->button == 1 && e->shift)
            return drop(v);
        if (e->button == 1 && on_water(v, xy))
            v->dragging = 1;
        return 0;
    }
    case VIEW_BUTTON_UP:
        v->px = e->x, v->py = e->y;
        v->button[e->button] = 0;
        return e->button == 1 ? end_drag(v) : 0;
    case VIEW_MOTION: {
        float dx = e->x - v->px, dy = e->y - v->py;
        v->px = e->x, v->py = e->y;
        if (v->button[3]) {
            view_camera_orbit(&v->cam, dx, dy);
            v->camera_moved = 1;
        } else if (v->button[2]) {
            view_camera_pan(&v->cam, dx, dy, (float)v->w / (float)v->h);
            v->camera_moved = 1;
        }
        return 0;
    }
    case VIEW_WHEEL:
        view_camera_zoom(&v->cam, e->wheel);
        v->camera_moved = 1;
        return 0;
    case VIEW_QUIT:
        v->quit = 1;
        return 0;
    case VIEW_RESIZE:
        v->w = e->w, v->h = e->h;
        v->renderer_stale = 1;
        return 0;
    case VIEW_LOSE_CONTEXT:
        v->lose_context = 1;
        return 0;
    }
    return 0;
}

/* The drag of this step: where the pointer meets the water, moving at the
 * pointer's speed over the last frame (so a still pointer holds the water). */
static int drag_step(view_state *v)
{
    float xy[2];
    if (!on_water(v, xy))
        return 0; /* off the pool: nothing this frame */
    float vel[2] = {0, 0};
    if (v->drag_moved)
        for (int k = 0; k < 2; ++k) {
            vel[k] = (xy[k] - v->drag_prev[k]) / v->frame_dt;
            vel[k] = fminf(fmaxf(vel[k], -2.0f), 2.0f); /* m/s: a hand, not a jump */
        }
    v->drag_prev[0] = xy[0], v->drag_prev[1] = xy[1];
    v->drag_moved = 1;
    const float side = pool_side(v);
    const ms_renderer_desc *d = &v->rdesc;
    if (v->has_volume) {
        /* as fig1's scripted drag: 15 % of the pool across, 8 /s */
        float depth = 0.4f * (d->water_level - d->pool_min[2]);
        if (ms_sim_drag(v->sim, xy, vel, 0.12f * side, depth, 8.0f) != MS_OK)
            return fail("drag");
        return 0;
    }
    ms_surface *s = ms_sim_surface(v->sim);
    ms_grid g;
    if (!s || ms_sim_field_grid(v->sim, MS_FIELD_SURFACE, &g) != MS_OK)
        return 0;
    float x = xy[0] - g.origin[0], y = xy[1] - g.origin[1];
    if (v->disturber < 0) {
        ms_disturber_desc dd = ms_disturber_desc_default();
        dd.x = x;
        dd.y = y;
        dd.vx = vel[0];
        dd.vy = vel[1];
        dd.radius = 0.05f * side;
        dd.depth = 0.01f * side;
        if (ms_surface_add_disturber(s, &dd, &v->disturber) != MS_OK)
            return fail("the drag's disturber");
        return 0;
    }
    if (ms_surface_move_disturber(s, v->disturber, x, y, vel[0], vel[1]) != MS_OK)
        return fail("the drag's disturber");
    return 0;
}

static int boat_step(view_state *v)
{
    const int *h = v->held;
    int any = h[VIEW_HELD_UP] | h[VIEW_HELD_DOWN] | h[VIEW_HELD_LEFT] | h[VIEW_HELD_RIGHT];
    if (!v->has_boat || (!any && !v->boat_steered))
        return 0;
    v->boat_steered = any; /* let go: one more call stops it */
    /* along the camera's view on the water: up = away from the viewer */
    float fwd = (float)(h[VIEW_HELD_UP] - h[VIEW_HELD_DOWN]);
    float side = (float)(h[VIEW_HELD_RIGHT] - h[VIEW_HELD_LEFT]);
    float fx = -cosf(v->cam.yaw), fy = -sinf(v->cam.yaw); /* towards the target */
    float rx = fy, ry = -fx;
    float speed = 0.45f * pool_side(v); /* fig10's boat: 0.45 m/s in a 1 m pool */
    float vel[2] = {speed * (fwd * fx + side * rx), speed * (fwd * fy + side * ry)};
    if (ms_sim_steer_boat(v->sim, vel) != MS_OK)
        return fail("steering the boat");
    return 0;
}

static void quat_mul(const float a[4], const float b[4], float out[4])
{
    out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

static int container_step(view_state *v)
{
    const int *h = v->held;
    int move = h[VIEW_HELD_W] | h[VIEW_HELD_A] | h[VIEW_HELD_S] | h[VIEW_HELD_D];
    int turn = h[VIEW_HELD_Q] | h[VIEW_HELD_E];
    if (!v->has_container || (!move && !turn && !v->cont_active))
        return 0;
    v->cont_active = move || turn; /* let go: one more call with speeds of 0 */
    if (!v->cont_known) {
        if (ms_sim_container_pose(v->sim, v->cont_pos, v->cont_quat) != MS_OK)
            return fail("the container");
        v->cont_known = 1;
    }
    const float dt = v->frame_dt, side = pool_side(v);
    float fwd = (float)(h[VIEW_HELD_W] - h[VIEW_HELD_S]);
    float lat = (float)(h[VIEW_HELD_D] - h[VIEW_HELD_A]);
    float fx = -cosf(v->cam.yaw), fy = -sinf(v->cam.yaw), rx = fy, ry = -fx;
    float speed = 0.5f * side; /* m/s */
    float vel[3] = {speed * (fwd * fx + lat * rx), speed * (fwd * fy + lat * ry), 0};
    const ms_renderer_desc *d = &v->rdesc;
    for (int k = 0; k < 2; ++k) {
        v->cont_pos[k] += vel[k] * dt;
        if (v->cont_pos[k] < d->pool_min[k] || v->cont_pos[k] > d->pool_max[k]) {
            v->cont_pos[k] = fminf(fmaxf(v->cont_pos[k], d->pool_min[k]), d->pool_max[k]);
            vel[k] = 0;
        }
    }
    if (ms_sim_move_container(v->sim, v->cont_pos, vel) != MS_OK)
        return fail("moving the container");
    if (turn || v->tilt != 0) {
        /* tilt about the camera's right axis, 60 degrees/s, up to 120 degrees */
        float rate = (float)(h[VIEW_HELD_E] - h[VIEW_HELD_Q]) * 1.0472f;
        float t = fminf(fmaxf(v->tilt + rate * dt, -2.094f), 2.094f);
        rate = (t - v->tilt) / dt;
        v->tilt = t;
        float s = sinf(0.5f * t), q[4] = {cosf(0.5f * t), s * rx, s * ry, 0}, out[4];
        quat_mul(q, v->cont_quat, out);
        float omega[3] = {rate * rx, rate * ry, 0};
        if (ms_sim_turn_container(v->sim, out, omega) != MS_OK)
            return fail("tilting the container");
    }
    return 0;
}

int view_before_step(view_state *v)
{
    if (v->dragging && v->button[1] && drag_step(v) != 0)
        return -1;
    if (boat_step(v) != 0 || container_step(v) != 0)
        return -1;
    return 0;
}
