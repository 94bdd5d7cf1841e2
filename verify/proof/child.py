"""The process that runs a derivation file (``python -m verify.proof.child PATH FD [N]``).

The checker (:mod:`verify.proof.isolate`) starts it with the file's text on file
descriptor FD and a pipe on standard output. In the sandbox (``N`` given: the largest
number of processes) it is the first process of its own namespaces and confines itself
first (:func:`verify.proof.confine.confine`: every mount read-only, private scratch
folders, no capabilities); then it writes one byte ``C`` (or ``F`` and the reason, and
stops), runs the file (:func:`verify.proof.user_file.run_source`), turns its derivations
into data (:mod:`verify.proof.wire`) and writes ``{"derivations": ...}`` or ``{"error":
"one line"}`` on the pipe. Nothing after the ``C`` is trusted: the checker reads it as
data with a size bound, rebuilds every object itself and treats an early exit or a crash
as a malformed file. See ``verify/proof/TRUSTED.md``.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path


def _write(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]


def _read_source(fd: int) -> bytes:
    chunks = []
    while True:
        chunk = os.read(fd, 1 << 20)
        if not chunk:
            break
        chunks.append(chunk)
    os.close(fd)
    return b"".join(chunks)


def main(argv: list[str]) -> None:
    out = os.dup(1)  # the handover pipe; the file's own prints go nowhere
    null = os.open(os.devnull, os.O_RDWR)
    os.dup2(null, 0)
    os.dup2(null, 1)
    os.dup2(null, 2)
    path = argv[0]
    try:
        source = _read_source(int(argv[1]))
        # everything the front end needs is imported before the file systems change
        from verify.errors import VerifyInputError
        from verify.proof.user_file import contained, run_source
        from verify.proof.wire import dumps, encode

        if len(argv) > 2:
            from verify.proof.confine import ConfineError, confine

            try:
                confine(int(argv[2]))
            except (ConfineError, OSError) as exc:
                _write(out, b"F" + " ".join(str(exc).split()).encode("ascii", "replace"))
                os._exit(0)
        _write(out, b"C")
    except BaseException:
        os._exit(1)
    try:
        try:
            derivations = run_source(path, source)
            with contained(Path(path), "handing its derivations over"):
                data = encode(derivations)
        except VerifyInputError as exc:
            payload = json.dumps({"error": str(exc)}, ensure_ascii=True)
        else:
            payload = '{"derivations":' + dumps(data) + "}"
        _write(out, payload.encode("ascii"))
    except BaseException as exc:  # the file's code may raise anything, even at import
        try:
            _write(out, json.dumps({"error": f"{path}: {type(exc).__name__} while loading"},
                                   ensure_ascii=True).encode("ascii"))
        except BaseException:
            pass
    os._exit(0)  # no atexit hooks or lingering threads of the file after the handover


if __name__ == "__main__":
    main(sys.argv[1:])
