"""Robust band certificates: every model of a confidence region is passive on a band.

Schema ``verify-robust-band-certificate/1`` (registered in
:data:`verify.certificates.registry.SCHEMAS`). A file holds the claim (structure, parameter
names, region: centre θc, covariance Σ, confidence level and χ² value as exact rationals;
the band [w1, w2] in rad/s, or null for all frequencies), the statement derived from it,
a fingerprint of the claim (also in the file name), the half-widths of the box enclosing
the region's image in φ = (diagonal parameters, c12 + c21), and one tree of midpoint
splits per frequency piece whose leaves are *positive* (claimed lower bounds of N_1, N_2
and det, all > 0, by interval arithmetic on the box), *linear* (claimed lower bounds and
square-root bounds of the first-order form on the box's part of the ellipsoid,
:func:`verify.passivity.check.robust_band.linear_bound`) or *outside* (a point whose
tangent plane shows the box misses the ellipsoid).

This module is the format: the claim's derived parts (statement, fingerprint, file name,
the frequency pieces a band needs) and the certificate's JSON and bytes, which the robust
verdict writes. Its checker, which re-derives everything and decides it exactly with no
solver, is :func:`verify.identify.robust.band_check.check_robust_file`.
"""

from __future__ import annotations

import hashlib
import json
from fractions import Fraction
from typing import Any

from gmpy2 import mpq

from verify.identify.model.region import Region
from verify.passivity.check import robust_band as rb
from verify.passivity.io.binding import slug
from verify.passivity.io.strict_json import CertificateFormatError

SCHEMA = "verify-robust-band-certificate/1"


def q_text(x: Any) -> str:
    """The canonical spelling of a rational ("p" or "p/q")."""
    return str(mpq(x))


def shape_of(structure_text: str) -> rb.Shape:
    """The diagonal degrees of a structure spelled "paper" or "P:Z"."""
    if structure_text == "paper":
        return rb.Shape(1, 2)
    head, sep, tail = structure_text.partition(":")
    if sep and head.isdigit() and tail.isdigit():
        p, z = int(head), int(tail)
        if 0 <= z <= p and 1 <= p <= 12:
            return rb.Shape(z, p)
    raise CertificateFormatError(f"structure {structure_text!r}: expected paper or P:Z "
                                 "(constant off-diagonal elements, at most 12 poles)")


def parameter_names(shape: rb.Shape) -> list[str]:
    """Names in structure order (as :meth:`verify.identify.estimate.structure.Structure.names`)."""
    out: list[str] = []
    for i in (1, 2):
        out += [f"b{k}_{i}" for k in range(shape.zeros, -1, -1)]
        out += [f"a{k}_{i}" for k in range(shape.poles - 1, -1, -1)]
    return [*out, "c12", "c21"]


def pieces_for(band: tuple[Fraction, Fraction] | None) -> list[tuple[str, mpq, mpq]]:
    """The frequency pieces a claim needs: (variable, t1, t2)."""
    if band is None:
        return [("x", mpq(0), mpq(1)), ("y", mpq(0), mpq(1))]
    w1, w2 = mpq(band[0]), mpq(band[1])
    return [("x", w1 * w1, w2 * w2)]


def statement(structure_text: str, level: Fraction, band: tuple | None) -> str:
    """What a certificate proves, derived from its claim."""
    where = ("at every frequency, and every diagonal denominator is Hurwitz (Kharitonov), "
             "so H_θ is passive (positive real)") if band is None else \
        f"for {band[0]} <= w <= {band[1]} rad/s"
    return (f"for every θ with (θ - θc)^T Σ^-1 (θ - θc) <= chi2 (the {float(level):.4g} "
            f"confidence region of the identification), the model H_θ of structure "
            f"{structure_text} (diagonal num_i/den_i, constant off-diagonals) has "
            f"H_θ(jw) + H_θ(jw)^H > 0 {where}")


def fingerprint(structure_text: str, names: list[str], region: dict[str, Any],
                band: list[str] | None) -> str:
    """sha256 of the claim (structure, names, region, band) in canonical JSON."""
    text = json.dumps([structure_text, names, region, band], sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


def file_name(name: str, band: tuple | None, fp: str) -> str:
    """``<name>-robust-band-<w1>-<w2>-<fp12>.json`` or ``<name>-robust-all-<fp12>.json``."""
    where = "all" if band is None else f"band-{float(band[0]):.6g}-{float(band[1]):.6g}"
    return f"{slug(name)}-robust-{where}-{fp[:12]}.json"


def region_json(region: Region) -> dict[str, Any]:
    return {"center": [q_text(x) for x in region.center],
            "covariance": [[q_text(x) for x in row] for row in region.covariance],
            "level": q_text(region.level), "chi2": q_text(region.chi2)}


def certificate_json(name: str, source: str, structure_text: str, region: Region,
                     band: tuple[Fraction, Fraction] | None, enclosure: list[mpq],
                     trees: list[list]) -> dict[str, Any]:
    """The certificate of a proof found by :mod:`verify.identify.robust.verdict`."""
    shape = shape_of(structure_text)
    names = parameter_names(shape)
    reg = region_json(region)
    band_json = None if band is None else [q_text(band[0]), q_text(band[1])]
    pieces = [{"variable": v, "interval": [q_text(t1), q_text(t2)], "tree": tree}
              for (v, t1, t2), tree in zip(pieces_for(band), trees, strict=True)]
    count = sum(1 for tree in trees for node in tree if isinstance(node, list))
    return {"schema": SCHEMA, "name": name, "source": source, "structure": structure_text,
            "parameters": names, "region": reg, "band": band_json,
            "statement": statement(structure_text, region.level, band),
            "fingerprint": fingerprint(structure_text, names, reg, band_json),
            "enclosure": [q_text(r) for r in enclosure], "pieces": pieces, "leaves": count}


def dumps(data: dict[str, Any]) -> str:
    """Certificate bytes: compact JSON, a function of the content only."""
    return json.dumps(data, separators=(",", ":")) + "\n"


__all__ = ["SCHEMA", "certificate_json", "dumps", "file_name", "fingerprint", "parameter_names",
           "pieces_for", "q_text", "region_json", "shape_of", "statement"]
