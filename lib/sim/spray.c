/* Spray and foam where the height field cannot follow (the paper's
 * conclusion: splashes are simulated by SPH but the 2.5D surface cannot
 * show them). Only for a scene's effects.spray; runs on the surface
 * thread after the combined field of frame m, reading the particle copy
 * and the SPH field of t_m, so 1 and 2 threads give the same bytes.
 *
 * Emission, after Ihmsen et al. 2012 ("Unified spray, foam and bubbles for
 * particle-based fluids": its potentials and emission count) with their
 * neighbour sums replaced by what the extraction already has per field
 * cell (no neighbour pass):
 * each particle within two spacings of its cell's surface H_m emits
 *     n = phi_k (k_ta phi_ta + k_wc phi_wc) dt
 * spray particles, every phi a ramp clamped to [0, 1] over the scene's
 * [lo, hi]:
 *   phi_k   kinetic energy |v|^2 / 2 (J/kg): only fast water emits;
 *   phi_ta  trapped air: |v - u_c|, the speed relative to the mean
 *           velocity u_c of the band's particles of the cell (Ihmsen's
 *           v_diff sums the same relative speed over the neighbours);
 *   phi_wc  wave crest: the upward speed v_z of a surface particle
 *           (Ihmsen's curvature times "moving along the normal", with the
 *           normal of a nearly flat free surface taken as z).
 * The fraction of n is drawn from the sim's own generator (seeded from the
 * scene), so a still pool, whose particles move by mm/s, draws nothing and
 * emits nothing. A spray particle starts at its emitter (jittered within
 * half a spacing, each velocity component spread by up to 30 % of its
 * speed, so the droplets of one emitter fan out as a sheet): no liquid
 * mass is taken, the SPH particle is untouched. At most `budget` fly at
 * once; above it the emission waits.
 *
 * Flight: ballistic under the volume's gravity, exact for constant
 * acceleration (x += v h + g h^2 / 2, v += g h) at any step, in sub-steps
 * of at most 1/240 s only to find where it crosses the surface. It lands
 * when it falls through the surface of frame m (the combined field, or
 * the SPH field without waves), and leaves when it leaves the domain's
 * x-y extent or falls below its floor. It does not pass through the
 * obstacles and the container: after each sub-step, where a shape's
 * signed distance (the plugin's, as the SPH particles' collisions use
 * it) is negative, the droplet is put back on the shape's surface along
 * its normal and loses its velocity into the shape (it runs down a wall,
 * as the particles do). The shapes are the spray's own copies, placed at
 * t_m on the surface thread.
 *
 * Foam: a cover in [0, 1] on the wave grid (the SPH field's grid without
 * waves). Each landing and each emission (the surface breaking) adds the
 * scene's `foam` to the cells within a particle spacing; the cover fades
 * as exp(-dt / lifetime), exact, and is carried semi-Lagrangian by the
 * surface flow, the band's mean horizontal velocity per field cell (the
 * floaters' flow). */
#include <math.h>
#include <string.h>

#include "modesplit/volume.h"
#include "sim/sim_internal.h"

static float ramp(float x, const float r[2])
{
    float t = (x - r[0]) / (r[1] - r[0]);
    return t <= 0.0f ? 0.0f : t >= 1.0f ? 1.0f : t;
}

ms_status ms_sim_spray_setup(ms_sim *sim, const ms_scene *sc)
{
    ms_sim_spray_state *s = &sim->spray;
    if (!sc || !sc->has_spray || !sim->volume)
        return MS_OK;
    size_t nf = (size_t)sim->fnx * sim->fny;
    s->gnx = sim->surface ? sim->snx : sim->fnx;
    s->gny = sim->surface ? sim->sny : sim->fny;
    s->gdx = sim->surface ? sim->sdx : (sim->domain_max[0] - sim->domain_min[0]) / (float)sim->fnx;
    s->gdy = sim->surface ? sim->sdx : (sim->domain_max[1] - sim->domain_min[1]) / (float)sim->fny;
    size_t ng = (size_t)s->gnx * s->gny, cap = (size_t)sc->spray_budget;
    s->pos = ms_alloc_array(3 * cap, sizeof(float));
    s->vel = ms_alloc_array(3 * cap, sizeof(float));
    s->cell_v = ms_alloc_array(3 * nf, sizeof(float));
    s->cell_n = ms_alloc_array(nf, sizeof(float));
    s->foam = ms_alloc_array(ng, sizeof(float));
    s->foam_tmp = ms_alloc_array(ng, sizeof(float));
    if (!s->pos || !s->vel || !s->cell_v || !s->cell_n || !s->foam || !s->foam_tmp)
        return ms_fail(MS_ERR_OUT_OF_MEMORY,
                       "sim: out of memory for a spray budget of %d and its foam field",
                       sc->spray_budget);
    memset(s->foam, 0, ng * sizeof(float));
    sim->own_effects_bytes += (6 * cap + 4 * nf + 2 * ng) * sizeof(float);
    s->cap = sc->spray_budget;
    ms_volume_desc vd = ms_volume_get_desc(sim->volume);
    memcpy(s->g, vd.gravity, sizeof s->g);
    ms_rng_seed(&s->rng, sc->seed ^ 0x7370726179ull); /* "spray" */
    for (int i = 0; i < sim->nshapes; ++i) {
        ms_sim_shape *sh = &sim->shapes[i];
        ms_status st = ms_shape_create(sh->spec->kind, sh->spec->params_json, &sh->spray);
        if (st == MS_OK)
            st = ms_sim_shape_place(sh, sh->spray, 0.0);
        if (st != MS_OK)
            return st;
    }
    return MS_OK;
}

void ms_sim_spray_free(ms_sim *sim)
{
    ms_sim_spray_state *s = &sim->spray;
    ms_free(s->pos);
    ms_free(s->vel);
    ms_free(s->cell_v);
    ms_free(s->cell_n);
    ms_free(s->foam);
    ms_free(s->foam_tmp);
}

float ms_sim_surface_z(const ms_sim *sim, int slot, float x, float y)
{
    const float *lo = sim->domain_min;
    if (sim->surface)
        return lo[2] + ms_sim_sample(sim->combined, sim->snx, sim->sny, 1, 0, lo[0], lo[1],
                                     sim->sdx, sim->sdx, x, y);
    float fdx = (sim->domain_max[0] - lo[0]) / (float)sim->fnx;
    float fdy = (sim->domain_max[1] - lo[1]) / (float)sim->fny;
    return lo[2] +
           ms_sim_sample(sim->hfield[slot], sim->fnx, sim->fny, 1, 0, lo[0], lo[1], fdx, fdy, x, y);
}

/* Foam where a droplet lands or the surface breaks at world (x, y): the
 * cover of every cell whose centre lies within `radius` m (one particle
 * spacing: the patch of surface one SPH particle stands for) raised by
 * `amount`, at most to 1; the nearest cell at least. */
static void deposit(ms_sim_spray_state *s, const float *lo, float radius, float x, float y,
                    float amount)
{
    if (!(amount > 0))
        return;
    if (!s->foam_on) {
        s->box[0] = s->gnx, s->box[1] = -1, s->box[2] = s->gny, s->box[3] = -1;
        s->foam_on = 1;
    }
    const float u = (x - lo[0]) / s->gdx - 0.5f, v = (y - lo[1]) / s->gdy - 0.5f;
    const float ru = radius / s->gdx, rv = radius / s->gdy;
    const int i0 = (int)MS_CLAMP(ceilf(u - ru), 0.0f, (float)(s->gnx - 1));
    const int i1 = (int)MS_CLAMP(floorf(u + ru), 0.0f, (float)(s->gnx - 1));
    const int j0 = (int)MS_CLAMP(ceilf(v - rv), 0.0f, (float)(s->gny - 1));
    const int j1 = (int)MS_CLAMP(floorf(v + rv), 0.0f, (float)(s->gny - 1));
    for (int j = j0; j <= j1 && radius > 0; ++j)
        for (int i = i0; i <= i1; ++i) {
            const float a = ((float)i - u) / ru, b = ((float)j - v) / rv;
            if (a * a + b * b > 1.0f)
                continue;
            float *f = &s->foam[(size_t)j * s->gnx + i];
            *f = fminf(1.0f, *f + amount);
        }
    const int ic = (int)MS_CLAMP(floorf(u + 0.5f), 0.0f, (float)(s->gnx - 1));
    const int jc = (int)MS_CLAMP(floorf(v + 0.5f), 0.0f, (float)(s->gny - 1));
    s->box[0] = MS_MIN(s->box[0], MS_MIN(i0, ic)), s->box[1] = MS_MAX(s->box[1], MS_MAX(i1, ic));
    s->box[2] = MS_MIN(s->box[2], MS_MIN(j0, jc)), s->box[3] = MS_MAX(s->box[3], MS_MAX(j1, jc));
    float *f = &s->foam[(size_t)jc * s->gnx + ic];
    if (*f < amount)
        *f = fminf(1.0f, amount);
}

/* Ballistic flight over dt; landed and departed particles leave (stable
 * compaction: the survivors keep their order). */
void ms_sim_spray_fly(ms_sim *sim, int slot, float dt, float foam)
{
    ms_sim_spray_state *s = &sim->spray;
    const float *lo = sim->domain_min, *hi = sim->domain_max;
    int nsub = (int)MS_CLAMP(ceilf(dt * 240.0f), 1.0f, 2400.0f);
    float h = dt / (float)nsub;
    int kept = 0;
    for (int i = 0; i < s->n; ++i) {
        float p[3], v[3];
        memcpy(p, s->pos + 3 * i, sizeof p);
        memcpy(v, s->vel + 3 * i, sizeof v);
        int gone = 0;
        for (int k = 0; k < nsub && !gone; ++k) {
            for (int a = 0; a < 3; ++a) {
                p[a] += v[a] * h + 0.5f * s->g[a] * h * h;
                v[a] += s->g[a] * h;
            }
            for (int o = 0; o < sim->nshapes; ++o) {
                const ms_shape *tw = sim->shapes[o].spray;
                float nrm[3];
                const float d = tw ? ms_shape_distance(tw, p, nrm) : 1.0f; /* m */
                if (!(d < 0.0f))
                    continue;
                const float vn = v[0] * nrm[0] + v[1] * nrm[1] + v[2] * nrm[2];
                for (int a = 0; a < 3; ++a) {
                    p[a] -= d * nrm[a];
                    if (vn < 0.0f)
                        v[a] -= vn * nrm[a];
                }
            }
            if (p[0] < lo[0] || p[0] > hi[0] || p[1] < lo[1] || p[1] > hi[1] || p[2] < lo[2])
                gone = 1;
            else if (v[2] < 0 && p[2] <= ms_sim_surface_z(sim, slot, p[0], p[1])) {
                deposit(s, lo, sim->spacing, p[0], p[1], foam);
                s->landed++;
                gone = 2;
            }
        }
        if (gone)
            continue;
        memcpy(s->pos + 3 * kept, p, sizeof p);
        memcpy(s->vel + 3 * kept, v, sizeof v);
        kept++;
    }
    s->n = kept;
}

/* Fade (exact exponential) and carry the foam by the surface flow. */
void ms_sim_foam_step(ms_sim *sim, const float *flow, float dt, float lifetime)
{
    ms_sim_spray_state *s = &sim->spray;
    if (!s->foam_on)
        return;
    const float keep = expf(-dt / lifetime);
    const float *lo = sim->domain_min;
    size_t ng = (size_t)s->gnx * s->gny;
    if (flow) {
        /* the flow at each foam cell's centre, bilinear on the field grid
         * (cell-centred, edges held), and the cover at the point it came
         * from, bilinear on the foam grid: the same sampling as
         * ms_sim_sample, written out (3x faster on the boat's 300 x 200) */
        const int fnx = sim->fnx, fny = sim->fny, gnx = s->gnx, gny = s->gny;
        const float rx = s->gdx * (float)fnx / (sim->domain_max[0] - lo[0]);
        const float ry = s->gdy * (float)fny / (sim->domain_max[1] - lo[1]);
        const float sx = dt / s->gdx, sy = dt / s->gdy;
        const float *restrict f = s->foam;
        float *restrict out = s->foam_tmp;
        /* only the cells the foam can reach: its box (foam_step's last
         * pass) grown by the farthest the flow carries it, plus a cell */
        float umax = 0.0f;
        for (size_t c = 0; c < 2 * (size_t)fnx * fny; ++c)
            umax = fmaxf(umax, fabsf(flow[c]));
        const int mi = (int)MS_MIN(ceilf(umax * sx) + 1.0f, (float)gnx);
        const int mj = (int)MS_MIN(ceilf(umax * sy) + 1.0f, (float)gny);
        const int ilo = MS_MAX(s->box[0] - mi, 0), ihi = MS_MIN(s->box[1] + mi, gnx - 1);
        const int jlo = MS_MAX(s->box[2] - mj, 0), jhi = MS_MIN(s->box[3] + mj, gny - 1);
        memset(out, 0, ng * sizeof *out);
        for (int j = jlo; j <= jhi; ++j) {
            float v = MS_CLAMP(((float)j + 0.5f) * ry - 0.5f, 0.0f, (float)(fny - 1));
            int b0 = MS_MIN((int)v, MS_MAX(fny - 2, 0)), b1 = MS_MIN(b0 + 1, fny - 1);
            float wb = v - (float)b0;
            const float *r0 = flow + 2 * (size_t)b0 * fnx, *r1 = flow + 2 * (size_t)b1 * fnx;
            for (int i = ilo; i <= ihi; ++i) {
                float u = MS_CLAMP(((float)i + 0.5f) * rx - 0.5f, 0.0f, (float)(fnx - 1));
                int a0 = MS_MIN((int)u, MS_MAX(fnx - 2, 0)), a1 = MS_MIN(a0 + 1, fnx - 1);
                float wa = u - (float)a0;
                float ux = (1 - wb) * ((1 - wa) * r0[2 * a0] + wa * r0[2 * a1]) +
                           wb * ((1 - wa) * r1[2 * a0] + wa * r1[2 * a1]);
                float uy = (1 - wb) * ((1 - wa) * r0[2 * a0 + 1] + wa * r0[2 * a1 + 1]) +
                           wb * ((1 - wa) * r1[2 * a0 + 1] + wa * r1[2 * a1 + 1]);
                float p = MS_CLAMP((float)i - ux * sx, 0.0f, (float)(gnx - 1));
                float q = MS_CLAMP((float)j - uy * sy, 0.0f, (float)(gny - 1));
                int i0 = MS_MIN((int)p, MS_MAX(gnx - 2, 0)), i1 = MS_MIN(i0 + 1, gnx - 1);
                int j0 = MS_MIN((int)q, MS_MAX(gny - 2, 0)), j1 = MS_MIN(j0 + 1, gny - 1);
                float c = p - (float)i0, d = q - (float)j0;
                const float *g0 = f + (size_t)j0 * gnx, *g1 = f + (size_t)j1 * gnx;
                out[(size_t)j * gnx + i] = keep * ((1 - d) * ((1 - c) * g0[i0] + c * g0[i1]) +
                                                   d * ((1 - c) * g1[i0] + c * g1[i1]));
            }
        }
        float *t = s->foam;
        s->foam = s->foam_tmp;
        s->foam_tmp = t;
    } else {
        for (size_t c = 0; c < ng; ++c)
            s->foam[c] *= keep;
    }
    /* below 1e-4 the cover is invisible: cleared, so a calm scene stops
     * paying for its foam; the box of what is left */
    int box[4] = {s->gnx, -1, s->gny, -1};
    for (int j = 0; j < s->gny; ++j)
        for (int i = 0; i < s->gnx; ++i) {
            float *c = &s->foam[(size_t)j * s->gnx + i];
            if (*c < 1e-4f) {
                *c = 0.0f;
                continue;
            }
            box[0] = MS_MIN(box[0], i), box[1] = MS_MAX(box[1], i);
            box[2] = MS_MIN(box[2], j), box[3] = MS_MAX(box[3], j);
        }
    memcpy(s->box, box, sizeof box);
    s->foam_on = box[1] >= 0;
}

/* Ihmsen's potentials over the particles of slot (the header's rule). */
static void emit(ms_sim *sim, int slot, float dt)
{
    ms_sim_spray_state *s = &sim->spray;
    const ms_scene *sc = sim->scene;
    const float *lo = sim->domain_min;
    const int n = sim->pcount[slot];
    const float *const *pp = (const float *const *)sim->ppos[slot];
    const float *const *pv = (const float *const *)sim->pvel[slot];
    const float *hf = sim->hfield[slot];
    const size_t nf = (size_t)sim->fnx * sim->fny;
    const float sx = sim->fnx / (sim->domain_max[0] - lo[0]);
    const float sy = sim->fny / (sim->domain_max[1] - lo[1]);
    const float band = 2 * sim->spacing; /* m, as the surface flow's */
    memset(s->cell_v, 0, 3 * nf * sizeof(float));
    memset(s->cell_n, 0, nf * sizeof(float));
    /* pass 1: the band's mean velocity per cell (stable order) */
    for (int i = 0; i < n; ++i) {
        int ci = (int)MS_CLAMP((pp[0][i] - lo[0]) * sx, 0.0f, (float)(sim->fnx - 1));
        int cj = (int)MS_CLAMP((pp[1][i] - lo[1]) * sy, 0.0f, (float)(sim->fny - 1));
        size_t c = (size_t)cj * sim->fnx + ci;
        if (pp[2][i] - lo[2] < hf[c] - band)
            continue;
        for (int a = 0; a < 3; ++a)
            s->cell_v[3 * c + a] += pv[a][i];
        s->cell_n[c] += 1.0f;
    }
    for (size_t c = 0; c < nf; ++c)
        if (s->cell_n[c] > 0)
            for (int a = 0; a < 3; ++a)
                s->cell_v[3 * c + a] /= s->cell_n[c];
    /* pass 2: the potentials and the emission */
    for (int i = 0; i < n; ++i) {
        const float v[3] = {pv[0][i], pv[1][i], pv[2][i]};
        const float ek = 0.5f * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); /* J/kg */
        const float phi_k = ramp(ek, sc->spray_kinetic);
        if (phi_k == 0.0f)
            continue;
        int ci = (int)MS_CLAMP((pp[0][i] - lo[0]) * sx, 0.0f, (float)(sim->fnx - 1));
        int cj = (int)MS_CLAMP((pp[1][i] - lo[1]) * sy, 0.0f, (float)(sim->fny - 1));
        size_t c = (size_t)cj * sim->fnx + ci;
        if (pp[2][i] - lo[2] < hf[c] - band)
            continue;
        float d[3];
        for (int a = 0; a < 3; ++a)
            d[a] = v[a] - s->cell_v[3 * c + a];
        const float phi_ta =
            ramp(sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), sc->spray_trapped_air);
        const float phi_wc = ramp(v[2], sc->spray_wave_crest);
        const float mean = phi_k * (sc->spray_rate[0] * phi_ta + sc->spray_rate[1] * phi_wc) * dt;
        if (!(mean > 0.0f))
            continue;
        int count = (int)mean;
        if (ms_rng_uniform(&s->rng) < mean - (float)count)
            count++;
        const float speed = sqrtf(2.0f * ek);
        for (int k = 0; k < count && s->n < s->cap; ++k) {
            float *p = s->pos + 3 * s->n, *w = s->vel + 3 * s->n;
            for (int a = 0; a < 3; ++a) {
                p[a] = pp[a][i] + (ms_rng_uniform(&s->rng) - 0.5f) * sim->spacing;
                w[a] = v[a] + (ms_rng_uniform(&s->rng) - 0.5f) * 0.6f * speed;
            }
            /* the jitter keeps it in the domain (an emitter at a wall) */
            for (int a = 0; a < 2; ++a)
                p[a] = MS_CLAMP(p[a], lo[a], sim->domain_max[a]);
            p[2] = MS_MAX(p[2], lo[2]);
            s->n++;
            s->emitted++;
        }
        if (count > 0) /* the surface breaks here */
            deposit(s, lo, sim->spacing, pp[0][i], pp[1][i], sc->foam_deposit);
    }
}

void ms_sim_spray_frame(ms_sim *sim, int slot, float dt)
{
    ms_sim_spray_state *s = &sim->spray;
    if (!s->cap || !(dt > 0.0f))
        return;
    double c0 = ms_now();
    const ms_scene *sc = sim->scene;
    for (int i = 0; i < sim->nshapes; ++i) { /* the shapes at t_m */
        ms_sim_shape *sh = &sim->shapes[i];
        if (sh->spray && ms_sim_shape_dynamic(sh))
            ms_sim_shape_place(sh, sh->spray, sim->t_fields + dt);
    }
    ms_sim_spray_fly(sim, slot, dt, sc->foam_deposit);
    ms_sim_foam_step(sim, sim->flow[slot], dt, sc->foam_lifetime);
    emit(sim, slot, dt);
    s->ms += (ms_now() - c0) * 1e3;
}
