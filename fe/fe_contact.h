/* fe_contact: penalty contact interfaces of the explicit FE kernel (DESIGN.md `fe.contacts`):
 * node-to-segment contact against shell and hex-face segments (two-surface, one-way and
 * single-surface/self), Coulomb friction with an elastic stick, and nodes against rigid
 * ellipsoids (for coupling stage-1 bodies). docs/fe.md "Contact" gives the formulas.
 *
 * Model side (built once by fe_model_create from the builder's descriptors): segments, slave
 * node lists, penalty stiffnesses, neighbour lists for self-contact. State side: the bucket
 * grid (rebuilt when a segment node has moved more than the search margin), friction history,
 * contact energies and force histories. fe_internal_forces and fe_contact_forces (fe_stages.c)
 * call the three parts below, which add the contact forces to node_fext. */
#ifndef FE_CONTACT_H
#define FE_CONTACT_H

#include <stddef.h>

#include "core/mcs_hysteresis.h"
#include "fe/fe_model.h"

#define FE_CONTACT_MAX 16    /* most contact interfaces                                      */
#define FE_CONTACT_PARTS 8   /* most parts on each side of an interface                      */
#define FE_ELLIPSOID_MAX 64  /* most rigid ellipsoids (a rider's surfaces in several contacts) */
#define FE_FACETS_MAX 32     /* most rigid facet (triangle mesh) surfaces                    */
#define FE_FACET_DEPTH 0.01  /* rigid facets: a node counts within this distance of the mesh,
                                and behind it down to this depth [m]                        */
#define FE_RIGID_MARGIN 0.02 /* moving rigid surfaces: candidate nodes within their bounding
                                sphere grown by this, kept until nodes and centre together may
                                have moved half of it [m]                                   */
#define FE_CONTACT_LIVE_CHUNK 64 /* live entries per chunk of the threaded entry loop      */
#define FE_CONTACT_CAND 4    /* candidate segments kept between searches, per slave node on
                                average (one pool; entries past it scan their buckets)     */
#define FE_CONTACT_LIVE 8    /* slave entries whose per-step results are kept for the
                                threaded pass: one in this many (the rest run inline)      */

typedef enum {
    FE_CONTACT_TWO_SURFACE,     /* slave nodes vs master segments and master nodes vs slave
                                   segments (symmetric, two passes; LS-DYNA SURFACE_TO_SURFACE) */
    FE_CONTACT_NODE_TO_SURFACE, /* slave nodes vs master segments only (one pass)               */
    FE_CONTACT_SINGLE_SURFACE   /* every node of the parts vs every segment of the parts that
                                   neither contains it nor neighbours one that does (self) */
} fe_contact_type;

typedef struct {
    char name[FE_NAME_MAX];                   /* results: /stage<N>/contact/<name>          */
    fe_contact_type type;
    int nslave;                               /* slave parts (single surface: the parts) [-] */
    char slave[FE_CONTACT_PARTS][FE_NAME_MAX];
    int nmaster;                              /* master parts (unused for single surface) [-] */
    char master[FE_CONTACT_PARTS][FE_NAME_MAX];
    double friction;                          /* static Coulomb coefficient mu_s [-]          */
    double friction_dynamic;                  /* dynamic mu_d; < 0 takes mu_s [-]             */
    double friction_decay;                    /* mu = mu_d + (mu_s - mu_d) exp(-dc |v_t|) [s/m] */
    double damping; /* viscous damping normal to the contact, fraction of critical (LS-DYNA VDC
                       / 100): c = damping 2 m omega per node, m the smaller of the node's and
                       the segment's masses, omega = sqrt(k (m_n + m_s) / (m_n m_s)) [-] */
    double birth, death; /* active from birth to death (death 0: never dies; LS-DYNA BT, DT) [s] */
    double penalty_scale;                     /* s of k = s K A^2/V, s K A/diag; 0 -> 0.1 [-] */
    double thickness_scale;                   /* on the shell offsets t/2; 0 -> 1 [-]         */
    double fabric_thickness;                  /* contact thickness of membrane (fabric) parts;
                                                 0 -> max(section thickness,
                                                 FE_CONTACT_FABRIC_TMIN) [m]                   */
    /* a side on part of its parts' surface (LS-DYNA segment and node sets): its nodes limited
     * to *_node (builder node indices), its segments to the element faces (shells, exterior
     * hex faces) whose nodes are *_face's (n x 4, a triangle repeats its 3rd); n 0: the whole
     * parts. Copied by fe_builder_add_contact. */
    int nslave_node, nslave_face, nmaster_node, nmaster_face; /* [-]                          */
    const int *slave_node, *slave_face, *master_node, *master_face;
} fe_contact_desc;

/* the smallest default contact thickness of fabric (membrane parts): two layers rest this far
 * apart; airbag practice (OpenRadioss airbag self contact GAP_MIN = 1 mm) [m] */
#define FE_CONTACT_FABRIC_TMIN 1e-3

/* a body-side contact law in series with the penalty (an ellipsoid's; docs/contracts.md
 * "Soft body surfaces in bodies contacts"): the body's surface yields by delta_b with the stress
 * sigma(delta_b) over the node's tributary area A (fe_contact_model.node_area), the penalty
 * spring carries the same force: delta_b + A sigma(delta_b) / k_p = penetration. Loading and
 * unloading as the characteristics' hysteresis element (core/mcs_hysteresis.h) on stress. */
#define FE_BODY_LAW_PTS 32
typedef struct {
    int n;                      /* points of the stress curve; 0: none (rigid surface) [-]     */
    double x[FE_BODY_LAW_PTS];  /* penetration into the body [m], increasing                    */
    double y[FE_BODY_LAW_PTS];  /* stress [Pa]                                                 */
    double unload_slope;        /* unloading line slope [Pa/m]; 0: elastic (along the curve)    */
    double elastic_limit;       /* no permanent set below this penetration [m]                  */
} fe_body_law_desc;

/* a node's body-law history while in contact: the stress path's state (deflection delta_b
 * [m], stress [Pa]), the work of the node's law force on delta_b [J] (trapezoid per step),
 * that force [N] */
typedef struct fe_body_law_node {
    mcs_hyst_state h;
    double work, force;
} fe_body_law_node;

typedef struct {
    char name[FE_NAME_MAX];
    double center[3];        /* at t = 0 [m]                                                   */
    double semi_axes[3];     /* along the body axes [m]                                        */
    double orientation[4];   /* body -> world quaternion w, x, y, z (0 0 0 0 takes identity) [-] */
    double velocity[3];      /* prescribed translational velocity [m/s]                        */
    double penalty_scale;    /* k = s m_node / dt0^2 per node; 0 -> 0.1 [-]                     */
    double friction;         /* Coulomb coefficient [-]                                        */
    int nparts;              /* 0: every node with mass                                        */
    char parts[FE_CONTACT_PARTS][FE_NAME_MAX];
    fe_body_law_desc law;    /* the body's surface compliance in series (law.n = 0: rigid)     */
} fe_ellipsoid_desc;

/* a rigid triangle mesh moving with a pose (stage-1 facet surfaces, stage1_mb/
 * mb_couple_contact.c): one-sided, outward by the counter-clockwise vertex order; a node
 * meets it from the outer side only (docs/fe.md "Contact") */
typedef struct {
    char name[FE_NAME_MAX];
    double center[3];        /* reference point at t = 0, world [m]                            */
    double orientation[4];   /* mesh -> world quaternion w, x, y, z (0 0 0 0 takes identity) [-] */
    int nvert, ntri;         /* [-]                                                            */
    const double *vert;      /* (nvert x 3) vertices about center, mesh frame (copied) [m]      */
    const int *tri;          /* (ntri x 3) vertex indices, outward counter-clockwise (copied)  */
    double penalty_scale;    /* k = s m_node / dt0^2 per node; 0 -> 0.1 [-]                     */
    double friction;         /* Coulomb coefficient [-]                                        */
    int nparts;              /* 0: every node with mass                                        */
    char parts[FE_CONTACT_PARTS][FE_NAME_MAX];
} fe_facet_desc;

fe_contact_desc fe_contact_desc_default(void);
/* frees the side filters a builder's copy holds (fe_builder_destroy) */
void fe_contact_desc_free(fe_contact_desc *d);

/* the builder keeps the descriptors; fe_model_create resolves them */
mcs_status fe_builder_add_contact(fe_builder *b, const fe_contact_desc *d, mcs_error *err);
mcs_status fe_builder_add_ellipsoid(fe_builder *b, const fe_ellipsoid_desc *d, mcs_error *err);
mcs_status fe_builder_add_facets(fe_builder *b, const fe_facet_desc *d, mcs_error *err);
/* rigid ellipsoids and facet surfaces added so far: the next one's kernel index */
int fe_builder_nellipsoid(const fe_builder *b);
int fe_builder_nfacets(const fe_builder *b);

/* ---- the frozen contact model (fe_model.contact; NULL when there is no contact) --------- */

typedef struct {
    char name[FE_NAME_MAX];
    double mu_s, mu_d, decay;  /* friction law [-], [-], [s/m]                                 */
    double damping;            /* normal viscous damping, fraction of critical [-]             */
    double birth, death;       /* active time span (death 0: none) [s]                         */
} fe_contact_if;

typedef struct {
    int iface;                 /* interface it belongs to [-]                                  */
    int self;                  /* single surface: topological exclusion of neighbours [-]     */
    int reverse;               /* second pass of a two-surface contact: masters as slaves [-] */
    int ent_begin, ent_end;    /* its slave entries [-]                                        */
    int seg_begin, seg_end;    /* its segments [-]                                             */
} fe_contact_pass;

typedef struct {
    double center[3], R[9];    /* initial pose: centre [m], body -> world rotation (row major) */
    double semi[3];            /* semi-axes [m]                                                */
    double velocity[3];        /* prescribed velocity [m/s]                                    */
    double scale, mu;          /* penalty scale, friction [-]                                  */
    int node_begin, node_end;  /* its nodes in ell_node [-]                                    */
    char name[FE_NAME_MAX];
    mcs_curve *law_curve;      /* body law: stress vs. penetration (owned; NULL: rigid)        */
    mcs_hyst_model law;        /* its hysteresis element (stress [Pa] vs. penetration [m])     */
} fe_contact_ellipsoid;

typedef struct {
    double center[3], R[9];    /* initial pose: reference point [m], mesh -> world rotation    */
    double scale, mu;          /* penalty scale, friction [-]                                  */
    int node_begin, node_end;  /* its nodes in fac_node [-]                                    */
    int nvert, ntri;           /* [-]                                                          */
    double *vert;              /* (nvert x 3) mesh frame [m] (owned)                           */
    int *tri;                  /* (ntri x 3) (owned)                                           */
    double *tri_n;             /* (ntri x 3) unit outward normals, mesh frame (owned)          */
    double rmax;               /* largest vertex distance from the reference point [m]       */
    double lo[3], cell;        /* grid over the mesh grown by FE_FACET_DEPTH: origin, cell [m] */
    int dim[3];                /* cells along x, y, z [-]                                      */
    int *cell_off, *cell_tri;  /* triangles near each cell (dim product + 1, ...) (owned)      */
    char name[FE_NAME_MAX];
} fe_contact_facets;

typedef struct fe_contact_model {
    int nif, npass, nseg, nent, nnode_touch, nell, nell_node, nfac, nfac_node;
    fe_contact_if *iface;        /* (nif)                                                      */
    fe_contact_pass *pass;       /* (npass)                                                    */
    int *seg_node;               /* (nseg x 4) segment nodes (triangle: 4th = 3rd)             */
    int *seg_part;               /* (nseg) part of each segment                                */
    unsigned char *seg_solid;    /* (nseg) 1: hex face (one-sided), 0: shell (two-sided)       */
    double *seg_ht;              /* (nseg) half thickness of the surface offset [m]            */
    double *seg_k;               /* (nseg) penalty stiffness (LS-DYNA form) [N/m]              */
    int *seg_elem;               /* (nseg) its element in the erosion flags (hex e, shell
                                    nhex + e; fe_state.elem_gone): an eroded one is left out  */
    int *ent_node;               /* (nent) slave node of each entry                            */
    double *ent_ht;              /* (nent) half shell thickness at the slave node (0 solid) [m] */
    int *nbr_off, *nbr;          /* (nnode + 1), (...) nodes sharing an element with a node    */
    int *touch;                  /* (nnode_touch) nodes of any contact (slave or segment)       */
    fe_contact_ellipsoid *ell;   /* (nell)                                                     */
    int *ell_node;               /* (nell_node) nodes each ellipsoid acts on                   */
    double margin;               /* search margin: rebuild when a node moved half of it [m]    */
    double k_cap;                /* stiffness cap: k (1/m_s + 1/m_m) dt0^2 <= k_cap [-]        */
    double dt0;                  /* stable step the cap refers to [s]                          */
    size_t bytes;                /* memory held [B]                                            */
    double *ell_ht;              /* (nell_node) half shell thickness at each ellipsoid node [m] */
    fe_contact_facets *fac;      /* (nfac) rigid facet surfaces (fe_contact_facet.c)            */
    int *fac_node;               /* (nfac_node) nodes each facet surface acts on                */
    double *fac_ht;              /* (nfac_node) half shell thickness at each of them [m]        */
    /* body laws: each node's surface faces (exterior hex faces, shell elements), CSR, for its
     * tributary contact area (fe_contact_node_area); NULL without a body law */
    int *area_off;               /* (nnode + 1)                                                */
    int (*area_face)[5];         /* its faces: 4 nodes (a triangle's repeated), 1: two-sided  */
} fe_contact_model;

/* called by fe_model_create once the model is frozen (masses, dt_initial known) */
mcs_status fe_contact_model_build(const fe_builder *b, fe_model *m, mcs_error *err);
void fe_contact_model_free(fe_model *m);

/* ---- the contact state (fe_state.contact) ------------------------------------------------ */

typedef struct fe_contact_state {
    /* search (fe_contact_search.c): each segment in the bucket of its centre; the cell is the
     * largest grown box, so a node's candidates are in the 27 cells around it */
    float *x_ref;           /* (nnode_touch x 3) positions at the last rebuild [m]           */
    float *seg_box;         /* (nseg x 6) grown boxes at the last rebuild, rounded outwards [m] */
    int *cell_off;          /* (per pass: hash size + 1) bucket offsets                       */
    int *cell_item;         /* (nseg) segments of each bucket                                 */
    int *pass_hash;         /* (npass) hash size (power of two) of each pass [-]             */
    int *pass_cell_base;    /* (npass) first offset of each pass in cell_off [-]            */
    double *pass_cell;      /* (npass x 4) grid origin [m] and cell size [m]                 */
    int *ent_cand_off;      /* (nent + 1) each entry's candidates in ent_cand (a Verlet list) */
    int *ent_cand;          /* (cand_cap) candidate segments, entry by entry                 */
    int cand_cap;           /* FE_CONTACT_CAND x nent [-]                                     */
    unsigned char *ent_flag;/* (nent) FE_CFLAG_*: slots in contact, list overflowed, live    */
    int *live;              /* (nent) entries with candidates or a slot in contact, in order  */
    int nlive;              /* [-]                                                            */
    struct fe_contact_slot *slot; /* (slot_cap x 2) this step's results of live[0 .. slot_cap) */
    int slot_cap;           /* nent / FE_CONTACT_LIVE + 1 [-]                                 */
    long nrebuild;          /* searches done [-]                                              */
    int need_rebuild;
    double margin2;         /* squared motion that asks for a new search: (margin / 2 less the
                               rounding of x_ref)^2 [m^2]                                    */
    /* friction history per slave entry, two slots (nearest segment, nearest one on the other
     * side) */
    double *ent_ft;         /* (nent x 2 x 3) friction force history [N]                     */
    double *ent_et;         /* (nent x 2) tangential (stick) elastic energy of the slot [J]  */
    double *ell_ft;         /* (nell_node x 3) ellipsoid friction history [N]               */
    double *ell_et;         /* (nell_node) its tangential elastic energy [J]                 */
    struct fe_body_law_node *ell_law; /* (nell_node) body-law history of each node          */
    /* nodal contact forces and the energy bookkeeping */
    double *node_fc;        /* (nnode x 3) contact force at t [N]                            */
    double *part_fric;      /* (npart) frictional dissipation so far [J]                     */
    double *part_elastic;   /* (npart) elastic energy stored now [J]                          */
    double *if_force;       /* (nif x 3) resultant force on the slave side at t [N]          */
    double *if_energy;      /* (nif) elastic + dissipated energy of the interface [J]       */
    double *if_fric;        /* (nif) frictional dissipation so far [J]                        */
    double *ell_c, *ell_R, *ell_v; /* (nell x 3, 9, 3) current ellipsoid poses [m], [-], [m/s] */
    double *ell_w;          /* (nell x 3) angular velocity over this step, world [rad/s]     */
    double *ell_vl;         /* (nell x 6) velocity and angular velocity of the last step     */
    double *ell_force;      /* (nell x 3) force of the structure on each ellipsoid at t [N]  */
    double *ell_moment;     /* (nell x 3) its moment about the ellipsoid's centre [N m]      */
    double *ell_work;       /* (nell) work of each moving ellipsoid on the structure [J]      */
    /* candidate nodes of the moving rigid surfaces (fe_contact_rigid_candidates): per surface
     * a sublist of its nodes (in its node range), their count, and the centre [m] and the
     * node travel [m] when it was made */
    int *ell_cand, *ell_ncand;      /* (nell_node), (nell)                                    */
    double *ell_cref;               /* (nell x 4)                                             */
    int *fac_cand, *fac_ncand;      /* (nfac_node), (nfac)                                    */
    double *fac_cref;               /* (nfac x 4)                                             */
    double travel;          /* sum over steps of the fastest contact node's travel [m]       */
    /* rigid facet surfaces, as the ellipsoids (pose of the reference point); fac_side: 1 once
     * a node was seen on the outer side (a node first seen behind is left alone) */
    double *fac_c, *fac_R, *fac_v, *fac_w, *fac_vl; /* (nfac x 3, 9, 3, 3, 6)               */
    double *fac_force, *fac_moment, *fac_work;      /* (nfac x 3, 3, 1) [N], [N m], [J]     */
    double *fac_ft;         /* (nfac_node x 3) friction history [N]                          */
    double *fac_et;         /* (nfac_node) its tangential elastic energy [J]                 */
    unsigned char *fac_side; /* (nfac_node) [-]                                              */
    double work_nodes;      /* work of contact forces on the nodes, synchronised with work_ext [J] */
    double work_bodies;     /* work of moving rigid bodies through contact [J]               */
    double dth_prev;        /* velocity-update step of the previous step [s]                 */
    double pen_max;         /* deepest penetration seen, relative to the offset [m]           */
    double energy;          /* elastic + frictional energy of every interface at t [J]      */
    size_t bytes;
    /* threaded loops (fe_contact.c): the live list in chunks of FE_CONTACT_LIVE_CHUNK, each on
     * the thread owning its first slave node; each thread keeps only the entries with a force
     * or a dissipation, in its own part of `slot` (records); the serial scatter walks the
     * records chunk by chunk, then runs inline the entries a full part left over */
    int *rec_live;          /* (slot_cap) live index of each record                           */
    int *q_rec0, *q_nrec;   /* (live chunks) first record and number of records of each chunk */
    int *q_done;            /* (live chunks) first live index the chunk's thread left over    */
    double *pow_chunk;      /* (nnode_chunk) contact power of each node chunk [W]            */
    int live_nt;            /* threads of this step's live list (fe_contact_begin) [-]        */
    int live_done;          /* fe_contact_live ran every thread's chunks this step            */
    int rec0[FE_PAR_MAX + 1]; /* each thread's first record this step [-]                     */
} fe_contact_state;

mcs_status fe_contact_state_create(const fe_model *m, fe_contact_state **out, mcs_error *err);
void fe_contact_state_destroy(fe_contact_state **p);
void fe_contact_state_reset(const fe_model *m, fe_contact_state *c);

struct fe_state;
/* the contact sub-stage: reads x, v (t - dt/2), time; adds contact forces to node_fext;
 * updates the contact energies (part_energy[FE_E_contact]) and the contact work that
 * fe_stable_step takes out of the external work (the contact is internal to the structure).
 * In three parts, so that the slave entries can run in the element loops' parallel region
 * (fe_internal_forces) with no barrier between them:
 *   fe_contact_begin   before the elements, after fe_par_team: last step's power, the search
 *                      when a node moved far enough, the live list (reads x, v, node_fc);
 *   fe_contact_live    thread t's live chunks (those of its nodes), when fe_contact_threaded;
 *                      writes only its own records; any time before fe_contact_finish;
 *   fe_contact_finish  after the gather zeroed node_fext: the entries fe_contact_live did not
 *                      run, the scatter, node_fc into node_fext, energies. */
void fe_contact_begin(const fe_model *m, struct fe_state *s);
int fe_contact_threaded(const fe_model *m, const struct fe_state *s);
void fe_contact_live(const fe_model *m, struct fe_state *s, int t);
void fe_contact_finish(const fe_model *m, struct fe_state *s);
/* contact energy at t (elastic + dissipated) and the contact work included in work_ext [J] */
double fe_contact_energy(const fe_model *m, const struct fe_state *s);
/* the slave entries a threaded contact shares among the threads, 0 when it runs on one
 * (fe_par_team counts them as work) */
long fe_contact_omp_work(const fe_model *m);
double fe_contact_work(const fe_model *m, const struct fe_state *s);

/* move an ellipsoid (stage-1 coupling): centre [m], rotation body -> world (row major) [-],
 * velocity [m/s] and angular velocity [rad/s] over the coming step (the surface moves at
 * v + w x (x - c)); R may be NULL to keep the orientation, w NULL for none. The contact
 * force and moment of the structure on it come back in ell_force, ell_moment, the work it
 * did in ell_work. */
void fe_contact_set_ellipsoid(const fe_model *m, struct fe_state *s, int i, const double c[3],
                              const double R[9], const double v[3], const double w[3]);
/* the same for rigid facet surface i (c: its reference point) */
void fe_contact_set_facets(const fe_model *m, struct fe_state *s, int i, const double c[3],
                           const double R[9], const double v[3], const double w[3]);

/* nearest point of an ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 (body frame) to p; returns
 * the signed distance (< 0 inside) and the point in q [m] */
double fe_ellipsoid_nearest(const double semi[3], const double p[3], double q[3]);

#endif
