"""The commands' common entry (tools/NAME.py, python3 -m ldfcz_tools.NAME, benchmarks/*.py): a bad input or a missing
dependency ends a command with one line on standard error and a non-zero exit status, never a Python traceback.

  run(NAME)     import ldfcz_tools.NAME and call its main(); the thin commands use it
  guard(main)   call main() of a module already imported (a module's own `python3 -m` entry, the benchmarks)

A command whose module declares REQUIRES (Python modules such as numpy, scipy, vtk) and is run by a Python that lacks
one of them starts itself again under Debian's /usr/bin/python3 when that one has them (tools/setup.sh installs
python3-numpy, python3-scipy, python3-matplotlib, python3-vtk9 there; `python3` on PATH may be another, e.g. a
pyenv one); otherwise it names the missing module and the Debian package that brings it. LDFCZ_NO_REEXEC=1 keeps
the Python it was started with; LDFCZ_TRACEBACK=1 shows the traceback of an unexpected error.

Exit status: 2 for bad input or a missing dependency (as argparse's usage errors), 130 after Ctrl-C, else the
command's own.
"""
import importlib
import importlib.util
import inspect
import os
import subprocess
import sys

SYSTEM_PYTHON = '/usr/bin/python3'
#: the Debian package of a Python module the tools use
DEBIAN_PACKAGES = {'numpy': 'python3-numpy', 'scipy': 'python3-scipy', 'matplotlib': 'python3-matplotlib',
                   'vtk': 'python3-vtk9', 'vtkmodules': 'python3-vtk9'}


class ToolError(Exception):
    """A bad input a command reports in one line (its message names the file and what is wrong)."""


def prog_name():
    return os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else 'ldfcz tool'


def missing_modules(names):
    """The modules of names this Python cannot import (their top-level package not found)."""
    out = []
    for n in names:
        try:
            if importlib.util.find_spec(n) is None:
                out.append(n)
        except (ImportError, ValueError):
            out.append(n)
    return out


def system_python_has(names):
    """True when /usr/bin/python3 is another interpreter than this one and imports every module of names."""
    if not os.access(SYSTEM_PYTHON, os.X_OK):
        return False
    try:
        if os.path.realpath(SYSTEM_PYTHON) == os.path.realpath(sys.executable):
            return False   # the same interpreter (perhaps started with -S): the caller's choice stands
    except OSError:
        return False
    code = 'import importlib.util, sys; sys.exit(any(importlib.util.find_spec(n) is None for n in %r))' % (
        list(names),)
    try:
        return subprocess.run([SYSTEM_PYTHON, '-c', code], capture_output=True, timeout=60).returncode == 0
    except (OSError, subprocess.SubprocessError):
        return False


def missing_text(names):
    pkgs = sorted(set(DEBIAN_PACKAGES.get(n, 'python3-' + n) for n in names))
    what = 'needs the Python module%s %s, which %s cannot import' % ('s' if len(names) > 1 else '', ', '.join(names),
                                                                      sys.executable)
    try:
        same = os.path.realpath(sys.executable) == os.path.realpath(SYSTEM_PYTHON)
    except OSError:
        same = False
    if same:
        return '%s: install %s (apt-get install %s; tools/setup.sh does)' % (what, ' '.join(pkgs), ' '.join(pkgs))
    return '%s: run it with %s, where tools/setup.sh installs %s (Debian), or install them for this Python' % (
        what, SYSTEM_PYTHON, ' '.join(pkgs))


def ensure_modules(names):
    """Start the command again under /usr/bin/python3 when this Python lacks modules of names that one has;
    else raise ToolError naming them. Returns when every module is importable."""
    missing = missing_modules(names)
    if not missing:
        return
    if os.environ.get('LDFCZ_NO_REEXEC') != '1' and system_python_has(missing):
        reexec([SYSTEM_PYTHON])
    raise ToolError(missing_text(missing))


def reexec(prefix):
    """Replace this process by prefix + the command as it was started (the script, or the module of
    python3 -m ldfcz_tools.NAME run as its file), the package on PYTHONPATH."""
    tools = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.environ['PYTHONPATH'] = tools + (os.pathsep + os.environ['PYTHONPATH'] if os.environ.get('PYTHONPATH') else '')
    sys.stdout.flush()
    sys.stderr.flush()
    os.execv(prefix[0], prefix + [os.path.abspath(sys.argv[0])] + sys.argv[1:])


def executable(path, what='program'):
    """path, when it names an executable file; else ToolError saying what it is instead."""
    if not os.path.exists(path):
        raise ToolError('%s: no such %s' % (path, what))
    if os.path.isdir(path):
        raise ToolError('%s: is a directory, not the %s' % (path, what))
    if not os.access(path, os.X_OK):
        raise ToolError('%s: not an executable %s' % (path, what))
    if os.path.getsize(path) == 0:
        raise ToolError('%s: an empty file, not the %s' % (path, what))
    return path


def error_text(e):
    """One line for an exception of a command."""
    if isinstance(e, ToolError):
        return str(e)
    if isinstance(e, ModuleNotFoundError) and e.name:
        return missing_text([e.name.split('.')[0]])
    if isinstance(e, IsADirectoryError):
        return '%s: is a directory, not a file' % e.filename
    if isinstance(e, FileExistsError):
        return '%s: exists and is not a directory (a directory is expected there)' % e.filename
    if isinstance(e, NotADirectoryError):
        return '%s: is not a directory' % e.filename
    if isinstance(e, FileNotFoundError):
        return '%s: file not found' % (e.filename or e)
    if isinstance(e, PermissionError):
        return '%s: permission denied (not readable, or not an executable program)' % (e.filename or e)
    if isinstance(e, OSError) and e.filename:
        return '%s: %s' % (e.filename, e.strerror or e)
    if isinstance(e, UnicodeDecodeError):
        named = binary_arguments()
        if len(named) == 1:
            return '%s: not a text file (a binary file?)' % named[0]
        return 'an input file is not text (a binary file?): %s at byte %d' % (e.reason, e.start)
    if isinstance(e, KeyError):
        return 'missing column or key %s in an input file' % e
    if isinstance(e, (ValueError, IndexError, TypeError)):
        return 'bad input: %s' % (str(e).splitlines()[0] if str(e) else type(e).__name__)
    return '%s: %s' % (type(e).__name__, str(e).splitlines()[0] if str(e) else '')


def binary_arguments():
    """The command's arguments that name existing files whose beginning is not UTF-8 text."""
    out = []
    for arg in sys.argv[1:]:
        for path in (arg, arg.split('=', 1)[-1]):
            if os.path.isfile(path):
                try:
                    with open(path, 'rb') as f:
                        f.read(4096).decode('utf-8')
                except UnicodeDecodeError:
                    out.append(path)
                except OSError:
                    pass
                break
    return out


def guard(main, argv=None):
    """Call main (with argv when it takes an argument) and turn any exception into one line and exit status 2."""
    prog = prog_name()
    try:
        params = [p for p in inspect.signature(main).parameters.values()
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
        if params and params[0].default is inspect.Parameter.empty:
            rc = main(sys.argv[1:] if argv is None else argv)
        elif params and argv is not None:
            rc = main(argv)
        else:
            rc = main()
        return rc if isinstance(rc, int) else (0 if rc is None else 1)
    except SystemExit:
        raise
    except KeyboardInterrupt:
        sys.stderr.write('%s: interrupted\n' % prog)
        return 130
    except BrokenPipeError:
        return 1
    except Exception as e:  # the one place that turns a failure into a line instead of a traceback
        if os.environ.get('LDFCZ_TRACEBACK') == '1':
            raise
        sys.stderr.write('%s: error: %s\n' % (prog, error_text(e)))
        return 2


def run(name, argv=None):
    """The command NAME: its module imported (its REQUIRES checked first), then guard(module.main)."""
    prog = prog_name()
    try:
        spec = importlib.util.find_spec('ldfcz_tools.' + name)
        if spec is None:
            raise ToolError('no module ldfcz_tools.%s' % name)
        mod = importlib.import_module('ldfcz_tools.' + name)
        ensure_modules(getattr(mod, 'REQUIRES', ()))
    except SystemExit:
        raise
    except Exception as e:
        if os.environ.get('LDFCZ_TRACEBACK') == '1':
            raise
        sys.stderr.write('%s: error: %s\n' % (prog, error_text(e)))
        return 2
    return guard(mod.main, argv)
