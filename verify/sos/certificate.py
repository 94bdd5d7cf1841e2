"""SOS certificates as JSON (schema ``verify-sos-certificate/1``), and their exact checks.

A certificate holds exact rationals as strings and nothing else numeric::

    {"schema": "verify-sos-certificate/1",
     "claim": {"statement": "tr(R) <= 3", "key": "<sha256>", "source": "..."},
     "variables": ["R[0]", ...],
     "numerator": [[[exponents], "p/q"], ...],     # the slack's numerator
     "factors": [{"polynomial": [...], "power": 1}],  # numerator = prod f^k * target
     "target": [...],
     "blocks": [{"grounds": "...", "multiplier": [[poly, ...], ...],
                 "basis": [[exponents], ...], "gram": [["p/q", ...], ...]}]}

Bytes are deterministic (sorted keys, canonical term order). The key is a SHA-256 of
the claim's own data (variables, numerator, and every multiplier the step allows), so a
stored file is reused only for the very step it was made for.

The checks are exact and solver-free, and use only what the certificate and the program
of its claim (:class:`~verify.sos.program.StepProgram`, re-derived by the caller) say:

- :func:`check_bound` (used by ``verify check``/``verify all``): the certificate must
  match the step as re-derived now (numerator, factors, target, each block's multiplier
  among those the step allows, with the same grounds), then identity and Gram PSD.
- :func:`check_form` (a stored file by itself): it parses within the size limits, the
  factors are visibly non-negative (a constant >= 0 plus squares of single variables),
  a block labelled plain SOS has the multiplier 1, the file is named by its key.
- :func:`check_against_program` (a stored file against its claim's program): the key
  and statement are the program's, then :func:`check_bound`.

Which program a stored certificate is bound to (the step it carries, or the paper's
step with its key) is decided above this library, by ``verify certificates check``
(:mod:`verify.certificates.sos_kind`).
"""

from __future__ import annotations

import hashlib
import json
import re
from pathlib import Path

from verify.artefacts.atomic import write_atomic
from verify.sos import poly as pl
from verify.sos.check import SosCheck, check_identity_and_psd
from verify.sos.program import Block, Multiplier, StepProgram

SCHEMA = "verify-sos-certificate/1"
PAPER = "verify.paper_proofs"


def _matrix_json(m: Multiplier) -> list:
    return [[pl.to_json(e) for e in row] for row in m.matrix]


def claim_key(sp: StepProgram) -> str:
    """SHA-256 of the claim: variables, numerator, allowed multipliers (canonical JSON)."""
    claim = {
        "variables": list(sp.program.variables),
        "numerator": pl.to_json(sp.numerator),
        "multipliers": [[m.grounds, _matrix_json(m)] for m in sp.program.multipliers],
    }
    text = json.dumps(claim, sort_keys=True, separators=(",", ":"), ensure_ascii=True)
    return hashlib.sha256(text.encode()).hexdigest()


def file_name(key: str) -> str:
    return f"sos-{key[:20]}.json"


def to_data(sp: StepProgram, blocks: list[Block], grams, key: str, source: str = "",
            step: dict | None = None) -> dict:
    extra = {} if step is None else {"step": step}
    return {
        **extra,
        "schema": SCHEMA,
        "claim": {"statement": sp.statement, "key": key, "source": source},
        "variables": list(sp.program.variables),
        "numerator": pl.to_json(sp.numerator),
        "factors": [{"polynomial": pl.to_json(f), "power": k} for f, k in sp.factors],
        "target": pl.to_json(sp.program.target),
        "blocks": [
            {
                "grounds": b.multiplier.grounds,
                "multiplier": _matrix_json(b.multiplier),
                "basis": [list(m) for m in b.basis],
                "gram": [[str(x) for x in row] for row in q],
            }
            for b, q in zip(blocks, grams, strict=True)
        ],
    }


def dumps(data: dict) -> str:
    return json.dumps(data, sort_keys=True, indent=1, ensure_ascii=False) + "\n"


def write(directory: Path, data: dict) -> Path:
    """Write atomically (temporary file, then rename); returns the path."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / file_name(data["claim"]["key"])
    write_atomic(path, dumps(data))
    return path


def lookup(directory: Path, key: str) -> dict | None:
    path = Path(directory) / file_name(key)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return None
    return data if isinstance(data, dict) else None


# -- parsing --------------------------------------------------------------------------
FIELDS = {"schema", "claim", "variables", "numerator", "factors", "target", "blocks"}
SOURCE = re.compile(r"file:[^\x00-\x1f/\\]{1,255}\.py")


def _exact_fields(obj: object, what: str, required: set[str], optional: set[str] = frozenset()
                  ) -> None:
    if not isinstance(obj, dict):
        raise ValueError(f"{what} must be an object")
    keys = set(obj)
    if not required <= keys or not keys <= required | optional:
        unknown = sorted(keys - required - optional)
        missing = sorted(required - keys)
        raise ValueError(f"{what}: " + (f"unknown field {unknown[0]!r}" if unknown
                                        else f"missing field {missing[0]!r}"))


class Parsed:
    def __init__(self, data: dict):
        if not isinstance(data, dict) or data.get("schema") != SCHEMA:
            raise ValueError(f"schema is not {SCHEMA}")
        _exact_fields(data, "certificate", FIELDS, {"step"})
        _exact_fields(data["claim"], "claim", {"statement", "key", "source"})
        source = data["claim"]["source"]
        if not isinstance(source, str) or not (source in ("", PAPER)
                                               or SOURCE.fullmatch(source)):
            raise ValueError("claim.source must be '', 'verify.paper_proofs' or 'file:NAME.py'")
        key = data["claim"]["key"]
        if not isinstance(key, str) or not re.fullmatch(r"[0-9a-f]{64}", key):
            raise ValueError("claim.key must be a SHA-256 in hexadecimal")
        for f in data["factors"] if isinstance(data["factors"], list) else []:
            _exact_fields(f, "a factor", {"polynomial", "power"})
        for b in data["blocks"] if isinstance(data["blocks"], list) else []:
            _exact_fields(b, "a block", {"grounds", "multiplier", "basis", "gram"})
        names = data.get("variables")
        if not (isinstance(names, list) and all(isinstance(x, str) for x in names)
                and 0 < len(names) <= 400):
            raise ValueError("variables must be a non-empty list of names")
        n = self.n = len(names)
        self.variables = tuple(names)
        claim = data.get("claim")
        if not (isinstance(claim, dict) and isinstance(claim.get("key"), str)
                and isinstance(claim.get("statement"), str)):
            raise ValueError("claim must name its statement and key")
        self.claim = claim
        self.numerator = pl.from_json(data.get("numerator"), n, "numerator")
        self.target = pl.from_json(data.get("target"), n, "target")
        factors = data.get("factors")
        if not isinstance(factors, list):
            raise ValueError("factors must be a list")
        self.factors = []
        for f in factors:
            if not (isinstance(f, dict) and isinstance(f.get("power"), int)
                    and not isinstance(f.get("power"), bool) and 1 <= f["power"] <= 64):
                raise ValueError("a factor needs a polynomial and a power in [1, 64]")
            self.factors.append((pl.from_json(f.get("polynomial"), n, "factor"), f["power"]))
        blocks = data.get("blocks")
        if not isinstance(blocks, list) or len(blocks) > 200:
            raise ValueError("blocks must be a list")
        self.blocks: list[Block] = []
        self.grams = []
        for k, b in enumerate(blocks):
            what = f"block {k}"
            if not isinstance(b, dict) or not isinstance(b.get("grounds"), str):
                raise ValueError(f"{what}: needs grounds, multiplier, basis and gram")
            mat = b.get("multiplier")
            if not (isinstance(mat, list) and mat and len(mat) <= 9
                    and all(isinstance(r, list) and len(r) == len(mat) for r in mat)):
                raise ValueError(f"{what}: multiplier must be a square matrix of polynomials")
            matrix = tuple(tuple(pl.from_json(e, n, what) for e in row) for row in mat)
            basis = b.get("basis")
            if not isinstance(basis, list) or not basis or len(basis) > 2000:
                raise ValueError(f"{what}: basis must be a non-empty list of exponents")
            mons = tuple(pl.monomial_from_json(m, n, what) for m in basis)
            block = Block(Multiplier(b["grounds"], matrix), mons)
            gram = b.get("gram")
            size = block.gram_size
            if not (isinstance(gram, list) and len(gram) == size
                    and all(isinstance(r, list) and len(r) == size for r in gram)):
                raise ValueError(f"{what}: gram must be {size} x {size}")
            self.blocks.append(block)
            self.grams.append([[pl.rational(x, what) for x in row] for row in gram])


MAX_DEGREE = 64  # of the numerator a certificate may state
MAX_TERMS = 2_000_000  # bound on the terms the expansions may produce


def _too_large(c: Parsed) -> str:
    """Why expanding the certificate's identities would be too much work, or "" (decided
    from degrees and term counts alone, before any multiplication)."""
    from math import comb

    top = pl.degree(c.numerator) if c.numerator else 0
    if top > MAX_DEGREE:
        return f"the numerator's degree {top} exceeds {MAX_DEGREE}"
    stated = (pl.degree(c.target) if c.target else 0) + sum(
        k * pl.degree(f) for f, k in c.factors)
    if c.numerator and c.target and stated != top:
        return "numerator is not prod(factor^power) * target (degrees differ)"
    terms = max(len(c.target), 1)
    for f, k in c.factors:
        terms *= comb(len(f) + k - 1, k)
        if terms > MAX_TERMS:
            return f"prod(factor^power) * target would expand to more than {MAX_TERMS} terms"
    work = sum(b.gram_size ** 2 * max((len(e) for row in b.multiplier.matrix for e in row),
                                      default=1) for b in c.blocks)
    if work > 25 * MAX_TERMS:
        return "the Gram expansion would take more than the certificate check's budget"
    return ""


def _identity(c: Parsed) -> SosCheck:
    too_large = _too_large(c)
    if too_large:
        raise ValueError(f"too large to check: {too_large}")
    rebuilt = c.target
    for f, k in c.factors:
        rebuilt = pl.mul(rebuilt, pl.power(f, k, c.n))
    if rebuilt != c.numerator:
        return SosCheck(False, "numerator is not prod(factor^power) * target")
    return check_identity_and_psd(c.target, c.blocks, c.grams)


def check_bound(data: dict, sp: StepProgram) -> SosCheck:
    """Exact check of a certificate against the step it claims (re-derived as ``sp``)."""
    try:
        c = Parsed(data)
        too_large = _too_large(c)
    except ValueError as exc:
        return SosCheck(False, f"malformed SOS certificate: {exc}")
    if too_large:
        return SosCheck(False, f"SOS certificate too large to check: {too_large}")
    if c.variables != sp.program.variables or c.numerator != sp.numerator:
        return SosCheck(False, "the certificate is about another polynomial than this step's")
    if c.target != sp.program.target or c.factors != sp.factors:
        return SosCheck(False, "the certificate's factors or target differ from this step's")
    for k, b in enumerate(c.blocks):
        if not any(b.multiplier.same_as(m) for m in sp.program.multipliers):
            return SosCheck(False, f"block {k}: multiplier '{b.multiplier.grounds}' is not one "
                                   "this step allows")
    return _identity(c)


def _nonneg_factor(f: pl.Poly) -> bool:
    """A constant >= 0 plus non-negative multiples of squares of single variables."""
    for m, c in f.items():
        if c < 0 or not (sum(m) == 0 or (sum(m) == 2 and max(m) == 2)):
            return False
    return bool(f)


def _plain_sos_multipliers(c: Parsed) -> str:
    """A block labelled plain SOS must have the multiplier 1 (else: why not)."""
    for k, b in enumerate(c.blocks):
        if b.multiplier.grounds == "1 (plain SOS)" and b.multiplier.matrix != (
                (pl.constant(1, c.n),),):
            return f"block {k}: labelled plain SOS, but its multiplier is not 1"
    return ""


def check_form(data: dict, path: Path) -> str:
    """What a stored certificate shows by itself, before it is bound to a claim.

    It parses within the size limits (else :class:`ValueError` naming ``path``), every
    factor is visibly non-negative, a block labelled plain SOS has the multiplier 1, and
    the file is named by its key. Returns why not, or "" when all hold.
    """
    try:
        c = Parsed(data)
        too_large = _too_large(c)
    except ValueError as exc:
        raise ValueError(f"{path}: malformed SOS certificate: {exc}") from None
    if too_large:
        raise ValueError(f"{path}: SOS certificate too large to check: {too_large}")
    if not all(_nonneg_factor(f) for f, _k in c.factors):
        return "a factor is not visibly non-negative"
    plain = _plain_sos_multipliers(c)
    if plain:
        return plain
    if path.name != file_name(c.claim["key"]):
        return f"file name is not {file_name(c.claim['key'])} (its key)"
    return ""


def check_against_program(data: dict, sp: StepProgram, bound: str) -> SosCheck:
    """Exact check of a certificate against the program of the claim it is bound to.

    ``sp`` is the claim's program re-derived by the caller (from the step the certificate
    carries, or from the paper's proofs) and ``bound`` says how, for the reason. The
    certificate's key must be the program's key and its written statement the program's
    (else it is refused as *statement edited*: a certificate of ``tr(R) <= 3`` that
    says ``tr(R) <= 2`` is not accepted with a remark), then :func:`check_bound`
    decides it. A valid one is reported as :func:`printed_statement` says.
    """
    key = data["claim"]["key"]
    if claim_key(sp) != key:
        return SosCheck(False, "the claim key is not the key of the step it carries")
    edited = statement_edited(data, sp)
    if edited:
        return SosCheck(False, edited)
    result = check_bound(data, sp)
    if not result.ok:
        return result
    return SosCheck(True, f"{printed_statement(sp)}: {result.reason}; {bound}")


def statement_edited(data: dict, sp: StepProgram) -> str:
    """Why the certificate's written statement is not its program's (``statement
    edited: ...``), or "" when it is."""
    claim = data.get("claim")
    written = claim.get("statement") if isinstance(claim, dict) else None
    if written == sp.statement:
        return ""
    return (f"statement edited: the certificate says {written!r}, but what it proves is "
            f"{sp.claim}")


def printed_statement(sp: StepProgram) -> str:
    """What a checked certificate is reported as: its statement (as the step's tree
    says, names quoted where they could be misread) for all its variables, each with
    its kind or declared sign, with every assumption the step allows
    (:attr:`~verify.sos.program.StepProgram.claim`), e.g.
    ``c (1 + tr(R)) >= 0 for all R ∈ SO(3), c ∈ ℝ with c >= 0``."""
    return sp.claim


__all__ = ["PAPER", "SCHEMA", "check_against_program", "check_bound", "check_form", "claim_key",
           "file_name", "lookup", "printed_statement", "statement_edited", "to_data",
           "write"]
