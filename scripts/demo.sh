#!/bin/sh
# make demo: run the richest stage-1 scenario that exists today and print a summary.
# The ISO 13232 413-0/13.4 motorcycle-into-car scenario (issue #4) is not shipped yet; when it
# is, this script runs it and prints its injury table instead.
set -u
MCRASH=${1:-bin/mcrash}
mkdir -p out
echo "== mcrash demo =="
"$MCRASH" --version
for s in scenarios/*.yaml scenarios/*/*.yaml; do
    [ -e "$s" ] || continue
    printf 'check %s: ' "$s"
    "$MCRASH" check "$s" >/dev/null && echo ok
done
for s in two_spheres bounce_elastic pendulum; do
    f=scenarios/verification/$s.yaml
    [ -e "$f" ] || continue
    echo "== stage 1: $f"
    "$MCRASH" run "$f" -o "out/$s.h5" --stage 1 --json --quiet || exit 1
done
echo "results in out/*.h5 (h5ls -r out/two_spheres.h5 lists the /stage1 layout)."
echo "the 413-0/13.4 motorcycle scenario comes later (issue #4: motorcycle, rider, car models)."
