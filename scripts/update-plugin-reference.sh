#!/usr/bin/env bash
# Rewrites docs/plugins.md's parameter tables (between its parameter markers) from
# the plugins' declarations, as `caustica plugins` prints them. The test
# `registry` fails until this has been run after a declaration changed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh" >/dev/null
/usr/bin/python3 - "$root" <<'PY'
import subprocess, sys
root = sys.argv[1]
tables = subprocess.run([root + "/build/caustica", "plugins"], check=True, capture_output=True, text=True).stdout
path = root + "/docs/plugins.md"
text = open(path).read()
begin, end = "<!-- parameters: begin -->\n", "<!-- parameters: end -->"
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(path, "w").write(head + begin + tables + end + tail)
PY
