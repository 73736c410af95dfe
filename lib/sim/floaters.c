/* Objects carried by the flow (the paper's leaves, sections 1 and 4): a
 * floater takes the horizontal velocity of the SPH particles near the
 * surface at a rate `drag` (1/s, an exact exponential relaxation, stable
 * for any dt) and slides down the wave slopes, a = -slope * g * grad f
 * (the gravity component along a tilted surface, small slopes). It stays
 * inside the domain and out of solid cells of the obstacle mask, and sits
 * on the combined surface. Runs on the surface thread. */
#include <string.h>

#include "sim/sim_internal.h"

float ms_sim_sample(const float *f, int nx, int ny, int comp, int k, float x0, float y0, float dx,
                    float dy, float x, float y)
{
    float u = (x - x0) / dx - 0.5f, v = (y - y0) / dy - 0.5f;
    u = MS_CLAMP(u, 0.0f, (float)(nx - 1));
    v = MS_CLAMP(v, 0.0f, (float)(ny - 1));
    int i = MS_MIN((int)u, nx - 2 < 0 ? 0 : nx - 2), j = MS_MIN((int)v, ny - 2 < 0 ? 0 : ny - 2);
    int i1 = MS_MIN(i + 1, nx - 1), j1 = MS_MIN(j + 1, ny - 1);
    float a = u - (float)i, b = v - (float)j;
    float f00 = f[((size_t)j * nx + i) * comp + k], f10 = f[((size_t)j * nx + i1) * comp + k];
    float f01 = f[((size_t)j1 * nx + i) * comp + k], f11 = f[((size_t)j1 * nx + i1) * comp + k];
    return (1 - b) * ((1 - a) * f00 + a * f10) + b * ((1 - a) * f01 + a * f11);
}

static int solid_at(const ms_sim *sim, float x, float y)
{
    if (!sim->mask_static)
        return 0;
    const unsigned char *m = sim->have_moving_mask ? sim->mask : sim->mask_static;
    int i = (int)((x - sim->domain_min[0]) / sim->sdx),
        j = (int)((y - sim->domain_min[1]) / sim->sdx);
    if (i < 0 || j < 0 || i >= sim->snx || j >= sim->sny)
        return 0;
    return m[(size_t)j * sim->snx + i] != 0;
}

void ms_sim_floaters_step(ms_sim *sim, const float *flow, const float *wave, float dt)
{
    const ms_scene *sc = sim->scene;
    float drag = sc ? sc->floater_drag : 4.0f, slope = sc ? sc->floater_slope : 1.0f;
    float fdx = (sim->domain_max[0] - sim->domain_min[0]) / (float)MS_MAX(sim->fnx, 1);
    float fdy = (sim->domain_max[1] - sim->domain_min[1]) / (float)MS_MAX(sim->fny, 1);
    float lo[2] = {sim->domain_min[0], sim->domain_min[1]};
    float hi[2] = {sim->domain_max[0], sim->domain_max[1]};
    /* sub-steps of at most 1/60 s keep the slope term explicit-stable */
    int nsub = (int)MS_CLAMP(ceil(dt * 60.0), 1.0, 600.0);
    float h = dt / (float)nsub;
    float keep = expf(-drag * h);
    for (int f = 0; f < sim->nfloaters; ++f) {
        float *p = sim->floater_xyz + 3 * f, *v = sim->floater_vel + 2 * f;
        for (int s = 0; s < nsub; ++s) {
            float u[2] = {0, 0}, a[2] = {0, 0};
            if (flow)
                for (int k = 0; k < 2; ++k)
                    u[k] = ms_sim_sample(flow, sim->fnx, sim->fny, 2, k, lo[0], lo[1], fdx, fdy,
                                         p[0], p[1]);
            if (wave && slope > 0) {
                /* central differences over one wave cell either side */
                float d = sim->sdx;
                float gx = (ms_sim_sample(wave, sim->snx, sim->sny, 1, 0, lo[0], lo[1], d, d,
                                          p[0] + d, p[1]) -
                            ms_sim_sample(wave, sim->snx, sim->sny, 1, 0, lo[0], lo[1], d, d,
                                          p[0] - d, p[1])) /
                           (2 * d);
                float gy = (ms_sim_sample(wave, sim->snx, sim->sny, 1, 0, lo[0], lo[1], d, d, p[0],
                                          p[1] + d) -
                            ms_sim_sample(wave, sim->snx, sim->sny, 1, 0, lo[0], lo[1], d, d, p[0],
                                          p[1] - d)) /
                           (2 * d);
                a[0] = -slope * sim->gravity * gx;
                a[1] = -slope * sim->gravity * gy;
            }
            float np[2];
            for (int k = 0; k < 2; ++k) {
                v[k] = u[k] + (v[k] - u[k]) * keep + a[k] * h;
                np[k] = p[k] + v[k] * h;
                /* walls: stop at them */
                if (np[k] < lo[k] || np[k] > hi[k]) {
                    np[k] = MS_CLAMP(np[k], lo[k], hi[k]);
                    v[k] = 0;
                }
            }
            if (solid_at(sim, np[0], np[1])) {
                v[0] = v[1] = 0; /* against an obstacle: stays */
                continue;
            }
            p[0] = np[0];
            p[1] = np[1];
        }
    }
}

void ms_sim_floaters_height(ms_sim *sim)
{
    float lo[2] = {sim->domain_min[0], sim->domain_min[1]};
    for (int f = 0; f < sim->nfloaters; ++f) {
        float *p = sim->floater_xyz + 3 * f;
        float z;
        if (sim->surface)
            z = ms_sim_sample(sim->combined, sim->snx, sim->sny, 1, 0, lo[0], lo[1], sim->sdx,
                              sim->sdx, p[0], p[1]);
        else {
            long m = sim->calls; /* the frame being finished: m = n - 1 = calls */
            const float *hf = sim->hfield[m % 2];
            float fdx = (sim->domain_max[0] - sim->domain_min[0]) / (float)sim->fnx;
            float fdy = (sim->domain_max[1] - sim->domain_min[1]) / (float)sim->fny;
            z = ms_sim_sample(hf, sim->fnx, sim->fny, 1, 0, lo[0], lo[1], fdx, fdy, p[0], p[1]);
        }
        p[2] = sim->domain_min[2] + z;
    }
}
