/* Eq. 20 and Fig. 7: the SPH height field (X_SPH x Y_SPH cells) is
 * up-sampled bilinearly onto the wave grid (X_WE x Y_WE) and summed with
 * the wave field. Both grids span the domain's x-y extent with cell
 * centres at (i + 0.5) * cell size; N_surf = X_WE / X_SPH need not be an
 * integer. The taps and weights of each wave column and row are computed
 * once. A frame first up-samples each SPH row along x (Y_SPH x X_WE values,
 * the only gathers), then blends two such rows per wave row: a unit-stride
 * loop, vectorised (omp simd), which streams the wave field once. Outside
 * the outermost SPH cell centres the edge value is held. */
#include "sim/sim_internal.h"

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
