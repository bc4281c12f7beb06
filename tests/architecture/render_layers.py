#!/usr/bin/env python3
"""render/'s floors: a sub-folder of render/ may include its own headers and those of the
folders below it in LAYERS, never one above it (render/README.md explains the order).

Usage: render_layers.py RENDER_DIR    checks the tree; exit 1 listing every arrow back up
       render_layers.py --self-test   checks the checker on small made-up trees
"""
import os
import re
import sys
import tempfile

import include_check

# Lowest first. A new folder of render/ must be given its place here and in render/README.md.
LAYERS = ["core", "geometry", "scene", "image", "texture", "accel", "snapshot", "integrator",
          "io", "session"]

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCES = (".h", ".cpp", ".inl")


def problems(render_dir):
    """Every include that points up a floor (or out of render/), and every unplaced folder."""
    found = []
    rank = {name: i for i, name in enumerate(LAYERS)}
    for folder in sorted(os.listdir(render_dir)):
        path = os.path.join(render_dir, folder)
        if not os.path.isdir(path):
            continue
        if folder not in rank:
            found.append(f"render/{folder}/: a folder with no place in the floors "
                         f"({' < '.join(LAYERS)}); add it to {os.path.basename(__file__)}")
            continue
        for root, _, files in os.walk(path):
            for name in sorted(files):
                if not name.endswith(SOURCES):
                    continue
                file = os.path.join(root, name)
                shown = "render/" + os.path.relpath(file, render_dir).replace(os.sep, "/")
                with open(file, encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = m.group(1).split("/")[0]
                        if "/" not in m.group(1) or target not in rank:
                            found.append(f'{shown}:{number}: includes "{m.group(1)}", which is '
                                         f"not a header of one of render/'s floors")
                        elif rank[target] > rank[folder]:
                            found.append(f'{shown}:{number}: includes "{m.group(1)}": {folder} '
                                         f"is below {target} ({' < '.join(LAYERS)})")
    return found


def self_test():
    """The checker passes a tree that keeps the order and fails each kind of breach."""
    def tree(files):
        d = tempfile.mkdtemp()
        for rel, text in files.items():
            os.makedirs(os.path.join(d, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(d, rel), "w", encoding="utf-8") as f:
                f.write(text)
        return d

    good = tree({"core/a.h": "#pragma once\n#include <vector>\n",
                 "session/b.cpp": '#include "core/a.h"\n#include "session/b.h"\n',
                 "session/b.h": "#pragma once\n"})
    up = tree({"core/a.h": "#pragma once\n",
               "image/c.cpp": '// x\n#include "core/a.h"\n  #  include "integrator/d.h"\n'})
    stray = tree({"gadgets/e.h": "#pragma once\n"})
    outside = tree({"core/f.h": '#include "f2.h"\n'})
    checks = [
        (problems(good) == [], "a tree that keeps the order passes"),
        (problems(up) == ['render/image/c.cpp:3: includes "integrator/d.h": image is below '
                          'integrator (' + " < ".join(LAYERS) + ")"],
         "an include one floor up fails, naming file and line"),
        (len(problems(stray)) == 1 and "gadgets" in problems(stray)[0],
         "a folder with no place fails"),
        (len(problems(outside)) == 1 and "f2.h" in problems(outside)[0],
         "an include that names no floor fails"),
    ]
    failed = [what for ok, what in checks if not ok]
    for what in failed:
        print(f"render_layers self-test: expected that {what}", file=sys.stderr)
    return 1 if failed else 0


def main(argv):
    return include_check.run(argv, "render_layers", __doc__, os.path.isdir, problems, self_test,
                             "include(s) against render/'s floors")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
