"""Test-part makers: generated parts with their known truth (aeronc.tests.parts)."""
