/* fe_contact_impl: private helpers shared by the fe_contact*.c files. Not a public header. */
#ifndef FE_CONTACT_IMPL_H
#define FE_CONTACT_IMPL_H

#include "fe/fe_contact.h"
#include "fe/fe_state.h"

#include <math.h>

/* one slot's result of a step (fe_contact.c phase 1 -> phase 2) */
typedef struct fe_contact_slot {
    int seg;              /* segment in contact, -1 none [-]                     */
    double w[4];          /* weights of its nodes at the nearest point [-]        */
    double f[3];          /* force on the slave node [N]                          */
    double el, d, g;      /* elastic energy now, friction dissipated this step [J], gap [m] */
} fe_contact_slot;

/* ent_flag bits: slot 0 / 1 in contact after the last step, candidate list overflowed (the
 * entry scans its buckets), on the live list */
enum { FE_CFLAG_SLOT0 = 1, FE_CFLAG_SLOT1 = 2, FE_CFLAG_SCAN = 4, FE_CFLAG_LIVE = 8 };

/* hash size of pass p's bucket table (a power of two) */
int fe_contact_hash_size(const fe_contact_model *c, int p);
/* rebuild every pass's bucket table from the current positions */
void fe_contact_search(const fe_model *m, fe_state *s);
/* the distinct buckets of the 27 cells about a point for pass p (at most 27, written to
 * bk); each bucket's segments are cell_item[off[b] .. off[b + 1]) with off = cell_off +
 * pass_cell_base[p]; returns their number */
int fe_contact_buckets(const fe_contact_state *cs, int p, const double x[3], int bk[27]);

/* after a search: each entry's candidate list (the segments whose grown box holds it, its own
 * and in self contact its neighbours' left out) and the live list */
void fe_contact_candidates(const fe_model *m, fe_state *s);

/* the pass of slave entry e (each pass's entries are contiguous) */
static inline int fe_contact_ent_pass(const fe_contact_model *c, int e)
{
    int p = 0;
    while (p < c->npass - 1 && e >= c->pass[p].ent_end) p++;
    return p;
}

/* 1 / smallest node mass of segment sg (0 when a node has none) [1/kg] */
static inline double fe_contact_seg_minv(const fe_contact_model *c, const fe_model *m, int sg)
{
    double mmin = INFINITY;
    for (int i = 0; i < 4; i++) mmin = fmin(mmin, m->node_mass[c->seg_node[4 * sg + i]]);
    return mmin > 0 ? 1 / mmin : 0;
}

/* deepest penetration still taken by a hex face: half the square root of its initial area [m] */
static inline double fe_contact_seg_depth(const fe_contact_model *c, const fe_model *m, int sg)
{
    const int *q = c->seg_node + 4 * sg;
    double d1[3], d2[3], nn[3];
    for (int i = 0; i < 3; i++) {
        d1[i] = m->node_x0[3 * q[2] + i] - m->node_x0[3 * q[0] + i];
        d2[i] = m->node_x0[3 * q[3] + i] - m->node_x0[3 * q[1] + i];
    }
    nn[0] = d1[1] * d2[2] - d1[2] * d2[1];
    nn[1] = d1[2] * d2[0] - d1[0] * d2[2];
    nn[2] = d1[0] * d2[1] - d1[1] * d2[0];
    const double a = 0.5 * sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
    return 0.5 * sqrt(a);
}

/* whether segment sg's element was deleted by erosion before this step (fe_stages.c) */
static inline int fe_contact_seg_gone(const fe_model *m, const fe_state *s, int sg)
{
    return m->nerode > 0 && s->elem_gone[m->contact->seg_elem[sg]];
}

/* whether x lies in a (float) grown box */
static inline int fe_contact_in_box(const float *b, const double x[3])
{
    return !(x[0] < (double)b[0] || x[0] > (double)b[3] || x[1] < (double)b[1] ||
             x[1] > (double)b[4] || x[2] < (double)b[2] || x[2] > (double)b[5]);
}

/* whether segment q has a node sharing an element with `node` (self contact leaves it out) */
static inline int fe_contact_seg_has_nbr(const fe_contact_model *c, const int *q, int node)
{
    for (int j = c->nbr_off[node]; j < c->nbr_off[node + 1]; j++) {
        int v = c->nbr[j];
        if (q[0] == v || q[1] == v || q[2] == v || q[3] == v) return 1;
    }
    return 0;
}

/* nearest point of triangle (a, b, c) to p: barycentric weights w[3], squared distance */
double fe_tri_nearest(const double p[3], const double a[3], const double b[3], const double c[3],
                      double w[3]);

/* elastic-stick Coulomb friction (return mapping): ft (in: history, out: new force on the
 * slave), n unit normal, du relative tangential slip increment [m], k stiffness [N/m],
 * fmax = mu fn [N]; returns the new tangential elastic energy [J], *taken the work the
 * interface took from the nodes over du [J] (dissipation = taken - change of elastic energy) */
double fe_friction_update(double ft[3], const double n[3], const double du[3], double k,
                          double fmax, double *taken);

/* node n in contact with a moving rigid surface (phase 3, fe_contact.c): gap g < 0 along the
 * unit normal db at the surface point qb (about the surface's reference point), both in the
 * surface's frame, R its rotation body -> world (row major), the surface moving at V and
 * spinning at W; penalty stiffness scale m_n / dt0^2 and elastic-stick
 * friction mu (ft the stick force, *et its energy): the force onto the node (node_fc), minus it
 * onto the surface's F and its moment about the reference point onto M, the part's elastic and
 * frictional energy, pen_max */
/* a body-side law in series (fe_body_law_desc): its model (NULL: rigid surface), the node's
 * history */
typedef struct {
    const mcs_hyst_model *model;
    fe_body_law_node *node;
} fe_contact_law;

/* node n's tributary contact area facing a body along dir (unit, from the body towards the
 * node, world): a quarter (a third for a triangle) of each of its surface faces' vector areas
 * in the current configuration, summed, projected on -dir (an exterior hex face counts when
 * it faces the body; a shell element, two-sided, either way) [m^2] */
double fe_contact_node_area(const fe_model *m, const fe_state *s, int n, const double dir[3]);

void fe_contact_rigid_node(const fe_model *m, fe_state *s, int n, double g, const double R[9],
                           const double db[3], const double qb[3], double scale, double mu, const double V[3],
                           const double W[3], double ft[3], double *et, const fe_contact_law *law,
                           double F[3], double M[3]);
/* node n out of contact with it: the stick spring's energy *et is dissipated, ft zeroed; a
 * body law unloads to 0 and its work (the hysteresis' dissipation) is dissipated, history reset */
void fe_contact_rigid_release(const fe_model *m, fe_state *s, int n, double ft[3], double *et,
                              const fe_contact_law *law);

/* rigid facet surfaces (fe_contact_facet.c): node lists and grids when the model is built
 * (mark: nnode bytes of scratch, shell_ht: half shell thickness per node), freed with it; their
 * forces in the serial phase 3 (after the ellipsoids) */
mcs_status fe_contact_facets_build(const fe_builder *b, fe_contact_model *c,
                                   const fe_model *m, unsigned char *mark,
                                   const double *shell_ht, mcs_error *err);
void fe_contact_facets_free(fe_contact_model *c);
void fe_contact_facets_forces(const fe_model *m, fe_state *s);

/* before the rigid surfaces' forces: the fastest contact node's travel since the last step
 * into cs->travel, and each surface's candidate list made anew when nodes and centre may have
 * moved FE_RIGID_MARGIN / 2 since it was made (fe_contact_facet.c) */
void fe_contact_rigid_candidates(const fe_model *m, fe_state *s);

/* body -> world rotation of a quaternion w, x, y, z (all zero: identity) */
void fe_contact_quat_to_R(const double q[4], double R[9]);

#endif
