"""Task panels of AeroNC (installed as aeronc.panels). GUI only."""
