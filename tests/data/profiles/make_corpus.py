#!/usr/bin/env python3
"""Writes the profile-file test corpus of tests/data/profiles (see data/PROVENANCE.md).

Inputs: s1002.csv (tread's own S1002 construction, `tread profile --family S1002 --step 0.1
--format csv`) and the Manchester benchmark rail tests/data/rail/manchester_benchmark/
MBench_UIC60_v3.prr (UIC60 inclined 1:40). Every variant is derived deterministically (a fixed
linear congruential generator for the noise), so running this again gives the same files.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
MANCHESTER = os.path.join(HERE, "..", "rail", "manchester_benchmark", "MBench_UIC60_v3.prr")


class Lcg:
    def __init__(self, seed):
        self.state = seed

    def uniform(self):  # in [-1, 1)
        self.state = (1103515245 * self.state + 12345) % 2**31
        return 2.0 * self.state / 2**31 - 1.0


def read_wheel():
    ys, zs = [], []
    with open(os.path.join(HERE, "s1002.csv")) as f:
        next(f)
        for line in f:
            y, z, _ = line.split(",")
            ys.append(float(y))
            zs.append(float(z))
    return ys, zs


def read_manchester_upright():
    """The Manchester UIC60 (SIMPACK z down, inclined 1:40) turned upright, z up."""
    ys, zs = [], []
    inside = False
    with open(MANCHESTER) as f:
        for line in f:
            t = line.split("!")[0].strip()
            if t == "point.begin":
                inside = True
            elif t == "point.end":
                inside = False
            elif inside and t:
                a, b = t.split()[:2]
                ys.append(float(a))
                zs.append(-float(b))
    th = math.atan(1.0 / 40.0)  # uncant: rotate by -1:40
    c, s = math.cos(th), math.sin(th)
    return [c * y + s * z for y, z in zip(ys, zs)], [-s * y + c * z for y, z in zip(ys, zs)]


def write_csv(name, ys, zs, header="y_mm,z_mm", sep=","):
    with open(os.path.join(HERE, name), "w") as f:
        if header:
            f.write(header + "\n")
        for y, z in zip(ys, zs):
            f.write("%.9f%s%.9f\n" % (y, sep, z))


def interp(ys, zs, y):
    for k in range(1, len(ys)):
        if ys[k] >= y:
            t = (y - ys[k - 1]) / (ys[k] - ys[k - 1])
            return zs[k - 1] + t * (zs[k] - zs[k - 1])
    return zs[-1]


def main():
    wy, wz = read_wheel()
    # The clean originals.
    write_csv("s1002_clean.csv", wy, wz)
    ry, rz = read_manchester_upright()
    assert all(b > a for a, b in zip(ry, ry[1:]))
    write_csv("uic60_upright_clean.csv", ry, rz)

    # Wheel given z down and mirrored (y toward the flange), decreasing order, no header, ';'.
    write_csv("s1002_zdown_mirrored.csv", [-y for y in wy], [-z for z in wz], header=None,
              sep=";")

    # Wheel with its y origin 4 mm outside the flange back (y from 4 to 144 mm), tab separated.
    write_csv("s1002_offset.csv", [y + 74.0 for y in wy], wz, header="y_mm\tz_mm", sep="\t")

    # MiniProf-style wheel: X from the flange back, Y up (flange down); the back face measured
    # from 6 mm below the flange's back down to the flange; noise of +-0.002 mm in Y; every 40th
    # point followed by one 0.004 mm behind it in X.
    rng = Lcg(13)
    pts = []
    for k in range(16):  # the vertical back face, X = 0, from Y = 6 up to the flange
        pts.append((0.0, 6.0 - k * (6.0 + wz[0]) / 16.0))
    for k, (y, z) in enumerate(zip(wy, wz)):
        x = y + 70.0
        pts.append((x, -z + 0.002 * rng.uniform()))
        if k % 40 == 20:
            xb = x - 0.004
            pts.append((xb, -interp(wy, wz, xb - 70.0) + 0.002 * rng.uniform()))
    with open(os.path.join(HERE, "s1002_measured.whl"), "w") as f:
        f.write("Filename=s1002_measured.whl\n")
        f.write("Date=2026-11-25\n")
        f.write("Instrument=synthetic (tread test corpus)\n")
        f.write("Side=Left\n")
        f.write("ColumnDef=X,Y\n")
        f.write("Points=%d\n" % len(pts))
        f.write("\n")
        for x, yv in pts:
            f.write("%.4f %.4f\n" % (x, yv))

    # MiniProf-style rail: upright UIC60, columns in the order Y,X with a flags column, 3 points
    # stepping back 0.003 mm in X, noise of +-0.001 mm.
    rng = Lcg(60)
    rows = []
    for k, (y, z) in enumerate(zip(ry, rz)):
        rows.append((y, z + 0.001 * rng.uniform()))
        if k in (100, 250, 400):
            rows.append((y - 0.003, interp(ry, rz, y - 0.003)))
    with open(os.path.join(HERE, "uic60_measured.ban"), "w") as f:
        f.write("# synthetic MiniProf-style rail (tread test corpus)\n")
        f.write("Filename=uic60_measured.ban\n")
        f.write("ColumnDef=Y, X, Flags\n")
        f.write("\n")
        for x, yv in rows:
            f.write("%.5f, %.5f, 0\n" % (yv, x))

    # CONTACT-style .prr with '%' comments: the upright UIC60 head down to 16 mm below its top on
    # the gauge side (y < 0), then an undercut back under the head and down.
    top = max(rz)
    k16 = next(k for k in range(len(ry)) if rz[k] >= top - 16.0)
    hy = ry[k16:]
    hz = rz[k16:]
    y16, z16 = hy[0], hz[0]
    under = [(y16 + 1.5, z16 - 3.0), (y16 + 2.0, z16 - 6.0), (y16 + 2.0, z16 - 10.0),
             (y16 + 0.5, z16 - 14.0)]
    pts = list(reversed(under)) + list(zip(hy, hz))
    with open(os.path.join(HERE, "uic60_undercut.prr"), "w") as f:
        f.write("% CONTACT-style SIMPACK rail profile (tread test corpus)\n")
        f.write("% UIC60 upright with an undercut gauge face below 16 mm\n")
        f.write("header.begin\n  version = 1\n  type = 0   % 0 = rail\nheader.end\n")
        f.write("spline.begin\n  units.len.f = 1000.   % mm\n  point.begin\n")
        for y, z in pts:
            f.write("  %.9f %.9f\n" % (y, -z))  # SIMPACK z down
        f.write("  point.end\nspline.end\n")


if __name__ == "__main__":
    main()
