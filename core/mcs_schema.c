/* mcs_schema.c: every contract key of the scenario (DESIGN.md "The scenario (YAML)"), with its
 * type, dimension, required flag and range. Later stages add their keys here.
 * Where DESIGN.md is silent the choice is what a crash engineer expects; it says so in a comment.
 * Cross-key rules (inertia definite, time step below end time, ...) live in mcs_scn_rules.c. */
#include "core/mcs_schema.h"

/* row makers: name, flags, then what the type needs; doc is the text of "missing" messages */
#define Q(n, d, fl, lo_, hi_, doc_)                                                                \
    {                                                                                              \
        .name = n, .type = MCS_SK_NUM, .flags = fl, .dim = d, .lo = lo_, .hi = hi_, .doc = doc_    \
    }
#define V(n, d, n0, n1, fl, lo_, doc_)                                                             \
    {                                                                                              \
        .name = n, .type = MCS_SK_VEC, .flags = fl, .dim = d, .nmin = n0, .nmax = n1, .lo = lo_,   \
        .doc = doc_                                                                                \
    }
#define I(n, fl, lo_, hi_, doc_)                                                                   \
    {                                                                                              \
        .name = n, .type = MCS_SK_INT, .flags = fl, .lo = lo_, .hi = hi_, .doc = doc_              \
    }
#define IS(n, n0, n1, fl, lo_, doc_)                                                               \
    {                                                                                              \
        .name = n, .type = MCS_SK_INTS, .flags = fl, .nmin = n0, .nmax = n1, .lo = lo_,            \
        .doc = doc_                                                                                \
    }
#define S(n, fl, doc_)                                                                             \
    {                                                                                              \
        .name = n, .type = MCS_SK_STR, .flags = fl, .doc = doc_                                    \
    }
#define B(n, fl, doc_)                                                                             \
    {                                                                                              \
        .name = n, .type = MCS_SK_BOOL, .flags = fl, .doc = doc_                                   \
    }
#define E(n, ch, fl, doc_)                                                                         \
    {                                                                                              \
        .name = n, .type = MCS_SK_ENUM, .flags = fl, .choices = ch, .doc = doc_                    \
    }
#define R(n, r, fl, doc_)                                                                          \
    {                                                                                              \
        .name = n, .type = MCS_SK_REF, .flags = fl, .ref = r, .doc = doc_                          \
    }
#define RS(n, r, n0, fl, doc_)                                                                     \
    {                                                                                              \
        .name = n, .type = MCS_SK_REFS, .flags = fl, .ref = r, .nmin = n0, .doc = doc_             \
    }
#define C(n, dx, dy, n0, fl, lo_, doc_)                                                            \
    {                                                                                              \
        .name = n, .type = MCS_SK_CURVE, .flags = fl, .dim = dx, .dim_y = dy, .nmin = n0,          \
        .lo = lo_, .doc = doc_                                                                     \
    }
#define M(n, s, fl, doc_)                                                                          \
    {                                                                                              \
        .name = n, .type = MCS_SK_MAP, .flags = fl, .sub = &s, .doc = doc_                         \
    }
#define L(n, s, fl, doc_)                                                                          \
    {                                                                                              \
        .name = n, .type = MCS_SK_LIST, .flags = fl, .sub = &s, .doc = doc_                        \
    }
#define NM(n, s, fl, doc_)                                                                         \
    {                                                                                              \
        .name = n, .type = MCS_SK_NAMED, .flags = fl, .sub = &s, .doc = doc_                       \
    }
#define A(n, fl, doc_)                                                                             \
    {                                                                                              \
        .name = n, .type = MCS_SK_ANY, .flags = fl, .doc = doc_                                    \
    }
#define D(n, doc_)                                                                                 \
    {                                                                                              \
        .name = n, .type = MCS_SK_DISC, .doc = doc_                                                \
    }
#define END                                                                                        \
    {                                                                                              \
        .name = 0                                                                                  \
    }

enum {
    REQ = MCS_SK_REQ,
    GT = MCS_SK_GT,
    GE = MCS_SK_GE,
    LT = MCS_SK_LT,
    LE = MCS_SK_LE,
    NZ = MCS_SK_NONZERO,
    UNIQ = MCS_SK_UNIQUE,
    NE = MCS_SK_NONEMPTY,
};

#define LEN MCS_DIM_LENGTH
#define NONE MCS_DIM_NONE
#define ANG MCS_DIM_ANGLE
#define VEL MCS_DIM_VELOCITY
#define FRC MCS_DIM_FORCE
#define PRS MCS_DIM_PRESSURE
#define BODY MCS_REF_BODY
#define BODY_G MCS_REF_BODY_OR_GROUND
#define CHR MCS_REF_CHAR
#define PART MCS_REF_FE_PART
#define CHOICES_AXIS "x|y|z"

/* ---- simulation, environment ---- */

static const mcs_skey sim_keys[] = {
    /* required, except beside a whole keyword deck (fe.keyword): its *CONTROL_TERMINATION */
    Q("end_time", MCS_DIM_TIME, GT, 0, 0, "simulated duration [s]"),
    /* stage 1: the fixed step; FE stages: an upper bound on the stable (Courant) step */
    Q("time_step", MCS_DIM_TIME, GT, 0, 0, "time step [s]"),
    /* FE: safety factor on the Courant step (LS-DYNA TSSFAC, default 0.9) */
    Q("time_step_scale", NONE, GT | LE, 0, 1, "FE time step scale factor"),
    Q("output_rate", MCS_DIM_FREQ, GT, 0, 0, "sampling rate of the results [Hz]"),
    /* FE parts: /stageN/fields at their own rate (stage 1: every k-th output row, k = round(
     * output_rate / field_rate)); default 200 frames per run (fe_scn_field_rate) */
    Q("field_rate", MCS_DIM_FREQ, GT, 0, 0,
      "sampling rate of the FE displacement fields [Hz] (default 200 frames per run, at most "
      "output_rate)"),
    END,
};
static const mcs_smap sim_map = {
    .what = "simulation block", .keys = sim_keys, .check = mcs_rule_simulation};

static const mcs_skey ground_keys[] = {
    Q("height", LEN, REQ, 0, 0, "ground height z [m]"),
    Q("friction", NONE, GE, 0, 0, "Coulomb friction coefficient"),
    R("characteristic", CHR, 0, "contact characteristic of the ground"),
    END,
};
static const mcs_smap ground_map = {.what = "ground", .keys = ground_keys};

static const mcs_skey env_keys[] = {
    /* magnitude, acting along -z (DESIGN: z up); "1 g" reads as 9.80665 m/s^2 */
    Q("gravity", MCS_DIM_ACCEL, GE, 0, 0, "gravitational acceleration [m/s^2]"),
    M("ground", ground_map, 0, "the ground plane"),
    END,
};
static const mcs_smap env_map = {.what = "environment block", .keys = env_keys};

/* ---- characteristics: force vs. penetration (default) or moment vs. angle ----
 * The unloading rule of the hysteresis element (core/mcs_hysteresis.h) follows from the keys:
 * neither unloading nor unloading_slope: elastic; unloading_slope: a line from the maximum;
 * unloading: the curve, scaled to the maximum; both: the line down to the (absolute) unloading
 * curve, then along it (paper Fig. 7). elastic_limit: no permanent set below it. */

static const mcs_skey char_force_keys[] = {
    C("loading", LEN, FRC, 2, REQ, 0, "loading curve [[penetration m, force N], ...]"),
    C("unloading", LEN, FRC, 2, 0, 0, "unloading curve (null: elastic)"),
    Q("unloading_slope", MCS_DIM_STIFFNESS, GT, 0, 0, "unloading slope from the maximum [N/m]"),
    Q("elastic_limit", LEN, GE, 0, 0, "penetration below which unloading is elastic [m]"),
    Q("damping", MCS_DIM_DAMPING, GE, 0, 0, "viscous damping [N s/m]"),
    END,
};
static const mcs_smap char_force = {.what = "force characteristic", .keys = char_force_keys};

static const mcs_skey char_moment_keys[] = {
    C("loading", ANG, MCS_DIM_MOMENT, 2, REQ, 0, "loading curve [[angle rad, moment N m], ...]"),
    C("unloading", ANG, MCS_DIM_MOMENT, 2, 0, 0, "unloading curve (null: elastic)"),
    Q("unloading_slope", MCS_DIM_ROTSTIFF, GT, 0, 0, "unloading slope [N m/rad]"),
    Q("elastic_limit", ANG, GE, 0, 0, "angle below which unloading is elastic [rad]"),
    Q("damping", MCS_DIM_ROTDAMP, GE, 0, 0, "viscous damping [N m s/rad]"),
    END,
};
static const mcs_smap char_moment = {.what = "moment characteristic", .keys = char_moment_keys};

static const mcs_svariant char_variants[] = {{"force", &char_force}, {"moment", &char_moment}, {0}};

static const mcs_skey char_keys[] = {
    D("type", "force (default) or moment"),
    Q("friction", NONE, GE, 0, 0, "Coulomb friction coefficient"),
    END,
};
static const mcs_smap char_map = {.what = "characteristic",
                                  .keys = char_keys,
                                  .disc = "type",
                                  .variants = char_variants,
                                  .disc_default = "force"};

/* ---- bodies and their surfaces ---- */

static const mcs_skey ellipsoid_keys[] = {
    V("center", LEN, 3, 3, REQ, 0, "centre in the body frame [m]"),
    V("semi_axes", LEN, 3, 3, REQ | GT, 0, "semi-axes [m]"),
    /* MADYMO hyper-ellipsoid degree: 2 is an ellipsoid, higher is boxier */
    I("degree", GE | LE, 2, 16, "hyper-ellipsoid degree"),
    V("orientation", ANG, 3, 3, 0, 0, "roll, pitch, yaw in the body frame [rad]"),
    END,
};
static const mcs_skey plane_keys[] = {
    V("point", LEN, 3, 3, REQ, 0, "a point of the plane [m]"),
    V("normal", NONE, 3, 3, REQ | NZ, 0, "outward normal"),
    V("size", LEN, 2, 2, GT, 0, "extent of a finite plane [m]"),
    END,
};
static const mcs_skey cylinder_keys[] = {
    V("center", LEN, 3, 3, REQ, 0, "centre [m]"),
    Q("radius", LEN, REQ | GT, 0, 0, "radius [m]"),
    Q("length", LEN, REQ | GT, 0, 0, "length [m]"),
    V("axis", NONE, 3, 3, REQ | NZ, 0, "axis direction"),
    END,
};
/* a triangle mesh in the body frame: inline, or an OBJ file (core/mcs_obj.h); checked by
 * mcs_rule_facet (one of the two forms, indices in range, lengths converted) */
static const mcs_skey facet_keys[] = {
    A("vertices", 0, "points [[x, y, z], ...] in the body frame [m]"),
    A("triangles", 0, "[[i, j, k], ...] 0-based, counter-clockwise seen from outside"),
    S("file", NE, "OBJ file (v and f lines), relative to this YAML file"),
    END,
};
static const mcs_smap ellipsoid_map = {.what = "ellipsoid surface", .keys = ellipsoid_keys};
static const mcs_smap plane_map = {.what = "plane surface", .keys = plane_keys};
static const mcs_smap cylinder_map = {.what = "cylinder surface", .keys = cylinder_keys};
static const mcs_smap facet_map = {
    .what = "facet surface", .keys = facet_keys, .check = mcs_rule_facet};
static const mcs_svariant surface_variants[] = {{"ellipsoid", &ellipsoid_map},
                                                {"plane", &plane_map},
                                                {"cylinder", &cylinder_map},
                                                {"facet", &facet_map},
                                                {0}};

static const mcs_skey surface_keys[] = {
    D("type", "surface type"),
    S("name", 0, "surface name"),
    R("characteristic", CHR, 0, "contact characteristic"),
    END,
};
static const mcs_smap surface_map = {
    .what = "surface", .keys = surface_keys, .disc = "type", .variants = surface_variants};

static const mcs_skey body_keys[] = {
    S("name", REQ | UNIQ | NE, "body name"),
    Q("mass", MCS_DIM_MASS, REQ | GT, 0, 0, "mass [kg]"),
    /* principal Ixx Iyy Izz, or Ixx Iyy Izz Ixy Iyz Ixz (MADYMO order), about the centre of mass */
    V("inertia", MCS_DIM_INERTIA, 3, 6, REQ, 0, "inertia [kg m^2] (3 or 6 values)"),
    V("position", LEN, 3, 3, REQ, 0, "centre of mass in the world [m]"),
    /* 3 values: roll, pitch, yaw (z-y-x Cardan, ISO 8855); 4: quaternion w, x, y, z */
    V("orientation", ANG, 3, 4, 0, 0, "orientation"),
    V("velocity", VEL, 3, 3, REQ, 0, "initial velocity [m/s]"),
    V("angular_velocity", MCS_DIM_ANGVEL, 3, 3, 0, 0, "initial angular velocity [rad/s]"),
    L("surfaces", surface_map, 0, "contact surfaces"),
    END,
};
static const mcs_smap body_map = {.what = "body", .keys = body_keys, .check = mcs_rule_body};

static const mcs_skey contact_keys[] = {
    S("name", UNIQ, "contact name"),
    R("a", BODY_G, REQ, "first body (or ground)"),
    R("b", BODY_G, REQ, "second body (or ground)"),
    R("characteristic", CHR, REQ, "contact characteristic"),
    Q("friction", NONE, GE, 0, 0, "friction coefficient (overrides the characteristic's)"),
    END,
};
static const mcs_smap contact_map = {
    .what = "contact", .keys = contact_keys, .check = mcs_rule_pair};

/* ---- joints ---- */

/* range: stops beyond [min, max] of the joint position (stage 1 makes them stiff springs) */
static const mcs_skey revolute_keys[] = {
    V("axis", NONE, 3, 3, REQ | NZ, 0, "rotation axis (world frame)"),
    V("range", ANG, 2, 2, 0, 0, "stops [min, max] [rad]"),
    /* docs/joints.md: the restraint's zero at `neutral`; `preload` added to it (held by the
     * negative side's characteristic, e.g. a top-out stop) */
    Q("neutral", ANG, 0, 0, 0, "angle of the restraint's zero, from the initial angle [rad]"),
    Q("preload", MCS_DIM_MOMENT, 0, 0, 0, "restraint preload [N m]"),
    END,
};
static const mcs_skey universal_keys[] = {
    V("axis", NONE, 3, 3, REQ | NZ, 0, "first axis"),
    V("axis2", NONE, 3, 3, REQ | NZ, 0, "second axis"),
    /* docs/joints.md: per axis (axis, axis2) the restraint's zero and a constant preload */
    V("neutral", ANG, 2, 2, 0, 0, "restraint zero per axis (axis, axis2) [rad]"),
    V("preload", MCS_DIM_MOMENT, 2, 2, 0, 0, "restraint preload per axis (axis, axis2) [N m]"),
    END,
};
/* docs/joints.md: per restraint axis (the parent's x, y, z) on the rotation vector */
static const mcs_skey spherical_keys[] = {
    V("neutral", ANG, 3, 3, 0, 0, "restraint zero per axis (rotation vector x, y, z) [rad]"),
    V("preload", MCS_DIM_MOMENT, 3, 3, 0, 0, "restraint preload per axis (x, y, z) [N m]"),
    END,
};
static const mcs_skey translational_keys[] = {
    V("axis", NONE, 3, 3, REQ | NZ, 0, "sliding axis"),
    V("range", LEN, 2, 2, 0, 0, "stops [min, max] [m]"),
    Q("neutral", LEN, 0, 0, 0, "position of the restraint's zero, from the initial one [m]"),
    Q("preload", FRC, 0, 0, 0, "restraint preload [N]"),
    END,
};
static const mcs_skey no_keys[] = {END};
static const mcs_smap revolute_map = {
    .what = "revolute joint", .keys = revolute_keys, .check = mcs_rule_range};
static const mcs_smap universal_map = {.what = "universal joint", .keys = universal_keys};
static const mcs_smap translational_map = {
    .what = "translational joint", .keys = translational_keys, .check = mcs_rule_range};
static const mcs_smap spherical_map = {.what = "spherical joint", .keys = spherical_keys};
static const mcs_smap fixed_map = {
    .what = "fixed joint", .keys = no_keys, .check = mcs_rule_fixed_joint};
static const mcs_svariant joint_variants[] = {
    {"revolute", &revolute_map},   {"spherical", &spherical_map},
    {"universal", &universal_map}, {"translational", &translational_map},
    {"fixed", &fixed_map},         {0}};

static const mcs_skey joint_keys[] = {
    S("name", UNIQ | NE, "joint name"),
    D("type", "joint type"),
    R("parent", BODY_G, REQ, "parent body (or ground)"),
    R("child", BODY, REQ, "child body"),
    V("anchor", LEN, 3, 3, REQ, 0, "joint point in the world [m]"),
    /* the same characteristic acts in both directions (moment for rotations, force for travel)
     * unless restraint_negative gives the negative direction's own */
    R("restraint", CHR, 0, "restraint characteristic"),
    R("restraint_negative", CHR, 0, "restraint characteristic for negative deflection"),
    END,
};
static const mcs_smap joint_map = {.what = "joint",
                                   .keys = joint_keys,
                                   .disc = "type",
                                   .variants = joint_variants,
                                   .check = mcs_rule_joint};

/* ---- attachments (breakable spring-dampers), sensors, impact ---- */

static const mcs_skey attachment_keys[] = {
    S("name", UNIQ | NE, "attachment name"),
    R("a", BODY_G, REQ, "first body"),
    R("b", BODY_G, REQ, "second body"),
    V("point_a", LEN, 3, 3, REQ, 0, "attachment point on a (body frame) [m]"),
    V("point_b", LEN, 3, 3, REQ, 0, "attachment point on b (body frame) [m]"),
    Q("stiffness", MCS_DIM_STIFFNESS, REQ | GT, 0, 0, "spring stiffness [N/m]"),
    Q("damping", MCS_DIM_DAMPING, GE, 0, 0, "damping [N s/m]"),
    Q("failure_force", FRC, REQ | GT, 0, 0, "force at which it breaks for good [N]"),
    /* absent: at rest in the initial posture; 0: the two points are pulled together */
    Q("length", LEN, GE, 0, 0, "free length [m]"),
    END,
};
static const mcs_smap attachment_map = {
    .what = "attachment", .keys = attachment_keys, .check = mcs_rule_pair};

static const mcs_skey sensor_keys[] = {
    S("name", REQ | UNIQ | NE, "channel name"),
    R("body", BODY, REQ, "body carrying the sensor"),
    E("type", "acceleration|velocity|displacement|angular_velocity|angular_acceleration|load_cell",
      REQ, "quantity measured"),
    V("point", LEN, 3, 3, 0, 0, "sensor point in the body frame [m] (default: centre of mass)"),
    /* SAE J211 channel frequency class; 0 = unfiltered */
    I("cfc", GE, 0, 0, "channel frequency class (0, 60, 180, 600, 1000)"),
    /* load_cell (stage1_mb/mb_loadcell.c): the force and moment the joint exerts on `body`
     * (J211: the part above the cell), about `point` of `frame`, on the frame's axes */
    S("joint", 0, "load_cell: joint whose load is measured"),
    R("frame", BODY, 0, "load_cell: body carrying the cell's point and axes (default: body)"),
    V("orientation", ANG, 3, 3, 0, 0, "load_cell: cell axes in the frame body: roll, pitch, yaw"),
    END,
};
static const mcs_smap sensor_map = {
    .what = "sensor", .keys = sensor_keys, .check = mcs_rule_sensor};

/* named points on bodies (seat H-point, grips, pegs; the rider's H-point, hands, feet) */
static const mcs_skey mount_keys[] = {
    S("name", REQ | UNIQ | NE, "mount point name"),
    R("body", BODY, REQ, "body carrying the point"),
    V("point", LEN, 3, 3, REQ, 0, "point in the body frame [m]"),
    END,
};
static const mcs_smap mount_map = {.what = "mount point", .keys = mount_keys};

/* seating the rider on the motorcycle (stage1_mb/mb_position.c, docs/rider.md); the mount
 * points seat_h_point, grip_l/r, peg_l/r (motorcycle) and rider_h_point, rider_grip_l/r,
 * rider_peg_l/r (rider) must exist */
static const mcs_skey rider_keys[] = {
    Q("torso_lean", ANG, GE | LT, 0, 1.5707963267948966, "forward lean of the torso [rad]"),
    Q("head_pitch", ANG, 0, 0, 0, "forward pitch of the head, 0 = upright [rad]"),
    Q("foot_pitch", ANG, 0, 0, 0, "toes-down pitch of the feet [rad]"),
    B("attachments", 0, "create the breakable pelvis-seat, hand-grip, foot-peg attachments"),
    Q("seat_failure_force", FRC, GT, 0, 0, "pelvis-seat attachment failure force [N]"),
    Q("grip_failure_force", FRC, GT, 0, 0, "hand-grip attachment failure force [N]"),
    Q("peg_failure_force", FRC, GT, 0, 0, "foot-peg attachment failure force [N]"),
    Q("attachment_stiffness", MCS_DIM_STIFFNESS, GT, 0, 0, "attachment stiffness [N/m]"),
    Q("attachment_damping", MCS_DIM_DAMPING, GE, 0, 0, "attachment damping [N s/m]"),
    E("dummy", "50th_male|5th_female|95th_male", 0,
      "Hybrid III size the rider model represents (default 50th_male): selects the Nij "
      "intercepts and injury limits of `mcrash injury` (docs/rider.md \"Sizes\")"),
    END,
};
static const mcs_smap rider_map = {.what = "rider block", .keys = rider_keys};

/* the impact configuration (stage1_mb/mb_impact.c, docs/scenario_keys.md "impact"): the
 * motorcycle group is rotated to its heading, translated so that its contact point meets the
 * opponent's (in plan view, less the gap), and both groups get their speeds (wheels rolling) */
static const mcs_skey impact_keys[] = {
    S("code", 0, "ISO 13232 impact configuration code, e.g. 413-0/13.4"),
    S("motorcycle", 0, "motorcycle model (a label)"),
    S("opponent", 0, "opponent model (a label)"),
    /* from the opponent's heading to the motorcycle's, counter-clockwise seen from above */
    Q("heading_angle", ANG, 0, 0, 0,
      "motorcycle heading from the opponent's, counter-clockwise from above [rad]"),
    Q("motorcycle_speed", VEL, GE, 0, 0, "motorcycle speed along its heading [m/s]"),
    Q("opponent_speed", VEL, GE, 0, 0, "opponent speed along its heading [m/s]"),
    V("motorcycle_contact", LEN, 3, 3, 0, 0, "contact point, motorcycle model frame [m]"),
    V("opponent_contact", LEN, 3, 3, 0, 0, "contact point on the opponent, world [m]"),
    Q("roll_angle", ANG, 0, 0, 0, "motorcycle roll (lean) angle, + = right [rad]"),
    V("opponent_heading", NONE, 3, 3, NZ, 0, "opponent's forward direction, world (default x)"),
    Q("initial_gap", LEN, GE, 0, 0, "distance to contact along the motorcycle heading [m]"),
    /* body names, or patterns with * and ? (default ["moto_*", "rider_*"]) */
    A("motorcycle_bodies", 0, "bodies of the motorcycle group (names or patterns)"),
    /* default: every body outside the motorcycle group */
    A("opponent_bodies", 0, "bodies of the opponent group (names or patterns)"),
    END,
};
static const mcs_smap impact_map = {
    .what = "impact block", .keys = impact_keys, .check = mcs_rule_impact};

/* ---- fe: meshes ---- */

#define MESH_COMMON V("origin", LEN, 3, 3, 0, 0, "translation of the generated mesh [m]")

static const mcs_skey square_tube_keys[] = {
    Q("side", LEN, REQ | GT, 0, 0, "side of the square section (mid-surface) [m]"),
    Q("length", LEN, REQ | GT, 0, 0, "tube length [m]"),
    Q("element_size", LEN, REQ | GT, 0, 0, "element edge length [m]"),
    E("axis", CHOICES_AXIS, 0, "tube axis (default z)"),
    MESH_COMMON,
    END,
};
static const mcs_skey round_tube_keys[] = {
    Q("diameter", LEN, REQ | GT, 0, 0, "mid-surface diameter [m]"),
    Q("length", LEN, REQ | GT, 0, 0, "length [m]"),
    Q("element_size", LEN, REQ | GT, 0, 0, "element edge length [m]"),
    E("axis", CHOICES_AXIS, 0, "axis (default z)"),
    MESH_COMMON,
    END,
};
static const mcs_skey plate_keys[] = {
    V("size", LEN, 2, 2, REQ | GT, 0, "plate size [m]"),
    IS("divisions", 2, 2, GE, 1, "elements along each side"),
    Q("element_size", LEN, GT, 0, 0, "element edge length [m]"),
    E("axis", CHOICES_AXIS, 0, "plate normal (default z)"),
    V("origin", LEN, 3, 3, 0, 0, "min corner [m]"),
    END,
};
static const mcs_skey box_keys[] = {
    V("size", LEN, 3, 3, REQ | GT, 0, "box size [m]"),
    IS("divisions", 3, 3, REQ | GE, 1, "hex8 elements along x, y, z"),
    V("origin", LEN, 3, 3, 0, 0, "min corner [m]"),
    END,
};
static const mcs_skey sphere_keys[] = {
    Q("radius", LEN, REQ | GT, 0, 0, "radius [m]"),
    Q("element_size", LEN, REQ | GT, 0, 0, "element edge length [m]"),
    MESH_COMMON,
    END,
};
/* a flat (2D-design) gas bag: two panels sewn at their edges (fe/model/fe_mesh_shell.c) */
static const mcs_skey flat_bag_keys[] = {
    V("size", LEN, 2, 2, REQ | GT, 0, "panel size along the two in-plane axes [m]"),
    Q("gap", LEN, REQ | GT, 0, 0, "distance of the two panels inside the seam [m]"),
    Q("element_size", LEN, REQ | GT, 0, 0, "element edge length [m]"),
    E("axis", CHOICES_AXIS, 0, "panel normal (default z)"),
    V("origin", LEN, 3, 3, 0, 0, "centre of the bag [m]"),
    END,
};
static const mcs_skey line_keys[] = {
    V("origin", LEN, 3, 3, REQ, 0, "start point [m]"),
    V("end", LEN, 3, 3, REQ, 0, "end point [m]"),
    I("divisions", REQ | GE, 1, 0, "truss elements along the line"),
    END,
};
/* FE parts on a body's surface at its pose of t = 0 (fe/scn/fe_scn_pad.h): foam_pad, a layer of
 * solids (hexahedra over a patch of an ellipsoid, its inner face on the surface, the outer one
 * `thickness` out along the normal; prisms over a whole facet surface, along the vertex
 * normals); surface_shell, shells on the same patch or facets. The ellipsoid patch in its
 * frame: p = (a cos lat cos lon, b cos lat sin lon, c sin lat) */
#define SURFACE_MESH_KEYS                                                                          \
    R("body", BODY, REQ, "body whose surface the part covers"),                                    \
        S("surface", REQ | NE, "name of the body's ellipsoid or facet surface"),                   \
        Q("element_size", LEN, GT, 0, 0, "ellipsoid: element edge length on the surface [m]"),     \
        V("longitude", ANG, 2, 2, 0, 0, "ellipsoid: patch azimuth range about its z axis [rad]"),  \
        V("latitude", ANG, 2, 2, 0, 0,                                                             \
          "ellipsoid: patch elevation range from its x-y plane, poles out [rad]")
static const mcs_skey foam_pad_keys[] = {
    SURFACE_MESH_KEYS,
    Q("thickness", LEN, REQ | GT, 0, 0, "pad thickness, along the surface normal [m]"),
    I("layers", GE | LE, 1, 16, "elements through the thickness (default 1)"),
    END,
};
static const mcs_skey surface_shell_keys[] = {SURFACE_MESH_KEYS, END};
/* a mesh from a file: a keyword deck's part, or a part a run wrote to a results file
 * (fe/scn/fe_scn_from.c, docs/exchange.md); one of keyword / from (mcs_rule_mesh_file) */
static const mcs_skey keyword_keys[] = {
    /* an LS-DYNA keyword file, relative to the YAML file that names it */
    S("keyword", NE, "LS-DYNA keyword file (or give generate: or from:)"),
    I("part", GE, 1, 0, "part ID in the keyword file (with keyword:)"),
    /* FILE.h5:/stageN/mesh/<part>, the file relative to the YAML file that names it */
    S("from", NE, "a part's mesh in a results file: FILE.h5:/stageN/mesh/<part>"),
    A("at", 0, "with from: the deformed shape at this time [s], or final (default: reference)"),
    /* keyword decks carry no units: LENGTH-TIME-MASS of the deck (docs/keyword.md) */
    E("units", "m-s-kg|mm-s-t|mm-ms-kg|mm-ms-g|cm-s-g|cm-us-g", 0,
      "unit system of the deck (default m-s-kg, SI)"),
    E("unknown_keywords", "warn|error", 0, "keywords outside the subset (default warn)"),
    END,
};
static const mcs_smap square_tube_map = {.what = "square_tube mesh", .keys = square_tube_keys};
static const mcs_smap circular_tube_map = {.what = "circular_tube mesh", .keys = round_tube_keys};
static const mcs_skey cylinder_shell_keys[] = {
    Q("diameter", LEN, REQ | GT, 0, 0, "mid-surface diameter [m]"),
    Q("length", LEN, REQ | GT, 0, 0, "length [m]"),
    Q("element_size", LEN, REQ | GT, 0, 0, "element edge length [m]"),
    E("axis", CHOICES_AXIS, 0, "axis (default z)"),
    B("closed", 0, "add flat end caps: a closed surface (default false)"),
    V("origin", LEN, 3, 3, 0, 0, "centre of the first end [m]"),
    END,
};
static const mcs_smap cylinder_shell_map = {.what = "cylinder_shell mesh",
                                            .keys = cylinder_shell_keys};
static const mcs_smap plate_map = {
    .what = "plate mesh", .keys = plate_keys, .check = mcs_rule_plate};
static const mcs_smap box_map = {.what = "box mesh", .keys = box_keys};
static const mcs_smap sphere_shell_map = {.what = "sphere_shell mesh", .keys = sphere_keys};
static const mcs_smap line_map = {.what = "line mesh", .keys = line_keys};
static const mcs_smap flat_bag_map = {.what = "flat_bag mesh", .keys = flat_bag_keys};
static const mcs_smap keyword_map = {
    .what = "keyword or results mesh", .keys = keyword_keys, .check = mcs_rule_mesh_file};
/* the parametric FE motorcycle (stage3_fe/s3_moto.h): parts <name>_frame, ... from a stage-1
 * motorcycle model; its sections and materials are its own */
static const mcs_skey motorcycle_keys[] = {
    /* relative to the YAML file that names it (scenarios/models/motorcycles/sport_208kg.yaml) */
    S("model", REQ | NE, "stage-1 motorcycle model file (bodies, joints, characteristics)"),
    Q("element_size", LEN, REQ | GT, 0, 0, "target element edge (coarse 0.04, fine 0.01) [m]"),
    END,
};
static const mcs_smap motorcycle_map = {.what = "motorcycle mesh", .keys = motorcycle_keys};
/* the sedan's side structure in FE (stage3_fe/s3_sedan.h): parts <name>_door_outer, ... and
 * the rigid rest <name>_body from a stage-1 sedan model; its sections and materials are its own */
static const mcs_skey sedan_side_keys[] = {
    /* relative to the YAML file that names it (scenarios/models/opponents/sedan_1668kg.yaml) */
    S("model", REQ | NE, "stage-1 sedan model file (bodies sedan, sedan_upper; side surfaces)"),
    Q("element_size", LEN, REQ | GT, 0, 0, "target element edge (coarse 0.05, fine 0.01) [m]"),
    END,
};
static const mcs_smap sedan_side_map = {.what = "sedan_side mesh", .keys = sedan_side_keys};
static const mcs_smap foam_pad_map = {
    .what = "foam_pad mesh", .keys = foam_pad_keys, .check = mcs_rule_surface_mesh};
static const mcs_smap surface_shell_map = {
    .what = "surface_shell mesh", .keys = surface_shell_keys, .check = mcs_rule_surface_mesh};
/* "(keyword)": chosen when generate: is absent, never by name */
static const mcs_svariant mesh_variants[] = {{"square_tube", &square_tube_map},
                                             {"circular_tube", &circular_tube_map},
                                             {"cylinder_shell", &cylinder_shell_map},
                                             {"plate", &plate_map},
                                             {"box", &box_map},
                                             {"sphere_shell", &sphere_shell_map},
                                             {"flat_bag", &flat_bag_map},
                                             {"line", &line_map},
                                             {"foam_pad", &foam_pad_map},
                                             {"surface_shell", &surface_shell_map},
                                             {"motorcycle", &motorcycle_map},
                                             {"sedan_side", &sedan_side_map},
                                             {"(keyword)", &keyword_map},
                                             {0}};
/* the initial metric method (fe/elem/fe_imm.c, docs/gasbag.md): membrane parts only */
static const mcs_skey mesh_initial_keys[] = {
    V("scale", NONE, 3, 3, REQ | GT, 0, "factors along x, y, z, each in (0, 1]"),
    V("about", LEN, 3, 3, 0, 0, "fixed point (default: the part's bounding-box middle) [m]"),
    END,
};
static const mcs_smap mesh_initial_map = {.what = "initial mesh", .keys = mesh_initial_keys};
static const mcs_skey mesh_keys[] = {
    D("generate", "mesh generator"),
    /* nodes start on a scaled copy of the mesh, which stays the elements' reference */
    M("initial", mesh_initial_map, 0, "start on a scaled copy (membranes: initial metric)"),
    END,
};
static const mcs_smap mesh_map = {.what = "mesh",
                                  .keys = mesh_keys,
                                  .disc = "generate",
                                  .variants = mesh_variants,
                                  .disc_default = "(keyword)"};

/* ---- fe: sections and materials ---- */

#define HOURGLASS                                                                                  \
    E("hourglass", "viscous|stiffness", 0, "hourglass control (default viscous)"),                 \
        Q("hourglass_coefficient", NONE, GE, 0, 0, "Q_hg (default 0.1 viscous, 0.05 stiffness)")

static const mcs_skey shell_keys[] = {
    Q("thickness", LEN, REQ | GT, 0, 0, "shell thickness [m]"),
    /* through-thickness points (LS-DYNA NIP); default 5 */
    I("integration_points", GE | LE, 1, 10, "through-thickness integration points"),
    Q("shear_factor", NONE, GT | LE, 0, 1, "transverse shear factor (default 5/6)"),
    HOURGLASS,
    END,
};
static const mcs_skey solid_keys[] = {
    HOURGLASS,
    /* hex8: one point + hourglass control (LS-DYNA ELFORM 1) or 2x2x2 Gauss, selective
     * reduced (fe/elem/fe_hex_full.c) */
    E("formulation", "one_point|full", 0, "hex integration (default one_point)"),
    END,
};
static const mcs_skey membrane_keys[] = {
    Q("thickness", LEN, REQ | GT, 0, 0, "membrane thickness [m]"),
    END,
};
static const mcs_skey truss_keys[] = {
    Q("area", MCS_DIM_AREA, REQ | GT, 0, 0, "cross-section area [m^2]"),
    B("tension_only", 0, "carries no compression (a cable)"),
    END,
};
static const mcs_smap shell_map = {.what = "shell section", .keys = shell_keys};
static const mcs_smap membrane_map = {.what = "membrane section", .keys = membrane_keys};
static const mcs_smap solid_map = {.what = "solid section", .keys = solid_keys};
static const mcs_smap truss_map = {.what = "truss section", .keys = truss_keys};
static const mcs_svariant section_variants[] = {{"shell", &shell_map},
                                                {"solid", &solid_map},
                                                {"membrane", &membrane_map},
                                                {"truss", &truss_map},
                                                {0}};
static const mcs_skey section_keys[] = {D("type", "section type"), END};
static const mcs_smap section_map = {
    .what = "section", .keys = section_keys, .disc = "type", .variants = section_variants};

#define ELASTIC_KEYS                                                                               \
    Q("youngs_modulus", PRS, REQ | GT, 0, 0, "Young's modulus [Pa]"),                              \
        Q("poisson", NONE, REQ | GT | LT, -1, 0.5, "Poisson's ratio")

static const mcs_skey elastic_keys[] = {ELASTIC_KEYS, END};
static const mcs_skey plastic_keys[] = {
    ELASTIC_KEYS,
    Q("yield_stress", PRS, REQ | GT, 0, 0, "initial yield stress [Pa]"),
    /* true stress vs. effective plastic strain (LS-DYNA *MAT_024 LCSS) */
    C("hardening", NONE, PRS, 1, GE, 0, "hardening curve [[plastic strain, stress Pa], ...]"),
    Q("tangent_modulus", PRS, GE, 0, 0, "bilinear hardening modulus [Pa] (without a curve)"),
    Q("failure_strain", NONE, GT, 0, 0,
      "effective plastic strain that deletes an element (erosion; one-point hex, shell)"),
    /* strain-rate factor 1 + (rate/C)^(1/p) on the flow stress (mild steel: C 40.4/s, p 5) */
    Q("cowper_symonds_c", MCS_DIM_FREQ, GT, 0, 0, "Cowper-Symonds C [1/s]"),
    Q("cowper_symonds_p", NONE, GT, 0, 0, "Cowper-Symonds p"),
    END,
};
/* foam (fe/mat/fe_foam.c, in the spirit of LS-DYNA MAT_083 and MAT_057): nominal stress vs.
 * engineering strain per principal direction (Poisson 0), curves at several strain rates
 * interpolated in log rate, hysteretic unloading; give stress_strain or curves */
static const mcs_skey foam_curve_keys[] = {
    Q("rate", MCS_DIM_FREQ, REQ | GE, 0, 0, "engineering strain rate of the curve [1/s]"),
    C("points", NONE, PRS, 1, REQ | GE, 0, "[[strain, nominal stress Pa], ...]"),
    END,
};
static const mcs_smap foam_curve_map = {.what = "foam curve", .keys = foam_curve_keys};
static const mcs_skey foam_keys[] = {
    Q("youngs_modulus", PRS, REQ | GT, 0, 0, "modulus in tension [Pa]"),
    Q("poisson", NONE, GE | LE, 0, 0, "Poisson's ratio (0 only)"),
    C("stress_strain", NONE, PRS, 1, GE, 0, "one curve [[strain, nominal stress Pa], ...]"),
    L("curves", foam_curve_map, 0, "loading curves at increasing strain rates"),
    /* LS-DYNA *MAT_057 HU and SHAPE; 1 (default): no hysteresis */
    Q("hysteresis", NONE, GT | LE, 0, 1, "unloading factor HU (default 1: none)"),
    Q("shape", NONE, GT, 0, 0, "unloading shape exponent (default 1)"),
    Q("tension_cutoff", PRS, GT, 0, 0, "largest tensile stress [Pa] (default none)"),
    Q("damping", NONE, GE | LE, 0, 1, "viscous damping fraction"),
    END,
};
/* fabric (membranes): linear in the fibre frame, no compressive stress (docs/fe.md) */
static const mcs_skey fabric_keys[] = {
    ELASTIC_KEYS,
    Q("youngs_modulus_b", PRS, GT, 0, 0,
      "modulus along fibre b, the weft [Pa] (default isotropic)"),
    Q("shear_modulus", PRS, GT, 0, 0, "in-plane shear modulus [Pa] (default E/(2(1+nu)))"),
    V("direction", NONE, 3, 3, NZ, 0, "fibre a (warp) direction, projected on each element"),
    Q("damping", NONE, GE | LE, 0, 1, "stiffness damping, fraction of critical (top frequency)"),
    END,
};
static const mcs_skey rigid_keys[] = {ELASTIC_KEYS, END};
/* nonstructural (LS-DYNA *MAT_NULL): mass and a contact surface, no stress, no element step; for parts
 * carried rigidly by a stage-1 body (the stage-2 cockpit panels), whose elements cannot strain */
static const mcs_skey null_keys[] = {END};
static const mcs_smap elastic_map = {.what = "elastic material", .keys = elastic_keys};
static const mcs_smap plastic_map = {
    .what = "elastic_plastic material", .keys = plastic_keys, .check = mcs_rule_plastic};
static const mcs_smap foam_map = {.what = "foam material", .keys = foam_keys};
static const mcs_smap fabric_map = {.what = "fabric material", .keys = fabric_keys};
static const mcs_smap rigid_map = {.what = "rigid material", .keys = rigid_keys};
static const mcs_smap null_map = {.what = "nonstructural material", .keys = null_keys};
static const mcs_svariant material_variants[] = {
    {"elastic", &elastic_map}, {"elastic_plastic", &plastic_map},
    {"foam", &foam_map},       {"fabric", &fabric_map},
    {"rigid", &rigid_map},     {"nonstructural", &null_map},
    {0}};
static const mcs_skey material_keys[] = {
    D("model", "material model"),
    Q("density", MCS_DIM_DENSITY, REQ | GT, 0, 0, "density [kg/m^3]"),
    END,
};
static const mcs_smap material_map = {
    .what = "material", .keys = material_keys, .disc = "model", .variants = material_variants};

/* ---- fe: parts, boundary, rigid walls, contacts ---- */

static const mcs_skey attach_keys[] = {
    R("body", BODY, REQ, "stage-1 body carrying the nodes"),
    /* surface: the nodes on one of the body's ellipsoid or facet surfaces (within 0.1 mm; a
     * foam_pad's inner face, a surface_shell, a keyword mesh modelled on the body),
     * fe/scn/fe_scn_pad.c */
    E("where", "x_min|x_max|y_min|y_max|z_min|z_max|all|surface", REQ,
      "which nodes of the part (as boundary, or those on the body's surfaces): they move "
      "rigidly with the body"),
    END,
};
static const mcs_smap attach_map = {.what = "FE part attachment", .keys = attach_keys};

static const mcs_skey part_keys[] = {
    S("name", REQ | UNIQ | NE, "part name"),
    M("mesh", mesh_map, REQ, "mesh (generate: or keyword:)"),
    /* required, except with a keyword mesh: then the deck's *SECTION / *MAT (mcs_rule_fe_part) */
    M("section", section_map, 0, "section"),
    M("material", material_map, 0, "material"),
    /* one material for several parts (the cockpit pads take the leg protectors'), no copy */
    R("material_from", PART, 0, "the material of this other FE part (instead of material)"),
    V("initial_velocity", VEL, 3, 3, 0, 0, "initial velocity [m/s]"),
    M("attach", attach_map, 0, "nodes carried by a stage-1 body (stage1_mb/mb_couple.c)"),
    END,
};
static const mcs_smap part_map = {.what = "FE part", .keys = part_keys, .check = mcs_rule_fe_part};

static const mcs_skey boundary_keys[] = {
    R("part", PART, REQ, "FE part"),
    E("where", "x_min|x_max|y_min|y_max|z_min|z_max|all", REQ, "which nodes of the part"),
    /* degrees of freedom held: all = translations and rotations */
    E("fix", "all|translations|rotations|x|y|z|xy|yz|xz", 0, "fixed degrees of freedom"),
    Q("tolerance", LEN, GE, 0, 0, "distance from the extreme that still counts [m]"),
    V("velocity", VEL, 3, 3, 0, 0, "prescribed velocity of the fixed x, y, z [m/s]"),
    END,
};
static const mcs_smap boundary_map = {.what = "boundary condition", .keys = boundary_keys};

static const mcs_skey load_keys[] = {
    R("part", PART, REQ, "FE part"),
    E("where", "x_min|x_max|y_min|y_max|z_min|z_max|all", REQ, "which nodes (split equally)"),
    V("force", FRC, 3, 3, REQ, 0, "total force at scale 1 [N]"),
    C("curve", MCS_DIM_TIME, NONE, 1, 0, 0, "[[time s, scale], ...] (default constant 1)"),
    END,
};
static const mcs_smap load_map = {.what = "load", .keys = load_keys};

/* a rigid wall moved by a curve (fe/step/fe_wall_motion.c; LS-DYNA
 * *BOUNDARY_PRESCRIBED_MOTION_RIGIDWALL VAD 0, 1, 2): along `direction` (default the normal),
 * on top of `velocity` t (the initial velocity of an acceleration curve) */
static const mcs_skey wall_vel_keys[] = {
    C("curve", MCS_DIM_TIME, VEL, 1, REQ, 0, "[[time s, velocity m/s], ...]"), END};
static const mcs_skey wall_acc_keys[] = {
    C("curve", MCS_DIM_TIME, MCS_DIM_ACCEL, 1, REQ, 0, "[[time s, acceleration m/s^2], ...]"), END};
static const mcs_skey wall_disp_keys[] = {
    C("curve", MCS_DIM_TIME, LEN, 1, REQ, 0, "[[time s, displacement m], ...]"), END};
static const mcs_smap wall_vel_map = {.what = "wall velocity curve", .keys = wall_vel_keys};
static const mcs_smap wall_acc_map = {.what = "wall acceleration curve", .keys = wall_acc_keys};
static const mcs_smap wall_disp_map = {.what = "wall displacement curve", .keys = wall_disp_keys};
static const mcs_svariant wall_motion_variants[] = {{"velocity", &wall_vel_map},
                                                    {"acceleration", &wall_acc_map},
                                                    {"displacement", &wall_disp_map},
                                                    {0}};
static const mcs_skey wall_motion_keys[] = {
    D("type", "what the curve gives"),
    V("direction", NONE, 3, 3, NZ, 0, "direction of the motion (default the wall's normal)"),
    END,
};
static const mcs_smap wall_motion_map = {.what = "wall motion",
                                         .keys = wall_motion_keys,
                                         .disc = "type",
                                         .variants = wall_motion_variants};

static const mcs_skey wall_keys[] = {
    S("name", REQ | UNIQ | NE, "wall name"),
    V("point", LEN, 3, 3, REQ, 0, "a point of the wall [m]"),
    V("normal", NONE, 3, 3, REQ | NZ, 0, "normal, pointing to the side it stops"),
    V("velocity", VEL, 3, 3, 0, 0, "prescribed velocity [m/s] (default fixed)"),
    Q("friction", NONE, GE, 0, 0, "Coulomb coefficient (>= 1: no sliding; LS-DYNA FRIC)"),
    V("size", LEN, 2, 2, GT, 0, "extent of a finite wall [m] (default infinite)"),
    E("method", "kinematic|penalty", 0, "contact treatment (default kinematic)"),
    Q("penalty_scale", NONE, GT, 0, 0, "penalty stiffness scale (default 0.1)"),
    RS("parts", PART, 1, 0, "parts it stops (default every part)"),
    Q("mass", MCS_DIM_MASS, GT, 0, 0,
      "a free wall of this mass moving along its normal, velocity = "
      "its initial velocity [kg]"),
    M("motion", wall_motion_map, 0, "motion from a curve, on top of velocity t"),
    END,
};
static const mcs_smap wall_map = {.what = "rigid wall", .keys = wall_keys};

static const mcs_skey single_surface_keys[] = {
    RS("parts", PART, 1, REQ, "parts in contact with themselves and each other"),
    END,
};
static const mcs_skey two_surface_keys[] = {
    RS("a", PART, 1, REQ, "first side (slave, LS-DYNA terms)"),
    RS("b", PART, 1, REQ, "second side (master)"),
    END,
};
static const mcs_skey slave_master_keys[] = {
    RS("slave", PART, 1, REQ, "slave side (its nodes against the master segments)"),
    RS("master", PART, 1, REQ, "master side (symmetric: its nodes against the slave segments too)"),
    END,
};
/* the bodies' surface compliance in series with the penalty, per FE node: force = stress(delta_b)
 * x the node's tributary area (MADYMO's MB-FE contact characteristic; docs/contracts.md "Soft
 * body surfaces in bodies contacts"); the unloading keys as a characteristic's, on stress */
static const mcs_skey body_law_keys[] = {
    C("stress", LEN, MCS_DIM_PRESSURE, 2, REQ, 0,
      "stress vs. penetration into the body [[m, Pa], ...] (2 to 32 points)"),
    Q("unloading_slope", MCS_D(-2, 1, -2, 0, 0), GT, 0, 0,
      "unloading slope from the maximum [Pa/m] (none: elastic, along the curve)"),
    Q("elastic_limit", LEN, GE, 0, 0, "penetration below which unloading is elastic [m]"),
    END,
};
static const mcs_smap body_law_map = {.what = "body characteristic", .keys = body_law_keys};
/* FE nodes against stage-1 bodies' surfaces (stage1_mb/mb_couple_contact.c) */
static const mcs_skey bodies_contact_keys[] = {
    RS("parts", PART, 1, REQ, "FE parts whose nodes meet the bodies"),
    RS("bodies", BODY, 1, REQ, "stage-1 bodies whose ellipsoid and facet surfaces they meet"),
    /* inline, or the name of one of fe.body_characteristics (or stage2.fe's, in stage2.fe) */
    {.name = "body_characteristic",
     .type = MCS_SK_MAP,
     .sub = &body_law_map,
     .ref = MCS_REF_BODY_LAW,
     .doc = "the bodies' surface compliance in series, or its name in fe.body_characteristics "
            "(ellipsoids only; none: rigid surfaces)"},
    END,
};
static const mcs_smap bodies_contact_map = {.what = "bodies contact", .keys = bodies_contact_keys};
static const mcs_smap single_surface_map = {.what = "single_surface contact",
                                            .keys = single_surface_keys};
static const mcs_smap two_surface_map = {.what = "two_surface contact", .keys = slave_master_keys};
static const mcs_smap s2s_map = {.what = "surface_to_surface contact", .keys = two_surface_keys};
static const mcs_smap n2s_map = {.what = "node_to_surface contact", .keys = two_surface_keys};
static const mcs_svariant fe_contact_variants[] = {
    {"single_surface", &single_surface_map}, {"two_surface", &two_surface_map},
    {"surface_to_surface", &s2s_map},        {"node_to_surface", &n2s_map},
    {"bodies", &bodies_contact_map},         {0}};
static const mcs_skey fe_contact_keys[] = {
    D("type", "contact type"),
    S("name", UNIQ, "contact name"),
    Q("friction", NONE, GE, 0, 0, "Coulomb friction coefficient"),
    /* penalty stiffness scale (LS-DYNA SLSFAC), default 0.1 */
    Q("penalty_scale", NONE, GT, 0, 0, "penalty stiffness scale factor"),
    /* mu = mu_d + (mu_s - mu_d) exp(-decay |v_t|) (LS-DYNA FS, FD, DC) */
    Q("friction_dynamic", NONE, GE, 0, 0, "dynamic friction coefficient (default friction)"),
    Q("friction_decay", NONE, GE, 0, 0, "exponential decay of friction with slip speed [s/m]"),
    /* on the shell offsets t/2 (LS-DYNA SST/MST scale) */
    Q("thickness_scale", NONE, GT, 0, 0, "scale on the shell contact thickness (default 1)"),
    /* membrane parts: two fabric layers rest t_c apart (docs/fe.md "Contact") */
    Q("fabric_thickness", LEN, GT, 0, 0,
      "contact thickness of fabric (membrane) parts [m] (default max(fabric thickness, 1 mm))"),
    END,
};
static const mcs_smap fe_contact_map = {
    .what = "FE contact", .keys = fe_contact_keys, .disc = "type", .variants = fe_contact_variants};

/* ---- fe: discrete springs and dampers, point masses (fe/elem/fe_discrete.c) ---- */

static const mcs_skey spring_end_keys[] = {
    /* a node of a part (the one nearest to point), or without part a fixed anchor point */
    R("part", PART, 0, "FE part whose node nearest to point is the end (none: fixed anchor)"),
    V("point", LEN, 3, 3, REQ, 0, "point [m]"),
    END,
};
static const mcs_smap spring_end_map = {.what = "spring end", .keys = spring_end_keys};
static const mcs_skey spring_keys[] = {
    S("name", 0, "spring name"),
    M("a", spring_end_map, REQ, "first end"),
    M("b", spring_end_map, REQ, "second end"),
    Q("stiffness", MCS_DIM_STIFFNESS, GE, 0, 0, "linear stiffness, F = k (l - l0) [N/m]"),
    C("curve", LEN, FRC, 2, 0, 0, "[[elongation m, force N], ...] instead of stiffness"),
    Q("damping", MCS_DIM_DAMPING, GE, 0, 0, "viscous damping, F = c dl/dt [N s/m]"),
    S("part", NE,
      "spring part its energies are reported under (default \"springs\"); not "
      "an element part's name"),
    END,
};
static const mcs_smap spring_map = {.what = "spring", .keys = spring_keys};
static const mcs_skey fe_mass_keys[] = {
    R("part", PART, REQ, "FE part"),
    /* one of where (split equally) or point (the nearest node) */
    E("where", "x_min|x_max|y_min|y_max|z_min|z_max|all", 0, "nodes sharing the mass equally"),
    V("point", LEN, 3, 3, 0, 0, "the part's node nearest to this point carries the mass [m]"),
    Q("mass", MCS_DIM_MASS, REQ | GT, 0, 0, "added mass [kg]"),
    END,
};
static const mcs_smap fe_mass_map = {.what = "point mass", .keys = fe_mass_keys};
static const mcs_skey mass_scaling_keys[] = {
    Q("time_step", MCS_DIM_TIME, REQ | GT, 0, 0, "target step, safety factor included [s]"),
    I("check_interval", GE, 0, 0,
      "re-check the elements every this many cycles during the run, "
      "adding mass where the step fell below the target (0: at t = 0 "
      "only, the default)"),
    END,
};
static const mcs_smap mass_scaling_map = {.what = "mass scaling", .keys = mass_scaling_keys};
/* ---- fe: gas bags and belt retractors (fe/fe_restraint.h) ---- */

#define MASSFLOW MCS_D(0, 1, -1, 0, 0)
#define GASCONST MCS_D(2, 0, -2, -1, 0) /* J/(kg K) */

/* fire on a stage-1 contact (stage1_mb/mb_couple_trigger.c): t_fire = the first time the
 * contact's normal force exceeds `force`, plus `delay` */
static const mcs_skey trigger_keys[] = {
    S("contact", REQ | NE, "stage-1 contact (contacts[].name, or <a>-<b> when unnamed)"),
    Q("force", FRC, GE, 0, 0, "normal force that fires it [N] (default: any force > 0)"),
    Q("delay", MCS_DIM_TIME, GE, 0, 0, "firing delay after that [s] (default 0)"),
    END,
};
static const mcs_smap trigger_map = {.what = "trigger", .keys = trigger_keys};

static const mcs_skey inflator_keys[] = {
    Q("fire_time", MCS_DIM_TIME, 0, 0, 0, "firing time [s] (default 0)"),
    M("trigger", trigger_map, 0,
      "fire on a stage-1 contact instead of at fire_time (coupled "
      "stage-1 runs)"),
    C("mass_flow", MCS_DIM_TIME, MASSFLOW, 1, REQ | GE, 0, "[[time since firing s, kg/s], ...]"),
    C("temperature", MCS_DIM_TIME, MCS_DIM_TEMP, 1, REQ | GE, 0,
      "[[time s, gas temperature K], ...]"),
    END,
};
static const mcs_smap inflator_map = {.what = "inflator", .keys = inflator_keys};
static const mcs_skey vent_keys[] = {
    Q("area", MCS_DIM_AREA, REQ | GE, 0, 0, "orifice area [m^2]"),
    Q("discharge_coefficient", NONE, GT | LE, 0, 1, "C_d (default 1)"),
    Q("open_pressure", PRS, GE, 0, 0, "gauge pressure that opens it [Pa] (default 0: open)"),
    END,
};
static const mcs_smap vent_map = {.what = "vent", .keys = vent_keys};
static const mcs_skey leakage_keys[] = {
    Q("area", MCS_DIM_AREA, GE, 0, 0, "effective leak area [m^2]"),
    Q("porosity", NONE, GE | LT, 0, 1, "leak area per fabric area"),
    Q("discharge_coefficient", NONE, GT | LE, 0, 1, "C_d of the leakage (default 1)"),
    END,
};
static const mcs_smap leakage_map = {.what = "leakage", .keys = leakage_keys};
static const mcs_skey airbag_keys[] = {
    S("name", REQ | UNIQ | NE, "gas bag name (results /stage3/airbag/<name>)"),
    RS("parts", PART, 1, REQ, "shell or membrane parts forming the closed surface"),
    M("inflator", inflator_map, 0, "inflator tables"),
    L("vents", vent_map, 0, "exhaust vents (at most 8)"),
    M("leakage", leakage_map, 0, "fabric and seam leakage"),
    Q("gamma", NONE, GT | LT, 1, 2, "cp/cv of the gas (default 1.4)"),
    Q("gas_constant", GASCONST, GT, 0, 0, "specific gas constant [J/(kg K)] (default 287.05)"),
    Q("molar_mass", NONE, GT, 0, 0, "molar mass [kg/mol] (instead of gas_constant)"),
    Q("cp", GASCONST, GT, 0, 0, "specific heat at constant pressure [J/(kg K)] (with cv)"),
    Q("cv", GASCONST, GT, 0, 0, "specific heat at constant volume [J/(kg K)] (with cp)"),
    Q("ambient_pressure", PRS, GT, 0, 0, "[Pa] (default 101325)"),
    Q("ambient_temperature", MCS_DIM_TEMP, GT, 0, 0, "also the initial gas [K] (default 293.15)"),
    Q("initial_pressure", PRS, GT, 0, 0, "absolute pressure at t = 0 [Pa] (default ambient)"),
    Q("initial_temperature", MCS_DIM_TEMP, GT, 0, 0, "gas at t = 0 [K] (default ambient)"),
    END,
};
static const mcs_smap airbag_map = {.what = "gas bag", .keys = airbag_keys};
static const mcs_skey retractor_keys[] = {
    S("name", REQ | UNIQ | NE, "retractor name (results /stage3/retractor/<name>)"),
    R("part", PART, REQ, "belt part (truss) whose end node is pulled"),
    E("where", "x_min|x_max|y_min|y_max|z_min|z_max", REQ, "the belt end (one node)"),
    V("anchor", LEN, 3, 3, REQ, 0, "retractor position (world, t = 0) [m]"),
    R("anchor_body", BODY, 0, "stage-1 body carrying the anchor (default: fixed in the world)"),
    Q("stiffness", MCS_DIM_STIFFNESS, GT, 0, 0, "webbing to the anchor [N/m] (default E A / l0)"),
    Q("fire_time", MCS_DIM_TIME, 0, 0, 0, "pretensioner firing time [s] (default 12 ms)"),
    M("trigger", trigger_map, 0,
      "fire on a stage-1 contact instead of at fire_time (coupled "
      "stage-1 runs)"),
    C("payin", MCS_DIM_TIME, LEN, 1, 0, 0, "[[time since firing s, payout <= 0 m], ...] (Eq. 3)"),
    Q("pretensioner_max_force", FRC, GE, 0, 0, "stall force [N] (default none)"),
    Q("load_limit", FRC, GE, 0, 0, "load-limiter force [N] (default 2 kN; 0 none)"),
    Q("spool_stiffness", MCS_DIM_STIFFNESS, GE, 0, 0, "film spool once locked [N/m] (0 rigid)"),
    Q("spool_force", FRC, GE, 0, 0, "tension of the unlocked spool [N] (default 5)"),
    Q("lock_time", MCS_DIM_TIME, GE, 0, 0, "locks at this time (default: at firing)"),
    Q("lock_payout_rate", VEL, GT, 0, 0, "webbing sensor: locks above this payout rate [m/s]"),
    END,
};
static const mcs_smap retractor_map = {.what = "retractor", .keys = retractor_keys};
/* belt slip rings (fe/fe_slipring.h), LS-DYNA *ELEMENT_SEATBELT_SLIPRING */
static const mcs_skey slipring_keys[] = {
    S("name", REQ | UNIQ | NE, "slip ring name (results /stage3/slipring/<name>)"),
    R("part", PART, REQ, "belt part (truss) holding the ring node"),
    V("point", LEN, 3, 3, REQ, 0, "ring position; the part's nearest node is the ring node [m]"),
    R("body", BODY, 0, "stage-1 body carrying the ring node (default: the node is free)"),
    Q("friction", NONE, GE, 0, 0, "Coulomb coefficient round the ring (LS-DYNA FC; default 0)"),
    Q("lock_time", MCS_DIM_TIME, GE, 0, 0, "no slip from this time on (LS-DYNA LTIME)"),
    Q("min_length", LEN, GT, 0, 0,
      "smallest unstretched side length; the run stops there "
      "(LS-DYNA LMIN; default 5 % of the shorter side)"),
    S("retractor", NE,
      "retractor whose webbing segment is one side (its belt end is the ring "
      "node): the retractor feeds through the ring"),
    END,
};
static const mcs_smap slipring_map = {.what = "slip ring", .keys = slipring_keys};

/* rigid ellipsoids the FE nodes meet (penalty on the surface; stage-1 bodies later) */
static const mcs_skey fe_ellipsoid_keys[] = {
    S("name", REQ | UNIQ | NE, "ellipsoid name"),
    V("center", LEN, 3, 3, REQ, 0, "centre at t = 0 [m]"),
    V("semi_axes", LEN, 3, 3, REQ | GT, 0, "semi-axes along its body axes [m]"),
    V("orientation", NONE, 4, 4, 0, 0, "body-to-world quaternion w, x, y, z (default identity)"),
    V("velocity", VEL, 3, 3, 0, 0, "prescribed velocity [m/s] (default fixed)"),
    RS("parts", PART, 1, 0, "parts whose nodes it meets (default every part)"),
    Q("friction", NONE, GE, 0, 0, "Coulomb friction coefficient"),
    Q("penalty_scale", NONE, GT, 0, 0, "stiffness scale s of k = s m / dt^2 (default 0.1)"),
    END,
};
static const mcs_smap fe_ellipsoid_map = {.what = "rigid ellipsoid", .keys = fe_ellipsoid_keys};

/* the entity lists and settings of fe: that stage2.fe: has too (one list: its lists are
 * appended to fe:'s, its settings replace fe:'s, stage2_fe/s2_scenario.c) */
#define FE_SHARED_KEYS                                                                             \
    L("boundary", boundary_map, 0, "boundary conditions"),                                         \
        L("contacts", fe_contact_map, 0, "FE contacts"),                                           \
        L("rigid_ellipsoids", fe_ellipsoid_map, 0, "rigid ellipsoids"),                            \
        L("loads", load_map, 0, "nodal loads"),                                                    \
        L("airbags", airbag_map, 0, "gas bags (uniform pressure) bounded by membrane parts"),      \
        L("retractors", retractor_map, 0, "belt retractors at truss belt ends"),                   \
        L("sliprings", slipring_map, 0, "belt slip rings (D-ring, buckle tongue)"),                \
        L("springs", spring_map, 0, "discrete springs and dampers"),                               \
        L("masses", fe_mass_map, 0, "point masses"),                                               \
        NM("body_characteristics", body_law_map, 0,                                                \
           "named body characteristics (body_characteristic: NAME of a bodies contact)"),          \
        Q("damping", MCS_DIM_FREQ, GE, 0, 0, "mass-proportional damping c, f = -c m v [1/s]"),     \
        Q("bulk_q1", NONE, GE, 0, 0, "quadratic bulk viscosity (default 1.5)"),                    \
        Q("bulk_q2", NONE, GE, 0, 0, "linear bulk viscosity (default 0.06)"),                      \
        Q("energy_growth_limit", NONE, GE, 0, 0, "stop when total energy grows by this fraction")

/* ---- fe: joints between rigid parts (fe/fe_joint.h, LS-DYNA *CONSTRAINED_JOINT_*) ---- */
static const mcs_skey fe_revolute_keys[] = {
    V("axis", NONE, 3, 3, REQ | NZ, 0, "rotation axis (world, t = 0)"),
    Q("stiffness", MCS_DIM_ROTSTIFF, GE, 0, 0, "spring on the angle [N m/rad]"),
    Q("damping", MCS_DIM_ROTDAMP, GE, 0, 0, "damper on the angle [N m s/rad]"),
    V("range", ANG, 2, 2, 0, 0, "elastic stops [min, max] of the angle from t = 0 [rad]"),
    END,
};
static const mcs_skey fe_slide_keys[] = {
    V("axis", NONE, 3, 3, REQ | NZ, 0, "sliding axis (world, t = 0)"),
    Q("stiffness", MCS_DIM_STIFFNESS, GE, 0, 0, "spring on the slide [N/m]"),
    Q("damping", MCS_DIM_DAMPING, GE, 0, 0, "damper on the slide [N s/m]"),
    V("range", LEN, 2, 2, 0, 0, "elastic stops [min, max] of the slide from t = 0 [m]"),
    END,
};
static const mcs_smap fe_revolute_map = {
    .what = "revolute joint", .keys = fe_revolute_keys, .check = mcs_rule_range};
static const mcs_smap fe_cylindrical_map = {
    .what = "cylindrical joint", .keys = fe_slide_keys, .check = mcs_rule_range};
static const mcs_smap fe_translational_map = {
    .what = "translational joint", .keys = fe_slide_keys, .check = mcs_rule_range};
static const mcs_smap fe_spherical_map = {.what = "spherical joint", .keys = no_keys};
static const mcs_svariant fe_joint_variants[] = {{"revolute", &fe_revolute_map},
                                                 {"spherical", &fe_spherical_map},
                                                 {"cylindrical", &fe_cylindrical_map},
                                                 {"translational", &fe_translational_map},
                                                 {0}};
static const mcs_skey fe_joint_keys[] = {
    S("name", REQ | UNIQ | NE, "joint name (results /stage3/joints/<name>)"),
    D("type", "revolute | spherical | cylindrical | translational"),
    RS("parts", PART, 1, REQ, "rigid parts A, B (one: A held to the ground)"),
    V("point", LEN, 3, 3, REQ, 0, "joint point (world, t = 0) [m]"),
    Q("penalty_scale", NONE, GT | LE, 0, 1, "s of the penalty k = s / (dt^2 lambda) (default 0.1)"),
    END,
};
static const mcs_smap fe_joint_map = {.what = "FE joint",
                                      .keys = fe_joint_keys,
                                      .disc = "type",
                                      .variants = fe_joint_variants};

static const mcs_skey fe_keys[] = {
    /* required, except with a whole keyword deck (keyword:, mcs_rule_fe) */
    L("parts", part_map, NE, "FE parts"),
    /* the whole stage-3 model from an LS-DYNA deck (docs/keyword.md, docs/contracts.md) */
    S("keyword", NE, "LS-DYNA keyword deck read whole: parts, contacts, boundary, initial "
                     "velocities, walls, end time (relative to the YAML file)"),
    E("units", "m-s-kg|mm-s-t|mm-ms-kg|mm-ms-g|cm-s-g|cm-us-g", 0,
      "unit system of the keyword deck (default m-s-kg, SI)"),
    E("unknown_keywords", "warn|error", 0,
      "keywords of the deck outside the subset (default warn)"),
    L("rigid_walls", wall_map, 0, "rigid walls"),
    FE_SHARED_KEYS,
    L("joints", fe_joint_map, 0, "joints between rigid parts (penalty; docs/fe.md \"Joints\")"),
    /* LS-DYNA DT2MS < 0: mass added only to elements whose step is below time_step */
    M("mass_scaling", mass_scaling_map, 0, "selective mass scaling"),
    END,
};
static const mcs_smap fe_map = {.what = "fe block", .keys = fe_keys, .check = mcs_rule_fe};

/* ---- stage 2: vehicles prescribed from a stage-1 results file (DESIGN.md "Stage 2") ---- */

static const mcs_skey stage2_presc_keys[] = {
    R("body", BODY, REQ | UNIQ, "body moved as the file's body"),
    S("from", NE, "the file's body it moves as (default the same name)"),
    END,
};
static const mcs_smap stage2_presc_map = {.what = "prescribed body", .keys = stage2_presc_keys};

/* stage2.fe: FE entities of stage 2 only (cockpit foam, panels, their contacts), appended to
 * fe:'s lists when stage 2 is compiled (stage2_fe/s2_scenario.c); the names they refer to may
 * be fe:'s or these; its settings replace fe:'s */
static const mcs_skey stage2_fe_keys[] = {
    L("parts", part_map, 0, "FE parts of stage 2 only"),
    FE_SHARED_KEYS,
    END,
};
static const mcs_smap stage2_fe_map = {.what = "stage2 fe block", .keys = stage2_fe_keys};

/* energy groups (stage1_mb/mb_egroup.h): a named group's bodies, names or patterns with * and ?
 * (the group "rider" of the bodies rider_* exists without it) */
static const mcs_skey egroup_keys[] = {
    A("bodies", REQ, "bodies of the group (names or patterns); prescribed bodies are left out"),
    /* {<partner name or pattern>: <category>}: replaces the derived category (belts, airbags,
     * foam, fe, motorcycle, opponent, ground, bodies) of the partners it matches */
    A("categories", 0, "partner categories by partner name or pattern (a map)"),
    END,
};
static const mcs_smap egroup_map = {.what = "energy group", .keys = egroup_keys};

static const mcs_skey stage2_keys[] = {
    /* relative to the scenario file (as include:); `--motion FILE` (cwd) wins */
    S("motion", NE, "stage-1 results file the motion is read from (relative to the scenario)"),
    E("method", "pose|pulse", 0,
      "pose: written poses interpolated; pulse: velocity and acceleration histories integrated "
      "(default pose)"),
    L("prescribed", stage2_presc_map, REQ | NE, "bodies moved as in the file (others free)"),
    M("fe", stage2_fe_map, 0, "FE parts and contacts of stage 2 only, appended to fe:"),
    /* e.g. {rider: {bodies: "rider_*", categories: {"pad_*": cockpit}}}: partners that exist in
     * stage 2 only (stage2.fe's contacts) cannot be named in the top-level block */
    NM("energy_groups", egroup_map, 0,
       "energy groups of stage 2 only, merged on top of energy_groups (same keys)"),
    END,
};
static const mcs_smap stage2_map = {.what = "stage2 block", .keys = stage2_keys};

/* ---- stage 3: the full FE run of the scenario (docs/contracts.md "Stage 3") ----
 * stage3.fe replaces fe: (stage 1's FE restraints are coupled to its bodies), stage3.simulation
 * is merged over simulation:, and the stage-1 keys (bodies, contacts, joints, impact, ...) are
 * left out when stage 3 is compiled (stage3_fe/s3_scenario.c); its names refer to its own */
static const mcs_skey stage3_keys[] = {
    M("simulation", sim_map, 0, "simulation keys of stage 3, over simulation: (e.g. end_time)"),
    M("fe", fe_map, REQ, "the stage-3 model (replaces fe:): parts (a generated motorcycle, an "
                         "opponent), rigid walls, contacts"),
    END,
};
static const mcs_smap stage3_map = {.what = "stage3 block", .keys = stage3_keys};
/* ---- retune and loop (docs/retune.md, docs/loop.md, docs/contracts.md) ---- */

/* the stage-1 names and target paths `mcrash retune` uses (defaults: the sport motorcycle
 * against a rigid wall); read by translators/tr_retune.c */
static const mcs_skey retune_keys[] = {
    S("wall_body", NE, "stage-1 body the wall force acts on (default barrier)"),
    S("joint", NE, "stage-1 restrained revolute joint of the fork hinge (default "
                   "moto_fork_deformation)"),
    S("tyre", NE, "characteristic of the front tyre's contact (default tyre_front)"),
    S("fork", NE, "elastic-plastic characteristic of the fork hinge (default fork_deformation)"),
    S("target_force", NE, "stage-3 wall force: a dataset, or a group whose members' force are "
                          "summed (default: the impact wall, else every wall)"),
    S("target_angle", NE, "stage-3 fork angle dataset (default /stage3/channels/<joint>_angle, "
                          "else /stage3/joints/<joint>/angle)"),
    A("free", 0, "parameters fitted, a list of tyre_force_scale, fork_moment_scale, "
                 "fork_elastic_limit, fork_stop_angle, rim_force_scale, fork_stop_stiffness "
                 "(default the first four)"),
    Q("end_time", MCS_DIM_TIME, GT, 0, 0, "compared span [s] (default the target's)"),
    END,
};
static const mcs_smap retune_map = {.what = "retune block", .keys = retune_keys};

/* `mcrash loop`'s scenarios, relative to the file that names them (as include:) */
static const mcs_skey loop_keys[] = {
    S("wall", REQ | NE, "stage-3 wall scenario (the target of retune)"),
    S("retune", REQ | NE, "stage-1 scenario of the same wall case, retuned (its retune: block)"),
    S("crash", REQ | NE, "stage-1/2 crash scenario (a stage2: block); the retuned curves are "
                         "merged over it"),
    I("max_iter", GE | LE, 1, 100, "iterations at most (default 5; --max-iter wins)"),
    Q("tolerance", NONE, GT, 0, 0, "converged when no rating changes by more (default 0.01)"),
    END,
};
static const mcs_smap loop_map = {.what = "loop block", .keys = loop_keys};

/* ---- the reduced-order model (rom/rom.h, docs/rom.md) ---- */

#define STF MCS_DIM_STIFFNESS
#define DMP MCS_DIM_DAMPING
/* every parameter optional: the defaults are the stage-1 sport motorcycle's (docs/rom.md) */
static const mcs_skey rom_keys[] = {
    Q("tyre_stiffness", STF, GT, 0, 0, "front crush slope up to tyre_travel [N/m]"),
    Q("tyre_travel", LEN, GT, 0, 0, "tyre crush where the rim takes over [m]"),
    Q("rim_stiffness", STF, GT, 0, 0, "front crush slope beyond tyre_travel [N/m]"),
    Q("tyre_unload", STF, GT, 0, 0, "tyre unloading slope [N/m]"),
    Q("tyre_damping", DMP, GE, 0, 0, "tyre damping [N s/m]"),
    Q("fork_stiffness", STF, GT, 0, 0, "fork elastic slope [N/m]"),
    Q("fork_yield", FRC, GT, 0, 0, "fork force at its elastic limit [N]"),
    Q("fork_hardening", STF, GT, 0, 0, "fork slope after yield [N/m]"),
    Q("fork_stop", LEN, GT, 0, 0, "fork travel where the wheel meets the engine [m]"),
    Q("stop_stiffness", STF, GT, 0, 0, "slope beyond fork_stop [N/m]"),
    Q("fork_unload", STF, GT, 0, 0, "fork unloading slope [N/m]"),
    Q("fork_damping", DMP, GE, 0, 0, "fork damping [N s/m]"),
    Q("frame_gap", LEN, GE, 0, 0, "frame travel before it meets the barrier [m]"),
    Q("frame_stiffness", STF, GT, 0, 0, "frame against the barrier [N/m]"),
    Q("frame_unload", STF, GT, 0, 0, "frame unloading slope [N/m]"),
    Q("frame_damping", DMP, GE, 0, 0, "frame damping [N s/m]"),
    Q("rider_gap", LEN, GE, 0, 0, "rider travel before the restraint acts [m]"),
    Q("rider_stiffness", STF, GT, 0, 0, "rider against the frame [N/m]"),
    Q("rider_limit", FRC, GT, 0, 0, "rider restraint force plateau (sliding over the tank) [N]"),
    Q("rider_unload", STF, GT, 0, 0, "rider restraint unloading slope [N/m]"),
    Q("rider_damping", DMP, GE, 0, 0, "rider restraint damping [N s/m]"),
    Q("rider_wall_gap", LEN, GE, 0, 0, "rider travel before the rider meets the barrier [m]"),
    Q("rider_wall_stiffness", STF, GT, 0, 0, "rider against the barrier [N/m]"),
    Q("rider_wall_damping", DMP, GE, 0, 0, "rider-barrier damping [N s/m]"),
    Q("rider_wall_unload", STF, GT, 0, 0, "rider-barrier unloading slope [N/m]"),
    Q("opponent_mass", MCS_DIM_MASS, GE, 0, 0, "0: rigid barrier, else a free opponent [kg]"),
    Q("rtol", NONE, GT, 0, 0, "CVODE relative tolerance (default 1e-6)"),
    E("method", "bdf|adams", 0, "CVODE method (default bdf)"),
    END,
};
static const mcs_smap rom_map = {.what = "rom block", .keys = rom_keys};

/* ---- the root ---- */

static const mcs_skey root_keys[] = {
    I("mcrash", REQ, 0, 0, "schema version (1)"),
    S("name", 0, "scenario name"),
    S("description", 0, "free text"),
    A("include", 0, "files to include (resolved before validation)"),
    /* no simulation block: a model file (scenarios/models/), checked but not runnable */
    M("simulation", sim_map, 0, "simulation block"),
    M("environment", env_map, 0, "environment block"),
    NM("characteristics", char_map, 0, "named characteristics"),
    L("bodies", body_map, 0, "rigid bodies"),
    L("contacts", contact_map, 0, "contacts between bodies"),
    L("joints", joint_map, 0, "joints"),
    L("attachments", attachment_map, 0, "breakable attachments"),
    L("sensors", sensor_map, 0, "sensors"),
    M("impact", impact_map, 0, "impact configuration"),
    M("fe", fe_map, 0, "FE block"),
    L("mount_points", mount_map, 0, "named points on bodies"),
    M("rider", rider_map, 0, "seat the rider on the motorcycle"),
    M("stage2", stage2_map, 0, "stage 2: bodies prescribed from a stage-1 results file"),
    M("stage3", stage3_map, 0, "stage 3: the scenario's full FE model (motorcycle, opponent)"),
    M("retune", retune_map, 0, "mcrash retune: stage-1 names and stage-3 target paths"),
    M("loop", loop_map, 0, "mcrash loop: the wall, retune and crash scenarios"),
    M("rom", rom_map, 0, "stage 0: the reduced-order model's parameters (mcrash rom)"),
    NM("energy_groups", egroup_map, 0,
       "energy balances of named groups of bodies, split by contact partner (default: rider)"),
    END,
};
const mcs_smap mcs_schema_root = {.what = "scenario", .keys = root_keys, .check = mcs_rule_root};
