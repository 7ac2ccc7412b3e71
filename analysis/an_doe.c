/* an_doe.c: full and fractional factorial, Latin hypercube designs (an_doe.h) */
#include "analysis/an_doe.h"

#include <stdio.h>
#include <string.h>

long an_doe_full(int k, const int *nlev, int *idx, long cap)
{
    long n = k > 0 ? 1 : 0;
    for (int j = 0; j < k; j++) {
        if (nlev[j] < 1 || n > cap / nlev[j]) return 0;
        n *= nlev[j];
    }
    for (long c = 0; c < n; c++) {
        long r = c;
        for (int j = 0; j < k; j++) {
            idx[c * k + j] = (int)(r % nlev[j]);
            r /= nlev[j];
        }
    }
    return n;
}

/* a generator "E=ABC" / "E = -ABC" of factor `self` over nbase base factors: the bit mask of
 * its base factors and its sign; 0 when malformed */
static unsigned parse_gen(const char *g, int self, int nbase, int *neg)
{
    while (*g == ' ') g++;
    if (*g != 'A' + self) return 0;
    g++;
    while (*g == ' ') g++;
    if (*g++ != '=') return 0;
    while (*g == ' ') g++;
    *neg = *g == '-';
    if (*g == '-' || *g == '+') g++;
    unsigned mask = 0;
    for (; *g && *g != ' '; g++) {
        int f = *g - 'A';
        if (f < 0 || f >= nbase || (mask & (1u << f))) return 0;
        mask |= 1u << f;
    }
    while (*g == ' ') g++;
    return *g ? 0 : mask;
}

long an_doe_fractional(int k, int ngen, const char *const *gen, int *sign, long cap, char *why,
                       int nwhy)
{
    int nbase = k - ngen;
    unsigned mask[AN_DOE_MAXFACTOR];
    int neg[AN_DOE_MAXFACTOR];
    if (k > AN_DOE_MAXFACTOR || nbase < 1 || nbase > 30 || (1L << nbase) > cap) {
        snprintf(why, (size_t)nwhy, "%d factors with %d generators is not a design", k, ngen);
        return -1;
    }
    for (int g = 0; g < ngen; g++) {
        mask[g] = parse_gen(gen[g], nbase + g, nbase, &neg[g]);
        if (!mask[g]) {
            snprintf(why, (size_t)nwhy,
                     "generator '%s': expected %c=WORD with WORD of the base factors A..%c",
                     gen[g], 'A' + nbase + g, 'A' + nbase - 1);
            return -1;
        }
    }
    long n = 1L << nbase;
    for (long c = 0; c < n; c++) {
        for (int j = 0; j < nbase; j++)
            sign[c * k + j] = (c >> j) & 1 ? 1 : -1;
        for (int g = 0; g < ngen; g++) {
            int s = neg[g] ? -1 : 1;
            for (int j = 0; j < nbase; j++)
                if (mask[g] & (1u << j)) s *= sign[c * k + j];
            sign[c * k + nbase + g] = s;
        }
    }
    return n;
}

/* Montgomery (8th ed.) Table 8.14: k, resolution, generators (signs +) */
typedef struct {
    int k, res;
    const char *gen[4];
} std_design;

static const std_design std_designs[] = {
    {3, 3, {"C=AB"}},
    {4, 4, {"D=ABC"}},
    {5, 5, {"E=ABCD"}},
    {5, 3, {"D=AB", "E=AC"}},
    {6, 6, {"F=ABCDE"}},
    {6, 4, {"E=ABC", "F=BCD"}},
    {6, 3, {"D=AB", "E=AC", "F=BC"}},
    {7, 7, {"G=ABCDEF"}},
    {7, 4, {"F=ABCD", "G=ABDE"}},
    {7, 4, {"E=ABC", "F=BCD", "G=ACD"}},
    {7, 3, {"D=AB", "E=AC", "F=BC", "G=ABC"}},
    {8, 5, {"G=ABCD", "H=ABEF"}},
    {8, 4, {"F=ABC", "G=ABD", "H=BCDE"}},
    {8, 4, {"E=BCD", "F=ACD", "G=ABC", "H=ABD"}},
};

int an_doe_standard(int k, int resolution, const char **gen, int *ngen)
{
    const std_design *best = NULL;
    int nbest = 0;
    for (size_t i = 0; i < sizeof std_designs / sizeof std_designs[0]; i++) {
        const std_design *d = &std_designs[i];
        int ng = 0;
        while (ng < 4 && d->gen[ng]) ng++;
        if (d->k != k || d->res < resolution) continue;
        if (!best || ng > nbest) best = d, nbest = ng; /* more generators: fewer runs */
    }
    if (!best) return 0;
    for (int g = 0; g < nbest; g++)
        gen[g] = best->gen[g];
    *ngen = nbest;
    return best->res;
}

int an_doe_resolution(int k, int ngen, const char *const *gen)
{
    int nbase = k - ngen, res = 0, neg;
    unsigned word[AN_DOE_MAXFACTOR];
    if (ngen < 1 || ngen > 16 || nbase < 1 || k > AN_DOE_MAXFACTOR) return 0;
    for (int g = 0; g < ngen; g++) {
        unsigned m = parse_gen(gen[g], nbase + g, nbase, &neg);
        if (!m) return 0;
        word[g] = m | (1u << (nbase + g)); /* I = E*ABC: the word ABCE */
    }
    /* every product of a non-empty subset of the generators' words is a word of the relation */
    for (unsigned s = 1; s < (1u << ngen); s++) {
        unsigned w = 0;
        for (int g = 0; g < ngen; g++)
            if (s & (1u << g)) w ^= word[g];
        int len = __builtin_popcount(w);
        if (!res || len < res) res = len;
    }
    return res;
}

uint64_t an_splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double an_rand01(uint64_t *state)
{
    return (double)(an_splitmix64(state) >> 11) * 0x1p-53;
}

void an_doe_lhs(int n, int k, uint64_t seed, double *u)
{
    uint64_t s = seed;
    for (int j = 0; j < k; j++) {
        for (int i = 0; i < n; i++)
            u[i * k + j] = i; /* strata, shuffled in place */
        for (int i = n - 1; i > 0; i--) {
            int r = (int)(an_rand01(&s) * (i + 1));
            double t = u[i * k + j];
            u[i * k + j] = u[r * k + j];
            u[r * k + j] = t;
        }
        for (int i = 0; i < n; i++)
            u[i * k + j] = (u[i * k + j] + an_rand01(&s)) / n;
    }
}
