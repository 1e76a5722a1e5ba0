"""App-side document objects of AeroNC, imported as aeronc.objects (FeaturePython proxies;
they work headless under freecadcmd). FreeCAD rebuilds a saved object's proxy from its class
path, aeronc.objects.<module>.<class>: keep these names.

The machining-domain tree in the document:
  MachiningFeatures            (machining_features.py) settings + JSON result + counts + tool plan
    SetupDirection             (setup_direction.py)    one per setup / tool axis
      DomainElement            (domain_element.py)     nested by parent/child
Each proxy declares all its properties; aeronc.makers creates, remakes and removes the tree;
transaction.py makes each change one undo step.
"""
from aeronc.objects.base import descendants, proxy_type
from aeronc.objects.domain_element import TYPE as DOMAIN_ELEMENT
from aeronc.objects.machining_features import TYPE as MACHINING_FEATURES
from aeronc.objects.machining_features import is_machining_features, result_of, settings_of
from aeronc.objects.setup_direction import TYPE as SETUP_DIRECTION

__all__ = ["is_machining_features", "result_of", "settings_of", "proxy_type", "descendants",
           "MACHINING_FEATURES", "SETUP_DIRECTION", "DOMAIN_ELEMENT"]
