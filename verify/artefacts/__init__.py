"""Writing artefacts, a utility below every layer.

Bytes and paths flow in; files flow out. :mod:`~verify.artefacts.atomic` writes a file
(or a set of files) through a temporary file and a rename, so that no reader sees a
half-written one; :mod:`~verify.artefacts.figure_bytes` renders a Matplotlib figure to
bytes that depend only on what is drawn; :mod:`~verify.artefacts.html_style` is the
style sheet shared by the HTML reports. Nothing here knows of the paper, models or
claims, so every layer (input, checks, simulation, identification, reports) may use it.
"""
