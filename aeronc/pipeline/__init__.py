"""The part-to-program pipeline, App side, one module a step:

  recognition           part -> machining-domain tree (the core's layered slicing)
  knowledge_base        the user's knowledge base (SQLite, through the core)
  tool_planning         tree -> tool plan: finishing and roughing tools, drills (Select tools)
  cutting_optimisation  tool plan -> spindle speeds and feeds of the ToolControllers
  chain_building        tree + plan -> NC machining chain -> one Path Job per setup
  chain_edits           the programmer's edits of the chain (order, tools, units on or off)
  setup_job             a setup's Job: its frame, blank and stock
  verification          posted programs re-read and simulated against the blank
"""
