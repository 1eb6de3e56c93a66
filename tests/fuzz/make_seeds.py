#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora (tests/fuzz/corpus/<target>/) from the repository's own
data: .tir files, profile files, the recorded rig log, and a few hand-written lines. A target whose
input starts with selector bytes (see its source) gets them prepended. Run from anywhere; the
corpora are committed, so this only needs to run again when the data or a target's input layout
changes:  python3 tests/fuzz/make_seeds.py
"""
import pathlib
import shutil

here = pathlib.Path(__file__).resolve().parent
root = here.parent.parent
corpus = here / "corpus"


def target(name):
    d = corpus / name
    if d.exists():
        shutil.rmtree(d)
    d.mkdir(parents=True)
    return d


def write(d, name, data):
    (d / name).write_bytes(data if isinstance(data, bytes) else data.encode())


# .tir: the whole input is the file.
d = target("tir")
for p in sorted((root / "tests/data/tir-variants").glob("*.tir")):
    shutil.copy(p, d / p.name)
for name in ["MagicFormula52_Parameters.tir", "MagicFormula61_Parameters.tir",
             "MagicFormula62_Parameters.tir", "chrono_HMMWV_Pac89Tire.tir",
             "chrono_Sedan_Pac02Tire.tir"]:
    shutil.copy(root / "data/tyres" / name, d / name)

# measurements: byte 0 = reader (0 CSV, 1 TYDEX, 2 input table) + 4 × convention.
d = target("measurement")
csv = ("Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fx_N,Fy_N,Mz_Nm\n"
       "4000,0.05,0,0,16.7,1500,,\n4000,0,0.05,0.01,16.7,,-2500,40\n"
       "# a comment\n\n6000,-0.1,-0.02,0,10,-3000,600,-12\n")
sae = "FZ,SL,SA,IA,V,FX,FY,MZ\nN,1,deg,deg,km/h,N,N,Nm\n4000,0.05,2,0,60,1500,-2500,40\n"
tydex = ("**HEADER\nRELEASE     1.3\n**COMMENTS\nseed\n**CONSTANTS\n"
         "FZW         Vertical load                 N        4000\n**MEASURCHANNELS\n"
         "! name     description                   unit  factor  offsets\n"
         "RUNTIME     Time                          s        1  0  0\n"
         "FZW         Vertical force                kN       1  0  0\n"
         "SLIPANGL    Slip angle                    deg      1  0  0\n"
         "LONGSLIP    Longitudinal slip             %        1  0  0\n"
         "INCLANGL    Inclination angle             deg      1  0  0\n"
         "LONGVEL     Longitudinal velocity         km/h     1  0  0\n"
         "FYW         Lateral force                 N        2  0.5  10\n"
         "MZW         Self aligning moment          Nm       1  0  0\n**MEASURDATA\n"
         "0.0  4.0  2.0  0.0  1.0  36.0  -300  20\n0.1  4.1  -2.0  5.0  0.0  72.0  300  -20\n**END\n")
inputs = "Fz_N;kappa;alpha_rad;gamma_rad;Vx_mps\n4000;0,05;0;0;16,7\n"
write(d, "csv_iso_w", b"\x00" + csv.encode())
write(d, "csv_sae_units_row", b"\x04" + sae.encode())
write(d, "tydex", b"\x01" + tydex.encode())
write(d, "input_table_semicolon", b"\x02" + inputs.encode())
write(d, "input_table_tab", b"\x02" + csv.replace(",", "\t").encode())

# profiles: byte 0 = extension (index into .csv .prw .prr .whl .ban .txt; bit 7 rail),
# byte 1 = format (low 2 bits) and options.
d = target("profile")
ext = {".csv": 0, ".prw": 1, ".prr": 2, ".whl": 3, ".ban": 4}
for p in sorted((root / "tests/data/profiles").iterdir()):
    if p.suffix not in ext:
        continue
    rail = p.name.startswith("uic60")
    a = ext[p.suffix] | (0x80 if rail else 0)
    b = 0x10  # auto format, locate the wheel origin
    if "zdown_mirrored" in p.name:
        b |= 0x04 | 0x08
    write(d, p.name, bytes([a, b]) + p.read_bytes())

# candump logs through the node: byte 0 = FD (1), fixed point (2), E2E repaired (4), sync (8).
d = target("candump_replay")
log = (root / "tests/data/target/sweep_rig.log").read_text().splitlines(keepends=True)
head = "".join(log[:130])
for pick, name in [(0, "classic_float"), (2, "classic_fixed"), (4, "classic_float_repaired"),
                   (6, "classic_fixed_repaired"), (12, "classic_sync_repaired")]:
    write(d, name, bytes([pick]) + head.encode())
write(d, "fd_lines", b"\x01(1.000000) vcan0 120##1" + b"00" * 12 + b"\n(1.001000) vcan0 0F0##0"
      + b"11" * 8 + b"\n(1.001000) vcan0 20000080#0004000000000000\n")

# CAN frames: byte 0 = layout (bit 7 FD) and message index; then the payload.
d = target("can_frames")
for i in range(0, 40, 3):
    write(d, f"classic_{i:02d}", bytes([i]) + bytes((7 * i + 13 * k) & 0xFF for k in range(8)))
    write(d, f"fd_{i:02d}", bytes([0x80 | i]) + bytes((5 * i + 11 * k) & 0xFF for k in range(64)))
write(d, "extremes", bytes([1]) + b"\xff" * 8)

# command-line values: byte 0 = parser (0 number, 1 wheel spec, 2 cant, 3 rail section,
# 4 inclination, 5 wheel family, 6 outer slope, 7 profile format, 8 sign convention).
d = target("cli_values")
values = [(0, "1.5e3"), (0, "-0.25D-03"), (0, "+7"), (1, "S1002"), (1, "S1002:h=28,e=32.5"),
          (1, "EPS:h=30,e=32.5,slope=1:15,width=140,chamfer=1"), (1, "1/40:h=26"), (2, "1:40"),
          (2, "none"), (3, "60E1"), (3, "UIC54"), (4, "1:20"), (5, "EPS"), (6, "6.7"),
          (6, "8.5 %"), (6, "1:12"), (7, "miniprof"), (8, "adapted-iso")]
for i, (pick, text) in enumerate(values):
    write(d, f"{i:02d}", bytes([pick]) + text.encode())
print("seed corpora written to", corpus)
