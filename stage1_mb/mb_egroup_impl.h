/* mb_egroup_impl.h: the energy groups' model and state (mb_egroup.c, mb_egroup_work.c) */
#ifndef MB_EGROUP_IMPL_H
#define MB_EGROUP_IMPL_H

#include "stage1_mb/mb_egroup.h"

enum { EG_NONE = -1, EG_INTERNAL = -2 };

typedef struct {
    mb_name name;
    unsigned char *in; /* member flag (nbody)                                   */
    int nmember;
    int npartner;
    mb_name *pname;              /* (npartner)                                            */
    char (*pcat)[MB_EGROUP_CAT]; /* (npartner)                                            */
    /* each source's partner, EG_NONE (no member), EG_INTERNAL (two members) */
    int *pair, *att, *joint;   /* (npair), (nattach), (njoint)                          */
    int *node, *anchor, *surf; /* attached FE nodes (natt), anchors, bodies-contact
                                  kernel surfaces                                      */
    int nnode, nanchor, nsurf;
} eg_group;

struct mb_egroup {
    int ngroup;
    eg_group *g;
};

struct mb_egroup_state {
    int ngroup;
    double *vbar;  /* mean velocity and angular velocity of each body over the step
                      (nbody x 6) [m/s, rad/s]                                             */
    double **work; /* per group: each partner's work on the group so far (npartner) [J]   */
    double **rec;  /* per group: (nout x (MB_EGROUP_NSERIES + npartner)) [J]               */
    double **now;  /* per group: scratch row                                               */
};

#endif
