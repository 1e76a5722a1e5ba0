"""The Python side's house rules (docs/architecture.md), checked on the source tree:

  1. only aeronc/pathcompat.py imports FreeCAD's Path workbench (Path, PathScripts, CAM);
  2. no App module imports the GUI: aeronc/ outside viewproviders/ imports neither
     aeronc.viewproviders, aeronc.commands, aeronc.panels nor FreeCADGui or PySide;
  3. every exception class AeroNC defines derives from AeroNCError;
  4. nothing shipped imports what is not shipped: aeronc/, commands/ and panels/ never import
     aeronc.tests (the test-part makers and the demos live there);
  5. the shipped modules import each other without a cycle, imports inside functions included.

Plain python3, no FreeCAD: the source is read, not run.

    python3 tests/rules/python_rules.py SOURCE_DIR     check the tree; exit 1 listing each breach
    python3 tests/rules/python_rules.py --self-test    each rule catches a breach planted in a
                                                       small tree of its own
"""
import ast
import os
import sys
import tempfile

PATH_MODULES = ("Path", "PathScripts", "CAM")
GUI_MODULES = ("FreeCADGui", "PySide", "PySide2", "aeronc.viewproviders", "aeronc.commands", "aeronc.panels")
BUILTIN_ERRORS = {"Exception", "BaseException", "ValueError", "RuntimeError", "TypeError", "KeyError",
                  "OSError", "IOError", "LookupError", "ArithmeticError", "AssertionError"}


def _modules(root):
    """{module name: path} of the shipped Python: aeronc/ as aeronc.*, commands/ and panels/ as
    aeronc.commands.* and aeronc.panels.* (where CMake installs them)."""
    out = {}
    for folder, package in (("aeronc", "aeronc"), ("commands", "aeronc.commands"), ("panels", "aeronc.panels")):
        base = os.path.join(root, folder)
        for dirpath, _, files in os.walk(base):
            for f in files:
                if not f.endswith(".py"):
                    continue
                rel = os.path.relpath(os.path.join(dirpath, f), base)[:-3].replace(os.sep, ".")
                name = package if rel == "__init__" else package + "." + rel.replace(".__init__", "")
                out[name] = os.path.join(dirpath, f)
    return out


def _imports(tree, module, is_package, known=()):
    """Every module an import statement of the tree names (at any depth), absolute. For
    `from X import a`: X.a when that is a module of `known`, else X."""
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = module.split(".")
                parts = parts if is_package else parts[:-1]
                parts = parts[:len(parts) - node.level + 1]
                base = ".".join(parts + ([base] if base else []))
            for a in node.names:
                sub = "{}.{}".format(base, a.name)
                names.append(sub if sub in known else base)
    return names


def _under(name, prefixes):
    return any(name == p or name.startswith(p + ".") for p in prefixes)


def check(root):
    """The breaches of the rules in the tree at root, one line each."""
    mods = _modules(root)
    breaches, graph, classes = [], {}, {}
    for name, path in sorted(mods.items()):
        with open(path, encoding="utf-8") as f:
            tree = ast.parse(f.read(), path)
        rel = os.path.relpath(path, root)
        imported = _imports(tree, name, path.endswith("__init__.py"), mods)
        if name != "aeronc.pathcompat":
            for i in sorted({i for i in imported if _under(i, PATH_MODULES)}):
                breaches.append("{}: imports FreeCAD's Path workbench ({}); only aeronc/pathcompat.py may".format(rel, i))
        gui_side = _under(name, ("aeronc.viewproviders", "aeronc.commands", "aeronc.panels"))
        if not gui_side:
            for i in sorted({i for i in imported if _under(i, GUI_MODULES)}):
                breaches.append("{}: an App module imports the GUI ({})".format(rel, i))
        for i in sorted({i for i in imported if _under(i, ("aeronc.tests",))}):
            breaches.append("{}: a shipped module imports {}, which is not shipped".format(rel, i))
        graph[name] = {i for i in imported if i in mods and i != name}
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                classes[node.name] = ([ast.unparse(b).split(".")[-1] for b in node.bases], rel)
    for cls, (bases, rel) in sorted(classes.items()):
        if cls != "AeroNCError" and _is_exception(cls, classes) and not _derives(cls, "AeroNCError", classes):
            breaches.append("{}: exception {} does not derive from AeroNCError".format(rel, cls))
    for cycle in _cycles(graph):
        breaches.append("import cycle: {}".format(" -> ".join(cycle + [cycle[0]])))
    return breaches


def _derives(cls, target, classes, seen=()):
    if cls == target:
        return True
    if cls in seen or cls not in classes:
        return False
    return any(_derives(b, target, classes, seen + (cls,)) for b in classes[cls][0])


def _is_exception(cls, classes, seen=()):
    if cls in BUILTIN_ERRORS:
        return True
    if cls in seen or cls not in classes:
        return False
    return any(_is_exception(b, classes, seen + (cls,)) for b in classes[cls][0])


def _cycles(graph):
    """One cycle per strongly connected component of more than one module (Tarjan)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))
    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def self_test():
    """Plant one breach of each rule in a small tree; each must be reported, a clean tree not."""
    planted = {
        "aeronc/__init__.py": "",
        "aeronc/errors.py": "class AeroNCError(RuntimeError):\n    pass\n\n\nclass GoodError(AeroNCError):\n    pass\n",
        "aeronc/pathcompat.py": "import Path\n",
        "aeronc/objects/__init__.py": "",
        "aeronc/objects/thing.py": "def f():\n    from aeronc import viewproviders\n",
        "aeronc/viewproviders/__init__.py": "import FreeCADGui\nfrom aeronc.objects import thing\n",
        "aeronc/drilling/__init__.py": "",
        "aeronc/drilling/holes.py": "class HoleError(ValueError):\n    pass\n",
        "aeronc/drilling/camera.py": "def f():\n    import Path\n",
        "aeronc/runs/__init__.py": "",
        "aeronc/runs/demo.py": "from aeronc.tests.parts import skin\n",
        "aeronc/a.py": "def f():\n    from aeronc import b\n",
        "aeronc/b.py": "from aeronc import a\n",
        "commands/__init__.py": "", "panels/__init__.py": "import FreeCADGui\n",
    }
    expected = ["aeronc/drilling/camera.py: imports FreeCAD's Path workbench (Path)",
                "aeronc/objects/thing.py: an App module imports the GUI (aeronc.viewproviders)",
                "exception HoleError does not derive from AeroNCError",
                "aeronc/runs/demo.py: a shipped module imports aeronc.tests",
                "import cycle: aeronc.a -> aeronc.b",
                "import cycle: aeronc.objects.thing -> aeronc.viewproviders"]
    with tempfile.TemporaryDirectory() as root:
        for rel, text in planted.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        found = check(root)
        missed = [e for e in expected if not any(e in b for b in found)]
        extra = [b for b in found if not any(e in b for e in expected)]
        for rel in ("aeronc/drilling/camera.py", "aeronc/objects/thing.py", "aeronc/drilling/holes.py",
                    "aeronc/runs/demo.py", "aeronc/b.py"):
            os.unlink(os.path.join(root, rel))
        clean = check(root)
    ok = not missed and not extra and not clean
    for m in missed:
        print("self-test: breach not caught: " + m)
    for b in extra + clean:
        print("self-test: reported without a breach: " + b)
    return ok


def main(argv):
    if argv[1:] == ["--self-test"]:
        ok = self_test()
        print("python rules self-test: " + ("every planted breach caught" if ok else "FAILED"))
        return 0 if ok else 1
    if len(argv) != 2:
        print(__doc__)
        return 2
    breaches = check(argv[1])
    for b in breaches:
        print(b)
    print("python rules: {}".format("{} breach(es)".format(len(breaches)) if breaches else "all hold"))
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
