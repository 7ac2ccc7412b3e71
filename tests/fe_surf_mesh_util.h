/* fe_surf_mesh_util.h: closed test surfaces for the surface-volume and gas-bag tests
 * (icosphere, latitude-longitude sphere, subdivided box). Faces are nface x 4 node indices
 * with -1 as the 4th index of a triangle, outward oriented. Test-only: allocates freely. */
#ifndef FE_SURF_MESH_UTIL_H
#define FE_SURF_MESH_UTIL_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int nnode, nface;
    double *x;      /* nnode x 3 */
    int *face_node; /* nface x 4 */
} sm_mesh;

static inline void sm_free(sm_mesh *m)
{
    free(m->x);
    free(m->face_node);
    memset(m, 0, sizeof(*m));
}

/* midpoint cache for icosphere subdivision: open addressing on the (min, max) pair */
typedef struct {
    long long *key;
    int *val;
    int cap;
} sm_edge_map;

static inline int sm_midpoint(sm_edge_map *em, sm_mesh *m, int a, int b, double r)
{
    long long lo = a < b ? a : b, hi = a < b ? b : a, k = lo * 1000003LL + hi;
    int h = (int)((unsigned long long)(k * 2654435761ULL) % (unsigned long long)em->cap);
    while (em->key[h] != -1) {
        if (em->key[h] == k) return em->val[h];
        h = (h + 1) % em->cap;
    }
    int id = m->nnode++;
    double *p = m->x + 3 * id, n = 0.0;
    for (int d = 0; d < 3; d++) {
        p[d] = 0.5 * (m->x[3 * a + d] + m->x[3 * b + d]);
        n += p[d] * p[d];
    }
    for (int d = 0; d < 3; d++)
        p[d] *= r / sqrt(n);
    em->key[h] = k;
    em->val[h] = id;
    return id;
}

/* icosphere of radius r: the icosahedron subdivided `level` times, nodes on the sphere.
 * 20*4^level triangles, 10*4^level + 2 nodes. */
static inline sm_mesh sm_icosphere(int level, double r)
{
    const double t = (1.0 + sqrt(5.0)) / 2.0;
    const double v0[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    const int f0[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                           {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                           {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                           {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    int nf_final = 20, nn_final = 12;
    for (int l = 0; l < level; l++) {
        nn_final += nf_final * 3 / 2;
        nf_final *= 4;
    }
    sm_mesh m = {0, 20, malloc(sizeof(double) * 3 * nn_final), malloc(sizeof(int) * 4 * 20)};
    for (int i = 0; i < 12; i++) {
        double n = sqrt(v0[i][0] * v0[i][0] + v0[i][1] * v0[i][1] + v0[i][2] * v0[i][2]);
        for (int d = 0; d < 3; d++)
            m.x[3 * i + d] = r * v0[i][d] / n;
    }
    m.nnode = 12;
    for (int i = 0; i < 20; i++) {
        for (int k = 0; k < 3; k++)
            m.face_node[4 * i + k] = f0[i][k];
        m.face_node[4 * i + 3] = -1;
    }
    for (int l = 0; l < level; l++) {
        sm_edge_map em = {malloc(sizeof(long long) * 4 * m.nface),
                          malloc(sizeof(int) * 4 * m.nface), 4 * m.nface};
        for (int i = 0; i < em.cap; i++)
            em.key[i] = -1;
        int *nf = malloc(sizeof(int) * 16 * m.nface);
        for (int i = 0; i < m.nface; i++) {
            int a = m.face_node[4 * i], b = m.face_node[4 * i + 1], c = m.face_node[4 * i + 2];
            int ab = sm_midpoint(&em, &m, a, b, r), bc = sm_midpoint(&em, &m, b, c, r),
                ca = sm_midpoint(&em, &m, c, a, r);
            const int q[4][3] = {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}};
            for (int j = 0; j < 4; j++) {
                for (int k = 0; k < 3; k++)
                    nf[4 * (4 * i + j) + k] = q[j][k];
                nf[4 * (4 * i + j) + 3] = -1;
            }
        }
        free(em.key);
        free(em.val);
        free(m.face_node);
        m.face_node = nf;
        m.nface *= 4;
    }
    return m;
}

/* latitude-longitude sphere of radius r: nlat bands (even: the equator is a node ring),
 * nlon segments; triangles at the poles, quads elsewhere. Node 0 north pole, 1 south pole. */
static inline sm_mesh sm_uvsphere(int nlat, int nlon, double r)
{
    sm_mesh m;
    m.nnode = 2 + (nlat - 1) * nlon;
    m.nface = nlat * nlon;
    m.x = malloc(sizeof(double) * 3 * m.nnode);
    m.face_node = malloc(sizeof(int) * 4 * m.nface);
    m.x[0] = 0, m.x[1] = 0, m.x[2] = r;
    m.x[3] = 0, m.x[4] = 0, m.x[5] = -r;
    for (int j = 1; j < nlat; j++)
        for (int i = 0; i < nlon; i++) {
            double th = M_PI * j / nlat, ph = 2.0 * M_PI * i / nlon;
            double *p = m.x + 3 * (2 + (j - 1) * nlon + i);
            p[0] = r * sin(th) * cos(ph);
            p[1] = r * sin(th) * sin(ph);
            p[2] = r * cos(th);
        }
#define SM_RING(j, i) (2 + ((j)-1) * nlon + ((i) % nlon))
    int f = 0;
    for (int i = 0; i < nlon; i++) {
        int *q = m.face_node + 4 * f++;
        q[0] = 0, q[1] = SM_RING(1, i), q[2] = SM_RING(1, i + 1), q[3] = -1;
    }
    for (int j = 1; j < nlat - 1; j++)
        for (int i = 0; i < nlon; i++) {
            int *q = m.face_node + 4 * f++;
            q[0] = SM_RING(j, i), q[1] = SM_RING(j + 1, i), q[2] = SM_RING(j + 1, i + 1),
            q[3] = SM_RING(j, i + 1);
        }
    for (int i = 0; i < nlon; i++) {
        int *q = m.face_node + 4 * f++;
        q[0] = 1, q[1] = SM_RING(nlat - 1, i + 1), q[2] = SM_RING(nlat - 1, i), q[3] = -1;
    }
#undef SM_RING
    return m;
}

/* surface of the box [0,a] x [0,b] x [0,c], n[d] quads per edge, nodes of the full lattice
 * (interior nodes unused) */
static inline sm_mesh sm_box(const double size[3], const int n[3])
{
    sm_mesh m;
    m.nnode = (n[0] + 1) * (n[1] + 1) * (n[2] + 1);
    m.nface = 2 * (n[0] * n[1] + n[1] * n[2] + n[2] * n[0]);
    m.x = malloc(sizeof(double) * 3 * m.nnode);
    m.face_node = malloc(sizeof(int) * 4 * m.nface);
#define SM_ID(i, j, k) (((k) * (n[1] + 1) + (j)) * (n[0] + 1) + (i))
    for (int k = 0; k <= n[2]; k++)
        for (int j = 0; j <= n[1]; j++)
            for (int i = 0; i <= n[0]; i++) {
                double *p = m.x + 3 * SM_ID(i, j, k);
                p[0] = size[0] * i / n[0], p[1] = size[1] * j / n[1], p[2] = size[2] * k / n[2];
            }
    int f = 0;
    for (int a = 0; a < 3; a++) {
        int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int side = 0; side < 2; side++)
            for (int u = 0; u < n[b]; u++)
                for (int w = 0; w < n[c]; w++) {
                    int ijk[4][3], du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
                    for (int q = 0; q < 4; q++) {
                        ijk[q][a] = side ? n[a] : 0;
                        ijk[q][b] = u + du[q];
                        ijk[q][c] = w + dw[q];
                    }
                    int *fn = m.face_node + 4 * f++;
                    for (int q = 0; q < 4; q++) {
                        int qq = side ? q : 3 - q; /* min side: reversed (outward -e_a) */
                        fn[q] = SM_ID(ijk[qq][0], ijk[qq][1], ijk[qq][2]);
                    }
                }
    }
#undef SM_ID
    return m;
}

/* deterministic pseudo-random number in [-1, 1) */
static inline double sm_rand(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / (double)(1ULL << 52) - 1.0;
}

#endif
