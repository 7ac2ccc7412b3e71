#!/bin/sh
# plot_restraints.sh: the plots of docs/validation_restraints.md. Runs the coupled stage-1
# verification scenarios (scenarios/verification/coupled_*.yaml) with `mcrash run` and draws
# from their results files with gnuplot (apt-get install gnuplot-nox) through
# scripts/validation_restraints.py (h5dump, hdf5-tools):
#   docs/img/restraints_bag.png           force on the plate against the stroke, closed bag
#   docs/img/restraints_limiter.png       body velocity through the load limiter
#   docs/img/restraints_pretensioner.png  body pulled by the pretensioner, Eq. 3
#   docs/img/restraints_foam.png          foam block force against deflection, two rates
#   docs/img/restraints_energy.png        energy balance of each run
# and the ISO 13232 413-0/13.4 pair, conventional and concept (300 ms each; a few minutes),
# through scripts/validation_concept.py:
#   docs/img/concept_{belts,airbag,trajectory,velocity,criteria,energy}.png
# The figures the doc states come from tests/test_validation_restraints.c (`make figures`).
# Usage: scripts/plot_restraints.sh [bin/mcrash] [output directory for the PNGs]
set -eu
MCRASH=${1:-bin/mcrash}
IMG=${2:-docs/img}
WORK=${TMPDIR:-/tmp}/mcrash_restraints.$$
mkdir -p "$WORK" "$IMG"
trap 'rm -rf "$WORK"' EXIT
command -v gnuplot >/dev/null || { echo "plot_restraints: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 2; }
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} # one thread: a 2-thread team waits badly on busy cores
for c in bag_piston belt_limiter belt_pretensioner foam_block foam_impact foam_contact momentum; do
    "$MCRASH" run scenarios/verification/coupled_$c.yaml --stage 1 --quiet -o "$WORK/coupled_$c.h5" >/dev/null
done
python3 scripts/validation_restraints.py "$WORK" "$IMG"
echo "plot_restraints: $IMG/restraints_{bag,limiter,pretensioner,foam,energy}.png"
"$MCRASH" run scenarios/iso13232_413-0_13.4_sedan_rider.yaml --stage 1 --quiet -o "$WORK/conv.h5" >/dev/null
"$MCRASH" run scenarios/iso13232_413-0_13.4_sedan_rider_concept.yaml --stage 1 --quiet -o "$WORK/conc.h5" >/dev/null
python3 scripts/validation_concept.py "$WORK/conv.h5" "$WORK/conc.h5" "$WORK" "$IMG"
echo "plot_restraints: $IMG/concept_{belts,airbag,trajectory,velocity,criteria,energy}.png"
