"""`verify all` draws Section 4's figures (nu(w), Bode) and cites them as claim evidence."""

from __future__ import annotations

import json

from verify.cli import main


def test_nu_curves_claim_writes_figures_and_links_them(tmp_path, capsys):
    out, certs = tmp_path / "reports", tmp_path / "certs"
    assert main(["all", "--out", str(out), "--certificates", str(certs),
                 "--only", "sec4.nu-curves-indices", "--strict"]) == 0
    figures = sorted(p.name for p in (out / "figures").iterdir())
    assert figures == ["bode_reconstructed.pdf", "bode_reconstructed.svg",
                       "nu_reconstructed.pdf", "nu_reconstructed.svg"]
    for name in figures:  # vector: the HTML report shows the SVG, LaTeX includes the PDF
        data = (out / "figures" / name).read_bytes()
        assert data.startswith(b"%PDF-") if name.endswith(".pdf") else b"<svg" in data[:400]
        assert b"<image" not in data and b"/Subtype /Image" not in data  # no raster inside
    assert not list((out / "figures").glob(".*.tmp"))
    md = (out / "report.md").read_text()
    assert "![ν(ω) of both reconstructions" in md and "(figures/nu_reconstructed.svg)" in md
    assert "<img src='figures/bode_reconstructed.svg'" in (out / "report.html").read_text()
    assert r"\includegraphics[width=0.8\linewidth]{figures/nu_reconstructed.pdf}" in (
        out / "supplement.tex").read_text()
    (claim,) = json.loads((out / "report.json").read_text())["claims"]
    kinds = [e["kind"] for e in claim["evidence"]]
    assert kinds.count("figure") == 2 and claim["verdict"] == "verified"
    summaries = " ".join(e["summary"] for e in claim["evidence"])
    assert "ν_IFP = 0 exactly" in summaries and "ρ_OFP = 0 exactly" in summaries
    assert main(["certificates", "check", str(certs)]) == 0  # the band certificate
