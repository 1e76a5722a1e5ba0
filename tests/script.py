"""Entry for scripts run by freecadcmd (scripts/, tools/), imported as aeronc.tests.script.
freecadcmd neither passes exit codes through nor exits cleanly by itself: run main, print
any traceback, exit 0 or 1."""
import os
import sys
import traceback


def run(main):
    try:
        main()
        code = 0
    except Exception:
        traceback.print_exc()
        code = 1
    sys.stdout.flush()
    os._exit(code)
