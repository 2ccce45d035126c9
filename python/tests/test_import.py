"""import gab where something is missing: the error names the interpreter,
what is missing and where gab looked (run by ctest and .ci/run). Each case
imports gab in a fresh interpreter (this one's), so a failed import leaves
this process alone."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import gab

PACKAGE = os.path.dirname(os.path.abspath(gab.__file__))

# Prints the ImportError's text, or "imported" when the import worked.
IMPORT = "try:\n    import gab\n    print('imported')\nexcept ImportError as e:\n    print(e)\n"


def import_gab(path, environment=None):
    """The output of importing gab with `path` first on sys.path and the
    environment changed by `environment` (a value None removes the name)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = path
    for name, value in (environment or {}).items():
        if value is None:
            env.pop(name, None)
        else:
            env[name] = value
    done = subprocess.run([sys.executable, "-c", IMPORT], env=env, capture_output=True, text=True, timeout=60)
    return (done.stdout + done.stderr).strip()


class ImportTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.folder)

    def installed_copy(self, library, python=""):
        """A copy of the package as cmake --install lays it out: a _location.py
        naming its library (relative to the package) and its interpreter."""
        package = os.path.join(self.folder, "gab")
        shutil.copytree(PACKAGE, package, ignore=shutil.ignore_patterns("__pycache__", "_location.py"))
        with open(os.path.join(package, "_location.py"), "w") as f:
            f.write(f"LIBRARY = {library!r}\nPYTHON = {python!r}\n")
        return self.folder

    def without_numpy(self, path):
        """`path` after a folder whose numpy.py fails as a missing numpy does."""
        hidden = os.path.join(self.folder, "no-numpy")
        os.makedirs(hidden)
        with open(os.path.join(hidden, "numpy.py"), "w") as f:
            f.write("raise ModuleNotFoundError(\"No module named 'numpy'\", name='numpy')\n")
        return hidden + os.pathsep + path

    def test_without_numpy_the_error_names_the_interpreter_and_numpy(self):
        text = import_gab(self.without_numpy(os.path.dirname(PACKAGE)))
        self.assertIn(f"gab needs numpy, and this interpreter, {sys.executable} (Python ", text)
        self.assertIn("cannot import it: No module named 'numpy'", text)
        self.assertIn(f"{sys.executable} -m pip install numpy", text)

    def test_without_numpy_an_installed_gab_names_the_interpreter_it_was_installed_for(self):
        library = os.path.relpath(os.environ.get("GAB_LIBRARY", "libgab.so"), os.path.join(self.folder, "gab"))
        path = self.installed_copy(library, python="/opt/elsewhere/bin/python3")
        text = import_gab(self.without_numpy(path), {"GAB_LIBRARY": None})
        self.assertIn(f"this interpreter, {sys.executable}", text)
        self.assertIn("gab was installed for /opt/elsewhere/bin/python3", text)

    def test_a_missing_library_names_where_gab_looked(self):
        missing = os.path.join(self.folder, "lib", "libgab.so")
        text = import_gab(os.path.dirname(PACKAGE), {"GAB_LIBRARY": missing})
        self.assertIn(f"gab: cannot load libgab for {sys.executable}; looked at $GAB_LIBRARY ({missing}): ", text)
        self.assertIn("No such file or directory", text)
        self.assertIn("Set GAB_LIBRARY to the path of libgab.so, or install gab with cmake --install", text)

    def test_an_installed_package_without_its_library_names_both_places(self):
        path = self.installed_copy("../../lib/libgab.so.0.1")
        text = import_gab(path, {"GAB_LIBRARY": None})
        if text == "imported":
            self.skipTest("the dynamic loader finds a libgab on this machine")
        expected = os.path.normpath(os.path.join(self.folder, "gab", "../../lib/libgab.so.0.1"))
        self.assertIn(f"looked at the library installed with this package ({expected}): ", text)
        self.assertIn("; the dynamic loader's search path (LD_LIBRARY_PATH, ldconfig's cache, /usr/lib) (libgab.so): ",
                      text)


if __name__ == "__main__":
    unittest.main()
