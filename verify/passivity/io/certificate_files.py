"""Certificate files: the JSON of KYP and band (generalized KYP) certificates, read strictly.

Two layouts per kind. Version 2 (written now) stores the model H exactly as its source
file denotes it, the margin nu0 and band as fields of their own, the statement derived
from them (:func:`verify.passivity.io.binding.statement`), the certificate matrices, and the
model file's descriptive fields under ``unverified``. Version 1 (the first certificates)
stored descriptive and solver fields under ``meta``; it is still checked, with a fixed
statement text and margin 0 only.

Checking a file (:func:`check_kyp_file`, :func:`check_band_file`) refuses, with one line:
unknown or missing fields, a fingerprint or file name that does not match the content,
a statement other than the derived one, a source file that denotes another model or
another name, and matrices that fail the exact check of
:func:`verify.passivity.check.certificate.check_kyp` or
:func:`verify.passivity.check.gkyp.check_gkyp` for H - nu0 I. Nothing here calls a solver.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from verify.inputs.number_text import short_text, unlimited_int_text
from verify.passivity.check import band_fd
from verify.passivity.check import exact as ex
from verify.passivity.check.certificate import ExactModel, KypCheck, check_kyp
from verify.passivity.check.gkyp import ComplexMatrix, check_gkyp
from verify.passivity.io.binding import (
    LEGACY_BAND_STATEMENT,
    LEGACY_KYP_STATEMENT,
    UNVERIFIED_KEYS,
    Claim,
    Perturbed,
    bind_source,
    check_unverified,
    claim_from_fields,
    file_name,
    locate_source,
    model_from_json,
    perturbed_from_json,
    same_source,
    shifted,
    statement,
)
from verify.passivity.io.strict_json import (
    CertificateFormatError,
    fields,
    rational_matrix,
    read_strict,
    text_field,
)

KYP_V1, KYP_V2 = "verify-kyp-certificate/1", "verify-kyp-certificate/2"
BAND_V1, BAND_V2 = "verify-gkyp-certificate/1", "verify-gkyp-certificate/2"

_HEAD = ("schema", "name", "source", "fingerprint", "statement", "model", "P")
_LEGACY_META = ("margin", "numerical_margin", "rounding", *UNVERIFIED_KEYS)


@dataclass(frozen=True)
class StoredCertificate:
    """A certificate file's content, parsed; not yet checked."""

    schema: str
    name: str
    source: str
    fingerprint: str
    statement: str
    claim: Claim
    model: ExactModel  # H, as the source file denotes it
    P: ex.RationalMatrix | ComplexMatrix
    Q: ComplexMatrix | None
    unverified: dict[str, Any]
    perturbed: Perturbed | None = None  # a model perturbed within tolerance (KYP only)

    def same_claim(self, other: StoredCertificate, path: Path | None = None) -> bool:
        """Same name, source, exact model and claim (the proof matrices may differ); with
        ``path`` (where both would be stored), sources spelt differently but naming the
        same file count as the same."""
        if (self.name, self.claim, self.model, self.perturbed) != (
                other.name, other.claim, other.model, other.perturbed):
            return False
        return self.source == other.source or (
            path is not None and same_source(self.source, other.source, path))


# ------------------------------------------------------------------------------ writing


def kyp_json(name: str, source: str, model: ExactModel, claim: Claim, P: ex.RationalMatrix,
             unverified: dict[str, Any], perturbed: Perturbed | None = None
             ) -> dict[str, Any]:
    """Version-2 JSON of a KYP certificate: P certifies H - margin I for H = ``model``.

    ``perturbed``: ``model`` is the source file's model perturbed within tolerance by
    (a, d), stored as field ``perturbation`` so that the check re-derives it from the file.
    """
    data = {"schema": KYP_V2, "name": name, "source": source,
            "fingerprint": model.fingerprint(), "margin": str(claim.margin),
            "statement": statement(claim), "model": model.to_json(), "P": ex.to_strings(P),
            "unverified": dict(unverified)}
    if perturbed is not None:
        data["perturbation"] = perturbed.to_json()
    return data


def band_json(name: str, source: str, model: ExactModel, claim: Claim, P: ComplexMatrix,
              Q: ComplexMatrix, unverified: dict[str, Any]) -> dict[str, Any]:
    """Version-2 JSON of a band certificate for H = ``model`` on ``claim.band``."""
    assert claim.band is not None
    return {"schema": BAND_V2, "name": name, "source": source,
            "fingerprint": model.fingerprint(),
            "band": [str(claim.band[0]), str(claim.band[1])], "margin": str(claim.margin),
            "statement": statement(claim), "model": model.to_json(),
            "P": {"re": ex.to_strings(P[0]), "im": ex.to_strings(P[1])},
            "Q": {"re": ex.to_strings(Q[0]), "im": ex.to_strings(Q[1])},
            "unverified": dict(unverified)}


def dumps(data: dict[str, Any]) -> str:
    """The bytes of a certificate file: a function of its content only."""
    return json.dumps(data, indent=1) + "\n"


def store_certificate(data: dict[str, Any], directory: Path) -> tuple[Path, bool]:
    """Write a certificate under the name its content asks for, unless that file already
    holds a valid certificate of the same model and claim (then it is kept byte for byte).

    Keeping a valid file makes ``certificates/`` a function of the models and claims: a
    rerun, or a run on another machine whose floating-point search proposes a slightly
    different P, leaves a committed certificate untouched. Returns the path and whether
    the existing file was kept.
    """
    fresh = PARSERS[data["schema"]](data)
    path = Path(directory) / file_name(fresh.name, fresh.claim, fresh.fingerprint)

    def still_valid(old: Path) -> bool:
        old_data = read_strict(old)
        parse = PARSERS.get(old_data.get("schema"))  # type: ignore[arg-type]
        return (parse is not None and parse(old_data).same_claim(fresh, old)
                and valid_and_bound(old_data, old))

    return keep_or_write(path, dumps(data), still_valid)


def valid_and_bound(data: dict[str, Any], path: Path) -> bool:
    """A KYP or band certificate that re-checks exactly and whose source file is found
    from its folder (what ``verify certificates check`` accepts without
    ``--allow-unbound``)."""
    checker = check_band_file if data["schema"] in (BAND_V1, BAND_V2) else check_kyp_file
    with unlimited_int_text():  # parsed strictly (bounded digits): any size from here
        ok = checker(data, path).ok
    source = data.get("source")
    return ok and isinstance(source, str) and locate_source(source, path) is not None


def keep_or_write(path: Path, text: str, still_valid: Callable[[Path], bool]
                  ) -> tuple[Path, bool]:
    """Keep ``path`` if it holds ``text`` or ``still_valid(path)`` (a valid certificate of
    the same model and claim), else write ``text`` atomically; returns (path, kept).

    A file that cannot be read or parsed is not ours and is replaced.
    """
    from verify.artefacts.atomic import write_atomic

    if path.is_file():
        try:
            if path.read_text() == text or still_valid(path):
                return path, True
        except (OSError, ValueError, CertificateFormatError):
            pass  # not a certificate of ours: replaced below
    write_atomic(path, text)
    return path, False


def store_band_fd_certificate(cert: band_fd.BandFdCertificate, certificates_dir: Path
                              ) -> tuple[Path, bool]:
    """Write the certificate under the name its claim asks for; a file that already holds
    a valid certificate of this schema, model and claim is kept."""
    data = cert.to_json()
    given = shifted(cert.model, -cert.margin)
    path = Path(certificates_dir) / file_name(cert.name, Claim(cert.margin, cert.band),
                                              given.fingerprint())

    def still_valid(old: Path) -> bool:
        stored = read_strict(old)
        return (stored.get("schema") == band_fd.SCHEMA
                and stored.get("fingerprint") == data["fingerprint"]
                and stored.get("band") == data["band"]
                and stored.get("meta") == data["meta"]
                and band_fd.check_band_fd_file(stored, old).ok)

    return keep_or_write(path, dumps(data), still_valid)


# ------------------------------------------------------------------------------ parsing


def _common(data: dict[str, Any], model: ExactModel, claim: Claim, P, Q,
            unverified: dict[str, Any]) -> StoredCertificate:
    schema = data["schema"]
    return StoredCertificate(schema, text_field(data, "name"), text_field(data, "source"),
                             text_field(data, "fingerprint"), text_field(data, "statement"),
                             claim, model, P, Q, unverified)


def _legacy_meta(data: dict[str, Any]) -> dict[str, Any]:
    meta = data["meta"]
    if not isinstance(meta, dict):
        raise CertificateFormatError("field 'meta' must be an object")
    fields(meta, required=("margin",), optional=_LEGACY_META, where="meta")
    if meta["margin"] != "0":
        raise CertificateFormatError(f"meta.margin {meta['margin']!r}: schema version 1 "
                                     "certificates state margin 0 only")
    return check_unverified({k: meta[k] for k in UNVERIFIED_KEYS if k in meta})


def _real(data: dict[str, Any], n: int) -> ex.RationalMatrix:
    return rational_matrix(data["P"], "P", n, n)


def _complex(value: Any, what: str, n: int) -> ComplexMatrix:
    if not isinstance(value, dict):
        raise CertificateFormatError(f"field {what!r} must be an object {{re, im}}")
    fields(value, required=("re", "im"), where=what)
    return (rational_matrix(value["re"], f"{what}.re", n, n),
            rational_matrix(value["im"], f"{what}.im", n, n))


def parse_kyp(data: dict[str, Any]) -> StoredCertificate:
    """A KYP certificate of either version (shapes checked, nothing proven yet)."""
    if data["schema"] == KYP_V1:
        fields(data, required=(*_HEAD, "meta"))
        unverified, claim = _legacy_meta(data), Claim()
    else:
        fields(data, required=(*_HEAD, "margin"), optional=("unverified", "perturbation"))
        unverified = check_unverified(data.get("unverified", {}))
        claim = claim_from_fields(data["margin"], None)
    model = model_from_json(data["model"])
    perturbed = perturbed_from_json(data["perturbation"]) if "perturbation" in data else None
    return replace(_common(data, model, claim, _real(data, model.n), None, unverified),
                   perturbed=perturbed)


def parse_band(data: dict[str, Any]) -> StoredCertificate:
    """A band certificate of either version (shapes checked, nothing proven yet)."""
    if data["schema"] == BAND_V1:
        fields(data, required=(*_HEAD, "band", "Q", "meta"))
        unverified, margin = _legacy_meta(data), "0"
    else:
        fields(data, required=(*_HEAD, "band", "Q", "margin"), optional=("unverified",))
        unverified, margin = check_unverified(data.get("unverified", {})), data["margin"]
    claim = claim_from_fields(margin, data["band"])
    model = model_from_json(data["model"])
    P, Q = _complex(data["P"], "P", model.n), _complex(data["Q"], "Q", model.n)
    return _common(data, model, claim, P, Q, unverified)


# ------------------------------------------------------------------------------ checking


PARSERS = {KYP_V1: parse_kyp, KYP_V2: parse_kyp, BAND_V1: parse_band, BAND_V2: parse_band}


def _derived_statement(cert: StoredCertificate) -> str:
    if cert.schema == KYP_V1:
        return LEGACY_KYP_STATEMENT
    if cert.schema == BAND_V1:
        return LEGACY_BAND_STATEMENT
    return statement(cert.claim)


def check_binding(cert: StoredCertificate, path: Path) -> tuple[str | None, str]:
    """Everything but the exact inequalities: (refusal or None, note on the source)."""
    if cert.fingerprint != cert.model.fingerprint():
        return "fingerprint does not match the model data", ""
    expected = file_name(cert.name, cert.claim, cert.fingerprint)
    if Path(path).name != expected:
        return f"file name does not match the content (expected {expected})", ""
    if cert.statement != _derived_statement(cert):
        return ("statement edited: the statement is not the one derived from what the "
                "certificate proves "
                f"(margin {cert.claim.margin}"
                + ("" if cert.claim.band is None else
                   f", band [{cert.claim.band[0]}, {cert.claim.band[1]}]")
                + f"); expected: {_derived_statement(cert)!r}"), ""
    bound = bind_source(cert.name, cert.source, cert.model, cert.unverified, path,
                        cert.perturbed)
    return bound.error, bound.note


def check_exact(cert: StoredCertificate) -> KypCheck:
    """The exact inequalities for H - nu0 I (and the band), no solver."""
    target = shifted(cert.model, cert.claim.margin)
    if cert.claim.band is None:
        result = check_kyp(target, cert.P)  # type: ignore[arg-type]
    else:
        assert cert.Q is not None
        result = check_gkyp(target, cert.P, cert.Q, cert.claim.band)  # type: ignore[arg-type]
    return result


def summary(claim: Claim) -> str:
    """A short form of the claim for the check's one line."""
    margin = "" if claim.margin == 0 else f" with margin {short_text(claim.margin)}"
    if claim.band is None:
        return f"passive{margin}"
    w1, w2 = (short_text(w) for w in claim.band)
    return f"passive on [{w1}, {w2}] rad/s{margin}"


def check_parsed(cert: StoredCertificate, path: Path) -> KypCheck:
    """Binding first (cheap), then the exact check."""
    error, note = check_binding(cert, path)
    if error is not None:
        return KypCheck(False, error)
    result = check_exact(cert)
    if not result.ok:
        return KypCheck(False, f"does not prove {summary(cert.claim)}: {result.reason}")
    return KypCheck(True, f"{summary(cert.claim)}: {result.reason}; {note}")


def check_kyp_file(data: dict[str, Any], path: Path) -> KypCheck:
    """Checker of the KYP schemas (registered in :mod:`verify.certificates.registry`)."""
    return check_parsed(parse_kyp(data), path)


def check_band_file(data: dict[str, Any], path: Path) -> KypCheck:
    """Checker of the band schemas (registered in :mod:`verify.certificates.registry`)."""
    return check_parsed(parse_band(data), path)


__all__ = [
    "BAND_V1",
    "BAND_V2",
    "KYP_V1",
    "KYP_V2",
    "StoredCertificate",
    "band_json",
    "check_band_file",
    "check_binding",
    "check_exact",
    "check_kyp_file",
    "check_parsed",
    "dumps",
    "kyp_json",
    "parse_band",
    "parse_kyp",
    "store_band_fd_certificate",
    "store_certificate",
    "summary",
    "valid_and_bound",
]
