#!/usr/bin/python3
"""Independent check of tread's CAN codec against its DBC files with python3-canmatrix.

usage: dbc_crosscheck.py CODEC_VECTORS DBC_DIR

1. tread -> canmatrix: frames encoded by tread's codec from random values are decoded by canmatrix
   from the DBC; every signal must equal tread's own decoding, and the E2E CRC (computed here by an
   independent CRC-8/SAE-J1850) must match.
2. canmatrix -> tread: frames encoded by canmatrix from random physical values (CRC and counter
   computed here) are decoded by tread; values must match within half a quantisation step and every
   frame must pass tread's E2E check.
Prints 'dbc_crosscheck: N passed, M failed' and exits non-zero on any failure.
"""
import decimal
import json
import logging
import random
import subprocess
import sys
import tempfile

logging.disable(logging.CRITICAL)
import canmatrix.formats  # noqa: E402
from e2e_crc import e2e_crc  # noqa: E402  (next to this script)

D = decimal.Decimal


def main():
    vectors, dbc_dir = sys.argv[1], sys.argv[2]
    passed = failed = 0

    def check(ok, what):
        nonlocal passed, failed
        if ok:
            passed += 1
        else:
            failed += 1
            print("FAIL:", what)

    for layout in ("classic", "fd"):
        db = canmatrix.formats.loadp_flat(f"{dbc_dir}/tread_{layout}.dbc")
        check(len(db.frames) > 0, f"{layout}: DBC has frames")

        # 1. tread encodes, canmatrix decodes.
        out = subprocess.run([vectors, "encode", layout, "7", "40"], check=True,
                             capture_output=True, text=True).stdout
        for line in out.splitlines():
            rec = json.loads(line)
            frame = db.frame_by_id(canmatrix.ArbitrationId(rec["id"]))
            payload = bytes.fromhex(rec["data"])
            check(frame is not None and frame.name == rec["message"], f"{layout}: frame {rec['id']:#x} in DBC")
            check(frame.size == len(payload), f"{rec['message']}: length {len(payload)} vs DBC {frame.size}")
            check(bool(frame.is_fd) == rec["fd"], f"{rec['message']}: FD flag")
            check(payload[0] == e2e_crc(rec["id"], payload), f"{rec['message']}: CRC")
            decoded = frame.decode(payload)
            for name, value in rec["values"].items():
                sig = decoded[name].signal
                ref = decoded[name].phys_value
                tol = float(sig.factor) * 1e-3 + abs(float(ref)) * 2e-7
                check(abs(float(ref) - value) <= tol,
                      f"{rec['message']}.{name}: canmatrix {ref} vs tread {value}")

        # 2. canmatrix encodes, tread decodes.
        rng = random.Random(11)
        lines, expected = [], []
        counters = {}
        for _ in range(40):
            for frame in db.frames:
                if "Rig" not in frame.transmitters:
                    continue
                values = {}
                for sig in frame.signals:
                    if sig.name in ("CRC", "Counter"):
                        values[sig.name] = D(0)
                    elif sig.factor == 1 and sig.offset == 0:
                        values[sig.name] = D(rng.randint(int(sig.min), int(sig.max)))
                    else:
                        values[sig.name] = D(repr(rng.uniform(float(sig.min), float(sig.max))))
                fid = frame.arbitration_id.id
                counter = counters.get(fid, 0)
                counters[fid] = (counter + 1) % 15
                values["Counter"] = D(counter)
                # Frame.encode takes raw values: convert with canmatrix's own phys2raw.
                raw = {sig.name: sig.phys2raw(values[sig.name]) for sig in frame.signals}
                payload = bytearray(frame.encode(raw))
                payload[0] = e2e_crc(fid, payload)
                sep = "##0" if frame.is_fd else "#"
                lines.append(f"{fid:03X}{sep}{payload.hex().upper()}")
                expected.append((frame, values, frame.decode(bytes(payload))))
        with tempfile.NamedTemporaryFile("w", suffix=".log", delete=False) as f:
            f.write("\n".join(lines) + "\n")
            path = f.name
        out = subprocess.run([vectors, "decode", layout, path], check=True,
                             capture_output=True, text=True).stdout.splitlines()
        check(len(out) == len(expected), f"{layout}: tread decoded every frame")
        for line, (frame, values, cm_decoded) in zip(out, expected):
            rec = json.loads(line)
            check(rec["e2e_ok"], f"{frame.name}: tread's E2E check accepts canmatrix's frame")
            for sig in frame.signals:
                if sig.name in ("CRC",):
                    continue
                got = rec["values"][sig.name]
                # Same bytes, same DBC: tread must read what canmatrix reads ...
                ref = float(cm_decoded[sig.name].phys_value)
                check(abs(got - ref) <= float(sig.factor) * 1e-3 + abs(ref) * 2e-7,
                      f"{frame.name}.{sig.name}: canmatrix reads {ref}, tread {got}")
                # ... and that is the value sent, to within one step (canmatrix truncates).
                step = float(sig.factor) * 1.0001 + abs(float(values[sig.name])) * 2e-7
                check(abs(got - float(values[sig.name])) <= step,
                      f"{frame.name}.{sig.name}: sent {values[sig.name]}, tread {got}")

    print(f"dbc_crosscheck: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
