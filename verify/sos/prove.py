"""Search, round, check: from an :class:`SosProgram` to an exactly checked certificate."""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass

from verify.sos import poly as pl
from verify.sos.basis import choose_basis
from verify.sos.check import SosCheck, check_identity_and_psd
from verify.sos.program import Block, SosProgram
from verify.sos.rounding import DENOMINATORS, _columns, correct, round_grams
from verify.sos.search import solve

MAX_GRAM_ENTRIES = 12000  # sum of n(n+1)/2 over a stage's blocks; larger ones are not attempted


@dataclass
class Found:
    """Outcome of a search; ``grams`` is exact and checked when ``check.ok``."""

    check: SosCheck
    blocks: list[Block]
    grams: list | None
    solver_seconds: float = 0.0
    seconds: float = 0.0
    denominator: int | None = None


def blocks_for(program: SosProgram, groups: Sequence[Sequence[int]],
               max_degree: int | None = None) -> list[Block]:
    blocks = []
    for mult in program.multipliers:
        basis = choose_basis(program.target, mult, groups, max_degree=max_degree)
        if basis:
            blocks.append(Block(mult, basis))
    return blocks


def find_certificate(program: SosProgram, groups: Sequence[Sequence[int]], *,
                     max_degree: int | None = None, time_limit: float = 60.0) -> Found:
    start = time.perf_counter()
    target = program.target
    if not target:
        return Found(SosCheck(True, "the target is the zero polynomial"), [], [])
    blocks = blocks_for(program, groups, max_degree)
    if not blocks:
        return Found(SosCheck(False, "no multiplier and monomial basis fits the slack "
                                     f"(degree {pl.degree(target)})"), [], None)
    # matrix multipliers (spectral facts, PSD assumptions) first, alone: when they
    # suffice the program is much smaller; then every block
    stages = [[b for b in blocks if b.multiplier.size > 1], blocks]
    stages = [st for k, st in enumerate(stages) if st and (k == 0 or st != stages[0])]
    last = SosCheck(False, "no SOS decomposition found")
    solver_seconds = 0.0
    for stage in stages:
        found = _attempt(stage, target, time_limit)
        solver_seconds += found.solver_seconds
        found.solver_seconds, found.seconds = solver_seconds, time.perf_counter() - start
        if found.check.ok:
            return found
        last = found.check
    return Found(last, blocks, None, solver_seconds, time.perf_counter() - start)


def _attempt(blocks: list[Block], target: pl.Poly, time_limit: float) -> Found:
    entries = sum(b.gram_size * (b.gram_size + 1) // 2 for b in blocks)
    if entries > MAX_GRAM_ENTRIES:
        return Found(SosCheck(False, f"too large for the SOS search ({entries} Gram unknowns "
                                     f"in {len(blocks)} block(s))"), blocks, None)
    result = solve(blocks, target, time_limit=time_limit)
    if result.grams is None:
        return Found(SosCheck(False, f"no SOS decomposition found ({result.status})"),
                     blocks, None, result.seconds)
    structure = _columns(blocks)
    last = SosCheck(False, "rounding failed")
    for bound in DENOMINATORS:
        grams = correct(blocks, round_grams(result.grams, bound), target, structure)
        if grams is None:
            last = SosCheck(False, "the rounded Gram matrices cannot be corrected exactly")
            continue
        check = check_identity_and_psd(target, blocks, grams)
        if check.ok:
            return Found(check, blocks, grams, result.seconds, 0.0, bound)
        last = check
    return Found(SosCheck(False, f"numerical SOS found, but no exact rounding: {last.reason}"),
                 blocks, None, result.seconds)
