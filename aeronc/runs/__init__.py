"""Whole runs, headless, each a sequence of stages over one context (runs.stages):

  stages         the harness: output folder, FreeCAD's output to a log, timed stages
  main_job       STEP part -> posted, verified programs and report (scripts/run.sh demo)
  impeller_run   impeller part -> Program impeller, checks and report (scripts/run.sh impeller)
  drilling_run   part and datum holes -> camera program, compensation, drilling program
                 (scripts/run.sh drill)
"""
