#!/usr/bin/env python3
"""Writes fixtures/rigs/*.bvh: one small BVH per naming family the shared corpus lacks, built
from published skeleton layouts (sources in fixtures/README.md, section rigs/). Deterministic:
the same files on every run. Every file holds 3 frames of the rig's own rest pose (all
rotations zero) with the root at its rest height, in centimetres, Y up, facing +Z.

    python3 tools/make_rig_fixtures.py            # writes fixtures/rigs/
"""
import os

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fixtures", "rigs")
FRAMES = 3


def write_bvh(path, joints, root_position, end_sites):
    """joints: list of (name, parent_name or None, offset_cm (x, y, z)) in depth-first order."""
    children = {}
    for name, parent, _ in joints:
        children.setdefault(parent, []).append(name)
    offsets = {name: off for name, _, off in joints}
    lines = ["HIERARCHY"]
    order = []

    def emit(name, depth):
        pad = "\t" * depth
        order.append(name)
        lines.append(f"{pad}{'ROOT' if depth == 0 else 'JOINT'} {name}")
        lines.append(pad + "{")
        x, y, z = offsets[name]
        lines.append(f"{pad}\tOFFSET {x:.4f} {y:.4f} {z:.4f}")
        if depth == 0:
            lines.append(f"{pad}\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation")
        else:
            lines.append(f"{pad}\tCHANNELS 3 Zrotation Xrotation Yrotation")
        kids = children.get(name, [])
        for kid in kids:
            emit(kid, depth + 1)
        if not kids:
            ex, ey, ez = end_sites.get(name, (0.0, 0.0, 0.0))
            lines.append(f"{pad}\tEnd Site")
            lines.append(pad + "\t{")
            lines.append(f"{pad}\t\tOFFSET {ex:.4f} {ey:.4f} {ez:.4f}")
            lines.append(pad + "\t}")
        lines.append(pad + "}")

    emit(children[None][0], 0)
    lines.append("MOTION")
    lines.append(f"Frames: {FRAMES}")
    lines.append("Frame Time: 0.0333333")
    row = [f"{v:.4f}" for v in root_position] + ["0.0000"] * (3 + 3 * (len(order) - 1))
    for _ in range(FRAMES):
        lines.append(" ".join(row))
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


# --- Mixamo: 20tab/bvh-python, tests/test_freebvh.bvh (MIT); offsets in cm as published. ---
# Body, eyes, head top and the index finger of each hand (the other fingers left out).
def mixamo():
    p = "mixamorig:"
    j = [
        ("Hips", None, (0, 0, 0)),
        ("Spine", "Hips", (0.0000, 9.9235, -1.2273)),
        ("Spine1", "Spine", (-0.0001, 11.6455, -1.4224)),
        ("Spine2", "Spine1", (0.0001, 13.3602, -1.6265)),
        ("Neck", "Spine2", (0.0000, 15.0325, 0.7929)),
        ("Head", "Neck", (-0.0000, 10.3218, 3.1424)),
        ("HeadTop_End", "Head", (0.0002, 18.4747, 6.6364)),
        ("LeftEye", "Head", (2.9479, 7.6817, 9.1207)),
        ("RightEye", "Head", (-2.9445, 7.6817, 9.1205)),
        ("LeftShoulder", "Spine2", (6.1059, 9.1104, 0.7056)),
        ("LeftArm", "LeftShoulder", (12.6532, -0.3431, -2.6009)),
        ("LeftForeArm", "LeftArm", (27.3517, -0.9645, -1.4034)),
        ("LeftHand", "LeftForeArm", (27.5619, -0.7072, 1.5500)),
        ("LeftHandIndex1", "LeftHand", (11.9722, -1.1061, 3.7324)),
        ("LeftHandIndex2", "LeftHandIndex1", (3.8387, -0.6406, -0.0310)),
        ("LeftHandIndex3", "LeftHandIndex2", (3.3346, -0.7374, -0.0133)),
        ("RightShoulder", "Spine2", (-6.1057, 9.1105, 0.7056)),
        ("RightArm", "RightShoulder", (-12.6532, -0.3429, -2.6009)),
        ("RightForeArm", "RightArm", (-27.3518, -0.9642, -1.4034)),
        ("RightHand", "RightForeArm", (-27.5619, -0.7068, 1.5501)),
        ("RightHandIndex1", "RightHand", (-11.9722, -1.1059, 3.7324)),
        ("RightHandIndex2", "RightHandIndex1", (-3.8387, -0.6406, -0.0310)),
        ("RightHandIndex3", "RightHandIndex2", (-3.3346, -0.7373, -0.0133)),
        ("RightUpLeg", "Hips", (-9.1245, -6.6564, -0.0554)),
        ("RightLeg", "RightUpLeg", (0.0000, -40.5610, -1.7662)),
        ("RightFoot", "RightLeg", (0.4978, -41.9625, -3.3512)),
        ("RightToeBase", "RightFoot", (-0.3734, -10.4922, 12.6406)),
        ("LeftUpLeg", "Hips", (9.1245, -6.6564, -0.0554)),
        ("LeftLeg", "LeftUpLeg", (-0.0000, -40.5610, -1.7662)),
        ("LeftFoot", "LeftLeg", (-0.4978, -41.9625, -3.3512)),
        ("LeftToeBase", "LeftFoot", (0.3734, -10.4922, 12.6406)),
    ]
    joints = [(p + n, (p + q) if q else None, o) for n, q, o in j]
    ends = {p + "RightToeBase": (0, 0, 9.9925), p + "LeftToeBase": (0, 0, 9.9925),
            p + "LeftHandIndex3": (2.9714, -0.8030, 0.0009), p + "RightHandIndex3": (-2.9715, -0.8029, 0.0009)}
    # Root position of the source's frame 0 (its hips height, 98.29 cm).
    write_bvh(os.path.join(OUT, "mixamo_prefixed.bvh"), joints, (-0.2399, 98.2948, -0.5224), ends)


# --- Rigify: blender/blender-addons, rigify/metarigs/Basic/basic_human.py (GPL-2.0-or-later),
# commit f1c55295b0d95307559c1f8b09d6b8bd6c8bbbf0: metarig bone heads and tails in metres,
# Blender Z up facing -Y. DEF bones as Rigify generates them: limbs split in two segments (the
# ".001" halves start at the bone's midpoint).
RIGIFY_BONES = {  # name: (head, tail, parent)
    "spine": ((0.0, 0.0552, 1.0099), (0.0, 0.0172, 1.1573), None),
    "spine.001": ((0.0, 0.0172, 1.1573), (0.0, 0.0004, 1.2929), "spine"),
    "spine.002": ((0.0, 0.0004, 1.2929), (0.0, 0.0059, 1.4657), "spine.001"),
    "spine.003": ((0.0, 0.0059, 1.4657), (0.0, 0.0114, 1.6582), "spine.002"),
    "spine.004": ((0.0, 0.0114, 1.6582), (0.0, -0.0130, 1.7197), "spine.003"),
    "spine.005": ((0.0, -0.0130, 1.7197), (0.0, -0.0247, 1.7813), "spine.004"),
    "spine.006": ((0.0, -0.0247, 1.7813), (0.0, -0.0247, 1.9796), "spine.005"),
    "pelvis.L": ((0.0, 0.0552, 1.0099), (0.1112, -0.0451, 1.1533), "spine"),
    "thigh.L": ((0.0980, 0.0124, 1.0720), (0.0980, -0.0286, 0.5372), "spine"),
    "shin.L": ((0.0980, -0.0286, 0.5372), (0.0980, 0.0162, 0.0852), "thigh.L"),
    "foot.L": ((0.0980, 0.0162, 0.0852), (0.0980, -0.0934, 0.0167), "shin.L"),
    "toe.L": ((0.0980, -0.0934, 0.0167), (0.0980, -0.1606, 0.0167), "foot.L"),
    "shoulder.L": ((0.0183, -0.0684, 1.6051), (0.1694, 0.0205, 1.6050), "spine.003"),
    "upper_arm.L": ((0.1953, 0.0267, 1.5846), (0.4424, 0.0885, 1.4491), "shoulder.L"),
    "forearm.L": ((0.4424, 0.0885, 1.4491), (0.6594, 0.0492, 1.3061), "upper_arm.L"),
    "hand.L": ((0.6594, 0.0492, 1.3061), (0.7234, 0.0412, 1.2585), "forearm.L"),
}
RIGIFY_TWO_SEGMENTS = {"thigh.L", "shin.L", "upper_arm.L", "forearm.L"}


def rigify():
    bones = dict(RIGIFY_BONES)
    for name in [n for n in bones if n.endswith(".L")]:  # mirror the left side
        h, t, p = bones[name]
        mirror = lambda v: (-v[0], v[1], v[2])
        rp = p[:-2] + ".R" if p and p.endswith(".L") else p
        bones[name[:-2] + ".R"] = (mirror(h), mirror(t), rp)
    to_yup = lambda v: (v[0] * 100, v[2] * 100, -v[1] * 100)  # Blender (x, y, z) -> Y up: (x, z, -y), cm
    heads, tails, parents = {}, {}, {}
    order = []

    def add(name, head, tail, parent):
        heads[name], tails[name], parents[name] = head, tail, parent
        order.append(name)

    def deform_end(name):  # the DEF bone a child of `name` hangs from (the second half if split)
        return "DEF-" + name + (".001" if name in RIGIFY_TWO_SEGMENTS or name.replace(".R", ".L") in RIGIFY_TWO_SEGMENTS else "")

    def visit(name):
        h, t, p = bones[name]
        parent = deform_end(p) if p else None
        if name in RIGIFY_TWO_SEGMENTS or name.replace(".R", ".L") in RIGIFY_TWO_SEGMENTS:
            mid = tuple((a + b) / 2 for a, b in zip(h, t))
            add("DEF-" + name, h, mid, parent)
            add("DEF-" + name + ".001", mid, t, "DEF-" + name)
        else:
            add("DEF-" + name, h, t, parent)
        for child in [n for n in bones if bones[n][2] == name]:
            visit(child)

    visit("spine")
    joints, ends = [], {}
    has_child = {parents[n] for n in order}
    for n in order:
        p = parents[n]
        off = (0.0, 0.0, 0.0) if p is None else tuple(a - b for a, b in zip(to_yup(heads[n]), to_yup(heads[p])))
        joints.append((n, p, off))
        if n not in has_child:
            ends[n] = tuple(a - b for a, b in zip(to_yup(tails[n]), to_yup(heads[n])))
    root = to_yup(heads["DEF-spine"])
    write_bvh(os.path.join(OUT, "rigify_def.bvh"), joints, root, ends)


# --- SMPL body joints: T-pose joint positions (metres, Y up, facing +Z) as printed in
# luebbertevan/kikitora-internship, src/retarget.py (J_ABSOLUTE, first 22 rows = the SMPL body
# joints), the same offsets as edoardocompagnucci/HSyn9DHPE's SMPL_BONE_OFFSETS_22. SMPL's
# L_Hand/R_Hand (joints 22, 23) are the wrists plus the offsets of ZhengyiLuo/PHC,
# phc/data/assets/mjcf/smpl_humanoid.xml (commit fe5aaa946a9c1f183bbf10f181004b517a5e560c,
# BSD-3-Clause): MuJoCo body positions in metres to 4 decimals, written as (z, x, y) of SMPL's
# Y-up axes; their other body offsets equal J_ABSOLUTE's differences within 1e-4 m (same template).
PHC_HAND_OFFSETS = {"L_Hand": (-0.0149, 0.084, -0.0082), "R_Hand": (-0.0103, -0.0846, -0.0061)}  # as printed: z x y
SMPL_NAMES = ["Pelvis", "L_Hip", "R_Hip", "Spine1", "L_Knee", "R_Knee", "Spine2", "L_Ankle", "R_Ankle", "Spine3",
              "L_Foot", "R_Foot", "Neck", "L_Collar", "R_Collar", "Head", "L_Shoulder", "R_Shoulder", "L_Elbow",
              "R_Elbow", "L_Wrist", "R_Wrist", "L_Hand", "R_Hand"]
SMPL_PARENTS = [-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21]
SMPL_J = [
    (-0.001795, -0.223333, 0.028219), (0.067725, -0.314740, 0.021404), (-0.069466, -0.313855, 0.023899),
    (-0.004328, -0.114370, 0.001523), (0.102001, -0.689938, 0.016908), (-0.107756, -0.696424, 0.015049),
    (0.001159, 0.020810, 0.002615), (0.088406, -1.087899, -0.026785), (-0.091982, -1.094839, -0.027263),
    (0.002616, 0.073732, 0.028040), (0.114764, -1.143690, 0.092503), (-0.117354, -1.142983, 0.096085),
    (-0.000162, 0.287603, -0.014817), (0.081461, 0.195482, -0.006050), (-0.079143, 0.192565, -0.010575),
    (0.004990, 0.352572, 0.036532), (0.172438, 0.225951, -0.014918), (-0.175155, 0.225116, -0.019719),
    (0.432050, 0.213179, -0.042374), (-0.428897, 0.211787, -0.041119), (0.681284, 0.222165, -0.043545),
    (-0.684196, 0.219560, -0.046679),
]
for _name, (_z, _x, _y) in PHC_HAND_OFFSETS.items():
    _wrist = SMPL_J[SMPL_PARENTS[SMPL_NAMES.index(_name)]]
    SMPL_J.append((_wrist[0] + _x, _wrist[1] + _y, _wrist[2] + _z))


def smpl():
    cm = lambda v: tuple(100 * x for x in v)
    joints = []
    # Depth-first order as the BVH nests them (children in index order).
    def visit(i):
        p = SMPL_PARENTS[i]
        off = (0.0, 0.0, 0.0) if p < 0 else cm(tuple(a - b for a, b in zip(SMPL_J[i], SMPL_J[p])))
        joints.append((SMPL_NAMES[i], SMPL_NAMES[p] if p >= 0 else None, off))
        for c in range(len(SMPL_NAMES)):
            if SMPL_PARENTS[c] == i:
                visit(c)
    visit(0)
    floor = min(v[1] for v in SMPL_J)
    root = cm((SMPL_J[0][0], SMPL_J[0][1] - floor, SMPL_J[0][2]))
    write_bvh(os.path.join(OUT, "smpl_body.bvh"), joints, root, {})


# --- Unreal Engine naming (root/pelvis/spine_01/thigh_l/calf_l/ball_l ...), on a CC0 character:
# Quaternius "Universal Base Characters", Superhero_Male.glb as kept in GitHub
# Dallolz/moorfall-assets, characters/Superhero_Male.glb (added in commit
# 43824dae24b04fea6254b96e9edb12157cfcde11; the repository's LICENSE.md: CC0 1.0, models by
# Quaternius). Node transforms copied from the file's glTF JSON (metres; rotations x, y, z, w;
# the root node turns Blender's Z up into glTF's Y up). The rest pose is the bind pose (every
# joint's world matrix times its inverse bind matrix is the identity within 5e-7). Body bones
# only: fingers, the *_leaf end bones and the node scales (1 within 2e-6) are left out.
UE_NODES = [  # name, parent, translation, rotation (x, y, z, w)
    ("root", None, (0.0, 0.0, 0.0), (-0.7071067690849304, 0.0, 0.0, 0.7071067690849304)),
    ("pelvis", "root", (0.0, 0.042999982833862305, 0.9491000175476074), (0.8005710244178772, 0.0, 0.0, 0.5992379188537598)),
    ("spine_01", "pelvis", (0.0, 0.1280922144651413, -3.259629011154175e-08), (-0.09185619652271271, 0.0, 0.0, 0.9957723021507263)),
    ("spine_02", "spine_01", (0.0, 0.10634974390268326, -1.3969838619232178e-09), (-0.03958535194396973, 0.0, 0.0, 0.9992161989212036)),
    ("spine_03", "spine_02", (0.0, 0.1331336796283722, 0.0), (-0.12418898940086365, 0.0, 0.0, 0.9922585487365723)),
    ("neck_01", "spine_03", (0.0, 0.21509313583374023, 1.862645149230957e-08), (0.25725916028022766, 0.0, 0.0, 0.9663424491882324)),
    ("Head", "neck_01", (0.0, 0.08285234868526459, 9.313225746154785e-09), (-0.13207007944583893, 0.0, 0.0, 0.991240382194519)),
    ("clavicle_l", "spine_03", (0.03139999881386757, 0.1737176477909088, 0.06732845306396484),
     (-0.5287374258041382, -0.32910192012786865, -0.41380804777145386, 0.663996696472168)),
    ("upperarm_l", "clavicle_l", (-0.009135720320045948, 0.20573900640010834, -0.03967121243476868),
     (0.149803027510643, 0.6911307573318481, -0.14938844740390778, 0.6910719275474548)),
    ("lowerarm_l", "upperarm_l", (3.7845666156499647e-08, 0.251115083694458, -5.1513779908418655e-09),
     (0.030732227489352226, 4.16175062127877e-05, -1.2497959005486337e-06, 0.9995276927947998)),
    ("hand_l", "lowerarm_l", (-1.5123794128157897e-07, 0.243594229221344, 2.6994939616997726e-09),
     (-0.015601660124957561, -4.1717584053913015e-07, -9.051257521264233e-09, 0.9998782873153687)),
    ("clavicle_r", "spine_03", (-0.03139999881386757, 0.1737176477909088, 0.06732845306396484),
     (-0.5287374258041382, 0.32910192012786865, 0.41380804777145386, 0.663996696472168)),
    ("upperarm_r", "clavicle_r", (0.009135720320045948, 0.20573900640010834, -0.03967121243476868),
     (0.1498030126094818, -0.6911307573318481, 0.14938844740390778, 0.6910719275474548)),
    ("lowerarm_r", "upperarm_r", (-3.0872001843818e-08, 0.251115083694458, -2.86672729998827e-09),
     (0.030732227489352226, -4.1677081753732637e-05, 1.251685375791567e-06, 0.9995276927947998)),
    ("hand_r", "lowerarm_r", (1.5123667651550932e-07, 0.2435941994190216, 2.032038537436165e-09),
     (-0.015601660124957561, 4.7677681891400425e-07, 8.121838313002172e-09, 0.9998782873153687)),
    ("thigh_l", "pelvis", (0.11430513858795166, 0.023176943883299828, 0.0004878304898738861), (0.9898310303688049, 0.0, 0.0, 0.14224845170974731)),
    ("calf_l", "thigh_l", (-7.450580596923828e-09, 0.4288000166416168, 3.1723175197839737e-09), (0.05598893761634827, 0.0, 0.0, 0.998431384563446)),
    ("foot_l", "calf_l", (0.0, 0.4587883949279785, 5.587935447692871e-09),
     (-0.5721680521965027, 1.9553584706955007e-07, -1.3641555085541768e-07, 0.8201364278793335)),
    ("ball_l", "foot_l", (-4.181756274590498e-09, 0.15907371044158936, -7.893650177948075e-09),
     (6.497470650401738e-08, 0.9731196165084839, -0.23030038177967072, 1.894733969720619e-07)),
    ("thigh_r", "pelvis", (-0.11430513858795166, 0.023176943883299828, 0.0004878304898738861), (0.9898310303688049, 0.0, 0.0, 0.14224845170974731)),
    ("calf_r", "thigh_r", (7.450580596923828e-09, 0.4288000166416168, 3.1723175197839737e-09), (0.05598893761634827, 0.0, 0.0, 0.998431384563446)),
    ("foot_r", "calf_r", (0.0, 0.4587883949279785, 5.587935447692871e-09),
     (-0.5721680521965027, -1.9553584706955007e-07, 1.3641555085541768e-07, 0.8201364278793335)),
    ("ball_r", "foot_r", (4.181756274590498e-09, 0.15907371044158936, -7.893650177948075e-09),
     (6.497470650401738e-08, -0.9731196165084839, 0.23030038177967072, 1.894733969720619e-07)),
]


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def quat_rotate(q, v):
    x, y, z, w = quat_mul(quat_mul(q, (v[0], v[1], v[2], 0.0)), (-q[0], -q[1], -q[2], q[3]))
    return (x, y, z)


def unreal():
    world = {}
    for name, parent, t, r in UE_NODES:
        if parent is None:
            world[name] = ((0.0, 0.0, 0.0), r)
            continue
        pp, pr = world[parent]
        moved = quat_rotate(pr, t)
        world[name] = (tuple(a + b for a, b in zip(pp, moved)), quat_mul(pr, r))
    joints = []
    order = []
    def visit(name):
        order.append(name)
        for child, parent, _, _ in UE_NODES:
            if parent == name:
                visit(child)
    visit("root")
    parents = {name: parent for name, parent, _, _ in UE_NODES}
    for name in order:
        parent = parents[name]
        off = (0.0, 0.0, 0.0) if parent is None else tuple(
            100 * (a - b) for a, b in zip(world[name][0], world[parent][0]))
        joints.append((name, parent, off))
    write_bvh(os.path.join(OUT, "unreal_quaternius.bvh"), joints, (0.0, 0.0, 0.0), {})


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    mixamo()
    rigify()
    smpl()
    unreal()
