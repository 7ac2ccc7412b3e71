/* rom_step.c: the reduced-order model's right-hand side (rom.h), thesis §3.1: each element
 * pushes its two masses apart with F = F_spring(d) + c d' (never pulling: a contact), d the
 * deflection along the line between them; Newton's law gives each mass its acceleration. */
#include "rom/rom.h"


void rom_forces(const rom_model *m, const mcs_hyst_state *hs, const double *x, const double *v,
                double *acc, double *f, double *d)
{
    double force[ROM_NMASS] = {0};
    /* elements: deflection and rate from the two masses (the wall at rest), force on both */
    for (int i = 0; i < ROM_NELEM; i++) {
        const rom_elem *e = &m->elem[i];
        f[i] = 0, d[i] = 0;
        if (m->mass[e->a] <= 0 || (e->b >= 0 && m->mass[e->b] <= 0)) continue;
        double xb = e->b >= 0 ? x[e->b] : 0, vb = e->b >= 0 ? v[e->b] : 0;
        d[i] = x[e->a] - xb - e->gap;
        if (d[i] <= 0 && hs[i].x_max <= 0) continue; /* open gap, never touched */
        double fs = mcs_hyst_force(&e->hyst, &hs[i], d[i]);
        f[i] = d[i] > 0 ? mcs_hyst_damped(fs, e->damping, v[e->a] - vb, 1) : 0;
        force[e->a] -= f[i];
        if (e->b >= 0) force[e->b] += f[i];
    }
    /* accelerations; an absent mass stays at rest */
    for (int k = 0; k < ROM_NMASS; k++) acc[k] = m->mass[k] > 0 ? force[k] / m->mass[k] : 0;
}
