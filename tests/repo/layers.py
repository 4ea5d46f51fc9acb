#!/usr/bin/env python3
"""Keeps the layers of docs/architecture.md: every #include "..." under src/ must name a header its
layer may see. Above the emulator, only core/console.h and the core's small shared pieces (types,
errors, files, hashes) are visible; agents see environments, never the console; nothing includes
a higher layer. Prints each include that breaks the rule and exits 1; run by CTest as repo.layers.
Usage: layers.py SOURCE_DIR"""
import re
import sys
from pathlib import Path

# The core's small shared pieces, which every layer may use.
SHARED = ["core/types.h", "core/input_error.h", "core/atomic_file.h", "core/hash.h", "core/sha1.h",
          "core/audio_fifo.h", "core/state.h", "core/sio/pad_names.h", "core/sio/pad.h", "util/"]
FACE = ["core/console.h"] + SHARED

# Layer (a folder under src/; the longest match wins) -> what its files may include: "X/" any
# header under X/, "X/*" headers directly in X/, else one header.
RULES = {
    "util": ["util/", "core/types.h", "core/atomic_file.h"],
    "core": ["core/", "gpu/", "spu/", "util/"],
    "gpu": ["core/", "gpu/", "spu/", "util/"],
    "spu": ["core/", "gpu/", "spu/", "util/"],
    "lua": ["lua/"] + FACE,
    # MFCC features of captured sound, a pure function of samples (the audio observation).
    "rl": ["rl/*", "lua/", "spu/audio_features.h"] + FACE,
    # font5x7.h: Tumble's bitmap font (games/tumble/tools), which the learning-curve plot writes with.
    "rl/agents": ["rl/", "font5x7.h"] + SHARED,
    "memsearch": ["memsearch/"] + FACE,
    # The OpenGL context interface, which the play window implements for Console::use_gl_renderer.
    "frontend": ["frontend/", "gpu/gl/gl_context.h"] + FACE,
    "cli": ["cli/", "rl/", "lua/", "memsearch/", "frontend/"] + FACE,
    "python": ["python/", "rl/", "memsearch/", "frontend/"] + FACE,
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def allowed(header, rules):
    for rule in rules:
        if rule.endswith("/*"):
            if header.startswith(rule[:-1]) and "/" not in header[len(rule) - 1:]:
                return True
        elif rule.endswith("/"):
            if header.startswith(rule):
                return True
        elif header == rule:
            return True
    return False


def layer_of(relative):
    parts = relative.parts[:-1]
    for n in range(len(parts), 0, -1):
        name = "/".join(parts[:n])
        if name in RULES:
            return name
    return None


def main():
    src = Path(sys.argv[1]) / "src"
    broken = []
    checked = 0
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        relative = path.relative_to(src)
        layer = layer_of(relative)
        if layer is None:
            broken.append(f"src/{relative}: in no layer (add its folder to tests/repo/layers.py)")
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            header = m.group(1)
            checked += 1
            if "/" not in header and (path.parent / header).exists():
                continue  # a header beside the file
            if not allowed(header, RULES[layer]):
                broken.append(f"src/{relative}:{number}: layer {layer} includes {header}")
    for b in broken:
        print(b)
    print(f"{checked} includes checked, {len(broken)} outside their layer")
    return 1 if broken or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
