/* fe_scn_keyword: fe.parts[].mesh: {keyword: FILE.k, part: ID, units: ..., unknown_keywords: ...}
 * (docs/keyword.md): the deck is read once per file and unit system while a scenario is built
 * (parts from one deck share their nodes), the part's nodes and elements go into the builder,
 * and the section and material come from the scenario, or from the deck's *SECTION_* and
 * *MAT_* cards when the scenario leaves them out. */
#ifndef FE_SCN_KEYWORD_H
#define FE_SCN_KEYWORD_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

typedef struct fe_scn_kw_cache fe_scn_kw_cache;

/* add the part whose scenario node is `part` (d: its name, initial velocity and the section /
 * material given in the scenario); *cache starts NULL and is freed with fe_scn_kw_cache_free */
mcs_status fe_scn_kw_add_part(fe_scn_kw_cache **cache, fe_builder *b, const mcs_node *part,
                          const fe_part_desc *d, mcs_error *err);
void fe_scn_kw_cache_free(fe_scn_kw_cache **cache);

struct fe_kw_deck;
/* called per keyword deck a scenario names: its resolved path, the scenario node naming it */
typedef void (*fe_scn_kw_visit)(const char *path, const mcs_node *at, const struct fe_kw_deck *d,
                                void *user);

/* read every keyword deck the scenario names (each map with a `keyword:` file: fe.parts[].mesh
 * and a whole-deck fe:) with its units, as a build would; a `part:` beside it must be the part
 * ID of some element of the deck. Errors name the scenario node and the deck's file:line. fn
 * (may be NULL) sees each deck once. Used by `mcrash check`. */
mcs_status fe_scn_kw_check(const mcs_node *root, fe_scn_kw_visit fn, void *user, mcs_error *err);

#endif
