#!/usr/bin/env python3
"""Fails when an include points up or sideways in the layer order (docs/architecture.md).

C++ (src/): layers, low to high, platform, gl, core, scene, {gi, reference}, render, bench,
app. A file includes its own layer or a lower one; gi and reference are siblings and never
include each other; inside gi, voxel/ and atlas/ never include each other, and gi's own
interface files (src/gi/*.h) include neither. Only gl/ includes the GLSL-shared header
(shaders/common/shared.h, as "common/shared.h").

GLSL (shaders/): shaders/<family>/ includes its own folder and common/ only; common/ includes
only common/.

Prints one line per offence (file:line: what and why) and exits 1; exits 0 when clean.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
LAYER_RANK = {"platform": 0, "gl": 1, "core": 2, "scene": 3, "gi": 4, "reference": 4,
              "render": 5, "bench": 6, "app": 7}
GI_TECHNIQUES = {"voxel", "atlas", "vpl"}


def includes(path):
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        match = INCLUDE.match(line)
        if match:
            yield number, match.group(1)


def cpp_unit(relative):
    """(layer, technique) of a path under src/; technique is '' outside gi's sub-folders."""
    parts = relative.parts
    layer = parts[0]
    technique = parts[1] if layer == "gi" and len(parts) > 2 else ""
    return layer, technique


def cpp_offence(source, target):
    """Why `source` (path under src/) may not include `target` (as written), or None."""
    layer, technique = cpp_unit(source)
    if target.startswith("common/"):
        return None if layer == "gl" else "only gl/ includes the GLSL-shared header"
    target_path = pathlib.PurePosixPath(target)
    if len(target_path.parts) < 2:
        return None   # a file beside the includer
    target_layer, target_technique = cpp_unit(target_path)
    if target_layer not in LAYER_RANK:
        return None   # not a project header
    if layer not in LAYER_RANK:
        return f"{layer}/ is not a layer in the order"
    if target_layer == layer:
        if layer != "gi" or target_technique in ("", technique):
            return None
        if technique == "":
            return "gi's interface must not depend on a technique"
        return f"gi/{technique} and gi/{target_technique} are siblings"
    if LAYER_RANK[target_layer] == LAYER_RANK[layer]:
        return f"{layer} and {target_layer} are siblings"
    if LAYER_RANK[target_layer] > LAYER_RANK[layer]:
        return f"{target_layer} lies above {layer}"
    return None


def glsl_offence(source, target):
    """Why shader `source` (path under shaders/) may not include `target`, or None. The
    include resolves as gl/ShaderLibrary resolves it: beside the including file when such a
    file exists, else from shaders/."""
    beside = ROOT / "shaders" / source.parent / target
    written = pathlib.PurePosixPath(target) if not beside.exists() else source.parent / target
    parts = []
    for part in written.parts:
        if part == "..":
            if not parts:
                return "leaves shaders/"
            parts.pop()
        elif part != ".":
            parts.append(part)
    family = source.parts[0]
    target_family = parts[0] if len(parts) > 1 else ""
    if target_family in (family, "common"):
        return None
    if family == "common":
        return "common/ includes only common/"
    return f"{family}/ includes only its own folder and common/"


def check(tree, suffixes, offence):
    failures = []
    base = ROOT / tree
    for path in sorted(base.rglob("*")):
        if path.suffix not in suffixes or not path.is_file():
            continue
        relative = pathlib.PurePosixPath(path.relative_to(base).as_posix())
        for number, target in includes(path):
            why = offence(relative, target)
            if why:
                failures.append(f'{tree}/{relative}:{number}: include "{target}" points up or '
                                f"sideways: {why}")
    return failures


def main():
    failures = check("src", {".h", ".cpp"}, cpp_offence)
    failures += check("shaders", {".glsl", ".vert", ".frag", ".geom", ".comp", ".h"},
                      glsl_offence)
    for line in failures:
        print(line)
    if failures:
        print(f"lint-includes: {len(failures)} include(s) against the layer order "
              "(docs/architecture.md)", file=sys.stderr)
        return 1
    print("lint-includes: every include in src/ and shaders/ points down or within its layer")
    return 0


if __name__ == "__main__":
    sys.exit(main())
