"""Tests of the dh2urdf package (DH table -> URDF)."""
