/* mcs_schema.h: the scenario schema, as data (tables in core/mcs_schema.c, walker in
 * core/mcs_scn_check.c). To add a key, add a row to the table of its map; to add a map, add a
 * key table and an mcs_smap. Internal to core/. */
#ifndef MCS_SCHEMA_H
#define MCS_SCHEMA_H

#include "core/mcs_scn_internal.h"
#include "core/mcs_units.h"

typedef enum {
    MCS_SK_NUM,   /* quantity of .dim: a number (SI) or "value unit" */
    MCS_SK_INT,   /* integer number, no unit */
    MCS_SK_VEC,   /* list of .nmin...nmax quantities of .dim (nmax 0: no limit) */
    MCS_SK_INTS,  /* list of .nmin...nmax integers */
    MCS_SK_STR,   /* any non-null scalar, kept as a string */
    MCS_SK_BOOL,  /* true or false */
    MCS_SK_ENUM,  /* one of .choices ("a|b|c") */
    MCS_SK_REF,   /* name of an entity of kind .ref */
    MCS_SK_REFS,  /* list of names of entities of kind .ref */
    MCS_SK_CURVE, /* [[x, y], ...]: x of .dim strictly increasing, y of .dim_y, >= .nmin points */
    MCS_SK_MAP,   /* mapping with keys .sub; with .ref: or the name of one (a reference) */
    MCS_SK_LIST,  /* list of mappings .sub */
    MCS_SK_NAMED, /* mapping {<name>: mapping .sub} */
    MCS_SK_ANY,   /* free-form: any YAML (no NaN/Inf) */
    MCS_SK_DISC, /* the discriminator of a map with variants (checked when the variant is chosen) */
} mcs_sk_type;

enum {
    MCS_SK_REQ = 1 << 0,      /* must be given */
    MCS_SK_NULLOK = 1 << 1,   /* null is accepted (means "not given") */
    MCS_SK_GT = 1 << 2,       /* value > lo */
    MCS_SK_GE = 1 << 3,       /* value >= lo */
    MCS_SK_LT = 1 << 4,       /* value < hi */
    MCS_SK_LE = 1 << 5,       /* value <= hi */
    MCS_SK_NONZERO = 1 << 6,  /* vector: not all zero (directions) */
    MCS_SK_UNIQUE = 1 << 7,   /* in a LIST item: value unique across the list (names) */
    MCS_SK_NONEMPTY = 1 << 8, /* string or list: not empty */
};

/* entities a name may refer to */
typedef enum {
    MCS_REF_NONE,
    MCS_REF_BODY,           /* bodies[].name */
    MCS_REF_BODY_OR_GROUND, /* bodies[].name or "ground" */
    MCS_REF_CHAR,           /* characteristics.<name> */
    MCS_REF_FE_PART,        /* fe.parts[].name */
    MCS_REF_BODY_LAW,       /* fe.body_characteristics.<name> */
} mcs_sref;

typedef struct mcs_smap mcs_smap;
typedef struct mcs_skey mcs_skey;
typedef struct scn_walk scn_walk;

/* extra check of a whole map after its keys passed (cross-key rules); MCS_OK or an error */
typedef mcs_status (*mcs_scheck_fn)(scn_walk *w, mcs_node *map);

struct mcs_skey {
    const char *name;
    mcs_sk_type type;
    unsigned flags;      /* MCS_SK_* */
    mcs_dim dim, dim_y;  /* NUM, VEC: dim; CURVE: x and y */
    double lo, hi;       /* range (with GT/GE/LT/LE), per component for VEC, on x for CURVE */
    int nmin, nmax;      /* VEC/INTS/REFS: length range; CURVE: nmin points */
    const char *choices; /* ENUM: "a|b|c" */
    const mcs_smap *sub; /* MAP, LIST, NAMED */
    mcs_sref ref;        /* REF, REFS */
    const char *doc;     /* what it is, for messages and documentation */
};

typedef struct {
    const char *value;   /* discriminator value */
    const mcs_smap *map; /* keys of this variant (in addition to the base keys) */
} mcs_svariant;

struct mcs_smap {
    const char *what;             /* "body", "mesh" (messages) */
    const mcs_skey *keys;         /* terminated by a row with name NULL */
    const char *disc;             /* key choosing a variant (NULL: none) */
    const mcs_svariant *variants; /* terminated by value NULL */
    const char *disc_default;     /* variant when disc is absent (NULL: disc required) */
    int open;                     /* unknown keys accepted (free-form map) */
    mcs_scheck_fn check;          /* extra check, may be NULL */
};

/* cross-key rules (core/mcs_scn_rules.c) */
mcs_status mcs_rule_root(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_simulation(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_range(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_fixed_joint(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_body(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_pair(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_joint(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_sensor(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_plate(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_plastic(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_impact(scn_walk *w, mcs_node *map); /* core/mcs_scn_rule_impact.c */
mcs_status mcs_rule_facet(scn_walk *w, mcs_node *map);  /* core/mcs_scn_rule_facet.c */
mcs_status mcs_rule_fe_part(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_fe(scn_walk *w, mcs_node *map);
mcs_status mcs_rule_surface_mesh(scn_walk *w, mcs_node *map); /* core/mcs_scn_rule_pad.c */
mcs_status mcs_rule_mesh_file(scn_walk *w, mcs_node *map);    /* core/mcs_scn_rule_mesh.c */

/* the whole scenario */
extern const mcs_smap mcs_schema_root;

/* the walker's state (core/mcs_scn_check.c, core/mcs_scn_walk.c) */
struct scn_walk {
    mcs_scenario *scn;
    mcs_error *err;
    const mcs_node *root;
    char path[1024]; /* dotted path of the node being checked */
    size_t plen;
};

size_t scn_walk_push_key(scn_walk *w, const char *key);
size_t scn_walk_push_index(scn_walk *w, int i);
void scn_walk_pop(scn_walk *w, size_t old);
mcs_status scn_walk_set_path(scn_walk *w, mcs_node *n);

/* scalar checks (mcs_scn_check.c); v is converted in place */
mcs_status scn_check_scalar(scn_walk *w, mcs_node *v, const mcs_skey *k);
mcs_status scn_quantity(scn_walk *w, mcs_node *v, mcs_dim d);
mcs_status scn_range_check(scn_walk *w, const mcs_node *v, const mcs_skey *k, double x, mcs_dim d);
const char *scn_got_str(const mcs_node *v, char *buf, size_t n);
/* "bodies" for "body", "contacts" for "contact" (names of schema maps) */
const char *scn_plural(const char *what, char *buf, size_t n);
/* " (did you mean 'x'?)" or "" */
void scn_suggest(char *buf, size_t n, const char *word, const char *const *cands, int nc);

/* walker services for check functions */
mcs_status scn_walk_fail(scn_walk *w, const mcs_node *at, const char *key, mcs_status st,
                         const char *fmt, ...) __attribute__((format(printf, 5, 6)));

#endif
