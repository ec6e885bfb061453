#!/usr/bin/env bash
# Usage: check_rules.sh KESTREL GRAPH
# GRAPH breaks declared parameter rules on purpose. `kestrel validate` must refuse it (exit 3) and
# report every rule the graph lists as "# expect: LINE:COL: MESSAGE", at that position, and no
# other broken rule.
set -uo pipefail
kestrel=$1 graph=$2
out=$("$kestrel" validate "$graph" 2>&1)
rc=$?
if [ "$rc" -ne 3 ]; then
  echo "kestrel validate exited $rc, not 3 (invalid graph):"
  echo "$out"
  exit 1
fi
fail=0 expected=0
while IFS= read -r expect; do
  expected=$((expected + 1))
  if ! grep -qxF "$graph:$expect" <<<"$out"; then
    echo "not reported: $graph:$expect"
    fail=1
  fi
done < <(sed -n 's/^# expect: //p' "$graph")
if [ "$expected" -eq 0 ]; then
  echo "$graph lists no '# expect:' line"
  exit 1
fi
reported=$(grep -c "break the rule" <<<"$out")
if [ "$reported" -ne "$expected" ]; then
  echo "$expected broken rule(s) expected, $reported reported"
  fail=1
fi
if [ "$fail" -ne 0 ]; then
  echo "--- kestrel validate said:"
  echo "$out"
fi
exit "$fail"
