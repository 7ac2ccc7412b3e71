/* s3_keyword: fe.parts[].mesh: {keyword: FILE.k, part: ID, units: ..., unknown_keywords: ...}
 * (docs/keyword.md): the deck is read once per file and unit system while a scenario is built
 * (parts from one deck share their nodes), the part's nodes and elements go into the builder,
 * and the section and material come from the scenario, or from the deck's *SECTION_* and
 * *MAT_* cards when the scenario leaves them out. */
#ifndef S3_KEYWORD_H
#define S3_KEYWORD_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

typedef struct s3_kw_cache s3_kw_cache;

/* add the part whose scenario node is `part` (d: its name, initial velocity and the section /
 * material given in the scenario); *cache starts NULL and is freed with s3_kw_cache_free */
mcs_status s3_kw_add_part(s3_kw_cache **cache, fe_builder *b, const mcs_node *part,
                          const fe_part_desc *d, mcs_error *err);
void s3_kw_cache_free(s3_kw_cache **cache);

#endif
