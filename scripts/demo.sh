#!/bin/sh
# make demo: check every shipped scenario, run the ISO 13232 413-0/13.4 pair with the seated
# Hybrid III 50th-class rider (the 208 kg motorcycle at 13.4 m/s into the side of a stationary
# 1668 kg sedan at 90 deg): the conventional motorcycle and the one with the rider restraint
# concept (thigh belts, front airbag, leg protectors), and print both injury tables side by
# side; then the thesis' frontal rigid-barrier impact (motorcycle only); results, a short
# text report and one HTML page per run (`mcrash report`, out/report/) go to out/.
set -u
MCRASH=${1:-bin/mcrash}
OUT=out
SCN=scenarios/iso13232_413-0_13.4_sedan_rider.yaml
SCNC=scenarios/iso13232_413-0_13.4_sedan_rider_concept.yaml
BAR=scenarios/thesis_frontal_barrier_13.4.yaml
mkdir -p "$OUT"
echo "== mcrash demo =="
"$MCRASH" --version
for s in scenarios/*.yaml scenarios/*/*.yaml scenarios/*/*/*.yaml; do
    [ -e "$s" ] || continue
    # an include fragment (no mcrash: key) is checked through the scenarios that include it
    grep -q '^mcrash:' "$s" || continue
    "$MCRASH" check "$s" >/dev/null || exit 2
done
echo "all shipped scenarios pass 'mcrash check' (include fragments through their includers)"

echo "== stage 1: $SCN"
"$MCRASH" run "$SCN" -o "$OUT/iso413.h5" --stage 1 --json --quiet >"$OUT/iso413.json" || exit 1
"$MCRASH" export "$OUT/iso413.h5" --csv "$OUT/iso413_csv" >/dev/null || exit 1
"$MCRASH" export "$OUT/iso413.h5" --xdmf >/dev/null || exit 1
echo "== stage 1: $SCNC"
# one FE thread unless asked otherwise: its few hundred elements step every 10 us, where a
# second thread's per-step barrier costs more than it shares (same results either way)
OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} "$MCRASH" run "$SCNC" -o "$OUT/iso413_concept.h5" --stage 1 \
    --json --quiet >"$OUT/iso413_concept.json" || exit 1
"$MCRASH" export "$OUT/iso413_concept.h5" --xdmf >/dev/null || exit 1
echo "== stage 1: $BAR"
"$MCRASH" run "$BAR" -o "$OUT/frontal_barrier.h5" --stage 1 --json --quiet \
    >"$OUT/frontal_barrier.json" || exit 1
"$MCRASH" export "$OUT/frontal_barrier.h5" --csv "$OUT/frontal_barrier_csv" >/dev/null || exit 1
"$MCRASH" export "$OUT/frontal_barrier.h5" --xdmf >/dev/null || exit 1
echo "== report pages"
for r in iso413 iso413_concept frontal_barrier; do
    "$MCRASH" report "$OUT/$r.h5" -o "$OUT/report" || exit 1
done
{
    echo "mcrash demo report"
    echo "ISO 13232 413-0/13.4, conventional: $SCN"
    echo "run summary: $(cat "$OUT/iso413.json")"
    echo "ISO 13232 413-0/13.4, restraint concept: $SCNC"
    echo "run summary: $(cat "$OUT/iso413_concept.json")"
    echo "injury tables side by side ([1] conventional, [2] restraint concept):"
    "$MCRASH" injury "$OUT/iso413.h5" "$OUT/iso413_concept.h5" || exit 1
    echo "results: $OUT/iso413.h5 (ParaView: $OUT/iso413.xmf; CSV: $OUT/iso413_csv/)," \
         "$OUT/iso413_concept.h5 (ParaView: $OUT/iso413_concept.xmf: bodies, belts, bag, foam)"
    echo
    echo "thesis frontal rigid barrier: $BAR"
    echo "run summary: $(cat "$OUT/frontal_barrier.json")"
    echo "frame acceleration (resultant, CFC 60):"
    "$MCRASH" signal a3ms "$OUT/frontal_barrier_csv/stage1_channels.csv"
    echo "results: $OUT/frontal_barrier.h5 (ParaView: $OUT/frontal_barrier.xmf;" \
         "CSV: $OUT/frontal_barrier_csv/)"
    echo
    echo "HTML pages (plots, injury bars, snapshots): $OUT/report/iso413.html," \
         "$OUT/report/iso413_concept.html, $OUT/report/frontal_barrier.html"
} >"$OUT/demo_report.txt" || exit 1
cat "$OUT/demo_report.txt"
