#!/bin/sh
# run every test binary given; each ends with "FILE: N passed, N failed".
# Sum them and end with one line "N passed, N failed"; exit 1 if any failed or crashed.
# OpenMP threads sleep rather than spin while waiting: tests share the machine with builds
# and with each other, and spinning threads of an oversubscribed run cost many times the work
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
passed=0; failed=0
for t in "$@"; do
    out=$("$t" 2>&1); rc=$?
    line=$(printf '%s\n' "$out" | grep -E '^[^ ]+: [0-9]+ passed, [0-9]+ failed$' | tail -n 1)
    if [ -z "$line" ]; then
        printf '%s\n' "$out" | tail -n 30
        echo "$t: crashed or printed no result (exit $rc)"
        failed=$((failed + 1)); continue
    fi
    p=$(echo "$line" | sed -E 's/.*: ([0-9]+) passed, ([0-9]+) failed/\1/')
    f=$(echo "$line" | sed -E 's/.*: ([0-9]+) passed, ([0-9]+) failed/\2/')
    if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then
        printf '%s\n' "$out" | grep -v -E 'passed, [0-9]+ failed$' | tail -n 40
        [ "$f" -eq 0 ] && f=1
    fi
    echo "  $(basename "$t"): $p passed, $f failed"
    passed=$((passed + p)); failed=$((failed + f))
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
