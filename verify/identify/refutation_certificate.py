"""Region-wide refutation certificates: every model of a confidence region fails passivity.

Schema ``verify-robust-refutation-certificate/1`` (registered in
:data:`verify.certificates.registry.SCHEMAS`), the counterpart of the robust band
certificate (:mod:`verify.identify.robust_certificate`) for the paper's Section 4 class:
2 x 2 models with diagonal elements num_i/den_i and constant off-diagonal elements. A file
holds the claim (structure, parameter names, the region as exact rationals: centre θc,
covariance Σ, confidence level and χ²; the band asked, or null), one rational frequency w
inside the band and one real rational direction v = (v_1, v_2), the statement derived from
them, a fingerprint of all of it (also in the file name), the half-widths of the box
enclosing the region's image in φ = (diagonal parameters, c12 + c21), and one tree of
midpoint splits over that box whose leaves are

* *negative*: a claimed bound u < 0 with g <= u over the box by exact interval arithmetic,
  and |den_i(jw)|^2 > 0 (:func:`verify.passivity.check.robust_band.check_negative_leaf`);
* *linear*: the same on the box's part of the ellipsoid by the first-order form
  (:func:`verify.passivity.check.robust_band.check_negative_linear_leaf`);
* *outside*: a point whose tangent plane shows the box misses the ellipsoid.

With g = (D_1 D_2 / 2) v^T (H_θ(jw) + H_θ(jw)^H) v, every θ of the region then has
v^T (H_θ(jw) + H_θ(jw)^H) v < 0 at one w of the band: no model of the region is passive
on the band (passivity on a band asks H(jw) + H(jw)^H >= 0 at every w of it). The check
(:func:`check_refutation_file`) re-derives all of it in rational arithmetic, with no
solver, and compares the region with the source model file when it is found.
"""

from __future__ import annotations

import hashlib
import json
from fractions import Fraction
from pathlib import Path
from typing import Any

from gmpy2 import mpq

from verify.identify import robust_certificate as rc
from verify.identify.region import Region, chi2_refusal
from verify.passivity.check import robust_band as rb
from verify.passivity.check.certificate import KypCheck
from verify.passivity.io.binding import slug
from verify.passivity.io.strict_json import (
    CertificateFormatError,
    fields,
    rational,
    text_field,
)

SCHEMA = "verify-robust-refutation-certificate/1"
_FIELDS = ("schema", "name", "source", "structure", "parameters", "region", "band",
           "frequency", "direction", "statement", "fingerprint", "enclosure", "tree",
           "leaves")


def statement(structure_text: str, level: Fraction, band: tuple | None, w: mpq,
              v: tuple[mpq, mpq]) -> str:
    """What a refutation proves, derived from its claim."""
    where = "at all frequencies" if band is None else \
        f"on the band {band[0]} <= w <= {band[1]} rad/s"
    return (f"for every θ with (θ - θc)^T Σ^-1 (θ - θc) <= chi2 (the {float(level):.4g} "
            f"confidence region of the identification), the model H_θ of structure "
            f"{structure_text} (diagonal num_i/den_i, constant off-diagonals) has "
            f"v^T (H_θ(jw) + H_θ(jw)^H) v < 0 at w = {w} rad/s for v = ({v[0]}, {v[1]}), so "
            f"no model of the region is passive {where}")


def fingerprint(structure_text: str, names: list[str], region: dict[str, Any],
                band: list[str] | None, w: str, v: list[str]) -> str:
    """sha256 of the claim in canonical JSON."""
    text = json.dumps([structure_text, names, region, band, w, v], sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


def file_name(name: str, w: Any, fp: str) -> str:
    """``<name>-robust-refuted-at-<w>-<fp12>.json``."""
    return f"{slug(name)}-robust-refuted-at-{float(w):.6g}-{fp[:12]}.json"


def certificate_json(name: str, source: str, structure_text: str, region: Region,
                     band: tuple[Fraction, Fraction] | None, w: mpq, v: tuple[mpq, mpq],
                     enclosure: list[mpq], tree: list) -> dict[str, Any]:
    """The certificate of a refutation found by :mod:`verify.identify.robust_refutation`."""
    names = rc.parameter_names(rc.shape_of(structure_text))
    reg = rc.region_json(region)
    band_json = None if band is None else [rc.q_text(band[0]), rc.q_text(band[1])]
    w_text, v_text = rc.q_text(w), [rc.q_text(v[0]), rc.q_text(v[1])]
    return {"schema": SCHEMA, "name": name, "source": source, "structure": structure_text,
            "parameters": names, "region": reg, "band": band_json, "frequency": w_text,
            "direction": v_text,
            "statement": statement(structure_text, region.level, band, mpq(w), v),
            "fingerprint": fingerprint(structure_text, names, reg, band_json, w_text,
                                       v_text),
            "enclosure": [rc.q_text(r) for r in enclosure], "tree": tree,
            "leaves": sum(1 for node in tree if isinstance(node, list))}


# ------------------------------------------------------------------ checking


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
    region, reg_json = rc.parse_region(data["region"], shape.parameters)
    band = rc.parse_band(data["band"])

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
        return refuse("statement is not the one derived from the claim")
    return shape, region, band, w, v, None


def check_tree(data: dict[str, Any], shape: rb.Shape, region: Region, w: mpq,
               v: tuple[mpq, mpq]) -> str | None:
    """The enclosure and every leaf, exactly; None when all pass."""
    enclosed = rc.read_enclosure(data, region)
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
    refusal, note = rc.check_source(data, shape, region, path)
    if refusal is not None:
        return KypCheck(False, refusal)
    refusal = check_tree(data, shape, region, w, v)
    if refusal is not None:
        return KypCheck(False, f"does not refute the region: {refusal}")
    where = "at all frequencies" if band is None else f"on [{band[0]}, {band[1]}] rad/s"
    return KypCheck(True, f"no model of the {float(region.level):.4g} confidence region is "
                    f"passive {where}: v^T (H + H^H) v < 0 at w = {w} rad/s for every "
                    f"model, {data['leaves']} leaves checked exactly; {note}")


def dumps(data: dict[str, Any]) -> str:
    """Certificate bytes: compact JSON, a function of the content only."""
    return json.dumps(data, separators=(",", ":")) + "\n"


__all__ = ["SCHEMA", "certificate_json", "check_claim", "check_refutation_file",
           "check_tree", "dumps", "file_name", "fingerprint", "statement"]
