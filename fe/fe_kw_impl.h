/* fe_kw_impl: the keyword reader's insides, shared by fe_kw_field.c (cards and fields),
 * fe_kw_read.c (files, keyword lines, dispatch), fe_kw_cards.c (one handler per keyword) and
 * fe_kw_deck.c (the deck's memory and checks). */
#ifndef FE_KW_IMPL_H
#define FE_KW_IMPL_H

#include "fe/fe_keyword.h"

/* card formats */
enum { KW_FMT_STD, KW_FMT_I10, KW_FMT_LONG };

/* one data card: a NUL-terminated line (no newline) and where it was read */
typedef struct {
    const char *s;
    int len;
    int line;
    int file;
} kw_card;

#define KW_INCLUDE_DEPTH 8 /* *INCLUDE nesting */

/* a node while reading (sorted and checked at the end) */
typedef struct {
    int id;
    double x[3];
    fe_kw_loc loc;
} kw_node;

typedef struct {
    fe_kw_deck *d;
    const fe_kw_opts *o;
    mcs_error *err;
    int depth;             /* *INCLUDE nesting                                    */
    int gfmt;              /* format from *KEYWORD (I10=Y, LONG=Y)                 */
    int fmt;               /* format of the keyword being read                    */
    char kw[FE_KW_NAME_MAX]; /* its name as written, upper case, without '*'       */
    int has_title;         /* the keyword ended in _TITLE                          */
    int has_id;            /* the keyword ended in _ID                             */
    fe_kw_loc kwloc;       /* its line                                            */
    int nnode, cap_node;
    kw_node *node;         /* nodes read so far                                   */
    int ended;             /* *END seen in the current file                       */
    /* reader mechanics (fe_kw_read.c, fe_kw_param.c) */
    int nopen;             /* files being read, outermost first                   */
    int open[KW_INCLUDE_DEPTH + 1]; /* their indices in d->file                    */
    int npath, cap_path;
    char **path;           /* *INCLUDE_PATH(_RELATIVE) folders, in the order given  */
    struct kw_params *par; /* *PARAMETER values (fe_kw_param.c)                    */
} kw_ctx;

/* layouts: standard widths of a card's fields */
typedef struct {
    int n;
    int w[10];
} kw_layout;

extern const kw_layout KW_L10;      /* 8 fields of 10                           */
extern const kw_layout KW_L_NODE;   /* 8, 16, 16, 16, 8, 8                      */
extern const kw_layout KW_L_ELEM;   /* 10 fields of 8                           */
extern const kw_layout KW_L_DISCR;  /* 8, 8, 8, 8, 8, 16, 8, 16                 */
extern const kw_layout KW_L_CURVE;  /* 2 fields of 20                           */

/* ---- fields (fe_kw_field.c) ---- */

/* an integer field i (0-based); blank gives dflt. name is the manual's field name. */
mcs_status kw_int(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i, const char *name,
                  int dflt, int *out);
/* a real field i; blank gives dflt. Fortran forms accepted: 1.5e3, 1.5E+3, 1.5d3, 1.5-3. */
mcs_status kw_real(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i, const char *name,
                   double dflt, double *out);
/* a text field over columns [col0, col0+w) trimmed into buf (whole card when w <= 0) */
void kw_text(const kw_card *cd, int col0, int w, char *buf, size_t n);
/* field i's text, trimmed, into buf; returns its 1-based column */
int kw_field_text(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i, char *buf, size_t n);
/* true when the field is blank */
int kw_blank(kw_ctx *c, const kw_card *cd, const kw_layout *l, int i);
/* an error at a card: "FILE:LINE:COL: error: *KEYWORD: ..." (col 0: no column) */
mcs_status kw_fail(kw_ctx *c, int file, int line, int col, mcs_status st, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
/* the parser of one real number from text; 0 on success */
int kw_parse_real(const char *s, int n, double *out);
int kw_parse_int(const char *s, int n, int *out);

/* ---- the deck (fe_kw_deck.c) ---- */

int kw_grow(void **p, int *cap, int need, size_t sz);
mcs_status kw_add_node(kw_ctx *c, int id, const double x[3], fe_kw_loc loc);
mcs_status kw_add_elem(kw_ctx *c, fe_kw_etype t, int id, int pid, const int *nodes,
                       const double *dval, fe_kw_loc loc);
int kw_add_file(fe_kw_deck *d, const char *path); /* index, -1 out of memory */
/* *ELEMENT_SOLID_TET4TOTET10 elements (tet10 with N5..N10 = 0) get their mid-edge nodes,
 * shared along edges, numbered from the largest node ID + 1 (fe_kw_tet10.c); c->node must be
 * sorted by ID, and stays so */
mcs_status kw_tet4_to_tet10(kw_ctx *c);
/* sort nodes, check unique IDs and that every element's nodes exist */
mcs_status kw_finish(kw_ctx *c);
/* a new entry at the end of a deck list (zeroed); NULL out of memory */
void *kw_push(void **arr, int *n, int *cap, size_t sz);

/* ---- parameters (fe_kw_param.c, fe_kw_expr.c) ---- */

/* *PARAMETER(_EXPRESSION)(_LOCAL|_GLOBAL), *PARAMETER_DUPLICATION: 1 = handled (*st set) */
int kw_param_block(kw_ctx *c, const kw_card *cards, int ncard, mcs_status *st);
/* field text p[0..n) is a reference &NAME or -&NAME */
int kw_param_is_ref(const char *p, int n);
/* the value of a reference (as_int: must be integral), errors at the field's column */
mcs_status kw_param_num(kw_ctx *c, const kw_card *cd, const char *p, int n, const char *field,
                        int as_int, double *out);
/* a file ended: its _LOCAL parameters go out of scope */
mcs_status kw_param_file_done(kw_ctx *c, int file);
void kw_param_free(kw_ctx *c);
/* evaluate an expression (fe_kw_expr.c); names through look (0: found); 0 on success, else
 * -1 with the 0-based offset of the fault in *errpos and a message */
int kw_expr_eval(const char *s, int (*look)(void *user, const char *name, double *v), void *user,
                 double *out, int *errpos, char *msg, size_t nmsg);

/* ---- handlers (fe_kw_cards.c): cards of one keyword; 1 = handled, 0 = unknown keyword ---- */
int kw_dispatch(kw_ctx *c, const kw_card *cards, int ncard, mcs_status *st);

/* ---- element, section, part and control handlers (fe_kw_cards_elem.c) ---- */
mcs_status kw_h_shell_opt(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_tshell(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_section_solid(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_section_tshell(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_section_beam(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_part(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_hourglass(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_control_hourglass(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_control_timestep(kw_ctx *c, const kw_card *cd, int n);
/* builder side (fe_kw_build_elem.c): the deck part's hourglass form, its beam section, its
 * *PART_INERTIA (and the refusal of an EOSID), the thickness of shell element i of the deck
 * (0: the section's T1 applies) */
mcs_status kw_part_hourglass(const fe_kw_deck *dk, const fe_kw_part *p, fe_section_desc *s,
                             mcs_error *err);
mcs_status kw_beam_section(const fe_kw_deck *dk, const fe_kw_section *k, fe_section_desc *s,
                           mcs_error *err);
mcs_status kw_part_inertia(const fe_kw_deck *dk, const fe_kw_part *p, fe_part_desc *d,
                           mcs_error *err);
double kw_shell_thickness(const fe_kw_deck *dk, const fe_kw_section *k, int i);
/* ---- material handlers (fe_kw_cards_mat.c): *MAT_PLASTIC_KINEMATIC, *MAT_NULL, *MAT_RIGID,
 * *MAT_MOONEY-RIVLIN_RUBBER, *MAT_LOW_DENSITY_FOAM; kw_mat_desc: their kernel descriptors
 * (1 when k is one of them, *st the status; 0 otherwise) ---- */
mcs_status kw_h_mat_pk(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_mat_null(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_mat_rigid(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_mat_mr(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_mat_ldf(kw_ctx *c, const kw_card *cd, int n);
int kw_mat_desc(const fe_kw_deck *dk, const fe_kw_mat *k, fe_material_desc *m, mcs_error *err,
                mcs_status *st);

/* ---- handlers of fe_kw_cards_contact.c (contacts, sets, node velocities, prescribed
 * motions, loads, termination) and the deck memory they own ---- */
mcs_status kw_h_contact_single(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_contact_general(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_contact_s2s(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_contact_auto_s2s(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_contact_n2s(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_contact_auto_n2s(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_contact_mpp(kw_ctx *c, const kw_card *cd, int n); /* _MPP, _ID_MPP */
mcs_status kw_h_control_contact(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_set_node_gen(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_set_part_gen(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_set_segment(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_initvel_node(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_pmotion_node(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_pmotion_set(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_pmotion_rigid(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_load_node_point(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_load_node_set(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_load_segment(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_control_termination(kw_ctx *c, const kw_card *cd, int n);
void kw_contact_free(fe_kw_deck *d);
/* the deck's contacts, node velocities, prescribed motions and loads into a builder once its
 * parts are in (fe_kw_build_contact.c): names[k] is deck part k's builder name, map the deck
 * node -> builder node map (-1: not in the model) */
mcs_status kw_add_deck_more(fe_builder *b, const fe_kw_deck *dk, const char (*names)[FE_NAME_MAX],
                            const int *map, mcs_error *err);

/* ---- joints and constraints (fe_kw_cards_joint.c) ---- */
mcs_status kw_h_joint_spherical(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_joint_revolute(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_joint_cylindrical(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_joint_translational(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_nodal_rigid_body(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_extra_nodes_node(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_extra_nodes_set(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_jstiff_generalized(kw_ctx *c, const kw_card *cd, int n);
mcs_status kw_h_jstiff_translational(kw_ctx *c, const kw_card *cd, int n);
void kw_joint_free(fe_kw_deck *d);
/* before the constraints: the deck nodes the joints and extra nodes name that no element
 * holds join the builder (map updated); after everything: nodal rigid bodies, extra nodes,
 * joints and their stiffness (fe_kw_build_joint.c) */
mcs_status kw_add_deck_joint_nodes(fe_builder *b, const fe_kw_deck *dk, int *map,
                                   mcs_error *err);
mcs_status kw_add_deck_joints(fe_builder *b, const fe_kw_deck *dk,
                              const char (*names)[FE_NAME_MAX], const int *map, mcs_error *err);
/* the joints, nodal rigid bodies and extra nodes of a model into its deck (node i has ID i+1,
 * part i ID i+1; new nodes, sets and curves numbered after the deck's) */
mcs_status kw_joints_from_model(const fe_model *m, const double *x, fe_kw_deck *d,
                                mcs_error *err);

/* ---- unit conversions (SI value of the deck's unit of each quantity) ---- */
static inline double kw_u_len(const fe_kw_deck *d) { return d->unit[0]; }
static inline double kw_u_vel(const fe_kw_deck *d) { return d->unit[0] / d->unit[1]; }
static inline double kw_u_rate(const fe_kw_deck *d) { return 1.0 / d->unit[1]; }
static inline double kw_u_dens(const fe_kw_deck *d)
{
    return d->unit[2] / (d->unit[0] * d->unit[0] * d->unit[0]);
}
static inline double kw_u_stress(const fe_kw_deck *d)
{
    return d->unit[2] / (d->unit[0] * d->unit[1] * d->unit[1]);
}


/* ---- helpers shared by the handler and build files (fe_kw_util.c) ---- */

/* return the status of x when it is an error */
#define KW_TRY(x)                                                                                  \
    do {                                                                                           \
        mcs_status s_ = (x);                                                                       \
        if (s_) return s_;                                                                         \
    } while (0)

/* where a card was read */
static inline fe_kw_loc kw_loc_of(const kw_card *cd) { return (fe_kw_loc){cd->file, cd->line}; }
/* k more cards must follow card i of the n a keyword has */
mcs_status kw_need(kw_ctx *c, const kw_card *cd, int n, int i, int k);
/* true when a card holds only blanks */
int kw_blank_card(const kw_card *cd);
/* a warning at a card: "FILE:LINE: warning: *KEYWORD: ..." (nothing when the options are quiet) */
void kw_warn(kw_ctx *c, const kw_card *cd, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* out of memory while reading */
mcs_status kw_nomem(kw_ctx *c);
/* an error at a deck place while building: "FILE:LINE: error: ..." */
mcs_status kw_at(const fe_kw_deck *dk, fe_kw_loc l, mcs_error *err, mcs_status st,
                 const char *fmt, ...) __attribute__((format(printf, 5, 6)));

#endif
