"""A fork server ("zygote") that starts the checker's child processes already warm.

Every child the checker starts (checker/isolation/child.py) would spend its first ~0.3 CPU-s starting
Python and importing pygame, lesson11 and the checker's probes before any lab code runs.
The zygote does that work once per grading run: it imports those modules (and nothing else:
it never calls pygame.init(), opens a window or configures lesson11.runtime), then serves
requests from the grader over a Unix socket. For each request it forks; the forked process
sets itself up the way `python -X faulthandler -m checker.isolation.child ...` under sandbox.run_child
would be set up (its own session, the same resource limits, the working directory, the
environment, sys.path as PYTHONPATH would make it, stdin from /dev/null, stdout and stderr on
the grader's pipes, unbuffered utf-8 text streams, no bytecode written, faulthandler on) and
runs checker/isolation/child.py as __main__. The zygote reaps its children and reports each exit status.

Protocol (SOCK_SEQPACKET, one JSON message per packet):
  grader -> zygote, on the control socket: {"argv", "cwd", "env", "limits"} with four file
      descriptors: the write ends of the stdout and stderr pipes, the zygote's end of a
      fresh socket pair for this request, and the write end of the result pipe (fd 3 in the child);
  zygote -> grader, on the request's socket: {"pid": n} once forked (or {"error": text}),
      later {"returncode": n} (Popen's convention: -signal when killed by a signal).
The zygote says {"ready": true} on the control socket once its imports are done, and leaves
(killing the process groups of children still running) when the grader's end is closed.

The grader side is checker.isolation.sandbox (ZygoteClient); the zygote is started with
`python -m checker.isolation.zygote FD`.
"""
import functools
import json
import os
import selectors
import signal
import socket
import sys

WARM_MODULES = ("pygame", "pygame.font", "pygame.freetype", "pygame.sysfont", "pygame.pkgdata", "pygame.sprite",
                "pygame.surfarray", "pygame.sndarray", "numpy", "lesson11.runtime", "lesson11.panel",
                "lesson11.physics2d", "lesson11.physics2d.draw", "checker.isolation.child", "checker.judging.tape")
# and every lab's probe module (_lab_probes: found as the registry finds the labs, so a new lab needs no row here)
# the standard library a step or a lab may import (item 7 of issue 35 allows the pure ones in steps), and what
# the child's own error and timing paths import late: all imported here, so a child that runs as another user
# never opens a file of Python's after it switched (its interpreter may sit where that user cannot enter)
WARM_STDLIB = ("math", "cmath", "itertools", "functools", "operator", "fractions", "decimal", "numbers",
               "statistics", "random", "collections", "collections.abc", "dataclasses", "typing", "enum", "abc",
               "copy", "heapq", "bisect", "array", "string", "re", "time", "contextlib", "warnings", "traceback",
               "linecache", "tokenize", "textwrap", "pprint", "reprlib", "weakref", "types", "struct", "json",
               "hashlib", "io", "os", "sys", "atexit", "threading", "queue", "datetime", "calendar", "colorsys",
               "inspect", "ast", "dis", "importlib.resources", "importlib.readers", "importlib.util",
               "importlib.machinery", "encodings.latin_1", "encodings.ascii", "encodings.utf_16",
               "encodings.unicode_escape", "encodings.raw_unicode_escape", "unicodedata", "zlib", "base64",
               "pkgutil", "pathlib", "glob", "fnmatch", "shutil", "tempfile", "csv", "argparse", "platform",
               "pickle", "copyreg", "codecs", "difflib", "shlex", "errno", "stat", "signal", "subprocess",
               "logging", "secrets", "uuid", "locale", "gettext", "sysconfig")
PACKAGE_DATA = ("freesansbold.ttf", "pygame_icon.bmp")   # what pygame opens lazily (its default font)
MAX_MESSAGE = 1 << 20


def _child(request, fds, base_path, close):
    """In the forked process: become the child sandbox.run_child would have started, run it, exit.

    Everything that needs a file of Python's or the project's (the child module's code) is done before
    the limits switch the user: after that the child opens only its work folder.
    """
    code = 1
    try:
        signal.signal(signal.SIGCHLD, signal.SIG_DFL)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        for thing in close:
            thing.close()  # the zygote's sockets (this request's among them) and its selector
        out_fd, err_fd, _, result_fd = fds
        argv = request["argv"]
        spec, main_code = _main_code(argv[0])   # read while still the zygote's user
        import importlib
        for name in request.get("preload") or ():   # the lab's probes (a lab the zygote did not import): now, as root
            importlib.import_module(name)
        from checker.isolation import confine
        limits = confine.Limits(**request["limits"])
        null = os.open(os.devnull, os.O_RDONLY)   # before the jail, which has no /dev
        confine.limit_child(limits, result_fd)()  # setsid, the rlimits (refused ones as notes), the uid's process
        # limit, the jail and the user switch, as the preexec_fn does
        os.dup2(null, 0)
        os.dup2(out_fd, 1)
        os.dup2(err_fd, 2)
        os.dup2(result_fd, 3)   # the result pipe: the child's argv names fd 3
        os.closerange(4, max(os.sysconf("SC_OPEN_MAX"), 256) if hasattr(os, "sysconf") else 4096)
        os.chdir(request["cwd"])
        os.environ.clear()
        os.environ.update(request["env"])
        _fresh_stdio()
        import faulthandler
        faulthandler.enable()  # -X faulthandler
        sys.dont_write_bytecode = True  # PYTHONDONTWRITEBYTECODE
        python_path = [p for p in request["env"].get("PYTHONPATH", "").split(os.pathsep) if p]
        sys.path[:] = python_path + base_path   # the project and Python's own; not the work folder
        sys.argv[:] = argv
        try:
            _run_main(spec, main_code)
            code = 0
        except SystemExit as exc:
            code = _exit_code(exc.code)
        except BaseException:  # noqa: BLE001 - what an uncaught exception does to python: a traceback, 1
            import traceback
            traceback.print_exc()
            code = 1
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except BaseException:  # noqa: BLE001
                pass
    except BaseException:   # the set-up failed (the lab never ran): its account goes to the run's stderr
        import traceback
        os.write(fds[1], traceback.format_exc().encode())
        raise
    finally:
        os._exit(code)


_MAIN_CODE = {}   # module name -> (its spec, its code object), read once by the zygote


def _main_code(name):
    """(spec, code) of module `name`, to run as __main__ as `python -m name` does (cached)."""
    if name not in _MAIN_CODE:
        import importlib.util
        spec = importlib.util.find_spec(name)
        _MAIN_CODE[name] = (spec, spec.loader.get_code(name))
    return _MAIN_CODE[name]


def _run_main(spec, main_code):
    """Run `main_code` as the module __main__, as runpy.run_module(alter_sys=True) does."""
    import types
    module = types.ModuleType("__main__")
    module.__dict__.update(__file__=spec.origin, __cached__=None, __loader__=spec.loader,
                           __package__=spec.parent, __spec__=spec)
    sys.modules["__main__"] = module
    sys.argv[0] = spec.origin
    exec(main_code, module.__dict__)


def _exit_code(code):
    """The exit status python gives `raise SystemExit(code)`."""
    if code is None:
        return 0
    if isinstance(code, int):
        return code & 0xFF
    try:
        print(code, file=sys.stderr)
    except BaseException:  # noqa: BLE001
        pass
    return 1


def _fresh_stdio():
    """sys.stdin/stdout/stderr as python makes them with PYTHONUNBUFFERED=1 PYTHONIOENCODING=utf-8."""
    import io

    def stream(fd, mode, errors):
        raw = io.FileIO(fd, mode, closefd=False)
        raw.name = f"<{('stdin', 'stdout', 'stderr')[fd]}>"
        if mode == "r":
            text = io.TextIOWrapper(io.BufferedReader(raw), encoding="utf-8", errors=errors)
        else:
            text = io.TextIOWrapper(raw, encoding="utf-8", errors=errors, newline="\n", write_through=True)
        text.mode = mode
        return text

    sys.stdin = sys.__stdin__ = stream(0, "r", "strict")
    sys.stdout = sys.__stdout__ = stream(1, "w", "strict")
    sys.stderr = sys.__stderr__ = stream(2, "w", "backslashreplace")


def _returncode(status):
    return os.waitstatus_to_exitcode(status)


def serve(control):
    """Answer requests on `control` until the grader closes its end."""
    base_path = sys.path[1:]
    project = os.environ.get("PYTHONPATH", "")
    for entry in [p for p in project.split(os.pathsep) if p]:
        if entry in base_path:
            base_path.remove(entry)
    wake_read, wake_write = os.pipe()
    os.set_blocking(wake_read, False)
    os.set_blocking(wake_write, False)
    signal.signal(signal.SIGCHLD, lambda signum, frame: None)
    signal.set_wakeup_fd(wake_write)
    selector = selectors.DefaultSelector()
    selector.register(control, selectors.EVENT_READ, "control")
    selector.register(wake_read, selectors.EVENT_READ, "wake")
    running = {}   # pid -> the request's socket
    control.send(json.dumps({"ready": True}).encode())
    try:
        while True:
            for key, _ in selector.select():
                if key.data == "wake":
                    try:
                        while os.read(wake_read, 4096):
                            pass
                    except BlockingIOError:
                        pass
                    _reap(running)
                    continue
                try:
                    data, fds, _flags, _addr = socket.recv_fds(control, MAX_MESSAGE, 4)
                except OSError:
                    return
                if not data:
                    return  # the grader is gone
                if len(fds) != 4:
                    for fd in fds:
                        os.close(fd)
                    continue
                reply = socket.socket(fileno=fds[2])
                try:
                    request = json.loads(data)
                    pid = os.fork()
                except BaseException as exc:  # noqa: BLE001 - tell the grader, keep serving
                    for fd in (fds[0], fds[1], fds[3]):
                        os.close(fd)
                    _send(reply, {"error": f"{type(exc).__name__}: {exc}"})
                    reply.close()
                    continue
                if pid == 0:
                    signal.set_wakeup_fd(-1)
                    close = [selector, control, reply] + list(running.values())
                    os.close(wake_read)
                    os.close(wake_write)
                    _child(request, fds, base_path, close)
                for fd in (fds[0], fds[1], fds[3]):
                    os.close(fd)
                running[pid] = reply
                _send(reply, {"pid": pid})
                _reap(running)
    finally:
        for pid in running:
            try:
                os.killpg(pid, signal.SIGKILL)
            except OSError:
                pass
        for pid in list(running):
            try:
                os.waitpid(pid, 0)
            except OSError:
                pass


def _reap(running):
    while running:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
        reply = running.pop(pid, None)
        if reply is not None:
            _send(reply, {"returncode": _returncode(status)})
            reply.close()


def _send(sock, message):
    try:
        sock.send(json.dumps(message).encode())
    except OSError:
        pass  # the grader stopped listening for this run


def main(argv):
    control = socket.socket(fileno=int(argv[0]))
    warm_up()
    _main_code("checker.isolation.child")
    import gc
    gc.collect()
    gc.freeze()  # what is here now stays shared with the children: their collections never walk it
    serve(control)


def warm_up():
    """Import everything a child needs and keep the data files pygame opens lazily, while still the grader's user.

    The zygote does it once before it forks; the portable child (checker/isolation/child.py) does it itself before it
    switches user, so that a child running as another user never opens a file of Python's afterwards.
    """
    import importlib
    importlib.import_module("checker.isolation.confine")
    required = WARM_MODULES + _lab_probes()
    for name in required + WARM_STDLIB + _handout_imports():
        try:
            importlib.import_module(name)
        except ImportError:
            if name in required:
                raise
    _keep_package_data()


@functools.lru_cache(maxsize=None)
def warm_names(probes=None):
    """The modules warm_up imports (and `probes`, a run's preloaded lab probes): in a child forked from the
    zygote, or a portable child after warm_up, importing one again needs no file. The optional ones count only
    where this Python has them."""
    import importlib.util
    optional = [name for name in WARM_STDLIB + _handout_imports() if _findable(importlib.util, name)]
    return frozenset(WARM_MODULES + _lab_probes() + tuple(optional) + ((probes,) if probes else ()))


def _findable(util, name):
    try:
        return util.find_spec(name) is not None
    except (ImportError, ValueError):
        return False


def _lab_probes():
    """The import name of every lab's probe module (checker/labs/<id>/probes.py)."""
    from checker import labs
    return tuple(lab.probes for lab in labs.LABS)


def _handout_imports():
    """Every module the labs' handouts (their starters) import, so a lab needs no import of its own."""
    import ast
    from checker import labs
    names = []
    for lab in labs.LABS:
        try:
            with open(lab.starter, "rb") as handle:
                tree = ast.parse(handle.read())
        except (OSError, SyntaxError, ValueError, AttributeError):
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                names += [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                names.append(node.module)
    return tuple(dict.fromkeys(names))


def _keep_package_data():
    """Read the files pygame opens lazily (its default font) now, and have pygame.pkgdata serve them from memory.

    pygame.font.Font(None, size) opens freesansbold.ttf beside pygame's own files, which a child running as
    another user may not be able to read; a file-like object of the same bytes is what pygame takes instead.
    """
    import io
    import pygame.pkgdata as pkgdata
    original = pkgdata.getResource
    kept = {}
    for name in PACKAGE_DATA:
        try:
            with original(name) as handle:
                kept[name] = handle.read()
        except OSError:
            pass

    def get_resource(identifier, pkgname=pkgdata.__name__):
        if pkgname == pkgdata.__name__ and identifier in kept:
            return io.BytesIO(kept[identifier])
        return original(identifier, pkgname)

    get_resource.__doc__ = original.__doc__
    pkgdata.getResource = get_resource
    from lesson11 import panel
    panel.study_rows()   # the solver panel's table (lesson11/bench/frontier.json), read once and kept


if __name__ == "__main__":
    main(sys.argv[1:])
