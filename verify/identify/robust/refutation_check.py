"""The checker of region-wide refutation certificates (``verify-robust-refutation-certificate/1``).

What flows in: a certificate's parsed JSON and its path (the format is
:mod:`verify.identify.robust.refutation_certificate`); what flows out: a
:class:`verify.passivity.check.certificate.KypCheck`, the verdict of
:func:`check_refutation_file` (registered in :data:`verify.certificates.registry.SCHEMAS`).
It re-derives the claim, checks the enclosure and every leaf of the tree in rational
arithmetic with no solver (:mod:`verify.passivity.check.robust_band`), and compares the
region with the source model file when it is found
(:func:`verify.identify.robust.band_check.check_source`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from gmpy2 import mpq

from verify.identify.model.region import Region, chi2_refusal
from verify.identify.robust import band_certificate as rc
from verify.identify.robust import band_check
from verify.identify.robust.refutation_certificate import file_name, fingerprint, statement
from verify.passivity.check import robust_band as rb
from verify.passivity.check.certificate import KypCheck
from verify.passivity.io.strict_json import (
    CertificateFormatError,
    fields,
    rational,
    text_field,
)

_FIELDS = ("schema", "name", "source", "structure", "parameters", "region", "band",
           "frequency", "direction", "statement", "fingerprint", "enclosure", "tree",
           "leaves")


def _leaf(node: Any, dims: int) -> tuple[str, list[mpq]]:
    if not isinstance(node, list) or not node or not isinstance(node[0], str):
        raise CertificateFormatError("a leaf must start with 'negative', 'linear' or "
                                     "'outside'")
    if node[0] == "negative" and len(node) == 2:
        return "negative", [rational(node[1], "leaf bound")]
    if node[0] == "linear" and len(node) == 3:
        return "linear", [rational(v, "leaf bound") for v in node[1:]]
    if node[0] == "outside" and len(node) == 2 and isinstance(node[1], list) \
            and len(node[1]) == dims:
        return "outside", [rational(v, "leaf point") for v in node[1]]
    raise CertificateFormatError(f"malformed leaf {str(node)[:60]}")


def check_claim(data: dict[str, Any], path: Path
                ) -> tuple[rb.Shape, Region | None, tuple | None, mpq, tuple, str | None]:
    """Everything but the tree: (shape, region, band, w, v, refusal or None)."""
    fields(data, required=_FIELDS)
    name, structure_text = text_field(data, "name"), text_field(data, "structure")
    text_field(data, "source")
    shape = rc.shape_of(structure_text)
    names = rc.parameter_names(shape)
    w = rational(data["frequency"], "frequency")
    direction = data["direction"]
    if not isinstance(direction, list) or len(direction) != 2:
        raise CertificateFormatError("field 'direction' must be [v1, v2]")
    v = (rational(direction[0], "direction[0]"), rational(direction[1], "direction[1]"))
    if data["parameters"] != names:
        return shape, None, None, w, v, (f"parameters {data['parameters']!r} are not the "
                                         f"structure's {names}")
    region, reg_json = band_check.parse_region(data["region"], shape.parameters)
    band = band_check.parse_band(data["band"])

    def refuse(why: str):
        return shape, region, band, w, v, why

    if not 0 < region.level < 1:
        return refuse(f"level {region.level} is not in (0, 1)")
    if not rb.is_positive_definite([list(r) for r in region.covariance]):
        return refuse("the covariance is not symmetric positive definite")
    why = chi2_refusal(region.level, region.chi2, shape.parameters)
    if why is not None:
        return refuse(why)
    if w < 0 or (band is not None and not band[0] <= w <= band[1]):
        return refuse(f"the frequency {w} rad/s is not in the band")
    if v[0] == 0 and v[1] == 0:
        return refuse("the direction v is zero")
    fp = fingerprint(structure_text, names, reg_json, data["band"], data["frequency"],
                     list(direction))
    if data["fingerprint"] != fp:
        return refuse("fingerprint does not match the claim")
    if Path(path).name != file_name(name, w, fp):
        return refuse(f"file name does not match the content (expected "
                      f"{file_name(name, w, fp)})")
    if data["statement"] != statement(structure_text, region.level, band, w, v):
        return refuse("statement edited: not the one derived from the claim")
    return shape, region, band, w, v, None


def check_tree(data: dict[str, Any], shape: rb.Shape, region: Region, w: mpq,
               v: tuple[mpq, mpq]) -> str | None:
    """The enclosure and every leaf, exactly; None when all pass."""
    enclosed = band_check.read_enclosure(data, region)
    if isinstance(enclosed, str):
        return enclosed
    phi, cov_phi, r = enclosed
    dims = len(phi)
    if not isinstance(data["tree"], list):
        raise CertificateFormatError("field 'tree' must be a list")
    S = rb.inverse(cov_phi)
    x = w * w
    root = [(c - h, c + h) for c, h in zip(phi, r, strict=True)]
    count = 0
    try:
        for index, (box, node) in enumerate(rb.leaves(data["tree"], root)):
            kind, values = _leaf(node, dims)
            if kind == "negative":
                result = rb.check_negative_leaf(box, x, v, shape, values[0])
            elif kind == "linear":
                result = rb.check_negative_linear_leaf(box, x, v, shape, cov_phi, phi,
                                                       region.chi2, values[0], values[1])
            else:
                result = rb.check_outside_leaf([*box, (x, x)], S, phi, region.chi2, values)
            if not result.ok:
                return f"leaf {index} ({kind}): {result.reason}"
            count += 1
    except rb.TreeError as exc:
        return str(exc)
    if count != data["leaves"]:
        return f"{count} leaves checked, the file says {data['leaves']}"
    return None


def check_refutation_file(data: dict[str, Any], path: Path) -> KypCheck:
    """Checker of :data:`SCHEMA` (registered in :mod:`verify.certificates.registry`)."""
    shape, region, band, w, v, refusal = check_claim(data, path)
    if refusal is not None or region is None:
        return KypCheck(False, refusal or "no region")
    refusal, note = band_check.check_source(data, shape, region, path)
    if refusal is not None:
        return KypCheck(False, refusal)
    refusal = check_tree(data, shape, region, w, v)
    if refusal is not None:
        return KypCheck(False, f"does not refute the region: {refusal}")
    where = "at all frequencies" if band is None else f"on [{band[0]}, {band[1]}] rad/s"
    return KypCheck(True, f"no model of the {float(region.level):.4g} confidence region is "
                    f"passive {where}: v^T (H + H^H) v < 0 at w = {w} rad/s for every "
                    f"model, {data['leaves']} leaves checked exactly; {note}")


__all__ = ["check_claim", "check_refutation_file", "check_tree"]
