/* fe_out: the result series an FE model writes under /stage<N>, the same for a stage-3 run
 * (stage3_fe/s3_run.c) and the FE parts of a coupled stage-1 run (stage1_mb/mb_couple_out.c):
 * /stage<N>/fields (fe_out_mesh.h), contact, ellipsoid and facets (fe_out_contact.h), airbag and
 * retractor (fe_scn_restraints.h), slipring (fe_scn_slipring.h), parts (fe_out_parts.h). The
 * meshes (fe_out_meshes) and the stage's own series (time, energy) are the caller's. */
#ifndef FE_OUT_H
#define FE_OUT_H

#include "fe/out/fe_out_contact.h"
#include "fe/out/fe_out_joint.h"
#include "fe/fe_out_mesh.h"
#include "fe/out/fe_out_motion.h"
#include "fe/out/fe_out_parts.h"
#include "fe/fe_scn_restraints.h"
#include "fe/scn/fe_scn_slipring.h"

typedef struct {
    fe_out_field field;     /* /stage<N>/fields                                  */
    fe_out_contact contact; /* /stage<N>/contact, /stage<N>/ellipsoid, /facets   */
    fe_out_restraint rest;  /* /stage<N>/airbag, /stage<N>/retractor             */
    fe_out_slipring rings;  /* /stage<N>/slipring                                */
    fe_out_parts parts;     /* /stage<N>/parts/<part>/energy                     */
    fe_out_motion motion;   /* /stage<N>/parts/<part>/{mass, motion} (fe_out_motion.h) */
    fe_out_joint joints;    /* /stage<N>/joints, /stage<N>/bodies (fe_out_joint.h)  */
} fe_out;

/* every series of m into /stage<stage> of r */
mcs_status fe_out_open(mcs_results *r, int stage, const fe_model *m, fe_out *o, mcs_error *err);
/* one row of all but the fields (fe_out_field_sample, at the caller's rate): at the state's
 * energy time */
mcs_status fe_out_sample(const fe_model *m, const fe_state *s, fe_out *o, mcs_error *err);
void fe_out_free(fe_out *o);

#endif
