/* s3_model_file: the stage-1 model file a stage-3 generator (`mesh: {generate: motorcycle |
 * sedan_side, model: FILE}`) is built from, read relative to the file that names it. */
#ifndef S3_MODEL_FILE_H
#define S3_MODEL_FILE_H

#include "core/mcs_scenario.h"

/* loads the model file named by node mf into *m; an error at mf ("WHAT model: ...") when it
 * cannot be read */
mcs_status s3_load_model(const mcs_node *mf, const char *what, mcs_scenario **m, mcs_error *err);

#endif
