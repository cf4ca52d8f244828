#!/usr/bin/env bash
# Runs every ```bash example of the README, block by block in their order, as written, in a
# scratch folder that has the build's binary at build/gbssn1d and the repository's plots/ and
# runs/ (the README's commands are written from the repository's top folder). Not run: the two
# set-up commands of the first block (the demo and this very test suite, each run by CI
# itself) and the Slurm submission line (tests/cluster/slurm_sweep.sh submits the same --wrap
# form to a real Slurm). GNU parallel lines run where parallel is installed (CI installs it).
# A block whose run prints a warning fails unless one of its lines explains it ('# warns: ...').
# Usage: run_examples.sh README BUILD_DIR SOURCE_DIR SCRATCH
set -euo pipefail
readme=$1 build=$2 source=$3 scratch=$4
rm -rf "$scratch" && mkdir -p "$scratch"
ln -s "$build" "$scratch/build"
ln -s "$source/plots" "$scratch/plots"
ln -s "$source/runs" "$scratch/runs"
python3 - "$readme" "$scratch" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
blocks = re.findall(r"```bash\n(.*?)```", text, re.S)
kept = 0
for k, block in enumerate(blocks):
    lines = [l.strip() for l in block.splitlines()]
    if any('runs/demo.sh' in l or 'tests/run' in l or 'sbatch' in l for l in lines):
        continue
    open(f"{sys.argv[2]}/block{k:02d}.sh", 'w').write('\n'.join(lines) + '\n')
    kept += 1
print(f"{kept} of {len(blocks)} README example blocks to run")
PY
cd "$scratch"
for b in block*.sh; do
  if grep -q '^parallel ' "$b" && ! command -v parallel >/dev/null 2>&1; then
    echo "$b: GNU parallel is not installed; its lines are run one by one by bash instead"
    sed -i 's/^parallel -j [0-9]* < \(.*\)$/bash \1/' "$b"
  fi
  echo "== $b"
  if ! bash -euo pipefail "$b" >"$b.log" 2>&1; then
    echo "README example failed: $b"
    cat "$b"
    tail -20 "$b.log"
    exit 1
  fi
  # a warning the README does not explain (a line of the block saying '# warns: ...') is a
  # broken example too: a newcomer pasting it would not know what to make of it
  if grep -q "warning" "$b.log" && ! grep -q "# warns:" "$b"; then
    echo "README example warns without saying why: $b"
    cat "$b"
    grep "warning" "$b.log"
    exit 1
  fi
done
echo "every README example ran"
