"""Re-checking stored certificates by their schema (``verify certificates check``).

:data:`SCHEMAS`, the one table of certificate kinds, maps a schema name to its checker,
which lives with the checks of that kind (the gate's KYP, band and positive-realness
certificates in :mod:`verify.passivity`, the robust verdicts of identified models in
:mod:`verify.identify`, SOS certificates in :mod:`verify.certificates.sos_kind`); this
module sits above them all, so none of those packages imports another's checker. A new
kind plugs in with one line, ``SCHEMAS["verify-xyz-certificate/1"] = check_xyz``. A
checker takes the strictly parsed JSON object and the file's path and returns a
:class:`~verify.passivity.check.certificate.KypCheck`; it raises
:class:`~verify.passivity.io.strict_json.CertificateFormatError` for malformed content.
Every checker re-derives what the certificate claims and decides it in exact arithmetic,
with no solver: a certificate is bound to its claim and trusted only once re-checked
(Necula, "Proof-carrying code", POPL 1997: check the proof, not the prover).

Bound or refused: some labels of a certificate (the model's name, the descriptive fields,
a robust region's tie to its identification) can only be re-derived from the ``source``
file it names. :data:`SOURCE_LABELS` lists them per schema; when that file cannot be
found from the certificate's folder (:func:`verify.passivity.io.binding.locate_source`),
the certificate is *unbound* (:class:`CertificateStatus`): not valid unless the caller
accepts unbound certificates, and then the result names the labels left unchecked.
"""

from __future__ import annotations

import os
import stat
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path
from typing import Any

from verify.artefacts.atomic import kind_of
from verify.certificates import sos_kind
from verify.errors import VerifyInputError
from verify.inputs.number_text import unlimited_int_text
from verify.passivity.check import band_fd, fd_certificate
from verify.passivity.check.certificate import KypCheck
from verify.passivity.io import certificate_files as cf
from verify.passivity.io.binding import UNVERIFIED_KEYS, locate_source
from verify.passivity.io.strict_json import CertificateFormatError, read_strict
from verify.sos import certificate as sos_certificate

Checker = Callable[[dict[str, Any], Path], KypCheck]

def _check_robust(data: dict[str, Any], path: Path) -> KypCheck:
    """Robust band certificates of identified models
    (:mod:`verify.identify.robust.band_check`)."""
    from verify.identify.robust.band_check import check_robust_file

    return check_robust_file(data, path)


def _check_refutation(data: dict[str, Any], path: Path) -> KypCheck:
    """Region-wide refutations (:mod:`verify.identify.robust.refutation_check`)."""
    from verify.identify.robust.refutation_check import check_refutation_file

    return check_refutation_file(data, path)


SCHEMAS: dict[str, Checker] = {
    "verify-robust-refutation-certificate/1": _check_refutation,
    "verify-robust-band-certificate/1": _check_robust,
    sos_certificate.SCHEMA: sos_kind.check_sos_file,
    fd_certificate.SCHEMA: fd_certificate.check_pr_file,
    band_fd.SCHEMA: band_fd.check_band_fd_file,
    cf.KYP_V1: cf.check_kyp_file,
    cf.KYP_V2: cf.check_kyp_file,
    cf.BAND_V1: cf.check_band_file,
    cf.BAND_V2: cf.check_band_file,
}


def _model_labels(data: dict[str, Any]) -> tuple[str, ...]:
    """KYP, band and positive-realness certificates: the name and descriptive fields."""
    described = data.get("unverified", data.get("meta", {}))
    keys = [k for k in UNVERIFIED_KEYS if isinstance(described, dict) and k in described]
    return ("name", *(f"unverified.{k}" for k in keys))


def _robust_labels(data: dict[str, Any]) -> tuple[str, ...]:
    """Robust certificates: the name, and the region as the identification's."""
    return ("name", "structure",
            "region = the source's identified coefficients, covariance, chi2 and level")


#: Per schema, the labels only the source file can confirm (schemas not listed here
#: bind to no model file).
SOURCE_LABELS: dict[str, Callable[[dict[str, Any]], tuple[str, ...]]] = {
    "verify-robust-band-certificate/1": _robust_labels,
    "verify-robust-refutation-certificate/1": _robust_labels,
    fd_certificate.SCHEMA: _model_labels,
    band_fd.SCHEMA: _model_labels,
    cf.KYP_V1: _model_labels,
    cf.KYP_V2: _model_labels,
    cf.BAND_V1: _model_labels,
    cf.BAND_V2: _model_labels,
}


class CertificateStatus(StrEnum):
    """Outcome of checking one certificate file."""

    VALID = "valid"  # proof re-checked, every label re-derived
    UNBOUND = "unbound"  # proof re-checked, but its source file was not found
    INVALID = "invalid"  # refused


@dataclass(frozen=True)
class CertificateCheck:
    """The check of one certificate file: status, one-line reason, unchecked labels."""

    status: CertificateStatus
    reason: str
    unchecked: tuple[str, ...] = ()  # labels not re-derived (an unbound certificate)
    accepted: bool = False  # True when the status is acceptable to the caller

    @property
    def ok(self) -> bool:
        """Valid, or unbound and accepted (``allow_unbound``)."""
        return self.accepted


def _unbound_labels(data: dict[str, Any], schema: str, path: Path) -> tuple[str, ...]:
    """The labels left unchecked because the source file is not found (empty if bound)."""
    labels = SOURCE_LABELS.get(schema)
    if labels is None:
        return ()
    source = data.get("source")
    if isinstance(source, str) and locate_source(source, path) is not None:
        return ()
    return labels(data)


def check_stored_certificate(path: Path, *, allow_unbound: bool = False) -> CertificateCheck:
    """The binding and exact re-check of one file; malformed content is a refusal.

    A certificate whose source file cannot be found from its folder is *unbound*: its
    proof is re-checked, but the labels only that file can confirm are not, so it is
    accepted only with ``allow_unbound=True`` (and then :attr:`CertificateCheck.unchecked`
    names those labels).
    """
    try:
        data = read_strict(path)
        schema = data.get("schema")
        checker = SCHEMAS.get(schema) if isinstance(schema, str) else None
        if checker is None:
            return _invalid(f"unknown schema {schema!r}; known: {', '.join(sorted(SCHEMAS))}")
        with unlimited_int_text():  # parsed strictly (bounded digits): any size from here
            result = checker(data, Path(path))
        if not result.ok:
            return _invalid(result.reason)
        unchecked = _unbound_labels(data, schema, Path(path))  # type: ignore[arg-type]
    except CertificateFormatError as exc:
        return _invalid(f"malformed: {exc}")
    if not unchecked:
        return CertificateCheck(CertificateStatus.VALID, result.reason, accepted=True)
    return CertificateCheck(
        CertificateStatus.UNBOUND,
        f"{result.reason}; unbound: not checked against a source file: "
        f"{', '.join(unchecked)}", unchecked, accepted=allow_unbound)


def _invalid(reason: str) -> CertificateCheck:
    return CertificateCheck(CertificateStatus.INVALID, reason)


def certificate_files(paths: Iterable[Path]) -> list[Path]:
    """The files to check: each FILE as given, each DIR's ``*.json`` in name order."""
    files: list[Path] = []
    for p in paths:
        try:
            mode = os.stat(p).st_mode
        except FileNotFoundError:
            raise VerifyInputError(f"{p}: no such file or directory") from None
        except OSError as exc:
            raise VerifyInputError(f"{p}: cannot read ({exc.strerror})") from None
        if stat.S_ISDIR(mode):
            files += sorted(p.glob("*.json"))
        elif stat.S_ISREG(mode):
            files.append(p)
        else:
            raise VerifyInputError(f"{p}: is {kind_of(mode)}, not a certificate file; give "
                                   "a certificate's .json file or a folder of them")
    return files


__all__ = ["SCHEMAS", "SOURCE_LABELS", "CertificateCheck", "CertificateStatus", "Checker",
           "certificate_files", "check_stored_certificate"]
