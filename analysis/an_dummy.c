/* an_dummy.c: Hybrid III size names */
#include "analysis/an_dummy.h"

#include <string.h>

static const char *const names[AN_NDUMMY] = {"50th_male", "5th_female", "95th_male"};

int an_dummy_parse(const char *name, an_dummy *d)
{
    for (int k = 0; name && k < AN_NDUMMY; k++)
        if (strcmp(name, names[k]) == 0) {
            *d = (an_dummy)k;
            return 0;
        }
    return -1;
}

const char *an_dummy_name(an_dummy d)
{
    return d >= 0 && d < AN_NDUMMY ? names[d] : "?";
}
