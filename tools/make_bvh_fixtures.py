#!/usr/bin/env python3
"""Regenerates fixtures/bvh/*.bvh and fixtures/bad/*.bvh from the shared corpus.

    python3 tools/make_bvh_fixtures.py [shared-data-dir]

Every fixture is a short cut of a real capture (CMU 01_01, Bandai-Namco walk_normal_001,
Assimp Boxing_Toes) or a variant of such a cut for one corner case. Variants keep the
motion identical: the mixed-order file converts each joint's angles to its new Euler
order with the math below (independent of the C++ code it tests), printed with repr() so
the rotations agree to ~1e-13 degrees. Output is deterministic.
"""
import math
import os
import random
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "..", "shared", "data")
OUT = os.path.join(ROOT, "fixtures")

AXES = "XYZ"
ORDERS = ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"]


class Bvh:
    """A BVH split into header lines, the frame-time line and rows of value strings."""

    def __init__(self, path):
        with open(path, newline="") as f:
            lines = f.read().splitlines()
        motion = lines.index("MOTION")
        self.header = lines[:motion]
        self.frame_time_line = lines[motion + 2]
        self.rows = [line.split() for line in lines[motion + 3:] if line.strip()]
        # (joint name, header line index of CHANNELS, channel list) in file order.
        self.joints = []
        name = None
        for i, line in enumerate(self.header):
            words = line.split()
            if words and words[0] in ("ROOT", "JOINT"):
                name = line.strip().split(None, 1)[1]
            elif words and words[0] == "CHANNELS":
                self.joints.append((name, i, words[2:2 + int(words[1])]))

    def text(self, rows, frames_line=None, newline="\n", final_newline=True):
        frames_line = frames_line or "Frames: %d" % len(rows)
        lines = self.header + ["MOTION", frames_line, self.frame_time_line] + [" ".join(r) for r in rows]
        return newline.join(lines) + (newline if final_newline else "")


def quat_mul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw)


def euler_to_quat(angles_deg, order):
    q = (1.0, 0.0, 0.0, 0.0)
    for angle, axis in zip(angles_deg, order):
        h = math.radians(angle) / 2
        e = [0.0, 0.0, 0.0]
        e[AXES.index(axis)] = math.sin(h)
        q = quat_mul(q, (math.cos(h), e[0], e[1], e[2]))
    return q


def quat_to_matrix(q):
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def matrix_to_euler(r, order, previous):
    """Tait-Bryan angles (degrees) of R = R_i(a) R_j(b) R_k(c), nearest to `previous`."""
    i, j, k = (AXES.index(c) for c in order)
    s = 1.0 if (j - i) % 3 == 1 else -1.0
    b = math.asin(max(-1.0, min(1.0, s * r[i][k])))
    a = math.atan2(-s * r[j][k], r[k][k])
    c = math.atan2(-s * r[i][j], r[i][i])
    first = [math.degrees(a), math.degrees(b), math.degrees(c)]
    second = [first[0] + 180, 180 - first[1], first[2] + 180]
    if previous is None:
        return first
    best = None
    for candidate in (first, second):
        wrapped = [v + 360 * round((p - v) / 360) for v, p in zip(candidate, previous)]
        cost = sum(abs(v - p) for v, p in zip(wrapped, previous))
        if best is None or cost < best[0]:
            best = (cost, wrapped)
    return best[1]


def write(relative, text, binary=False):
    path = os.path.join(OUT, relative)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(text if binary else text.encode())


def rename(header, old, new):
    return [l.replace("ROOT " + old, "ROOT " + new).replace("JOINT " + old, "JOINT " + new)
            if l.strip() in ("ROOT " + old, "JOINT " + old) else l for l in header]


def mixed_orders(cmu, rows):
    """Each joint gets ORDERS[n % 6]; angles converted so every rotation is unchanged."""
    out = Bvh.__new__(Bvh)
    out.header = list(cmu.header)
    out.frame_time_line = cmu.frame_time_line
    new_rows = [[] for _ in rows]
    previous = {}
    column = 0
    for n, (name, line, channels) in enumerate(cmu.joints):
        order = ORDERS[n % 6]
        old_order = "".join(c[0] for c in channels if c.endswith("rotation"))
        positions = [c for c in channels if c.endswith("position")]
        indent = out.header[line][:len(out.header[line]) - len(out.header[line].lstrip())]
        names = positions + [a + "rotation" for a in order]
        out.header[line] = indent + "CHANNELS %d %s" % (len(names), " ".join(names))
        for f, row in enumerate(rows):
            values = row[column:column + len(channels)]
            pos = [v for v, c in zip(values, channels) if c.endswith("position")]
            angles = [float(v) for v, c in zip(values, channels) if c.endswith("rotation")]
            q = euler_to_quat(angles, old_order)
            new = matrix_to_euler(quat_to_matrix(q), order, previous.get(name))
            previous[name] = new
            new_rows[f] += pos + [repr(v) for v in new]
        column += len(channels)
    return out, new_rows


def two_roots(cmu, rows, shift):
    """A second copy of the skeleton ('B:' names) whose root is shifted along X."""
    out = Bvh.__new__(Bvh)
    copy = [l for l in cmu.header[1:]]
    for name, _, _ in cmu.joints:
        copy = rename(copy, name, "B:" + name)
    out.header = cmu.header + copy
    out.frame_time_line = cmu.frame_time_line
    new_rows = []
    for row in rows:
        second = list(row)
        second[0] = repr(float(row[0]) + shift)
        new_rows.append(row + second)
    return out, new_rows


def interleaved(boxing, rows):
    """Hips channels interleaved; Ab gains 6 channels and Chest a Y position (both constant = OFFSET)."""
    out = Bvh.__new__(Bvh)
    out.header = list(boxing.header)
    out.frame_time_line = boxing.frame_time_line
    hips, ab, chest = boxing.joints[0], boxing.joints[1], boxing.joints[2]
    offsets = {}
    for name, line, _ in (ab, chest):
        offsets[name] = out.header[line - 1].split()[1:4]
    hips_layout = ["Zrotation", "Xposition", "Xrotation", "Yposition", "Zposition", "Yrotation"]
    ab_layout = ["Zrotation", "Xposition", "Xrotation", "Yposition", "Yrotation", "Zposition"]
    chest_layout = ["Yposition", "Zrotation", "Xrotation", "Yrotation"]
    for (name, line, _), layout in ((hips, hips_layout), (ab, ab_layout), (chest, chest_layout)):
        text = out.header[line]
        indent = text[:len(text) - len(text.lstrip())]
        out.header[line] = indent + "CHANNELS %d %s" % (len(layout), " ".join(layout))
    new_rows = []
    for row in rows:
        h = dict(zip(hips[2], row[0:6]))
        a = dict(zip(ab[2], row[6:9]))
        a.update(zip(["Xposition", "Yposition", "Zposition"], offsets[ab[0]]))
        c = dict(zip(chest[2], row[9:12]))
        c["Yposition"] = offsets[chest[0]][1]
        new_rows.append([h[x] for x in hips_layout] + [a[x] for x in ab_layout] + [c[x] for x in chest_layout] +
                        row[12:])
    return out, new_rows


def main():
    cmu = Bvh(os.path.join(DATA, "cmu", "01_01.bvh"))
    bandai = Bvh(os.path.join(DATA, "bandai-namco-1", "data", "dataset-1_walk_normal_001.bvh"))
    boxing = Bvh(os.path.join(DATA, "assimp", "Boxing_Toes.bvh"))

    write("bvh/cmu_01_01_short.bvh", cmu.text(cmu.rows[:60]))
    write("bvh/bandai_walk_normal_001_short.bvh", bandai.text(bandai.rows[:40], "Frames:\t40"))
    # Keeps the original's quirks: one row more than declared, padded header, no final newline.
    write("bvh/boxing_toes_short.bvh", boxing.text(boxing.rows[:80], "Frames:    79", final_newline=False))

    write("bvh/cmu_crlf.bvh", cmu.text(cmu.rows[:20], newline="\r\n"))
    mixed, mixed_rows = mixed_orders(cmu, cmu.rows[:20])
    write("bvh/cmu_mixed_orders.bvh", mixed.text(mixed_rows))
    roots, roots_rows = two_roots(cmu, cmu.rows[:10], 50.0)
    write("bvh/cmu_two_roots.bvh", roots.text(roots_rows))
    names = Bvh.__new__(Bvh)
    names.header = bandai.header
    for old, new in (("joint_Root", "mixamorig:Root"), ("Spine", "Spine Lower"), ("Chest", "Bip01 Spine1"),
                     ("Hand_L", "Left Hand:Palm.001"), ("Toes_R", "mixamorig:Right Toe")):
        names.header = rename(names.header, old, new)
    names.frame_time_line = bandai.frame_time_line
    write("bvh/bandai_names.bvh", names.text(bandai.rows[:10]))
    inter, inter_rows = interleaved(boxing, boxing.rows[:10])
    write("bvh/boxing_interleaved.bvh", inter.text(inter_rows))

    rows3 = [list(r) for r in cmu.rows[:3]]
    truncated = cmu.text(rows3)
    write("bad/truncated.bvh", truncated[:truncated.rindex("\n", 0, len(truncated) - 1) + 1] +
          " ".join(rows3[2][:40]))
    nan_rows = [list(r) for r in rows3]
    nan_rows[1][10] = "nan"
    write("bad/nan_value.bvh", cmu.text(nan_rows))
    inf_rows = [list(r) for r in rows3]
    inf_rows[2][5] = "-inf"
    write("bad/inf_value.bvh", cmu.text(inf_rows))
    bad = Bvh.__new__(Bvh)
    bad.frame_time_line = cmu.frame_time_line
    line = cmu.joints[1][1]
    bad.header = list(cmu.header)
    bad.header[line] = bad.header[line].replace("CHANNELS 3", "CHANNELS 4")
    write("bad/wrong_channel_count.bvh", bad.text(rows3))
    bad.header = list(cmu.header)
    line = cmu.joints[2][1]
    bad.header[line] = bad.header[line].replace("Xrotation", "Wrotation")
    write("bad/unknown_channel.bvh", bad.text(rows3))
    write("bad/zero_frames.bvh", cmu.text([], "Frames: 0"))
    write("bad/absurd_frames.bvh", cmu.text(rows3[:2], "Frames: 1000000000000"))
    bad.header = list(cmu.header)
    end_site_close = bad.header.index("\t\t\t\t\t\t}")
    del bad.header[end_site_close]
    write("bad/missing_brace.bvh", bad.text(rows3))
    rng = random.Random(20240601)
    write("bad/garbage.bvh", bytes(rng.randrange(256) for _ in range(1024)), binary=True)


if __name__ == "__main__":
    main()
