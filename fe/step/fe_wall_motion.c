/* fe_wall_motion: a rigid wall moved by curves (scenario `rigid_walls: [{motion}]`, LS-DYNA
 * *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL). The wall's displacement at t is
 *     d(t) = velocity t + sum_k e_k D_k(t),
 * e_k a unit direction and D_k from the piecewise-linear curve f_k (held constant beyond its
 * ends): displacement D = f(t); velocity D = int_0^t f; acceleration (from rest; `velocity` is
 * the initial velocity) D = int_0^t (t - s) f(s) ds. Both integrals are exact: on each piece
 * the trapezoid rule integrates the linear f and Simpson's rule the quadratic (t - s) f(s).
 * The node update lands nodes on d(t + dt) (kinematic) or the penalty uses d(t), as for a
 * wall at constant velocity; the wall's velocity at t + dt/2 is (d(t + dt) - d(t)) / dt. */
#include "fe/fe_elem.h"
#include "fe/fe_solid.h"

#include <math.h>

static double curve_at(const fe_wall_motion *mo, double t)
{
    const int n = mo->ncurve;
    const double (*c)[2] = mo->curve;
    if (n == 1 || t <= c[0][0]) return c[0][1];
    if (t >= c[n - 1][0]) return c[n - 1][1];
    int k = 0;
    while (t > c[k + 1][0]) k++;
    return c[k][1] + (t - c[k][0]) / (c[k + 1][0] - c[k][0]) * (c[k + 1][1] - c[k][1]);
}

double fe_wall_motion_disp(const fe_wall_motion *mo, double t)
{
    if (mo->kind == FE_MOTION_DISPLACEMENT) return curve_at(mo, t);
    /* pieces of [0, t] split at the curve's points */
    double sum = 0, a = 0;
    int k = 0;
    while (a < t) {
        while (k < mo->ncurve && mo->curve[k][0] <= a) k++;
        const double b = k < mo->ncurve && mo->curve[k][0] < t ? mo->curve[k][0] : t;
        const double fa = curve_at(mo, a), fb = curve_at(mo, b);
        if (mo->kind == FE_MOTION_VELOCITY) {
            sum += 0.5 * (b - a) * (fa + fb);
        } else {
            const double h = 0.5 * (a + b);
            sum += (b - a) / 6 * ((t - a) * fa + 4 * (t - h) * curve_at(mo, h) + (t - b) * fb);
        }
        a = b;
    }
    return sum;
}

void fe_wall_motion_unit(fe_wall_motion *mo)
{
    const double n = sqrt(fe_dot(mo->direction, mo->direction));
    for (int i = 0; i < 3; i++) mo->direction[i] /= n;
}

void fe_wall_motion_x(const fe_wall *W, double t, double x[3])
{
    for (int i = 0; i < 3; i++) x[i] = W->velocity[i] * t;
    for (int k = 0; k < W->nmotion; k++) {
        const double D = fe_wall_motion_disp(&W->motion[k], t);
        for (int i = 0; i < 3; i++) x[i] += D * W->motion[k].direction[i];
    }
}

mcs_status fe_wall_motion_check(const fe_wall_desc *d, mcs_error *err)
{
    if (!(d->friction >= 0) || !isfinite(d->friction))
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: rigid wall '%s': friction must be >= 0, got %g",
                       d->name, d->friction);
    if (d->nmotion < 0 || d->nmotion > FE_WALL_NMOTION)
        return MCS_ERR(err, MCS_ERR_RANGE, "fe: rigid wall '%s': 0..%d motion components, got %d",
                       d->name, FE_WALL_NMOTION, d->nmotion);
    if (d->nmotion > 0 && d->mass > 0)
        return MCS_ERR(err, MCS_ERR_RANGE,
                       "fe: rigid wall '%s': a wall with mass moves freely; it cannot also "
                       "follow a motion curve",
                       d->name);
    for (int k = 0; k < d->nmotion; k++) {
        const fe_wall_motion *mo = &d->motion[k];
        const double nn = fe_dot(mo->direction, mo->direction);
        if ((unsigned)mo->kind > FE_MOTION_DISPLACEMENT || !(nn > 0) || !isfinite(nn))
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: rigid wall '%s': motion %d: kind velocity, acceleration or "
                           "displacement, and a nonzero direction",
                           d->name, k + 1);
        if (mo->ncurve < 1 || mo->ncurve > FE_CURVE_MAX)
            return MCS_ERR(err, MCS_ERR_RANGE,
                           "fe: rigid wall '%s': motion %d: 1..%d curve points, got %d", d->name,
                           k + 1, FE_CURVE_MAX, mo->ncurve);
        for (int i = 0; i < mo->ncurve; i++)
            if (!isfinite(mo->curve[i][0]) || !isfinite(mo->curve[i][1]) ||
                (i > 0 && !(mo->curve[i][0] > mo->curve[i - 1][0])))
                return MCS_ERR(err, MCS_ERR_RANGE,
                               "fe: rigid wall '%s': motion %d: curve point %d: times must "
                               "increase and values be finite",
                               d->name, k + 1, i + 1);
    }
    return MCS_OK;
}
