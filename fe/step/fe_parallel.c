/* fe_parallel: the chunks of the threaded loops and their deterministic reduction.
 *
 * Element loops run over chunks of FE_CHUNK_ELEMS elements of one part, node loops over
 * chunks of FE_CHUNK_NODES nodes. Each chunk writes only its own elements' slots (or its own
 * nodes) and its own partial sums; the partial sums are then added in chunk order by one
 * thread. The chunks do not depend on the number of threads, so a run gives the same result
 * to the last bit with any OMP_NUM_THREADS (tests/test_fe_parallel.c). */
#include "fe/fe_builder_impl.h" /* fe_kind_nnode */
#include "fe/fe_contact.h"
#include "fe/fe_elem.h"
#include "fe/fe_parallel.h"

#include <math.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* smallest node of the elements of chunk k */
static int chunk_first_node(const fe_model *m, int k)
{
    const fe_part *p = m->part + m->chunk_part[k];
    const int e0 = m->chunk_elem[k];
    const int e1 = e0 + FE_CHUNK_ELEMS < p->elem_end ? e0 + FE_CHUNK_ELEMS : p->elem_end;
    const int *conn = fe_kind_conn(m, p->elem_kind), nper = fe_kind_nnode(p->elem_kind);
    int lo = m->nnode;
    for (int i = nper * e0; i < nper * e1; i++)
        if (conn[i] < lo) lo = conn[i];
    return lo;
}

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
    /* a share starting at element chunk k starts at the node chunk nearest the first node of
     * k's elements, never before the share before it */
    for (k = 0; k < m->nchunk; k++) {
        int nc = (chunk_first_node(m, k) + FE_CHUNK_NODES / 2) / FE_CHUNK_NODES;
        if (k > 0 && nc < m->chunk_nc[k - 1]) nc = m->chunk_nc[k - 1];
        m->chunk_nc[k] = nc < m->nnode_chunk ? nc : m->nnode_chunk;
    }
}

void fe_count_chunked(fe_model *m)
{
    m->nelem_chunked = 0;
    for (int ip = 0; ip < m->npart; ip++)
        if (fe_part_chunked(m->part + ip))
            m->nelem_chunked += m->part[ip].elem_end - m->part[ip].elem_begin;
}

void fe_chunk_commit(fe_state *s, int ip, const fe_chunk_acc *acc)
{
    double *pe = s->part_energy + FE_NENERGY * ip;
    /* an eroded element's internal energy moves to the eroded term (the balance keeps it) */
    pe[FE_E_internal] += acc->e_int - acc->e_erode;
    pe[FE_E_eroded] += acc->e_erode;
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
    into->e_erode += a->e_erode;
    into->nerode += a->nerode;
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

/* ---- thread shares (fe_parallel.h) ------------------------------------------------------ */

int fe_par_tid(void)
{
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

int fe_par_nth(void)
{
#ifdef _OPENMP
    return omp_get_num_threads();
#else
    return 1;
#endif
}

double fe_par_clock(void)
{
#ifdef _OPENMP
    return omp_get_wtime();
#else
    return 0;
#endif
}

/* the first node chunk that goes with element chunk k (k = nchunk: the end) */
static int first_nc(const fe_model *m, int k)
{
    return k < m->nchunk ? m->chunk_nc[k] : m->nnode_chunk;
}

/* the cost of element chunk k since the last balance: its elements' time and the contact
 * time of the node chunks that go with it (a thread's contact work is that of its nodes) */
static double chunk_load(const fe_model *m, const fe_state *s, int k)
{
    double c = s->chunk_cost[k];
    for (int j = first_nc(m, k); j < first_nc(m, k + 1); j++) c += s->node_cost[j];
    return c;
}

/* a new window: no time summed yet */
static void clear_costs(const fe_model *m, fe_state *s)
{
    s->par_steps = 0;
    for (int k = 0; k < m->nchunk; k++) s->chunk_cost[k] = 0;
    for (int j = 0; j < m->nnode_chunk; j++) s->node_cost[j] = 0;
}

/* at the end of each window of steps, move the element cuts so that every thread's chunks,
 * with the contact work of their nodes, took about the same time over the window; kept as
 * they are while the slowest share is within 3 % of the mean. A moved cut sends the state of
 * the chunks it moves to the other core's cache: balanced on single steps, the timing noise
 * moved the cut every 5 steps in the tube crush. The windows grow 1, 2, 4, ... to
 * FE_PAR_WINDOW steps, so that a new team finds its balance within a few steps. */
static void rebalance(const fe_model *m, fe_state *s, int nt)
{
    const int win = s->par_nbal < 30 && (1 << s->par_nbal) < FE_PAR_WINDOW ? 1 << s->par_nbal
                                                                          : FE_PAR_WINDOW;
    if (++s->par_steps < win) return;
    s->par_nbal++;
    const int nch = m->nchunk;
    int *cut = s->par_cut;
    double *c = s->chunk_cost; /* becomes the chunk loads, then zero for the next window */
    double tot = 0, worst = 0;
    for (int k = 0; k < nch; k++) tot += c[k] = chunk_load(m, s, k);
    for (int t = 0; t < nt; t++) {
        double load = 0;
        for (int k = cut[t]; k < cut[t + 1]; k++) load += c[k];
        worst = fmax(worst, load);
    }
    if (tot > 0 && worst > 1.03 * tot / nt) {
        double cum = 0;
        int k = 0;
        for (int t = 1; t < nt; t++) {
            const double target = tot * t / nt;
            while (k < nch && cum + c[k] <= target) cum += c[k++];
            if (k < nch && cum + c[k] - target < target - cum) cum += c[k++];
            cut[t] = k;
        }
    }
    clear_costs(m, s);
}

int fe_par_team(const fe_model *m, fe_state *s)
{
    int nt = fe_threads();
    if (nt > FE_PAR_MAX) nt = FE_PAR_MAX;
    if (nt > m->nchunk) nt = m->nchunk;
    if (m->nchunk < FE_PAR_MIN_CHUNKS || nt < 1) nt = 1;
    /* FE_PAR_MIN_WORK per thread: the elements of the chunk loops and, when the contact is
     * threaded (fe_contact_omp_work), its entries; membranes and the rest run on one thread */
    const long work = (long)m->nelem_chunked + fe_contact_omp_work(m);
    const long most = work / FE_PAR_MIN_WORK;
    if (nt > most) nt = most > 1 ? (int)most : 1;
    if (nt != s->par_nt) {
        /* a new team: equal numbers of chunks */
        for (int t = 0; t <= nt; t++) s->par_cut[t] = (int)((long)m->nchunk * t / nt);
        s->par_nt = nt;
        s->par_nbal = 0;
        clear_costs(m, s);
    } else if (nt > 1) {
        rebalance(m, s, nt);
    }
    /* node shares: the node chunks that go with each thread's first element chunk */
    s->par_ncut[0] = 0;
    for (int t = 1; t < nt; t++) s->par_ncut[t] = first_nc(m, s->par_cut[t]);
    s->par_ncut[nt] = m->nnode_chunk;
    return nt;
}

void fe_par_share(const fe_model *m, const fe_state *s, int t, fe_par_range *r)
{
    if (s->par_nt <= 1) {
        r->c0 = 0, r->c1 = m->nchunk;
        r->nc0 = 0, r->nc1 = m->nnode_chunk;
    } else {
        r->c0 = s->par_cut[t], r->c1 = s->par_cut[t + 1];
        r->nc0 = s->par_ncut[t], r->nc1 = s->par_ncut[t + 1];
    }
    r->n0 = r->nc0 * FE_CHUNK_NODES;
    r->n1 = r->nc1 * FE_CHUNK_NODES < m->nnode ? r->nc1 * FE_CHUNK_NODES : m->nnode;
    if (r->n0 > r->n1) r->n0 = r->n1;
}
