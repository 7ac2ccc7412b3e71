/* fe_membrane: the 3-node membrane element and the fabric material (fe_membrane.c,
 * fe_fabric.c). Not a public header: the kernel calls fe_membrane_part for parts whose
 * section is FE_SECTION_MEMBRANE (they live in the shell arrays as degenerate triangles). */
#ifndef FE_MEMBRANE_H
#define FE_MEMBRANE_H

#include "fe/fe_state.h"

enum { FE_FABRIC_TAUT, FE_FABRIC_WRINKLED, FE_FABRIC_SLACK };

/* plane-stress stiffness in the fibre frame [Pa]; iso: isotropic (wrinkling by the mixed
 * criterion), E and nu its constants */
typedef struct {
    double q11, q12, q22, q66; /* S = [q11 q12 0; q12 q22 0; 0 0 2 q66] (E11, E22, E12) [Pa] */
    double E, nu;              /* fibre-a modulus [Pa] and Poisson's ratio [-]               */
    int iso;                   /* isotropic [-]                                              */
} fe_fabric_c;

void fe_fabric_constants(const fe_material_desc *mt, fe_fabric_c *c);
/* second Piola-Kirchhoff stress s (xx, yy, xy) [Pa] from the Green strain e (tensor xx, yy,
 * xy) [-], no compressive stress; returns FE_FABRIC_TAUT, _WRINKLED or _SLACK */
int fe_fabric_stress(const fe_fabric_c *c, const double e[3], double s[3]);
/* the (relaxed) strain energy per unit reference volume [J/m^3] of which s is the gradient */
double fe_fabric_energy(const fe_fabric_c *c, const double e[3]);
/* the fastest in-plane wave speed, lowered for the damping's stability limit [m/s] */
double fe_fabric_wave_speed(const fe_material_desc *mt);

/* reference geometry of a membrane triangle: constant gradients (b, c) of the three shape
 * functions in the fibre frame [1/m], area [m^2] and smallest altitude [m]; 0 if degenerate */
typedef struct {
    double b[3], c[3]; /* dN_k/dX, dN_k/dY (fibre frame) [1/m] */
    double area;       /* [m^2]                                 */
    double length;     /* smallest altitude 2 A / longest side [m] */
} fe_membrane_ref;

int fe_membrane_reference(const double X[3][3], const double fibre[3], fe_membrane_ref *r);

/* the reference of every membrane element from node_x0 into m->shell_mref (model build) */
void fe_membrane_references(struct fe_model *m);
/* element loop of a membrane part: stresses, slot forces, energies, element steps */
void fe_membrane_part(const fe_model *m, fe_state *s, int ip);

#endif
