"""Stored certificates re-checked by their schema, above every kind they list.

A certificate file flows in (strict JSON, any schema the project writes); a
:class:`~verify.certificates.registry.CertificateCheck` flows out: valid, unbound (its
proof re-checked but its source file not found) or invalid, with a one-line reason.
The registry is one table from schema name to checker. Each checker lives with the
checks of its kind (the passivity gate's certificates in :mod:`verify.passivity`, the
robust verdicts of identified models in :mod:`verify.identify`, SOS certificates bound to
their derivation step here, since binding one to the paper's proofs needs
:mod:`verify.paper_proofs`); this package only dispatches, so no library layer needs to
know the others.
"""

from verify.certificates.registry import (
    SCHEMAS,
    SOURCE_LABELS,
    CertificateCheck,
    CertificateStatus,
    certificate_files,
    check_stored_certificate,
)

__all__ = ["SCHEMAS", "SOURCE_LABELS", "CertificateCheck", "CertificateStatus",
           "certificate_files", "check_stored_certificate"]
