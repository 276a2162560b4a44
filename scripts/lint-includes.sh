#!/usr/bin/env bash
# Fails if an #include points where its layer may not look (STYLE.md, "Layering"), printing
# one line per offence: `file:line: include "x" points up or sideways`. One function per
# language; each prints its offences and returns 1 if it found any.
set -euo pipefail
cd "$(dirname "$0")/.."

# Shaders: a file in shaders/<family>/ includes only its own folder and shaders/common/;
# shaders/common/ includes only itself. An include resolves as gl/ShaderLibrary resolves it:
# from the including file's folder if the file exists there, else from shaders/.
lint_shaders() {
    /usr/bin/python3 - <<'PYTHON'
import os
import re
import sys

ROOT = "shaders"
COMMON = os.path.join(ROOT, "common")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"\s*$')

def resolve(including_dir, target):
    beside = os.path.normpath(os.path.join(including_dir, target))
    from_root = os.path.normpath(os.path.join(ROOT, target))
    if os.path.exists(beside) or not os.path.exists(from_root):
        return beside
    return from_root

offences = 0
for directory, _, files in sorted(os.walk(ROOT)):
    allowed = {os.path.normpath(directory), COMMON}
    if os.path.normpath(directory) == COMMON:
        allowed = {COMMON}
    for name in sorted(files):
        path = os.path.join(directory, name)
        with open(path, encoding="utf-8", errors="replace") as source:
            for number, line in enumerate(source, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = resolve(directory, match.group(1))
                if os.path.dirname(target) not in allowed:
                    print(f'{path}:{number}: include "{match.group(1)}" points up or sideways')
                    offences += 1
sys.exit(1 if offences else 0)
PYTHON
}

status=0
lint_shaders || status=1
if [ "$status" -ne 0 ]; then
    echo "lint-includes: includes above point outside their layer (see STYLE.md, 'Layering')" >&2
    exit 1
fi
echo "lint-includes: every include stays within its layer"
