"""Modules that moved, for documents saved before: FreeCAD rebuilds a proxy from the module
path saved with the object, so an old path must still import, as the module now in its place."""
import importlib
import importlib.abc
import importlib.util
import sys

MOVED = {"aeronc.objects.compensated_drilling": "aeronc.operations.compensated_drilling"}


class _Finder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    def find_spec(self, name, path=None, target=None):
        return importlib.util.spec_from_loader(name, self) if name in MOVED else None

    def create_module(self, spec):
        return importlib.import_module(MOVED[spec.name])

    def exec_module(self, module):
        pass  # the module in its new place is already executed


def install():
    if not any(isinstance(f, _Finder) for f in sys.meta_path):
        sys.meta_path.append(_Finder())
