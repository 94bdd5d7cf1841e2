"""The ``verify`` command.

Exit codes: 0 the run completed (and, with ``--strict`` or for gates, everything passed);
1 some check failed or a claim is not verified under ``--strict``; 2 bad input or an
output that cannot be written (an OS error), printed as one line on stderr; 3 an internal
error of the tool (a bug; VERIFY_DEBUG=1 shows it); 130 and 143 after SIGINT and SIGTERM
(:mod:`verify.stopping`).
"""

from __future__ import annotations

import argparse
import os
import sys
import textwrap
from collections.abc import Sequence
from pathlib import Path

from verify import __version__
from verify.artefacts.text import shown
from verify.errors import VerifyInputError
from verify.process_tree import CallProcesses, adopt_orphans
from verify.stopping import StopSignals, deferred_stop, forget_caught_interrupt

#: Where ``verify gate`` and ``verify check`` write certificates unless told (under the
#: git-ignored build/; ``verify all`` writes the paper's into certificates/).
GATE_CERTIFICATES = Path("build") / "certificates"
#: Where ``verify all --only`` writes unless --out says otherwise (git-ignored build/).
ONLY_OUT = Path("build") / "only"


def command_parsers(parser: argparse.ArgumentParser, path: tuple[str, ...] = ()):
    """Every command and nested command (``certificates check``) of ``parser``, as
    (words after ``verify``, its parser), depth first."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield (*path, name), sub
                yield from command_parsers(sub, (*path, name))


def _build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="verify",
        description="Machine checks of the claims of the SO(3) passivity paper: exact "
        "symbolic proofs, passivity certificates and property-based simulation.",
    )
    parser.add_argument("--version", action=_VersionAction,
                        help="print the version and the hash of the Coq prelude, then exit")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    p_all = sub.add_parser("all", help="run every registered claim check and write reports/ "
                           "(and certificates/)")
    p_all.add_argument(
        "--out", type=Path, default=None, metavar="DIR",
        help=f"report directory (default: reports; with --only, {ONLY_OUT / 'reports'}, so "
        "a partial run never overwrites the full report)"
    )
    p_all.add_argument(
        "--strict", action="store_true", help="exit 1 unless every claim is 'verified'"
    )
    p_all.add_argument(
        "--quick", action="store_true", help="fewer random samples in the numerical cross-checks"
    )
    p_all.add_argument("--seed", type=int, default=20261121,
                       help="seed of the random samples (default: 20261121)")
    p_all.add_argument("--certificates", type=Path, default=None, metavar="DIR",
                       help="where certificates are written (default: certificates; with "
                       "--only, a certificates folder inside the report directory)")
    p_all.add_argument("--run-record", type=Path, default=None, metavar="FILE",
                       help="where the date and timings of the run are written (default "
                       "build/run.json, git-ignored; they are never in the reports)")
    p_all.add_argument("--latex", action=argparse.BooleanOptionalAction, default=True,
                       help="write appendix.tex and supplement.tex in the report directory "
                            "too: a short two-column appendix for the paper (one pdflatex "
                            "pass) and the full supplement (three passes); default on, "
                            "--no-latex leaves them out")
    p_all.add_argument("--jobs", type=int, default=min(os.cpu_count() or 1, 4), metavar="N",
                       help="claim checks run in N processes (default: the cores, at most 4); "
                            "the report does not depend on N")
    p_all.add_argument("--progress", action="store_true",
                       help="stage lines on stderr even when it is not a terminal")
    p_all.add_argument(
        "--only",
        metavar="PREFIX",
        action="append",
        default=[],
        help="run only claims whose id starts with PREFIX (repeatable)",
    )

    sub.add_parser("list", help="list the registered claims")

    p_net = sub.add_parser("network", help="check the stealthy projector on network files")
    p_net.add_argument(
        "files",
        nargs="+",
        type=Path,
        metavar="FILE",
        help="TOML file with 'quaternions' or 'rotations'",
    )
    p_net.add_argument(
        "--project",
        action="store_true",
        help="project rotation matrices onto SO(3) instead of rejecting them",
    )
    p_net.add_argument(
        "--tolerance",
        type=float,
        default=1e-9,
        help="max |R^T R - I| accepted as a rotation (default 1e-9)",
    )

    p_check = sub.add_parser(
        "check",
        help="check the derivations of a Python file of your own, step by step",
        description="FILE is either the derivations' JSON form (format "
        "'verify-derivations/1', read as data: nothing of it runs; write it with --emit) "
        "or a Python file whose DERIVATIONS make that data, run in a sandbox. Exit 0 if "
        "every step of every derivation is verified, 1 if some step "
        "is refuted or inconclusive (or, with --coq, a verified step is not in Coq or coqc "
        "refuses it), 2 if the file is malformed, over a budget while it is "
        "read, or a .py file cannot be run in a sandbox (user, PID, mount and network "
        "namespaces) and --unsandboxed was not given.",
    )
    p_check.add_argument("file", type=Path, metavar="FILE",
                         help="derivations data (.json: read, never run) or a Python file "
                         "with DERIVATIONS (.py: run in a sandbox to make that data)")
    p_check.add_argument("--emit", type=Path, metavar="OUT.json",
                         help="also write the derivations as data (commit it beside the "
                         "Python; CI checks it with 'verify check OUT.json')")
    p_check.add_argument("--unsandboxed", action="store_true",
                         help="run a .py file without namespaces where they are not "
                         "available (only for a file you trust)")
    p_check.add_argument("--quick", action="store_true", help="less falsification effort")
    p_check.add_argument("--seed", type=int, default=20261121, help="seed of the searches")
    p_check.add_argument("--json", type=Path, metavar="OUT", help="also write results as JSON")
    p_check.add_argument("--coq", type=Path, metavar="DIR",
                         help="also write the verified steps as a Coq development (one "
                         "theorem per step), audit it and compile it with coqc; exit 1 "
                         "unless every verified step is in Coq and coqc accepts it")
    p_check.add_argument("--allow-partial", action="store_true",
                         help="with --coq: exit 0 when coqc accepts the steps exported even "
                         "if some verified step could not be exported (each is named)")
    p_check.add_argument("--certificates", type=Path, default=GATE_CERTIFICATES,
                         metavar="DIR", help="where by_sos steps reuse and write their SOS "
                         f"certificates (default {GATE_CERTIFICATES}, git-ignored)")
    p_check.add_argument("--budget-seconds", type=float, default=120.0, metavar="S",
                         help="time for the whole file (loading it and checking every "
                         "step); a step past it is inconclusive: budget exceeded "
                         "(default 120)")
    p_check.add_argument("--budget-memory", type=float, default=4.0, metavar="GB",
                         help="memory for loading the file, and for each step (default 4)")
    p_check.add_argument("--progress", action="store_true",
                         help="stage lines on stderr even when it is not a terminal")

    p_gate = sub.add_parser(
        "gate",
        help="passivity gate for human models H(s): exact KYP certificates or witnesses",
        description="Exit 0 if every model is passive (with an exactly checked certificate), "
        "1 if some model is not passive or inconclusive, 2 on bad input, 3 if the tool "
        "failed on some model (the others keep their verdicts).",
    )
    p_gate.add_argument("models", nargs="+", type=Path, metavar="MODEL",
                        help="TOML model file ([state_space] or [transfer_function])")
    p_gate.add_argument("--margin", default="0", metavar="NU",
                        help="require nu(w) >= NU for all w (exact rational, default 0)")
    p_gate.add_argument("--band", metavar="W1:W2",
                        help="passivity on the band W1 <= w <= W2 rad/s only (generalized "
                        "KYP certificate or exact witness inside the band)")
    p_gate.add_argument("--indices", action="store_true",
                        help="also report the passivity indices nu_IFP and rho_OFP: numerical "
                        "estimates with exact rational lower (certificate) and upper (witness) "
                        "bounds")
    p_gate.add_argument("--tolerance", default="0", metavar="EPS",
                        help="pass a model within relative distance EPS of one certified "
                        "passive (H(s + a) + d I; default 0 = exact)")
    p_gate.add_argument("--certificates", type=Path, default=GATE_CERTIFICATES,
                        metavar="DIR", help="where certificates are written (default "
                        f"{GATE_CERTIFICATES}, git-ignored: gating a model never adds "
                        "files to a checkout; the paper's certificates/ are written by "
                        "'verify all')")
    p_gate.add_argument("--json", type=Path, metavar="OUT",
                        help="write a JSON summary (- for standard output)")
    p_gate.add_argument("--junit", type=Path, metavar="OUT",
                        help="write JUnit XML (- for standard output)")
    p_gate.add_argument("--progress", action="store_true",
                        help="stage lines on stderr (which model is being decided) even when "
                        "it is not a terminal")
    p_gate.add_argument("--plot", type=Path, metavar="FILE",
                        help="draw nu(w) and the relative index R(w) with the band, margin "
                        "and exact witness marked (PNG, PDF or SVG by the suffix); with several "
                        "models, one file per model: nu.pdf gives nu-<model stem>.pdf")
    p_gate.add_argument("--coq", type=Path, metavar="DIR",
                        help="also write a Coq development of the verdicts (certificates of "
                        "passive models, witnesses of the others) to DIR, and compile it "
                        "with coqc when coqc is installed; the JSON and JUnit outputs give "
                        "each verdict's kernel status")
    p_gate.add_argument("--require-coq", action="store_true",
                        help="with --coq: fail (exit 1) unless coqc accepted a unit for "
                        "every verdict printed (the flag a lab's CI sets)")

    p_coq = sub.add_parser(
        "coq",
        help="write a Coq development of certificates (default: the paper's, "
        "certificates/ -> certificates/coq/), --check compiles it with coqc",
        description="Exit 0 when written (and, with --check, accepted by coqc and the "
        "audit), 1 when a certificate was refused or coqc failed, 2 on bad input or "
        "when --check finds no coqc.",
    )
    p_coq.add_argument("inputs", nargs="*", type=Path, metavar="CERT",
                       help="certificate files or folders (default: the paper's "
                       "development from certificates/)")
    p_coq.add_argument("--out", type=Path, metavar="DIR",
                       help="where to write (default certificates/coq for the paper, "
                       "build/coq for given files)")
    p_coq.add_argument("--jobs", type=int, default=min(4, os.cpu_count() or 1), metavar="N",
                       help="with --check, compile N units at a time (default: the cores, "
                       "up to 4)")
    p_coq.add_argument("--check", action="store_true",
                       help="compile with coqc (in a temporary copy) and audit: no "
                       "Admitted/admit/Axiom, Print Assumptions only Coq's real-number "
                       "axioms")

    p_id = sub.add_parser(
        "identify",
        help="identify H(s) from experiment logs, decide its passivity nominally and over "
        "the 95 %% confidence region",
        description="Exit 0 if every model of the 95 % confidence region is passive (on "
        "--band, or at all frequencies), with exactly checked certificates; 1 if not or "
        "inconclusive; 2 on bad input (nothing written).")
    p_id.add_argument("logs", nargs="+", type=Path, metavar="LOG",
                      help="experiment log (.csv or .npz)")
    p_id.add_argument("--structure", default="paper", metavar="S",
                      help="paper (default), P:Z (poles:zeros per diagonal element) or "
                      "order:N")
    p_id.add_argument("--rate", metavar="HZ", help="rate after decimation in Hz, 'off' (no "
                      "decimation) or 'auto' (default: the logged rate up to 250 Hz, "
                      "above it the highest integer fraction of it <= 250 Hz)")
    p_id.add_argument("--split", default="6:6", metavar="A:B",
                      help="trials for identification and validation (default 6:6)")
    p_id.add_argument("--band", metavar="W1:W2",
                      help="robust passivity on W1 <= w <= W2 rad/s (default: all "
                      "frequencies)")
    p_id.add_argument("--out", type=Path, default=Path("build/identified"), metavar="DIR",
                      help="model file, certificates and figures (default build/identified, "
                      "git-ignored)")
    p_id.add_argument("--name", help="model name (default: the first log's name)")
    p_id.add_argument("--json", type=Path, metavar="OUT", help="write a JSON summary")
    p_id.add_argument("--junit", type=Path, metavar="OUT", help="write JUnit XML")
    p_id.add_argument("--progress", action="store_true",
                      help="stage lines on stderr even when it is not a terminal (on a "
                      "terminal they are shown anyway)")
    p_id.add_argument("--no-offset", dest="offset", action="store_false", default=None,
                      help="do not estimate a constant offset per output (an uncalibrated "
                      "stick); by default it is estimated as a nuisance parameter")

    p_cert = sub.add_parser("certificates", help="certificates/ tools")
    cert_sub = p_cert.add_subparsers(dest="cert_command", metavar="ACTION", required=True)
    p_cc = cert_sub.add_parser(
        "check", help="re-verify stored certificates with no solver",
        description="Check each certificate file (each DIR's *.json): strict JSON (no "
        "duplicate keys, no unknown fields), its fingerprint and file name, the statement "
        "derived from what it proves, its source model file (looked up relative to the "
        "certificate's folder, never the working directory), and the exact inequalities. "
        "A certificate whose source file is not found is UNBOUND: its name and descriptive "
        "labels are not checked. Each valid certificate is printed with the claim it "
        "proves and every premise (an SOS claim: for all its variables, with their kinds "
        "and declared signs, with its assumptions; names that could be misread are "
        "quoted); a certificate whose written statement is not that claim's is refused "
        "as 'statement edited'. Exit 0 if all are valid (or unbound, with "
        "--allow-unbound), 1 if one is refused or unbound or none is found, 2 if a path "
        "does not exist.")
    p_cc.add_argument("paths", nargs="*", type=Path, metavar="DIR_OR_FILE",
                      help=f"certificate files or folders (default: certificates and "
                      f"{GATE_CERTIFICATES}, those that exist)")
    p_cc.add_argument("--allow-unbound", action="store_true",
                      help="accept certificates whose source file is not found (their proof "
                      "is re-checked; the summary lists the labels left unchecked)")
    p_cc.add_argument("--budget-seconds", type=float, default=120.0, metavar="S",
                      help="time for checking each file; past it the file is refused "
                      "(default 120)")
    p_cc.add_argument("--budget-memory", type=float, default=4.0, metavar="GB",
                      help="memory for checking each file (default 4)")

    p_sim = sub.add_parser(
        "simulate",
        help="run the closed loop of Sections 2-3 and write the trajectory and plots",
        description="Simulate n bodies, the quasi-average, the virtual leader and a human "
        "model with Lie-group steps on SO(3); write the trajectory (NPZ or CSV) and plots "
        "of V(t), tr(R-bar_r)(t), |dbar - d_r| and the d_i on the sphere. Exit 2 on bad input.",
    )
    p_sim.add_argument("--n", type=int, default=8, help="number of bodies (default 8)")
    p_sim.add_argument("--ks", type=float, default=3.0, help="coupling gain k_s > 0 (default 3)")
    p_sim.add_argument("--human", choices=("vr", "static", "model"), default=None,
                       help="human model: the VR operator of Section 4 (default), a static "
                       "gain, or an LTI model file (default when --model is given)")
    p_sim.add_argument("--model", type=Path, metavar="FILE",
                       help="LTI human model H(s), a TOML file as for 'verify gate'")
    p_sim.add_argument("--gain", type=float, default=1.0,
                       help="static gain k of --human static (K = k I; default 1)")
    p_sim.add_argument("--seconds", type=float, default=30.0, help="simulated time (default 30)")
    p_sim.add_argument("--step", type=float, default=1 / 120, help="step in s (default 1/120)")
    p_sim.add_argument("--seed", type=int, default=0, help="seed of attitudes and inputs")
    p_sim.add_argument("--autonomous", choices=("zero", "random", "consensus"),
                       default="consensus", help="autonomous input (default consensus)")
    p_sim.add_argument("--reference", choices=("constant", "switching"), default="constant",
                       help="constant R_r or a new one every 15 s")
    p_sim.add_argument("--network", type=Path, metavar="FILE",
                       help="initial attitudes from a network file (as for 'verify network')")
    p_sim.add_argument("--out", type=Path, default=Path("build/simulation"),
                       help="output directory (default build/simulation)")
    p_sim.add_argument("--format", choices=("npz", "csv"), default="npz", dest="fmt",
                       help="trajectory file: trajectory.npz (NumPy arrays, default) or "
                       "trajectory.csv (one row per sample)")
    p_sim.add_argument("--no-plots", action="store_true", help="write the trajectory only")
    p_sim.add_argument("--check", action="store_true",
                       help="also check stealthiness, R-bar e3 = dbar, Lemma 1, V decrease and "
                       "LaSalle on this run, within the integrator's error (one pair of runs "
                       "at h and h/2 shared by the checks; a check the integration cannot "
                       "resolve is reported UNRESOLVED)"),
    p_sim.add_argument("--progress", action="store_true",
                       help="show progress on stderr even when it is not a terminal")
    p_sim.add_argument("--adaptive", type=float, metavar="RTOL", default=None,
                       help="error-controlled steps (step doubling of CF4, atol = RTOL/100), "
                       "still sampled every --step; default: fixed steps of --step")
    p_sim.add_argument("--log", type=Path, metavar="PATH", help="also write the trials (one per "
                       "reference segment) as an experiment log, .csv or .npz, for 'identify'")
    p_sim.add_argument("--operator-noise", type=float, default=0.0, metavar="STD",
                       help="white noise on the model human's output, in the loop (default 0)")
    p_sim.add_argument("--measurement-noise", type=float, default=0.0, metavar="STD",
                       help="white noise on the logged e and u (default 0)")
    _add_campaign_parser(sub)
    _add_examples(sub)
    return parser


class _VersionAction(argparse.Action):
    """``verify --version``: the package version and the SHA-256 of the Coq prelude the
    exported developments are written against (computed only when asked)."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS,
                 help=None):
        super().__init__(option_strings, dest=dest, default=default, nargs=0, help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        from verify.coq.development import prelude_digest

        print(f"verify {__version__}\nCoq prelude sha256 {prelude_digest()}")
        parser.exit()


#: Two or three examples per command, shown at the end of its --help.
EXAMPLES: dict[str, tuple[tuple[str, str], ...]] = {
    "all": (("verify all", "every claim on the shipped defaults; writes reports/ and "
             "certificates/"),
            ("verify all --only sec2 --no-latex", "Section 2's claims only, into "
             "build/only/reports/"),
            ("verify all --strict --jobs 2", "exit 1 unless every claim is verified")),
    "list": (("verify list", "every claim id with the paper's section or equation (an id "
              "prefix is what 'verify all --only' takes)"),
             ("verify list | grep '^lemma1'", "Lemma 1's claims; 'verify all --only "
              "lemma1' checks them alone")),
    "network": (("verify network my_formation.toml", "rank of W, stealth residuals"),
                ("verify network --project measured.toml", "project noisy rotation "
                 "matrices onto SO(3) first")),
    "check": (("verify check examples/damped_leader.py --emit damped_leader.json",
               "run the Python front end in a sandbox; also write the derivations' JSON "
               "form (verify-derivations/1)"),
              ("verify check damped_leader.json", "check the JSON form in CI: read as "
               "data, nothing of the file runs"),
              ("verify check damped_leader.json --coq build/coq", "also export every step "
               "to Coq (then coqc on the files of build/coq/_CoqProject)")),
    "gate": (("verify gate models/*.toml --junit gate.xml", "gate every model; JUnit "
              "for CI; exit 1 if one is not passive"),
             ("verify gate operator.toml --band 0:10 --plot nu.svg", "passivity on "
              "0 <= w <= 10 rad/s, with the nu(w) figure as SVG"),
             ("verify gate operator.toml --coq build/coq-gate", "also have Coq's kernel "
              "re-check the KYP certificate")),
    "coq": (("verify coq --check", "export the paper's development to certificates/coq/ "
             "and compile it with coqc"),
            ("verify coq build/certificates --out build/coq", "a development of your own "
             "gate certificates")),
    "identify": (("verify identify verify/data/logs/passive_human.npz", "the shipped "
                  "log: model file, region verdict, figures in build/identified/"),
                 ("verify identify trials.csv --band 0:5 --junit id.xml", "robust "
                  "passivity on 0 <= w <= 5 rad/s over the 95 % region, JUnit for CI")),
    "certificates": (("verify certificates check", "re-check certificates/ and "
                      "build/certificates/ exactly, no solver"),
                     ("verify certificates check gate-out/ --allow-unbound",
                      "certificates whose source model is not beside them")),
    "certificates check": (("verify certificates check", "re-check certificates/ and "
                            "build/certificates/ exactly, no solver"),
                           ("verify certificates check build/certificates/*.json",
                            "the gate's certificates; exit 1 if one is refused or "
                            "unbound")),
    "simulate": (("verify simulate --n 8 --seconds 30 --check", "the closed loop with "
                  "the VR operator, and the paper's properties on the run"),
                 ("verify simulate --model operator.toml --log trials.npz", "your H(s) in "
                  "the loop; the trials as an experiment log for 'verify identify'")),
    "campaign": (("verify campaign verify/data/campaigns/small.toml --workers 2",
                  "a small sweep on a LocalCluster of 2 workers"),
                 ("verify campaign spec.toml --scheduler tcp://10.0.0.5:8786",
                  "on an existing Dask scheduler"),
                 ("verify campaign spec.toml --resume --out build/campaigns/spec",
                  "continue: runs already stored are skipped")),
}


def _add_examples(sub: argparse._SubParsersAction) -> None:
    """End each command's --help with its :data:`EXAMPLES` (text kept as written)."""
    for name, examples in EXAMPLES.items():
        first, *rest = name.split()
        parser = sub.choices[first]
        for word in rest:  # a nested command: certificates check
            (nested,) = [a for a in parser._actions
                         if isinstance(a, argparse._SubParsersAction)]
            parser = nested.choices[word]
        lines = []
        for command, what in examples:
            lines.append(f"  {command}")
            lines += textwrap.wrap(what, 76, initial_indent="      ",
                                   subsequent_indent="      ")
        parser.epilog = "examples:\n" + "\n".join(lines)
        parser.formatter_class = _ExamplesFormatter


class _ExamplesFormatter(argparse.HelpFormatter):
    """argparse's formatter, except that the examples epilog keeps its lines."""

    def _fill_text(self, text, width, indent):
        if text.startswith("examples:\n"):
            return "".join(indent + line for line in text.splitlines(keepends=True))
        return super()._fill_text(text, width, indent)


def _add_campaign_parser(sub) -> None:
    p = sub.add_parser(
        "campaign", help="sweep closed-loop runs with property checks on Dask",
        description="Expand a campaign spec (TOML) into runs, simulate and check each on a "
        "Dask LocalCluster (default) or an existing scheduler, store one row per run in a "
        "Parquet dataset as runs finish, and write a report. Exit 0 when every run has a "
        "row and none raised, 1 otherwise, 2 on bad input (before any run starts).")
    p.add_argument("spec", type=Path, metavar="SPEC.toml", help="the campaign spec")
    p.add_argument("--out", type=Path, metavar="DIR",
                   help="output folder (default build/campaigns/<spec file name>); an "
                   "existing file there is refused before any run")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on an existing Dask scheduler, e.g. tcp://127.0.0.1:8786")
    p.add_argument("--workers", type=int, metavar="N",
                   help="worker processes of the embedded LocalCluster (default: the cores)")
    p.add_argument("--resume", action="store_true",
                   help="continue a campaign in DIR: runs already stored are skipped")
    p.add_argument("--quiet", action="store_true", help="no progress line on stderr")
    p.add_argument("--progress", action="store_true",
                   help="show progress on stderr even when it is not a terminal")
    p.add_argument("--no-wait", dest="wait", action="store_false",
                   help="when another campaign is writing DIR's store, exit 2 naming it "
                   "(PID, host, start time) instead of waiting for it to finish")


def _all_paths(args: argparse.Namespace) -> tuple[Path, Path, Path]:
    """Report folder, certificate folder and run record of ``verify all``: a run of some
    claims (--only) writes under build/only unless told, never over reports/ or
    certificates/."""
    from verify.report import RUN_RECORD

    if args.only:
        out = args.out if args.out is not None else ONLY_OUT / "reports"
        certificates = args.certificates if args.certificates is not None \
            else out / "certificates"
    else:
        out = args.out if args.out is not None else Path("reports")
        certificates = args.certificates if args.certificates is not None \
            else Path("certificates")
    return out, certificates, args.run_record or RUN_RECORD


def _cmd_all(args: argparse.Namespace) -> int:
    from verify.artefacts.outputs import OutputPlan
    from verify.claims.catalog import REGISTRY
    from verify.claims.model import CheckContext
    from verify.claims.runner import run_claims
    from verify.report import write_report, write_run_record
    from verify.report.render import VERDICT_MARK

    if args.jobs < 1:
        raise VerifyInputError(f"--jobs must be at least 1, got {args.jobs}")
    claims = [c for c in REGISTRY if not args.only or any(c.id.startswith(p) for p in args.only)]
    if not claims:
        raise VerifyInputError(f"no claim id starts with {', '.join(args.only)}")
    out, certificates, record = _all_paths(args)
    outputs = OutputPlan()  # both folders and the run record checked before any work
    outputs.folder("--out", out)
    outputs.folder("--certificates", certificates)
    outputs.file("--run-record", record)
    context = CheckContext(seed=args.seed, quick=args.quick, out_dir=out,
                           certificates_dir=certificates)
    width = max(len(c.id) for c in claims)

    def progress(result) -> None:
        mark = VERDICT_MARK[result.outcome.verdict]
        print(f"  {result.claim.id:<{width}}  {mark:<22} {result.seconds:6.2f} s", flush=True)

    from verify.progress import Stages

    stage = Stages.for_command("verify all", forced=args.progress)
    noun = "claim" if len(claims) == 1 else "claims"
    print(f"verify all: {len(claims)} {noun} (seed {args.seed})")
    stage(f"checking {len(claims)} claims in {min(args.jobs, len(claims))} process(es); a "
          "line on stdout as each one ends")
    run = run_claims(claims, context, progress=progress, jobs=args.jobs)
    stage(f"writing the report to {out}")
    paths = write_report(run, out, latex=args.latex)
    write_run_record(run, record, reports=paths)
    counts = ", ".join(f"{v} {k}" for k, v in run.counts().items() if v)
    print(f"{counts}; {run.seconds:.1f} s")
    print("reports: " + ", ".join(str(p) for p in paths))
    print(f"date and timings: {record}")
    if not args.only:  # the paper's development needs every certificate of a full run
        from verify.coq.command import write_paper_development

        print(write_paper_development(certificates))
    if args.strict and not run.all_verified():
        print("--strict: some claims are not 'verified'", file=sys.stderr)
        return 1
    return 0


def _budget(args: argparse.Namespace):
    """The --budget-seconds / --budget-memory options as a Budget (bad values: exit 2)."""
    import math

    from verify.proof.budget import Budget

    seconds, memory = args.budget_seconds, args.budget_memory
    if not (math.isfinite(seconds) and 0 < seconds <= 86400 and math.isfinite(memory)
            and 0 < memory <= 1024):
        raise VerifyInputError("--budget-seconds is in (0, 86400] and --budget-memory in "
                               "(0, 1024] GB")
    return Budget(seconds, int(memory * 2**30))


def _cmd_check(args: argparse.Namespace) -> int:
    import json
    import time

    from verify.artefacts.outputs import OutputPlan
    from verify.claims.model import CheckContext, to_jsonable
    from verify.claims.proofs import search_settings
    from verify.progress import Stages
    from verify.proof import ProofSyntaxError, certificate_store, check
    from verify.proof.dynamics import tangency_budget
    from verify.proof.isolate import data_text, load_isolated, read_data_file
    from verify.proof.report_lines import result_lines, summary_line

    budget = _budget(args)
    stage = Stages.for_command("verify check", forced=args.progress)
    outputs = OutputPlan(inputs=[args.file])  # checked before the file runs
    outputs.file("--json", args.json)
    if args.emit:
        outputs.file("--emit", args.emit)
    if args.coq:
        outputs.folder("--coq", args.coq)
    outputs.folder("--certificates", args.certificates)
    deadline = time.monotonic() + budget.seconds  # the whole file: loading and every step
    with tangency_budget(budget):  # declared dynamics re-checked under the step budget
        if args.file.suffix == ".json":
            stage(shown(f"reading {args.file} as data"))
            derivations = read_data_file(args.file)  # data only: nothing of the user runs
        else:  # the Python front end, in a sandbox (a child in its own namespaces)
            stage(shown(f"loading {args.file} in a sandboxed process"))
            derivations = load_isolated(args.file, budget=budget,
                                        sandboxed=not args.unsandboxed)
    if args.emit:
        outputs.write(args.emit, data_text(derivations))
    context = CheckContext(seed=args.seed, quick=args.quick)
    results = []
    for k, d in enumerate(derivations):
        stage(shown(f"checking derivation {k + 1} of {len(derivations)}: {d.name}"))
        with certificate_store(args.certificates, source=f"file:{args.file.stem}.py"):
            try:
                r = check(d, search_settings(context, 101 * k), budget=budget,
                          deadline=deadline)
            except ProofSyntaxError as exc:
                raise VerifyInputError(f"{args.file}: {exc}") from None
        results.append(r)
        for line in result_lines(r):
            print(line)
    print(summary_line(results))
    if args.json:
        outputs.write(args.json, json.dumps(to_jsonable([r.to_json() for r in results]),
                                            indent=2, ensure_ascii=True) + "\n")
    coq_ok = True
    if args.coq:
        stage(shown(f"writing the verified steps to {args.coq} and compiling them"))
        coq_ok = _write_coq(args.coq, derivations, results, budget=budget,
                            allow_partial=args.allow_partial,
                            certificates=args.certificates)
    return 0 if coq_ok and all(r.verdict == "verified" for r in results) else 1


def _write_coq(folder: Path, derivations, results, *, budget=None,
               allow_partial: bool = False, certificates: Path | None = None) -> bool:
    """``verify check --coq DIR``: the verified steps as a Coq development, audited and
    compiled (:mod:`verify.coq.check_export`; an SOS step by the certificate the checker
    stored in ``certificates``); True when the exit status may be 0."""
    from verify.coq.check_export import write_and_compile

    return write_and_compile(folder, derivations, results, budget=budget,
                             allow_partial=allow_partial, say=lambda s: print(shown(s)),
                             certificates=certificates)


def _cmd_gate(args: argparse.Namespace) -> int:
    from verify.artefacts.outputs import OutputPlan, is_stream
    from verify.inputs.number_text import short_text, unlimited_int_text
    from verify.passivity.gate import (
        add_indices,
        gate_cases,
        json_text,
        junit_text,
        parse_margin,
        parse_tolerance,
        run_band_gate,
        run_gate,
    )
    from verify.passivity.io.model_file import load_model

    margin = parse_margin(args.margin)
    tolerance = parse_tolerance(args.tolerance)
    band = None
    if args.band is not None:  # the band route's modules load only when asked for
        from verify.passivity.band import parse_band

        band = parse_band(args.band)
    if tolerance and band is not None:
        raise VerifyInputError("--tolerance applies to the full frequency axis, not with "
                               "--band")
    outputs = OutputPlan(inputs=args.models)  # every output checked before any work
    outputs.file("--json", args.json, stream=True)
    outputs.file("--junit", args.junit, stream=True)
    if is_stream(args.json) and is_stream(args.junit):
        raise VerifyInputError("--json - and --junit -: only one output can go to standard "
                               "output")
    outputs.folder("--certificates", args.certificates)
    if args.require_coq and args.coq is None:
        raise VerifyInputError("--require-coq needs --coq DIR (the folder of the Coq "
                               "development it compiles)")
    if args.coq is not None:
        if args.coq.resolve() == args.certificates.resolve():
            raise VerifyInputError("--coq DIR must not be the --certificates folder (the Coq "
                                   "development is written beside the certificates, not "
                                   "among them)")
        outputs.folder("--coq", args.coq)
    plots = None
    if args.plot is not None:  # a bad --plot fails before any work
        from verify.passivity.figure import figure_paths

        plots = figure_paths(args.plot, list(args.models))
        for path in plots:
            outputs.file("--plot", path)
    # with an output on standard output, the verdict lines go to standard error
    text = sys.stderr if is_stream(args.json) or is_stream(args.junit) else sys.stdout
    models = [load_model(path) for path in args.models]  # validate all before any work
    stage = _gate_stages(args.progress, models, args.indices)
    with unlimited_int_text():  # every input is validated: exact numbers of any size now
        if band is None:
            results = run_gate(models, margin, args.certificates, tolerance,
                               keep_going=True, stage=stage)
        else:
            results = run_band_gate(models, band, margin, args.certificates,
                                    keep_going=True, stage=stage)
        if args.indices:
            add_indices(results, stage)
        for r in results:
            print(shown(r.line()), file=text, flush=True)
        passed = sum(r.passed for r in results)
        errors = sum(r.error is not None for r in results)
        where = "" if band is None else \
            f" on [{short_text(band[0])}, {short_text(band[1])}] rad/s"
        within = sum(getattr(r.decision, "perturbation", None) is not None for r in results)
        spelled = args.tolerance if len(args.tolerance) <= 24 else short_text(tolerance)
        print(f"{passed} of {len(results)} model(s) passive{where}"
              + (f" ({within} within tolerance {spelled})" if within else "")
              + (f" with margin {short_text(margin)}" if margin else "")
              + (f"; {errors} ended in an internal error (no verdict; set "
                 "VERIFY_DEBUG=1 and report it)" if errors else ""), file=text)
        coq_ok = _gate_kernel(args, results, stage, text)
        if args.json:
            outputs.write(args.json, json_text(results))
        if args.junit:
            outputs.write(args.junit, junit_text(gate_cases(results)))
        if plots is not None:
            from verify.passivity.figure import figure_format, passivity_figure_bytes

            for r, path in zip(results, plots, strict=True):
                if r.error is not None:
                    print(shown(f"figure: none for {r.decision.model.name} (internal "
                                "error)"), file=text)
                    continue
                stage(f"drawing {path}")
                outputs.write(path, passivity_figure_bytes(r.decision, figure_format(path)))
                print(shown(f"figure: {path}"), file=text)
    return 3 if errors else 0 if passed == len(results) and coq_ok else 1


def _gate_kernel(args: argparse.Namespace, results, stage, text) -> bool:
    """Each result's kernel status (``--coq``: the verdicts' development, compiled);
    False when coqc refused it or, with ``--require-coq``, a verdict is not in Coq."""
    import contextlib

    from verify.coq.gate_kernel import (
        default_status,
        gate_kernel,
        require_coq_problems,
    )

    if args.coq is None:
        for r in results:
            status = default_status(r)
            r.kernel, r.coq_theorem = status.kernel, status.theorem
        return True
    stage(f"writing the Coq development to {args.coq}")
    with contextlib.redirect_stdout(text):
        statuses, accepted = gate_kernel(results, args.coq)
    for r, status in zip(results, statuses, strict=True):
        r.kernel, r.coq_theorem = status.kernel, status.theorem
        r.coq_closed_loop_theorem = status.closed_loop
    if args.require_coq:
        problems = require_coq_problems(results, statuses)
        for p in problems:
            print(shown(f"coq: --require-coq: not accepted by coqc: {p}"), file=text)
        return accepted and not problems
    return accepted


#: Models up to this many states decide in well under 2 s: on a terminal no stage lines
#: (``--progress`` still asks for them).
QUICK_GATE_STATES = 20


def _gate_stages(forced: bool, models, indices: bool):
    """Stage lines for ``verify gate``: asked for, or on a terminal when a model is big,
    there are many, or the indices are asked for (the gate runs longer than about 2 s)."""
    from verify.progress import Stages

    big = indices or len(models) > 10 or any(m.n > QUICK_GATE_STATES for m in models)
    stage = Stages.for_command("verify gate", forced=forced)
    stage.enabled = stage.enabled and (forced or big)
    return stage


def _cmd_coq(args: argparse.Namespace) -> int:
    from verify.coq.command import run_coq

    if args.jobs < 1:
        raise VerifyInputError(f"--jobs must be at least 1, got {args.jobs}")
    return run_coq(args.inputs, args.out, args.check, jobs=args.jobs)


def _cmd_certificates(args: argparse.Namespace) -> int:
    from verify.certificates.registry import (
        CertificateCheck,
        CertificateStatus,
        certificate_files,
        check_stored_certificate,
    )
    from verify.proof.budget import BudgetExceededError, run_bounded

    budget = _budget(args)
    paths = args.paths or [p for p in (Path("certificates"), GATE_CERTIFICATES)
                           if p.is_dir()] or [Path("certificates")]
    files = certificate_files(paths)
    if not files:
        where = ", ".join(str(p) for p in paths)
        print(shown(f"verify: no certificate found in {where} (no *.json file)"),
              file=sys.stderr)
        return 1
    marks = {CertificateStatus.VALID: "ok     ", CertificateStatus.UNBOUND: "UNBOUND",
             CertificateStatus.INVALID: "INVALID"}
    checks = []
    for f in files:
        try:  # each file in a forked process within the budget (a crash refuses it)
            c = run_bounded(lambda f=f: check_stored_certificate(
                f, allow_unbound=args.allow_unbound), budget)
        except BudgetExceededError as exc:
            c = CertificateCheck(CertificateStatus.INVALID,
                                 f"not checked: budget exceeded ({exc})")
        except RuntimeError as exc:
            c = CertificateCheck(CertificateStatus.INVALID, f"not checked: {exc}")
        checks.append((f, c))
        print(shown(f"{marks[c.status]} {f}: {c.reason}"), flush=True)
    valid = sum(c.status is CertificateStatus.VALID for _, c in checks)
    unbound = [(f, c) for f, c in checks if c.status is CertificateStatus.UNBOUND]
    print(f"{valid} of {len(files)} certificate(s) valid (bound to their claims, exact "
          "re-check, no solver)")
    if unbound:
        verdict = "accepted (--allow-unbound)" if args.allow_unbound else \
            "not accepted (source file not found; --allow-unbound accepts them)"
        print(f"{len(unbound)} unbound, {verdict}; labels not checked:")
        for f, c in unbound:
            print(shown(f"  {f}: {', '.join(c.unchecked)}"))
    return 0 if all(c.ok for _, c in checks) else 1


def _cmd_simulate(args: argparse.Namespace) -> int:
    from verify.sim.command import SimulateSettings, run_simulate

    human = args.human or ("model" if args.model is not None else "vr")
    return run_simulate(SimulateSettings(
        n=args.n, k_s=args.ks, human=human, model=args.model, gain=args.gain,
        seconds=args.seconds, step=args.step, seed=args.seed, autonomous=args.autonomous,
        reference=args.reference, network=args.network, out=args.out, fmt=args.fmt,
        plots=not args.no_plots, check=args.check, log=args.log, adaptive=args.adaptive,
        operator_noise=args.operator_noise, measurement_noise=args.measurement_noise,
        progress=args.progress))


def _cmd_identify(args: argparse.Namespace) -> int:
    from verify.identify.command import IdentifySettings, run_identify

    return run_identify(IdentifySettings(
        logs=tuple(args.logs), structure=args.structure, rate=args.rate, split=args.split,
        band=args.band, out=args.out, json=args.json, junit=args.junit, name=args.name,
        progress=args.progress, offset=args.offset))


def _cmd_campaign(args: argparse.Namespace) -> int:
    from verify.campaign.command import CampaignSettings, run_campaign_command

    return run_campaign_command(CampaignSettings(
        spec=args.spec, out=args.out, scheduler=args.scheduler, workers=args.workers,
        resume=args.resume, quiet=args.quiet, progress=args.progress, wait=args.wait))


def _cmd_list(_: argparse.Namespace) -> int:
    from verify.claims.index import CLAIMS  # written out: no module of checks is imported

    for claim_id, paper_ref in CLAIMS:
        print(f"{claim_id:<26} {paper_ref}")
    return 0


def _cmd_network(args: argparse.Namespace) -> int:
    import numpy as np

    from verify.network_file import load_network
    from verify.system.diagnostics import diagnose

    # validate every file before printing results, so bad input fails fast and whole
    networks = [load_network(f, project=args.project, tolerance=args.tolerance) for f in args.files]
    status = 0
    for path, net in zip(args.files, networks, strict=True):
        d = diagnose(net.attitudes)
        sv = ", ".join(f"{v:.3g}" for v in d.singular_values)
        print(shown(f"{path}: {net.name} (n = {d.n})"))
        if net.projected_by:
            print(f"  projected onto SO(3): entries moved by up to {net.projected_by:.3g}")
        print(f"  |sum d_i| = {d.abs_sum:.6g}, dbar = {np.array2string(d.dbar, precision=6)}")
        print(
            f"  singular values of W: {sv} -> rank 2; W^T W is singular, the paper's "
            "(W^T W)^-1 is undefined, the pseudo-inverse is used"
        )
        print(
            f"  condition number of W on its range: {d.kappa:.3g}; rounding bound "
            f"{d.rounding_bound:.2g}"
        )
        dense = (
            "skipped (n > 2000)"
            if d.dense_vs_structured is None
            else f"{d.dense_vs_structured:.2g}"
        )
        print(
            f"  |J S A x|: {d.stealth_residual:.2g}, |A A x - A x|: "
            f"{d.idempotence_residual:.2g}, dense vs structured: {dense}"
        )
        print(f"  {'ok' if d.ok else 'FAILED: a residual exceeds the rounding bound'}")
        status = max(status, 0 if d.ok else 1)
    return status


#: Options whose value is a number (or band) that may be negative.
SIGNED_VALUE_OPTIONS = ("--margin", "--tolerance", "--band")


def _looks_signed(value: str) -> bool:
    """"-1e-3", "-.5", "-1/100", "-1:2": a negative number, not an option."""
    return len(value) > 1 and value[0] == "-" and (value[1].isdigit() or value[1] == ".")


def _attach_signed_values(argv: Sequence[str]) -> list[str]:
    """``--margin -1e-3`` as ``--margin=-1e-3`` (likewise ``--tolerance``, ``--band``).

    argparse takes a value that starts with "-" and is not a plain decimal for an option
    and prints usage; joined, both spellings reach the number parser, which accepts the
    value or refuses it in one line.
    """
    out: list[str] = []
    tokens = list(argv)
    i = 0
    while i < len(tokens):
        token = tokens[i]
        if token == "--":  # everything after is positional
            out += tokens[i:]
            break
        if (token in SIGNED_VALUE_OPTIONS and i + 1 < len(tokens)
                and _looks_signed(tokens[i + 1])):
            out.append(f"{token}={tokens[i + 1]}")
            i += 2
            continue
        out.append(token)
        i += 1
    return out


#: Commands whose linear algebra is many small matrices (the identification's least
#: squares on N x 6 regressors), where a multithreaded BLAS only adds synchronisation.
SMALL_MATRIX_COMMANDS = ("identify", "all")
BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def single_threaded_blas() -> None:
    """One BLAS thread unless the user chose otherwise, if numpy is not loaded yet (the
    setting is read once, when numpy loads its BLAS)."""
    if "numpy" not in sys.modules:
        for variable in BLAS_THREAD_VARIABLES:
            os.environ.setdefault(variable, "1")


def main(argv: Sequence[str] | None = None) -> int:
    parser = _build_parser()
    args = parser.parse_args(_attach_signed_values(sys.argv[1:] if argv is None else argv))
    if args.command is None:
        parser.print_help()
        return 2
    if args.command in SMALL_MATRIX_COMMANDS:
        single_threaded_blas()
    handlers = {"all": _cmd_all, "check": _cmd_check, "list": _cmd_list,
                "network": _cmd_network, "gate": _cmd_gate,
                "certificates": _cmd_certificates, "simulate": _cmd_simulate,
                "identify": _cmd_identify, "campaign": _cmd_campaign, "coq": _cmd_coq}
    # The top process of a call (the `verify` command) is the subreaper of its
    # descendants and ends them all; a library caller of main(argv) keeps its processes
    # (multiprocessing's forkserver and resource tracker, reused by its next call).
    processes = None
    if argv is None:
        adopt_orphans()
        processes = CallProcesses()
    stop = StopSignals()
    with stop:
        return _run_and_end(handlers[args.command], args, stop, processes)


def _run_and_end(handler, args: argparse.Namespace, stop: StopSignals,
                 processes: CallProcesses | None) -> int:
    """Run a command's handler; whatever its end, end every process it started before a
    last word is printed (so a stop message is true when it appears)."""
    try:
        try:
            return handler(args)
        finally:
            if processes is not None:
                with deferred_stop():  # a signal now is held, the tree ended, then raised
                    processes.end()
    except KeyboardInterrupt:
        forget_caught_interrupt()  # handled here: the exit code is 128 + the signal
        print(f"verify: {stop.name()}: stopped; files written before it are whole, "
              "nothing was written after it", file=sys.stderr)
        return stop.exit_code()
    except VerifyInputError as exc:
        print(f"verify: error: {shown(str(exc))}", file=sys.stderr)
        return 2
    except OSError as exc:  # the system refused a read or a write: not a bug of ours
        where = f"{exc.filename}: " if exc.filename else ""
        reason = exc.strerror or os.strerror(exc.errno or 0) or type(exc).__name__
        print(shown(f"verify: error: {where}{reason}"), file=sys.stderr)
        return 2
    except Exception as exc:  # a bug of ours: one line, the traceback on request
        if os.environ.get("VERIFY_DEBUG"):
            raise
        print(
            f"verify: internal error: {type(exc).__name__}: {shown(str(exc))} "
            "(set VERIFY_DEBUG=1 for the traceback)",
            file=sys.stderr,
        )
        return 3


if __name__ == "__main__":
    sys.exit(main())
