#!/usr/bin/env bash
# Regenerates the reference data the project ships (data/tyres/, tests/data/) from the originals in
# a refdata directory (default ../shared/refdata), in the project's own formats:
#   - .tir files rewritten by `tread tir convert` (sections, keys, values and table rows; none of the
#     original comments), the Chrono PAC89 JSON as a PAC89 .tir;
#   - CSV tables as numbers: the column-name line kept, the originals' comment lines dropped;
#   - SIMPACK profiles read by tread's reader and written by its writer (`tread profile --input`).
# data/PROVENANCE.md says where each file came from. Run after a change to the originals or to the
# writers; `git diff` then shows what moved. Needs the host build (`cmake --build --preset host`).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
src=${1:-../shared/refdata}
tread=${TREAD:-build/host/sim/tread}
[[ -d $src ]] || { echo "import-refdata: no refdata directory '$src'" >&2; exit 1; }
[[ -x $tread ]] || { echo "import-refdata: build tread first ($tread)" >&2; exit 1; }

mkdir -p data/tyres tests/data/mfeval tests/data/rail/en13715 tests/data/rail/en15302 \
  tests/data/rail/manchester_benchmark tests/data/tyres

for f in "$src"/tir/*.tir; do
  name=$(basename "$f")
  "$tread" tir convert "$f" "data/tyres/$name" \
    --note "$name: numbers as published (see data/PROVENANCE.md); rewritten by tread tir convert" 2>/dev/null
done
"$tread" tir convert "$src/tir/chrono_HMMWV_Pac89Tire.json" data/tyres/chrono_HMMWV_Pac89Tire.tir \
  --note "chrono_HMMWV_Pac89Tire: Chrono's PAC89 JSON coefficients (see data/PROVENANCE.md) as a PAC89 .tir" \
  2>/dev/null

# The Chrono JSON reader's test input: the same numbers in Chrono's key layout, without its comments.
/usr/bin/python3 - "$src/tir/chrono_HMMWV_Pac89Tire.json" tests/data/tyres/chrono_HMMWV_Pac89Tire.json <<'PY'
import json, re, sys
text = open(sys.argv[1]).read()
text = re.sub(r'//[^\n]*', '', text)  # Chrono allows // comments; JSON does not
data = json.loads(text)
with open(sys.argv[2], 'w') as out:
    json.dump(data, out, indent=2)
    out.write('\n')
PY

# CSV: drop comment lines except a trailing column-name comment ("# a_mm,b_mm,...").
strip_csv() {
  awk 'BEGIN { names = "" }
       /^#/ { line = $0; sub(/^# */, "", line);
              if (line ~ /^[A-Za-z_][A-Za-z0-9_.]*(,[A-Za-z_][A-Za-z0-9_.]*)+$/) print "# " line;
              next }
       { print }' "$1" >"$2"
}
for f in "$src"/mfeval/*.csv; do strip_csv "$f" "tests/data/mfeval/$(basename "$f")"; done
for f in "$src"/rail/en13715/*.csv; do strip_csv "$f" "tests/data/rail/en13715/$(basename "$f")"; done
for f in "$src"/rail/en15302/*.csv; do strip_csv "$f" "tests/data/rail/en15302/$(basename "$f")"; done

"$tread" profile --input "$src/rail/manchester_benchmark/MBench_S1002_v3.prw" --format prw \
  --output tests/data/rail/manchester_benchmark/MBench_S1002_v3.prw
"$tread" profile --input "$src/rail/manchester_benchmark/MBench_UIC60_v3.prr" --format prr \
  --output tests/data/rail/manchester_benchmark/MBench_UIC60_v3.prr
# The other EN 15302 Annex I wheels are generated from their analytic pieces (no original file).
python3 scripts/en15302-wheels.py tests/data/rail/en15302
echo "import-refdata: data/tyres and tests/data regenerated from $src"
