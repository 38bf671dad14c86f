"""The shape of the Python code (issue 34): one package, thin commands, no sys.path changes, no JOB.log parsing.
Read from the sources with the ast module: every .py under tools/, tests/ and benchmarks/ (no sys.path attribute
anywhere); the package and the benchmarks (no path to a .log file built, no import of a test or benchmark
module); the commands tools/NAME.py (each imports main from ldfcz_tools.NAME, which has one)."""
import ast
import importlib
import os
import unittest

from ldfcz_tools.paths import PACKAGE, ROOT, TOOLS


def sources(*folders):
    # tools/paraview holds scripts for ParaView's own Python (pvpython, pvbatch): not the package's code
    for folder in folders:
        for d, dirs, files in os.walk(os.path.join(ROOT, folder)):
            dirs[:] = [x for x in dirs if x not in ('__pycache__', 'ldfcz_tools', 'paraview') or
                       (d == TOOLS and x == 'ldfcz_tools')]
            for f in files:
                if f.endswith('.py'):
                    yield os.path.join(d, f)


def tree(path):
    with open(path) as f:
        return ast.parse(f.read(), path)


class Package(unittest.TestCase):

    def test_no_sys_path(self):
        bad = [os.path.relpath(p, ROOT) for p in sources('tools', 'tests', 'benchmarks')
               if any(isinstance(n, ast.Attribute) and n.attr == 'path' and isinstance(n.value, ast.Name) and
                      n.value.id == 'sys' for n in ast.walk(tree(p)))]
        self.assertEqual(bad, [], 'files using sys.path')

    def test_no_log_paths(self):
        # a string ending in '.log' inside an expression that builds a path or opens a file
        bad = []
        for p in sources('tools', 'benchmarks'):
            for n in ast.walk(tree(p)):
                if isinstance(n, (ast.BinOp, ast.JoinedStr, ast.Call)):
                    for c in ast.walk(n):
                        if isinstance(c, ast.Constant) and isinstance(c.value, str) and c.value.endswith('.log'):
                            bad.append('%s:%d' % (os.path.relpath(p, ROOT), c.lineno))
        self.assertEqual(sorted(set(bad)), [], 'paths to .log files')

    def test_imports(self):
        # the package and the benchmarks import the standard library, the package and a few known packages
        # (numpy, scipy, matplotlib, VTK), each other's benchmark only within benchmarks/, never a test
        allowed = {'numpy', 'scipy', 'matplotlib', 'vtkmodules', 'ldfcz_tools'}
        bench = {os.path.splitext(f)[0] for f in os.listdir(os.path.join(ROOT, 'benchmarks')) if f.endswith('.py')}
        for p in sources('tools', 'benchmarks'):
            for n in ast.walk(tree(p)):
                names = [a.name for a in n.names] if isinstance(n, ast.Import) else \
                    [n.module] if isinstance(n, ast.ImportFrom) and n.level == 0 else []
                for name in names:
                    top = name.split('.')[0]
                    if top in bench:
                        self.assertTrue(p.startswith(os.path.join(ROOT, 'benchmarks')), '%s imports %s' % (p, name))
                        continue
                    self.assertTrue(top in allowed or top in __import__('sys').stdlib_module_names,
                                    '%s imports %s' % (os.path.relpath(p, ROOT), name))

    def test_commands(self):
        # every tools/NAME.py that names a package module is thin: it calls ldfcz_tools.cli.run('NAME') (which
        # imports the module and calls its main, turning bad input into one line: issue 37), and that main exists
        commands = 0
        for f in sorted(os.listdir(TOOLS)):
            name = os.path.splitext(f)[0]
            if not f.endswith('.py') or not os.path.exists(os.path.join(PACKAGE, f)):
                continue
            t = tree(os.path.join(TOOLS, f))
            imports = [(n.module, [a.name for a in n.names]) for n in ast.walk(t) if isinstance(n, ast.ImportFrom)]
            self.assertIn(('ldfcz_tools.cli', ['run']), imports, f)
            calls = [c.args[0].value for c in ast.walk(t) if isinstance(c, ast.Call) and
                     isinstance(c.func, ast.Name) and c.func.id == 'run' and c.args and
                     isinstance(c.args[0], ast.Constant)]
            self.assertEqual(calls, [name], f)
            self.assertLessEqual(len([n for n in t.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))]), 0, f)
            self.assertTrue(callable(getattr(importlib.import_module('ldfcz_tools.' + name), 'main', None)), name)
            commands += 1
        self.assertGreaterEqual(commands, 10)

    def test_entry_points_guarded(self):
        # every `if __name__ == '__main__':` of the package, tools/ and benchmarks/ goes through ldfcz_tools.cli (run
        # or guard): no traceback on bad input (issue 37)
        bad = []
        for p in sources('tools', 'benchmarks'):
            for n in tree(p).body:
                if isinstance(n, ast.If) and isinstance(n.test, ast.Compare) and \
                        getattr(n.test.left, 'id', '') == '__name__':
                    names = {c.func.id for c in ast.walk(n) if isinstance(c, ast.Call) and isinstance(c.func, ast.Name)}
                    if not names & {'run', 'guard'}:
                        bad.append(os.path.relpath(p, ROOT))
        self.assertEqual(bad, [], 'entry points without ldfcz_tools.cli')

    def test_modules_import(self):
        for f in sorted(os.listdir(PACKAGE)):
            if f.endswith('.py'):
                importlib.import_module('ldfcz_tools.' + os.path.splitext(f)[0])


if __name__ == '__main__':
    unittest.main()
