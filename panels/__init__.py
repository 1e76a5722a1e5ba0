"""Task panels of AeroNC, imported as aeronc.panels. GUI only.

The folder is panels/ at the top of the source tree; it installs as
<Mod>/AeroNC/aeronc/panels, so that no module with a generic name lands on FreeCAD's
sys.path. One panel per command (recognise_panel, select_tools_panel, optimise_cutting_panel,
knowledge_base_panel); result_table.py holds the widgets they share.
"""
