/* fe_model: the immutable explicit-FE model (nodes, elements, parts, materials, sections,
 * boundary conditions, loads, rigid walls) and the builder that assembles it.
 *
 * A model is built once: parts are added with a generated mesh (DESIGN.md `fe:` block keys:
 * the descriptor fields below carry the same names) or with explicit nodes and elements, then
 * fe_model_create() validates everything, computes lumped masses and the node-to-element
 * gather lists, and freezes it. The time loop only reads it (fe_state holds what changes).
 *
 * Element kinds live in separate flat arrays (hex8, shell4, truss2), each sorted by part so
 * an element loop runs over contiguous ranges. Internal forces are stored per element slot
 * (element x local node) and gathered per node, so element loops never write to shared nodes.
 * Units are SI throughout. */
#ifndef FE_MODEL_H
#define FE_MODEL_H

#include <stddef.h>

#include "core/mcs_error.h"

#define FE_NAME_MAX 64   /* longest part / wall name + 1                 */
#define FE_CURVE_MAX 32  /* most points in a hardening or load table       */
#define FE_NIP_MAX 10    /* most through-thickness points of a shell       */
#define FE_WALL_MAX 32   /* most rigid walls (one bit each in a node mask) */

/* ---- descriptors: what a part is made of (the `fe:` block keys) ------------------------ */

typedef enum {
    FE_MESH_NONE,           /* nodes and elements added explicitly             */
    FE_MESH_BOX,            /* hex8 block: size, divisions, origin (min corner) */
    FE_MESH_PLATE,          /* shell plate: size[0..1], divisions[0..1], origin, axis = normal */
    FE_MESH_SQUARE_TUBE,    /* shell tube: side, length, element_size, axis    */
    FE_MESH_CIRCULAR_TUBE,  /* shell tube: diameter, length, element_size, axis */
    FE_MESH_LINE,           /* truss line: origin -> end, divisions[0]          */
    FE_MESH_SPHERE_SHELL,   /* closed sphere of quads: radius, element_size, origin = centre */
    FE_MESH_CYLINDER_SHELL, /* circular cylinder: diameter, length, element_size, axis,
                               origin = centre of the w = 0 end; closed: end caps (triangles) */
    FE_MESH_FLAT_BAG        /* closed flat bag, two panels sewn at their edges: size[0..1],
                               gap, element_size, axis = panel normal, origin = centre */
} fe_mesh_kind;

typedef struct {
    fe_mesh_kind generate; /* which generator                                          */
    double size[3];        /* box edge lengths / plate in-plane lengths [m]              */
    int divisions[3];      /* elements per direction [-]                                */
    double origin[3];      /* box/plate min corner; line start [m]                      */
    double end[3];         /* line end [m]                                              */
    double side;           /* square tube side (mid-surface) [m]                        */
    double diameter;       /* circular tube diameter (mid-surface) [m]                  */
    double length;         /* tube length along the axis, from 0 to length [m]          */
    double element_size;   /* target element edge for tubes [m]                         */
    int axis;              /* tube axis / plate normal: 0 x, 1 y, 2 z [-]               */
    double radius;         /* sphere_shell radius [m]                                   */
    int closed;            /* cylinder_shell: add end caps (a closed surface) [-]       */
    double gap;            /* flat_bag: distance of the panels' inner nodes [m]         */
} fe_mesh_desc;

typedef enum {
    FE_SECTION_SOLID,
    FE_SECTION_SHELL,
    FE_SECTION_TRUSS,
    FE_SECTION_MEMBRANE, /* 3-node membrane (fe_membrane.c); stored as degenerate shells */
    FE_SECTION_TET10     /* 10-node quadratic tetrahedron, 4 Gauss points (fe_tet10.c) */
} fe_section_type;
typedef enum { FE_HG_VISCOUS, FE_HG_STIFFNESS } fe_hourglass;
/* hex8 formulation: one point + hourglass control (default), or 2x2x2 Gauss with the mean
 * dilatation (B-bar) volumetric term (fe_hex_full.c) */
typedef enum { FE_HEX_ONE_POINT, FE_HEX_FULL } fe_hex_formulation;

typedef struct {
    fe_section_type type;         /* solid (hex8) | shell (BT quad) | truss (2-node)           */
    double thickness;             /* shell thickness [m]                                        */
    int integration_points;       /* shell points through the thickness (Gauss), 1..10 [-]     */
    double area;                  /* truss cross-section area [m^2]                             */
    int tension_only;             /* truss carries no compression (cable) [-]                   */
    fe_hourglass hourglass;       /* hourglass control form                                     */
    double hourglass_coefficient; /* Q_hg [-]; 0 takes the default (0.1 viscous, 0.05 stiffness) */
    double shear_factor;          /* shell transverse shear factor; 0 takes 5/6 [-]             */
    fe_hex_formulation formulation; /* solid: one point (default) or fully integrated          */
} fe_section_desc;

typedef enum {
    FE_MAT_ELASTIC,
    FE_MAT_ELASTIC_PLASTIC,
    FE_MAT_FABRIC, /* membranes only: no compressive stress (fe_fabric.c) */
    FE_MAT_FOAM,   /* hex8: rate-dependent hysteretic foam (fe_foam.c) */
    FE_MAT_RIGID,  /* any element: the part is one 6-DOF body (fe_rigid.c) */
    FE_MAT_NULL    /* any element: no stress, mass only (LS-DYNA *MAT_NULL without an
                      equation of state); youngs_modulus (may be 0) serves contact only */
} fe_mat_model;

#define FE_FOAM_NCURVE 8 /* most loading curves (strain rates) of a foam */

typedef struct {
    fe_mat_model model;                /* elastic | elastic_plastic                          */
    double density;                    /* [kg/m^3]                                           */
    double youngs_modulus;             /* [Pa]                                               */
    double poisson;                    /* [-]                                                */
    double yield_stress;               /* initial yield, used when no hardening table [Pa]   */
    int nhardening;                    /* points in hardening (0: perfectly plastic) [-]     */
    double hardening[FE_CURVE_MAX][2]; /* (plastic strain [-], flow stress [Pa]), from 0     */
    double cowper_symonds_c;           /* rate factor 1+(rate/C)^(1/p); 0 = off [1/s]        */
    double cowper_symonds_p;           /* [-]                                                */
    /* fabric: youngs_modulus/poisson are the fibre-a (warp) values; orthotropic when
       fabric_e2 > 0 (fibre b = in-plane normal to a) */
    double fabric_e2;                  /* modulus along fibre b (weft); 0 isotropic [Pa]     */
    double fabric_g12;                 /* in-plane shear modulus; 0: E/(2(1+nu)) [Pa]        */
    double fabric_direction[3];        /* fibre a, projected on each element at t = 0; zero:
                                          the element's first side [-]                        */
    double fabric_damping;             /* stiffness-proportional damping, fraction of critical
                                          at the element's highest frequency [-] (0)         */
    /* foam (fe_foam.c): nominal stress vs. engineering compressive strain, one curve per rate */
    int nfoam_curve;                   /* loading curves (1..FE_FOAM_NCURVE) [-]               */
    double foam_rate[FE_FOAM_NCURVE];  /* their engineering strain rates, increasing [1/s]    */
    int foam_npoint[FE_FOAM_NCURVE];   /* points of each curve (2..FE_CURVE_MAX) [-]          */
    double foam_curve[FE_FOAM_NCURVE][FE_CURVE_MAX][2]; /* (strain [-], stress [Pa]) from (0,0) */
    double foam_hysteresis;            /* unloading factor HU in (0, 1]; 1: no hysteresis [-]  */
    double foam_shape;                 /* unloading shape exponent (> 0; 0 takes 1) [-]        */
    double foam_tension_cutoff;        /* largest tensile stress (0: no cutoff) [Pa]           */
    unsigned rigid_fix;                /* rigid: FE_DOF_* held on the body, global axes (LS-DYNA
                                          *MAT_RIGID CMO 1 CON1/CON2); rotations all or none */
    double failure_strain;             /* elastic_plastic, one-point hex and shell parts: an
                                          element whose plastic strain reaches this (a shell: at
                                          any point through the thickness) is deleted, element
                                          erosion (fe_stages.c); 0: never [-]                 */
} fe_material_desc;

/* a rigid part's given mass properties (LS-DYNA *PART_INERTIA), used instead of the sums
 * over its nodes (fe_rigid.c) */
typedef struct {
    int given;                 /* 1: use these [-]                                          */
    double mass;               /* [kg]                                                      */
    double cg[3];              /* centre of mass at t = 0 [m]                               */
    double inertia[3][3];      /* about cg, global axes, symmetric positive definite [kg m^2] */
    double velocity[3];        /* initial velocity of the centre of mass [m/s]              */
    double omega[3];           /* initial angular velocity [rad/s]                          */
} fe_rigid_inertia;

typedef struct {
    char name[FE_NAME_MAX];     /* unique part name                                        */
    fe_mesh_desc mesh;          /* generated mesh (FE_MESH_NONE: add nodes/elements yourself) */
    fe_section_desc section;    /* element type and its properties                         */
    fe_material_desc material;  /* constitutive model                                      */
    double initial_velocity[3]; /* of every node of the part [m/s]                         */
    fe_rigid_inertia rigid;     /* rigid parts: given mass properties (rigid.given 0: none) */
} fe_part_desc;

/* degrees of freedom, as a mask for `fix` */
enum {
    FE_DOF_X = 1, FE_DOF_Y = 2, FE_DOF_Z = 4, FE_DOF_RX = 8, FE_DOF_RY = 16, FE_DOF_RZ = 32,
    FE_DOF_TRANS = 7, FE_DOF_ROT = 56, FE_DOF_ALL = 63
};

/* node selection on a part's bounding box */
typedef enum {
    FE_WHERE_ALL, FE_WHERE_X_MIN, FE_WHERE_X_MAX, FE_WHERE_Y_MIN,
    FE_WHERE_Y_MAX, FE_WHERE_Z_MIN, FE_WHERE_Z_MAX
} fe_where;

typedef struct {
    char part[FE_NAME_MAX]; /* part whose nodes are selected                              */
    fe_where where;         /* which of them                                              */
    unsigned fix;           /* FE_DOF_* mask of constrained dofs                          */
    double velocity[3];     /* prescribed translational velocity of the fixed x/y/z dofs [m/s] */
} fe_boundary_desc;

typedef struct {
    char part[FE_NAME_MAX];     /* part whose nodes are loaded                               */
    fe_where where;             /* which nodes; the force is split equally between them       */
    double force[3];            /* total force at scale 1 [N]                                */
    int ncurve;                 /* points in curve; 0: constant scale 1 [-]                  */
    double curve[FE_CURVE_MAX][2]; /* (time [s], scale [-]); held constant beyond the ends    */
} fe_load_desc;

typedef enum { FE_WALL_KINEMATIC, FE_WALL_PENALTY } fe_wall_method;

/* what a wall motion curve gives (LS-DYNA *BOUNDARY_PRESCRIBED_MOTION VAD 0, 1, 2) */
typedef enum { FE_MOTION_VELOCITY, FE_MOTION_ACCELERATION, FE_MOTION_DISPLACEMENT } fe_motion_kind;

/* one component of a wall's prescribed motion (fe_wall_motion.c): the wall moves along
 * `direction` by the curve's displacement, or its integral (velocity) or double integral from
 * rest (acceleration), on top of `velocity` t */
typedef struct {
    fe_motion_kind kind;
    double direction[3];           /* made unit at build [-]                              */
    int ncurve;                    /* points, 1..FE_CURVE_MAX [-]                          */
    double curve[FE_CURVE_MAX][2]; /* (time [s], value [m | m/s | m/s^2]), time increasing,
                                      held constant beyond the ends                         */
} fe_wall_motion;
#define FE_WALL_NMOTION 3 /* most motion components of one wall */

typedef struct {
    char name[FE_NAME_MAX];   /* wall name (results: /stage3/rigidwall/<name>)               */
    double point[3];          /* a point of the plane at t = 0 [m]                           */
    double normal[3];         /* points to the side whose nodes the wall stops (normalised) [-] */
    double velocity[3];       /* prescribed wall velocity [m/s]                              */
    fe_wall_method method;    /* kinematic (default) or penalty                              */
    double penalty_scale;     /* penalty: stiffness = scale * m / dt^2 per node; 0 -> 0.1 [-] */
    int nparts;               /* 0: every node in front of the wall at t = 0 is a slave       */
    char parts[8][FE_NAME_MAX]; /* slave parts                                              */
    double mass;              /* > 0: a free wall of this mass moving along its normal, with
                                 `velocity` (along the normal) as its initial velocity, either
                                 method (LS-DYNA *RIGIDWALL_PLANAR_MOVING) [kg]             */
    int nmotion;              /* prescribed motion components (0: `velocity` alone) [-]      */
    fe_wall_motion motion[FE_WALL_NMOTION]; /* LS-DYNA *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL */
    double friction;          /* Coulomb coefficient (LS-DYNA FRIC): 0 frictionless, 1 (or
                                 more) no sliding once in contact [-]                       */
} fe_wall_desc;

/* ---- model options (not per part) ----------------------------------------------------- */

typedef struct {
    double dt_scale;            /* safety factor on the stable step [-] (0.9)                  */
    double dt_max;              /* upper bound on the step; 0 none [s]                         */
    double dt_min;              /* a smaller stable step stops the run [s] (1e-12)             */
    double damping;             /* mass-proportional damping c: f = -c m v [1/s] (0)           */
    double bulk_q1;             /* quadratic bulk viscosity (hex) [-] (1.5)                    */
    double bulk_q2;             /* linear bulk viscosity (hex) [-] (0.06)                      */
    double energy_growth_limit; /* stop when total energy grows by more than this fraction of
                                   the largest energy seen [-] (0.05); 0 disables            */
    double history_interval;    /* sampling interval of the history arrays [s] (0: every step) */
    int history_capacity;       /* samples kept (0: none) [-]                                  */
    double gravity[3];          /* acceleration of gravity on every node with mass [m/s^2] (0) */
    double mass_scaling_dt;     /* target step, safety factor included: elements whose step is
                                   smaller get mass so theirs is this (LS-DYNA DT2MS < 0); 0 off [s] */
    int mass_scaling_interval;  /* > 0: also during the run, every this many cycles, elements
                                   whose step fell below the target get mass (fe_massscale.c);
                                   0: at t = 0 only [-]                                        */
} fe_opts;

fe_opts fe_opts_default(void);

/* ---- the frozen model ------------------------------------------------------------------ */

typedef struct {
    char name[FE_NAME_MAX];
    fe_section_desc section;
    fe_material_desc material;
    int elem_kind;      /* FE_KIND_HEX | FE_KIND_SHELL | FE_KIND_TRUSS | FE_KIND_TET10 */
    int elem_begin;     /* first element of this part in its kind's arrays [-]          */
    int elem_end;       /* one past the last [-]                                       */
    int node_begin;     /* nodes created with the part (generated meshes) [-]           */
    int node_end;
    /* derived material constants */
    double lambda, mu;  /* Lamé constants [Pa]                                          */
    double bulk;        /* bulk modulus [Pa]                                            */
    double wave_speed;  /* dilatational (solid), plate (shell), bar (truss) speed [m/s]  */
    double hg_coef;     /* effective Q_hg [-]                                           */
    double shear_factor;/* shell transverse shear factor [-]                            */
    double ip_z[FE_NIP_MAX]; /* shell point positions in [-1/2, 1/2] of the thickness [-] */
    double ip_w[FE_NIP_MAX]; /* their weights, summing to 1 [-]                           */
    int gp_begin;       /* fully integrated hex: first of its 8 x nelem Gauss points in hex_gp */
    int body;           /* rigid part: its body (fe_rigid.c); -1 otherwise [-]          */
    int foam_begin;     /* foam hex: first of its points (1 or 8 per element) in foam_hist [-] */
    fe_rigid_inertia rigid; /* rigid part: given mass properties (rigid.given 0: none)    */
} fe_part;

enum { FE_KIND_HEX, FE_KIND_SHELL, FE_KIND_TRUSS, FE_KIND_TET10, FE_NKIND };

typedef struct {
    double point[3], normal[3], velocity[3]; /* [m], [-], [m/s]                             */
    fe_wall_method method;
    double penalty_scale;                    /* [-]                                          */
    char name[FE_NAME_MAX];
    double mass;                             /* > 0: free wall moving along its normal [kg]  */
    int nmotion;                             /* prescribed motion components [-]             */
    fe_wall_motion motion[FE_WALL_NMOTION];  /* unit directions                              */
    double friction;                         /* Coulomb coefficient; >= 1: sticking [-]      */
} fe_wall;

typedef struct {
    int node;              /* loaded node [-]                                              */
    double force[3];       /* force at scale 1 [N]                                         */
    int load;              /* index of its load curve [-]                                  */
} fe_nodal_load;

typedef struct {
    int ncurve;
    double curve[FE_CURVE_MAX][2];
} fe_load_curve;

/* a pressure on a segment (LS-DYNA *LOAD_SEGMENT): p x scale(t) over the segment's current
 * area, against its normal (right-hand rule over node[0..3]), shared equally by its nodes */
typedef struct {
    int node[4];           /* segment nodes (a triangle repeats its 3rd) [-]                */
    double p;              /* pressure at scale 1 [Pa]                                      */
    int load;              /* index of its load curve [-]                                  */
} fe_pressure;

/* the model's arrays: X(type, name, count (a size field), components, unit, what).
 * Drives the struct layout, allocation, freeing and the memory count (STYLE.md §4). */
#define FE_MODEL_ARRAYS(X)                                                                         \
    X(double, node_x0, nnode, 3, "m", "initial position")                                          \
    X(double, node_v0, nnode, 3, "m/s", "initial velocity")                                        \
    X(double, node_w0, nnode, 3, "rad/s", "initial angular velocity (carried shell nodes)")        \
    X(double, node_mass, nnode, 1, "kg", "lumped mass")                                            \
    X(double, node_inertia, nnode, 1, "kg m^2", "lumped rotary inertia (shell nodes)")             \
    X(unsigned, node_fix, nnode, 1, "-", "FE_DOF_* mask of constrained dofs")                      \
    X(double, node_vfix, nnode, 3, "m/s", "prescribed velocity of fixed translations")             \
    X(unsigned, node_walls, nnode, 1, "-", "bit w: slave of rigid wall w")                         \
    X(int, node_part, nnode, 1, "-", "part of the node (of its first element)")                    \
    X(int, node_slot_off, nnode + 1, 1, "-", "gather list offsets")                                \
    X(int, node_slot, nslot, 1, "-", "element-node force slots of each node")                      \
    X(int, hex_node, nhex, 8, "-", "hex8 connectivity")                                            \
    X(int, hex_part, nhex, 1, "-", "part of each hex")                                             \
    X(int, shell_node, nshell, 4, "-", "shell connectivity, counter-clockwise about the normal")   \
    X(int, shell_part, nshell, 1, "-", "part of each shell")                                       \
    X(double, shell_t, nshell, 1, "m", "shell thickness (its own, else its section's)")            \
    X(int, truss_node, ntruss, 2, "-", "truss connectivity")                                       \
    X(int, truss_part, ntruss, 1, "-", "part of each truss")                                     \
    X(int, tet10_node, ntet10, 10, "-", "tet10 connectivity: corners 1-4, then mid-edges 12 23 31 14 24 34") \
    X(int, tet10_part, ntet10, 1, "-", "part of each tet10")                                       \
    X(double, tet10_dtf, ntet10, 1, "-", "tet10 step factor: (2 / omega_max) / (l / c) at t = 0") \
    X(int, node_body, nnode, 1, "-", "rigid body carrying the node, -1 none")                      \
    X(double, shell_mref, nshell_mref, 8, "-",                                                     \
      "membrane reference: b (3), c (3) [1/m], area [m^2], altitude [m] (fe_membrane.c)")        \
    X(int, chunk_part, nchunk, 1, "-", "part of each element chunk (threaded element loops)")      \
    X(int, chunk_elem, nchunk, 1, "-", "first element of each chunk, index in its kind")           \
    X(int, chunk_nc, nchunk, 1, "-", "first node chunk of each element chunk's thread share")

struct fe_contact_model;

typedef struct fe_model {
    /* sizes */
    int nnode, nelem;      /* nodes; elements of every kind                              */
    int nhex, nshell, ntruss;
    int ntet10;            /* 10-node tetrahedra (fe_tet10.c) [-]                         */
    int npart, nwall, nload, nnodal_load;
    int nslot;             /* element-node force slots: 8 nhex + 4 nshell + 2 ntruss + 10 ntet10 */
    int nip_max;           /* largest number of shell points through the thickness        */
    int nshell_ip;         /* nshell x nip_max: shell stress points [-]                    */

    /* every per-node and per-element array, declared once (FE_MODEL_ARRAYS) */
#define FE_X_DECL(T, name, n, k, unit, doc) T *name;
    FE_MODEL_ARRAYS(FE_X_DECL)
#undef FE_X_DECL
    int slot_base[FE_NKIND]; /* first slot of each kind [-]                              */

    fe_part *part;         /* (npart)                                                     */
    fe_wall *wall;         /* (nwall)                                                     */
    fe_nodal_load *nodal_load; /* (nnodal_load)                                           */
    fe_load_curve *load_curve; /* (nload)                                                 */
    int npressure;             /* pressure segments [-]                                   */
    fe_pressure *pressure;     /* (npressure)                                             */

    fe_opts opts;
    double dt_initial;     /* stable step of the undeformed mesh, safety factor applied [s] */
    double mass_total;     /* [kg]                                                        */
    size_t bytes;          /* memory held by the model [B]                                 */
    struct fe_restraints *restraints; /* gas bags and retractors (fe_restraint.h); NULL none */

    /* discrete springs and dampers, rigid bodies, mass scaling (fe_discrete.c, fe_rigid.c,
     * fe_massscale.c) */
    int nspring;           /* discrete springs/dampers [-]                                 */
    struct fe_spring *spring; /* (nspring)                                                 */
    double dt_discrete;    /* stable step of the springs, no safety factor (inf: none) [s]  */
    int nbody, nbody_node; /* rigid bodies; nodes they carry [-]                           */
    struct fe_body *body;  /* (nbody)                                                      */
    int *body_node;        /* nodes of the bodies, body by body (nbody_node)               */
    double *body_r0;       /* those nodes about their body's centre of mass at t = 0 [m] (nbody_node x 3) */
    int nhex_gp;           /* Gauss points of fully integrated hexes (8 each) [-]          */
    double *elem_dt_factor; /* mass scaling: element step factor, hex then shell then truss
                               (nelem), NULL without mass scaling [-]                       */
    double mass_added;     /* mass added by mass scaling [kg]                              */
    struct fe_contact_model *contact; /* contact interfaces (fe_contact.h), NULL if none   */
    /* threaded loops (fe_parallel.c): elements in chunks of FE_CHUNK_ELEMS within a part and
     * nodes in chunks of FE_CHUNK_NODES, each reduced in chunk order (thread-count independent) */
    int nchunk;            /* element chunks [-]                                           */
    int nelem_chunked;     /* elements of the parts in the threaded chunk loops [-]        */
    int nnode_chunk;       /* node chunks [-]                                              */
    int node_acc_stride;   /* partial sums per node chunk: FE_NACC_FIXED + npart + 3 FE_WALL_MAX */
    int nnode_acc;         /* nnode_chunk x node_acc_stride [-]                            */
    int nshell_rate;       /* nshell_ip when a shell part has a rate factor, else 0 [-]    */
    int nshell_mref;       /* nshell when a part is a membrane (its t = 0 reference geometry
                              is kept, fe_membrane.c), else 0 [-]                          */
    int nspring_part;      /* spring parts (energies per part, fe_discrete.c) [-]          */
    int nms_node, nms_elem; /* run-time mass scaling: nnode, nelem (0 when off) [-]        */
    double *elem_ms0;      /* (nms_elem) density factor of the t = 0 mass scaling (1 none) [-] */
    double *elem_mass0;    /* (nms_elem) element mass at t = 0 without scaling [kg]        */
    char (*spring_part)[FE_NAME_MAX]; /* their names (nspring_part)                        */
    int nfoam_ip;          /* integration points of foam hexes (1 or 8 per element) [-]    */
    struct fe_sliprings *sliprings; /* belt slip rings (fe_slipring.h), NULL if none      */
    /* kinematic walls with mass (fe_wall_kin.c): their slave nodes, wall by wall */
    int nerode;            /* element erosion: nhex + nshell when a part has a failure
                              strain (element e of kind k at e, nhex + e for shells), else 0 */
    int nwall_slave;       /* slave nodes of kinematic walls with mass, all walls [-]      */
    int nwall_part;        /* nwall x npart: penalty walls' normal force by part (fe_state
                              wall_part_f, row w: wall w) [-]                              */
    int *wall_slave;       /* (nwall_slave) node indices                                   */
    int wall_slave_off[FE_WALL_MAX + 1]; /* wall w's slaves: wall_slave_off[w] ..[w+1] [-]  */
    int njoint;            /* joints between rigid bodies (fe_joint.h) [-]                 */
    struct fe_joint *joint; /* (njoint)                                                    */
} fe_model;

#define FE_CHUNK_ELEMS 128 /* elements per chunk of a threaded element loop [-]            */
#define FE_CHUNK_NODES 128 /* nodes per chunk of a threaded node loop [-]                  */
/* smaller models run their loops on one thread (a parallel region costs microseconds) */
#define FE_PAR_MIN_CHUNKS 8      /* element chunks [-]                                   */
#define FE_PAR_MIN_NODE_CHUNKS 4 /* node chunks [-]                                      */
/* and each thread gets at least this many threaded elements or contact entries: a step opens
 * 4-6 parallel regions, and a tiny model stepped in short subcycles (a stage-1 coupling) paid
 * more for them than its loops took (docs/fe.md "Threads and speed") */
#define FE_PAR_MIN_WORK 512 /* [-] */
#define FE_PAR_MAX 64            /* threads used at most by the FE loops [-]             */
#define FE_PAR_WINDOW 64         /* steps between two balances of the thread shares [-]  */

/* ---- the builder ------------------------------------------------------------------------ */

typedef struct fe_builder fe_builder;

mcs_status fe_builder_create(fe_builder **out, mcs_error *err);
void fe_builder_destroy(fe_builder **p);

/* add a part; a generated mesh is created now. Returns the part index in *index (may be NULL). */
mcs_status fe_builder_add_part(fe_builder *b, const fe_part_desc *d, int *index, mcs_error *err);
/* explicit meshes: a node, then elements of a part (4 nodes for shells, 8 hex, 2 truss,
 * 10 tet10: corners N1..N4, then the mid-edge nodes of 1-2, 2-3, 3-1, 1-4, 2-4, 3-4).
 * A shell with its 3rd and 4th node equal is a degenerate triangle. */
mcs_status fe_builder_add_node(fe_builder *b, const double x[3], int *index, mcs_error *err);
mcs_status fe_builder_add_elem(fe_builder *b, int part, const int *nodes, mcs_error *err);
/* a shell of its own thickness [m] (> 0; the section's thickness is the others') */
mcs_status fe_builder_add_shell(fe_builder *b, int part, const int nodes[4], double thickness,
                                mcs_error *err);
mcs_status fe_builder_add_boundary(fe_builder *b, const fe_boundary_desc *d, mcs_error *err);
mcs_status fe_builder_fix_node(fe_builder *b, int node, unsigned fix, const double vel[3],
                               mcs_error *err);
/* the initial velocity of one node, replacing its part's (LS-DYNA *INITIAL_VELOCITY_NODE) */
mcs_status fe_builder_node_velocity(fe_builder *b, int node, const double v[3], mcs_error *err);
mcs_status fe_builder_add_load(fe_builder *b, const fe_load_desc *d, mcs_error *err);
/* one node's share of a load; curve as in fe_load_desc (ncurve 0: constant) */
mcs_status fe_builder_add_nodal_load(fe_builder *b, int node, const double force[3], int ncurve,
                                     const double (*curve)[2], mcs_error *err);
/* a pressure p [Pa] on segment nodes[4] (fe_pressure), times the curve (time [s], scale)
 * (ncurve 0: constant) */
mcs_status fe_builder_add_pressure(fe_builder *b, const int nodes[4], double p, int ncurve,
                                   const double (*curve)[2], mcs_error *err);
mcs_status fe_builder_add_wall(fe_builder *b, const fe_wall_desc *d, mcs_error *err);
int fe_builder_nnode(const fe_builder *b);
/* index of a part by name, -1 if none */
int fe_builder_find_part(const fe_builder *b, const char *name);
/* 1 when part (an index from fe_builder_find_part) is rigid (material model rigid) */
int fe_builder_part_rigid(const fe_builder *b, int part);
/* nodes of a part on its bounding-box side `where`, written to idx (capacity cap); count returned */
int fe_builder_select(const fe_builder *b, int part, fe_where where, int *idx, int cap);
/* the initial metric method (fe_imm.c): the nodes of membrane part `part` (nodes of its own)
 * move to about + scale (x - about) (about NULL: the middle of the part's bounding box; each
 * scale factor in (0, 1]); the elements keep the unscaled mesh as their stress-free reference
 * and their masses */
mcs_status fe_builder_imm(fe_builder *b, int part, const double scale[3], const double *about,
                          mcs_error *err);
/* the node of a part nearest to p [m] (the first of equals), -1 if the part has none */
int fe_builder_nearest(const fe_builder *b, int part, const double p[3]);

/* validate and freeze; opts NULL takes fe_opts_default() */
mcs_status fe_model_create(const fe_builder *b, const fe_opts *opts, fe_model **out,
                           mcs_error *err);
void fe_model_destroy(fe_model **p);

/* descriptors with the documented defaults (zeros elsewhere) */
fe_part_desc fe_part_desc_default(void);

/* ---- discrete springs and dampers, point masses (fe_discrete.c) ------------------------- */

/* a spring end: a node; or (node -1) the node of `part` nearest to `point`; or (node -1,
 * part "") a fixed anchor at `point` */
typedef struct {
    int node;               /* node index, or -1 [-]                                      */
    char part[FE_NAME_MAX]; /* part to pick the node from ("" with node -1: anchor)       */
    double point[3];        /* [m]                                                        */
} fe_spring_end;

typedef struct {
    char name[FE_NAME_MAX];        /* for messages                                          */
    fe_spring_end end[2];
    double stiffness;              /* F = k (l - l0), tension positive [N/m]                */
    int ncurve;                    /* > 0: F = curve(l - l0) instead of k [-]              */
    double curve[FE_CURVE_MAX][2]; /* (elongation [m], force [N]), elongation increasing    */
    double damping;                /* F = c dl/dt [N s/m]                                   */
    char part[FE_NAME_MAX];        /* spring part its energies are reported under ("":
                                      "springs"); a name of its own, not an element part's    */
} fe_spring_desc;

/* a point mass: on one node, on the node of a part nearest to a point, or split equally
 * over a part's nodes on a side (`where`) */
typedef struct {
    int node;               /* node index, or -1: select in part [-]                      */
    char part[FE_NAME_MAX];
    fe_where where;         /* with at_point 0                                            */
    int at_point;           /* 1: the node of part nearest to point [-]                    */
    double point[3];        /* [m]                                                        */
    double mass;            /* total added mass [kg]                                      */
} fe_mass_desc;

mcs_status fe_builder_add_spring(fe_builder *b, const fe_spring_desc *d, mcs_error *err);
/* index of a spring part by name, -1 if none */
int fe_spring_part_find(const struct fe_model *m, const char *name);
mcs_status fe_builder_add_mass(fe_builder *b, const fe_mass_desc *d, mcs_error *err);

#endif
