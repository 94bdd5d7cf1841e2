"""Files in and out: human model files and certificate JSON (not trusted for verdicts).

:mod:`.model_file` reads a model H(s) from TOML (numbers only, each validated and kept
exact); :mod:`.certificate_files` writes and strictly reads KYP and band certificates,
:mod:`.strict_json` refuses any JSON with more than one meaning, :mod:`.binding` derives
what a certificate claims and ties it to its model file, and :mod:`.stored` re-checks a
stored certificate by its schema. Reading a certificate only parses it: whether it
proves anything is decided by the exact checks of :mod:`verify.passivity.check`, which
every reader here calls before accepting a file. Bad input is a one-line
:class:`~verify.errors.VerifyInputError`, and files are written whole or not at all.
"""
