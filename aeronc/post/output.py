"""Atomic output: a file (a program, a picture) is complete on disk or not there at all."""
import os
import tempfile


def write_atomically(filename, data):
    """Write data (str as UTF-8 text, or bytes) to a temporary file beside filename, then
    rename it into place."""
    folder = os.path.dirname(os.path.abspath(filename))
    fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(filename) + ".", suffix=".part")
    try:
        binary = isinstance(data, (bytes, bytearray))
        with (os.fdopen(fd, "wb") if binary else os.fdopen(fd, "w", encoding="utf-8", newline="\n")) as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        # mkstemp makes the file private; give it the mode a plain open() would (or keep the old one's).
        if os.path.exists(filename):
            os.chmod(tmp, os.stat(filename).st_mode & 0o7777)
        else:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, filename)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
