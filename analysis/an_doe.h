/* an_doe: designs of experiments for studies (`mcrash study`, DESIGN.md "Studies").
 * Each design gives, per case and factor, a level index (factorial designs) or a value in
 * [0, 1) of the factor's range (Latin hypercube); the caller maps them to SI values.
 *
 * Run order (docs/contracts.md "Studies"): factorial designs in standard (Yates) order, the
 * first factor changing fastest. */
#ifndef AN_DOE_H
#define AN_DOE_H

#include <stdint.h>

#define AN_DOE_MAXFACTOR 26 /* factors named A..Z in generators */

/* full factorial of k factors with nlev[j] levels: the number of cases (0 when k is 0 or the
 * product exceeds cap); idx[case * k + j] the level index of factor j (first fastest) */
long an_doe_full(int k, const int *nlev, int *idx, long cap);

/* 2-level fractional factorial 2^(k-p): the first k-p factors (A, B, ...) in full factorial,
 * each later factor from a generator "E=ABC" or "E=-ABC" (the product of the signs of base
 * factors). sign[case * k + j] is -1 (low level) or +1 (high). Returns the number of cases
 * (2^(k-p)), or -1 with why filled when a generator is malformed (names a factor that is not
 * a base factor, or defines another factor than the next one). */
long an_doe_fractional(int k, int ngen, const char *const *gen, int *sign, long cap, char *why,
                       int nwhy);

/* the standard generators for k factors and at least the given resolution (the design with
 * the fewest runs; Montgomery, Design and Analysis of Experiments, 8th ed., Table 8.14, the
 * same as NIST/SEMATECH e-Handbook 5.3.3.4.7): *ngen generators into gen (static strings),
 * and the design's resolution returned; 0 when the table has none (k < 3 or k > 8, or the
 * resolution asked is beyond the half fraction's) */
int an_doe_standard(int k, int resolution, const char **gen, int *ngen);

/* resolution of a 2^(k-p) design from its generators: the shortest word of the defining
 * relation (its generators' words and all their products); 0 on a malformed generator */
int an_doe_resolution(int k, int ngen, const char *const *gen);

/* SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", OOPSLA
 * 2014): the next 64-bit output of the state, and a double in [0, 1) from its top 53 bits */
uint64_t an_splitmix64(uint64_t *state);
double an_rand01(uint64_t *state);

/* Latin hypercube of n samples and k factors from seed: u[i * k + j] in [0, 1), exactly one
 * sample in each of the n strata [m/n, (m+1)/n) of every factor. Per factor j in order: a
 * Fisher-Yates shuffle of the strata (for i = n-1 .. 1, swap i with floor(r (i+1)), r the
 * next an_rand01), then u = (stratum + r) / n for each sample in order. The state starts at
 * the seed. */
void an_doe_lhs(int n, int k, uint64_t seed, double *u);

#endif
