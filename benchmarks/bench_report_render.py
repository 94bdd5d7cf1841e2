"""Cost of typesetting the report: MathML and the LaTeX appendix against plain JSON.

Run: ``python benchmarks/bench_report_render.py [copies]``. It builds a run of every
registered claim with a derivation of ``copies`` x the paper's longest chain (no checks are
run: the renderers see the same data a real run gives them), renders it as JSON (the
baseline: no formulas), Markdown (LaTeX sources), HTML (LaTeX sources and MathML) and
the LaTeX appendix and supplement in one process, and prints each time and its ratio to
JSON, and how many formulas went through ``latex2mathml`` and at what cost each (cache
cleared).
"""

from __future__ import annotations

import sys
import time

sys.path.insert(0, "tests")

from report_fixtures import claim, derivation, registry_run, run_of, step

from verify.report.latex import render_latex, render_supplement
from verify.report.mathml import mathml
from verify.report.render import render_html, render_json, render_markdown

CHAIN = [  # the shape of the paper's S_r-dot chain (Theorem 1)
    ("=", "(-1/2) tr((d/dt R̄_r))"),
    ("=", "(-1/2) k_s tr(R̄_r sk(R̄_rᵀ R_rl))"),
    ("=", "(-1/4) k_s tr(R̄_r (R̄_rᵀ R_rl - R_rlᵀ R̄_r))"),
    ("=", "(-1/4) k_s tr((R̄_r + R̄_rᵀ) (I - R̄_rᵀ R_rl)) + (1/2) k_s tr(R̄_r)"),
    ("<=", "(-1/2) k_s λmin((R̄_r + R̄_rᵀ)) φ(R̄ᵀ R_l) - k_s φ(R̄_r) + k_s φ(R_rl)"),
]


def build(copies: int):
    steps = [step(k + 1, rel, f"{rhs} + {k}", "algebra (cyclic trace)",
                  conditions=["boundary h = 0, i.e. cosθ = 0"])
             for k, (rel, rhs) in enumerate(CHAIN * copies)]
    extra = claim("bench.chain", "3, Theorem 1", statement="tr(AB) >= lambda_min(A) tr(B)",
                  evidence=[derivation("bench.chain", "Ṡ_r", steps)])
    return run_of(*registry_run().results, extra)


def timed(fn, run, repeat: int = 3) -> float:
    best = float("inf")
    for _ in range(repeat):
        mathml.cache_clear()
        start = time.perf_counter()
        fn(run)
        best = min(best, time.perf_counter() - start)
    return best


def main(copies: int) -> None:
    run = build(copies)
    base = timed(render_json, run)
    print(f"{'format':>10} {'seconds':>9} {'/ json':>8}")
    for name, fn in (("json", render_json), ("markdown", render_markdown),
                     ("html", render_html), ("appendix", render_latex),
                     ("supplement", render_supplement)):
        t = timed(fn, run)
        print(f"{name:>10} {t:9.4f} {t / base:8.1f}")
    mathml.cache_clear()
    render_html(run)
    n = mathml.cache_info().currsize
    t = timed(render_html, run) - timed(render_markdown, run)
    print(f"{n} distinct formulas through latex2mathml: about {1e3 * t / n:.2f} ms each")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)
