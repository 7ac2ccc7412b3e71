/* s3_model_file: the stage-1 model file of a stage-3 generator (s3_model_file.h). */
#include "stage3_fe/s3_model_file.h"

#include <stdio.h>
#include <string.h>

mcs_status s3_load_model(const mcs_node *mf, const char *what, mcs_scenario **m, mcs_error *err)
{
    const char *file = mcs_node_file(mf), *rel = mcs_node_str(mf);
    char path[4096];
    const char *slash = file ? strrchr(file, '/') : NULL;
    if (rel[0] == '/' || !slash)
        snprintf(path, sizeof path, "%s", rel);
    else
        snprintf(path, sizeof path, "%.*s/%s", (int)(slash - file), file, rel);
    mcs_error lerr = {0};
    if (mcs_scenario_load(path, m, &lerr))
        return mcs_node_error(mf, err, MCS_ERR_IO, "%s model: %s", what, lerr.msg);
    return MCS_OK;
}
