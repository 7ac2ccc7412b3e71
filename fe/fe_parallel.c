/* fe_parallel: the chunks of the threaded loops and their deterministic reduction.
 *
 * Element loops run over chunks of FE_CHUNK_ELEMS elements of one part, node loops over
 * chunks of FE_CHUNK_NODES nodes. Each chunk writes only its own elements' slots (or its own
 * nodes) and its own partial sums; the partial sums are then added in chunk order by one
 * thread. The chunks do not depend on the number of threads, so a run gives the same result
 * to the last bit with any OMP_NUM_THREADS (tests/test_fe_parallel.c). */
#include "fe/fe_elem.h"

#include <math.h>
#ifdef _OPENMP
#include <omp.h>
#endif

void fe_build_chunks(fe_model *m)
{
    int k = 0;
    for (int ip = 0; ip < m->npart; ip++)
        for (int e = m->part[ip].elem_begin; e < m->part[ip].elem_end; e += FE_CHUNK_ELEMS) {
            m->chunk_part[k] = ip;
            m->chunk_elem[k] = e;
            k++;
        }
    m->nchunk = k;
    m->nnode_chunk = (m->nnode + FE_CHUNK_NODES - 1) / FE_CHUNK_NODES;
    m->node_acc_stride = FE_NACC_FIXED + m->npart + 3 * FE_WALL_MAX;
    m->nnode_acc = m->nnode_chunk * m->node_acc_stride;
}

void fe_chunk_commit(fe_state *s, int ip, const fe_chunk_acc *acc)
{
    double *pe = s->part_energy + FE_NENERGY * ip;
    pe[FE_E_internal] += acc->e_int;
    pe[FE_E_hourglass] += acc->e_hg;
    pe[FE_E_dissipated] += acc->e_diss;
    s->part_dt[ip] = acc->dtmin;
    s->part_dt_elem[ip] = acc->dtel;
    if (acc->bad >= 0 && s->part_bad_elem[ip] < 0) s->part_bad_elem[ip] = acc->bad;
}

/* the partial sums of consecutive chunks of one part, in chunk order: sums add, the smallest
 * step keeps the first element that gives it, the first bad element is the first found */
void fe_chunk_merge(fe_chunk_acc *into, const fe_chunk_acc *a)
{
    into->e_int += a->e_int;
    into->e_hg += a->e_hg;
    into->e_diss += a->e_diss;
    if (a->dtmin < into->dtmin) into->dtmin = a->dtmin, into->dtel = a->dtel;
    if (into->bad < 0) into->bad = a->bad;
}

int fe_threads(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

void fe_set_threads(int n)
{
#ifdef _OPENMP
    if (n > 0) omp_set_num_threads(n);
#else
    (void)n;
#endif
}
