"""Robust verdicts over an identified region as Coq units (the paper's Section 4).

A ``verify-robust-band-certificate/1`` says that every model of an identification's
confidence region {θ : (θ - θc)^T Σ^-1 (θ - θc) <= χ²} is passive on a band; a
``verify-robust-refutation-certificate/1`` that none is. The unit written here states it
from the definitions of the prelude ``RobustCert.v`` (the model class of the paper's
structure, its Hermitian part with BandCert.v's complex arithmetic):

* ``robust_passive : forall th, in_region Si thc chi2 th -> paper_band_passive th w1 w2``
  or ``robust_not_passive : forall th, in_region Si thc chi2 th -> ~ paper_band_passive
  th w1 w2``;
* ``sigma_inverse : inv_check 10 Si Sg = true``: the region's matrix is the inverse of the
  identification's covariance Σ (Sg), exactly.

Both follow from one lemma, ``certificate_checked``, the whole check evaluated once by the
kernel (``Si Sg = I`` is part of it).

The data: Σ and its exact inverse, an LDLᵀ witness that Σ^-1 >= 0 (QCert's check), the
centre, χ², the enclosing box's half-widths and the certificate's tree of leaves. Coq
re-checks everything by computation (``robust_band_check``, ``robust_refutation_check``)
with the lemmas proved once in the prelude. The exporter first re-checks the certificate
with the exact Python checker (binding included) and refuses it when that fails.

A refutation's leaves (*negative*, *linear*) are exported as they are. A band's leaves
are written with short numbers (:func:`band_tree_literal`): a leaf *outside* (a tangent
plane shows the box misses the region) as ``ROut y``, a short rational direction y for
which Coq checks the region's dual bound over the box (``out_ok``;
:mod:`verify.coq.robust_outside`); a positive or linear leaf on its box rounded out to a
coarse dyadic grid (``RGrid``), a linear one with short directions (``RLinY``;
:mod:`verify.coq.robust_leaves`). Each form is checked exactly in Python before it is
written, and Coq re-checks it whatever its numbers.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from gmpy2 import mpq

from verify.coq.kyp import CoqExportError, matrix_literal, module_name, q_literal, terms_literal
from verify.coq.unit import CoqUnit, comment_text
from verify.coq.witness import psd_witness

BAND_SCHEMA = "verify-robust-band-certificate/1"
REFUTATION_SCHEMA = "verify-robust-refutation-certificate/1"
BAND_THEOREM = "robust_passive"
REFUTATION_THEOREM = "robust_not_passive"
INVERSE_THEOREM = "sigma_inverse"
CHECK_LEMMA = "certificate_checked"

#: Why a tangent-plane leaf without its direction cannot be written.
OUTSIDE_REASON = ("a leaf 'outside' (a tangent plane shows the box misses the region) needs "
                  "its direction, computed from the region")


def _q(x: Any) -> str:
    return q_literal(mpq(x))


def _list(values) -> str:
    return "[" + "; ".join(_q(v) for v in values) + "]"


def _leaf(node: list, refutation: bool) -> str:
    kind = node[0]
    if kind == "outside":
        raise CoqExportError(OUTSIDE_REASON)
    values = [mpq(v) for v in node[1:]]
    if not refutation and kind == "positive" and len(values) == 3:
        return "RLeaf (RPos " + " ".join(_q(v) for v in values) + ")"
    if not refutation and kind == "linear" and len(values) == 6:
        return "RLeaf (RLin " + " ".join(_q(v) for v in values) + ")"
    if refutation and kind == "negative" and len(values) == 1:
        return f"RLeaf (RNeg {_q(values[0])})"
    if refutation and kind == "linear" and len(values) == 2:
        return f"RLeaf (RNegLin {_q(values[0])} {_q(values[1])})"
    raise CoqExportError(f"leaf {kind!r} is not one RobustCert.v checks")


def tree_literal(tree: list, refutation: bool) -> str:
    """The pre-order tree (an int k splits coordinate k, left half first; a list is a
    leaf) as a nested Coq ``rtree``, its leaves as the certificate writes them (a leaf
    *outside* needs the region: :func:`band_tree_literal`)."""
    out: list[str] = []
    position = 0

    def walk() -> None:
        nonlocal position
        node = tree[position]
        position += 1
        if isinstance(node, int):
            out.append(f"(RSplit {node} ")
            walk()
            out.append(" ")
            walk()
            out.append(")")
        else:
            out.append("(" + _leaf(node, refutation) + ")")

    walk()
    if position != len(tree):
        raise CoqExportError("the tree has nodes after its last box")
    return "".join(out)


def band_tree_literal(tree: list, region, band: tuple, enclosure: Sequence) -> str:
    """A band tree as a Coq ``rtree`` with short numbers, every form checked exactly in
    Python first (:mod:`verify.coq.robust_leaves`, :mod:`verify.coq.robust_outside`):

    * a leaf *outside* as ``ROut y`` with a short direction y;
    * a positive leaf as ``RGrid 2^k (RLeaf (RPos c0 c1 c2))``, its box rounded out to the
      coarsest grid 2^-k that passes; a linear leaf as ``RGrid 2^k (RLeaf (RLinY ...))``
      with short directions.

    A leaf for which no short form passes is written as it is (``RPos``, ``RLin``)."""
    from verify.coq.robust_leaves import short_linear, short_positive
    from verify.coq.robust_outside import outside_direction
    from verify.passivity.check import robust_band as rb

    phi, cov_phi = rb.reduce_region(region.center, region.covariance)
    inverse = rb.inverse(cov_phi)
    chi2 = region.chi2
    r = [mpq(x) for x in enclosure]
    w1, w2 = (mpq(w) for w in band)
    root = [(c - h, c + h) for c, h in zip(phi, r, strict=True)] + [(w1 * w1, w2 * w2)]
    list(rb.leaves(tree, root))  # a malformed tree is refused here, as the checker does
    position = 0

    def short(box, claimed, linear: bool) -> str | None:
        """A leaf on ``box`` with short numbers that passes, or None."""
        if not linear:
            found = short_positive(box, claimed)
            if found is None:
                return None
            bits, bounds = found
            return (f"(RGrid {2 ** bits} (RLeaf (RPos " + " ".join(_q(c) for c in bounds)
                    + ")))")
        found_lin = short_linear(box, claimed, phi, cov_phi, chi2)
        if found_lin is None:
            return None
        bits, forms = found_lin
        cs = " ".join(_q(c) for c, _, _ in forms)
        ss = " ".join(_q(s) for _, s, _ in forms)
        ys = " ".join(_list(y) for _, _, y in forms)
        return f"(RGrid {2 ** bits} (RLeaf (RLinY {cs} {ss} {ys})))"

    def walk(box):
        nonlocal position
        node = tree[position]
        position += 1
        if isinstance(node, int):
            left, right = rb.midpoint_split(box, node)
            return f"(RSplit {node} {walk(left)} {walk(right)})"
        kind = node[0]
        if kind == "outside":
            point = [mpq(v) for v in node[1]]
            y = outside_direction(box[:-1], point, phi, cov_phi, inverse, chi2)
            if y is None:
                raise CoqExportError("a leaf 'outside' whose box meets the region")
            return f"(RLeaf (ROut {_list(y)}))"
        values = [mpq(v) for v in node[1:]]
        if (kind, len(values)) in (("positive", 3), ("linear", 6)):
            found = short(box, values[:3], kind == "linear")
            if found is not None:
                return found
        return "(" + _leaf(node, False) + ")"

    return walk(root)


_LONG_INTEGER = re.compile(r"(?<![\w.])(-?)(\d{20,})(?![\w.])")


def _hex_integers(text: str) -> str:
    """The integers of 20 digits or more in a literal rewritten in Coq's hexadecimal
    notation (``0x...``): the same numbers, but Coq converts hexadecimal digits to its
    binary integers in linear time, decimal ones in quadratic time (the inverse of Σ has
    numerators of about 165 digits, seconds of coqc for the decimal form)."""
    return _LONG_INTEGER.sub(lambda m: f"{m.group(1)}{hex(int(m.group(2)))}", text)


def _region_lines(region) -> list[str]:
    from verify.passivity.check import robust_band as rb

    sigma = [[mpq(x) for x in row] for row in region.covariance]
    inverse = rb.inverse(sigma)
    witness = psd_witness(inverse)
    if witness is None:
        raise CoqExportError("no witness that the inverse covariance is >= 0")
    return [
        "(** The identification's covariance, its exact inverse (the region's matrix), and a",
        "    witness that the inverse is >= 0 (QCert.v's check); integers of 20 digits or",
        "    more are written in hexadecimal, 0x... *)",
        f"Definition Sg : matQ :=\n  {_hex_integers(matrix_literal(sigma))}.",
        f"Definition Si : matQ :=\n  {_hex_integers(matrix_literal(inverse))}.",
        f"Definition eS : Q := {_q(witness.eps)}.",
        f"Definition wS : list term :=\n  {_hex_integers(terms_literal(witness))}.",
        f"Definition thc : list Q := {_list(region.center)}.",
        f"Definition chi2 : Q := {_q(region.chi2)}.",
        "",
    ]


def robust_unit(path: Path, data: dict[str, Any]) -> CoqUnit:
    """The unit of a checked robust band or refutation certificate (paper structure)."""
    from verify.identify.robust.band_check import parse_band, parse_region

    if data.get("structure") != "paper":
        raise CoqExportError(f"structure {data.get('structure')!r}: RobustCert.v states the "
                             "paper's structure only")
    refutation = data["schema"] == REFUTATION_SCHEMA
    region, _ = parse_region(data["region"], 10)
    band = parse_band(data["band"])
    if band is None:
        raise CoqExportError("a claim at every frequency (stability of the denominators) is "
                             "not stated in RobustCert.v")
    if refutation:
        tree = tree_literal(data["tree"], True)
    else:
        if len(data["pieces"]) != 1:
            raise CoqExportError("expected one frequency piece for a band")
        piece_tree = data["pieces"][0]["tree"]
        tree = band_tree_literal(piece_tree, region, band, data["enclosure"])
    w1, w2 = band
    name = module_name(path.name)
    kind = "Robust refutation" if refutation else "Robust band"
    lines = [
        f"(** {comment_text(kind + ' certificate ' + path.name)}:",
        "    exported by verify; checked by coqc.",
        f"    Model: {comment_text(data['name'])} (structure paper: diagonal",
        "    (b1 s + b0) / (s^2 + a1 s + a0), constant off-diagonal c12, c21).",
        f"    Source file: {comment_text(data['source'])}",
        f"    Fingerprint of the claim: {data['fingerprint']}",
        f"    Claim: {'no' if refutation else 'every'} model of the region "
        "(th - thc)^T Si (th - thc) <= chi2,",
        f"    Si Sg = I, is passive on [{w1}, {w2}] rad/s ([paper_band_passive] in "
        "RobustCert.v). *)",
        "",
        "From Coq Require Import QArith Reals List.",
        "From VerifyCoq Require Import QCert BandCert RobustCert.",
        "Import ListNotations.",
        "",
        *_region_lines(region),
        "(** The half-widths of the box enclosing the region (coordinates of phi). *)",
        f"Definition r : list Q := {_list(data['enclosure'])}.",
        f"Definition w1 : Q := {_q(w1)}.",
        f"Definition w2 : Q := {_q(w2)}.",
    ]
    if refutation:
        v1, v2 = (mpq(v) for v in data["direction"])
        lines += [
            f"Definition wstar : Q := {_q(data['frequency'])}.",
            f"Definition v1 : Q := {_q(v1)}.",
            f"Definition v2 : Q := {_q(v2)}.",
        ]
    lines += [
        "(** The certificate's tree of midpoint splits and its leaves. *)",
        f"Definition tr : rtree :=\n  {tree}.",
        "",
    ]
    if refutation:
        check, sound, args = ("robust_refutation_check", "robust_refutation_sound",
                              "Si Sg eS wS thc chi2 r w1 w2 wstar v1 v2 tr")
        statement = "~ paper_band_passive th w1 w2"
        theorem = REFUTATION_THEOREM
    else:
        check, sound, args = ("robust_band_check", "robust_band_sound",
                              "Si Sg eS wS thc chi2 r w1 w2 tr")
        statement = "paper_band_passive th w1 w2"
        theorem = BAND_THEOREM
    lines += [
        "(** The whole check (Si Sg = I included), evaluated once by the kernel, at Qed. *)",
        f"Lemma {CHECK_LEMMA} : {check} {args} = true.",
        "Proof. vm_cast_no_check (eq_refl true). Qed.",
        "",
        f"Theorem {INVERSE_THEOREM} : inv_check 10 Si Sg = true.",
        f"Proof. exact ({check}_inv {args} {CHECK_LEMMA}). Qed.",
        "",
        f"Theorem {theorem} :",
        f"  forall th, in_region Si thc chi2 th -> {statement}.",
        f"Proof. exact ({sound} {args} {CHECK_LEMMA}). Qed.",
        "",
    ]
    return CoqUnit(name, "\n".join(lines), (INVERSE_THEOREM, theorem),
                   f"Robust certificate {path.name}")


def robust_unit_from_file(path: Path) -> CoqUnit:
    """The unit of a stored robust certificate, after the exact checker accepts it
    (CoqExportError, one line, otherwise)."""
    from verify.identify.robust.band_check import check_robust_file
    from verify.identify.robust.refutation_check import check_refutation_file
    from verify.passivity.io.strict_json import CertificateFormatError, read_strict

    path = Path(path)
    try:
        data = read_strict(path)
        schema = data.get("schema")
        if schema not in (BAND_SCHEMA, REFUTATION_SCHEMA):
            raise CoqExportError(f"{path.name}: not a robust certificate (schema {schema!r})")
        check = check_robust_file if schema == BAND_SCHEMA else check_refutation_file
        result = check(data, path)
        if not result.ok:
            raise CoqExportError(f"{path.name}: not exported: {result.reason}")
        return robust_unit(path, data)
    except CertificateFormatError as exc:
        raise CoqExportError(f"{path.name}: {exc}") from None
    except CoqExportError as exc:
        text = str(exc)
        raise CoqExportError(text if text.startswith(path.name) else
                             f"{path.name}: {text}") from None


__all__ = ["BAND_SCHEMA", "OUTSIDE_REASON", "REFUTATION_SCHEMA", "band_tree_literal",
           "robust_unit", "robust_unit_from_file", "tree_literal"]
