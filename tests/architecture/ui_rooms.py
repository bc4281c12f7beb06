#!/usr/bin/env python3
"""ui/'s rooms: each sub-folder of ui/ may include its own headers and those of the rooms
ROOMS lets it, and only the session adapter (ui/adapter/) includes the render session's
headers (render/session/). ui/README.md explains the rooms; the designer app (app/designer/)
may use every room but not the session either.

Usage: ui_rooms.py SOURCE_DIR    checks ui/ and app/designer/; exit 1 listing every breach
       ui_rooms.py --self-test   checks the checker on small made-up trees
"""
import os
import re
import sys
import tempfile

import include_check

# Who may include whom: a room's own headers always, and those of the rooms named here.
# Lowest first; no room names one after it, so the rooms make no circle.
ROOMS = {
    "document": set(),  # the scene being edited, its edits and undo commands, its files
    "display": set(),  # the frame on screen: GUI-side copy, storage, GL and raster views
    "jobs": set(),  # work off the GUI thread: mailbox, background jobs, the render queue
    "adapter": {"display", "jobs"},  # the render session behind Qt signals
    "panels": {"document", "jobs"},  # outliner, properties, materials, world
    "viewport": {"adapter", "display", "document"},  # navigation, gestures, gizmo, overlays
    "shell": {"adapter", "display", "document", "jobs", "panels", "viewport"},  # the window
}
# render/'s floors (tests/architecture/render_layers.py); the last, session, is the adapter's.
RENDER_FOLDERS = {"core", "geometry", "scene", "image", "texture", "accel", "snapshot",
                  "integrator", "io", "session"}
SESSION = "session"
ADAPTER = "adapter"
APP = "app/designer"

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCES = (".h", ".cpp", ".inl")
NOT_CODE = {"CMakeLists.txt", "README.md"}


def includes(file):
    with open(file, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if m:
                yield number, m.group(1)


def judge(room, shown, number, target):
    """What is wrong with `room` including "target", or None."""
    head = target.split("/")[0] if "/" in target else None
    where = f'{shown}:{number}: includes "{target}"'
    if head is None:
        if room == APP:
            return None  # the app's own files and generated headers
        return f"{where}: name the header by its room (\"{room}/...\")"
    if head == SESSION:
        if room == ADAPTER:
            return None
        return (f"{where}: only ui/{ADAPTER}/ includes the render session's headers; "
                f"use the adapter's (session_controller.h, session_terms.h)")
    if head in RENDER_FOLDERS:
        return None
    if head in ROOMS:
        if room == APP or head == room or head in ROOMS[room]:
            return None
        allowed = ", ".join(sorted(ROOMS[room])) or "no other room"
        return f"{where}: ui/{room}/ may include {allowed}, not {head}"
    return f"{where}, which is neither a ui room nor a floor of render/"


def problems(source_dir):
    """Every include against the rooms, every file outside a room and every unknown room."""
    found = []
    ui = os.path.join(source_dir, "ui")
    for entry in sorted(os.listdir(ui)):
        path = os.path.join(ui, entry)
        if not os.path.isdir(path):
            if entry not in NOT_CODE:
                found.append(f"ui/{entry}: a file outside the rooms; put it in one of "
                             f"{', '.join(ROOMS)}")
            continue
        if entry not in ROOMS:
            found.append(f"ui/{entry}/: a room with no rules; add it to ROOMS in "
                         f"{os.path.basename(__file__)} and to ui/README.md")
    walks = [(room, os.path.join(ui, room)) for room in ROOMS]
    walks.append((APP, os.path.join(source_dir, *APP.split("/"))))
    for room, top in walks:
        if not os.path.isdir(top):
            continue
        for root, _, files in os.walk(top):
            for name in sorted(files):
                if not name.endswith(SOURCES):
                    continue
                file = os.path.join(root, name)
                shown = os.path.relpath(file, source_dir).replace(os.sep, "/")
                for number, target in includes(file):
                    problem = judge(room, shown, number, target)
                    if problem:
                        found.append(problem)
    return found


def self_test():
    """The checker passes a tree that keeps the rules and fails each kind of breach."""
    def tree(files):
        d = tempfile.mkdtemp()
        for rel, text in files.items():
            os.makedirs(os.path.join(d, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(d, rel), "w", encoding="utf-8") as f:
                f.write(text)
        return d

    good = tree({
        "ui/README.md": "# rooms\n",
        "ui/adapter/c.h": '#pragma once\n#include "session/render_session.h"\n',
        "ui/viewport/v.cpp": '#include "adapter/c.h"\n#include "scene/document.h"\n'
                             '#include <vector>\n',
        "ui/shell/w.cpp": '#include "viewport/v.h"\n#include "panels/p.h"\n',
        "app/designer/main.cpp": '#include "shell/w.h"\n#include "raystudio_version.h"\n'})
    session = tree({"ui/panels/p.cpp": '// x\n  #  include "session/interaction_policy.h"\n'})
    app_session = tree({"ui/shell/w.h": "#pragma once\n",
                        "app/designer/m.cpp": '#include "session/render_session.h"\n'})
    sideways = tree({"ui/panels/p.cpp": '#include "document/e.h"\n#include "viewport/v.h"\n'})
    up = tree({"ui/document/e.cpp": '#include "shell/w.h"\n'})
    loose = tree({"ui/stray.cpp": "int x;\n", "ui/shell/w.cpp": '#include "w.h"\n'})
    unknown = tree({"ui/gadgets/g.h": "#pragma once\n",
                    "ui/jobs/j.cpp": '#include "elsewhere/x.h"\n'})
    checks = [
        (problems(good) == [], "a tree that keeps the rules passes"),
        (problems(session) == ['ui/panels/p.cpp:2: includes "session/interaction_policy.h": '
                               "only ui/adapter/ includes the render session's headers; use "
                               "the adapter's (session_controller.h, session_terms.h)"],
         "a session header outside the adapter fails, naming file and line"),
        (len(problems(app_session)) == 1 and "app/designer/m.cpp:1" in problems(app_session)[0],
         "a session header in the designer app fails"),
        (problems(sideways) == ['ui/panels/p.cpp:2: includes "viewport/v.h": ui/panels/ may '
                                'include document, jobs, not viewport'],
         "an include of a room not allowed fails"),
        (len(problems(up)) == 1 and "not shell" in problems(up)[0],
         "an include from the ground room up fails"),
        (len(problems(loose)) == 2 and "ui/stray.cpp" in problems(loose)[0]
         and "by its room" in problems(loose)[1],
         "a file outside the rooms and an include without its room fail"),
        (len(problems(unknown)) == 2 and "gadgets" in problems(unknown)[0]
         and "elsewhere/x.h" in problems(unknown)[1],
         "an unknown room and an include of no known folder fail"),
    ]
    failed = [what for ok, what in checks if not ok]
    for what in failed:
        print(f"ui_rooms self-test: expected that {what}", file=sys.stderr)
    return 1 if failed else 0


def main(argv):
    return include_check.run(argv, "ui_rooms", __doc__, lambda root: os.path.isdir(os.path.join(root, "ui")), problems, self_test,
                             "breach(es) of ui/'s rooms")


if __name__ == "__main__":
    sys.exit(main(sys.argv))
