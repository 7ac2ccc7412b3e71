/* fe_builder_impl: the builder's insides, shared by fe_builder.c, fe_mesh.c and fe_model.c. */
#ifndef FE_BUILDER_IMPL_H
#define FE_BUILDER_IMPL_H

#include "fe/fe_contact.h"
#include "fe/fe_model.h"

typedef struct {
    int node;      /* constrained node [-]                                 */
    unsigned fix;  /* FE_DOF_* mask [-]                                    */
    double v[3];   /* prescribed velocity of fixed translations [m/s]      */
} fe_node_fix;

typedef struct {
    int node;        /* one node, or -1: the part/where selection of d; -2: a pressure */
    fe_load_desc d;  /* a pressure's: force[0] the pressure [Pa], its curve             */
    int seg[4];      /* a pressure's segment nodes                                      */
} fe_bload;

struct fe_builder {
    int nnode, cap_node;
    double *x;                                    /* (nnode x 3) [m]      */
    double *x_sel;  /* positions `where` selects on, before a placement moved x (fe_scn_place.c);
                       NULL: x (nnode x 3) [m] */
    double *xref;   /* reference (design) positions when a membrane part starts on a scaled
                       copy of its mesh (fe_imm.c); NULL: x is the reference (nnode x 3) [m] */
    int cap_xref;   /* nodes xref has room for [-] */
    int nelem[FE_NKIND], cap_conn[FE_NKIND], cap_epart[FE_NKIND];
    int *conn[FE_NKIND];                          /* connectivity per kind */
    int *epart[FE_NKIND];                         /* part per element      */
    double *shell_t;  /* own thickness of shells (nshell_t; 0: the section's) [m] */
    int nshell_t, cap_shell_t;
    int npart, cap_part;
    fe_part_desc *part;
    int nbc, cap_bc;
    fe_boundary_desc *bc;
    int nfix, cap_fix;
    fe_node_fix *fix;
    int nvel, cap_vel;
    fe_node_fix *vel;  /* initial velocities of single nodes (v; fix unused) */
    int nload, cap_load;
    fe_bload *load;
    int nwall;
    fe_wall_desc wall[FE_WALL_MAX];
    struct fe_restraint_list *restraints; /* gas bags and retractors to add (fe_restraint.c) */
    int nspring, cap_spring;                      /* discrete springs (fe_discrete.c) */
    fe_spring_desc *spring;
    int nmass, cap_mass;                          /* point masses                      */
    fe_mass_desc *mass;
    int ncontact, nellipsoid;                     /* contact descriptors (fe_contact.h) */
    fe_contact_desc contact[FE_CONTACT_MAX];
    fe_ellipsoid_desc ellipsoid[FE_ELLIPSOID_MAX];
    int nfacets;                                  /* rigid facet surfaces; vert and tri are
                                                     the builder's copies (owned)      */
    fe_facet_desc facets[FE_FACETS_MAX];
    struct fe_slipring_list *sliprings;           /* slip rings to add (fe_slipring.c) */
    struct fe_joint_list *joints; /* joints, nodal rigid bodies, extra nodes (fe_joint.c) */
};

int fe_kind_nnode(int kind);
int fe_section_kind(fe_section_type t);
void fe_builder_part_nodes(const fe_builder *b, int part, unsigned char *mark);
/* the node of part `name` nearest to p at t = 0 (m->node_x0), using mark (nnode + 1 bytes)
 * as scratch; -1 with an error naming `what` if the part is unknown or has no nodes
 * (fe_discrete.c) */
int fe_builder_nearest_node(const fe_builder *b, const fe_model *m, const char *name,
                            const double p[3], unsigned char *mark, const char *what,
                            mcs_error *err);
/* generate the mesh of part ip (fe_mesh.c) */
mcs_status fe_mesh_generate(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err);
/* sphere_shell and cylinder_shell (fe_mesh_shell.c) */
mcs_status fe_mesh_sphere(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err);
mcs_status fe_mesh_cylinder(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err);
mcs_status fe_mesh_flat_bag(fe_builder *b, int ip, const fe_mesh_desc *m, mcs_error *err);
/* fabric material keys of a membrane part (fe_fabric.c) */
mcs_status fe_fabric_check(const fe_part_desc *d, mcs_error *err);
void fe_restraint_list_free(fe_builder *b);
/* room in xref for every node x has room for (fe_imm.c) */
mcs_status fe_builder_imm_grow(fe_builder *b, mcs_error *err);

#endif
