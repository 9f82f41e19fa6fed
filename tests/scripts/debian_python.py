"""For the script tests whose scripts need numpy or h5py: a python of its own first on PATH (a
virtual environment, pyenv) may lack them, where Debian's has them (scripts/install-deps). Run the
test again under /usr/bin/python3 in that case, so that sys.executable, which the tests hand the
scripts, can import them; exit with a message where no python here can.

    import debian_python
    debian_python.require("numpy", "h5py")
"""
import importlib
import os
import sys

DEBIAN_PACKAGES = {"numpy": "python3-numpy", "h5py": "python3-h5py"}


def require(*modules):
    try:
        for module in modules:
            importlib.import_module(module)
    except ImportError as error:
        if sys.executable != "/usr/bin/python3" and os.path.exists("/usr/bin/python3"):
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        packages = ", ".join(DEBIAN_PACKAGES[m] for m in modules)
        sys.exit(f"needs {' and '.join(modules)} (Debian's {packages}): {error}")
