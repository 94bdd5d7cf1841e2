"""Which stored certificates become Coq units, and why the others do not.

:func:`export_certificates` turns certificate files into :class:`~verify.coq.unit.CoqUnit`
s (KYP certificates, :mod:`verify.coq.kyp`; band certificates, :mod:`verify.coq.band`;
exact-band certificates, :mod:`verify.coq.band_fd`; the paper's SOS certificates,
:mod:`verify.coq.sos`) and lists every file it does not export with
the reason, machine-readably (:func:`not_exported_json`, written beside the development
as ``NOT_EXPORTED.json``). :func:`paper_development_units` is the paper's development:
the derivation units of :mod:`verify.coq.paper` when that module is installed, then the
certificate units, written as a few bundles (:mod:`verify.coq.bundle`).
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from verify.coq.band import gkyp_unit_from_file
from verify.coq.band_fd import band_fd_unit_from_file
from verify.coq.kyp import CoqExportError, kyp_units_from_file
from verify.coq.positive_real import NOT_KERNEL_CHECKED, pr_unit_from_file
from verify.coq.robust import robust_unit_from_file
from verify.coq.unit import CoqUnit

KYP_SCHEMAS = ("verify-kyp-certificate/1", "verify-kyp-certificate/2")
BAND_SCHEMAS = ("verify-gkyp-certificate/1", "verify-gkyp-certificate/2")
BAND_FD_SCHEMAS = ("verify-band-fd-certificate/1",)
PR_SCHEMAS = ("verify-pr-certificate/1",)

#: Every schema :func:`export_certificates` turns into a unit (a file of one of these
#: kinds that is not exported was refused, with the reason).
EXPORTED_SCHEMAS = (*KYP_SCHEMAS, *BAND_SCHEMAS, *BAND_FD_SCHEMAS, *PR_SCHEMAS)

#: Robust certificates over an identified region (:mod:`verify.coq.robust`): exported when
#: every leaf is of a kind ``RobustCert.v`` checks; otherwise listed with the reason (not
#: a refusal: the Python exact checker still decides them).
ROBUST_SCHEMAS = ("verify-robust-band-certificate/1", "verify-robust-refutation-certificate/1")

#: Reason prefix of a paper's SOS certificate that was refused (edited statement, not
#: PSD, malformed): a failure of ``verify coq``, not a kind left out by design.
PAPER_SOS_REFUSED = "SOS certificate of a paper's step, not exported: "

#: Kinds exported in part: what their unit does not state, left to the Python checker.
PARTLY_EXPORTED: dict[str, str] = {"verify-pr-certificate/1": NOT_KERNEL_CHECKED}

#: Certificate kinds not exported, with the reason (shown in the README and the list).
NOT_EXPORTED_REASONS: dict[str, str] = {
    "verify-sos-certificate/1":
        "SOS certificate that is not one of the paper's by_sos steps: not exported (the "
        "paper's SOS certificates are; a user's is checked by the Python exact checker "
        "only)",
}


@dataclass(frozen=True)
class NotExported:
    """A certificate file left out of the development, and why."""

    file: str
    schema: str
    reason: str


@dataclass(frozen=True)
class Export:
    units: tuple[CoqUnit, ...]
    not_exported: tuple[NotExported, ...]
    #: Files exported in part, with what their unit leaves out (``reason``).
    partly: tuple[NotExported, ...] = ()


def certificate_files(paths: Iterable[Path]) -> list[Path]:
    """The ``*.json`` files named or inside the folders named (not recursive), sorted."""
    files: list[Path] = []
    for p in paths:
        p = Path(p)
        files += sorted(p.glob("*.json")) if p.is_dir() else [p]
    return files


def schema_of(path: Path) -> str:
    """The ``schema`` field of a JSON file, or "" when it has none (or is no JSON)."""
    from verify.errors import VerifyInputError
    from verify.inputs.files import read_bounded
    from verify.passivity.io.strict_json import MAX_CERTIFICATE_BYTES

    try:  # a regular file of bounded size (a FIFO or a device is not read)
        data = json.loads(read_bounded(path, max_bytes=MAX_CERTIFICATE_BYTES).decode("utf-8"))
    except (OSError, VerifyInputError, UnicodeDecodeError, json.JSONDecodeError):
        return ""
    schema = data.get("schema") if isinstance(data, dict) else None
    return schema if isinstance(schema, str) else ""


def export_certificates(paths: Sequence[Path], *, strict: bool = False) -> Export:
    """Units for the KYP, band and exact-band certificates among ``paths``; the rest
    listed with the reason.

    ``strict``: such a certificate that cannot be exported (unbound, no witness) raises
    :class:`CoqExportError` instead of being listed.
    """
    units: list[CoqUnit] = []
    left: list[NotExported] = []
    partly: list[NotExported] = []
    for path in certificate_files(paths):
        schema = schema_of(path)
        if schema in EXPORTED_SCHEMAS:
            make = (kyp_units_from_file if schema in KYP_SCHEMAS else
                    gkyp_unit_from_file if schema in BAND_SCHEMAS else
                    band_fd_unit_from_file if schema in BAND_FD_SCHEMAS else pr_unit_from_file)
            try:
                made = make(path)
                # a KYP certificate: its unit, then Theorem 1 with that human (thm1_lti)
                units.extend(made if isinstance(made, list) else [made])
                # a positive-real unit with its pole conditions ("stable") is whole
                if schema in PARTLY_EXPORTED and "stable" not in units[-1].theorems:
                    partly.append(NotExported(path.name, schema, PARTLY_EXPORTED[schema]))
            except CoqExportError as exc:
                if strict:
                    raise
                left.append(NotExported(path.name, schema, str(exc)))
        elif schema in ROBUST_SCHEMAS:
            try:
                units.append(robust_unit_from_file(path))
            except CoqExportError as exc:
                left.append(NotExported(path.name, schema, str(exc)))
        else:
            reason = NOT_EXPORTED_REASONS.get(schema, "unknown certificate kind: not exported")
            left.append(NotExported(path.name, schema, reason))
    return Export(tuple(units), tuple(left), tuple(partly))


def not_exported_json(items: Sequence[NotExported],
                      partly: Sequence[NotExported] = ()) -> str:
    """The machine-readable list of files left out and, when there are any, of files
    exported in part with what their unit does not state (stable bytes)."""
    def rows(found: Sequence[NotExported]) -> list[dict[str, str]]:
        return [{"file": i.file, "schema": i.schema, "reason": i.reason}
                for i in sorted(found, key=lambda i: i.file)]
    data: dict[str, list[dict[str, str]]] = {"not_exported": rows(items)}
    if partly:
        data["not_kernel_checked"] = rows(partly)
    return json.dumps(data, indent=1) + "\n"


def derivation_units() -> list[CoqUnit]:
    """The paper's derivation units (:func:`verify.coq.paper.paper_units`) when that
    module is installed, else none."""
    import importlib
    import importlib.util

    if importlib.util.find_spec("verify.coq.paper") is None:
        return []
    paper = importlib.import_module("verify.coq.paper")  # its own errors are not hidden
    return list(paper.paper_units())


def paper_development_units(certificates_dir: Path) -> Export:
    """The paper's development: derivation units, the SOS certificates of the paper's
    ``by_sos`` steps (:mod:`verify.coq.sos`), then the other certificates' units."""
    from verify.coq.conclusions import conclusion_units
    from verify.coq.sos import paper_sos_units

    certs = export_certificates([certificates_dir])
    sos_units, outcome = paper_sos_units(certificates_dir)
    left: list[NotExported] = []
    for item in certs.not_exported:
        fate = outcome.get(item.file)
        if fate is None:
            left.append(item)
        elif fate.startswith("refused: "):
            left.append(NotExported(item.file, item.schema,
                                    PAPER_SOS_REFUSED + fate.removeprefix("refused: ")))
    steps = derivation_units()
    units = (*in_bundle([u for u in steps if not u.name.startswith("thm1_")], "Lemma1Steps"),
             *in_bundle([u for u in steps if u.name.startswith("thm1_")], "Thm1Steps"),
             *in_bundle(sos_units, "SosSteps"),
             *in_bundle(certs.units, "Certificates"),
             *conclusion_units())
    return Export(units, tuple(left), certs.partly)


def in_bundle(units: Sequence[CoqUnit], bundle: str) -> list[CoqUnit]:
    """The units written as modules of one file ``bundle`` (:mod:`verify.coq.bundle`):
    the paper's development loads the libraries once per bundle instead of once per
    unit. A single unit keeps its own file."""
    if len(units) < 2:
        return list(units)
    return [replace(unit, bundle=bundle) for unit in units]
