#!/usr/bin/env python3
"""Samples the EN 15302:2021 Annex I reference wheels A, B, C, H and I into tests/data/rail/en15302.

Each wheel is a chain of analytic pieces over the lateral coordinate y (mm, from the running
circle, negative toward the flange); z (mm) is the rolling-radius increase (positive toward the
flange tip), i.e. r(y) = r0 + z(y). Pieces:
  ("line", z0, s)           z = z0 + s * y
  ("arc", zc, R, yc, sign)  z = zc + sign * sqrt(R^2 - (y - yc)^2)
The numbers are those published in the standard as transcribed in rohrbecka/EN15302 (see
data/PROVENANCE.md); at a joint the piece on the flange side is used. Sampled like WheelA.csv:
y = -70.00 ... 65.00 every 0.01 mm, y with 4 and z with 6 decimals.
Usage: scripts/en15302-wheels.py [OUTDIR] [WHEEL...]   (default: tests/data/rail/en15302, B C H I)
"""
import math
import os
import sys

# (y_end, piece): each piece holds from the previous y_end (or -70) up to its own y_end.
WHEELS = {
    "A": [
        (-62.7647, ("arc", 9.51926, 20.5, -49.5, +1)),
        (-49.6625, ("arc", 16.00065, 12.0, -55.0, +1)),
        (-39.7645, ("arc", 8.83556, 20.0, -58.5583, +1)),
        (-38.7372, ("line", -93.57685, -2.7475)),
        (-29.4591, ("arc", 17.64215, 14.0, -25.5816, -1)),
        (-10.8749, ("arc", 97.16493, 96.76055, -2.6594, -1)),
        (18.4173, ("arc", 344.50806, 345.0, 18.4173, -1)),
        (30.0, ("line", -0.49194, 0.0)),
        (60.0, ("line", 1.50804, -0.066666)),
        (65.0, ("line", 57.50808, -1.0)),
    ],
    "B": [
        (-62.7647, ("arc", 9.5193, 20.5, -49.5, +1)),
        (-49.6625, ("arc", 16.0, 12.0, -55.0, +1)),
        (-39.7640, ("arc", 8.8349, 20.0, -58.5583, +1)),
        (-38.7879, ("line", -93.5767, -2.7475)),
        (-29.3505, ("arc", 17.7814, 14.0, -25.6322, -1)),
        (-0.4787, ("arc", 119.9745, 120.0, 2.5204, -1)),
        (30.0, ("line", 0.0, -0.025)),
        (60.0, ("line", 0.75, -0.05)),
        (65.0, ("line", 57.75, -1.0)),
    ],
    # Wheel C: the transcription says it corrected the standard's formula for the last piece
    # (59 ... 65 mm), which it found faulty; its version is used here.
    "C": [
        (-69.4027, ("line", 21.39173 + 7.11537 * 69.40268, 7.11537)),
        (-59.5000, ("arc", 20.00006, 10.0, -59.5, +1)),
        (-43.8048, ("arc", 12.02753, 18.0, -60.4941, +1)),
        (-41.0534, ("line", 11.96051 - 2.47508685 * 41.05339, -2.47508685)),
        (-32.3621, ("arc", 16.830365, 13.0, -29.0, -1)),
        (-17.5870, ("arc", 100.870534, 100.0, -6.5, -1)),
        (19.0, ("arc", 329.45258, 330.0, 19.0, -1)),
        (29.0, ("line", -0.54742374, 0.0)),
        (59.0, ("line", -0.54742374 + 2.9, -0.1)),
        (65.0, ("line", -3.54742374 + 59.0, -1.0)),
    ],
    "H": [
        (-62.7647, ("arc", 9.5193, 20.5, -49.5, +1)),
        (-49.6625, ("arc", 16.0, 12.0, -55.0, +1)),
        (-39.7645, ("arc", 8.8349, 20.0, -58.5583, +1)),
        (-38.7220, ("line", -93.5767, -2.7475)),
        (-28.3119, ("arc", 17.6003, 14.0, -25.5663, -1)),
        (-10.2297, ("line", -1.7902, -0.2)),
        (30.0, ("line", 0.0, -0.025)),
        (60.0, ("line", 1.251, -0.0667)),
        (65.0, ("line", 57.249, -1.0)),
    ],
    "I": [
        (-62.7647, ("arc", 9.51929, 20.5, -49.5, +1)),
        (-49.6625, ("arc", 16.00054, 12.0, -55.0, +1)),
        (-39.7640, ("arc", 8.83545, 20.0, -58.5583, +1)),
        (-39.0486, ("line", -93.5767, -2.7475)),
        (-29.9231, ("arc", 18.49733, 14.0, -25.8929, -1)),
        (5.0, ("arc", math.sqrt(14375.0), 120.0, 5.0, -1)),
        (30.0, ("line", math.sqrt(14375.0) - 120.0, 0.0)),
        (60.0, ("line", 1.89679, -0.0667)),
        (65.0, ("line", 57.89479, -1.0)),
    ],
}


def z_of(pieces, y):
    for y_end, piece in pieces:
        if y <= y_end + 1e-9:
            break
    if piece[0] == "line":
        return piece[1] + piece[2] * y
    _, zc, radius, yc, sign = piece
    return zc + sign * math.sqrt(max(radius * radius - (y - yc) ** 2, 0.0))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "tests/data/rail/en15302"
    names = sys.argv[2:] or ["B", "C", "H", "I"]
    for name in names:
        path = os.path.join(out, f"Wheel{name}.csv")
        with open(path, "w") as f:
            f.write("y_mm,z_mm\n")
            for i in range(13501):
                y = -70.0 + 0.01 * i
                f.write(f"{y:.4f},{z_of(WHEELS[name], y):.6f}\n")
        print(f"en15302-wheels: wrote {path}")


if __name__ == "__main__":
    main()
