#!/usr/bin/env python3
"""gen_rider.py: writes the stage-1 rider models of scenarios/models/riders/ from the
segment table below (every number and its source: docs/rider.md).

  python3 scripts/gen_rider.py            # rewrites the rider YAML files (single neck,
                                          # 7-vertebra neck, each with a helmet) and the
                                          # 572.32 head-drop verification scenario

Hybrid III 50th-class rider: 78.2 kg, stature 1.75 m, sitting height 0.884 m (NHTSA, H3 50th).
No public H3 segment table was found, so the segment masses, centres of mass and radii of
gyration are de Leva (1996, J. Biomech. 29(9), Table 4, male) fractions scaled to 78.2 kg and
1.75 m; the head takes the commonly cited H3 head mass 4.54 kg (10 lb) out of de Leva's
head+neck. The trunk lengths are scaled (x0.871) so that the seated height is the H3's 0.884 m.

Reference posture (the file's bodies): seated upright, x forward, y left, z up, every body
frame parallel to the world: thighs horizontal forward, lower legs vertical, feet horizontal,
upper arms hanging, forearms and hands horizontal forward. The H-point (midpoint of the hip
joint centres) is at the sport_208kg seat point (0.52, 0, 0.955) m. The positioning step
(stage1_mb/mb_position.c, scenario key rider:) moves the segments onto a motorcycle."""
import math
import os
import re

M_TOTAL = 78.2          # H3 50th [kg]
STATURE_K = 1.75 / 1.741  # H3 stature / de Leva male mean stature
TRUNK_K = 0.8714        # trunk shortening so that the sitting height is 0.884 m
H = (0.52, 0.0, 0.955)  # H-point of the reference posture [m]

# de Leva 1996 Table 4 (male): mass fraction, CM from the proximal/cranial end [fraction of
# length], radii of gyration (sagittal, transverse, longitudinal) [fraction of length], length [m]
DL = {
    "head_neck": (0.0694, 0.5002, (0.303, 0.315, 0.261), 0.2429),
    "upt": (0.1596, 0.5066, (0.716, 0.454, 0.659), 0.2421),
    "mpt": (0.1633, 0.4502, (0.482, 0.383, 0.468), 0.2155),
    "lpt": (0.1117, 0.6115, (0.615, 0.551, 0.587), 0.1457),
    "upper_arm": (0.0271, 0.5772, (0.285, 0.269, 0.158), 0.2817),
    "forearm": (0.0162, 0.4574, (0.276, 0.265, 0.121), 0.2689),
    "hand": (0.0061, 0.7900, (0.628, 0.513, 0.401), 0.0862),
    "thigh": (0.1416, 0.4095, (0.329, 0.329, 0.149), 0.4222),
    "shank": (0.0433, 0.4395, (0.251, 0.246, 0.102), 0.4340),
    "foot": (0.0137, 0.4415, (0.257, 0.245, 0.124), 0.2581),
}
HEAD_MASS = 4.54        # H3 50th head assembly (10 lb), commonly cited [S]
HEAD_SURF_CENTER = (0.005, 0, 0)      # head ellipsoid centre from the head CG [m] [A]
HEAD_SURF_SEMI = (0.10, 0.078, 0.115)  # head ellipsoid semi-axes [m] [A]


class Size:
    """a Hybrid III size: segment masses [kg] and length factors relative to the 50th model
    (kt trunk, neck and head heights; ka arms; kl legs; kw breadths and depths; kh head)"""

    def __init__(self, masses, kt=1.0, ka=1.0, kl=1.0, kw=1.0, kh=1.0,
                 head_center=None, head_semi=None):
        self.masses = masses
        self.kt, self.ka, self.kl, self.kw, self.kh = kt, ka, kl, kw, kh
        self.head_center = head_center or HEAD_SURF_CENTER
        self.head_semi = head_semi or HEAD_SURF_SEMI

    def mass(self, seg):
        return self.masses[seg]


def masses_50th():
    """de Leva's fractions of 78.2 kg, the H3 head out of de Leva's head+neck"""
    m = {k: DL[k][0] * M_TOTAL for k in DL}
    m["head"] = HEAD_MASS
    m["neck"] = DL["head_neck"][0] * M_TOTAL - HEAD_MASS
    return m


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def f(v):
    return "%.7g" % v if abs(v) >= 1e-12 else "0"


def vec(v):
    return "[" + ", ".join(f(x) for x in v) + "]"


class Model:
    def __init__(self):
        self.bodies = []   # (name, mass, inertia, cg, surfaces, comment)
        self.joints = []   # dict
        self.mounts = []   # (name, body, point in body frame)
        self.sensors = []  # dict
        self.cell = {}     # load-cell points in body frames

    def body(self, name, mass, inertia, cg, surfaces, comment):
        self.bodies.append((name, mass, inertia, cg, surfaces, comment))
        return cg

    def cg(self, name):
        for b in self.bodies:
            if b[0] == name:
                return b[3]
        raise KeyError(name)


SIZE_50TH = Size(masses_50th())

# ---- the Hybrid III 5th female and 95th male (issue 13 item 6; docs/rider.md "Sizes") ------------
# [N5] NHTSA, "Hybrid III 5th Percentile Female" physical data page (nhtsa.gov/Research):
# weight 108.0 lb, stature 59.1 in, erect sitting height 31.0 in (50th male: 172.3 lb, 69.0 in,
# 34.8 in); assembly weights [lb]: head 8.23, neck 2.0, upper torso 26.5, lower torso 29.2, upper
# arms (both) 5.2, lower arms and hands (both) 5.2, upper legs (both) 13.8, lower legs and feet
# (both) 17.9 (sum 108.03); head width 5.6 in, depth 7.2 in. The dummy is the 50th scaled down
# (Mertz, Irwin, Melvin 1989, SAE 890756).
# [W95] the Hybrid III 95th male: 223 lb (101.2 kg), stature 188 cm (74 in) (Wikipedia "Hybrid
# III"; the SAE/Shaw et al. 2007 (ESV 07-0228) segment table was not retrieved) [S].
LB = 0.45359237         # [kg/lb]
INCH = 0.0254           # [m/in]
H3_50_STATURE_IN, H3_50_SIT_IN = 69.0, 34.8   # [N5]
H3_05_STATURE_IN, H3_05_SIT_IN = 59.1, 31.0   # [N5]
H3_95_STATURE_IN, H3_95_MASS_LB = 74.0, 223.0  # [W95]
SEAT_BELOW_H = 0.09     # the seat surface below the hip centres [m] [A] (docs/rider.md)


def split(total, a, b):
    """total split between de Leva segments a and b in proportion to their mass fractions"""
    fa, fb = DL[a][0], DL[b][0]
    return total * fa / (fa + fb), total * fb / (fa + fb)


def masses_05f():
    """[N5] assembly weights on the model's segments; an assembly covering two segments is
    split in de Leva's proportions: lower torso -> middle trunk + pelvis (lower trunk), lower
    arm and hand -> forearm + hand, lower leg and foot -> shank + foot; pairs halved"""
    m = {"head": 8.23 * LB, "neck": 2.0 * LB, "upt": 26.5 * LB,
         "upper_arm": 5.2 / 2 * LB, "thigh": 13.8 / 2 * LB}
    m["mpt"], m["lpt"] = split(29.2 * LB, "mpt", "lpt")
    m["forearm"], m["hand"] = split(5.2 / 2 * LB, "forearm", "hand")
    m["shank"], m["foot"] = split(17.9 / 2 * LB, "shank", "foot")
    return m


def size_05f():
    mass_k = 108.03 * LB / M_TOTAL                # mass ratio to the 50th (0.6266)
    stat_k = H3_05_STATURE_IN / H3_50_STATURE_IN  # stature ratio (0.8565)
    # arms: stature ratio [scaled]; breadths and depths: sqrt(mass ratio / stature ratio) (mass ~
    # length x breadth^2) [scaled]; legs below
    kw = math.sqrt(mass_k / stat_k)
    # head: width and depth [N5], height scaled by their mean ratio to the 50th model's
    semi = (7.2 / 2 * INCH, 5.6 / 2 * INCH, 0.0)
    kh = (semi[0] / HEAD_SURF_SEMI[0] + semi[1] / HEAD_SURF_SEMI[1]) / 2
    semi = (semi[0], semi[1], HEAD_SURF_SEMI[2] * kh)
    # trunk: the seated height (head top over the seat) is [N5]'s 31.0 in
    z50 = build(False).cg("rider_head")[2] - H[2]   # the 50th's head CG above the hips
    kt = (H3_05_SIT_IN * INCH - SEAT_BELOW_H - semi[2]) / z50
    # legs: standing, the hip centres are at stature - (sitting height - SEAT_BELOW_H) [N5]; the
    # model's standing hip height is thigh + shank + the ankle 70 mm above the heel, x kl
    leg50 = (DL["thigh"][3] + DL["shank"][3]) * STATURE_K + 0.07
    kl = ((H3_05_STATURE_IN - H3_05_SIT_IN) * INCH + SEAT_BELOW_H) / leg50
    return Size(masses_05f(), kt=kt, ka=stat_k, kl=kl, kw=kw, kh=kh,
                head_center=(HEAD_SURF_CENTER[0] * kh, 0, 0), head_semi=semi)


def head_exponent():
    """the H3 family's head-to-body mass scaling from the 5th and 50th [N5]: head ratio =
    (body ratio)^e; e = ln(3.733 / 4.54) / ln(49.00 / 78.2) = 0.42 (the head varies less than
    the body)"""
    return math.log(8.23 * LB / HEAD_MASS) / math.log(108.03 * LB / M_TOTAL)


def size_95m():
    """no 95th segment table was retrieved [scaled]: the head's mass from the 5th/50th head
    exponent (head_exponent), its size x (head mass ratio)^(1/3); every other 50th segment mass
    x the rest's ratio; lengths x the stature ratio lambda, breadths x sqrt(mass ratio /
    lambda) (Mertz et al. 1989's geometric scaling)"""
    mass_k = H3_95_MASS_LB * LB / M_TOTAL
    lam = H3_95_STATURE_IN / H3_50_STATURE_IN
    head = HEAD_MASS * mass_k ** head_exponent()
    rest_k = (H3_95_MASS_LB * LB - head) / (M_TOTAL - HEAD_MASS)
    m = {k: v * rest_k for k, v in masses_50th().items()}
    m["head"] = head
    kh = (head / HEAD_MASS) ** (1 / 3)
    return Size(m, kt=lam, ka=lam, kl=lam, kw=math.sqrt(mass_k / lam), kh=kh,
                head_center=tuple(c * kh for c in HEAD_SURF_CENTER),
                head_semi=tuple(c * kh for c in HEAD_SURF_SEMI))


def radii_inertia(m, r, L, long_axis):
    """principal inertia [Ixx, Iyy, Izz] in the reference frame from de Leva's radii
    (sagittal = anteroposterior axis, transverse = left-right, longitudinal = along the
    segment); long_axis 'z' (vertical segment) or 'x' (horizontal forward segment)."""
    sag, trv, lon = (m * (k * L) ** 2 for k in r)
    if long_axis == "z":
        return (sag, trv, lon)
    return (lon, trv, sag)   # horizontal: x along the segment, z the anteroposterior axis


def ellipsoid(name, center, semi, char):
    return "{name: %s, type: ellipsoid, center: %s, semi_axes: %s, characteristic: %s}" % (
        name, vec(center), vec(semi), char)


def build(neck7=False, z=None):
    """the rider of size z (SIZE_50TH by default; Size below); neck7: MYMOSA's neck"""
    z = z or SIZE_50TH
    md = Model()
    hz = H[2]
    s = STATURE_K * z.ka
    sl = STATURE_K * z.kl
    t = STATURE_K * TRUNK_K * z.kt
    kw, kt = z.kw, z.kt
    # ---- spine chain (reference: vertical through the H-point) ----
    mp, cp, rp, Lp = DL["lpt"]
    mm, cm, rm, Lm = DL["mpt"]
    mu, cu, ru, Lu = DL["upt"]
    Lp, Lm, Lu = Lp * t, Lm * t, Lu * t
    z_omph = hz + Lp
    z_xyph = z_omph + Lm
    z_t1 = z_xyph + Lu
    neck_len = 2 * 0.19 * math.sin(math.radians(37) / 2) * kt   # MYMOSA neck arc chord
    z_oc = z_t1 + neck_len
    z_head = z_oc + 0.035 * kt
    x0, y0 = H[0], H[1]
    # the pelvis ellipsoid keeps its bottom 95 mm below the hip centres for every size (the
    # seat's H-point is a motorcycle mount point, sport_208kg: 91 mm above the seat top)
    pelvis = md.body("rider_pelvis", z.mass("lpt"), radii_inertia(z.mass("lpt"), rp, Lp, "z"),
                     (x0 - 0.02 * kw, y0, z_omph - cp * Lp),
                     [ellipsoid("rider_pelvis", (-0.02 * kw, 0, hz - 0.005 - (z_omph - cp * Lp)),
                                (0.13 * kw, 0.17 * kw, 0.09), "rider_pelvis")],
                     "de Leva lower trunk (omphalion to hip centres)")
    lt = md.body("rider_lower_torso", z.mass("mpt"), radii_inertia(z.mass("mpt"), rm, Lm, "z"),
                 (x0, y0, z_xyph - cm * Lm),
                 [ellipsoid("rider_lower_torso", (0.01 * kw, 0, 0), (0.11 * kw, 0.15 * kw, 0.11 * kt),
                            "rider_torso")],
                 "de Leva middle trunk (xiphoid to omphalion)")
    ut = md.body("rider_upper_torso", z.mass("upt"), radii_inertia(z.mass("upt"), ru, Lu, "z"),
                 (x0, y0, z_t1 - cu * Lu),
                 [ellipsoid("rider_upper_torso", (0.02 * kw, 0, 0), (0.12 * kw, 0.17 * kw, 0.13 * kt),
                            "rider_torso")],
                 "de Leva upper trunk (C7 to xiphoid)")
    md.joints.append(dict(name="rider_lumbar", type="spherical", parent="rider_pelvis",
                          child="rider_lower_torso", anchor=(x0, y0, z_omph), restraint="rider_lumbar"))
    md.joints.append(dict(name="rider_thoracic", type="spherical", parent="rider_lower_torso",
                          child="rider_upper_torso", anchor=(x0, y0, z_xyph), restraint="rider_thoracic"))
    # ---- head and neck ----
    rh, Lh = DL["head_neck"][2], DL["head_neck"][3] * STATURE_K * z.kh
    neck_mass = z.mass("neck")
    head_mass = z.mass("head")
    md.body("rider_head", head_mass, radii_inertia(head_mass, rh, Lh, "z"), (x0, y0, z_head),
            [ellipsoid("rider_head", z.head_center, z.head_semi, "rider_head")],
            "H3 head mass; de Leva head radii")
    if not neck7:
        r, h = 0.05 * kw, neck_len
        md.body("rider_neck", neck_mass,
                (neck_mass * (3 * r * r + h * h) / 12, neck_mass * (3 * r * r + h * h) / 12,
                 neck_mass * r * r / 2), (x0, y0, (z_t1 + z_oc) / 2),
                [ellipsoid("rider_neck", (0, 0, 0), (0.05 * kw, 0.05 * kw, 0.065 * kt), "rider_limb")],
                "de Leva head+neck less the H3 head; a cylinder r 0.05 m")
        md.joints.append(dict(name="rider_lower_neck", type="spherical", parent="rider_upper_torso",
                              child="rider_neck", anchor=(x0, y0, z_t1), restraint="rider_neck"))
        md.joints.append(dict(name="rider_upper_neck", type="spherical", parent="rider_neck",
                              child="rider_head", anchor=(x0, y0, z_oc), restraint="rider_neck"))
    else:
        # MYMOSA Fig. 3.2: 7 equal vertebrae on an arc of radius 190 mm over 37 deg, T1 to OC,
        # convex forward (cervical lordosis); 8 spherical joints T1-C7 ... C1-OC
        R, span = 0.19 * kt, math.radians(37)
        zc = (z_t1 + z_oc) / 2
        xc = x0 - R * math.cos(span / 2)   # arc centre behind the chord

        def arc(u):   # u in [0, 1] from T1 to OC
            a = -span / 2 + span * u
            return (xc + R * math.cos(a), y0, zc + R * math.sin(a))
        pts = [arc(k / 7) for k in range(8)]
        pts[0] = (pts[0][0], y0, z_t1)
        pts[7] = (pts[7][0], y0, z_oc)
        mv = neck_mass / 7
        rv, hv = 0.035, neck_len / 7
        names = ["rider_c%d" % (7 - k) for k in range(7)]   # c7 at the bottom
        for k in range(7):
            cgk = arc((k + 0.5) / 7)
            md.body(names[k], mv, (mv * (3 * rv * rv + hv * hv) / 12,
                                   mv * (3 * rv * rv + hv * hv) / 12, mv * rv * rv / 2), cgk,
                    [ellipsoid(names[k], (0, 0, 0), (0.035, 0.035, 0.012), "rider_limb")],
                    "MYMOSA vertebra (1/7 of the neck mass)")
        parents = ["rider_upper_torso"] + names
        children = names + ["rider_head"]
        jn = ["rider_t1_c7"] + ["rider_c%d_c%d" % (7 - k, 6 - k) for k in range(6)] + ["rider_c1_oc"]
        jn[-1] = "rider_upper_neck"
        jn[0] = "rider_lower_neck"
        for k in range(8):
            md.joints.append(dict(name=jn[k], type="spherical", parent=parents[k], child=children[k],
                                  anchor=pts[k], restraint="rider_neck7"))
        # the head's CG over the OC as in the single-neck model (the OC moved forward on the arc)
    # ---- arms ----
    for side, sy in (("l", 1), ("r", -1)):
        sh = (x0, y0 + sy * 0.175 * kw, z_t1 - 0.04 * kt)
        ma, ca, ra, La = DL["upper_arm"]
        mf, cf, rf, Lf = DL["forearm"]
        mh, ch, rhd, Lhd = DL["hand"]
        La, Lf, Lhd = La * s, Lf * s, Lhd * s
        el = (sh[0], sh[1], sh[2] - La)
        wr = (el[0] + Lf, el[1], el[2])
        grip = (wr[0] + 0.07 * z.ka, wr[1], wr[2])
        ka = z.ka
        ua = md.body("rider_upper_arm_" + side, z.mass("upper_arm"),
                     radii_inertia(z.mass("upper_arm"), ra, La, "z"),
                     (sh[0], sh[1], sh[2] - ca * La),
                     [ellipsoid("rider_upper_arm_" + side, (0, 0, ca * La - La / 2),
                                (0.045 * kw, 0.045 * kw, 0.15 * ka), "rider_limb")],
                     "de Leva upper arm")
        la = md.body("rider_lower_arm_" + side, z.mass("forearm"),
                     radii_inertia(z.mass("forearm"), rf, Lf, "x"),
                     (el[0] + cf * Lf, el[1], el[2]),
                     [ellipsoid("rider_lower_arm_" + side, (Lf / 2 - cf * Lf, 0, 0),
                                (0.14 * ka, 0.04 * kw, 0.04 * kw), "rider_limb")],
                     "de Leva forearm")
        hd = md.body("rider_hand_" + side, z.mass("hand"), radii_inertia(z.mass("hand"), rhd, Lhd, "x"),
                     (wr[0] + ch * Lhd, wr[1], wr[2]),
                     [ellipsoid("rider_hand_" + side, (0, 0, 0), (0.05 * ka, 0.04 * kw, 0.045 * kw),
                                "rider_limb")],
                     "de Leva hand (wrist to 3rd knuckle)")
        md.joints.append(dict(name="rider_shoulder_" + side, type="spherical", parent="rider_upper_torso",
                              child="rider_upper_arm_" + side, anchor=sh, restraint="rider_shoulder"))
        # flexion positive: the hinge axis -y turns the forearm up
        md.joints.append(dict(name="rider_elbow_" + side, type="revolute", parent="rider_upper_arm_" + side,
                              child="rider_lower_arm_" + side, anchor=el, axis=(0, -1, 0),
                              restraint="rider_elbow", range=("-90 deg", "55 deg")))
        md.joints.append(dict(name="rider_wrist_" + side, type="spherical", parent="rider_lower_arm_" + side,
                              child="rider_hand_" + side, anchor=wr, restraint="rider_wrist"))
        md.mounts.append(("rider_grip_" + side, "rider_hand_" + side, sub(grip, hd)))
    # ---- legs ----
    for side, sy in (("l", 1), ("r", -1)):
        hip = (x0, y0 + sy * 0.085 * kw, hz)
        kl = z.kl
        mt, ct, rt, Lt = DL["thigh"]
        ms, cs, rs, Ls = DL["shank"]
        mft, cft, rft, Lft = DL["foot"]
        Lt, Ls, Lft = Lt * sl, Ls * sl, Lft * sl
        kn = (hip[0] + Lt, hip[1], hip[2])
        an = (kn[0], kn[1], kn[2] - Ls)
        heel = (an[0] - 0.05 * kl, an[1], an[2] - 0.07 * kl)
        th = md.body("rider_thigh_" + side, z.mass("thigh"), radii_inertia(z.mass("thigh"), rt, Lt, "x"),
                     (hip[0] + ct * Lt, hip[1], hip[2]),
                     [ellipsoid("rider_thigh_" + side, (Lt / 2 - ct * Lt, 0, 0),
                                (0.23 * kl, 0.08 * kw, 0.08 * kw), "rider_limb")],
                     "de Leva thigh")
        sk = md.body("rider_lower_leg_" + side, z.mass("shank"), radii_inertia(z.mass("shank"), rs, Ls, "z"),
                     (kn[0], kn[1], kn[2] - cs * Ls),
                     [ellipsoid("rider_lower_leg_" + side, (0, 0, cs * Ls - Ls / 2),
                                (0.05 * kw, 0.05 * kw, 0.23 * kl), "rider_limb")],
                     "de Leva shank")
        ft_cg = (heel[0] + cft * Lft, heel[1], an[2] - 0.04 * kl)
        ft = md.body("rider_foot_" + side, z.mass("foot"), radii_inertia(z.mass("foot"), rft, Lft, "x"),
                     ft_cg,
                     [ellipsoid("rider_foot_" + side, sub((heel[0] + Lft / 2, heel[1], an[2] - 0.045 * kl),
                                                          ft_cg),
                                (0.13 * kl, 0.05 * kw, 0.04 * kl), "rider_limb")],
                     "de Leva foot (heel to toe tip)")
        md.cell["thigh_" + side] = (Lt / 2 - ct * Lt, 0, 0)
        md.cell["shank_" + side] = (0, 0, cs * Ls - 0.07 * kl)
        md.joints.append(dict(name="rider_hip_" + side, type="spherical", parent="rider_pelvis",
                              child="rider_thigh_" + side, anchor=hip, restraint="rider_hip"))
        # flexion positive: the hinge axis +y turns the lower leg backward
        md.joints.append(dict(name="rider_knee_" + side, type="revolute", parent="rider_thigh_" + side,
                              child="rider_lower_leg_" + side, anchor=kn, axis=(0, 1, 0),
                              restraint="rider_knee", range=("-90 deg", "50 deg")))
        md.joints.append(dict(name="rider_ankle_" + side, type="spherical", parent="rider_lower_leg_" + side,
                              child="rider_foot_" + side, anchor=an, restraint="rider_ankle"))
        peg = (an[0] + 0.13 * kl, an[1], an[2] - 0.075 * kl)   # sole under the ball of the foot
        md.mounts.append(("rider_peg_" + side, "rider_foot_" + side, sub(peg, ft)))
    md.mounts.insert(0, ("rider_h_point", "rider_pelvis", sub(H, pelvis)))
    md.oc_below = 0.035 * kt   # the occipital condyle below the head CG [m]
    return md


CHARS = """\
characteristics:
  # ---- contact characteristics of the segments' surfaces [A], docs/rider.md ----
  # head: skin on the skull, 3.7 MN/m: CALIBRATED on the H3 head drop (376 mm onto a rigid
  # plate, 49 CFR 572.32: 225-275 g), v sqrt(k/m) = 2.716 x 903 = 245 g; no independent
  # sourced value was found (docs/rider.md); the 10 mm point and the damping are assumed
  rider_head:
    loading: [[0, 0], [5 mm, 18.5 kN], [10 mm, 45 kN]]
    damping: 200 N s/m
  rider_torso:
    loading: [[0, 0], [10 mm, 1 kN], [30 mm, 5 kN], [60 mm, 20 kN], [80 mm, 60 kN]]
    damping: 500 N s/m
  rider_pelvis:
    loading: [[0, 0], [10 mm, 1.5 kN], [30 mm, 6 kN], [60 mm, 25 kN], [80 mm, 70 kN]]
    damping: 500 N s/m
  rider_limb:
    loading: [[0, 0], [10 mm, 0.5 kN], [30 mm, 3 kN], [50 mm, 15 kN], [70 mm, 50 kN]]
    damping: 200 N s/m
  # ---- joint restraints: moment vs. angle per axis, both directions [A], docs/rider.md ----
  # About the seated posture, stiff enough to hold it under 1 g with a few degrees of sag (as
  # an ATD's joints are set to hold a posture), then stiffening to the end of the range.
  rider_lumbar:
    type: moment
    loading: [[0, 0], [0.1 rad, 60 N*m], [0.3 rad, 250 N*m], [0.6 rad, 1500 N*m]]
    damping: 20 N m s/rad
  rider_thoracic:
    type: moment
    loading: [[0, 0], [0.1 rad, 200 N*m], [0.3 rad, 1500 N*m]]
    damping: 30 N m s/rad
  rider_neck:
    type: moment
    loading: [[0, 0], [0.3 rad, 30 N*m], [0.6 rad, 90 N*m], [0.9 rad, 400 N*m]]
    damping: 1.5 N m s/rad
  rider_shoulder:
    type: moment
    loading: [[0, 0], [0.2 rad, 30 N*m], [0.8 rad, 80 N*m], [1.4 rad, 300 N*m], [1.7 rad, 1500 N*m]]
    damping: 3 N m s/rad
  rider_elbow:
    type: moment
    loading: [[0, 0], [0.2 rad, 30 N*m], [1.5 rad, 60 N*m]]
    damping: 2 N m s/rad
  rider_wrist:
    type: moment
    loading: [[0, 0], [0.2 rad, 10 N*m], [0.8 rad, 30 N*m], [1.2 rad, 200 N*m]]
    damping: 0.5 N m s/rad
  rider_hip:
    type: moment
    loading: [[0, 0], [0.2 rad, 60 N*m], [0.6 rad, 200 N*m], [1.0 rad, 600 N*m], [1.4 rad, 3000 N*m]]
    damping: 5 N m s/rad
  rider_knee:
    type: moment
    loading: [[0, 0], [0.2 rad, 30 N*m], [1.5 rad, 60 N*m]]
    damping: 3 N m s/rad
  rider_ankle:
    type: moment
    loading: [[0, 0], [0.2 rad, 15 N*m], [0.6 rad, 40 N*m], [0.9 rad, 300 N*m]]
    damping: 0.5 N m s/rad
"""

NECK7_CHAR = """\
  # 8 joints in series instead of 2: 4 times the rider_neck moment at the same angle share
  rider_neck7:
    type: moment
    loading: [[0, 0], [0.075 rad, 120 N*m], [0.15 rad, 360 N*m], [0.225 rad, 1600 N*m]]
    damping: 1.5 N m s/rad
"""


def scale_chars(lam, neck_k):
    """CHARS scaled by Mertz's dimensional analysis (equal density and modulus; length x lam,
    time x lam): contact deflection x lam, force x lam^2, damping [N s/m] x lam^2; restraint
    moment x lam^3 (the neck's x neck_k: the ratio of the Nij flexion intercepts), rotational
    damping x lam^4; angles unchanged"""
    def num(v):
        return "%.4g" % v
    out, name = [], ""
    for ln in CHARS.splitlines():
        if ln.startswith("  ") and not ln.startswith("    ") and not ln.lstrip().startswith("#"):
            name = ln.strip().rstrip(":")
        if ln.lstrip().startswith("#"):
            out.append(ln)
            continue
        km = neck_k if name == "rider_neck" else lam ** 3
        ln = re.sub(r"([0-9.]+) mm", lambda g: num(float(g.group(1)) * lam) + " mm", ln)
        ln = re.sub(r"([0-9.]+) kN", lambda g: num(float(g.group(1)) * lam ** 2) + " kN", ln)
        ln = re.sub(r"([0-9.]+) N\*m", lambda g: num(float(g.group(1)) * km) + " N*m", ln)
        ln = re.sub(r"([0-9.]+) N s/m", lambda g: num(float(g.group(1)) * lam ** 2) + " N s/m", ln)
        ln = re.sub(r"([0-9.]+) N m s/rad", lambda g: num(float(g.group(1)) * lam ** 4) + " N m s/rad",
                    ln)
        out.append(ln)
    return "\n".join(out) + "\n"


def write(md, path, title, header, chars=CHARS):
    out = [header, "mcrash: 1", 'name: "%s"' % title, chars.rstrip("\n")]
    if any(j["restraint"] == "rider_neck7" for j in md.joints):
        out.append(NECK7_CHAR.rstrip("\n"))
    out.append("bodies:")
    tot = 0
    for name, m, I, cg, surfs, comment in md.bodies:
        tot += m
        out.append("  - name: %s    # %s" % (name, comment))
        out.append("    mass: %s kg" % f(m))
        out.append("    inertia: %s" % vec(I))
        out.append("    position: %s" % vec(cg))
        out.append("    velocity: [0, 0, 0]")
        out.append("    surfaces:")
        for sf in surfs:
            out.append("      - " + sf)
    out.append("joints:")
    for j in md.joints:
        extra = ""
        if "axis" in j:
            extra += ", axis: %s" % vec(j["axis"])
        if "range" in j:
            extra += ", range: [%s, %s]" % j["range"]
        out.append("  - {name: %s, type: %s, parent: %s, child: %s,\n     anchor: %s%s, restraint: %s}" % (
            j["name"], j["type"], j["parent"], j["child"], vec(j["anchor"]), extra, j["restraint"]))
    out.append("mount_points:")
    for name, body, p in md.mounts:
        out.append("  - {name: %s, body: %s, point: %s}" % (name, body, vec(p)))
    out.append("sensors:")
    out.append("  - {name: head, body: rider_head, type: acceleration, cfc: 1000}")
    out.append("  - {name: chest, body: rider_upper_torso, type: acceleration, cfc: 180}")
    out.append("  - {name: pelvis, body: rider_pelvis, type: acceleration, cfc: 1000}")
    # upper-neck load cell: 17.78 mm above the occipital condyle (the H3's M_oc = My - 0.01778 Fx,
    # analysis/an_nij.c), the OC 35 mm below the head CG; loads on the head
    out.append("  - {name: neck, type: load_cell, body: rider_head, joint: rider_upper_neck, "
               "point: [0, 0, %s], cfc: 600}" % f(-md.oc_below + 0.01778))
    for side, lr in (("l", "left"), ("r", "right")):
        th, sk = md.cell["thigh_" + side], md.cell["shank_" + side]
        # femur: loads on the thigh through the knee (the part above the cell), at mid-femur,
        # axes of a standing femur (J211 z down the femur towards the knee): pitch -90 deg
        out.append("  - {name: femur_%s, type: load_cell, body: rider_thigh_%s, joint: rider_knee_%s, "
                   "point: %s, orientation: [0, -90 deg, 0], cfc: 600}" % (lr, side, side, vec(th)))
        # upper tibia: loads on the part above (the thigh) through the knee, at a point of the
        # lower leg 70 mm below the knee, on the lower leg's axes
        out.append("  - {name: tibia_%s, type: load_cell, body: rider_thigh_%s, frame: rider_lower_leg_%s, "
                   "joint: rider_knee_%s, point: %s, cfc: 600}" % (lr, side, side, side, vec(sk)))
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")
    return tot


HEADER = """\
# Hybrid III 50th-class rider (issue 4 item 4): %s
# Generated by scripts/gen_rider.py -- edit the script, not this file. Sources of every number:
# docs/rider.md. 78.2 kg, stature 1.75 m, sitting height 0.884 m (H3 50th); segment masses,
# centres of mass and inertias: de Leva (1996) fractions scaled to it; H3 head mass 4.54 kg.
# Reference posture: seated upright, body frames parallel to the world (x forward, y left,
# z up), H-point at (0.52, 0, 0.955) m (the sport_208kg seat point). A scenario's `rider:`
# block seats it on the motorcycle (stage1_mb/mb_position.c): pelvis H-point on the seat,
# hands on the grips, feet on the pegs, breakable attachments, the motorcycle's velocity.
# Joint restraints act about the positioned posture (as an ATD's joints set to hold it);
# the elbow and knee ranges are anatomical, given here about the reference posture."""


# ---- 49 CFR 572.32 head drop (verification scenario, docs/rider.md) ----------------------------
# 572.32(b), (c) (Subpart E, Hybrid III 50th male; text of the Oct. 2006 CFR edition, GPO): the
# head is dropped from 14.8 in (376 mm) onto a rigidly supported flat horizontal steel plate,
# suspended so that the lowest point on the forehead is 0.5 in below the lowest point on the
# nose (a forehead impact); peak resultant acceleration at the head CG not less than 225 g and
# not more than 275 g; the acceleration-time curve unimodal (oscillations after the main pulse
# less than 10 % of it, zero to peak); lateral acceleration not above 15 g (zero to peak).
DROP_HEIGHT = 0.376     # [m]
DROP_PITCH = 67.0       # forward pitch [deg] [A]: the surface normal at a forehead point 50 mm
                        # above the CG points down (face down, forehead first)


def head_drop_char():
    """the rider_head contact characteristic, as in the rider files (CHARS)"""
    lines, on = [], False
    for ln in CHARS.splitlines():
        if ln.startswith("  rider_head:"):
            on = True
        elif on and ln.startswith("  ") and not ln.startswith("    "):
            break
        if on:
            lines.append(ln)
    return "\n".join(lines)


def write_head_drop(path):
    rh, Lh = DL["head_neck"][2], DL["head_neck"][3] * STATURE_K
    inertia = radii_inertia(HEAD_MASS, rh, Lh, "z")
    th = math.radians(DROP_PITCH)
    a, b, c = HEAD_SURF_SEMI
    # pitched by th about y (x turns towards -z): the ellipsoid reaches sqrt(a^2 sin^2 + c^2 cos^2)
    # below its centre, and the centre lies HEAD_SURF_CENTER[0] sin(th) below the CG
    below = math.sqrt((a * math.sin(th)) ** 2 + (c * math.cos(th)) ** 2)
    z_cg = DROP_HEIGHT + below + HEAD_SURF_CENTER[0] * math.sin(th)
    out = ["# Hybrid III head drop, 49 CFR 572.32 (Subpart E): the rider's head (the segment of",
           "# scenarios/models/riders/hybrid3_50th.yaml: mass, inertia, ellipsoid and the rider_head skin",
           "# characteristic) dropped from rest with its lowest point 376 mm (14.8 in) above a rigid",
           "# plate, pitched %g deg forward so that the forehead strikes [A]. Corridor (572.32(b)):" % DROP_PITCH,
           "# peak resultant acceleration 225-275 g, unimodal (later oscillations < 10 % of the peak),",
           "# lateral <= 15 g. Impact speed sqrt(2 g h) = %.4f m/s. Checked by tests/test_rider_cert.c." % math.sqrt(2 * 9.81 * DROP_HEIGHT),
           "# Generated by scripts/gen_rider.py -- edit the script, not this file.",
           "mcrash: 1",
           'name: "Hybrid III head drop, 49 CFR 572.32 (376 mm, forehead, rigid plate)"',
           "simulation: {end_time: 300 ms, time_step: 10 us, output_rate: 20 kHz}",
           "environment: {gravity: 9.81 m/s^2, ground: {height: 0 m}}",
           "characteristics:",
           head_drop_char(),
           "bodies:",
           "  - name: rider_head",
           "    mass: %s kg" % f(HEAD_MASS),
           "    inertia: %s" % vec(inertia),
           "    position: %s" % vec((0, 0, z_cg)),
           "    orientation: [0, %g deg, 0]" % DROP_PITCH,
           "    velocity: [0, 0, 0]",
           "    surfaces:",
           "      - " + ellipsoid("rider_head", HEAD_SURF_CENTER, HEAD_SURF_SEMI, "rider_head"),
           "contacts:",
           "  - {name: head_plate, a: rider_head, b: ground, characteristic: rider_head}",
           "sensors:",
           "  - {name: head, body: rider_head, type: acceleration, cfc: 1000}"]
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")


# ---- helmet (MYMOSA 3-mass model) on either neck: hybrid3_50th_helmet.yaml and
# hybrid3_50th_neck7_helmet.yaml (docs/rider.md "Helmet"); the head CG is at the same place
# with both necks, so the helmet's bodies and couplings are the same -------------------------
HELMET_HEADER = """\
# The Hybrid III 50th-class rider (%(base)s, included) wearing a full-face motorcycle
# helmet: MYMOSA's multibody helmet (FISITA 2010-SC-P-02
# Sec. 3.3, after Gilchrist & Mills' 1-D model): the head is the headform (M2); the helmet is a
# shell (M1a) and an EPS liner (M1b) coupled by spring-dampers -- shell deformation k1/n1
# (shell-liner) and the liner's elastic deformation k2/n2 (liner-head, MYMOSA's spring-damper
# "between the headform CG and its replica on the helmet") -- and the liner's crushing (MYMOSA's
# "liner yield") is the plateau of the shell's contact characteristic against an obstacle (the
# anvil M3 of the drop test: the car, the road). Mass 1.4 kg in all: full-face helmets of the
# ECE 22.05 class weigh about 1.3-1.7 kg (makers' data sheets [S]); the split 1.0 kg shell
# (with chin bar and visor) / 0.4 kg liner and comfort padding, and every stiffness, are [A]:
# docs/rider.md "Helmet". The bodies are named rider_helmet_* so that seating the rider moves
# them with the head (stage1_mb/mb_position.c). Each coupling is three zero-length
# spring-dampers at non-collinear points (so it carries moments too), at rest in the seated
# posture, that never break.
# Generated by scripts/gen_rider.py -- edit the script, not this file.
"""

HELMET_BODY = """\
mcrash: 1
include: [%(base)s]
name: "%(title)s"
characteristics:
  # the shell against an obstacle: shell contact stiffness, then the EPS liner's crushing plateau
  # (~5-7 kN for a flat anvil, of the order of the ECE 22.05 275 g limit x 5 kg headform = 13 kN
  # not reached), then bottoming; crushing is permanent (unloading 2 MN/m)
  helmet_shell:
    loading: [[0, 0], [3 mm, 3 kN], [8 mm, 5.5 kN], [30 mm, 7 kN], [38 mm, 30 kN]]
    unloading_slope: 2e6 N/m
    elastic_limit: 2 mm
    damping: 100 N s/m
bodies:
  - name: rider_helmet_shell      # shell, chin bar, visor: a thin shell r ~0.15 m, I = 2/3 m r^2
    mass: 1.0 kg
    inertia: [0.015, 0.015, 0.015]
    position: [0.51, 0, 1.669]    # 30 mm above and 10 mm behind the head CG (the reference posture)
    velocity: [0, 0, 0]
    surfaces:
      - {name: rider_helmet_shell, type: ellipsoid, center: [0.01, 0, -0.01], semi_axes: [0.16, 0.13, 0.16], characteristic: helmet_shell}
  - name: rider_helmet_liner      # EPS liner and comfort padding, r ~0.12 m
    mass: 0.4 kg
    inertia: [0.0038, 0.0038, 0.0038]
    position: [0.51, 0, 1.664]
    velocity: [0, 0, 0]
attachments:
  # liner on the head (k2, n2: the liner's and comfort foam's elastic deformation): 3 x 100 kN/m
  - {name: rider_helmet_liner_head_1, a: rider_helmet_liner, b: rider_head, point_a: [0.06, 0, 0], point_b: [0, 0, 0], stiffness: 1e5 N/m, damping: 60 N s/m, failure_force: 1e9 N}
  - {name: rider_helmet_liner_head_2, a: rider_helmet_liner, b: rider_head, point_a: [-0.04, 0.06, 0], point_b: [0, 0, 0], stiffness: 1e5 N/m, damping: 60 N s/m, failure_force: 1e9 N}
  - {name: rider_helmet_liner_head_3, a: rider_helmet_liner, b: rider_head, point_a: [-0.04, -0.06, 0.05], point_b: [0, 0, 0], stiffness: 1e5 N/m, damping: 60 N s/m, failure_force: 1e9 N}
  # shell on the liner (k1, n1: the shell's deformation): 3 x 300 kN/m
  - {name: rider_helmet_shell_liner_1, a: rider_helmet_shell, b: rider_helmet_liner, point_a: [0.06, 0, 0], point_b: [0, 0, 0], stiffness: 3e5 N/m, damping: 80 N s/m, failure_force: 1e9 N}
  - {name: rider_helmet_shell_liner_2, a: rider_helmet_shell, b: rider_helmet_liner, point_a: [-0.04, 0.06, 0], point_b: [0, 0, 0], stiffness: 3e5 N/m, damping: 80 N s/m, failure_force: 1e9 N}
  - {name: rider_helmet_shell_liner_3, a: rider_helmet_shell, b: rider_helmet_liner, point_a: [-0.04, -0.06, 0.05], point_b: [0, 0, 0], stiffness: 3e5 N/m, damping: 80 N s/m, failure_force: 1e9 N}
"""


# ---- MYMOSA's own rider (issue 11): 73.25 kg with the helmet, 179 cm, 7-vertebra neck
# [seed 002, Table 1.1 and Sec. 3.1]. The helmet is one of MYMOSA's 24 bodies, so 73.25 kg
# includes it: every segment mass and inertia of the H3-class neck7 rider is scaled by
# (73.25 - 1.4) / 78.2 = 0.9188 (same geometry, so the inertias scale with the mass); the
# stature stays 1.75 m (MYMOSA's 1.79 m, 2 % taller, is not modelled: the same seated posture
# and reach to the grips), joint restraints and contact laws unchanged.
MYMOSA_MASS = 73.25     # MYMOSA dummy with its helmet [kg] [seed 002 Table 1.1]
HELMET_MASS = 1.4       # the helmet bodies of HELMET_BODY [kg]

MYMOSA_HEADER = """\
# MYMOSA's rider (issue 11): %s
# Generated by scripts/gen_rider.py -- edit the script, not this file. MYMOSA's dummy weighs
# 73.25 kg with its helmet, stature 1.79 m, 7-vertebra neck [seed 002, Table 1.1, Sec. 3.1]:
# the Hybrid III 50th-class 7-vertebra rider (hybrid3_50th_neck7.yaml: de Leva 1996 fractions,
# docs/rider.md) with every segment mass and inertia scaled by (73.25 - 1.4) / 78.2 = 0.9188
# (1.4 kg: the helmet, mymosa_50th_neck7_helmet.yaml), geometry, stature (1.75 m), joint
# restraints and contact laws unchanged. Reference posture and seating as hybrid3_50th.yaml."""


def scale_masses(md, k):
    md.bodies = [(n, m * k, tuple(i * k for i in I), cg, sf, c + " x%.4f (MYMOSA mass)" % k)
                 for n, m, I, cg, sf, c in md.bodies]
    return md


SIZE_HEADER = """\
# Hybrid III %(title)s-class rider (issue 13 item 6): 17 segments, single neck, %(mass).2f kg
# Generated by scripts/gen_rider.py -- edit the script, not this file. Sources and every
# scaling: docs/rider.md "Sizes". %(src)s
# Segment CG, inertia radii and joint layout: the 50th-class rider's (hybrid3_50th.yaml, de Leva
# 1996) with its lengths scaled: trunk, neck and head heights x %(kt).4f, arms x %(ka).4f, legs
# x %(kl).4f, breadths and depths x %(kw).4f, head x %(kh).4f; inertias m (r L)^2 of the new
# masses and lengths. Contact characteristics and joint restraints: the 50th's scaled by Mertz's
# dimensional analysis with lambda = %(lam).4f (stature ratio): deflection x lambda, force and
# contact damping x lambda^2, restraint moment x lambda^3 (the neck's x %(neck_k).4g: %(neck_src)s),
# rotational damping x lambda^4 [scaled]; the comments below the scaling are the 50th's.
# Reference posture and seating as hybrid3_50th.yaml: the same `rider:` block seats it."""


MASS_NOTE_05F = {
    "rider_head": "[N5] head 8.23 lb", "rider_neck": "[N5] neck 2.0 lb",
    "rider_upper_torso": "[N5] upper torso 26.5 lb",
    "rider_lower_torso": "[N5] lower torso 29.2 lb x de Leva's middle/lower trunk split",
    "rider_pelvis": "[N5] lower torso 29.2 lb x de Leva's middle/lower trunk split",
    "rider_upper_arm": "[N5] upper arms 5.2 lb / 2",
    "rider_lower_arm": "[N5] lower arms and hands 5.2 lb / 2 x de Leva's forearm/hand split",
    "rider_hand": "[N5] lower arms and hands 5.2 lb / 2 x de Leva's forearm/hand split",
    "rider_thigh": "[N5] upper legs 13.8 lb / 2",
    "rider_lower_leg": "[N5] lower legs and feet 17.9 lb / 2 x de Leva's shank/foot split",
    "rider_foot": "[N5] lower legs and feet 17.9 lb / 2 x de Leva's shank/foot split",
}


def mass_note(name, table, default):
    """the mass source of body `name`: table's entry for it or its side-less stem"""
    stem = name[:-2] if name[-2:] in ("_l", "_r") else name
    return table.get(name, table.get(stem, default))


def write_size(path, z, title, src, lam, neck_k, neck_src, notes=None, default_note=""):
    md = build(False, z)
    md.bodies = [(n, m, I, cg, sf, "geometry: %s; mass: %s" % (c, mass_note(n, notes or {},
                                                                              default_note)))
                 for n, m, I, cg, sf, c in md.bodies]
    mass = sum(b[1] for b in md.bodies)
    hdr = SIZE_HEADER % dict(title=title, mass=mass, src=src, kt=z.kt, ka=z.ka, kl=z.kl,
                             kw=z.kw, kh=z.kh, lam=lam, neck_k=neck_k, neck_src=neck_src)
    return write(md, path, "Hybrid III %s-class rider, 17 segments, %.2f kg" % (title, mass),
                 hdr, scale_chars(lam, neck_k))


def write_helmet(path, base, title):
    with open(path, "w") as fh:
        fh.write(HELMET_HEADER % {"base": base} + HELMET_BODY % {"base": base, "title": title})


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenarios", "models", "riders")
    os.makedirs(root, exist_ok=True)
    t1 = write(build(False), os.path.join(root, "hybrid3_50th.yaml"),
               "Hybrid III 50th-class rider, 17 segments, 78.2 kg",
               HEADER % "17 segments, single neck")
    t2 = write(build(True), os.path.join(root, "hybrid3_50th_neck7.yaml"),
               "Hybrid III 50th-class rider, 7-vertebra neck (MYMOSA), 23 segments, 78.2 kg",
               HEADER % "23 segments, MYMOSA's 7-vertebra neck (C7..C1)")
    print("masses: %.4f kg, %.4f kg" % (t1, t2))
    write_helmet(os.path.join(root, "hybrid3_50th_helmet.yaml"), "hybrid3_50th.yaml",
                 "Hybrid III 50th-class rider with a full-face helmet, 1.4 kg: shell and liner on "
                 "the headform (MYMOSA 3-mass helmet)")
    write_helmet(os.path.join(root, "hybrid3_50th_neck7_helmet.yaml"), "hybrid3_50th_neck7.yaml",
                 "Hybrid III 50th-class rider, 7-vertebra neck (MYMOSA), with a full-face helmet, "
                 "1.4 kg: shell and liner on the headform (MYMOSA 3-mass helmet)")
    k = (MYMOSA_MASS - HELMET_MASS) / M_TOTAL
    t3 = write(scale_masses(build(True), k), os.path.join(root, "mymosa_50th_neck7.yaml"),
               "MYMOSA-class rider, 7-vertebra neck, 23 segments, 71.85 kg (73.25 kg with the helmet)",
               MYMOSA_HEADER % "23 segments, 7-vertebra neck, masses scaled to 73.25 kg with the helmet")
    print("MYMOSA rider: %.4f kg + helmet %.1f kg" % (t3, HELMET_MASS))
    write_helmet(os.path.join(root, "mymosa_50th_neck7_helmet.yaml"), "mymosa_50th_neck7.yaml",
                 "MYMOSA-class rider, 73.25 kg, 7-vertebra neck, with a full-face helmet, 1.4 kg "
                 "(MYMOSA 3-mass helmet)")
    hp = os.path.join(root, "mymosa_50th_neck7_helmet.yaml")
    with open(hp) as fh:
        txt = fh.read().replace("# The Hybrid III 50th-class rider (", "# MYMOSA's rider (", 1)
    with open(hp, "w") as fh:
        fh.write(txt)
    write_head_drop(os.path.join(root, "..", "..", "verification", "h3_head_drop_572_32.yaml"))
    t5 = write_size(os.path.join(root, "hybrid3_05f.yaml"), size_05f(), "5th female",
                    "Masses: the NHTSA H3 5th female\n# assembly weights (108.03 lb = 49.00 kg); "
                    "stature 59.1 in, sitting height 31.0 in (NHTSA).",
                    H3_05_STATURE_IN / H3_50_STATURE_IN, 155.0 / 310.0,
                    "Myc 155/310 N m, FMVSS 208", MASS_NOTE_05F)
    t95 = write_size(os.path.join(root, "hybrid3_95m.yaml"), size_95m(), "95th male",
                     "Mass 223 lb = 101.15 kg, stature 74 in\n# (188 cm) [S]; no 95th segment "
                     "table retrieved [scaled]: head %.3f kg (the 5th/50th\n# head-to-body "
                     "exponent %.3f), every other 50th segment mass x %.4f." % (
                         size_95m().masses["head"], head_exponent(),
                         size_95m().masses["upt"] / masses_50th()["upt"]),
                     H3_95_STATURE_IN / H3_50_STATURE_IN,
                     (H3_95_STATURE_IN / H3_50_STATURE_IN) ** 3, "lambda^3, no 95th Myc retrieved",
                     {"rider_head": "the 5th/50th head exponent [scaled]"},
                     "the 50th's x %.4f [scaled]" % (size_95m().masses["upt"] / masses_50th()["upt"]))
    print("5th female: %.4f kg, 95th male: %.4f kg" % (t5, t95))


if __name__ == "__main__":
    main()
