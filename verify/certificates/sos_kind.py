"""SOS certificates (``verify-sos-certificate/1``) bound to their claim and re-checked.

In: a stored certificate's strictly parsed JSON and its path. Out: a
:class:`~verify.passivity.check.certificate.KypCheck` (valid or not, with the reason),
or :class:`~verify.passivity.io.strict_json.CertificateFormatError` for malformed
content. The SOS library checks what the file shows by itself and the file against a
given program (:func:`verify.sos.certificate.check_form`,
:func:`~verify.sos.certificate.check_against_program`); this module decides which
program that is, which needs the proof checker and the paper's proofs: a certificate
that carries its step (written by ``by_sos``, Section 3) is bound to that step, rebuilt
from the data with the checker's own classes (:func:`verify.proof.sos_rebuild.program_of_step`);
one of the paper's proofs without a step is bound to the paper's step with its key
(:func:`verify.paper_proofs.sos_proofs.program_for_key`); any other is refused.
"""

from __future__ import annotations

from pathlib import Path

from verify.passivity.check.certificate import KypCheck
from verify.passivity.io.strict_json import CertificateFormatError
from verify.sos import certificate as cert
from verify.sos.check import SosCheck


def check_sos_certificate_data(data: dict, path: Path) -> SosCheck:
    """Re-check a stored SOS certificate with no solver (``verify certificates check``).

    A certificate that carries its step (``step``: the one-step derivation in the schema
    of :mod:`verify.proof.wire`, as data) is bound like the gate's: the step is rebuilt
    with the checker's own classes, its SOS program re-derived (statement, key, file name,
    numerator, factors, every allowed multiplier with its grounds) and the certificate
    checked against it. Without a step, a certificate of the paper's proofs is bound to
    the paper's step with its key; any other is refused. Malformed content raises
    :class:`ValueError` naming ``path``.
    """
    refused = cert.check_form(data, path)
    if refused:
        return SosCheck(False, refused)
    claim = data["claim"]
    if "step" in data:
        from verify.proof.sos_rebuild import program_of_step

        sp = program_of_step(data["step"])
        if isinstance(sp, str):
            raise ValueError(f"{path}: malformed SOS certificate: step: {sp}")
        bound = "bound to its step (rebuilt from the data, program re-derived)"
    elif claim.get("source") == cert.PAPER:
        from verify.paper_proofs.sos_proofs import program_for_key

        sp = program_for_key(claim["key"], claim["statement"])
        if sp is None:
            return SosCheck(False, "no by_sos step of the paper's proofs has this claim key")
        bound = "bound to the paper's step (re-derived)"
    else:
        return SosCheck(False, "the certificate does not carry its step, so its statement, "
                               "key and multipliers cannot be bound (check the derivation "
                               "file again with `verify check` to renew it)")
    return cert.check_against_program(data, sp, bound)


def check_sos_file(data: dict, path: Path) -> KypCheck:
    """The checker of ``verify-sos-certificate/1`` files for ``verify certificates check``."""
    try:
        result = check_sos_certificate_data(data, path)
    except ValueError as exc:
        raise CertificateFormatError(str(exc).removeprefix(f"{path}: ")) from None
    return KypCheck(bool(result.ok), result.reason)


__all__ = ["check_sos_certificate_data", "check_sos_file"]
