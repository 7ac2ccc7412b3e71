/* mb_injury.c: /stageN/injury/<criterion> of a committed stage-1 (2) results file, from its
 * channels (analysis/an_injury.h names them: head_ax/ay/az, neck_fx/fz/my, chest_*, ...; a
 * sensor named "head" of type acceleration gives head_ax/ay/az). Nothing is written when no
 * known channel exists. The file is reopened for append and replaced atomically. */
#include "analysis/an_injury.h"
#include "core/mcs_results.h"
#include "stage1_mb/mb_model.h"

#include <stdlib.h>

mcs_status mb_injury_write(const char *path, int stage, int *ncrit, mcs_error *err)
{
    an_injury_row *rows = NULL;
    int n = 0, used = 0;
    *ncrit = 0;
    mcs_status st = an_injury_evaluate(path, stage, &rows, &n, &used, err);
    if (st || n == 0) {
        free(rows);
        return st;
    }
    mcs_results *r = NULL;
    st = mcs_results_append(&r, path, err);
    for (int i = 0; !st && i < n; i++)
        st = mcs_results_put_injury(r, stage, rows[i].key, rows[i].value, rows[i].unit,
                                    rows[i].limit, rows[i].t1, rows[i].t2, rows[i].channel, err);
    free(rows);
    if (st) {
        mcs_results_abort(&r);
        return st;
    }
    *ncrit = n;
    return mcs_results_commit(&r, err);
}
