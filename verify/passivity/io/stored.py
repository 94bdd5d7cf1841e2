"""Re-checking stored certificates by their schema (``verify certificates check``).

:data:`SCHEMAS` maps a schema name to its checker; a new kind of certificate plugs in
with one line, ``SCHEMAS["verify-xyz-certificate/1"] = check_xyz``. A checker takes the
strictly parsed JSON object and the file's path and returns a
:class:`~verify.passivity.check.certificate.KypCheck`; it raises
:class:`~verify.passivity.io.strict_json.CertificateFormatError` for malformed content.
Every checker re-derives what the certificate claims and decides it in exact arithmetic,
with no solver: a certificate is bound to its claim and trusted only once re-checked
(Necula, "Proof-carrying code", POPL 1997: check the proof, not the prover).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from verify.errors import VerifyInputError
from verify.passivity.check import band_fd, fd_certificate
from verify.passivity.check.certificate import KypCheck
from verify.passivity.io import certificate_files as cf
from verify.passivity.io.strict_json import CertificateFormatError, read_strict

Checker = Callable[[dict[str, Any], Path], KypCheck]

def _check_sos(data: dict[str, Any], path: Path) -> KypCheck:
    """SOS certificates of ``by_sos`` steps (:mod:`verify.sos.certificate`)."""
    from verify.sos.certificate import check_sos_certificate_data

    try:
        result = check_sos_certificate_data(data, path)
    except ValueError as exc:
        raise CertificateFormatError(str(exc).removeprefix(f"{path}: ")) from None
    return KypCheck(bool(result.ok), result.reason)


def _check_robust(data: dict[str, Any], path: Path) -> KypCheck:
    """Robust band certificates of identified models (:mod:`verify.identify.robust_certificate`)."""
    from verify.identify.robust_certificate import check_robust_file

    return check_robust_file(data, path)


SCHEMAS: dict[str, Checker] = {
    "verify-robust-band-certificate/1": _check_robust,
    "verify-sos-certificate/1": _check_sos,
    fd_certificate.SCHEMA: fd_certificate.check_pr_file,
    band_fd.SCHEMA: band_fd.check_band_fd_file,
    cf.KYP_V1: cf.check_kyp_file,
    cf.KYP_V2: cf.check_kyp_file,
    cf.BAND_V1: cf.check_band_file,
    cf.BAND_V2: cf.check_band_file,
}


def check_stored_certificate(path: Path) -> KypCheck:
    """The binding and exact re-check of one file; malformed content is a refusal."""
    try:
        data = read_strict(path)
        schema = data.get("schema")
        checker = SCHEMAS.get(schema) if isinstance(schema, str) else None
        if checker is None:
            return KypCheck(False, f"unknown schema {schema!r}; known: "
                            f"{', '.join(sorted(SCHEMAS))}")
        return checker(data, Path(path))
    except CertificateFormatError as exc:
        return KypCheck(False, f"malformed: {exc}")


def certificate_files(paths: Iterable[Path]) -> list[Path]:
    """The files to check: each FILE as given, each DIR's ``*.json`` in name order."""
    files: list[Path] = []
    for p in paths:
        if p.is_dir():
            files += sorted(p.glob("*.json"))
        elif p.is_file():
            files.append(p)
        else:
            raise VerifyInputError(f"{p}: no such file or directory")
    return files


__all__ = ["SCHEMAS", "Checker", "certificate_files", "check_stored_certificate"]
