"""AeroNC's exceptions: one base, AeroNCError, for every failure the user can act on.

  AeroNCError                  a RuntimeError, so callers that catch RuntimeError still do
    RecognitionError           the part cannot be recognised (not one solid, bad B-rep, ...)
      RecognitionCancelled     the progress callback asked to stop
    KnowledgeBaseError         the knowledge base or tool planning failed
    CuttingOptimisationError   the cutting-parameter optimisation cannot run or write
    MachiningChainError        the machining chain cannot be built or updated
    PostError                  a post failed; names the operation and the move
    ImpellerError              an impeller cannot be programmed (route, tools, toolpaths)
    DrillingError              datum holes, measurements or compensated drilling
      HoleError                a selected element is not a hole, or not one the set can take
      CameraError              the camera program cannot be made (machine, calibration, poses)
      CompensationError        measurements cannot be imported or the holes not compensated

The C++ core (aeronc._core) raises exceptions of its own; `from_core` turns them into these
at the call, so the rest of the Python side (commands, panels, scripts) catches AeroNCError
only. This module imports neither FreeCAD nor the core: the posts use it in plain Python.
"""
import contextlib


class AeroNCError(RuntimeError):
    """A failure with a message that says, in the NC programmer's words, what to change."""


class RecognitionError(AeroNCError):
    """Recognition failed; the message says why."""


class RecognitionCancelled(RecognitionError):
    """The progress callback asked to stop."""


class KnowledgeBaseError(AeroNCError):
    """The knowledge base or the tool planning failed; the message says why."""


class CuttingOptimisationError(AeroNCError):
    """The cutting-parameter optimisation cannot run or write; the message says why."""


class MachiningChainError(AeroNCError):
    """The machining chain or its Jobs cannot be built or updated; the message says why."""


class PostError(AeroNCError):
    """A post failed; the message names the operation and the move, and says what to change."""


class ImpellerError(AeroNCError):
    """An impeller's route, tools or toolpaths cannot be made; the message says why."""


class DrillingError(AeroNCError):
    """Datum holes, their measurements or the compensated drilling failed; the message says why."""


class HoleError(DrillingError):
    """A selected element is not a hole, or not one the photo-hole set can take."""


class CameraError(DrillingError):
    """The camera program cannot be made: no camera on the machine, no calibration, a pose out of reach."""


class CompensationError(DrillingError):
    """Measurements cannot be imported, or the holes cannot be compensated."""


# RuntimeErrors that are bugs in Python, not messages from the core.
_NOT_FROM_CORE = (AeroNCError, RecursionError, NotImplementedError)


@contextlib.contextmanager
def from_core(error=AeroNCError, context=""):
    """Run calls into aeronc._core in this block: the core's exception (a RuntimeError,
    whatever the binding names it) becomes `error`, its message prefixed with "context: "
    when given. AeroNC's own errors pass through unchanged."""
    try:
        yield
    except _NOT_FROM_CORE:
        raise
    except RuntimeError as e:
        raise error("{}: {}".format(context, e) if context else str(e)) from None
