"""Campaign specifications: a sweep of closed-loop runs, as TOML (numbers and names only).

A campaign asks where the conclusions of Lemma 1 and Theorem 1 hold as the coupling gain
k_s, the human operator (Section 4: identified models, or a family of random passive
ones), the network size, the autonomous input (Section 2) and the reference schedule vary.

```toml
name = "small"                       # optional label; description is optional text

[sweep]                              # each axis: one value, a list, or a range table
k_s = [1.5, 2.0, 2.5]                # or {from = 1.5, to = 4.0, step = 0.5}
n = 8                                # or [4, 8] or {from = 4, to = 16, step = 4}
seeds = {from = 0, count = 4}        # the seed of attitudes, reference and inputs
autonomous = ["consensus"]           # zero | random | consensus     (default consensus)
reference = ["constant"]             # constant | switching (15 s)   (default constant)
seconds = 30                         # simulated time per run        (default 30)
step = "1/120"                       # integrator step = loop period (default 1/120)

[[humans]]                           # at least one; each entry exactly one of:
model = "../models/reconstructed_ks2p5.toml"   # a model file, relative to this spec
[[humans]]
kind = "vr"                          # the VR operator of Section 4
[[humans]]
kind = "static"                      # omega_h^b = gain * e
gain = 1.0
[[humans]]
family = "random-passive"            # seeded random passive humans
count = 3                            # members with seeds seed, seed + 1, ...
seed = 0

[checks]
properties = ["lemma1", "lyapunov"]  # default: every property (see PROPERTIES)
convergence_threshold = 0.05         # |dbar - d_r| level of the convergence time
```

A range table has ``from`` and two of ``to`` (inclusive), ``step`` and ``count``, or
``from`` and ``count`` alone for integers (step 1). Ranges are computed in exact rational
arithmetic from the decimals as written, so ``{from = 1.5, to = 4, step = 0.5}`` gives
exactly 1.5, 2, ..., 4. ``step`` may also be a fraction in quotes ("1/120"): it is read
as the rational it spells, never evaluated.

Everything is checked before any run starts: unknown keys at every level (named, with
the valid ones listed), wrong types, NaN and Inf, empty lists and ranges, k_s <= 0,
n < 1, a model file that does not load or is not a 2- or 3-port model, runs longer than
the simulator keeps in memory. Each problem is a one-line
:class:`~verify.errors.VerifyInputError` that starts with the spec's path.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

from verify.errors import VerifyInputError
from verify.inputs.files import MAX_FILE_BYTES, read_bounded
from verify.inputs.model_file import ModelDocument, model_document_from_bytes
from verify.inputs.numbers import (
    WrittenDecimal,
    parse_number,
    positive_real,
    rational,
    real,
)
from verify.inputs.time_grid import step_count
from verify.inputs.toml import parse_toml_bytes
from verify.validation import shown

#: The property checks of :mod:`verify.sim.properties`, by the name a spec uses.
PROPERTIES = ("stealthiness", "quasi-average", "lemma1", "lyapunov", "lasalle")
AUTONOMOUS = ("zero", "random", "consensus")
REFERENCES = ("constant", "switching")
HUMAN_KINDS = ("vr", "static")
FAMILIES = ("random-passive",)

TOP_KEYS = ("name", "description", "sweep", "humans", "checks")
SWEEP_KEYS = ("k_s", "n", "seeds", "autonomous", "reference", "seconds", "step")
CHECK_KEYS = ("properties", "convergence_threshold")
RANGE_KEYS = ("from", "to", "step", "count")
HUMAN_KEYS = {"model": ("model", "label"), "kind": ("kind", "gain", "label"),
              "family": ("family", "count", "seed")}

DEFAULT_SECONDS = Fraction(30)
DEFAULT_STEP = Fraction(1, 120)  # the loop period of Section 4 (120 Hz)
DEFAULT_THRESHOLD = 0.05  # |dbar - d_r|, about 2.9 degrees between the two directions
MAX_AXIS_VALUES = 100_000  # values of one axis (a range with a tiny step is refused)
MAX_RUNS = 1_000_000  # runs of one campaign
MAX_BODIES = 1_000_000  # as ``verify simulate``: n 3x3 matrices per integrator stage
MAX_STEPS = 2_000_000  # as ``verify simulate``: samples kept in memory per run
MAX_FAMILY = 10_000  # members of one human family
MAX_MODEL_BYTES = MAX_FILE_BYTES  # a model file (a few KB when written by verify)
MAX_SPEC_BYTES = MAX_FILE_BYTES


@dataclass(frozen=True)
class HumanEntry:
    """One ``[[humans]]`` entry, validated.

    ``kind`` is ``model`` (an LTI model file: ``path`` resolved against the spec's
    folder, ``text`` its bytes, ``sha256`` their hash), ``vr``, ``static`` (``gain``) or
    ``family`` (``family``, ``count`` members seeded ``seed``, ``seed + 1``, ...).
    """

    kind: str
    label: str
    path: Path | None = None
    text: bytes | None = None
    sha256: str | None = None
    gain: float | None = None
    family: str | None = None
    count: int = 0
    seed: int = 0


@dataclass(frozen=True)
class CampaignSpec:
    """A validated campaign specification (each axis a non-empty tuple of values)."""

    path: Path
    name: str
    description: str
    k_s: tuple[float, ...]
    n: tuple[int, ...]
    seeds: tuple[int, ...]
    autonomous: tuple[str, ...]
    reference: tuple[str, ...]
    seconds: tuple[float, ...]
    step: tuple[float, ...]
    humans: tuple[HumanEntry, ...]
    properties: tuple[str, ...] = PROPERTIES
    convergence_threshold: float = DEFAULT_THRESHOLD
    source_sha256: str = field(default="", compare=False)

    @property
    def human_count(self) -> int:
        return sum(h.count if h.kind == "family" else 1 for h in self.humans)

    @property
    def run_count(self) -> int:
        """Runs before duplicates (equal human files) are merged."""
        return math.prod(len(a) for a in (self.k_s, self.n, self.seeds, self.autonomous,
                                          self.reference, self.seconds, self.step)
                         ) * self.human_count


def _unknown(table: dict[str, Any], allowed: tuple[str, ...], where: str) -> None:
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        raise VerifyInputError(f"{where}: unknown key(s) {', '.join(unknown)}; valid keys: "
                               f"{', '.join(allowed)}")


def _table(value: Any, where: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise VerifyInputError(f"{where}: expected a table, got {type(value).__name__} "
                               f"{shown(value)}")
    return value


def _text(value: Any, where: str) -> str:
    if not isinstance(value, str):
        raise VerifyInputError(f"{where}: expected a string in quotes, got "
                               f"{type(value).__name__} {shown(value)}")
    return value


def _integer(value: Any, where: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise VerifyInputError(f"{where}: expected an integer, got {type(value).__name__} "
                               f"{shown(value)}; write e.g. 8 (no decimal point, no quotes)")
    return value


def _exact(value: Any, where: str) -> Fraction:
    """A number of the spec as the exact rational it spells (decimals as decimals)."""
    q = rational(value, where)
    return Fraction(int(q.numerator), int(q.denominator))


def _range(table: dict[str, Any], where: str, integer: bool) -> list[Fraction]:
    """The values of a range table, computed exactly (module docstring)."""
    _unknown(table, RANGE_KEYS, where)
    if "from" not in table:
        raise VerifyInputError(f"{where}: a range needs 'from' and two of 'to', 'step', "
                               "'count' (or 'count' alone for integers)")
    number = _integer if integer else _exact
    start = Fraction(number(table["from"], f"{where}.from"))
    given = [k for k in ("to", "step", "count") if k in table]
    if integer and given == ["count"]:
        given, step = ["count", "step"], Fraction(1)
    elif len(given) != 2:
        raise VerifyInputError(f"{where}: give 'from' and exactly two of 'to', 'step', "
                               f"'count' (got {', '.join(given) or 'none of them'})")
    else:
        step = Fraction(number(table["step"], f"{where}.step")) if "step" in table else None
    if "count" in table:
        count = _integer(table["count"], f"{where}.count")
        if count < 1:
            raise VerifyInputError(f"{where}: empty range (count = {count}); give count >= 1")
        if count > MAX_AXIS_VALUES:
            raise VerifyInputError(f"{where}: count = {count} values; at most "
                                   f"{MAX_AXIS_VALUES} per axis")
    if step is not None and step <= 0:
        raise VerifyInputError(f"{where}: step must be > 0, got {table['step']}")
    if "to" in table:
        stop = Fraction(number(table["to"], f"{where}.to"))
        if stop < start:
            raise VerifyInputError(f"{where}: empty range (to = {table['to']} is below from = "
                                   f"{table['from']})")
        if step is None:  # from, to, count: evenly spaced, both ends included
            if count == 1:
                if stop != start:
                    raise VerifyInputError(f"{where}: count = 1 needs to = from")
                return [start]
            if integer and (stop - start) % (count - 1):
                raise VerifyInputError(f"{where}: {count} evenly spaced integers do not fit "
                                       f"from {start} to {stop}; use 'step'")
            return [start + (stop - start) * i / (count - 1) for i in range(count)]
        count = math.floor((stop - start) / step) + 1
        if count > MAX_AXIS_VALUES:
            raise VerifyInputError(f"{where}: the range has {_count_text(count)} values; at "
                                   f"most {MAX_AXIS_VALUES} per axis (enlarge the step)")
    return [start + i * step for i in range(count)]


def _axis(data: dict[str, Any], key: str, where: str, convert: Callable[[Any, str], Any],
          default: Any = None, *, integer: bool = False, ranged: bool = True) -> list[Any]:
    """One sweep axis: a value, a non-empty list of values, or (numbers) a range table."""
    here = f"{where}.{key}"
    if key not in data:
        if default is None:
            raise VerifyInputError(f"{where}: missing '{key}'")
        return [convert(default, here)]
    value = data[key]
    if isinstance(value, dict):
        if not ranged:
            raise VerifyInputError(f"{here}: expected a name or a list of names, not a table")
        values = _range(value, here, integer)
        if integer:  # every value is an integer here (integer from, step and to)
            values = [int(v) for v in values]
        out = []
        for i, v in enumerate(values):
            try:
                out.append(convert(v, f"{here}[{i}]"))
            except VerifyInputError:  # again, for a message that shows a number, not Fraction()
                convert(v if integer else WrittenDecimal(v, _number_text(v)), f"{here}[{i}]")
                raise
        return out
    items = value if isinstance(value, list) else [value]
    if not items:
        raise VerifyInputError(f"{here}: empty list; give at least one value")
    if len(items) > MAX_AXIS_VALUES:
        raise VerifyInputError(f"{here}: {len(items)} values; at most {MAX_AXIS_VALUES}")
    where_of = (lambda i: f"{here}[{i}]") if isinstance(value, list) else (lambda i: here)
    out = [convert(v, where_of(i)) for i, v in enumerate(items)]
    if len(set(out)) != len(out):
        raise VerifyInputError(f"{here}: a value is listed twice; list each once")
    return out


def _number_text(q: Fraction) -> str:
    """A computed rational as a reader would write it: 2, 1.5, or 1/3."""
    if q.denominator == 1 and abs(q.numerator) < 10**15:
        return str(q.numerator)
    if abs(q) < 10**15 and Fraction(float(q)) == q:
        return repr(float(q))
    if q.denominator < 10**6 and abs(q) < 10**15:
        return f"{q.numerator}/{q.denominator}"
    return f"{float(q):.6g}"  # a long value, in six significant figures


def _as_written(raw: Any, x: float) -> str:
    """The text a spec used for the axis value ``x`` (``raw``: the axis as parsed)."""
    items = (list(raw.values()) if isinstance(raw, dict) else raw if isinstance(raw, list)
             else [raw])  # a range's 'from' or 'to', a list, or one value
    for item in items:
        if isinstance(item, WrittenDecimal | int | str) and not isinstance(item, bool):
            try:
                value = float(parse_number(item, "", "") if isinstance(item, str) else item)
            except (VerifyInputError, OverflowError):
                continue
            if value == x:
                return str(item)
    return f"{x:g}"


def _count_text(count: float) -> str:
    """A count for a message: digits when short, else three significant figures."""
    if count < 10**7:
        return str(math.ceil(count))
    return f"{float(count):.3g}" if count < math.inf else "more than 1.8e+308"


def _gain(value: Any, where: str) -> float:
    return positive_real(value, where, "the coupling gain k_s of eq. (6) is > 0")


def _step(value: Any, where: str) -> float:
    """A step: a number, or a fraction in quotes such as "1/120" (read, not evaluated)."""
    if isinstance(value, str):
        value = parse_number(value, where, '"1/120" or 0.004')
    return positive_real(value, where)


def _bodies(value: Any, where: str) -> int:
    n = _integer(value, where)
    if not 1 <= n <= MAX_BODIES:
        raise VerifyInputError(f"{where}: n = {n} bodies; give 1 <= n <= {MAX_BODIES}")
    return n


def _seed(value: Any, where: str) -> int:
    seed = _integer(value, where)
    if not 0 <= seed < 2**63:
        raise VerifyInputError(f"{where}: seed {seed}; give an integer in [0, 2^63)")
    return seed


def _name(choices: tuple[str, ...]) -> Callable[[Any, str], str]:
    def convert(value: Any, where: str) -> str:
        text = _text(value, where)
        if text not in choices:
            raise VerifyInputError(f"{where}: unknown {shown(text)}; choose from "
                                   f"{', '.join(choices)}")
        return text
    return convert


def load_human_model(path: Path, where: str) -> tuple[bytes, ModelDocument]:
    """Read a human model file and validate it as a document (the LTI model it describes
    is built and checked by the campaign, :mod:`verify.campaign.models`).

    The path must name a regular file of at most ``MAX_MODEL_BYTES`` bytes (a FIFO or a
    device is refused before it is read); every error starts with ``where`` (the spec
    and ``humans[i].model``), then the model file's path.
    """
    try:
        raw = read_bounded(path, where=f"{where}: model file {path}",
                           max_bytes=MAX_MODEL_BYTES)
        doc = model_document_from_bytes(raw, str(path))
    except VerifyInputError as exc:
        raise VerifyInputError(prefixed(str(exc), where)) from None
    return raw, doc


def prefixed(text: str, where: str) -> str:
    """An error's text led by ``where`` (once)."""
    return text if text.startswith(where) else f"{where}: {text}"


def _human(entry: Any, where: str, folder: Path) -> HumanEntry:
    entry = _table(entry, where)
    kinds = [k for k in HUMAN_KEYS if k in entry]
    if len(kinds) != 1:
        raise VerifyInputError(f"{where}: give exactly one of 'model' (a file), 'kind' "
                               f"({' or '.join(HUMAN_KINDS)}) or 'family' "
                               f"({', '.join(FAMILIES)})"
                               + (f"; got {' and '.join(kinds)}" if kinds else ""))
    kind = kinds[0]
    _unknown(entry, HUMAN_KEYS[kind], where)
    label = _text(entry["label"], f"{where}.label") if "label" in entry else None
    if kind == "model":
        given = Path(_text(entry["model"], f"{where}.model"))
        path = given if given.is_absolute() else folder / given
        raw, doc = load_human_model(path, f"{where}.model")
        return HumanEntry("model", label or str(doc.name), path=path, text=raw,
                          sha256=hashlib.sha256(raw).hexdigest())
    if kind == "kind":
        name = _name(HUMAN_KINDS)(entry["kind"], f"{where}.kind")
        if name == "vr":
            if "gain" in entry:
                raise VerifyInputError(f"{where}: 'gain' applies to kind = \"static\" only")
            return HumanEntry("vr", label or "VR operator")
        if "gain" not in entry:
            raise VerifyInputError(f"{where}: kind = \"static\" needs 'gain' (omega_h^b = "
                                   "gain * e)")
        gain = real(entry["gain"], f"{where}.gain")
        return HumanEntry("static", label or f"static gain {gain:g}", gain=gain)
    family = _name(FAMILIES)(entry["family"], f"{where}.family")
    if "count" not in entry:
        raise VerifyInputError(f"{where}: a family needs 'count' (how many members)")
    count = _integer(entry["count"], f"{where}.count")
    if not 1 <= count <= MAX_FAMILY:
        raise VerifyInputError(f"{where}.count: {count} members; give 1 <= count <= "
                               f"{MAX_FAMILY}")
    seed = _seed(entry.get("seed", 0), f"{where}.seed")
    return HumanEntry("family", f"{family} (seeds {seed}..{seed + count - 1})",
                      family=family, count=count, seed=seed)


def parse_campaign_spec(data: dict[str, Any], source: Path) -> CampaignSpec:
    """Validate a parsed spec (decimals as exact Fractions); ``source`` is its path."""
    where = str(source)
    _unknown(data, TOP_KEYS, where)
    name = _text(data.get("name", source.stem), f"{where}: name")
    description = _text(data.get("description", ""), f"{where}: description")
    if "sweep" not in data:
        raise VerifyInputError(f"{where}: missing the [sweep] table (k_s, n, seeds, ...)")
    sweep = _table(data["sweep"], f"{where}: sweep")
    _unknown(sweep, SWEEP_KEYS, f"{where}: [sweep]")
    at = f"{where}: sweep"
    k_s = _axis(sweep, "k_s", at, _gain)
    n = _axis(sweep, "n", at, _bodies, integer=True)
    seeds = _axis(sweep, "seeds", at, _seed, integer=True)
    autonomous = _axis(sweep, "autonomous", at, _name(AUTONOMOUS), "consensus", ranged=False)
    reference = _axis(sweep, "reference", at, _name(REFERENCES), "constant", ranged=False)
    seconds = _axis(sweep, "seconds", at, positive_real, DEFAULT_SECONDS)
    step = _axis(sweep, "step", at, _step, DEFAULT_STEP)

    def written(key: str, x: float) -> str:
        return _as_written(sweep.get(key), x)

    for T in seconds:
        for h in step:
            if not T / h <= MAX_STEPS:  # also when T / h overflows to inf
                raise VerifyInputError(f"{at}: seconds = {written('seconds', T)} with step = "
                                       f"{written('step', h)} is {_count_text(T / h)} steps; "
                                       f"at most {MAX_STEPS} are kept in memory per run")
            if step_count(T, h) > MAX_STEPS:
                raise VerifyInputError(f"{at}: seconds = {written('seconds', T)} with step = "
                                       f"{written('step', h)} is "
                                       f"{_count_text(step_count(T, h))} steps; at most "
                                       f"{MAX_STEPS} are kept in memory per run")
        fastest = max(k_s)
        if not fastest * T <= MAX_STEPS:
            raise VerifyInputError(
                f"{at}: k_s = {written('k_s', fastest)} is a valid gain, but the leader's loop "
                "(eq. (6)) then turns at rates up to k_s rad/s, and resolving it over "
                f"seconds = {written('seconds', T)} "
                f"takes at least k_s * seconds = {_count_text(fastest * T)} steps "
                f"of at most 1/k_s, above the {MAX_STEPS} a run keeps; lower k_s or the run "
                "length")
    if "humans" not in data:
        raise VerifyInputError(f"{where}: missing [[humans]] (at least one human model)")
    humans_raw = data["humans"]
    if not isinstance(humans_raw, list) or not humans_raw:
        raise VerifyInputError(f"{where}: 'humans' must be a non-empty array of tables "
                               "[[humans]]")
    folder = source.parent
    humans = tuple(_human(h, f"{where}: humans[{i}]", folder)
                   for i, h in enumerate(humans_raw))
    checks = _table(data.get("checks", {}), f"{where}: checks")
    _unknown(checks, CHECK_KEYS, f"{where}: [checks]")
    properties: tuple[str, ...] = PROPERTIES
    if "properties" in checks:
        value = checks["properties"]
        if not isinstance(value, list):
            raise VerifyInputError(f"{where}: checks.properties: expected a list of names "
                                   f"from {', '.join(PROPERTIES)}")
        chosen = {_name(PROPERTIES)(v, f"{where}: checks.properties[{i}]")
                  for i, v in enumerate(value)}
        properties = tuple(p for p in PROPERTIES if p in chosen)  # canonical order
    threshold = positive_real(checks.get("convergence_threshold", DEFAULT_THRESHOLD),
                          f"{where}: checks.convergence_threshold")
    spec = CampaignSpec(source, name, description, tuple(k_s), tuple(n), tuple(seeds),
                        tuple(autonomous), tuple(reference), tuple(seconds), tuple(step),
                        humans, properties, threshold)
    if spec.run_count > MAX_RUNS:
        raise VerifyInputError(f"{where}: the sweep has {_count_text(spec.run_count)} runs; at "
                               f"most {MAX_RUNS} per campaign (split it into several specs)")
    return spec


def load_campaign_spec(path: str | Path) -> CampaignSpec:
    """Read and validate a campaign spec; every problem is a one-line VerifyInputError.

    Parameters
    ----------
    path : str or Path
        The TOML spec (module docstring); model files are resolved against its folder.

    Returns
    -------
    CampaignSpec
        The axes as tuples of values and the human entries with their files' bytes.
    """
    path = Path(path)
    raw = read_bounded(path, max_bytes=MAX_SPEC_BYTES)
    data = parse_toml_bytes(raw, str(path), exact=True, written=True)
    spec = parse_campaign_spec(data, path)
    return CampaignSpec(**{**spec.__dict__, "source_sha256": hashlib.sha256(raw).hexdigest()})


__all__ = ["AUTONOMOUS", "PROPERTIES", "REFERENCES", "CampaignSpec", "HumanEntry",
           "load_campaign_spec", "load_human_model", "parse_campaign_spec",
           "prefixed"]
