"""Region-wide refutation certificates: every model of a confidence region fails passivity.

Schema ``verify-robust-refutation-certificate/1`` (registered in
:data:`verify.certificates.registry.SCHEMAS`), the counterpart of the robust band
certificate (:mod:`verify.identify.robust.band_certificate`) for the paper's Section 4 class:
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
on the band (passivity on a band asks H(jw) + H(jw)^H >= 0 at every w of it).

This module is the format (statement, fingerprint, file name, the certificate's JSON and
bytes), which the robust verdict writes; the check, which re-derives all of it in rational
arithmetic with no solver, is
:func:`verify.identify.robust.refutation_check.check_refutation_file`.
"""

from __future__ import annotations

import hashlib
import json
from fractions import Fraction
from typing import Any

from gmpy2 import mpq

from verify.identify.model.region import Region
from verify.identify.robust import band_certificate as rc
from verify.passivity.io.binding import slug

SCHEMA = "verify-robust-refutation-certificate/1"


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
    """The certificate of a refutation found by :mod:`verify.identify.robust.refutation_search`."""
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


def dumps(data: dict[str, Any]) -> str:
    """Certificate bytes: compact JSON, a function of the content only."""
    return json.dumps(data, separators=(",", ":")) + "\n"


__all__ = ["SCHEMA", "certificate_json", "dumps", "file_name", "fingerprint", "statement"]
