/* s2_fig23.h: the concept 413 case's stage-2 kinematics against the 2023 paper's stage-2 figures
 * (seed 001 Sec. 3.2, Fig. 23: the 5th Hybrid III in coupled FE/MB, "the belt slips down at
 * 225 ms" with the HBM; Fig. 24b: belts > airbags > cockpit > leg protection), read from a
 * results file of either stage (tests/test_stage2_verify.c, make verify). The references are
 * geometric definitions, not model outputs: the belt's place on the thigh is the mean of its
 * webbing nodes (reference nodes + displacement field) in the thigh body's frame; the pelvis's
 * travel on the motorcycle is its position in moto_frame's frame; "stays on" uses the same
 * 0.25 m as tests/concept_pair.h's leave time. Include after harness.h and s2_test_util.h. */
#ifndef S2_FIG23_H
#define S2_FIG23_H

#define F23_LEAVE 0.25 /* pelvis off its seated place [m] (tests/concept_pair.h LEAVE) */

typedef struct {
    double slip[4];   /* belt's mean node along the thigh axis (body x), change from t = 0 [m],
                       * at 0/100/200/300 ms, mean of left and right */
    double along0;    /* the same at t = 0, from the thigh's origin [m] */
    double up[4];     /* the belt's offset along the thigh's z axis (up on the thigh), change */
    double head_dz;   /* peak head height above its t = 0 height [m] */
    double head_tpk;  /* its time [s] */
    double head_dx;   /* largest forward travel of the head in moto_frame's frame [m] */
    double pelvis_dx; /* largest forward travel of the pelvis in moto_frame's frame [m] */
    double pelvis_dmax; /* largest distance of the pelvis from its seated place (frame) [m] */
    int ok;
} f23_kin;

/* R(q)^T d, q = (w, x, y, z): d in the body's axes */
static inline void f23_to_body(const double *q, const double *d, double *r)
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    r[0] = (1 - 2 * (y * y + z * z)) * d[0] + 2 * (x * y + w * z) * d[1] +
           2 * (x * z - w * y) * d[2];
    r[1] = 2 * (x * y - w * z) * d[0] + (1 - 2 * (x * x + z * z)) * d[1] +
           2 * (y * z + w * x) * d[2];
    r[2] = 2 * (x * z + w * y) * d[0] + 2 * (y * z - w * x) * d[1] +
           (1 - 2 * (x * x + y * y)) * d[2];
}

static inline double *f23_ds(const char *file, int stage, const char *rest, size_t *n)
{
    char p[200];
    snprintf(p, sizeof p, "/stage%d/%.160s", stage, rest);
    return read_ds(file, p, n);
}

/* belt `part`'s mean node, in `thigh`'s frame, at the field row nearest time t */
static inline int f23_belt(const char *file, int stage, const char *part, const char *thigh,
                           double t, double *loc)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    char p[128];
    double off = -1;
    snprintf(p, sizeof p, "/stage%d/mesh/%s/nodes", stage, part);
    if (mcs_results_open(&r, file, &e)) return 0;
    mcs_results_attr_double(r, p, "node_offset", &off, &e);
    mcs_results_close(&r);
    size_t nn = 0, nft = 0, nd = 0, nt = 0, nq = 0, np = 0;
    double *x0 = read_ds(file, p, &nn);
    double *ft = f23_ds(file, stage, "fields/time", &nft);
    double *u = f23_ds(file, stage, "fields/displacement", &nd);
    double *tt = f23_ds(file, stage, "time", &nt);
    snprintf(p, sizeof p, "bodies/%s/orientation", thigh);
    double *q = f23_ds(file, stage, p, &nq);
    snprintf(p, sizeof p, "bodies/%s/position", thigh);
    double *bp = f23_ds(file, stage, p, &np);
    int ok = x0 && ft && u && tt && q && bp && off >= 0 && nft > 1 && nq == 4 * nt;
    if (ok) {
        size_t kf = 0, kt = 0, nrow = nd / nft / 3;
        for (size_t i = 0; i < nft; i++)
            if (fabs(ft[i] - t) < fabs(ft[kf] - t)) kf = i;
        for (size_t i = 0; i < nt; i++)
            if (fabs(tt[i] - ft[kf]) < fabs(tt[kt] - ft[kf])) kt = i;
        double c[3] = {0}, d[3];
        size_t nb = nn / 3, o = (size_t)off;
        for (size_t j = 0; j < nb; j++)
            for (int a = 0; a < 3; a++)
                c[a] += (x0[3 * j + a] + u[3 * (kf * nrow + o + j) + a]) / (double)nb;
        for (int a = 0; a < 3; a++)
            d[a] = c[a] - bp[3 * kt + a];
        f23_to_body(q + 4 * kt, d, loc);
    }
    free(x0), free(ft), free(u), free(tt), free(q), free(bp);
    return ok;
}

static inline f23_kin f23_kinematics(const char *file, int stage)
{
    f23_kin k = {0};
    const double tq[4] = {0, 0.1, 0.2, 0.3};
    int ok = 1;
    double l0[2][3] = {{0}};
    for (int i = 0; i < 4; i++) {
        double l[2][3];
        ok &= f23_belt(file, stage, "belt_l", "rider_thigh_l", tq[i], l[0]);
        ok &= f23_belt(file, stage, "belt_r", "rider_thigh_r", tq[i], l[1]);
        if (i == 0) memcpy(l0, l, sizeof l0), k.along0 = 0.5 * (l[0][0] + l[1][0]);
        k.slip[i] = 0.5 * (l[0][0] - l0[0][0] + l[1][0] - l0[1][0]);
        k.up[i] = 0.5 * (l[0][2] - l0[0][2] + l[1][2] - l0[1][2]);
    }
    size_t nt = 0, nh = 0, nf = 0, nq = 0, np = 0;
    double *t = f23_ds(file, stage, "time", &nt);
    double *h = f23_ds(file, stage, "bodies/rider_head/position", &nh);
    double *f = f23_ds(file, stage, "bodies/moto_frame/position", &nf);
    double *q = f23_ds(file, stage, "bodies/moto_frame/orientation", &nq);
    double *p = f23_ds(file, stage, "bodies/rider_pelvis/position", &np);
    double h0[3] = {0};
    ok &= t && h && f && q && p && nh == 3 * nt && nf == nh && np == nh && nq == 4 * nt;
    if (ok) {
        double r0[3];
        k.head_dz = -INFINITY;
        for (size_t i = 0; i < nt; i++) {
            if (h[3 * i + 2] - h[2] > k.head_dz) k.head_dz = h[3 * i + 2] - h[2], k.head_tpk = t[i];
            double d[3] = {p[3 * i] - f[3 * i], p[3 * i + 1] - f[3 * i + 1],
                           p[3 * i + 2] - f[3 * i + 2]},
                   r[3];
            f23_to_body(q + 4 * i, d, r);
            if (i == 0) memcpy(r0, r, sizeof r0);
            double dh[3] = {h[3 * i] - f[3 * i], h[3 * i + 1] - f[3 * i + 1],
                            h[3 * i + 2] - f[3 * i + 2]},
                   rh[3];
            f23_to_body(q + 4 * i, dh, rh);
            if (i == 0) memcpy(h0, rh, sizeof h0);
            k.head_dx = fmax(k.head_dx, rh[0] - h0[0]);
            k.pelvis_dx = fmax(k.pelvis_dx, r[0] - r0[0]);
            k.pelvis_dmax = fmax(k.pelvis_dmax, sqrt((r[0] - r0[0]) * (r[0] - r0[0]) +
                                                     (r[1] - r0[1]) * (r[1] - r0[1]) +
                                                     (r[2] - r0[2]) * (r[2] - r0[2])));
        }
    }
    free(t), free(h), free(f), free(q), free(p);
    k.ok = ok;
    return k;
}

/* FIG the kinematics of one run under the literal keys key[]: belt slip along the thigh and
 * its move up the thigh at 100/200/300 ms, head peak height, head and pelvis forward travel
 * on the motorcycle, pelvis off its place (tests/test_figures.c finds each
 * key in tests/), and print them; returns pelvis_dmax (NAN if unread) */
static inline double f23_fig(const char *file, int stage, const char *tag, const char *const key[10])
{
    f23_kin k = f23_kinematics(file, stage);
    CHECK(k.ok);
    printf("Fig. 23, %s: belt along the thigh %.1f mm from its origin at 0 ms, slip %+.1f %+.1f "
           "%+.1f mm at 100/200/300 ms (up %+.1f %+.1f %+.1f mm); head peak %+.0f mm at %.0f "
           "ms; head forward on the motorcycle %.0f mm, pelvis %.0f mm, off its place at most %.0f mm\n",
           tag, 1e3 * k.along0, 1e3 * k.slip[1], 1e3 * k.slip[2], 1e3 * k.slip[3], 1e3 * k.up[1],
           1e3 * k.up[2], 1e3 * k.up[3], 1e3 * k.head_dz, 1e3 * k.head_tpk, 1e3 * k.head_dx, 1e3 * k.pelvis_dx,
           1e3 * k.pelvis_dmax);
    for (int i = 0; i < 3; i++) {
        FIG(key[i], "%.0f", 1e3 * k.slip[i + 1]);
        FIG(key[3 + i], "%.0f", 1e3 * k.up[i + 1]);
    }
    FIG(key[6], "%.0f", 1e3 * k.head_dz);
    FIG(key[7], "%.0f", 1e3 * k.head_dx);
    FIG(key[8], "%.0f", 1e3 * k.pelvis_dx);
    FIG(key[9], "%.0f", 1e3 * k.pelvis_dmax);
    return k.ok ? k.pelvis_dmax : NAN;
}

/* the rider's contact energy by category at the end of the run [J] (0 when absent) */
static inline double f23_cat(const char *file, int stage, const char *cat)
{
    mcs_results *r = NULL;
    mcs_error e = {0};
    char g[128], **names = NULL;
    int n = 0;
    double sum = 0;
    snprintf(g, sizeof g, "/stage%d/energy_groups/rider/contact", stage);
    if (mcs_results_open(&r, file, &e) || mcs_results_list(r, g, &names, &n, &e)) {
        mcs_results_close(&r);
        return NAN;
    }
    for (int i = 0; i < n; i++) {
        char p[256], *c = NULL;
        snprintf(p, sizeof p, "%s/%s", g, names[i]);
        mcs_array a = {0};
        if (!mcs_results_attr_str(r, p, "category", &c, &e) && !strcmp(c, cat) &&
            !mcs_results_read(r, p, &a, &e) && a.n)
            sum += a.v[a.n - 1];
        free(c);
        mcs_array_free(&a);
    }
    mcs_results_list_free(&names, n);
    mcs_results_close(&r);
    return sum;
}

#endif
