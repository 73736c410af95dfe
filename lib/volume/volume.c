/* The ms_volume handle: creation (the constants of the model), particles in
 * and out, statistics. The time stepping is in step.c. */
#include <math.h>
#include <string.h>

#include <stdatomic.h>

#include "volume/extract.h"
#include "volume/volume_internal.h"
#include "volume/volume_sizes.h"

/* Mass per particle such that a cubic lattice of the desc's spacing has
 * exactly the rest density under eq. 9: m = rho0 / sum W. */
static double lattice_mass(const ms_volume_desc *d)
{
    double h = d->smoothing_length, s = d->spacing, sum = 0.0;
    int r = (int)ceil(h / s);
    for (int k = -r; k <= r; ++k)
        for (int j = -r; j <= r; ++j)
            for (int i = -r; i <= r; ++i)
                sum += ms_density_kernel_d(d->density_kernel == MS_DENSITY_POLY6, h,
                                           s * sqrt((double)(i * i + j * j + k * k)));
    return d->rest_density / sum;
}

/* The first moment of eq. 13's kernel gradient on the lattice the mass is
 * calibrated on: M = sum_j V (z_j - z_i) dW/dz_i (x_i - x_j), V = m/rho0.
 * It is 1 in the continuum (the gradient of a linear field is exact); at
 * h = 2 spacing it is about 0.78. */
static double gradient_moment(const ms_volume_desc *d, double mass)
{
    double h = d->smoothing_length, s = d->spacing, sum = 0.0;
    double c = 45.0 / (MS_PI_D * h * h * h * h * h * h), vol = mass / d->rest_density;
    int r = (int)ceil(h / s);
    for (int k = -r; k <= r; ++k)
        for (int j = -r; j <= r; ++j)
            for (int i = -r; i <= r; ++i) {
                double rr = s * sqrt((double)(i * i + j * j + k * k));
                if (rr <= 0.0 || rr >= h)
                    continue;
                double z = s * k;
                sum += vol * c * (h - rr) * (h - rr) * z * z / rr;
            }
    return sum;
}

ms_status ms_volume_create(const ms_volume_desc *d, ms_volume **out)
{
    if (!out)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: out is NULL");
    *out = NULL;
    ms_volume_desc desc = ms_volume_desc_default();
    ms_status st = ms_struct_in(d, &desc, MS_SIZES_VOLUME_DESC, "volume");
    if (st != MS_OK || (st = ms_volume_desc_check(&desc)) != MS_OK)
        return st;
    d = &desc;
    ms_volume *v = ms_alloc(sizeof *v);
    if (!v)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for the handle");
    v->desc = *d;
    double h = d->smoothing_length, s = d->spacing;
    v->K = ms_sph_kernels_make(h);
    v->mass = (float)lattice_mass(d);
    /* eq. 13's (p_i + p_j)/2 halves the continuum gradient (sum_j V_j p_i
     * grad W is ~0, sum_j V_j p_j grad W is grad p) and the lattice
     * moment M scales it again: 2/M makes the force -grad p / rho, so the
     * pressure law's p is the pressure the liquid exerts. */
    v->press_scale = (float)(2.0 / gradient_moment(d, v->mass));
    v->c0 = d->pressure == MS_PRESSURE_IDEAL_GAS ? sqrtf(d->gas_constant) : d->sound_speed;
    v->tait_b = (float)((double)d->rest_density * v->c0 * v->c0 / 7.0);
    v->col_range = (float)(0.5 * s);
    v->col_accel = (float)((double)v->c0 * v->c0 / h);
    v->col_damp = 2.0f * sqrtf(2.0f * v->col_accel / v->col_range);
    if (d->pressure == MS_PRESSURE_DFSPH) {
        /* No eq. 15 penalty field under DFSPH: its stiffness c^2/h would
         * bound the step at the sound speed's CFL, the bound DFSPH lifts.
         * The walls and shapes still take part in the density (their
         * images) and the solve keeps the liquid out of them; the swept
         * test still stops every particle at them. */
        v->col_accel = 0.0f;
        v->col_damp = 0.0f;
    }
    v->surface_nbrs = (float)(0.75 * 4.0 / 3.0 * MS_PI_D * pow(h / s, 3.0));
    v->eps2 = (float)(1e-10 * h * h);
    v->inv_h = (float)(1.0 / h);
    v->gx = (int)ceil((d->domain_max[0] - d->domain_min[0]) / h) + 2;
    v->gy = (int)ceil((d->domain_max[1] - d->domain_min[1]) / h) + 2;
    v->gz = (int)ceil((d->domain_max[2] - d->domain_min[2]) / h) + 2;
    v->ncells = (long)v->gx * v->gy * v->gz;
    v->cell_start = ms_alloc_array((size_t)v->ncells + 1, sizeof(int));
    v->cell_fill = ms_alloc_array((size_t)v->ncells, sizeof(int));
    if (!v->cell_start || !v->cell_fill) {
        ms_volume_destroy(v);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for %ld grid cells", v->ncells);
    }
    st = ms_volume_choose_isa(&v->isa);
    if (st != MS_OK) {
        ms_volume_destroy(v);
        return st;
    }
    st = ms_vpool_create(d->threads, &v->pool);
    if (st != MS_OK) {
        ms_volume_destroy(v);
        return st;
    }
    v->iso_level = ms_volume_iso_level(v);
    v->dt_limit = "cfl";
    v->max_dt = (float)(d->courant * h / v->c0);
    *out = v;
    return MS_OK;
}

static void free_particles(ms_volume *v)
{
    float **f[] = {&v->x,           &v->y,    &v->z,       &v->vx,      &v->vy,    &v->vz,
                   &v->x2,          &v->y2,   &v->z2,      &v->vx2,     &v->vy2,   &v->vz2,
                   &v->rho,         &v->prs,  &v->inv_rho, &v->ax,      &v->ay,    &v->az,
                   &v->visc_rate,   &v->b_ax, &v->b_ay,    &v->b_az,    &v->c_d,   &v->c_w,
                   &v->c_nx,        &v->c_ny, &v->c_nz,    &v->c_vx,    &v->c_vy,  &v->c_vz,
                   &v->df_inv_diag, &v->df_s, &v->df_sum,  &v->df_warm, &v->df_wx, &v->df_wy,
                   &v->df_wz};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; ++k) {
        ms_free(*f[k]);
        *f[k] = NULL;
    }
    ms_free(v->id);
    ms_free(v->id2);
    ms_free(v->nbr);
    ms_free(v->nl_begin);
    ms_free(v->nl_count);
    ms_free(v->gl_begin);
    ms_free(v->gl_count);
    ms_free(v->cell);
    ms_free(v->mark);
    ms_free(v->pk);
    ms_free(v->pub);
    v->pk = v->pub = NULL;
    ms_free(v->df_div_sum); /* the DFSPH pressure read-out's (dfsph.c) */
    ms_free(v->df_pmean);
    v->df_div_sum = v->df_pmean = NULL;
    v->id = v->id2 = v->nbr = v->cell = NULL;
    v->nl_begin = v->nl_count = v->gl_begin = v->gl_count = NULL;
    v->mark = NULL;
}

void ms_volume_destroy(ms_volume *v)
{
    if (!v)
        return;
    ms_vpool_destroy(v->pool);
    free_particles(v);
    ms_free(v->cell_start);
    ms_free(v->cell_fill);
    ms_free(v->grid_hist);
    ms_free(v->wave_prev);
    ms_free(v->ex_buf);
    ms_free(v->ex_start);
    ms_free(v->ex_list);
    ms_extract_work_free(&v->ex_verify);
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) {
        ms_free(v->lists[p].idx);
        ms_free(v->lists[p].r2);
        ms_free(v->ghosts[p].idx);
        ms_free(v->ghosts[p].r2);
        ms_free(v->cand[p]);
        ms_free(v->cand_idx[p]);
        ms_free(v->df_grad[p]);
        ms_free(v->df_img[p]);
    }
    ms_free(v);
}

/* Room for n particles (n <= max_particles); state arrays are copied. */
ms_status ms_volume_reserve(ms_volume *v, int n)
{
    if (n <= v->cap)
        return MS_OK;
    long want = (long)v->cap * 2;
    if (want < n)
        want = n;
    if (want < 1024)
        want = 1024;
    if (want > v->desc.max_particles)
        want = v->desc.max_particles;
    size_t cap = (size_t)want;
    size_t alloc = cap + MS_VOLUME_LANES; /* padding of the pair loops */
    ms_volume t = *v;
    float **state[] = {&t.x, &t.y, &t.z, &t.vx, &t.vy, &t.vz};
    float **other[] = {
        &t.x2,          &t.y2,   &t.z2,     &t.vx2,     &t.vy2,       &t.vz2,   &t.rho,  &t.prs,
        &t.inv_rho,     &t.ax,   &t.ay,     &t.az,      &t.visc_rate, &t.b_ax,  &t.b_ay, &t.b_az,
        &t.c_d,         &t.c_w,  &t.c_nx,   &t.c_ny,    &t.c_nz,      &t.c_vx,  &t.c_vy, &t.c_vz,
        &t.df_inv_diag, &t.df_s, &t.df_sum, &t.df_warm, &t.df_wx,     &t.df_wy, &t.df_wz};
    t.df_warm_n = -1; /* the warm start's values are not copied */
    int ok = 1;
    for (size_t k = 0; k < sizeof state / sizeof state[0]; ++k) {
        float *p = ms_alloc_array(alloc, sizeof(float));
        if (p && v->n > 0)
            memcpy(p, *state[k], (size_t)v->n * sizeof(float));
        *state[k] = p;
        ok &= p != NULL;
    }
    for (size_t k = 0; k < sizeof other / sizeof other[0]; ++k) {
        *other[k] = ms_alloc_array(alloc, sizeof(float));
        ok &= *other[k] != NULL;
    }
    t.id = ms_alloc_array(alloc, sizeof(int));
    if (t.id && v->n > 0)
        memcpy(t.id, v->id, (size_t)v->n * sizeof(int));
    t.id2 = ms_alloc_array(alloc, sizeof(int));
    t.nbr = ms_alloc_array(alloc, sizeof(int));
    t.nl_begin = ms_alloc_array(alloc, sizeof(int));
    t.nl_count = ms_alloc_array(alloc, sizeof(int));
    t.gl_begin = ms_alloc_array(alloc, sizeof(int));
    t.gl_count = ms_alloc_array(alloc, sizeof(int));
    t.cell = ms_alloc_array(alloc, sizeof(int));
    t.mark = ms_alloc_array(alloc, 1);
    t.pk = ms_alloc_array(8 * alloc, sizeof(float));
    /* the published block: same capacity, filled by the caller's publish */
    t.pub = v->pub_on ? ms_alloc_array(6 * cap, sizeof(float)) : NULL;
    ok &= !v->pub_on || t.pub;
    ok &= t.id && t.id2 && t.nbr && t.nl_begin && t.nl_count && t.gl_begin && t.gl_count &&
          t.cell && t.mark && t.pk;
    /* the DFSPH pressure read-out's (dfsph.c); its running mean restarts */
    t.df_div_sum = ms_alloc_array(alloc, sizeof(float));
    t.df_pmean = ms_alloc_array(alloc, sizeof(float));
    t.df_pmean_n = -1;
    ok &= t.df_div_sum && t.df_pmean;
    if (!ok) {
        free_particles(&t);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for %zu particles", cap);
    }
    free_particles(v);
    *v = t;
    v->cap = (int)cap;
    v->counts_valid = 0;
    return MS_OK;
}

static ms_status check_room(const ms_volume *v, long add, const char *what)
{
    if (v->n + add > v->desc.max_particles)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: %s would make %ld particles; max_particles is %d", what, v->n + add,
                       v->desc.max_particles);
    return MS_OK;
}

ms_status ms_volume_add_particles(ms_volume *v, int n, const float *pos, const float *vel)
{
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: add_particles to a NULL volume");
    if (n < 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: add_particles count %d is negative", n);
    if (n == 0)
        return MS_OK;
    if (!pos)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: add_particles positions are NULL");
    ms_status st = check_room(v, n, "add_particles");
    if (st != MS_OK)
        return st;
    const float *lo = v->desc.domain_min, *hi = v->desc.domain_max;
    for (int i = 0; i < n; ++i) {
        const float *p = pos + 3 * (size_t)i;
        for (int k = 0; k < 3; ++k) {
            if (!isfinite(p[k]))
                return ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "volume: particle %d position is not finite (%g, %g, %g)", i, p[0],
                               p[1], p[2]);
            if (p[k] < lo[k] || p[k] > hi[k])
                return ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "volume: particle %d at (%g, %g, %g) m lies outside the domain "
                               "[%g, %g] x [%g, %g] x [%g, %g] m; nothing was added",
                               i, p[0], p[1], p[2], lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
        }
        if (vel) {
            const float *u = vel + 3 * (size_t)i;
            if (!isfinite(u[0]) || !isfinite(u[1]) || !isfinite(u[2]))
                return ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "volume: particle %d velocity is not finite (%g, %g, %g)", i, u[0],
                               u[1], u[2]);
        }
    }
    st = ms_volume_reserve(v, v->n + n);
    if (st != MS_OK)
        return st;
    for (int i = 0; i < n; ++i) {
        int k = v->n + i;
        v->x[k] = pos[3 * (size_t)i];
        v->y[k] = pos[3 * (size_t)i + 1];
        v->z[k] = pos[3 * (size_t)i + 2];
        v->vx[k] = vel ? vel[3 * (size_t)i] : 0.0f;
        v->vy[k] = vel ? vel[3 * (size_t)i + 1] : 0.0f;
        v->vz[k] = vel ? vel[3 * (size_t)i + 2] : 0.0f;
        v->id[k] = k;
    }
    v->n += n;
    v->counts_valid = 0;
    ms_volume_publish(v);
    return MS_OK;
}

ms_status ms_volume_fill_box(ms_volume *v, const float lo[3], const float hi[3])
{
    if (!v || !lo || !hi)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: fill_box needs a volume and lo, hi");
    float a[3], b[3];
    long cnt[3], total = 1;
    const float s = v->desc.spacing;
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(lo[k]) || !isfinite(hi[k]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "volume: fill_box corner %d is not finite (%g to %g m)", k, lo[k],
                           hi[k]);
        if (!(hi[k] > lo[k]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "volume: fill_box is empty along axis %d: %g to %g m needs hi > lo", k,
                           lo[k], hi[k]);
        a[k] = fmaxf(lo[k], v->desc.domain_min[k]);
        b[k] = fminf(hi[k], v->desc.domain_max[k]);
        double c = b[k] > a[k] ? floor((double)(b[k] - a[k]) / s + 1e-4) : 0.0;
        cnt[k] = (long)c;
        total *= cnt[k];
        if (total > (1L << 26))
            total = 1L << 26; /* saturate: refused below */
    }
    if (total == 0)
        return MS_OK;
    ms_status st = check_room(v, total, "fill_box");
    if (st != MS_OK)
        return st;
    st = ms_volume_reserve(v, v->n + (int)total);
    if (st != MS_OK)
        return st;
    int k = v->n;
    for (long iz = 0; iz < cnt[2]; ++iz)
        for (long iy = 0; iy < cnt[1]; ++iy)
            for (long ix = 0; ix < cnt[0]; ++ix) {
                v->x[k] = a[0] + ((float)ix + 0.5f) * s;
                v->y[k] = a[1] + ((float)iy + 0.5f) * s;
                v->z[k] = a[2] + ((float)iz + 0.5f) * s;
                v->vx[k] = v->vy[k] = v->vz[k] = 0.0f;
                v->id[k] = k;
                k++;
            }
    v->n = k;
    v->counts_valid = 0;
    ms_volume_publish(v);
    return MS_OK;
}

int ms_volume_count(const ms_volume *v)
{
    return v ? v->n : 0;
}

ms_status ms_volume_get_particles(const ms_volume *v, float *pos, float *vel)
{
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: get_particles of a NULL volume");
    for (int i = 0; i < v->n; ++i) {
        size_t o = 3 * (size_t)v->id[i];
        if (pos) {
            pos[o] = v->x[i];
            pos[o + 1] = v->y[i];
            pos[o + 2] = v->z[i];
        }
        if (vel) {
            vel[o] = v->vx[i];
            vel[o + 1] = v->vy[i];
            vel[o + 2] = v->vz[i];
        }
    }
    return MS_OK;
}

ms_status ms_volume_particle_views(const ms_volume *v, int *n, const float *pos[3],
                                   const float *vel[3])
{
    if (!v || !n)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: particle_views needs a volume and n");
    *n = v->n;
    if (pos) {
        pos[0] = v->x;
        pos[1] = v->y;
        pos[2] = v->z;
    }
    if (vel) {
        vel[0] = v->vx;
        vel[1] = v->vy;
        vel[2] = v->vz;
    }
    return MS_OK;
}

void ms_volume_publish(ms_volume *v)
{
    if (!v->pub)
        return;
    size_t c = (size_t)v->cap;
    float *const pos[3] = {v->pub, v->pub + c, v->pub + 2 * c};
    float *const vel[3] = {v->pub + 3 * c, v->pub + 4 * c, v->pub + 5 * c};
    ms_volume_copy_particles(v, pos, vel);
}

void ms_volume_copy_particles(const ms_volume *v, float *const pos[3], float *const vel[3])
{
    float *restrict px = pos[0], *restrict py = pos[1], *restrict pz = pos[2];
    float *restrict ux = vel[0], *restrict uy = vel[1], *restrict uz = vel[2];
    for (int i = 0; i < v->n; ++i) {
        int k = v->id[i];
        px[k] = v->x[i];
        py[k] = v->y[i];
        pz[k] = v->z[i];
        ux[k] = v->vx[i];
        uy[k] = v->vy[i];
        uz[k] = v->vz[i];
    }
}

ms_status ms_volume_particles(ms_volume *v, int *n, const float *pos[3], const float *vel[3])
{
    if (n)
        *n = 0;
    for (int a = 0; a < 3; ++a) {
        if (pos)
            pos[a] = NULL;
        if (vel)
            vel[a] = NULL;
    }
    ms_status st = ms_check_not_null("volume", "volume", v);
    if (st == MS_OK)
        st = ms_check_not_null("volume", "n", n);
    if (st != MS_OK)
        return st;
    if (!v->pub_on && v->cap > 0) {
        v->pub = ms_alloc_array(6 * (size_t)v->cap, sizeof(float));
        if (!v->pub)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "volume: out of memory for the views of %d particles", v->cap);
        v->pub_on = 1;
        ms_volume_publish(v);
    }
    v->pub_on = 1; /* with no storage yet, ms_volume_reserve makes the block */
    *n = v->n;
    size_t c = (size_t)v->cap;
    for (int a = 0; a < 3 && v->pub; ++a) {
        if (pos)
            pos[a] = v->pub + (size_t)a * c;
        if (vel)
            vel[a] = v->pub + (size_t)(3 + a) * c;
    }
    return MS_OK;
}

void ms_volume_get_info(const ms_volume *v, ms_volume_info *user)
{
    size_t size = ms_struct_out(user, MS_SIZES_VOLUME_INFO, "volume");
    if (!size)
        return;
    ms_volume_info info = ms_volume_info_init(), *out = &info;
    if (!v) {
        ms_struct_write(user, &info, size);
        return;
    }
    out->time = v->time;
    out->steps = v->steps;
    out->substeps = v->substeps;
    out->last_dt = v->last_dt;
    out->max_dt = v->max_dt;
    out->dt_limit = v->dt_limit;
    out->max_speed = v->max_speed;
    out->sound_speed = v->c0;
    out->max_density_error = v->max_density_error;
    out->particle_mass = v->mass;
    out->count = v->n;
    out->surface_count = v->surface_count;
    out->pairs = v->pairs;
    size_t per = 45 * sizeof(float) + 8 * sizeof(int) + 1; /* pk: 8 floats */
    out->bytes = sizeof *v + (size_t)v->cap * per + ((size_t)v->ncells * 2 + 1) * sizeof(int) +
                 v->wave_cap * sizeof(float) + v->ex_cap * sizeof(float) +
                 (v->ex_start_cap + v->ex_list_cap) * sizeof(int) + v->grid_hist_cap * sizeof(int) +
                 ms_extract_work_bytes(&v->ex_verify);
    if (v->pub)
        out->bytes += (size_t)v->cap * 6 * sizeof(float);
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p)
        out->bytes += (v->lists[p].cap + v->ghosts[p].cap) * (sizeof(int) + sizeof(float)) +
                      3 * v->df_grad_cap[p] * sizeof(float) + 4 * v->df_img_cap[p] * sizeof(float);
    out->threads = ms_vpool_threads(v->pool);
    out->density_iterations = v->df_density_iters;
    out->divergence_iterations = v->df_divergence_iters;
    out->density_iterations_total = v->df_density_total;
    out->divergence_iterations_total = v->df_divergence_total;
    out->density_error = v->df_density_err;
    out->divergence_error = v->df_divergence_err;
    ms_struct_write(user, &info, size);
}

ms_status ms_volume_set_tasks(ms_volume *v, ms_enqueue_task_fn *enqueue_task,
                              ms_finish_task_fn *finish_task, void *user_task_context)
{
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: volume is NULL");
    if ((enqueue_task == NULL) != (finish_task == NULL))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: enqueue_task and finish_task must both be set or both be NULL");
    return ms_vpool_set_tasks(v->pool, enqueue_task, finish_task, user_task_context);
}

void ms_volume_cancel(ms_volume *v)
{
    if (v)
        atomic_store(&v->cancel, 1);
}

ms_volume_desc ms_volume_get_desc(const ms_volume *v)
{
    return v ? v->desc : ms_volume_desc_default();
}

ms_status ms_volume_add_collider(ms_volume *v, ms_shape *shape)
{
    if (!v || !shape)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: add_collider needs a volume and a shape");
    for (int i = 0; i < v->ncolliders; ++i)
        if (v->colliders[i] == shape)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "volume: add_collider: this shape is already a collider");
    if (v->ncolliders >= MS_VOLUME_MAX_COLLIDERS)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: add_collider: at most %d colliders",
                       MS_VOLUME_MAX_COLLIDERS);
    v->col_expect_valid[v->ncolliders] = 0;
    v->colliders[v->ncolliders++] = shape;
    v->pass_ready = 0; /* the boundary terms changed (density.c) */
    return MS_OK;
}

ms_status ms_volume_remove_collider(ms_volume *v, ms_shape *shape)
{
    if (!v || !shape)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: remove_collider needs a volume and a shape");
    for (int i = 0; i < v->ncolliders; ++i)
        if (v->colliders[i] == shape) {
            size_t rest = (size_t)(v->ncolliders - i - 1);
            memmove(&v->colliders[i], &v->colliders[i + 1], rest * sizeof v->colliders[0]);
            memmove(&v->col_expect[i], &v->col_expect[i + 1], rest * sizeof v->col_expect[0]);
            memmove(&v->col_expect_valid[i], &v->col_expect_valid[i + 1],
                    rest * sizeof v->col_expect_valid[0]);
            memmove(&v->col_end[i], &v->col_end[i + 1], rest * sizeof v->col_end[0]);
            v->ncolliders--;
            v->pass_ready = 0; /* a new shape may come at the same address */
            return MS_OK;
        }
    return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: remove_collider: shape is not a collider");
}
