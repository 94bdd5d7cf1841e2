"""Reference simulation on SO(3): Lie-group integrators and the closed loop."""
