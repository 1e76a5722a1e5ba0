"""What a run shows a programmer: HTML reports and pictures.

  html                  the style sheet and helpers every report shares
  chain_report          the main job's report (machining chain, checks, pictures)
  impeller_report       the impeller run's report
  compensation_report   the compensation report of a compensated drilling
  picture               the part coloured by feature role
  toolpath_picture      toolpaths and leftover maps
  optimisation_plot     the cutting-parameter optimiser's objective map
"""
