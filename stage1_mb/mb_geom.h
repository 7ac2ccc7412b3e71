/* mb_geom.h: penetration geometry of stage-1 contact surfaces (docs/contact_geometry.md).
 * Ellipsoid-plane (closed form), sphere-sphere (exact), ellipsoid-ellipsoid (common normal,
 * damped Newton on the unit sphere), ellipsoid-triangle mesh (face/edge/vertex, AABB tree) and
 * wheel-road (torus or thin disc against a plane). Functions return geometry only: depth, points
 * and normal; the force characteristics live elsewhere. No allocation except mb_mesh_create. */
#ifndef MB_GEOM_H
#define MB_GEOM_H

#include "core/mcs_error.h"

/* an ellipsoid surface placed in the world */
typedef struct {
    double center[3]; /* centre, world [m] */
    double rot[9];    /* ellipsoid axes -> world rotation, row-major; column i = local axis i */
    double semi[3];   /* semi-axes along the local x, y, z axes [m], > 0 */
} mb_ellipsoid;

/* a plane bounding a half-space solid (ground, barrier) */
typedef struct {
    double point[3];  /* any point of the plane, world [m] */
    double normal[3]; /* unit outward normal; the solid lies on the -normal side */
} mb_plane;

/* a wheel: torus (tube > 0) or thin disc (tube = 0) */
typedef struct {
    double center[3]; /* wheel centre, world [m] */
    double axis[3];   /* unit spin axis, world */
    double radius;    /* radius of the crown circle (wheel centre to tyre tube centre) [m] */
    double tube;      /* tyre crown (tube) radius, 0 = thin disc of radius `radius` [m] */
} mb_wheel;

/* mesh pose: mesh-local -> world */
typedef struct {
    double pos[3]; /* origin of the mesh frame, world [m] */
    double rot[9]; /* rotation mesh -> world, row-major */
} mb_pose;

/* which feature of a facet the contact lies on */
typedef enum { MB_FEATURE_NONE, MB_FEATURE_FACE, MB_FEATURE_EDGE, MB_FEATURE_VERTEX } mb_feature;

/* outcome of an iterative query */
typedef enum {
    MB_GEOM_OK = 0,            /* exact or converged                                        */
    MB_GEOM_NOT_CONVERGED = 1, /* iteration limit: best iterate returned (depth conservative) */
    MB_GEOM_DEGENERATE = 2     /* coincident centres / wheel flat on the plane: a chosen normal */
} mb_geom_status;

/* one contact between surface a and surface b */
typedef struct {
    double depth;      /* penetration [m], >= 0; 0 and the rest unset when apart       */
    double normal[3];  /* unit normal, world, from b into a: the force on a is along +normal */
    double point[3];   /* contact point, world [m]: midway between point_a and point_b   */
    double point_a[3]; /* deepest point of a inside b, world [m]                         */
    double point_b[3]; /* point of b's surface opposite point_a, world [m]               */
    int tri;           /* facet index for meshes, -1 otherwise                           */
    int feature;       /* mb_feature (facets), MB_FEATURE_NONE otherwise                 */
    int iterations;    /* Newton iterations (ellipsoid-ellipsoid), 0 otherwise           */
    int status;        /* mb_geom_status                                                 */
} mb_contact;

/* wheel-road contact with the tyre frame */
typedef struct {
    mb_contact c;      /* a = wheel, b = plane; point_b is the road contact point        */
    double camber;     /* camber angle, asin(axis . normal) [rad]                        */
    double forward[3]; /* unit rolling direction in the road plane, axis x normal        */
    double lateral[3]; /* unit lateral direction in the road plane, normal x forward      */
} mb_wheel_contact;

/* each returns 1 when the surfaces penetrate (c filled), 0 when apart (c->depth = 0) */
int mb_geom_ellipsoid_plane(const mb_ellipsoid *a, const mb_plane *b, mb_contact *c);
int mb_geom_sphere_sphere(const double ca[3], double ra, const double cb[3], double rb,
                          mb_contact *c);
/* warm_normal: last step's normal of this pair (from b into a) or NULL. When apart (returns 0)
 * c->normal holds a separating direction if one was found (else zero): a warm start for the
 * next step's culling */
int mb_geom_ellipsoid_ellipsoid(const mb_ellipsoid *a, const mb_ellipsoid *b,
                                const double *warm_normal, mb_contact *c);
/* culling (mb_geom_cull.c): 1 when a and b are proven apart by bounding spheres, boxes or the
 * unit direction n (may be NULL); 0 = undecided. The gap g(n) = n.(ca - cb) - ha(n) - hb(n)
 * is a lower bound of their distance for any unit n [m]. */
int mb_ellipsoids_apart(const mb_ellipsoid *a, const mb_ellipsoid *b, const double *n);
double mb_ellipsoid_gap(const mb_ellipsoid *a, const mb_ellipsoid *b, const double n[3]);
/* one triangle v0 v1 v2 (counter-clockwise seen from outside: outward normal by right hand) */
int mb_geom_ellipsoid_triangle(const mb_ellipsoid *a, const double v0[3], const double v1[3],
                               const double v2[3], mb_contact *c);
int mb_geom_wheel_plane(const mb_wheel *w, const mb_plane *b, mb_wheel_contact *wc);
/* wheel (a) against an ellipsoid (b): the filled wheel, the convex hull of its torus (disc of
 * radius `radius` grown by `tube`), by the ellipsoid-ellipsoid support-function maximisation
 * with the disc as a flat ellipsoid (R, R, MB_WHEEL_EPS R): depth exact for every normal not
 * along the axis, at most MB_WHEEL_EPS R too deep along it. warm_normal and the separating
 * normal as for mb_geom_ellipsoid_ellipsoid. */
#define MB_WHEEL_EPS 1e-4
int mb_geom_wheel_ellipsoid(const mb_wheel *w, const mb_ellipsoid *e, const double *warm_normal,
                            mb_contact *c);
/* the flat ellipsoid (R, R, MB_WHEEL_EPS R) of a wheel's disc (axis = its third axis) */
void mb_wheel_disc(const mb_wheel *w, mb_ellipsoid *disc);

/* the deepest point of an ellipsoid along -dir (support point), world [m] */
void mb_ellipsoid_support(const mb_ellipsoid *e, const double dir[3], double out[3]);

/* a triangle mesh with an AABB tree, built once (model); queries do not allocate */
typedef struct mb_mesh mb_mesh;

/* vert: nvert x 3 mesh-local coordinates [m]; tri: ntri x 3 vertex indices (0-based, outward
 * counter-clockwise). Rejects bad indices, non-finite coordinates and zero-area triangles. */
mcs_status mb_mesh_create(mb_mesh **out, int nvert, const double *vert, int ntri, const int *tri,
                          mcs_error *err);
void mb_mesh_destroy(mb_mesh **m);
int mb_mesh_ntri(const mb_mesh *m);
/* the mesh's vertices (nvert x 3, mesh frame) and triangles (ntri x 3) as given to create */
const double *mb_mesh_vert(const mb_mesh *m, int *nvert);
const int *mb_mesh_tri(const mb_mesh *m);
int mb_mesh_nnode(const mb_mesh *m); /* AABB tree nodes */

/* ellipsoid against a posed mesh (pose NULL = identity). Fills *deepest with the deepest
 * triangle contact and up to max_all per-triangle contacts in all[] (may be NULL); returns the
 * number of triangles in contact (may exceed max_all). */
int mb_geom_ellipsoid_mesh(const mb_ellipsoid *a, const mb_mesh *m, const mb_pose *pose,
                           mb_contact *deepest, mb_contact *all, int max_all);
/* the deepest triangle contact only (same answer as above), usually much cheaper: triangles are
 * evaluated in decreasing depth of their plane until no other can be deeper; returns 1/0 */
int mb_geom_ellipsoid_mesh_deepest(const mb_ellipsoid *a, const mb_mesh *m, const mb_pose *pose,
                                   mb_contact *deepest);
/* the same, ignoring triangle contacts deeper than max_depth [m] (a contact that would begin
 * deeper than a step can push it: an ellipsoid beside a panel's edge, mb_facet.h) */
int mb_geom_ellipsoid_mesh_deepest_capped(const mb_ellipsoid *a, const mb_mesh *m,
                                          const mb_pose *pose, double max_depth,
                                          mb_contact *deepest);

/* triangles whose contact began deeper than the cap: ignored for as long as that contact lasts
 * (a contact that shrinks below the cap would otherwise begin at the cap's depth at once) */
enum { MB_LATCH_MAX = 4 };
typedef struct {
    int n;                 /* latched triangles                                       */
    int tri[MB_LATCH_MAX]; /* their indices into the mesh                             */
} mb_mesh_latch;
/* the capped query with a latch (state of the caller, zero at first): a latched triangle is
 * skipped until it is out of contact, a triangle over the cap joins the latch (while there is
 * room; otherwise it is skipped for this call only) */
int mb_geom_ellipsoid_mesh_deepest_latched(const mb_ellipsoid *a, const mb_mesh *m,
                                           const mb_pose *pose, double max_depth,
                                           mb_mesh_latch *latch, mb_contact *deepest);

#endif
