"""Drilling of assemblies, App side: hole geometry, the datum holes' pattern, the camera
program and the compensation of the holes still to be drilled (drilling seed).

  hole_geometry    holes of a part: entry point, normal, diameter, depth
  hole_pattern     the datum holes and hole rows of a photo-hole set, as data
  camera_program   the camera program: poses, APT and NC
  compensation     measurements through the transform chain; the core's compensation
The document objects are in aeronc.objects (photo-hole set, measured-hole set) and
aeronc.operations (compensated drilling); aeronc.makers.datum_holes creates them.
"""
