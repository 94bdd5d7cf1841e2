"""Passivity of LTI human models (issue 4)."""
