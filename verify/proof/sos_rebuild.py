"""The SOS program of a step handed over as data (the ``step`` of an SOS certificate).

In: a one-step derivation as data (schema ``verify-derivations/1`` of
:mod:`verify.proof.wire`), as a certificate written by ``by_sos`` carries it. Out: the
step's :class:`~verify.sos.program.StepProgram` (numerator, factors, every allowed
multiplier with its grounds, statement), or why there is none. The step is rebuilt with
the checker's own classes (:mod:`verify.proof.rebuild`), validated as the checker
validates a derivation (:func:`verify.proof.checker.validate_derivation`), measured
before any algebra (:mod:`verify.proof.size`) and its program re-derived
(:func:`verify.proof.sos_step.step_program`). It sits above the checker, which decides
``by_sos`` steps with :mod:`verify.proof.sos_step`.
"""

from __future__ import annotations

from verify.proof.checker import step_problem, validate_derivation
from verify.proof.expr import ProofSyntaxError
from verify.proof.justify import BySos
from verify.proof.rebuild import decode
from verify.proof.size import over_limits
from verify.proof.sos_step import step_program
from verify.sos.program import StepProgram


def program_of_step(data: object) -> StepProgram | str:
    """The SOS program of the one-step derivation in ``data`` (rebuilt with our own
    classes, :func:`verify.proof.rebuild.decode`), or why there is none."""
    try:
        (d,) = decode(data)
        validate_derivation(d)
        (step,) = d.steps
        if not isinstance(step.because, BySos) or step.relation == "=":
            return "not an inequality step justified by by_sos"
        problem = step_problem(d, step)
        too_large = over_limits(*problem.all_exprs)
        if too_large:
            return too_large
        return step_program(problem, step.because)
    except (ProofSyntaxError, ValueError, ArithmeticError, TypeError, KeyError) as exc:
        return f"{type(exc).__name__}: {exc}"


__all__ = ["program_of_step"]
