/* mcs_scenario: the scenario reader. Loads a YAML scenario (libyaml), resolves its includes,
 * validates it against the schema (core/mcs_schema.c) and converts every quantity to SI.
 * Stages then read the tree with the accessors below: a quantity node holds its SI value.
 *
 * Input rules
 * - One YAML document per file, UTF-8, no NUL bytes, at most MCS_SCN_MAX_BYTES, nesting at
 *   most MCS_SCN_MAX_DEPTH levels. Aliases (*name) are refused: use include: or a named
 *   characteristic instead. Duplicate keys in one mapping are refused.
 * - Plain scalars resolve as YAML 1.2 core: null/~/empty -> null, true/false -> bool, decimal
 *   numbers -> number; quoted scalars are strings. A quantity is a number (SI) or a string
 *   "value unit" ("48.5 km/h", "12 ms", "50 g"); see core/mcs_units.h.
 *
 * include: (top level only) a path or a list of paths, relative to the including file.
 * The included files are loaded (recursively, cycles refused with the chain in the message)
 * and merged in order, then the including file is merged on top:
 *   - maps merge key by key, recursively;
 *   - lists of entities (sequences whose items are all mappings: bodies, joints, contacts,
 *     fe.parts, ...) merge by name: an entry whose `name:` is already in the list merges into
 *     that entry (its keys over the included entry's, by these same rules, in the entry's
 *     place); an entry with a new name or no name is appended, included items first (a
 *     model's bodies come before the scenario's own). Inside an entry merged by name, a list
 *     whose entries carry no name (vents, curves, unnamed surfaces) is a value: replaced. A
 *     `name:` that is a mapping or a list is refused there (FILE:LINE:COL of the name);
 *   - anything else given in both (a scalar, null, a vector, a curve, a kind mismatch) is a
 *     value: the including file's replaces it; between two includes, the later one wins.
 * The resolved tree has no include: key. Validation runs on the resolved tree, and every node
 * keeps the file, line and column it came from.
 *
 * Errors: status MCS_ERR_* and the message "FILE:LINE:COL: error: KEY: what is wrong" with KEY
 * the dotted path in the resolved tree (bodies[0].mass). */
#ifndef MCS_SCENARIO_H
#define MCS_SCENARIO_H

#include "core/mcs_error.h"

#include <stddef.h>
#include <stdio.h>

#define MCS_SCN_MAX_BYTES (16 * 1024 * 1024) /* per file */
#define MCS_SCN_MAX_DEPTH 64                 /* nesting of maps and sequences */
#define MCS_SCN_MAX_FILES 256                /* files read for one scenario, includes counted */
#define MCS_SCN_MAX_KEYS 10000               /* keys in one mapping */
#define MCS_SCN_MAX_NODES 4000000            /* nodes in one file */

typedef struct mcs_scenario mcs_scenario;
typedef struct mcs_node mcs_node;

typedef enum {
    MCS_NODE_NULL, /* null, ~, or an absent node (accessors given NULL) */
    MCS_NODE_BOOL,
    MCS_NODE_NUM, /* a number in SI */
    MCS_NODE_STR,
    MCS_NODE_MAP,
    MCS_NODE_SEQ,
} mcs_kind;

/* load, resolve includes, validate; on error *out is NULL and err says why */
mcs_status mcs_scenario_load(const char *path, mcs_scenario **out, mcs_error *err);

/* the same from text in memory; name is used in messages and to resolve includes */
mcs_status mcs_scenario_load_text(const char *name, const char *text, size_t len,
                                  mcs_scenario **out, mcs_error *err);

void mcs_scenario_destroy(mcs_scenario **scn);

/* a copy of scn (its own nodes: scn may be destroyed first) in which the map at the dotted path
 * `from` (e.g. "stage2.fe") is merged on top of the root's key `into` ("fe") by the include
 * rule above but with entity lists concatenated (scn's first: no override by name), `from`
 * removed, and the whole validated again (so a name given twice fails with its file and
 * line). A missing `from` gives a plain copy. (core/mcs_scn_merge.c; used by stage 2:
 * stage2_fe/s2_scenario.h) */
mcs_status mcs_scenario_merged(const mcs_scenario *scn, const char *from, const char *into,
                               mcs_scenario **out, mcs_error *err);

/* a copy of scn whose root key `into` ("fe") is the map at the dotted path `from`
 * ("stage3.fe", moved from there; none: `into` is left out), then without the root keys
 * drop[ndrop], validated again (core/mcs_scn_merge.c; used by stage 3: stage3_fe/s3_scenario.h) */
mcs_status mcs_scenario_replaced(const mcs_scenario *scn, const char *from, const char *into,
                                 const char *const *drop, int ndrop, mcs_scenario **out,
                                 mcs_error *err);

const mcs_node *mcs_scenario_root(const mcs_scenario *scn);

/* ---- keys by path (a study's factors: cli/cmd_study.c; core/mcs_scn_set.c) ----
 * A key path names one node of the resolved tree: map keys joined by '.', a sequence item by
 * [i] (0-based) or by [NAME] (the entry whose name: is NAME): "impact.motorcycle_speed",
 * "bodies[head].mass", "bodies[0].velocity[2]". */

/* the node at path in a tree; NULL when the path names none */
const mcs_node *mcs_scenario_find(const mcs_node *root, const char *path);

typedef struct {
    const char *path;      /* key path                                                    */
    const mcs_node *value; /* a scalar node (its text read by the key's schema, units and
                              all, as any scenario value), or NULL: then num               */
    double num;            /* the value in SI when value and str are NULL                 */
    const char *str;       /* a string value when value is NULL (the key's schema reads it) */
    const mcs_node *at;    /* where the setting was written: messages, and the added key   */
} mcs_scn_setting;

/* a copy of scn with the node at each set[i].path replaced (the last key of a path may be
 * absent from its map: it is added), then validated again, cross-key rules included. A path
 * that names no node: MCS_ERR_KEY at set[i].at; a value the key refuses (type, unit, range):
 * the validator's error at the value's FILE:LINE:COL */
mcs_status mcs_scenario_set(const mcs_scenario *scn, const mcs_scn_setting *set, int n,
                            mcs_scenario **out, mcs_error *err);

/* a YAML file read by the reader's rules (size, bytes, one document, plain scalars as YAML 1.2
 * core) but without include: and without the schema: strings stay as written ("9.8 m/s") and
 * nodes have no path. For files that are not scenarios (a study file) */
mcs_status mcs_yaml_load(const char *path, mcs_scenario **out, mcs_error *err);

/* the source texts that were read, in reading order, each preceded by a line
 * "# === mcrash source: PATH" (for /meta/scenario) */
const char *mcs_scenario_text(const mcs_scenario *scn);

/* the resolved scenario as JSON (includes merged, quantities in SI); MCS_ERR_IO on write error */
mcs_status mcs_scenario_write_json(const mcs_scenario *scn, FILE *f);

/* the reference of every key the reader accepts, as Markdown (docs/scenario_keys.md) */
mcs_status mcs_schema_write_markdown(FILE *f);

/* ---- nodes (a NULL node is an absent one: kind NULL, length 0, number NaN) ---- */
mcs_kind mcs_node_kind(const mcs_node *n);
const char *mcs_node_kind_str(mcs_kind k);

/* value of key in a map, NULL if absent or n is not a map */
const mcs_node *mcs_node_get(const mcs_node *map, const char *key);

/* entries of a map or sequence (0 for anything else) */
int mcs_node_len(const mcs_node *n);

/* i-th item of a sequence or i-th value of a map (in file order); NULL if out of range */
const mcs_node *mcs_node_at(const mcs_node *n, int i);

/* i-th key of a map; NULL if out of range */
const char *mcs_node_key(const mcs_node *map, int i);

/* number in SI (NaN if not a number); bool as 0/1 */
double mcs_node_num(const mcs_node *n);

/* number of key in map, or dflt when the key is absent or null */
double mcs_node_num_or(const mcs_node *map, const char *key, double dflt);

/* text of a string (NULL for other kinds) */
const char *mcs_node_str(const mcs_node *n);

/* text of a scalar as written in the file ("48.5 km/h"); NULL for maps and sequences */
const char *mcs_node_text(const mcs_node *n);

/* bool value, dflt when absent or null */
int mcs_node_bool(const mcs_node *n, int dflt);

/* where the node was written (1-based) and its dotted path in the resolved tree */
const char *mcs_node_file(const mcs_node *n);
int mcs_node_line(const mcs_node *n);
int mcs_node_col(const mcs_node *n);
const char *mcs_node_path(const mcs_node *n);

/* a sequence of exactly n numbers into v[n] (validated trees always satisfy their schema) */
mcs_status mcs_node_vec(const mcs_node *seq, double *v, int n, mcs_error *err);
mcs_status mcs_node_vec3(const mcs_node *seq, double v[3], mcs_error *err);

/* a curve [[x, y], ...]: number of points (0 if not a curve); then x[cap], y[cap] filled */
int mcs_node_curve_len(const mcs_node *curve);
mcs_status mcs_node_curve(const mcs_node *curve, double *x, double *y, int cap, mcs_error *err);

/* record an error located at a node: "FILE:LINE:COL: error: PATH: <fmt>" (for the stages'
 * own checks when they build a model) */
mcs_status mcs_node_error(const mcs_node *n, mcs_error *err, mcs_status st, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
