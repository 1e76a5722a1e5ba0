"""The one harness of AeroNC's runs (the main job, the impeller run, the drilling run).

A run writes into one output folder. A second run replaces the outputs of the first (the
files it listed in .aeronc-outputs) and nothing else there. FreeCAD's own console output goes
to freecad.log while the run's progress lines keep the terminal; each named stage is timed
and reported in one line; a stage that fails with an AeroNCError raises RunError naming it.
Documents the run opens are closed at the end, also when a stage failed.
"""
import contextlib
import os
import sys
import time

from aeronc.errors import AeroNCError

MANIFEST = ".aeronc-outputs"
LOG = "freecad.log"


class RunError(AeroNCError):
    """A stage of a run failed; the message names it."""


class Run:
    """The context a run's stages share: the output folder, what was written, the stage times
    and the documents opened."""

    def __init__(self, out, say=None):
        self.out = os.path.abspath(out)
        os.makedirs(self.out, exist_ok=True)
        _remove_previous(self.out)
        self.log_path = os.path.join(self.out, LOG)
        if os.path.exists(self.log_path):
            os.unlink(self.log_path)
        self.say = say
        self.times = []
        self.written = [LOG]
        self.opened = []

    def path(self, name):
        return os.path.join(self.out, name)

    @contextlib.contextmanager
    def console(self):
        """FreeCAD's output to the log for the block; progress lines (say) to the terminal
        unless the caller gave its own; the run's documents closed at the end."""
        try:
            with _freecad_output_to(self.log_path) as terminal:
                if self.say is None:
                    self.say = lambda text: print(text, file=terminal, flush=True)
                yield self
        finally:
            self.close_documents()

    @contextlib.contextmanager
    def stage(self, name):
        t0 = time.perf_counter()
        try:
            yield
        except AeroNCError as e:
            raise RunError("{}: {}".format(name, e)) from None
        self.times.append((name, time.perf_counter() - t0))

    def report(self, text):
        """One progress line for the stage that just ended: its time, its name, text."""
        name, seconds = self.times[-1]
        self.say("  {:>6.1f} s  {:<20s} {}".format(seconds, name, text))

    def total(self):
        return sum(t for _, t in self.times)

    def new_document(self, name):
        import FreeCAD
        doc = FreeCAD.newDocument(name)
        self.opened.append(doc)
        return doc

    def close_documents(self):
        import FreeCAD
        while self.opened:
            FreeCAD.closeDocument(self.opened.pop().Name)

    def wrote(self, *names):
        self.written += list(names)

    def write(self, name, data):
        """A file of the run, written atomically."""
        from aeronc.post.output import write_atomically
        write_atomically(self.path(name), data)
        self.wrote(name)

    def save_document(self, doc, name):
        save_document(doc, self.path(name))
        self.wrote(name)

    def finish(self):
        """List what the run wrote, so that the next run replaces exactly that."""
        from aeronc.post.output import write_atomically
        write_atomically(self.path(MANIFEST), "\n".join(self.written) + "\n")


def save_document(doc, path):
    """Save under a temporary name, then rename: no backup file, never a half-written document."""
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".part.FCStd")
    doc.saveAs(tmp)
    os.replace(tmp, path)
    doc.FileName = path


def _remove_previous(out):
    path = os.path.join(out, MANIFEST)
    if not os.path.exists(path):
        return
    with open(path) as f:
        for name in f.read().split("\n"):
            if name and os.path.basename(name) == name and os.path.isfile(os.path.join(out, name)):
                os.unlink(os.path.join(out, name))
    os.unlink(path)


@contextlib.contextmanager
def _freecad_output_to(log_path):
    """FreeCAD's own console output (recompute percentages, Path's messages) goes to the log;
    the run's progress lines keep the terminal (the stream yielded)."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with open(log_path, "ab") as log:
        os.dup2(log.fileno(), 1)
        os.dup2(log.fileno(), 2)
        try:
            yield os.fdopen(os.dup(saved[0]), "w", buffering=1)
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])
