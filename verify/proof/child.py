"""The process that runs a derivation file (``python -m verify.proof.child FILE OUT``).

It loads FILE (:func:`verify.proof.user_file.load_derivations`), turns its derivations
into data (:mod:`verify.proof.wire`) and writes ``{"derivations": ...}`` or
``{"error": "one line"}`` to OUT (a temporary file, then a rename). Nothing it does is
trusted: the checker process reads OUT as data, rebuilds every object itself and treats
an early exit or a crash here as a malformed file. See ``verify/proof/TRUSTED.md``.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path


def _write(out: Path, payload: dict) -> None:
    tmp = out.with_name(out.name + ".part")
    tmp.write_text(json.dumps(payload, ensure_ascii=True, separators=(",", ":")),
                   encoding="ascii")
    os.replace(tmp, out)


def main(argv: list[str]) -> None:
    path, out = Path(argv[0]), Path(argv[1])
    try:
        from verify.errors import VerifyInputError
        from verify.proof.user_file import contained, load_derivations
        from verify.proof.wire import encode

        try:
            derivations = load_derivations(path)
            with contained(path, "handing its derivations over"):
                data = encode(derivations)
        except VerifyInputError as exc:
            _write(out, {"error": str(exc)})
        else:
            _write(out, {"derivations": data})
    except BaseException as exc:  # the file's code may raise anything, even at import
        try:
            _write(out, {"error": f"{path}: {type(exc).__name__} while loading"})
        except BaseException:
            pass
    sys.stdout.flush()
    os._exit(0)  # no atexit hooks or lingering threads of the file after the handover


if __name__ == "__main__":
    main(sys.argv[1:])
