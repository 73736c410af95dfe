/* ms_volume: the low-frequency half of mode splitting (paper section 3.3).
 *
 * Smoothed particle hydrodynamics after Mueller, Charypar & Gross 2003:
 * poly6 density, the spiky pressure kernel and force (eqs. 11, 13), the
 * viscosity kernel and force (eqs. 12, 14), gravity, and the collider force
 * field of eq. 15. ms_volume_extract_height gives the 2.5D free surface of
 * eqs. 16-18 over the domain's x-y extent.
 *
 * Not thread-safe: one handle, one thread at a time.
 */
#ifndef MODESPLIT_VOLUME_H
#define MODESPLIT_VOLUME_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ms_pressure {
    MS_PRESSURE_IDEAL_GAS = 0, /* p = k (rho - rho0), the paper's */
    MS_PRESSURE_TAIT = 1,      /* weakly compressible, gamma = 7 */
    MS_PRESSURE_DFSPH = 2,     /* divergence-free SPH (may be unsupported) */
    MS_PRESSURE_FORCE_32BIT_ = 0x7fffffff
} ms_pressure;

typedef struct ms_volume_desc {
    float domain_min[3], domain_max[3]; /* m, the box the liquid lives in (a collider) */
    float spacing;                      /* m, particle spacing of fill_box */
    float smoothing_length;             /* m, h of eqs. 11-14; >= spacing */
    float rest_density;                 /* kg/m^3 */
    float gas_constant;                 /* J/kg (m^2/s^2), k of p = k (rho - rho0) */
    float viscosity;                    /* Pa s, mu of eq. 14 */
    float gravity[3];                   /* m/s^2 */
    ms_pressure pressure;
    int max_particles;
    /* --- grown at the end (ABI: descs only grow) --- */
} ms_volume_desc;

MS_API ms_volume_desc ms_volume_desc_default(void);
MS_API ms_status ms_volume_create(const ms_volume_desc *d, ms_volume **out);
MS_API void ms_volume_destroy(ms_volume *v);
MS_API ms_status ms_volume_fill_box(ms_volume *v, const float lo[3], const float hi[3]);
MS_API ms_status ms_volume_add_particles(ms_volume *v, int n, const float *pos, const float *vel);
MS_API ms_status ms_volume_step(ms_volume *v, float dt); /* CFL-adaptive sub-steps inside */
MS_API int ms_volume_count(const ms_volume *v);
MS_API ms_status ms_volume_get_particles(const ms_volume *v, float *pos, float *vel);
MS_API ms_status ms_volume_extract_height(ms_volume *v, int nx, int ny, float *out);
MS_API double ms_volume_kinetic_energy(const ms_volume *v);
MS_API ms_status ms_volume_add_collider(ms_volume *v, ms_shape *shape);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_VOLUME_H */
