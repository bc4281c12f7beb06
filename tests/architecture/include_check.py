"""The command line both include checks share (render_layers.py, ui_rooms.py): check a
tree, or the checker itself with --self-test."""
import sys


def run(argv, name, doc, tree_ok, problems, self_test, what):
    """Runs a check: `problems(root)` lists its breaches; `tree_ok(root)` says whether the
    argument is a tree it can check; `what` names a breach in the summary line."""
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2 or not tree_ok(argv[1]):
        print(doc, file=sys.stderr)
        return 2
    found = problems(argv[1])
    for p in found:
        print(p, file=sys.stderr)
    if found:
        print(f"{name}: {len(found)} {what}", file=sys.stderr)
        return 1
    return 0
