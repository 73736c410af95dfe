/* ms_volume_desc: the defaults and the checks ms_volume_create makes. Every
 * refusal names the key, the value and the bound it broke. */
#include <math.h>

#include "volume/volume_internal.h"
#include "volume/volume_sizes.h"

ms_volume_desc ms_volume_desc_default(void)
{
    ms_volume_desc d = {
        .size = (uint32_t)sizeof(ms_volume_desc),
        .domain_min = {0.0f, 0.0f, 0.0f},
        .domain_max = {1.0f, 1.0f, 1.0f},
        .spacing = 0.04f,
        .smoothing_length = 0.08f,
        .rest_density = 1000.0f,
        .gas_constant = 400.0f,
        .viscosity = 1.0f,
        .gravity = {0.0f, 0.0f, -9.81f},
        .pressure = MS_PRESSURE_IDEAL_GAS,
        .max_particles = 262144,
        .sound_speed = 20.0f,
        .courant = 0.4f,
        .max_substeps = 100000,
        .threads = 1,
        .smooth_steps = 4,
        .smooth_energy = 0.02f,
        .density_kernel = MS_DENSITY_SPIKY,
        .max_density_error = 0.001f,
        .max_divergence_error = 0.001f,
        .max_density_iterations = 100,
        .max_divergence_iterations = 100,
    };
    return d;
}

static ms_status check(const ms_volume_desc *d)
{
    static const char *const axis[3] = {"x", "y", "z"};
    const char *P = "volume";
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(d->domain_min[k]) || !isfinite(d->domain_max[k]))
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT,
                               isfinite(d->domain_min[k]) ? "domain_max" : "domain_min",
                               "volume: domain %s from %g to %g m; both must be finite numbers",
                               axis[k], d->domain_min[k], d->domain_max[k]);
        if (fabsf(d->domain_min[k]) > 1e6f || fabsf(d->domain_max[k]) > 1e6f)
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT,
                               fabsf(d->domain_min[k]) > 1e6f ? "domain_min" : "domain_max",
                               "volume: domain %s from %g to %g m lies outside [-1e6, 1e6] m",
                               axis[k], d->domain_min[k], d->domain_max[k]);
        if (!(d->domain_max[k] > d->domain_min[k]))
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "domain_max",
                               "volume: domain is empty: %s from %g to %g m needs max > min",
                               axis[k], d->domain_min[k], d->domain_max[k]);
    }
    MS_TRY(ms_check_positive(P, "spacing", d->spacing, "m"));
    MS_TRY(ms_check_positive(P, "smoothing_length", d->smoothing_length, "m"));
    if (d->smoothing_length < d->spacing)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "smoothing_length",
                           "volume: smoothing_length %g m is below spacing %g m; h must be >= "
                           "spacing or particles have no neighbours",
                           d->smoothing_length, d->spacing);
    if (d->smoothing_length > 4.0f * d->spacing)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "smoothing_length",
                           "volume: smoothing_length %g m is over 4 x spacing (%g m); more than "
                           "~270 neighbours per particle is refused",
                           d->smoothing_length, 4.0f * d->spacing);
    for (int k = 0; k < 3; ++k) {
        float ext = d->domain_max[k] - d->domain_min[k];
        if (2.0f * d->smoothing_length > ext)
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "smoothing_length",
                               "volume: smoothing_length %g m is over half the domain's %s extent "
                               "%g m; the domain must span at least 2 h",
                               d->smoothing_length, axis[k], ext);
    }
    double cells = 1.0;
    for (int k = 0; k < 3; ++k)
        cells *= ceil((double)(d->domain_max[k] - d->domain_min[k]) / d->smoothing_length) + 2.0;
    if (cells > (double)MS_VOLUME_MAX_CELLS)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "smoothing_length",
                           "volume: the domain holds %.3g neighbour cells of h = %g m; at most %ld "
                           "(raise smoothing_length or shrink the domain)",
                           cells, d->smoothing_length, MS_VOLUME_MAX_CELLS);
    MS_TRY(ms_check_range(P, "rest_density", d->rest_density, 1e-3, 1e5, "kg/m^3"));
    MS_TRY(ms_check_range(P, "viscosity", d->viscosity, 0.0, 1e6, "Pa s"));
    for (int k = 0; k < 3; ++k)
        if (!isfinite(d->gravity[k]) || fabsf(d->gravity[k]) > 1000.0f)
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "gravity",
                               "volume: gravity %s %g m/s^2 is outside [-1000, 1000]", axis[k],
                               d->gravity[k]);
    /* One rule for the constants of the pressure laws: each is range-checked
     * whichever law is chosen, as the DFSPH limits below are, so a desc that
     * is valid stays valid when only its law changes, and a bad value (-5
     * m/s as NaN) never waits unseen in a desc for the law that reads it. */
    MS_TRY(ms_check_positive(P, "gas_constant", d->gas_constant, "m^2/s^2"));
    MS_TRY(ms_check_range(P, "gas_constant", d->gas_constant, 0, 1e8, "m^2/s^2"));
    MS_TRY(ms_check_positive(P, "sound_speed", d->sound_speed, "m/s"));
    MS_TRY(ms_check_range(P, "sound_speed", d->sound_speed, 0, 1e4, "m/s"));
    switch (d->pressure) {
    case MS_PRESSURE_IDEAL_GAS:
    case MS_PRESSURE_TAIT:
        break;
    case MS_PRESSURE_DFSPH:
        /* sound_speed only sizes the coupling's cap and the info's c */
        if (d->density_kernel == MS_DENSITY_POLY6)
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "density_kernel",
                               "volume: density_kernel poly6 with pressure DFSPH; the DFSPH solve "
                               "differentiates the density kernel as the spiky one of eq. 11 "
                               "(use MS_DENSITY_SPIKY)");
        break;
    default:
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "pressure",
                           "volume: pressure %d is not a ms_pressure value (0 ideal gas, 1 Tait, "
                           "2 DFSPH)",
                           (int)d->pressure);
    }
    MS_TRY(ms_check_int_range(P, "max_particles", d->max_particles, 1, MS_VOLUME_MAX_PARTICLES));
    if (!isfinite(d->courant) || !(d->courant > 0.0f) || d->courant > 0.5f)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "courant",
                           "volume: courant %g is outside (0, 0.5]; 0.5 is the largest CFL number "
                           "this solver is tested stable at",
                           d->courant);
    MS_TRY(ms_check_int_range(P, "max_substeps", d->max_substeps, 1, 10000000));
    MS_TRY(ms_check_int_range(P, "threads", d->threads, 1, MS_VOLUME_MAX_THREADS));
    MS_TRY(ms_check_int_range(P, "smooth_steps", d->smooth_steps, 0, 64));
    MS_TRY(ms_check_positive(P, "smooth_energy", d->smooth_energy, "J/kg"));
    if (d->density_kernel != MS_DENSITY_SPIKY && d->density_kernel != MS_DENSITY_POLY6)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "density_kernel",
                           "volume: density_kernel %d is not a ms_density_kernel value (0 spiky, "
                           "1 poly6)",
                           (int)d->density_kernel);
    if (!isfinite(d->max_density_error) || !(d->max_density_error > 0.0f) ||
        d->max_density_error > 0.1f)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "max_density_error",
                           "volume: max_density_error %g is outside (0, 0.1]; it is the average "
                           "compression rho/rho0 - 1 the DFSPH density solve stops at",
                           d->max_density_error);
    if (!isfinite(d->max_divergence_error) || !(d->max_divergence_error > 0.0f) ||
        d->max_divergence_error > 0.1f)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "max_divergence_error",
                           "volume: max_divergence_error %g is outside (0, 0.1]; it is the average "
                           "dt (D rho/Dt) / rho0 the DFSPH divergence solve stops at",
                           d->max_divergence_error);
    MS_TRY(ms_check_int_range(P, "max_density_iterations", d->max_density_iterations, 1, 10000));
    MS_TRY(
        ms_check_int_range(P, "max_divergence_iterations", d->max_divergence_iterations, 0, 10000));
    return MS_OK;
}

ms_status ms_volume_desc_check(const ms_volume_desc *user)
{
    ms_volume_desc d = ms_volume_desc_default();
    MS_TRY(ms_struct_in(user, &d, MS_SIZES_VOLUME_DESC, "volume"));
    return check(&d);
}
