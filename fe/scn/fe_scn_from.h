/* fe_scn_from: fe.parts[].mesh: {from: FILE.h5:/stageN/mesh/<part>, at: TIME | final}: a part's
 * mesh as a run wrote it (fe/out/fe_out_mesh.c), read back (core/mcs_results_mesh.h) into any
 * stage's scenario, so a bag reshaped in stage 2 is the one stage 1 uses (docs/exchange.md).
 * The file is relative to the YAML file that names it; the reference shape by default, the
 * deformed one at `at` or at the last field row (`at: final`). The section and material come
 * from the scenario (a results file carries neither). */
#ifndef FE_SCN_FROM_H
#define FE_SCN_FROM_H

#include "core/mcs_scenario.h"
#include "fe/fe_model.h"

/* 1 when the mesh node names a results file (from:) */
int fe_scn_from_is(const mcs_node *mesh);

/* add the part whose scenario node is `part` (d: its name, section, material, velocity); errors
 * name the scenario's from: node, the results file and the path */
mcs_status fe_scn_from_add_part(fe_builder *b, const mcs_node *part, const fe_part_desc *d,
                                mcs_error *err);

#endif
