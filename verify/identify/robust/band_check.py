"""The checker of robust band certificates (schema ``verify-robust-band-certificate/1``).

What flows in: a certificate's parsed JSON and its path (the format is
:mod:`verify.identify.robust.band_certificate`); what flows out: a
:class:`verify.passivity.check.certificate.KypCheck`, the verdict of
:func:`check_robust_file` (registered in :data:`verify.certificates.registry.SCHEMAS`).
It re-derives everything and decides it exactly with no solver
(:mod:`verify.passivity.check.robust_band`):

* Σ symmetric positive definite, χ² at least the level's quantile (decided exactly,
  :func:`verify.identify.model.region.level_holds`, no float agreement), the
  fingerprint, file name and statement derived from the claim;
* the enclosure r_i^2 >= χ (A Σ A^T)_ii, the pieces the band asks for (x = w^2 in
  [w1^2, w2^2]; for all frequencies x in [0, 1] and y = 1/w^2 in [0, 1]);
* every leaf of every tree, re-evaluated exactly (the trees' leaves partition each root
  box by construction; a missing or extra node is refused);
* the source model file, when found: its name, structure, written coefficients (= θc),
  covariance (each decimal's nearest float = Σ's binary value), level and χ².
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path
from typing import Any

from gmpy2 import mpq

from verify.errors import VerifyInputError
from verify.identify.model.region import Region, chi2_refusal
from verify.identify.robust.band_certificate import (
    file_name,
    fingerprint,
    parameter_names,
    pieces_for,
    shape_of,
    statement,
)
from verify.inputs.numbers import fraction
from verify.inputs.numbers import rational as exact_number
from verify.passivity.check import robust_band as rb
from verify.passivity.check.certificate import KypCheck
from verify.passivity.io.binding import resolve_source
from verify.passivity.io.strict_json import (
    CertificateFormatError,
    fields,
    rational,
    rational_matrix,
    text_field,
)

_FIELDS = ("schema", "name", "source", "structure", "parameters", "region", "band",
           "statement", "fingerprint", "enclosure", "pieces", "leaves")


# ------------------------------------------------------------------ parsing


def _region(value: Any, p: int) -> tuple[Region, dict[str, Any]]:
    if not isinstance(value, dict):
        raise CertificateFormatError("field 'region' must be an object")
    fields(value, required=("center", "covariance", "level", "chi2"), where="region")
    (center,) = rational_matrix([value["center"]], "region.center", 1, p)
    cov = rational_matrix(value["covariance"], "region.covariance", p, p)
    level = rational(value["level"], "region.level")
    chi2 = rational(value["chi2"], "region.chi2")
    region = Region(tuple(center), tuple(tuple(r) for r in cov),
                    fraction(level), chi2)
    return region, value


def _band(value: Any) -> tuple[Fraction, Fraction] | None:
    if value is None:
        return None
    if not isinstance(value, list) or len(value) != 2:
        raise CertificateFormatError("field 'band' must be [w1, w2] or null")
    w1, w2 = (rational(v, f"band[{k}]") for k, v in enumerate(value))
    if not 0 <= w1 < w2:
        raise CertificateFormatError(f"band [{w1}, {w2}] does not satisfy 0 <= w1 < w2")
    return fraction(w1), fraction(w2)


def _leaf(node: list, dims: int) -> tuple[str, list[mpq]]:
    if not node or not isinstance(node[0], str):
        raise CertificateFormatError("a leaf must start with 'positive' or 'outside'")
    if node[0] == "positive" and len(node) == 4:
        return "positive", [rational(v, "leaf bound") for v in node[1:]]
    if node[0] == "outside" and len(node) == 2 and isinstance(node[1], list) \
            and len(node[1]) == dims:
        return "outside", [rational(v, "leaf point") for v in node[1]]
    if node[0] == "linear" and len(node) == 7:
        return "linear", [rational(v, "leaf bound") for v in node[1:]]
    raise CertificateFormatError(f"malformed leaf {str(node)[:60]}")


parse_region = _region
parse_band = _band


# ------------------------------------------------------------------ checking


def check_claim(data: dict[str, Any], path: Path) -> tuple[rb.Shape, Region,
                                                          tuple | None, str | None]:
    """Parse and check everything but the leaves: (shape, region, band, refusal or None)."""
    fields(data, required=_FIELDS)
    name, structure_text = text_field(data, "name"), text_field(data, "structure")
    text_field(data, "source")
    shape = shape_of(structure_text)
    names = parameter_names(shape)
    if data["parameters"] != names:
        return shape, None, None, f"parameters {data['parameters']!r} are not the " \
            f"structure's {names}"  # type: ignore[return-value]
    region, reg_json = _region(data["region"], shape.parameters)
    band = _band(data["band"])
    if not 0 < region.level < 1:
        return shape, region, band, f"level {region.level} is not in (0, 1)"
    if not rb.is_positive_definite([list(r) for r in region.covariance]):
        return shape, region, band, "the covariance is not symmetric positive definite"
    why = chi2_refusal(region.level, region.chi2, shape.parameters)
    if why is not None:
        return shape, region, band, why
    fp = fingerprint(structure_text, names, reg_json, data["band"])
    if data["fingerprint"] != fp:
        return shape, region, band, "fingerprint does not match the claim"
    if Path(path).name != file_name(name, band, fp):
        return shape, region, band, ("file name does not match the content (expected "
                                     f"{file_name(name, band, fp)})")
    if data["statement"] != statement(structure_text, region.level, band):
        return shape, region, band, "statement edited: not the one derived from the claim"
    return shape, region, band, None


def read_enclosure(data: dict[str, Any], region: Region
                   ) -> tuple[list, list, list] | str:
    """The region reduced to its free coordinates (phi, their covariance) and the
    certificate's box half-widths, checked exactly to enclose it; the refusal otherwise."""
    phi, cov_phi = rb.reduce_region(region.center, region.covariance)
    dims = len(phi)
    enclosure = data["enclosure"]
    if not isinstance(enclosure, list) or len(enclosure) != dims:
        raise CertificateFormatError(f"field 'enclosure' must list {dims} half-widths")
    r = [rational(x, f"enclosure[{i}]") for i, x in enumerate(enclosure)]
    bad = rb.enclosure_ok(cov_phi, region.chi2, r)
    if bad is not None:
        return f"the box does not enclose the region: {bad}"
    return phi, cov_phi, r


def check_leaves(data: dict[str, Any], shape: rb.Shape, region: Region,
                 band: tuple | None) -> str | None:
    """The enclosure, the pieces and every leaf, exactly; None when all pass."""
    enclosed = read_enclosure(data, region)
    if isinstance(enclosed, str):
        return enclosed
    phi, cov_phi, r = enclosed
    dims = len(phi)
    S = rb.inverse(cov_phi)
    pieces = data["pieces"]
    wanted = pieces_for(band)
    if not isinstance(pieces, list) or len(pieces) != len(wanted):
        return f"expected {len(wanted)} frequency piece(s) for this band"
    count = 0
    for k, (piece, (variable, t1, t2)) in enumerate(zip(pieces, wanted, strict=True)):
        if not isinstance(piece, dict):
            raise CertificateFormatError(f"pieces[{k}] must be an object")
        fields(piece, required=("variable", "interval", "tree"), where=f"pieces[{k}]")
        interval = [rational(v, f"pieces[{k}].interval") for v in piece["interval"]] \
            if isinstance(piece["interval"], list) else None
        if piece["variable"] != variable or interval != [t1, t2]:
            return (f"piece {k} covers {piece['variable']} in {piece['interval']}, not "
                    f"{variable} in [{t1}, {t2}] as the band asks")
        if not isinstance(piece["tree"], list):
            raise CertificateFormatError(f"pieces[{k}].tree must be a list")
        root = [(c - h, c + h) for c, h in zip(phi, r, strict=True)] + [(t1, t2)]
        try:
            for index, (box, node) in enumerate(rb.leaves(piece["tree"], root)):
                kind, values = _leaf(node, dims)
                if kind == "positive":
                    result = rb.check_positive_leaf(box, variable, shape, values,
                                                    stability=band is None)
                elif kind == "linear":
                    result = rb.check_linear_leaf(box, variable, shape, cov_phi, phi,
                                                  region.chi2, values[:3], values[3:],
                                                  stability=band is None)
                else:
                    result = rb.check_outside_leaf(box, S, phi, region.chi2, values)
                if not result.ok:
                    return f"piece {k}, leaf {index} ({kind}): {result.reason}"
                count += 1
        except rb.TreeError as exc:
            return f"piece {k}: {exc}"
    if count != data["leaves"]:
        return f"{count} leaves checked, the file says {data['leaves']}"
    return None


def check_source(data: dict[str, Any], shape: rb.Shape, region: Region,
                 path: Path) -> tuple[str | None, str]:
    """Compare the claim with the source model file when it is found: (refusal, note)."""
    from verify.identify.model.model_writer import read_identified, structure_text

    source = data["source"]
    found = resolve_source(source, path)
    if found is None and source:
        sibling = Path(path).parent / Path(source).name
        found = sibling if sibling.is_file() else None
    if found is None:
        return None, f"source {source} not found here: the claim is about the stored region"
    try:
        ident = read_identified(found)
        cov = ident.covariance()
        chi2 = ident.number("chi2")
        level = fraction(exact_number(ident.identification.get("confidence_level"),
                                      f"{source}: [identification] confidence_level"))
    except VerifyInputError as exc:
        return f"source {source} is not an identified model file ({exc})", ""
    if ident.model.name != data["name"]:
        return f"name {data['name']!r} is not the source file's {ident.model.name!r}", ""
    if structure_text(ident.structure) != data["structure"]:
        return "the source file's structure differs", ""
    if tuple(ident.center) != tuple(region.center):
        return ("the region's centre is not the source file's written coefficients "
                "(exact values differ)"), ""
    if any(mpq(float(v)) != region.covariance[i][j]
           for i, row in enumerate(cov) for j, v in enumerate(row)):
        return "the covariance differs from the source file's [identification] covariance", ""
    if mpq(chi2) != region.chi2 or level != region.level:
        return "the level or chi2 differ from the source file's", ""
    return None, f"region bound to {source} (centre = its written coefficients)"


def check_robust_file(data: dict[str, Any], path: Path) -> KypCheck:
    """Checker of :data:`SCHEMA` (registered in :mod:`verify.certificates.registry`)."""
    shape, region, band, refusal = check_claim(data, path)
    if refusal is not None:
        return KypCheck(False, refusal)
    refusal, note = check_source(data, shape, region, path)
    if refusal is not None:
        return KypCheck(False, refusal)
    refusal = check_leaves(data, shape, region, band)
    if refusal is not None:
        return KypCheck(False, f"does not prove robust passivity: {refusal}")
    where = "at all frequencies" if band is None else f"on [{band[0]}, {band[1]}] rad/s"
    return KypCheck(True, f"every model of the {float(region.level):.4g} confidence region "
                    f"is passive {where}: {data['leaves']} leaves checked exactly; {note}")


__all__ = ["check_claim", "check_leaves", "check_robust_file", "check_source", "parse_band",
           "parse_region", "read_enclosure"]
