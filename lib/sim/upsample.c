/* Eq. 20 and Fig. 7: the SPH height field (X_SPH x Y_SPH cells) is
 * up-sampled bilinearly onto the wave grid (X_WE x Y_WE) and summed with
 * the wave field. Both grids span the domain's x-y extent with cell
 * centres at (i + 0.5) * cell size; N_surf = X_WE / X_SPH need not be an
 * integer. The taps and weights of each wave column and row are computed
 * once. A frame first up-samples each SPH row along x (Y_SPH x X_WE values,
 * the only gathers), then blends two such rows per wave row: a unit-stride
 * loop, vectorised (omp simd), which streams the wave field once. Outside
 * the outermost SPH cell centres the edge value is held. */
#include <string.h>

#include "sim/sim_internal.h"
#include "surface/surface_internal.h"

static ms_status taps(ms_sim *sim, int n_out, int n_in, int **i0, int **i1, float **w)
{
    *i0 = ms_alloc_array((size_t)n_out, sizeof **i0);
    *i1 = ms_alloc_array((size_t)n_out, sizeof **i1);
    *w = ms_alloc_array((size_t)n_out, sizeof **w);
    if (!*i0 || !*i1 || !*w)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for the up-sampling taps");
    sim->own_surface_bytes += (size_t)n_out * (2 * sizeof **i0 + sizeof **w);
    for (int i = 0; i < n_out; ++i) {
        /* the wave cell centre in SPH-cell units, from the SPH cell centres */
        double u = ((double)i + 0.5) * n_in / n_out - 0.5;
        int a = (int)floor(u);
        double f = u - a;
        if (u <= 0) {
            a = 0;
            f = 0;
        } else if (a >= n_in - 1) {
            a = n_in - 1;
            f = 0;
        }
        (*i0)[i] = a;
        (*i1)[i] = a + 1 < n_in ? a + 1 : a;
        (*w)[i] = (float)f;
    }
    return MS_OK;
}

ms_status ms_sim_upsample_init(ms_sim *sim)
{
    ms_status st = taps(sim, sim->snx, sim->fnx, &sim->ix0, &sim->ix1, &sim->wx);
    if (st == MS_OK)
        st = taps(sim, sim->sny, sim->fny, &sim->iy0, &sim->iy1, &sim->wy);
    if (st == MS_OK) {
        size_t n = (size_t)sim->fny * sim->snx; /* the SPH rows up-sampled along x */
        sim->rowtmp = ms_alloc_array(n, sizeof *sim->rowtmp);
        if (!sim->rowtmp)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for the up-sampling");
        sim->own_surface_bytes += n * sizeof *sim->rowtmp;
    }
    return st;
}

void ms_sim_upsample_free(ms_sim *sim)
{
    ms_free(sim->ix0);
    ms_free(sim->ix1);
    ms_free(sim->iy0);
    ms_free(sim->iy1);
    ms_free(sim->wx);
    ms_free(sim->wy);
    ms_free(sim->rowtmp);
}

/* xrows[j*snx + i] = the SPH row j at wave column i. */
static void upsample_x(const ms_sim *sim, const float *field, float *restrict xrows)
{
    const int *restrict ix0 = sim->ix0, *restrict ix1 = sim->ix1;
    const float *restrict wx = sim->wx;
    for (int j = 0; j < sim->fny; ++j) {
        const float *restrict f = field + (size_t)j * sim->fnx;
        float *restrict o = xrows + (size_t)j * sim->snx;
        for (int i = 0; i < sim->snx; ++i) {
            float a = f[ix0[i]], b = f[ix1[i]];
            o[i] = a + wx[i] * (b - a);
        }
    }
}

void ms_sim_upsample(const ms_sim *sim, const float *field, float *xrows, float *out)
{
    upsample_x(sim, field, xrows);
    const int n = sim->snx;
    for (int j = 0; j < sim->sny; ++j) {
        const float *restrict a = xrows + (size_t)sim->iy0[j] * n;
        const float *restrict b = xrows + (size_t)sim->iy1[j] * n;
        const float wy = sim->wy[j];
        float *restrict o = out + (size_t)j * n;
#pragma omp simd
        for (int i = 0; i < n; ++i)
            o[i] = a[i] + wy * (b[i] - a[i]);
    }
}

void ms_sim_upsample_add(const ms_sim *sim, const float *field, const float *wave, float add,
                         float *xrows, float *out)
{
    upsample_x(sim, field, xrows);
    const int n = sim->snx;
    for (int j = 0; j < sim->sny; ++j) {
        const float *restrict a = xrows + (size_t)sim->iy0[j] * n;
        const float *restrict b = xrows + (size_t)sim->iy1[j] * n;
        const float wy = sim->wy[j];
        const float *restrict w = wave + (size_t)j * n;
        float *restrict o = out + (size_t)j * n;
#pragma omp simd
        for (int i = 0; i < n; ++i)
            o[i] = (a[i] + wy * (b[i] - a[i])) + w[i] + add;
    }
}

/* 3.5's impulse up(e) added to the wave solver's f^n and v in its own
 * padded rows (an impulse: f^{n-1} stays), as ms_surface_excite(up(e), 1)
 * does, in one pass instead of three (up-sample into a scratch field, the
 * check of every wave cell, the sum): the same sums, so the same
 * bits. Up-sampled values are convex combinations of e, so checking the
 * fnx * fny values of e bounds them all; a value that is not finite or
 * not below 1e30 m takes the checked path, which refuses it. */
ms_status ms_sim_upsample_excite(ms_sim *sim, const float *e, ms_surface *s)
{
    const size_t nf = (size_t)sim->fnx * sim->fny;
    int ok = 1;
    for (size_t c = 0; c < nf; ++c)
        ok &= fabsf(e[c]) <= 1e30f; /* false for NaN */
    if (!ok) {
        ms_sim_upsample(sim, e, sim->rowtmp, sim->excite);
        return ms_surface_excite(s, sim->excite, 1.0f);
    }
    float *xrows = sim->rowtmp;
    upsample_x(sim, e, xrows);
    const int n = sim->snx;
    for (int j = 0; j < sim->sny; ++j) {
        const float *restrict a = xrows + (size_t)sim->iy0[j] * n;
        const float *restrict b = xrows + (size_t)sim->iy1[j] * n;
        const float wy = sim->wy[j];
        float *restrict h = s->h + ms_surface_at(s, 0, j);
        float *restrict v = s->v + ms_surface_at(s, 0, j);
#pragma omp simd
        for (int i = 0; i < n; ++i) {
            const float x = a[i] + wy * (b[i] - a[i]); /* m */
            h[i] += x;
            v[i] += x;
        }
    }
    ms_surface_zero_solid(s, s->h);
    ms_surface_zero_solid(s, s->v);
    s->view_dirty = 1;
    return MS_OK;
}

/* The runs of wave columns per SPH column: run c is [r0[c], r0[c + 1])
 * (wave_colmap is non-decreasing). */
static void column_runs(const ms_sim *sim, int *r0)
{
    const int *map = sim->wave_colmap;
    int i = 0;
    for (int c = 0; c < sim->fnx; ++c) {
        r0[c] = i;
        while (i < sim->snx && map[i] == c)
            ++i;
    }
    r0[sim->fnx] = i;
}

/* The average of the wave field per SPH cell, one wave row at a time: each
 * SPH cell sums its wave cells row by row, left to right, as
 * dst[map[i]] += src[i] does (the same additions in the same order: the
 * same bits), over the runs of wave columns per SPH column. */
typedef struct avg_state {
    int r0[4097]; /* field_nx <= 4096 (create.c) */
    int row, count_y;
} avg_state;

static void avg_begin(const ms_sim *sim, avg_state *st, float *out)
{
    size_t nf = (size_t)sim->fnx * sim->fny;
    memset(sim->wave_rowsum, 0, nf * sizeof *sim->wave_rowsum);
    memset(out, 0, nf * sizeof *out); /* SPH cells no wave cell centre falls in */
    column_runs(sim, st->r0);
    st->row = 0;
    st->count_y = 0;
}

static void avg_flush(const ms_sim *sim, const avg_state *st, float *out)
{
    const int fnx = sim->fnx;
    const float *acc = sim->wave_rowsum + (size_t)st->row * fnx;
    for (int c = 0; c < fnx; ++c) {
        const int count_x = st->r0[c + 1] - st->r0[c];
        /* a column no wave cell centre falls in (a wave grid coarser than
         * the SPH field) is 0, as the rows are, not 0 / 0 */
        out[(size_t)st->row * fnx + c] =
            st->count_y && count_x ? acc[c] / (float)(st->count_y * count_x) : 0.0f;
    }
}

/* acc[c] += the wave cells of run c, left to right: a chain of additions a
 * SPH cell, but the chains of different cells are independent, so they
 * overlap in the core. Measured on fig1's 400 x 50 rows (AMD EPYC, one
 * thread): 55 us a frame, against 70 for the run loop that compared each
 * wave column's SPH column and 77-105 for the loop across
 * SPH columns with gathers (hardware or emulated: gathers are slow here). */
static void run_sums(float *restrict acc, const float *restrict src, const int *restrict r0,
                     int fnx)
{
    for (int c = 0; c < fnx; ++c) {
        float t = acc[c];
        for (int i = r0[c]; i < r0[c + 1]; ++i)
            t += src[i];
        acc[c] = t;
    }
}

static void avg_row(const ms_sim *sim, avg_state *st, int j, const float *src, float *out)
{
    const int fnx = sim->fnx;
    const int r = (int)(((2L * j + 1) * sim->fny) / (2L * sim->sny));
    if (r != st->row) {
        avg_flush(sim, st, out);
        st->row = r;
        st->count_y = 0;
    }
    ++st->count_y;
    run_sums(sim->wave_rowsum + (size_t)r * fnx, src, st->r0, fnx);
}

void ms_sim_average_waves(ms_sim *sim, const float *w, float *out)
{
    avg_state st;
    avg_begin(sim, &st, out);
    for (int j = 0; j < sim->sny; ++j)
        avg_row(sim, &st, j, w + (size_t)j * sim->snx, out);
    avg_flush(sim, &st, out);
}

/* Eq. 20 and the average for the volume in one pass over the wave field,
 * read in the solver's padded rows (stride floats apart, no copy into its
 * view): out = up(field) + wave, and, when avg is not NULL, the wave field
 * averaged per SPH cell (ms_sim_average_waves) while each row is in L1.
 * The same operations per value as ms_sim_upsample_add(.., 0, ..) and
 * ms_sim_average_waves: the same bits. */
void ms_sim_combine(ms_sim *sim, const float *field, const float *wave, size_t stride, float *out,
                    float *avg)
{
    upsample_x(sim, field, sim->rowtmp);
    avg_state st;
    if (avg)
        avg_begin(sim, &st, avg);
    const int n = sim->snx;
    const float add = 0.0f; /* m: as ms_sim_upsample_add(.., 0, ..) */
    for (int j = 0; j < sim->sny; ++j) {
        const float *restrict a = sim->rowtmp + (size_t)sim->iy0[j] * n;
        const float *restrict b = sim->rowtmp + (size_t)sim->iy1[j] * n;
        const float wy = sim->wy[j];
        const float *restrict w = wave + (size_t)j * stride;
        float *restrict o = out + (size_t)j * n;
#pragma omp simd
        for (int i = 0; i < n; ++i) {
            const float u = a[i] + wy * (b[i] - a[i]);    /* m, up(H) */
            const float lim = MS_SIM_WAVE_DEPTH_FRAC * u; /* m, >= 0 */
            const float wc = w[i] < -lim ? -lim : (w[i] > lim ? lim : w[i]);
            o[i] = u + wc + add;
        }
        if (avg)
            avg_row(sim, &st, j, w, avg);
    }
    if (avg)
        avg_flush(sim, &st, avg);
}

/* The waves ride on the liquid (3.5): W is a perturbation of the SPH
 * surface, so it lives only where up(H) holds liquid, and it carries no
 * volume of its own. Once a frame, after the wave steps and before the sum:
 *  - on a dry cell (up(H) = 0: the extraction found no liquid in the
 *    column) W and its previous step are set to 0, so no wave runs over a
 *    dry floor (a moved glass's ripples stayed on the floor around it);
 *  - the mean of W over the wet, non-solid cells is taken out of W (its
 *    last displacement v, the wave velocity, is kept). The coupling's
 *    impulses are zero-mean over the SPH field, but the parts falling on
 *    solid or dry cells are dropped, and the wave equation keeps a
 *    uniform offset for ever (damping acts on the velocity): a spinning
 *    paddle drove W's mean down by 3 cm a second, and with it the slopes;
 *  - ms_sim_combine bounds what W adds: |W| <= MS_SIM_WAVE_DEPTH_FRAC of
 *    the local depth up(H), so a trough never reaches the floor where
 *    there is liquid: combined >= (1 - MS_SIM_WAVE_DEPTH_FRAC) up(H).
 * Sums in double, row by row: the same bytes for any thread count. */
void ms_sim_waves_on_liquid(ms_sim *sim, const float *field)
{
    ms_surface *s = sim->surface;
    upsample_x(sim, field, sim->rowtmp);
    const int n = sim->snx;
    double sum = 0.0;
    long wet = 0;
    for (int j = 0; j < sim->sny; ++j) {
        const float *restrict a = sim->rowtmp + (size_t)sim->iy0[j] * n;
        const float *restrict b = sim->rowtmp + (size_t)sim->iy1[j] * n;
        const float wy = sim->wy[j];
        const size_t at = ms_surface_at(s, 0, j);
        float *restrict h = s->h + at, *restrict v = s->v + at;
        const unsigned char *solid = s->solid ? s->solid + at : NULL;
        double rs = 0.0;
        long rw = 0;
        for (int i = 0; i < n; ++i) {
            const float u = a[i] + wy * (b[i] - a[i]); /* m, up(H) */
            if (!(u > 0.0f)) {
                h[i] = 0.0f;
                v[i] = 0.0f;
            } else if (!solid || !solid[i]) {
                rs += h[i];
                rw++;
            }
        }
        sum += rs;
        wet += rw;
    }
    if (wet > 0) {
        const float mean = (float)(sum / (double)wet);
        for (int j = 0; j < sim->sny; ++j) {
            const float *restrict a = sim->rowtmp + (size_t)sim->iy0[j] * n;
            const float *restrict b = sim->rowtmp + (size_t)sim->iy1[j] * n;
            const float wy = sim->wy[j];
            const size_t at = ms_surface_at(s, 0, j);
            float *restrict h = s->h + at;
            const unsigned char *solid = s->solid ? s->solid + at : NULL;
            for (int i = 0; i < n; ++i) {
                const float u = a[i] + wy * (b[i] - a[i]);
                if (u > 0.0f && (!solid || !solid[i]))
                    h[i] -= mean;
            }
        }
    }
    s->view_dirty = 1;
}
