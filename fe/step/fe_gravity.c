/* fe_gravity: a uniform acceleration of gravity g on the whole model: f = m g on every node
 * with mass (rigid-body nodes included; their body sums the forces). Its work is external work
 * in the energy balance (as LS-DYNA reports body loads), so `potential` stays 0. */
#include "fe/fe_solid.h"

void fe_gravity_forces(const fe_model *m, fe_state *s)
{
    const double *g = m->opts.gravity;
    if (g[0] == 0 && g[1] == 0 && g[2] == 0) return;
    for (int n = 0; n < m->nnode; n++) {
        const double mass = m->node_mass[n] + (m->nms_node ? s->node_dm[n] : 0);
        double *f = s->node_fext + 3 * n;
        f[0] += mass * g[0];
        f[1] += mass * g[1];
        f[2] += mass * g[2];
    }
}
