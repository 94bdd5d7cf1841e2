"""`verify all` draws Section 4's figures (nu(w), Bode) and cites them as claim evidence."""

from __future__ import annotations

import json

from verify.cli import main


def test_nu_curves_claim_writes_figures_and_links_them(tmp_path, capsys):
    out, certs = tmp_path / "reports", tmp_path / "certs"
    assert main(["all", "--out", str(out), "--certificates", str(certs),
                 "--only", "sec4.nu-curves-indices", "--strict"]) == 0
    figures = sorted(p.name for p in (out / "figures").iterdir())
    assert figures == ["bode_reconstructed.png", "nu_reconstructed.png"]
    for name in figures:
        assert (out / "figures" / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not list((out / "figures").glob(".*.tmp"))
    md = (out / "report.md").read_text()
    assert "![ν(ω) of both reconstructions" in md and "(figures/nu_reconstructed.png)" in md
    assert "<img src='figures/bode_reconstructed.png'" in (out / "report.html").read_text()
    (claim,) = json.loads((out / "report.json").read_text())["claims"]
    kinds = [e["kind"] for e in claim["evidence"]]
    assert kinds.count("figure") == 2 and claim["verdict"] == "verified"
    summaries = " ".join(e["summary"] for e in claim["evidence"])
    assert "ν_IFP = 0 exactly" in summaries and "ρ_OFP = 0 exactly" in summaries
    assert main(["certificates", "check", str(certs)]) == 0  # the band certificate
