#!/usr/bin/env bash
# The cost and accuracy of an amplitude sweep's settings (docs/oscillation.md,
# "Settings, their error and cost"): the same packing sheared at three
# amplitudes — linear (1e-3), at the end of the plateau (0.03), past the
# crossover (0.3) — with the samples per cycle and the integrator's tolerance
# varied one at a time, each against a reference of 128 samples per cycle at a
# tenth of the default tolerance. Prints per setting and amplitude G', G'' and
# I3/I1, their relative differences from the reference (G'' and I3/I1 relative
# to |G*|: the difference that would show in the moduli), and the wall time.
#
# Usage: bench/oscillation_tradeoff.sh [build dir]   (env: N, PHI, OMEGA,
#        MODEL, OUT). Defaults: N = 250, phi = 0.80, omega~ = 2.31e-7 (the
#        castor-oil test), the default model; tens of minutes on one core.
set -euo pipefail
BUILD=${1:-build}
MICRO="$BUILD/micro/micro"
N=${N:-250}
PHI=${PHI:-0.80}
OMEGA=${OMEGA:-2.31e-7}
MODEL=${MODEL:-softglass}
OUT=${OUT:-$(mktemp -d)}
[[ -x "$MICRO" ]] || { echo "build $MICRO first" >&2; exit 1; }
mkdir -p "$OUT"

# setting name, samples per cycle, integrator tolerance (0: the scheme's default)
settings=("reference 128 1e-4" "samples16 16 0" "samples32 32 0" "samples64 64 0"
          "tolerance_x10 64 1e-2")

for s in "${settings[@]}"; do
  read -r name samples tolerance <<<"$s"
  cat > "$OUT/$name.prm" <<EOF
subsection model
  set preset = $MODEL
end
subsection particles
  set number          = $N
  set volume fraction = $PHI
end
subsection integrator
  set tolerance = $tolerance
end
subsection oscillation
  set amplitudes        = 1e-3, 0.03, 0.3
  set frequencies       = $OMEGA
  set samples per cycle = $samples
  set max cycles        = 12
  set output directory  = $OUT/$name
end
EOF
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 "$MICRO" --threads 1 oscillate "$OUT/$name.prm" -q > "$OUT/$name.log"
  echo "$name $(echo "$(date +%s.%N) - $start" | bc)" >> "$OUT/times.txt"
done

/usr/bin/python3 - "$OUT" <<'EOF'
import csv, sys
out = sys.argv[1]

def table(name):
    with open(f"{out}/{name}/oscillation.csv") as f:
        rows = list(csv.reader(l for l in f if not l.startswith("#")))
    head = [h.split(" [")[0] for h in rows[0]]
    return {float(r[head.index("gamma0")]): {h: float(v) for h, v in zip(head, r)} for r in rows[1:]}

times = dict(line.split() for line in open(f"{out}/times.txt"))
ref = table("reference")
print(f"{'setting':>14} {'gamma0':>8} {'G_prime':>11} {'dG_prime':>9} {'G_second':>11} {'dG_second':>9} "
      f"{'I3/I1':>7} {'dI3/I1':>8} {'wall_s':>7}")
for name in ["reference", "samples16", "samples32", "samples64", "tolerance_x10"]:
    t = table(name)
    for g, row in sorted(t.items()):
        r = ref[g]
        scale = (r["storage"] ** 2 + r["loss"] ** 2) ** 0.5
        print(f"{name:>14} {g:8.3g} {row['storage']:11.5g} {(row['storage'] - r['storage']) / scale:+9.2e} "
              f"{row['loss']:11.5g} {(row['loss'] - r['loss']) / scale:+9.2e} "
              f"{row['intensity_3']:7.4f} {row['intensity_3'] - r['intensity_3']:+8.1e} "
              f"{float(times[name]):7.0f}")
EOF
echo "results in $OUT"
