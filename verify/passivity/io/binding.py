"""What a stored certificate claims, derived from what it proves, and its tie to a model file.

A passivity certificate (paper, Section 4: the human model H is passive, so Theorem 1's
storage S_h exists) proves one thing: the exact inequalities on P (and Q) for the model
stored in it. Everything else a certificate file says is either derived from that proof
and compared when the file is checked, or labelled unverified:

* the claim (:class:`Claim`): passivity of H - nu0 I over all frequencies, or
  H(jw) + H(jw)^H >= 2 nu0 I on a band [w1, w2]; the ``statement`` text is a function of
  the claim alone (:func:`statement`), so "strictly passive with margin 5" cannot sit
  beside a proof of margin 0;
* the file name: the model's name, the claim and the model's fingerprint
  (:func:`file_name`);
* the ``source`` model file, looked up from the certificate's folder
  (:func:`locate_source`; the gate writes it relative to that folder,
  :func:`relative_source`): it must denote exactly the stored model (:func:`exact_of` is
  the one place that turns a loaded model into exact data), or that model perturbed by
  the stored (a, d) of ``--tolerance`` (:class:`Perturbed`), and carry the stored
  ``name`` (:func:`bind_source`); where it cannot be found the certificate is unbound
  (:mod:`verify.certificates.registry`);
* descriptive fields copied from the model file (description, units, k_s, reconstructed)
  travel under ``unverified``, are no part of the claim, and are compared with the file.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any

from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.inputs.number_text import approx_text
from verify.inputs.numbers import fraction
from verify.passivity.check.certificate import ExactModel
from verify.passivity.io.strict_json import (
    CertificateFormatError,
    fields,
    rational,
    rational_matrix,
)

if TYPE_CHECKING:
    from verify.passivity.model import LTIModel

#: Fields of a model file that a certificate may repeat, unverified.
UNVERIFIED_KEYS = ("description", "units", "k_s", "reconstructed")

#: Statements of the first schema versions (no margin field; margin 0 only).
LEGACY_KYP_STATEMENT = "P = P^T > 0 and [[A'P + PA, PB - C'], [B'P - C, -(D + D')]] <= 0"
LEGACY_BAND_STATEMENT = (
    "Q = Q^H >= 0 and N^H (Phi (x) P + Psi (x) Q) N + Theta <= 0 with N = [[A, B], [I, 0]], "
    "Phi = [[0, 1], [1, 0]], Psi = [[-1, j wc], [-j wc, -w1 w2]], wc = (w1 + w2)/2, "
    "Theta = -[[0, C'], [C, D + D']]; hence H(jw) + H(jw)^H >= 0 for w1 <= w <= w2 "
    "(Iwasaki-Hara generalized KYP)")


@dataclass(frozen=True)
class Claim:
    """What a certificate proves about the stored model H.

    ``band is None``: H - margin I is passive (KYP lemma), i.e. nu(w) >= margin at every
    w where H(jw) is defined. Otherwise H(jw) + H(jw)^H >= 2 margin I for w1 <= w <= w2.
    """

    margin: Fraction = Fraction(0)
    band: tuple[Fraction, Fraction] | None = None


def _shift_text(margin: Fraction) -> str:
    return "D + D'" if margin == 0 else f"D + D' - 2 nu0 I, nu0 = {margin}"


def statement(claim: Claim) -> str:
    """The statement a certificate of this claim carries (one function for every schema)."""
    m = claim.margin
    if claim.band is None:
        what = "H is passive" if m == 0 else f"H - nu0 I is passive with nu0 = {m}"
        return (f"{what}, where H(s) = C (sI - A)^-1 B + D is the stored model: "
                f"P = P^T > 0 and [[A'P + PA, PB - C'], [B'P - C, -({_shift_text(m)})]] "
                "<= 0 (KYP lemma), so x'Px/2 is a storage function and nu(w) >= "
                f"{m} wherever H(jw) is defined")
    w1, w2 = claim.band
    bound = "0" if m == 0 else f"2 nu0 I, nu0 = {m},"
    return (f"H(jw) + H(jw)^H >= {bound} for {w1} <= w <= {w2} rad/s wherever H(jw) is "
            "defined, where H(s) = C (sI - A)^-1 B + D is the stored model: Q = Q^H >= 0 and "
            "N^H (Phi (x) P + Psi (x) Q) N + Theta <= 0 with N = [[A, B], [I, 0]], "
            "Phi = [[0, 1], [1, 0]], Psi = [[-1, j wc], [-j wc, -w1 w2]], wc = (w1 + w2)/2, "
            f"Theta = -[[0, C'], [C, {_shift_text(m)}]] (Iwasaki-Hara generalized KYP)")


def slug(name: str) -> str:
    """A file-name-safe form of a model name."""
    return re.sub(r"[^A-Za-z0-9_.-]+", "-", name).strip("-") or "model"


def file_name(name: str, claim: Claim, fingerprint: str) -> str:
    """``<name>[-margin-<nu0>][-band-<w1>-<w2>]-<first 12 hex of the fingerprint>.json``."""
    parts = [slug(name)]
    if claim.margin != 0:
        text = approx_text(claim.margin, 6)
        parts.append("margin-" + (f"minus{text[1:]}" if text.startswith("-") else text))
    if claim.band is not None:
        parts.append(f"band-{approx_text(claim.band[0], 6)}-{approx_text(claim.band[1], 6)}")
    return "-".join([*parts, fingerprint[:12]]) + ".json"


def exact_of(model: LTIModel) -> ExactModel:
    """The exact rational (A, B, C, D) a loaded model denotes.

    The one conversion from a loaded model to the data a certificate is about: the gate
    certifies this, and a certificate's ``source`` file must yield exactly this again.
    """
    from verify.passivity.check.realization import minimal_part

    return minimal_part(model.exact).model


def shifted(model: ExactModel, margin: Fraction) -> ExactModel:
    """H - margin I, exactly (only D changes)."""
    if margin == 0:
        return model
    nu = mpq(margin)
    D = [[x - nu if i == j else x for j, x in enumerate(row)] for i, row in enumerate(model.D)]
    return ExactModel(model.A, model.B, model.C, D)


def model_to_json(model: ExactModel) -> dict[str, Any]:
    return model.to_json()


def model_from_json(data: Any) -> ExactModel:
    """A stored model {A, B, C, D} with consistent shapes (n >= 0 states, m >= 1 ports)."""
    if not isinstance(data, dict):
        raise CertificateFormatError("field 'model' must be an object {A, B, C, D}")
    fields(data, required=("A", "B", "C", "D"), where="model")
    D = rational_matrix(data["D"], "model.D")
    m = len(D)
    if m == 0 or len(D[0]) != m:
        raise CertificateFormatError("model.D must be a square m x m matrix with m >= 1")
    A = rational_matrix(data["A"], "model.A")
    n = len(A)
    if n and len(A[0]) != n:
        raise CertificateFormatError("model.A must be square")
    B = rational_matrix(data["B"], "model.B", n, m if n else None)
    C = rational_matrix(data["C"], "model.C", m, n)
    return ExactModel(A, B, C, D)


def claim_from_fields(margin: Any, band: Any) -> Claim:
    """The claim of a stored certificate from its ``margin`` and ``band`` fields."""
    nu = fraction(rational(margin, "margin"))
    if band is None:
        return Claim(nu)
    if not isinstance(band, list) or len(band) != 2:
        raise CertificateFormatError("field 'band' must be [w1, w2]")
    w1, w2 = (fraction(rational(w, f"band[{k}]")) for k, w in enumerate(band))
    if not 0 <= w1 < w2:
        raise CertificateFormatError(f"band [{w1}, {w2}] does not satisfy 0 <= w1 < w2")
    return Claim(nu, (w1, w2))


def unverified_meta(model: LTIModel) -> dict[str, Any]:
    """The descriptive fields of a model file, to be stored under ``unverified``."""
    return {k: model.meta[k] for k in UNVERIFIED_KEYS if k in model.meta}


def check_unverified(value: Any) -> dict[str, Any]:
    """The ``unverified`` block: only the known descriptive keys, with simple types."""
    if not isinstance(value, dict):
        raise CertificateFormatError("field 'unverified' must be an object")
    fields(value, required=(), optional=UNVERIFIED_KEYS, where="unverified")
    for key in ("description", "units"):
        if key in value and not isinstance(value[key], str):
            raise CertificateFormatError(f"unverified.{key} must be a string")
    if "reconstructed" in value and not isinstance(value["reconstructed"], bool):
        raise CertificateFormatError("unverified.reconstructed must be true or false")
    if "k_s" in value and (isinstance(value["k_s"], bool)
                           or not isinstance(value["k_s"], int | float)):
        raise CertificateFormatError("unverified.k_s must be a number")
    return value


#: Sources that name no file (a model built in Python, a perturbed model).
NO_SOURCE = ("", "python")


@dataclass(frozen=True)
class SourceLocation:
    """Where a certificate's source file was found, and by which rule."""

    path: Path
    rule: str  # e.g. "relative to the certificate's folder"

    def describe(self, source: str) -> str:
        return f"source {source} found {self.rule}"


def locate_source(source: str, cert_path: Path) -> SourceLocation | None:
    """The model file a certificate names, looked up from the certificate, never from the
    working directory (so the verdict does not depend on where the check runs).

    A relative ``source`` is taken relative to the certificate's folder (as ``verify
    gate`` writes it), then relative to each folder above it, nearest first (how
    certificates in a repository's ``certificates/`` named files from the repository
    root), then as a file of that name next to the certificate (a model file and its
    certificates kept together, as ``verify identify --out DIR`` writes them).
    ``python`` and ``""`` name no file.
    """
    if source in NO_SOURCE:
        return None
    path = Path(source)
    folder = Path(cert_path).resolve().parent
    if path.is_absolute():
        candidates = [(path, "at its absolute path")]
    else:
        candidates = [(folder / path, "relative to the certificate's folder")]
        candidates += [(up / path, f"relative to {up}, a folder above the certificate's")
                       for up in folder.parents]
        candidates.append((folder / path.name, "next to the certificate"))
    return next((SourceLocation(c, rule) for c, rule in candidates if c.is_file()), None)


def same_source(a: str, b: str, cert_path: Path) -> bool:
    """Two ``source`` texts of certificates at ``cert_path`` name the same file (or are
    the same text): a rewritten spelling of a source is no new claim."""
    if a == b:
        return True
    found_a, found_b = resolve_source(a, cert_path), resolve_source(b, cert_path)
    return found_a is not None and found_b is not None and \
        found_a.resolve() == found_b.resolve()


def resolve_source(source: str, cert_path: Path) -> Path | None:
    """The path :func:`locate_source` finds, or None."""
    found = locate_source(source, cert_path)
    return None if found is None else found.path


def relative_source(source: str, directory: Path) -> str:
    """A model file's path as a certificate in ``directory`` names it: relative to that
    folder, with "/" separators (the same bytes on every machine for the same layout);
    absolute only where no relative path exists (another drive). A source that names no
    file from here (e.g. a path inside the package, "verify/data/models/x.toml", given
    while the working directory is elsewhere) is kept as written: the check looks it up
    from the folders above the certificate."""
    if source in NO_SOURCE or not Path(source).is_file():
        return source
    target = Path(source).resolve()
    try:
        return Path(os.path.relpath(target, Path(directory).resolve())).as_posix()
    except ValueError:
        return target.as_posix()


#: The name suffix of a model perturbed within tolerance (``verify gate --tolerance``).
PERTURBED_SUFFIX = " (perturbed within tolerance)"


@dataclass(frozen=True)
class Perturbed:
    """A model perturbed within tolerance: H(s + a) + d I, i.e. A - a I and D + d I."""

    a: Fraction
    d: Fraction

    def to_json(self) -> dict[str, str]:
        return {"a": str(self.a), "d": str(self.d)}

    def apply(self, model: ExactModel) -> ExactModel:
        """A - a I and D + d I, exactly (B, C unchanged)."""
        qa, qd = mpq(self.a), mpq(self.d)
        A = [[x - qa if i == j else x for j, x in enumerate(row)]
             for i, row in enumerate(model.A)]
        D = [[x + qd if i == j else x for j, x in enumerate(row)]
             for i, row in enumerate(model.D)]
        return ExactModel(A, model.B, model.C, D)


def perturbed_from_json(value: Any) -> Perturbed:
    """The ``perturbation`` field {a, d} of a certificate (exact rationals >= 0)."""
    if not isinstance(value, dict):
        raise CertificateFormatError("field 'perturbation' must be an object {a, d}")
    fields(value, required=("a", "d"), where="perturbation")
    a, d = (fraction(rational(value[k], f"perturbation.{k}")) for k in ("a", "d"))
    if a < 0 or d < 0:
        raise CertificateFormatError("perturbation a and d must be >= 0")
    return Perturbed(a, d)


@dataclass(frozen=True)
class SourceBinding:
    """The outcome of comparing a certificate with its source file."""

    error: str | None  # a refusal, or None
    note: str  # what was compared (for the ok line)


def bind_source(name: str, source: str, model: ExactModel, unverified: dict[str, Any],
                cert_path: Path, perturbed: Perturbed | None = None) -> SourceBinding:
    """Compare the stored model, name and unverified fields with the source file.

    With ``perturbed``, the stored model must be the source file's model perturbed by
    (a, d) (on the file's realisation or on its minimal part) and the name the file's
    name with :data:`PERTURBED_SUFFIX`.
    """
    from verify.passivity.io.model_file import load_model

    location = locate_source(source, cert_path)
    if location is None:
        what = "no source file" if source in NO_SOURCE else \
            f"source {source} not found (looked up from the certificate's folder)"
        return SourceBinding(None, f"{what}: the claim is about the stored model only")
    found = location.path
    try:
        loaded = load_model(found)
    except VerifyInputError as exc:
        return SourceBinding(f"source {source} is not a valid model file ({exc})", "")
    if perturbed is None:
        expected_name, same = loaded.name, exact_of(loaded) == model
    else:
        from verify.passivity.check.realization import minimal_part

        expected_name = loaded.name + PERTURBED_SUFFIX
        moved = perturbed.apply(loaded.exact)
        same = model in (moved, minimal_part(moved).model)
    if not same:
        what = "" if perturbed is None else \
            f" perturbed by a = {perturbed.a}, d = {perturbed.d}"
        return SourceBinding(f"source {source}{what} denotes another model than the stored "
                             "one (exact data differ)", "")
    if expected_name != name:
        whose = "the source file's model name" if perturbed is None else \
            "the source file's model name marked perturbed"
        return SourceBinding(f"name {name!r} is not {whose} {expected_name!r}", "")
    for key in UNVERIFIED_KEYS:
        if key in unverified and unverified[key] != loaded.meta.get(key):
            return SourceBinding(f"unverified.{key} = {unverified[key]!r} differs from the "
                                 f"source file's {loaded.meta.get(key)!r}", "")
    how = "the one it denotes" if perturbed is None else \
        f"the one it denotes perturbed by a = {perturbed.a}, d = {perturbed.d}"
    return SourceBinding(None, f"{location.describe(source)}: the stored model is exactly "
                         f"{how}")


__all__ = [
    "LEGACY_BAND_STATEMENT",
    "LEGACY_KYP_STATEMENT",
    "NO_SOURCE",
    "PERTURBED_SUFFIX",
    "UNVERIFIED_KEYS",
    "Claim",
    "Perturbed",
    "SourceBinding",
    "SourceLocation",
    "bind_source",
    "check_unverified",
    "claim_from_fields",
    "exact_of",
    "file_name",
    "locate_source",
    "model_from_json",
    "model_to_json",
    "perturbed_from_json",
    "relative_source",
    "resolve_source",
    "same_source",
    "shifted",
    "slug",
    "statement",
    "unverified_meta",
]
