/* Setting up the scene's effects, each only when the scene names it:
 * obstacles and the container (volume colliders, eq. 15, and solid cells
 * of the wave grid at the water level), rain, the boat (a disturber that
 * makes bow waves, Fig. 10b), scripted drops (Fig. 3a), floaters, spray. */
#include <stdio.h>
#include <string.h>

#include "modesplit/surface.h"
#include "surface/surface_internal.h"
#include "modesplit/volume.h"
#include "sim/sim_internal.h"

/* A collider that holds the whole domain leaves the liquid nowhere to be:
 * every particle is pushed out of it on every sub-step, the sub-steps
 * shrink to the force bound, and one frame ran for 85 s (fig10 inside a
 * sphere of 50 m). Refused at create, when every point of a 5 x 5 x 5
 * lattice over the domain (its corners included) lies inside the shape:
 * for a convex shape, the whole domain is then inside. */
static ms_status check_not_enclosing(const ms_sim *sim, const ms_shape *shape, int index)
{
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            for (int k = 0; k < 5; ++k) {
                const int ijk[3] = {i, j, k};
                float p[3];
                for (int a = 0; a < 3; ++a)
                    p[a] = sim->domain_min[a] +
                           (sim->domain_max[a] - sim->domain_min[a]) * (float)ijk[a] / 4.0f;
                if (!(ms_shape_distance(shape, p, NULL) < 0.0f))
                    return MS_OK;
            }
    char name[32];
    if (index >= 0)
        snprintf(name, sizeof name, "obstacles[%d]", index);
    else
        snprintf(name, sizeof name, "the container");
    return ms_fail(MS_ERR_INVALID_ARGUMENT,
                   "sim: %s encloses the whole domain [%g, %g] x [%g, %g] x [%g, %g] m "
                   "(all 125 points of a lattice over it are inside the shape): the liquid has "
                   "nowhere to be and each frame would take unbounded time; allowed: a shape "
                   "that leaves part of the domain free",
                   name, (double)sim->domain_min[0], (double)sim->domain_max[0],
                   (double)sim->domain_min[1], (double)sim->domain_max[1],
                   (double)sim->domain_min[2], (double)sim->domain_max[2]);
}

static ms_status add_shape(ms_sim *sim, const ms_scene_shape *spec, ms_sim_shape *sh, int index)
{
    ms_status st = MS_OK;
    sh->spec = spec;
    sh->moving = spec->path.npoints > 1 || spec->velocity[0] != 0 || spec->velocity[1] != 0 ||
                 spec->velocity[2] != 0 || spec->spin[0] != 0 || spec->spin[1] != 0 ||
                 spec->spin[2] != 0;
    if (sim->volume) {
        st = ms_shape_create(spec->kind, spec->params_json, &sh->vol);
        if (st == MS_OK)
            st = ms_sim_shape_place(sh, sh->vol, 0.0);
        if (st == MS_OK)
            st = check_not_enclosing(sim, sh->vol, index);
        if (st == MS_OK)
            st = ms_volume_add_collider(sim->volume, sh->vol);
        if (st != MS_OK) {
            ms_shape_destroy(sh->vol);
            sh->vol = NULL;
            return st;
        }
    }
    if (sim->surface && spec->surface_mask) {
        st = ms_shape_create(spec->kind, spec->params_json, &sh->surf);
        if (st == MS_OK)
            st = ms_sim_shape_place(sh, sh->surf, 0.0);
    }
    return st;
}

static ms_status setup_shapes(ms_sim *sim, const ms_scene *sc)
{
    int n = sc->nobstacles + (sc->has_container ? 1 : 0);
    if (n == 0)
        return MS_OK;
    sim->shapes = ms_alloc_array((size_t)n, sizeof *sim->shapes);
    if (!sim->shapes)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for %d shapes", n);
    sim->own_effects_bytes += (size_t)n * sizeof *sim->shapes;
    int any_surf = 0;
    for (int i = 0; i < n; ++i) {
        const ms_scene_shape *spec = i < sc->nobstacles ? &sc->obstacles[i] : &sc->container;
        sim->nshapes = i + 1;
        ms_status st = add_shape(sim, spec, &sim->shapes[i], i < sc->nobstacles ? i : -1);
        if (st != MS_OK)
            return st;
        any_surf |= sim->shapes[i].surf != NULL;
        if (i >= sc->nobstacles)
            sim->container = i;
    }
    if (!any_surf)
        return MS_OK;
    /* the obstacle mask: static footprints once, moving ones each frame */
    size_t ns = (size_t)sim->snx * sim->sny;
    sim->mask_static = ms_alloc(ns);
    sim->mask = ms_alloc(ns);
    if (!sim->mask_static || !sim->mask)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for the obstacle mask");
    sim->own_effects_bytes += 2 * ns;
    float z = sim->domain_min[2] + sim->level; /* m, the water level */
    for (int i = 0; i < n; ++i) {
        ms_sim_shape *sh = &sim->shapes[i];
        if (!sh->surf)
            continue;
        if (sh->moving)
            sim->have_moving_mask = 1;
        ms_status st = ms_shape_footprint(sh->surf, &sim->wave_grid, z,
                                          sh->moving ? sim->mask : sim->mask_static);
        if (st != MS_OK)
            return st;
    }
    for (size_t c = 0; c < ns; ++c)
        sim->mask[c] |= sim->mask_static[c];
    return ms_surface_set_obstacle_mask(sim->surface, sim->mask);
}

ms_status ms_sim_setup_effects(ms_sim *sim, const ms_scene *sc)
{
    ms_status st = setup_shapes(sim, sc);
    if (st != MS_OK)
        return st;
    if (sim->surface && sc->has_rain)
        st = ms_surface_set_rain(sim->surface, &sc->rain);
    if (st == MS_OK && sim->surface && sc->has_boat) {
        /* the path in the wave grid's coordinates (from its corner) */
        int n = sc->boat_path.npoints;
        sim->boat_xy = ms_alloc_array((size_t)n * 2, sizeof *sim->boat_xy);
        if (!sim->boat_xy)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for the boat's path");
        sim->own_effects_bytes += (size_t)n * 2 * sizeof *sim->boat_xy;
        for (int i = 0; i < n; ++i) {
            sim->boat_xy[2 * i] = sc->boat_path.points[2 * i] - sim->domain_min[0];
            sim->boat_xy[2 * i + 1] = sc->boat_path.points[2 * i + 1] - sim->domain_min[1];
        }
        ms_disturber_desc d = ms_disturber_desc_default();
        d.x = sim->boat_xy[0];
        d.y = sim->boat_xy[1];
        d.radius = sc->boat_radius;
        d.depth = sc->boat_depth;
        st = ms_surface_add_disturber(sim->surface, &d, &sim->boat_id);
        /* its path now, at speed 0 (it stays on the first point, as above),
         * so the start sets it again in the same block: the frame the boat
         * starts allocates nothing */
        if (st == MS_OK && n > 1)
            st = ms_surface_set_disturber_path(sim->surface, sim->boat_id, n, sim->boat_xy, 0.0f,
                                               sc->boat_path.loop);
    }
    /* the dent the pointer drags without a volume is added when the drag
     * starts: its room now */
    if (st == MS_OK && sim->surface && sc->has_drag && !sim->volume)
        st = ms_surface_reserve_disturbers(sim->surface, sc->has_boat ? 2 : 1);
    if (st == MS_OK && sim->surface && sc->ndrops > 0) {
        /* drops in time order (stable: equal times keep the scene's order) */
        sim->drop_order = ms_alloc_array((size_t)sc->ndrops, sizeof *sim->drop_order);
        if (!sim->drop_order)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for %d drops", sc->ndrops);
        sim->own_effects_bytes += (size_t)sc->ndrops * sizeof *sim->drop_order;
        /* every drop is checked now, as ms_surface_add_drop will check it
         * when it falls: `modesplit check` then refuses what `run` would
         * refuse at a later frame */
        const float extent = (float)MS_MAX(sim->snx, sim->sny) * sim->sdx;
        double cells = 0.0;
        for (int i = 0; i < sc->ndrops; ++i) {
            const float r = sc->drops[i].radius;
            if (!isfinite(r) || !(r > 0) || r > extent)
                return ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "sim: scene drop %d (at t = %g s) has radius %g m, outside (0, "
                               "%g] m (the wave grid's extent)",
                               i, (double)sc->drops[i].time, (double)r, (double)extent);
            cells += ms_surface_drop_cells(sim->surface, r);
        }
        /* their work in all is bounded, as the rain's a second is */
        if (cells > MS_SURFACE_MAX_DROP_CELLS)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "sim: the scene's %d drops visit %.3g wave cells in all (each the "
                           "square of its diameter); at most %.3g (fewer or smaller drops)",
                           sc->ndrops, cells, MS_SURFACE_MAX_DROP_CELLS);
        for (int i = 0; i < sc->ndrops; ++i) {
            int k = i;
            while (k > 0 && sc->drops[sim->drop_order[k - 1]].time > sc->drops[i].time) {
                sim->drop_order[k] = sim->drop_order[k - 1];
                --k;
            }
            sim->drop_order[k] = i;
        }
    }
    if (st == MS_OK && sc->has_floaters) {
        int n = sc->nfloaters;
        sim->floater_xyz = ms_alloc_array((size_t)n * 3, sizeof(float));
        sim->floater_vel = ms_alloc_array((size_t)n * 2, sizeof(float));
        if (!sim->floater_xyz || !sim->floater_vel)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for %d floaters", n);
        sim->own_effects_bytes += (size_t)n * 5 * sizeof(float);
        for (int i = 0; i < n; ++i) {
            sim->floater_xyz[3 * i] = sc->floater_xy[2 * i];
            sim->floater_xyz[3 * i + 1] = sc->floater_xy[2 * i + 1];
            sim->floater_xyz[3 * i + 2] = sim->domain_min[2] + sim->level;
        }
        sim->nfloaters = n;
    }
    if (st == MS_OK)
        st = ms_sim_spray_setup(sim, sc);
    return st;
}
