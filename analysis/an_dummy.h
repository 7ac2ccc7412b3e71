/* an_dummy.h: the Hybrid III size a results file's rider represents. A scenario states it in
 * its rider: block (`rider: {dummy: 5th_female}`, default 50th_male; docs/rider.md "Sizes"),
 * stage 1 writes it as the attribute `dummy` of /stage1, and `mcrash injury` takes the Nij
 * intercepts and the size-specific limits from it (an_limits.c, an_nij.c). */
#ifndef AN_DUMMY_H
#define AN_DUMMY_H

typedef enum { AN_DUMMY_H3_50M, AN_DUMMY_H3_05F, AN_DUMMY_H3_95M, AN_NDUMMY } an_dummy;

/* "50th_male", "5th_female", "95th_male" -> *d, 0; -1 (and *d untouched) for any other name */
int an_dummy_parse(const char *name, an_dummy *d);

/* the name an_dummy_parse reads, "?" out of range */
const char *an_dummy_name(an_dummy d);

/* the names joined by "|" (schema choices, messages) */
#define AN_DUMMY_CHOICES "50th_male|5th_female|95th_male"

#endif
