/* mcs_scn_internal.h: the scenario tree inside core/ (not for stages: use mcs_scenario.h) */
#ifndef MCS_SCN_INTERNAL_H
#define MCS_SCN_INTERNAL_H

#include "core/mcs_scenario.h"

#include <stddef.h>

struct mcs_node {
    mcs_kind kind;
    const char *file; /* source file as named by the user or the include */
    int line, col;    /* 1-based position in file */
    const char *text; /* scalar as written (NULL for map/seq) */
    const char *path; /* dotted path, set by validation */
    double num;       /* NUM: value in SI; BOOL: 0 or 1 */
    int quoted;       /* scalar was quoted (always a string before validation) */
    int n, cap;       /* entries of a map or sequence */
    mcs_node **keys;  /* MAP: key scalars [n] */
    mcs_node **items; /* MAP: values [n]; SEQ: items [n] */
};

/* bump allocator: nodes and strings of one scenario live until mcs_scenario_destroy */
typedef struct scn_block scn_block;
typedef struct {
    scn_block *head;
    size_t used_total; /* bytes handed out [B] */
} scn_arena;

struct mcs_scenario {
    scn_arena arena;
    mcs_node *root;
    char *text; /* concatenated sources, NUL-terminated (malloc) */
    size_t text_len, text_cap;
    int nfiles; /* files read */
};

void *scn_alloc(scn_arena *a, size_t size); /* zeroed; NULL when out of memory */
char *scn_strndup(scn_arena *a, const char *s, size_t n);
void scn_arena_free(scn_arena *a);

mcs_node *scn_node_new(scn_arena *a, mcs_kind kind, const char *file, int line, int col);
/* append to a map (key != NULL) or sequence; MCS_ERR_NOMEM on failure */
mcs_status scn_node_push(scn_arena *a, mcs_node *parent, mcs_node *key, mcs_node *item);
/* index of key in map, -1 if absent */
int scn_map_find(const mcs_node *map, const char *key);
void scn_map_remove(mcs_node *map, int i);

/* "FILE:LINE:COL: error: [PATH: ]what" */
mcs_status scn_fail(mcs_error *err, mcs_status st, const mcs_node *at, const char *path,
                    const char *fmt, ...) __attribute__((format(printf, 5, 6)));

/* read and check one file: size, NUL bytes, UTF-8; appended to scn->text */
mcs_status scn_read_file(mcs_scenario *scn, const char *path, const mcs_node *from, char **text,
                         size_t *len, mcs_error *err);
mcs_status scn_check_bytes(const char *name, const char *text, size_t len, mcs_error *err);
void scn_add_source(mcs_scenario *scn, const char *name, const char *text, size_t len);

/* parse one YAML document into a tree (root is a map) */
mcs_status scn_parse(mcs_scenario *scn, const char *file, const char *text, size_t len,
                     mcs_node **root, mcs_error *err);

/* resolve include: of a parsed root (file = its path); returns the merged tree */
mcs_status scn_resolve(mcs_scenario *scn, const char *file, mcs_node *root, mcs_node **out,
                       mcs_error *err);

/* merged copy of two entries by the include rule (mcs_scenario.h) but with entity lists
 * concatenated (base's first, no override by name: mcs_scenario_merged), else over wins;
 * shares the leaves; NULL out of memory */
mcs_node *scn_merge(scn_arena *a, mcs_node *base, mcs_node *over);

/* deep copies: one node (its subtree) into arena a, a whole scenario; NULL out of memory */
mcs_node *scn_copy_node(scn_arena *a, const mcs_node *n);
mcs_scenario *scn_copy(const mcs_scenario *scn);

/* validate against the schema, convert quantities to SI, set paths */
mcs_status scn_validate(mcs_scenario *scn, mcs_error *err);

/* Damerau-Levenshtein distance (optimal string alignment), capped at 99 */
int scn_edit_distance(const char *a, const char *b);

#endif
