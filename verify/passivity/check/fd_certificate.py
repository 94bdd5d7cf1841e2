"""Positive-realness certificates (frequency domain): JSON form and exact re-check.

A certificate of schema ``verify-pr-certificate/1`` holds the exact model and every
fact the frequency-domain decision (:mod:`verify.passivity.check.frequency_domain`) derived
from it: the reduced transfer matrix, per-entry pole evidence (Routh column, exact
real-root count), the imaginary-axis poles with isolating intervals and the signs of their residue
forms, the principal-minor sums E_k of the Hermitian part, and for each E_k an exact
sum-of-squares decomposition. :func:`check_pr_certificate` re-derives every fact from
the stored model with exact polynomial arithmetic (no solver, no floating point),
compares, and checks each SOS identity; any edit of the model or of a derived fact makes
it fail, and duplicate or unknown keys are refused.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from verify.inputs.numbers import fraction
from verify.passivity.check import qpoly as qp
from verify.passivity.check.certificate import ExactModel, KypCheck
from verify.passivity.check.frequency_domain import PASSIVE, Analysis, analyse
from verify.passivity.check.univariate_sos import check_nonnegativity, nonnegativity_from_json

SCHEMA = "verify-pr-certificate/1"
STATEMENT = ("H(s) = C(sI - A)^-1 B + D is positive real: no pole in Re s > 0, simple "
             "imaginary-axis poles with Hermitian PSD residues, H(jw) + H(jw)^H >= 0 for "
             "all real w")
_KEYS = {"schema", "name", "source", "fingerprint", "statement", "model", "transfer",
         "poles", "hermitian", "meta"}


def _p(x) -> list[str]:
    return qp.coeff_strings(x)


def derived_json(an: Analysis) -> dict[str, Any]:
    """The exact facts of a passive analysis (SOS excluded), as JSON."""
    tm, sp = an.tm, an.split
    return {
        "transfer": {
            "charpoly": _p(tm.charpoly),
            "numerators": [[_p(x) for x in row] for row in tm.nums],
            "denominators": [[_p(x) for x in row] for row in tm.dens],
            "pole_polynomial": _p(tm.d),
        },
        "poles": {
            "entries": [{"entry": list(f.entry), "routh_first_column": [str(x) for x in f.routh],
                         "axis_real_roots": f.axis_real_roots, "axis_degree": f.axis_degree}
                        for f in an.pole_facts],
            "axis_polynomial": _p(sp.a),
            "rho": _p(sp.rho),
            "residue_forms": [_p(g) for g in an.residue_forms],
            "axis_poles": [{"interval": [str(p.lo), str(p.hi)], "residue_signs": p.signs}
                           for p in an.poles_on_axis],
        },
        "hermitian": {
            "gamma": _p(an.gamma),
            "minor_sums": [{"k": k + 1, "E": _p(E), "power": j, "quotient": _p(Q)}
                           for k, (E, j, Q) in enumerate(zip(an.E, an.powers, an.quotients,
                                                             strict=True))],
        },
    }


@dataclass(frozen=True)
class PrCertificate:
    """A passive verdict's frequency-domain certificate (``.model`` as for KYP ones)."""

    name: str
    source: str
    model: ExactModel
    analysis: Analysis
    meta: dict

    def to_json(self) -> dict[str, Any]:
        facts = derived_json(self.analysis)
        for item, cert in zip(facts["hermitian"]["minor_sums"], self.analysis.certificates,
                              strict=True):
            item["nonnegativity"] = cert.to_json()
        return {"schema": SCHEMA, "name": self.name, "source": self.source,
                "fingerprint": self.model.fingerprint(), "statement": STATEMENT,
                "model": self.model.to_json(), **facts, "meta": self.meta}


def parse_json_text(text: str) -> Any:
    """The strict JSON reading of every certificate kind (duplicate keys, NaN: ValueError)."""
    from verify.passivity.io.strict_json import loads_strict

    return loads_strict(text)


def _strict_matrix(rows: Any, where: str) -> list:
    """A matrix of strict rationals (:func:`verify.inputs.numbers.strict_rational`)."""
    from verify.inputs.numbers import strict_rational

    if not isinstance(rows, list) or not all(isinstance(row, list) for row in rows):
        raise ValueError(f"{where}: expected a list of rows")
    return [[strict_rational(x, f"{where}[{i}][{j}]") for j, x in enumerate(row)]
            for i, row in enumerate(rows)]


def model_from_json(data: dict) -> ExactModel:
    """The exact model a certificate stores under ``"model"`` (ValueError when malformed;
    shared by the positive-realness and band certificates)."""
    m = data["model"]
    if not isinstance(m, dict) or set(m) != {"A", "B", "C", "D"}:
        raise ValueError("the model must have exactly A, B, C, D")
    model = ExactModel(*(_strict_matrix(m[k], f"model.{k}") for k in ("A", "B", "C", "D")))
    n, p = model.n, model.m
    shapes = [(model.A, n, n), (model.B, n, p), (model.D, p, p)]
    if p == 0 or any(len(x) != r or any(len(row) != c for row in x) for x, r, c in shapes) \
            or len(model.C) != p or any(len(row) != n for row in model.C):
        raise ValueError("model matrices have inconsistent shapes")
    return model


def check_pr_certificate_data(data: Any, path: Path | None = None) -> KypCheck:
    """Exact re-check of a parsed certificate (ValueError, one line, when malformed)."""
    where = f"{path}: " if path else ""
    if not isinstance(data, dict) or data.get("schema") != SCHEMA:
        raise ValueError(f"{where}schema is not {SCHEMA}")
    if set(data) != _KEYS:
        extra, missing = sorted(set(data) - _KEYS), sorted(_KEYS - set(data))
        raise ValueError(f"{where}unknown fields {extra} / missing fields {missing}")
    try:
        model = model_from_json(data)
        stored_sums = data["hermitian"]["minor_sums"]
        certs = [nonnegativity_from_json(item["nonnegativity"]) for item in stored_sums]
    except (KeyError, TypeError, ValueError, ZeroDivisionError) as exc:
        raise ValueError(f"{where}malformed certificate ({exc})") from None
    if data["fingerprint"] != model.fingerprint():
        return KypCheck(False, "fingerprint does not match the model data")
    if data["statement"] != STATEMENT:
        return KypCheck(False, "statement edited: the statement is not the one this "
                               "certificate proves")
    an = analyse(model, certify=False)
    if an.verdict != PASSIVE:
        return KypCheck(False, f"the stored model is not positive real: {an.reason}")
    facts = derived_json(an)
    stored = {k: data[k] for k in ("transfer", "poles")}
    stored["hermitian"] = {
        "gamma": data["hermitian"].get("gamma"),
        "minor_sums": [{k: v for k, v in item.items() if k != "nonnegativity"}
                       for item in stored_sums]}
    if set(data["hermitian"]) != {"gamma", "minor_sums"}:
        return KypCheck(False, "unknown fields in 'hermitian'")
    for key in ("transfer", "poles", "hermitian"):
        if stored[key] != facts[key]:
            return KypCheck(False, f"the stored '{key}' facts differ from those re-derived "
                            "from the model")
    for k, (Q, cert) in enumerate(zip(an.quotients, certs, strict=True), start=1):
        problem = check_nonnegativity(Q, cert)
        if problem is not None:
            return KypCheck(False, f"E_{k}: {problem}")
    return KypCheck(True, "H(s) positive real: transfer matrix, pole evidence (Routh, root "
                    "counts), residue signs and principal-minor sums re-derived exactly; every sum "
                    "of squares re-expanded exactly")


def check_pr_certificate_file(path: Path) -> KypCheck:
    try:
        data = parse_json_text(Path(path).read_text())
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        raise ValueError(f"{path}: not a readable JSON certificate ({exc})") from None
    return check_pr_certificate_data(data, Path(path))


def check_pr_file(data: dict[str, Any], path: Path) -> KypCheck:
    """Checker of this schema for ``verify certificates check``: the exact facts, then the
    claim's binding (:mod:`verify.passivity.io.binding`).

    The stored model is H - nu0 I (``meta.margin`` = nu0, the only meta field); the model
    as given, H, must match the file name's fingerprint and, when the ``source`` file is
    found, be exactly the model that file denotes, under the same name.
    """

    from verify.passivity.io.binding import Claim, bind_source, file_name, shifted
    from verify.passivity.io.strict_json import CertificateFormatError, rational

    try:
        result = check_pr_certificate_data(data, path)
        meta = data["meta"]
        if not isinstance(meta, dict) or set(meta) != {"margin"}:
            raise CertificateFormatError("meta must hold exactly the margin nu0")
        q = rational(meta["margin"], "meta.margin")
        if not isinstance(data["name"], str) or not isinstance(data["source"], str):
            raise CertificateFormatError("name and source must be strings")
    except ValueError as exc:
        raise CertificateFormatError(str(exc).removeprefix(f"{path}: ")) from None
    if not result.ok:
        return result
    margin = fraction(q)
    given = shifted(model_from_json(data), -margin)  # H, the model as given
    expected = file_name(data["name"], Claim(margin), given.fingerprint())
    if Path(path).name != expected:
        return KypCheck(False, f"file name does not match the content (expected {expected})")
    bound = bind_source(data["name"], data["source"], given, {}, path)
    if bound.error is not None:
        return KypCheck(False, bound.error)
    what = "passive" if margin == 0 else f"passive with margin {margin}"
    return KypCheck(True, f"{what}: {result.reason}; {bound.note}")
