/* fe_keyword: the LS-DYNA keyword subset mcrash reads and writes (docs/keyword.md), so users
 * bring their own meshes and get theirs back.
 *
 * Reading gives a neutral in-memory deck (fe_kw_deck): nodes, elements of each type with their
 * part IDs, parts with section and material IDs, sections, materials, curves, node and part
 * sets, planar rigid walls, initial velocities and single-point constraints, all converted to
 * SI with the deck's unit system (fe_kw_opts.units; keyword decks carry no units). Curves are
 * kept as written (only SFA/SFO/OFFA/OFFO applied): whoever uses one converts its ordinate.
 * Keywords outside the subset are listed in the deck (fe_kw_deck.unknown, each with its file
 * and line) and logged as a warning, or rejected with opts.strict. Errors name FILE:LINE:COL,
 * the keyword and the field, with MCS_ERR_FORMAT (exit status 2).
 *
 * Formats: fixed columns (8/16 for *NODE, 8 for elements, 10 elsewhere, 20 for curve points),
 * I10 (`*KEYWORD I10=Y` or a `%` after a keyword: fields under 10 become 10), long
 * (`*KEYWORD LONG=Y` or a `+` after a keyword: every field 20 wide), and free format (a card
 * with a comma is split at the commas). `$` starts a comment line.
 *
 * Then fe_kw_add_part() puts one part (its nodes and elements) into an fe_builder, with its
 * section and material from the deck or from the caller; fe_kw_add_deck() puts in everything
 * (parts, constraints, initial velocities, rigid walls). fe_kw_from_model() turns a built model
 * into a deck and fe_kw_write() writes a deck in fixed format. */
#ifndef FE_KEYWORD_H
#define FE_KEYWORD_H

#include <stdio.h>

#include "core/mcs_error.h"
#include "fe/fe_model.h"

#define FE_KW_TITLE_MAX 81 /* an 80-column title + 1 */
#define FE_KW_NAME_MAX 48  /* longest keyword name kept for the unknown list + 1 */

/* FE_KW_TET10: 10-node tetrahedra of *ELEMENT_SOLID (two-card form, N1..N10; or
 * *ELEMENT_SOLID_TET4TOTET10, whose mid-edge nodes the reader adds: fe_kw_tet10.c) */
/* FE_KW_TSHELL: *ELEMENT_TSHELL (8-node thick shells): read and counted, refused when built
 * (docs/keyword.md says why) */
typedef enum {
    FE_KW_SHELL, FE_KW_SOLID, FE_KW_BEAM, FE_KW_DISCRETE, FE_KW_TET10, FE_KW_TSHELL, FE_KW_NETYPE
} fe_kw_etype;

/* nodes per element of each type as stored (shell 4, solid 8, beam 2, discrete 2, tet10 10,
 * tshell 8) */
int fe_kw_etype_nnode(fe_kw_etype t);
const char *fe_kw_etype_name(fe_kw_etype t); /* "SHELL", "SOLID", ... */

/* where something was read: deck file index and 1-based line */
typedef struct {
    int file;
    int line;
} fe_kw_loc;

typedef struct {
    int n, cap;
    int *id;       /* element ID (n)                                                   */
    int *pid;      /* part ID (n)                                                      */
    int *node;     /* node IDs (n x fe_kw_etype_nnode); a triangle repeats N3 as N4    */
    double *dval;  /* discrete only: scale factor S [-], offset [m] (n x 2)             */
    fe_kw_loc *loc;/* (n)                                                              */
    int nthick;    /* shells: elements thick has room for (the first nthick) [-]        */
    double *thick; /* shells: THIC1..THIC4 of *ELEMENT_SHELL_THICKNESS, 0 = the section's
                      Ti (nthick x 4; NULL: none given) [m]                              */
} fe_kw_elems;

/* *PART_INERTIA: a rigid part's given mass properties and initial velocity (SI) */
typedef struct {
    int given;       /* 1: the card was read [-]                                           */
    double mass;     /* TM [kg]                                                            */
    double cg[3];    /* XC YC ZC (or NODEID's position) [m]                                */
    int nodeid;      /* NODEID (0: none) [-]                                               */
    double i[6];     /* IXX IXY IXZ IYY IYZ IZZ about the CG, global axes [kg m^2]          */
    double v[3];     /* VTX VTY VTZ [m/s]                                                  */
    double w[3];     /* VRX VRY VRZ [rad/s]                                                */
    int ircs;        /* IRCS (1: principal moments + orientation; refused when built) [-]   */
} fe_kw_inertia;

/* *PART_CONTACT: the part's contact parameters (used by contacts that ask for them) */
typedef struct {
    int given;       /* 1: the card was read [-]                                           */
    double fs, fd;   /* static, dynamic friction [-]                                       */
    double dc;       /* exponential decay coefficient [s/m]                                 */
    double vc;       /* viscous friction coefficient [Pa]                                   */
    double optt;     /* contact thickness (0: the default) [m]                              */
    double sft, ssf; /* thickness and penalty scale factors (0: 1) [-]                       */
} fe_kw_pcontact;

typedef struct {
    int id, secid, mid;
    char title[FE_KW_TITLE_MAX];
    fe_kw_loc loc;
    int eosid;              /* EOSID: *EOS ID (0: none) [-]                               */
    int hgid;               /* HGID: *HOURGLASS ID (0: *CONTROL_HOURGLASS or the default) [-] */
    fe_kw_inertia inertia;  /* *PART_INERTIA                                               */
    fe_kw_pcontact contact; /* *PART_CONTACT                                               */
} fe_kw_part;

typedef enum {
    FE_KW_SEC_SHELL, FE_KW_SEC_SOLID, FE_KW_SEC_BEAM, FE_KW_SEC_DISCRETE, FE_KW_SEC_TSHELL
} fe_kw_sec_kind;

typedef struct {
    int id;
    fe_kw_sec_kind kind;
    int elform;     /* element formulation as written (0: the default); discrete: DRO [-] */
    double shrf;    /* shell shear factor (0: default) [-]                            */
    int nip;        /* shell through-thickness points (0: the default, 2) [-]         */
    double t[4];    /* shell thickness at N1..N4 [m]                                  */
    double area;    /* beam: A of ELFORM 2, 3 (and 12, 13) [m^2]                      */
    int cst;        /* beam: cross-section type CST (0 rectangle, 1 tube, 2 arbitrary) [-] */
    int irid;       /* beam: QR/IRID (< 0: a user integration rule) [-]               */
    double ts[2], tt[2]; /* beam ELFORM 1, 4, 5, 9, 11: TS1 TS2 TT1 TT2 (thicknesses, or
                            tube outer/inner diameters) [m]                             */
    double iss, itt, jt; /* beam ELFORM 2: ISS ITT J [m^4]                                */
    int user;       /* solid: ELFORM 101..105 (user element): its NIP and LMC cards were
                       consumed [-]                                                      */
    fe_kw_loc loc;
} fe_kw_section;

/* *HOURGLASS: HGID IHQ QM IBQ Q1 Q2 QB/VDC QW */
typedef struct {
    int id;
    int ihq;        /* hourglass type (0: the *CONTROL_HOURGLASS / default) [-]          */
    double qm;      /* hourglass coefficient (0: the default) [-]                       */
    double q1, q2;  /* quadratic, linear bulk viscosity (0: the defaults 1.5, 0.06) [-]  */
    double qb, qw;  /* shell bending, warping coefficients (0: QM) [-]                   */
    fe_kw_loc loc;
} fe_kw_hourglass;

/* *CONTROL_HOURGLASS and *CONTROL_TIMESTEP, as read (SI) */
typedef struct {
    int hg_given;            /* *CONTROL_HOURGLASS read [-]                                */
    int hg_ihq;              /* IHQ [-]                                                     */
    double hg_qh;            /* QH (0: the default) [-]                                     */
    fe_kw_loc hg_loc;
    int ts_given;            /* *CONTROL_TIMESTEP read [-]                                  */
    double dtinit;           /* DTINIT (ignored: the kernel computes the first step) [s]    */
    double tssfac;           /* TSSFAC (0: the default 0.9) [-]                             */
    int isdo;                /* ISDO [-]                                                    */
    double tslimt;           /* TSLIMT [s]                                                  */
    double dt2ms;            /* DT2MS [s]                                                   */
    int lctm;                /* LCTM [-]                                                    */
    int ms1st;               /* MS1ST [-]                                                   */
    double dt2msf;           /* card 2: DT2MSF [-]                                          */
    int dt2mslc, imscl;      /* card 2: DT2MSLC, IMSCL [-]                                  */
    fe_kw_loc ts_loc;
} fe_kw_control;

typedef enum {
    FE_KW_MAT_ELASTIC = 1,
    FE_KW_MAT_PK = 3,       /* *MAT_PLASTIC_KINEMATIC (fe_kw_cards_mat.c) */
    FE_KW_MAT_NULL = 9,     /* *MAT_NULL */
    FE_KW_MAT_RIGID = 20,
    FE_KW_MAT_PLP = 24,
    FE_KW_MAT_MR = 27,      /* *MAT_MOONEY-RIVLIN_RUBBER */
    FE_KW_MAT_LDF = 57,     /* *MAT_LOW_DENSITY_FOAM */
    FE_KW_MAT_SPRING = 101, /* *MAT_SPRING_ELASTIC (*MAT_S01) */
    FE_KW_MAT_DAMPER = 102  /* *MAT_DAMPER_VISCOUS (*MAT_S02) */
} fe_kw_mat_type;

typedef struct {
    int id;
    fe_kw_mat_type type; /* *MAT_001 | *MAT_020 | *MAT_024 | *MAT_S01 | *MAT_S02          */
    double ro;           /* density [kg/m^3]                                             */
    double e, pr;        /* Young's modulus [Pa], Poisson's ratio [-]                     */
    double sigy, etan;   /* MAT_024 yield stress, tangent modulus [Pa]                    */
    double c, p;         /* MAT_024 Cowper-Symonds C [1/s] and p [-] (0: off)              */
    int lcss;            /* MAT_024 curve of stress vs. effective plastic strain (0: none) */
    int neps;            /* MAT_024 points of the EPS/ES table given [-]                  */
    double eps[8], es[8];/* EPS1..8 [-], ES1..8 [Pa]                                      */
    double k;            /* MAT_S01 stiffness K [N/m]; MAT_S02 damping DC [N s/m]          */
    fe_kw_loc loc;
    /* fe_kw_cards_mat.c: MAT_003 (sigy, etan, c = SRC, p = SRP above), MAT_009, MAT_020
     * constraints, MAT_027, MAT_057 */
    double beta;         /* MAT_003 hardening parameter BETA (1 isotropic) [-]             */
    double fail;         /* MAT_003 FS, MAT_024 FAIL: failure plastic strain (0: none) [-]  */
    int cmo, con1, con2; /* MAT_020 constraint option and codes as written [-]             */
    double a, b;         /* MAT_027 constants A, B [Pa]                                   */
    int lcid;            /* MAT_057 curve of nominal stress vs. strain [-]                */
    double tc, hu, shape;/* MAT_057 tension cut-off [Pa] (0: none), HU, SHAPE [-]          */
} fe_kw_mat;

typedef struct {
    int id;
    int n;          /* points [-]                                                        */
    double *xy;     /* (n x 2), as written with SFA, SFO, OFFA, OFFO applied, no units    */
    fe_kw_loc loc;
} fe_kw_curve;

typedef struct {
    int id;
    int is_part;    /* 0: *SET_NODE, 1: *SET_PART                                         */
    int n;
    int *ids;       /* node or part IDs (n)                                              */
    fe_kw_loc loc;
} fe_kw_set;

typedef struct {
    int id;                     /* _ID option, else 0                                      */
    char title[FE_KW_TITLE_MAX];
    int nsid;                   /* slave node set (0: every node)                          */
    double tail[3], head[3];    /* XT..ZT, XH..ZH: the normal points from tail to head [m]  */
    double fric;                /* friction [-]                                            */
    fe_kw_loc loc;
    int moving;                 /* *RIGIDWALL_PLANAR_MOVING: a free wall with mass [-]      */
    double mass;                /* MASS: its mass [kg]                                     */
    double v0;                  /* V0: its initial velocity along the normal [m/s]          */
} fe_kw_wall;

/* *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL: ID DOF VAD LCID SF VID DEATH BIRTH, the card of
 * *BOUNDARY_PRESCRIBED_MOTION with the rigid wall's ID (its _ID, else its number in the deck) */
typedef struct {
    int wall;       /* rigid wall ID [-]                                                   */
    int dof;        /* 1 x, 2 y, 3 z [-]                                                    */
    int vad;        /* 0 velocity, 1 acceleration, 2 displacement [-]                       */
    int lcid;       /* curve of the value vs. time, in the deck's units [-]                 */
    double sf;      /* scale on the curve's value [-]                                       */
    fe_kw_loc loc;
} fe_kw_wmotion;

/* what an initial velocity or constraint applies to */
typedef enum { FE_KW_ON_NODE, FE_KW_ON_NODESET, FE_KW_ON_PART, FE_KW_ON_PARTSET } fe_kw_target;

typedef struct {
    fe_kw_target on;
    int id;         /* node, set or part ID; node set 0 = every node                       */
    double v[3];    /* translational velocity [m/s]                                        */
    double vr[3];   /* rotational velocity [rad/s] (*INITIAL_VELOCITY only)                 */
    fe_kw_loc loc;
} fe_kw_initvel;

typedef struct {
    fe_kw_target on; /* FE_KW_ON_NODE | FE_KW_ON_NODESET                                    */
    int id;
    unsigned dof;    /* FE_DOF_* mask                                                      */
    fe_kw_loc loc;
} fe_kw_spc;

/* ---- contacts, segment sets, node velocities, prescribed motions, loads, termination
 * (fe_kw_cards_contact.c, built by fe_kw_build_contact.c; docs/keyword.md) ---- */

/* the *CONTACT_* types read: AUTOMATIC_SINGLE_SURFACE, AUTOMATIC_GENERAL (self contact);
 * (AUTOMATIC_)SURFACE_TO_SURFACE (symmetric); (AUTOMATIC_)NODES_TO_SURFACE (one way) */
typedef enum { FE_KW_CT_SINGLE, FE_KW_CT_GENERAL, FE_KW_CT_S2S, FE_KW_CT_N2S } fe_kw_ctype;

typedef struct {
    int id;                      /* CID of the _ID/_TITLE card, else 0                        */
    char title[FE_KW_TITLE_MAX]; /* its HEADING                                               */
    fe_kw_ctype type;
    int automatic;               /* an _AUTOMATIC_ keyword [-]                                */
    int ssid, msid, sstyp, mstyp;/* card 1: sides and their ID types (0 segment set, 1 shell
                                    element set, 2 part set, 3 part, 4 node set, 5 all, 6 all
                                    but a part set, 7 branch) [-]                              */
    double fs, fd, dc;           /* card 2: static, dynamic friction [-], decay [s/m]         */
    double vc, vdc;              /* viscous friction limit [Pa], normal damping [% critical]  */
    double bt, dt;               /* birth, death time [s] (dt 0: never)                       */
    double sfs, sfm;             /* card 3: penalty scale of the slave, master side [-]       */
    double sst, mst;             /* contact thickness override of each side (0: none) [m]     */
    double sfst, sfmt, fsf;      /* scale on the shell thickness of each side, on FS/FD [-]   */
    int soft;                    /* optional card A: SOFT (0 penalty) [-]                      */
    double sldthk, sldstf;       /* optional card B: solid contact thickness [m], stiffness  */
    fe_kw_loc loc;               /* card 1                                                    */
} fe_kw_contact;

/* *SET_SEGMENT: quadrilaterals (a triangle repeats N3) by node ID */
typedef struct {
    int id;
    int n;
    int *node;                   /* (n x 4) node IDs                                          */
    fe_kw_loc loc;
} fe_kw_segset;

/* *INITIAL_VELOCITY_NODE */
typedef struct {
    int nid;
    double v[3], vr[3];          /* [m/s], [rad/s]                                            */
    fe_kw_loc loc;
} fe_kw_nodevel;

/* *BOUNDARY_PRESCRIBED_MOTION_NODE | _SET | _RIGID: ID DOF VAD LCID SF VID DEATH BIRTH */
typedef struct {
    fe_kw_target on;             /* FE_KW_ON_NODE, _NODESET or _PART (_RIGID)                 */
    int id, dof, vad, lcid;      /* [-]                                                       */
    double sf;                   /* scale on the curve [-]                                    */
    double death, birth;         /* [s] (death 0: never)                                      */
    fe_kw_loc loc;
} fe_kw_pmotion;

/* *LOAD_NODE_POINT, *LOAD_NODE_SET (NID|NSID DOF LCID SF), *LOAD_SEGMENT (LCID SF AT N1..N4) */
typedef struct {
    int segment;                 /* 0: a node, 1: a pressure on a segment, 2: a node set [-]  */
    int nid, dof, lcid;          /* node or set, direction 1 x 2 y 3 z [-]; the curve [-]     */
    double sf, at;               /* scale [-], arrival time [s]                               */
    int node[4];                 /* segment nodes [-]                                         */
    fe_kw_loc loc;
} fe_kw_load;

/* ---- joints and constraints (fe_kw_cards_joint.c; kernel: fe_joint.h) ---- */

/* *CONSTRAINED_JOINT_SPHERICAL|REVOLUTE|CYLINDRICAL|TRANSLATIONAL(_ID): N1..N6 RPS DAMP */
typedef struct {
    int id;                      /* JID of the _ID card, else its number among the joints   */
    char title[FE_KW_TITLE_MAX]; /* the _ID card's heading                                  */
    int type;                    /* fe_joint_type: 0 spherical 1 revolute 2 cyl. 3 transl.   */
    int node[6];                 /* N1..N6 (0: blank) [-]                                   */
    double rps, damp;            /* relative penalty stiffness, damping scale (default 1)   */
    fe_kw_loc loc;               /* the node card                                           */
} fe_kw_joint;

/* *CONSTRAINED_NODAL_RIGID_BODY (PID CID NSID ...), *CONSTRAINED_EXTRA_NODES_NODE|SET
 * (PID NID|NSID) */
typedef struct {
    int kind;                    /* 0 nodal rigid body (id: its node set), 1 extra node (id: a
                                    node), 2 extra nodes (id: a node set) [-]                */
    int pid;                     /* the body's ID / the rigid part's ID [-]                  */
    int id;
    fe_kw_loc loc;
} fe_kw_nrb;

/* *CONSTRAINED_JOINT_STIFFNESS_GENERALIZED (phi, theta, psi) | _TRANSLATIONAL (x, y, z) */
typedef struct {
    int translational;           /* 0 generalized (rotations), 1 translational [-]           */
    int jsid, pida, pidb, cida, cidb, jid;
    int lc[3], dlc[3];           /* stiffness and damping curves per axis (0: none) [-]       */
    double es[3], ff[3];         /* stop stiffness, friction limit per axis, as written      */
    double neg[3], pos[3];       /* stops per axis [rad | m] (0: none)                       */
    fe_kw_loc loc;
} fe_kw_jstiff;

/* a keyword outside the subset: one entry per distinct name, in the order first met */
typedef struct {
    char name[FE_KW_NAME_MAX + 16]; /* as written, without the "*" */
    fe_kw_loc loc;                  /* its first occurrence                               */
    int count;                      /* occurrences [-]                                    */
} fe_kw_unknown;

typedef struct fe_kw_deck {
    char title[FE_KW_TITLE_MAX];
    int nfile;
    char **file;          /* files read: the main deck first, then *INCLUDEs              */
    int nnode, cap_node;
    int *node_id;         /* node IDs, ascending after reading (nnode)                   */
    double *node_x;       /* coordinates [m] (nnode x 3)                                 */
    fe_kw_elems elem[FE_KW_NETYPE];
    int npart, cap_part;       fe_kw_part *part;
    int nsection, cap_section; fe_kw_section *section;
    int nmat, cap_mat;         fe_kw_mat *mat;
    int ncurve, cap_curve;     fe_kw_curve *curve;
    int nset, cap_set;         fe_kw_set *set;
    int nwall, cap_wall;       fe_kw_wall *wall;
    int niv, cap_iv;           fe_kw_initvel *iv;
    int nspc, cap_spc;         fe_kw_spc *spc;
    int nunknown, cap_unknown; fe_kw_unknown *unknown;
    double unit[3];       /* SI value of the deck's length [m], time [s], mass [kg] units  */
    int nwmotion, cap_wmotion; fe_kw_wmotion *wmotion; /* rigid wall motions              */
    int nhg, cap_hg;           fe_kw_hourglass *hg;       /* *HOURGLASS                    */
    fe_kw_control ctl;    /* *CONTROL_HOURGLASS, *CONTROL_TIMESTEP                          */
    int beams_as_trusses; /* set by the caller: build *SECTION_BEAM ELFORM 1 and 2 beams as
                             trusses of their area (axial force only) instead of refusing */
    int ncontact, cap_contact; fe_kw_contact *contact; /* *CONTACT_* (fe_kw_cards_contact.c) */
    int nsegset, cap_segset;   fe_kw_segset *segset;   /* *SET_SEGMENT                         */
    int nnodevel, cap_nodevel; fe_kw_nodevel *nodevel; /* *INITIAL_VELOCITY_NODE               */
    int npmotion, cap_pmotion; fe_kw_pmotion *pmotion; /* *BOUNDARY_PRESCRIBED_MOTION_*        */
    int nload, cap_load;       fe_kw_load *load;       /* *LOAD_NODE_POINT, *LOAD_SEGMENT      */
    double end_time;      /* *CONTROL_TERMINATION ENDTIM [s] (0: not given)                    */
    double slsfac;        /* *CONTROL_CONTACT SLSFAC: penalty scale (0: not given, 0.1) [-]   */
    double rwpnal;        /* RWPNAL: > 0 asks penalty rigid walls [-]                          */
    int shlthk;           /* SHLTHK: shell thickness in non-automatic contacts (0: not) [-]    */
    fe_kw_loc control_contact; /* its card (line 0: none)                                       */
    /* joints and constraints (fe_kw_cards_joint.c) */
    int njoint, cap_joint;     fe_kw_joint *joint;     /* *CONSTRAINED_JOINT_*                 */
    int nnrb, cap_nrb;         fe_kw_nrb *nrb;         /* nodal rigid bodies, extra nodes       */
    int njstiff, cap_jstiff;   fe_kw_jstiff *jstiff;   /* *CONSTRAINED_JOINT_STIFFNESS_*       */
} fe_kw_deck;

typedef struct {
    const char *units; /* "LENGTH-TIME-MASS": m|cm|mm - s|ms|us - kg|g|t; NULL = "m-s-kg" */
    int strict;        /* unknown keywords are an error (MCS_ERR_FORMAT) instead of a warning */
    int quiet;         /* do not log the unknown-keyword warning                             */
} fe_kw_opts;

fe_kw_opts fe_kw_opts_default(void);

/* "mm-ms-kg" -> SI values of the length, time and mass units */
mcs_status fe_kw_units(const char *units, double unit[3], mcs_error *err);

/* read a deck from a file (includes relative to the including file) or from memory
 * (name is used in messages; includes relative to the working directory) */
mcs_status fe_kw_read(const char *path, const fe_kw_opts *opts, fe_kw_deck **out,
                      mcs_error *err);
mcs_status fe_kw_read_mem(const char *name, const char *text, size_t len, const fe_kw_opts *opts,
                          fe_kw_deck **out, mcs_error *err);
void fe_kw_deck_destroy(fe_kw_deck **p);

/* the unknown keywords whose names start with one of the '|'-separated prefixes (e.g.
 * "ELEMENT_|PART"), as " (skipped as not supported: *ELEMENT_SPH at f.k:12, ...)" for an error
 * that their absence explains; "" when none. Returns buf. */
const char *fe_kw_skipped(const fe_kw_deck *d, const char *prefixes, char *buf, size_t n);

/* lookups by ID (NULL / -1 when absent) */
int fe_kw_node_index(const fe_kw_deck *d, int nid);
const fe_kw_part *fe_kw_find_part(const fe_kw_deck *d, int pid);
const fe_kw_section *fe_kw_find_section(const fe_kw_deck *d, int secid);
const fe_kw_mat *fe_kw_find_mat(const fe_kw_deck *d, int mid);
const fe_kw_curve *fe_kw_find_curve(const fe_kw_deck *d, int lcid);
const fe_kw_set *fe_kw_find_set(const fe_kw_deck *d, int sid, int is_part);
const fe_kw_hourglass *fe_kw_find_hourglass(const fe_kw_deck *d, int hgid);

/* the model options a deck sets (*CONTROL_TIMESTEP: TSSFAC -> dt_scale, DT2MS < 0 -> mass
 * scaling to TSSFAC |DT2MS|); what the kernel does not build is refused with its line */
mcs_status fe_kw_deck_opts(const fe_kw_deck *dk, fe_opts *o, mcs_error *err);

/* the section and material of a deck part as kernel descriptors (into d->section and
 * d->material; name and mesh untouched) */
mcs_status fe_kw_part_props(const fe_kw_deck *dk, int pid, fe_part_desc *d, mcs_error *err);

/* add deck part pid to a builder as a part described by base (name, section, material,
 * initial velocity; its mesh must be FE_MESH_NONE). With props_from_deck the section and
 * material come from the deck instead. node_map (dk->nnode ints, all -1 at first, may be NULL)
 * maps deck nodes to builder nodes and is updated, so that parts added from one deck with the
 * same map share their nodes. Nodes are added in ascending ID order. */
mcs_status fe_kw_add_part(fe_builder *b, const fe_kw_deck *dk, int pid, const fe_part_desc *base,
                          int props_from_deck, int *node_map, int *index, mcs_error *err);

/* everything: each part (named by its title, else "part_<ID>") with its deck section and
 * material, *ELEMENT_DISCRETE as springs/dampers (*SECTION_DISCRETE DRO 0 with *MAT_S01 or
 * *MAT_S02, force scaled by S), *BOUNDARY_SPC, *INITIAL_VELOCITY(_GENERATION) (on whole
 * parts), *RIGIDWALL_PLANAR */
mcs_status fe_kw_add_deck(fe_builder *b, const fe_kw_deck *dk, mcs_error *err);

/* a deck of a built model: node i gets ID i+1, part i ID i+1 with its section and material,
 * elements numbered per type from 1; x (nnode x 3, NULL: the initial coordinates) [m] */
mcs_status fe_kw_from_model(const fe_model *m, const double *x, const char *title,
                            fe_kw_deck **out, mcs_error *err);

/* an empty deck to fill by hand (SI units) */
mcs_status fe_kw_deck_create(fe_kw_deck **out, mcs_error *err);
/* add a node / element / part to a deck made by hand (IDs must be unique; nodes ascending) */
mcs_status fe_kw_deck_add_node(fe_kw_deck *d, int id, const double x[3], mcs_error *err);
mcs_status fe_kw_deck_add_elem(fe_kw_deck *d, fe_kw_etype t, int id, int pid, const int *nodes,
                               mcs_error *err);
mcs_status fe_kw_deck_add_part(fe_kw_deck *d, const fe_kw_part *p, mcs_error *err);

/* card formats a deck is written in: standard fixed columns, I10 (`*KEYWORD I10=Y`),
 * long (`*KEYWORD LONG=Y`, every field 20 wide) */
typedef enum { FE_KW_FIXED, FE_KW_FIXED_I10, FE_KW_FIXED_LONG } fe_kw_format;

/* write *KEYWORD, *TITLE, *PART, *SECTION_*, *MAT_*, *DEFINE_CURVE, *SET_*, *NODE,
 * *ELEMENT_*, *BOUNDARY_SPC_*, *INITIAL_VELOCITY*, *RIGIDWALL_PLANAR, *END; values converted
 * from SI to the deck's units (dk->unit). Reals take the shortest form that reads back to the
 * same double when it fits the field, else as many digits as fit. The file is written to a
 * temporary and renamed (never partial). */
mcs_status fe_kw_write(const fe_kw_deck *dk, const char *path, fe_kw_format fmt, mcs_error *err);
mcs_status fe_kw_write_stream(const fe_kw_deck *dk, FILE *f, fe_kw_format fmt, mcs_error *err);

#endif
