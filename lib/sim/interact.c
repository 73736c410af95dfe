/* A user at the controls (the viewer's keys, an engine's input): the
 * scene's rain switched on and off, the scene's boat steered by hand
 * instead of along its path (Fig. 10b's bow waves wherever the user takes
 * it). Between steps only, like every other call on the sim. */
#include <math.h>
#include <string.h>

#include "modesplit/shape.h"
#include "modesplit/surface.h"
#include "scene/scene_internal.h"
#include "sim/sim_internal.h"

#define PART "sim"

ms_status ms_sim_set_rain(ms_sim *sim, int on)
{
    ms_status st = ms_check_not_null(PART, "sim", sim);
    if (st != MS_OK)
        return st;
    if (!sim->surface)
        return ms_fail(MS_ERR_STATE, "sim: rain falls on the waves and this sim has no surface");
    if (!on)
        return ms_surface_set_rain(sim->surface, NULL);
    const ms_scene *sc = ms_sim_scene(sim);
    if (sc && sc->has_rain && sc->rain.rate > 0)
        return ms_surface_set_rain(sim->surface, &sc->rain);
    /* a scene without rain: a light shower like fig10's (15 drops per m^2
     * per s, 1 cm dents of 1.5 mm), widened to two wave cells on a coarse grid */
    ms_surface_desc d = ms_surface_get_desc(sim->surface);
    ms_rain r = ms_rain_default();
    r.rate = 15.0f;
    r.radius = fmaxf(0.01f, 2.0f * d.dx);
    r.amplitude = -0.0015f;
    return ms_surface_set_rain(sim->surface, &r);
}

static ms_status need_boat(const ms_sim *sim)
{
    const ms_scene *sc = ms_sim_scene(sim);
    if (!sim->surface || !sc || !sc->has_boat)
        return ms_fail(MS_ERR_STATE, "sim: this scene has no boat (effects.boat) to steer");
    return MS_OK;
}

ms_status ms_sim_steer_boat(ms_sim *sim, const float vel[2])
{
    ms_status st = ms_check_not_null(PART, "sim", sim);
    if (st == MS_OK)
        st = ms_check_not_null(PART, "vel", vel);
    if (st == MS_OK)
        st = ms_check_range(PART, "boat vel[0]", vel[0], -100, 100, "m/s");
    if (st == MS_OK)
        st = ms_check_range(PART, "boat vel[1]", vel[1], -100, 100, "m/s");
    if (st == MS_OK)
        st = need_boat(sim);
    if (st != MS_OK)
        return st;
    float x, y;
    if ((st = ms_surface_disturber_position(sim->surface, sim->boat_id, &x, &y)) != MS_OK)
        return st;
    /* keep it on the water: at the edge it stops going further out */
    const float w = (float)sim->wave_grid.nx * sim->wave_grid.dx;
    const float h = (float)sim->wave_grid.ny * sim->wave_grid.dy;
    float vx = vel[0], vy = vel[1];
    if ((x <= 0 && vx < 0) || (x >= w && vx > 0))
        vx = 0;
    if ((y <= 0 && vy < 0) || (y >= h && vy > 0))
        vy = 0;
    x = fminf(fmaxf(x, 0), w);
    y = fminf(fmaxf(y, 0), h);
    sim->boat_started = 1; /* the scene's path no longer takes over */
    return ms_surface_move_disturber(sim->surface, sim->boat_id, x, y, vx, vy);
}

ms_status ms_sim_boat(const ms_sim *sim, float pos[2])
{
    ms_status st = ms_check_not_null(PART, "sim", sim);
    if (st == MS_OK)
        st = ms_check_not_null(PART, "pos", pos);
    if (st == MS_OK)
        st = need_boat(sim);
    if (st != MS_OK)
        return st;
    float x, y;
    if ((st = ms_surface_disturber_position(sim->surface, sim->boat_id, &x, &y)) != MS_OK)
        return st;
    pos[0] = x + sim->domain_min[0];
    pos[1] = y + sim->domain_min[1];
    return MS_OK;
}

ms_status ms_sim_container_pose(const ms_sim *sim, float pos[3], float orientation[4])
{
    ms_status st = ms_check_not_null(PART, "sim", sim);
    if (st == MS_OK)
        st = ms_check_not_null(PART, "pos", pos);
    if (st != MS_OK)
        return st;
    if (sim->container < 0 || !sim->shapes)
        return ms_fail(MS_ERR_STATE, "sim: this scene has no container (effects.container)");
    const ms_sim_shape *sh = &sim->shapes[sim->container];
    const ms_shape *s = sh->vol ? sh->vol : sh->surf;
    if (!s)
        return ms_fail(MS_ERR_STATE, "sim: the container has no shape in this sim");
    float vel[3], omega[3], q[4];
    ms_shape_get_pose(s, pos, vel);
    ms_shape_get_orientation(s, q, omega);
    if (orientation)
        memcpy(orientation, q, sizeof q);
    return MS_OK;
}
