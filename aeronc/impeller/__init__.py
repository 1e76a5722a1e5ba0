"""Impellers, App side.

  recognition   the core's impeller recognition and dimensions, the blank and route data
  programming   Program impeller: features nodes, blank, Job, 5-axis operations, posted program
"""
