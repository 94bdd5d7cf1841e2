"""Re-checking any stored certificate by its schema (``verify certificates check``).

Two schemas live under ``certificates/``: KYP certificates of passivity on the whole
frequency axis (:mod:`verify.passivity.certificate`, paper Section 4's nu(w) >= 0 for all
w) and generalized-KYP certificates of passivity on a band (:mod:`verify.passivity.gkyp`).
Each is re-checked in exact rational arithmetic, with no solver.
"""

from __future__ import annotations

import json
from pathlib import Path

from verify.passivity import certificate, fd_certificate, gkyp
from verify.passivity.certificate import KypCheck


def check_stored_certificate(path: Path) -> KypCheck:
    """The exact re-check of one certificate file; ValueError (one line) when malformed."""
    try:
        data = json.loads(Path(path).read_text())
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"{path}: not a readable JSON certificate ({exc})") from None
    schema = data.get("schema") if isinstance(data, dict) else None
    if schema == gkyp.SCHEMA:
        return gkyp.check_band_certificate_data(data, Path(path))
    if schema == fd_certificate.SCHEMA:
        return fd_certificate.check_pr_certificate_data(data, Path(path))
    if schema == certificate.SCHEMA:
        return certificate.check_certificate_file(Path(path))
    raise ValueError(f"{path}: schema is neither {certificate.SCHEMA} nor {gkyp.SCHEMA}")


__all__ = ["check_stored_certificate"]
