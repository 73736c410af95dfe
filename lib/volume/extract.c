/* Free-surface extraction (paper 3.3.2): the liquid's 2.5D height field.
 *
 * Eqs. 16, 17: the potential of spheres of iso-radius R = h around the
 * particles,
 *     phi(x) = sum_i sqrt(1 - r_i^2 / R^2),   r_i = |x - x_i| < R,
 * and the height of a column is the topmost z where phi reaches the
 * iso-level T. "Just surface particles and their neighbours contribute":
 * surface particles are those with fewer than 3/4 of the neighbours of a
 * particle inside the liquid (the neighbour count of the density pass);
 * they and every particle within h of one are the spheres. T is the phi of
 * a still cubic lattice at half a spacing above its top layer (averaged
 * over where the column lies between particles), so a flat liquid's height
 * is its volume over its area. The domain's side walls mirror the spheres
 * (the wall is a collider, the liquid goes on in its image), so the field
 * does not sag at the walls.
 *
 * Eq. 18, adaptive smoothing. The paper: "If E_kin exceeds a defined
 * threshold, no smoothing occurs. Below this threshold, the number of
 * smoothing steps is increased as E_kin increases until the maximum number
 * of smoothing steps is reached. Thus, still liquids occur to be flat and
 * turbulent liquids remain detailed." Read literally the middle sentence
 * gives a still liquid (E_kin = 0) no smoothing, against the last
 * sentence; what it means, and what is done here, is the opposite ramp:
 *     steps = smooth_steps * (1 - e / smooth_energy)   for e < smooth_energy,
 *     steps = 0                                        above,
 * with e = E_kin / total mass (J/kg, so the threshold does not depend on
 * the particle count). A fractional step blends one more pass in, so the
 * field does not jump as e crosses an integer step. One pass is a 3 x 3
 * binomial filter over the cells that hold liquid (dry cells stay 0 and
 * do not pull the shore down).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "volume/volume_impl.h"

/* Column phi of a still lattice at half a spacing above the top layer. */
float ms_volume_iso_level(const ms_volume *v)
{
    const double s = v->desc.spacing, R = v->K.h;
    const int r = (int)ceil(R / s) + 1;
    double total = 0.0;
    const int sub = 4;
    for (int oy = 0; oy < sub; ++oy)
        for (int ox = 0; ox < sub; ++ox) {
            double px = s * ox / sub, py = s * oy / sub;
            for (int k = 0; k <= r; ++k)
                for (int j = -r; j <= r; ++j)
                    for (int i = -r; i <= r; ++i) {
                        double dx = i * s - px, dy = j * s - py, dz = (k + 0.5) * s;
                        double q = 1.0 - (dx * dx + dy * dy + dz * dz) / (R * R);
                        if (q > 0.0)
                            total += sqrt(q);
                    }
        }
    return (float)(total / (sub * sub));
}

static ms_status scratch(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return MS_OK;
    void *q = ms_alloc_array(need, size);
    if (!q)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for height extraction");
    ms_free(*p);
    *p = q;
    *cap = need;
    return MS_OK;
}

typedef struct mark_ctx {
    ms_volume *v;
} mark_ctx;

/* mark[i] = 1 surface particle, 2 within h of one, 0 neither (a gather). */
static void mark_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    ms_volume *v = ((mark_ctx *)ctxp)->v;
    const int *start = v->cell_start;
    const long sx = v->gx, sxy = (long)v->gx * v->gy;
    const float h2 = v->K.h2;
    for (int i = b; i < e; ++i) {
        if (ms_volume_is_surface(v, i)) {
            v->mark[i] = 1;
            continue;
        }
        int near = 0;
        const long c = v->cell[i];
        for (int dz = -1; dz <= 1 && !near; ++dz)
            for (int dy = -1; dy <= 1 && !near; ++dy) {
                const long row = c + dz * sxy + dy * sx;
                for (int j = start[row - 1]; j < start[row + 2]; ++j) {
                    float dx = v->x[i] - v->x[j], dyy = v->y[i] - v->y[j],
                          dzz = v->z[i] - v->z[j];
                    if (ms_volume_is_surface(v, j) && dx * dx + dyy * dyy + dzz * dzz < h2) {
                        near = 1;
                        break;
                    }
                }
            }
        v->mark[i] = near ? 2 : 0;
    }
}

/* phi (eq. 16) at height z of a column whose candidates are (zc, a), with
 * a = 1 - horizontal distance^2 / R^2; m is padded to a multiple of the
 * lanes with a = 0 (weight 0). Summed in lanes: vectorisable, fixed order. */
static float phi_at(const float *restrict zc, const float *restrict a, int m, float z,
                    float inv_r2)
{
    enum { L = MS_VOLUME_LANES };
    float acc[L] = {0};
    for (int k = 0; k < m; k += L)
        for (int l = 0; l < L; ++l) {
            float d = z - zc[k + l];
            float q = a[k + l] - d * d * inv_r2;
            q = q > 0.0f ? q : 0.0f;
            acc[l] += sqrtf(q);
        }
    float sum = 0.0f;
    for (int l = 0; l < L; ++l)
        sum += acc[l];
    return sum;
}

ms_status ms_volume_extract_height(ms_volume *v, int nx, int ny, float *out)
{
    if (!v || !out)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: extract_height needs a volume and out");
    if (nx < 1 || ny < 1 || nx > 4096 || ny > 4096)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: extract_height grid %d x %d is outside 1 .. 4096 per side", nx,
                       ny);
    const size_t cells = (size_t)nx * ny;
    memset(out, 0, cells * sizeof *out);
    if (v->n == 0)
        return MS_OK;
    if (!v->counts_valid) {
        ms_volume_grid_build(v);
        ms_status st = ms_volume_count_neighbours(v);
        if (st != MS_OK)
            return st;
    }
    mark_ctx mc = {.v = v};
    ms_vpool_run(v->pool, mark_part, &mc, v->n);

    const float *lo = v->desc.domain_min, *hi = v->desc.domain_max;
    const float dxe = (hi[0] - lo[0]) / (float)nx, dye = (hi[1] - lo[1]) / (float)ny;
    const float R = v->K.h, R2 = R * R, inv_r2 = 1.0f / R2;

    /* bin the marked particles by column (counting sort, stable) */
    int m = 0;
    for (int i = 0; i < v->n; ++i)
        m += v->mark[i] != 0;
    ms_status st = scratch((void **)&v->ex_start, &v->ex_start_cap, cells + 1, sizeof(int));
    if (st == MS_OK)
        st = scratch((void **)&v->ex_list, &v->ex_list_cap, (size_t)m + cells + 1, sizeof(int));
    /* ex_buf: 3m binned positions, 2 x 4m candidates (mirrors), 3 fields */
    if (st == MS_OK)
        st = scratch((void **)&v->ex_buf, &v->ex_cap,
                     3 * (size_t)m + 8 * ((size_t)m + MS_VOLUME_LANES) + 3 * cells, sizeof(float));
    if (st != MS_OK)
        return st;
    int *cstart = v->ex_start, *ckey = v->ex_list, *cfill = v->ex_list + m;
    float *bx = v->ex_buf, *by = bx + m, *bz = by + m;
    float *cz = bz + m, *ca = cz + 4 * ((size_t)m + MS_VOLUME_LANES);
    float *raw = ca + 4 * ((size_t)m + MS_VOLUME_LANES), *tmp = raw + cells, *blend = tmp + cells;
    memset(cfill, 0, cells * sizeof *cfill);
    for (int i = 0, k = 0; i < v->n; ++i) {
        if (!v->mark[i])
            continue;
        int ix = (int)fminf(fmaxf((v->x[i] - lo[0]) / dxe, 0.0f), (float)(nx - 1));
        int iy = (int)fminf(fmaxf((v->y[i] - lo[1]) / dye, 0.0f), (float)(ny - 1));
        ckey[k] = iy * nx + ix;
        cfill[ckey[k]]++;
        k++;
    }
    int sum = 0;
    for (size_t c = 0; c < cells; ++c) {
        cstart[c] = sum;
        sum += cfill[c];
        cfill[c] = cstart[c];
    }
    cstart[cells] = sum;
    for (int i = 0, k = 0; i < v->n; ++i) {
        if (!v->mark[i])
            continue;
        int d = cfill[ckey[k++]]++;
        bx[d] = v->x[i];
        by[d] = v->y[i];
        bz[d] = v->z[i];
    }

    /* the topmost crossing of phi = T in every column */
    const int rx = (int)ceilf(R / dxe), ry = (int)ceilf(R / dye);
    const float T = v->iso_level, dz = 0.25f * v->desc.spacing;
    const float ztop = hi[2] - lo[2];
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const float px = lo[0] + ((float)i + 0.5f) * dxe, py = lo[1] + ((float)j + 0.5f) * dye;
            int mc2 = 0;
            const float wx = px - lo[0] <= hi[0] - px ? lo[0] : hi[0];
            const float wy = py - lo[1] <= hi[1] - py ? lo[1] : hi[1];
            const int nxm = fabsf(px - wx) < R ? 2 : 1, nym = fabsf(py - wy) < R ? 2 : 1;
            float zmax = -INFINITY, zmin = INFINITY;
            for (int jj = j - ry; jj <= j + ry; ++jj) {
                if (jj < 0 || jj >= ny)
                    continue;
                for (int ii = i - rx; ii <= i + rx; ++ii) {
                    if (ii < 0 || ii >= nx)
                        continue;
                    int c = jj * nx + ii;
                    for (int k = cstart[c]; k < cstart[c + 1]; ++k) {
                        /* the particle and its image in the nearer side wall */
                        float ex[2] = {bx[k] - px, 2.0f * wx - bx[k] - px};
                        float ey[2] = {by[k] - py, 2.0f * wy - by[k] - py};
                        for (int my = 0; my < nym; ++my)
                            for (int mx = 0; mx < nxm; ++mx) {
                                float a = 1.0f - (ex[mx] * ex[mx] + ey[my] * ey[my]) * inv_r2;
                                if (a <= 0.0f)
                                    continue;
                                cz[mc2] = bz[k];
                                ca[mc2] = a;
                                float top = bz[k] + R * sqrtf(a);
                                zmax = fmaxf(zmax, top);
                                zmin = fminf(zmin, bz[k] - R * sqrtf(a));
                                mc2++;
                            }
                    }
                }
            }
            float height = 0.0f;
            for (int pad = mc2; pad % MS_VOLUME_LANES; ++pad) { /* weight-0 lanes */
                cz[pad] = 0.0f;
                ca[pad] = 0.0f;
            }
            mc2 = (mc2 + MS_VOLUME_LANES - 1) / MS_VOLUME_LANES * MS_VOLUME_LANES;
            if (mc2 > 0) {
                float za = zmax, zb = zmax; /* phi(za) < T <= phi(zb) */
                int found = 0;
                for (float z = zmax; z >= zmin; z -= dz) {
                    if (phi_at(cz, ca, mc2, z, inv_r2) >= T) {
                        zb = z;
                        found = 1;
                        break;
                    }
                    za = z;
                }
                if (found) {
                    for (int it = 0; it < 7; ++it) { /* to dz / 128 */
                        float zm = 0.5f * (za + zb);
                        if (phi_at(cz, ca, mc2, zm, inv_r2) >= T)
                            zb = zm;
                        else
                            za = zm;
                    }
                    height = fminf(fmaxf(0.5f * (za + zb) - lo[2], 0.0f), ztop);
                }
            }
            raw[(size_t)j * nx + i] = height;
        }

    /* eq. 18: the number of smoothing passes from E_kin / total mass */
    double e = ms_volume_kinetic_energy(v) / ((double)v->mass * v->n);
    double ramp = 1.0 - e / v->desc.smooth_energy;
    double steps = ramp > 0.0 ? v->desc.smooth_steps * ramp : 0.0;
    int full = (int)floor(steps);
    float frac = (float)(steps - full);
    memcpy(out, raw, cells * sizeof *out);
    for (int pass = 0; pass < full + (frac > 0.0f); ++pass) {
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                size_t c = (size_t)j * nx + i;
                if (raw[c] <= 0.0f) {
                    tmp[c] = 0.0f;
                    continue;
                }
                float s = 0.0f, w = 0.0f;
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di) {
                        int ii = i + di, jj = j + dj;
                        if (ii < 0 || ii >= nx || jj < 0 || jj >= ny)
                            continue;
                        size_t cc = (size_t)jj * nx + ii;
                        if (raw[cc] <= 0.0f)
                            continue;
                        float wk = (float)((2 - abs(di)) * (2 - abs(dj)));
                        s += wk * out[cc];
                        w += wk;
                    }
                tmp[c] = s / w;
            }
        if (pass < full) {
            memcpy(out, tmp, cells * sizeof *out);
        } else { /* the fractional pass: blend it in */
            for (size_t c = 0; c < cells; ++c)
                blend[c] = out[c] + frac * (tmp[c] - out[c]);
            memcpy(out, blend, cells * sizeof *out);
        }
    }
    return MS_OK;
}
