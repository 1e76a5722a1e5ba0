"""App-side document objects of AeroNC (FeaturePython; they work headless under freecadcmd).

The machining-domain tree in the document:
  MachiningFeatures            (machining_features.py) settings + JSON result + counts
    SetupDirection             (setup_direction.py)    one per setup / tool axis
      DomainElement            (domain_element.py)     nested by parent/child
"""
from aeronc.objects.base import descendants, proxy_type
from aeronc.objects.machining_features import (create_machining_features, is_machining_features,
                                               remove_machining_features, result_of, settings_of,
                                               update_machining_features)
from aeronc.objects.domain_element import TYPE as DOMAIN_ELEMENT
from aeronc.objects.machining_features import TYPE as MACHINING_FEATURES
from aeronc.objects.setup_direction import TYPE as SETUP_DIRECTION

__all__ = ["create_machining_features", "update_machining_features", "remove_machining_features",
           "is_machining_features", "result_of", "settings_of", "proxy_type", "descendants",
           "MACHINING_FEATURES", "SETUP_DIRECTION", "DOMAIN_ELEMENT"]
