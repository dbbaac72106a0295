"""Finds the mocapfill Python module (the C++ library's binding) from inside Blender.

Blender's Python does not see a module installed for the system's Python unless both share
site-packages (Debian's Blender uses the system Python 3.11, so a normal import usually
works). Otherwise the module is looked for where mocapfill installs it beside this add-on:
add-on in <prefix>/share/mocapfill/blender/mocapfill_blender/, module in
<prefix>/lib/python3/dist-packages/mocapfill/.
"""
import importlib
import os
import sys

INSTALL_HINT = ("install mocapfill with its Python module (cmake --install, or the Debian package), or put the "
                "folder holding the 'mocapfill' package on PYTHONPATH before starting Blender "
                "(in a build tree: PYTHONPATH=<build>/python)")


def installed_module_folder():
    addon_folder = os.path.dirname(os.path.abspath(__file__))
    return os.path.normpath(os.path.join(addon_folder, "..", "..", "..", "..", "lib", "python3", "dist-packages"))


def import_mocapfill():
    """The mocapfill module; ImportError with what was tried and how to install when missing."""
    try:
        return importlib.import_module("mocapfill")
    except ImportError as first:
        folder = installed_module_folder()
        if os.path.isdir(os.path.join(folder, "mocapfill")) and folder not in sys.path:
            sys.path.append(folder)
            try:
                return importlib.import_module("mocapfill")
            except ImportError as second:
                raise ImportError("mocapfill: the Python module in %s does not load (%s); it must be built for "
                                  "Blender's Python %d.%d" % (folder, second, *sys.version_info[:2])) from None
        raise ImportError("mocapfill: the Python module is not importable (%s) and is not in %s; %s"
                          % (first, folder, INSTALL_HINT)) from None
