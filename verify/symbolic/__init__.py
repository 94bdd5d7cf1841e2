"""Exact algebra: symbolic SO(3) identities and exact rational network instances."""
