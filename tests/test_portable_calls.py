"""No POSIX-only call in checker/, lesson11/, starters/, solutions/ outside the places that are the POSIX path.

The scan reads the code (ast), not its text: `import resource`, `from os import setsid`, `import signal as s`
then `s.SIGKILL`, `Popen(..., preexec_fn=...)` are all found, comments and strings are not. Each allowed use
is listed by file, function and name, so a new use anywhere else (or a new one in an allowed file's other
function) fails naming file:line. A use through getattr(module, "name", default) is a guarded one (it works
where the name is missing) and is not counted. Windows and macOS themselves are not run here: the list of
names below is what CPython lacks on Windows (os, signal, resource, pwd, grp, fcntl, termios) or on Windows and
macOS (socket.SOCK_SEQPACKET; selectors and select over pipes work on neither Windows nor with every macOS pipe).
"""
import ast
import os
import textwrap

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCANNED = ("checker", "lesson11", "starters", "solutions")

POSIX_ONLY = {  # module -> its attributes that exist on POSIX only (or, for select, work only on sockets there)
    "os": {"fork", "forkpty", "killpg", "setsid", "getsid", "setpgid", "getpgid", "setpgrp", "getpgrp", "getuid",
           "geteuid", "getgid", "getegid", "setuid", "seteuid", "setgid", "setegid", "setgroups", "initgroups",
           "setresuid", "setresgid", "chown", "lchown", "fchown", "chroot", "mkfifo", "mknod", "nice", "wait3",
           "wait4", "WNOHANG", "sysconf", "getloadavg", "sched_setaffinity", "register_at_fork", "posix_spawn",
           "openpty", "O_NOFOLLOW", "O_NONBLOCK", "O_CLOEXEC", "pipe2", "set_blocking", "get_blocking"},
    "signal": {"SIGKILL", "SIGXCPU", "SIGPROF", "SIGALRM", "SIGVTALRM", "SIGXFSZ", "SIGHUP", "SIGQUIT", "SIGUSR1",
               "SIGUSR2", "SIGCHLD", "SIGPIPE", "SIGSTOP", "SIGCONT", "SIGTSTP", "setitimer", "getitimer", "alarm",
               "ITIMER_REAL", "ITIMER_PROF", "ITIMER_VIRTUAL", "pause", "pthread_kill", "pthread_sigmask",
               "siginterrupt", "sigwait"},
    "socket": {"AF_UNIX", "SOCK_SEQPACKET", "send_fds", "recv_fds", "sendmsg", "recvmsg"},
    "select": {"poll", "epoll", "kqueue", "select"},
    "shutil": {"chown"},
}
POSIX_MODULES = {"resource", "pwd", "grp", "fcntl", "termios", "tty", "pty", "posix", "selectors", "crypt",
                 "syslog"}
POPEN_POSIX_ARGS = {"preexec_fn", "pass_fds", "user", "group", "extra_groups", "process_group", "umask"}
SOCKET_METHODS = {"send_fds", "recv_fds", "sendmsg", "recvmsg"}  # methods of a socket object: no Windows

# The places that are the POSIX path: {file: {function (qualified, or "<module>"): {names used}}}.
# checker/isolation/sandbox.py, zygote.py and child.py are the checker's POSIX child (issue 32: a portable path beside it
# is branch i32-portable's); the lead refines these three entries after that branch is merged.
ALLOWED = {
    "checker/isolation/confine.py": {
        # the portable path calls it too: `import resource` failing (Windows) and a refused limit (macOS) are notes
        "set_rlimits": {"import resource", "resource.setrlimit"},
        "limit_child.apply": {"os.setsid"},
        "leave_root": {"import resource", "resource.setrlimit", "resource.RLIMIT_NPROC"},   # a child user only
    },
    "checker/isolation/sandbox.py": {
        "<module>": {"import selectors"},
        "_start": {"Popen(pass_fds=)", "Popen(preexec_fn=)"},
        "ZygoteClient.__init__": {"Popen(pass_fds=)", "socket.AF_UNIX", "socket.SOCK_SEQPACKET"},
        "ZygoteClient.spawn": {"socket.AF_UNIX", "socket.SOCK_SEQPACKET", "socket.send_fds"},
        "_kill_group": {"os.killpg", "signal.SIGKILL"},   # the portable path calls it only where both exist
        "_run_in": {"import pwd", "os.chown", "pwd.getpwnam"},   # with a child user only (a root grader)
        "_run_posix": {"selectors.DefaultSelector", "selectors.EVENT_READ"},
    },
    "checker/isolation/zygote.py": {
        "<module>": {"import selectors"},
        "_child": {"os.sysconf", "signal.SIGCHLD"},
        "serve": {"os.fork", "os.killpg", "os.set_blocking", "selectors.DefaultSelector", "selectors.EVENT_READ",
                  "signal.SIGCHLD", "signal.SIGKILL", "socket.recv_fds"},
        "_reap": {"os.WNOHANG"},
    },
    "checker/isolation/child.py": {
        "call_limited": {"signal.ITIMER_PROF", "signal.SIGPROF", "signal.setitimer"},   # the Watchdog otherwise
        "main": {"signal.SIGXCPU"},   # the POSIX path only (the portable child has its Watchdog)
    },
    # the child's user: consulted only by a root grader (is_root() is hasattr-guarded and False on Windows)
    "checker/isolation/users.py": {
        "is_root": {"os.geteuid"},
        "choose": {"import pwd", "pwd.getpwnam"},
        "_entry": {"import pwd", "pwd.getpwnam"},
        "_groups": {"grp.getgrall", "import grp"},
        "drop_to": {"os.setgid", "os.setgroups", "os.setuid"},
        # one uid per run, the jail, the real permission checks: a root grader on POSIX only
        "enter_jail": {"os.chroot"},
        "jail_works": {"os.chroot", "os.fork"},
        "take_uid": {"import fcntl", "fcntl.flock", "fcntl.LOCK_EX", "fcntl.LOCK_NB"},
        "_has_entry": {"import pwd", "pwd.getpwuid"},
        "kill_uid": {"os.fork", "os.setgroups", "os.setuid", "signal.SIGKILL"},
        "as_run_user": {"os.fork"},
        "python_problem": {"Popen(preexec_fn=)"},
    },
    # shipped into the graders' Linux containers only (Gradescope, GitHub Classroom, PrairieLearn)
    "checker/platforms/templates/grade_submission.py": {"<module>": {"import pwd"}, "run_as": {"os.geteuid", "pwd.getpwnam"}},
    # the no-follow writer: used only where os.supports_dir_fd has what it needs (_can_use_dir_fd), and the
    # owner test only where os.geteuid exists; Windows writes by path with the same checks
    "checker/reporting/outputs.py": {"_own": {"os.geteuid"}, "write_below": {"os.O_NOFOLLOW"}},
}


class Scoped(ast.NodeVisitor):
    """Collects (line, function, what) notes, the function being the qualified name of the def around the node."""

    def __init__(self):
        self.found, self.scope = [], []

    def note(self, node, what):
        self.found.append((node.lineno, ".".join(self.scope) or "<module>", what))

    def visit_FunctionDef(self, node):
        self.scope.append(node.name)
        self.generic_visit(node)
        self.scope.pop()

    visit_AsyncFunctionDef = visit_ClassDef = visit_FunctionDef


class Scanner(Scoped):
    """Every POSIX-only use in one module's tree."""

    def __init__(self):
        super().__init__()
        self.aliases = {}  # local name -> the module it stands for

    def visit_Import(self, node):
        for alias in node.names:
            top = alias.name.split(".")[0]
            self.aliases[alias.asname or top] = alias.name if alias.asname else top
            if top in POSIX_MODULES:
                self.note(node, f"import {top}")

    def visit_ImportFrom(self, node):
        module = (node.module or "").split(".")[0]
        if node.level == 0 and module in POSIX_MODULES:
            self.note(node, f"import {module}")
        for alias in node.names:
            if node.level == 0 and alias.name in POSIX_ONLY.get(module, ()):
                self.note(node, f"{module}.{alias.name}")

    def visit_Attribute(self, node):
        if isinstance(node.value, ast.Name):
            module = self.aliases.get(node.value.id)
            if module in POSIX_ONLY and node.attr in POSIX_ONLY[module] or module in POSIX_MODULES:
                self.note(node, f"{module}.{node.attr}")
            elif module is None and node.attr in SOCKET_METHODS:
                self.note(node, f"socket.{node.attr}")
        self.generic_visit(node)

    def visit_Call(self, node):
        name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
        if name in ("Popen", "run", "call", "check_call", "check_output"):
            for keyword in node.keywords:
                if keyword.arg in POPEN_POSIX_ARGS:
                    self.note(node, f"Popen({keyword.arg}=)")
        if name == "getattr" and len(node.args) == 2 and isinstance(node.args[1], ast.Constant):
            module = self.aliases.get(getattr(node.args[0], "id", None))  # getattr(os, "fork"): no default
            if node.args[1].value in POSIX_ONLY.get(module, ()):
                self.note(node, f"{module}.{node.args[1].value}")
        self.generic_visit(node)


def scan(source):
    """[(line, function, name)] of the POSIX-only uses in source."""
    scanner = Scanner()
    scanner.visit(ast.parse(source))
    return scanner.found


def project_files():
    for folder in SCANNED:
        for here, dirs, files in os.walk(os.path.join(ROOT, folder)):
            dirs[:] = sorted(d for d in dirs if d != "__pycache__")
            for name in sorted(files):
                if name.endswith(".py"):
                    yield os.path.relpath(os.path.join(here, name), ROOT).replace(os.sep, "/")


def project_uses():
    """{file: [(line, function, name)]} over the scanned folders."""
    uses = {}
    for path in project_files():
        with open(os.path.join(ROOT, path), encoding="utf-8") as handle:
            uses[path] = scan(handle.read())
    return uses


def test_no_posix_only_call_outside_the_posix_path():
    """Every POSIX-only use is on the allow-list (file, function, name); any other fails naming file:line."""
    stray = [f"{path}:{line}: {name} in {function} (POSIX only: guard it for Windows/macOS, or if this is the "
             f"POSIX path, add it to ALLOWED in tests/test_portable_calls.py)"
             for path, found in project_uses().items() for line, function, name in found
             if name not in ALLOWED.get(path, {}).get(function, ())]
    assert not stray, "\n".join(stray)


def test_the_allow_list_names_only_uses_that_exist():
    """A stale allow-list entry would let a later use slip in unseen: each one listed is still in its place."""
    uses = project_uses()
    present = {(path, function, name) for path, found in uses.items() for _, function, name in found}
    stale = [f"{path}: {function}: {name}" for path, functions in ALLOWED.items()
             for function, names in functions.items() for name in sorted(names)
             if (path, function, name) not in present]
    assert not stale, "allowed but no longer used (remove from ALLOWED):\n" + "\n".join(stale)


# ------------------------------------------------------------ the scanner's own corpus: what it must find / leave

FOUND = {  # source -> the names the scan must report, in order
    "import resource\nresource.setrlimit(resource.RLIMIT_AS, (1, 1))":
        ["import resource", "resource.setrlimit", "resource.RLIMIT_AS"],
    "import os\ndef f():\n    os.killpg(os.getpgid(0), 9)": ["os.killpg", "os.getpgid"],
    "import os as o\no.setsid()": ["os.setsid"],
    "from os import fork, getcwd\nfork()": ["os.fork"],
    "import signal as s\nx = s.SIGKILL": ["signal.SIGKILL"],
    "from signal import setitimer, SIGINT": ["signal.setitimer"],
    "import pwd.x\n": ["import pwd"],
    "from fcntl import flock": ["import fcntl"],
    "import socket\nsocket.socket(socket.AF_UNIX, socket.SOCK_SEQPACKET)": ["socket.AF_UNIX", "socket.SOCK_SEQPACKET"],
    "def f(sock, fds):\n    sock.send_fds([b'x'], fds)": ["socket.send_fds"],
    "import subprocess\nsubprocess.Popen(['x'], preexec_fn=print, pass_fds=(3,))":
        ["Popen(preexec_fn=)", "Popen(pass_fds=)"],
    "import selectors\nselectors.DefaultSelector()": ["import selectors", "selectors.DefaultSelector"],
    "import select\nselect.select([r], [], [])": ["select.select"],
    "import os\nx = getattr(os, 'setsid')": ["os.setsid"],
    "import shutil\nshutil.chown('f', 'u')": ["shutil.chown"],
}
NOT_FOUND = [  # portable code the scan must leave alone
    "import os\nos.getpid(); os.kill(1, 2); os.dup2(os.open(os.devnull, os.O_WRONLY), 1)",
    "import os\nflag = getattr(os, 'O_NOFOLLOW', 0)",   # guarded: a default where the name is missing
    "import signal\nsignal.signal(signal.SIGINT, signal.SIG_DFL); signal.SIGTERM",
    "import subprocess\nsubprocess.run(['x'], text=True, encoding='utf-8', creationflags=0)",
    "x = 'os.fork() and import resource'  # os.setsid() in a comment",
    "from . import resource\nresource.thing()",   # a project module of the same name, not the stdlib's
    "import socket\nsocket.socketpair(); socket.AF_INET",
]


@pytest.mark.parametrize("source", list(FOUND))
def test_scanner_finds(source):
    assert [name for _, _, name in scan(source)] == FOUND[source]


@pytest.mark.parametrize("source", NOT_FOUND)
def test_scanner_leaves_portable_code(source):
    assert scan(source) == []


def test_scanner_names_the_function_and_line():
    source = textwrap.dedent("""\
        import os
        class Pool:
            def stop(self):
                os.killpg(1, 15)
        """)
    assert scan(source) == [(4, "Pool.stop", "os.killpg")]


# ------------------------------------------------------------ every text file opened with an explicit encoding

OPENERS = {"open", "fdopen"}          # open(), io.open(), codecs.open(), os.fdopen(), Path.open()
TEXT_RUNS = {"run", "Popen", "check_output", "call", "check_call"}
# Known gaps in files another branch owns (issue 32): each is a strict xfail below, so its fix is noticed.
def _keyword(node, name):
    return next((k.value for k in node.keywords if k.arg == name), None)


def _is_true(value):
    return isinstance(value, ast.Constant) and value.value is True


class TextScanner(Scoped):
    """Text I/O that takes the locale's encoding (cp1252 on Windows) in one module's tree."""

    def visit_Call(self, node):
        name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
        method = isinstance(node.func, ast.Attribute)
        has_encoding = _keyword(node, "encoding") is not None
        if name in OPENERS:
            # open(file, mode, buffering, encoding), os.fdopen/io.open likewise; Path.open(mode, buffering, encoding)
            at = 0 if method and getattr(node.func.value, "id", "") not in ("os", "io", "codecs") else 1
            mode = _keyword(node, "mode") or (node.args[at] if len(node.args) > at else ast.Constant("r"))
            binary = not isinstance(mode, ast.Constant) or "b" in str(mode.value)
            if not binary and not has_encoding and len(node.args) <= at + 2:
                self.note(node, f"{name}() in text mode without encoding=")
        elif name in ("read_text", "write_text") and method:
            if not has_encoding and len(node.args) < (1 if name == "read_text" else 2):
                self.note(node, f"{name}() without encoding=")
        elif name in TEXT_RUNS and not has_encoding:
            if _is_true(_keyword(node, "text")) or _is_true(_keyword(node, "universal_newlines")):
                self.note(node, f"{name}(text=True) without encoding=")
        self.generic_visit(node)


def text_scan(source):
    scanner = TextScanner()
    scanner.visit(ast.parse(source))
    return scanner.found


def text_gaps():
    gaps = []
    for path in project_files():
        with open(os.path.join(ROOT, path), encoding="utf-8") as handle:
            gaps += [(path, line, function, what) for line, function, what in text_scan(handle.read())]
    return gaps


def test_every_text_file_is_opened_with_an_encoding():
    """open()/os.fdopen()/Path.open() in text mode, read_text/write_text, subprocess text=True: each names its
    encoding, so a lab, a tool or the checker reads and writes the same bytes on Windows (cp1252) as here."""
    stray = [f"{path}:{line}: {what} in {function}" for path, line, function, what in text_gaps()]
    assert not stray, "\n".join(stray)


TEXT_FOUND = {
    "open('f')": 1, "open('f', 'w')": 1, "open('f', mode='a')": 1, "import os\nos.fdopen(3, 'w')": 1,
    "p.open()": 1, "p.open('w')": 1, "p.read_text()": 1, "p.write_text('x')": 1,
    "import subprocess\nsubprocess.run(['git'], text=True)": 1,
    "subprocess.check_output(['git'], universal_newlines=True)": 1,
}
TEXT_FINE = [
    "open('f', 'rb')", "open('f', encoding='utf-8')", "open('f', 'w', encoding='utf-8', newline='')",
    "import os\nos.fdopen(3, 'wb')", "os.fdopen(fd, 'w', encoding='utf-8')", "p.open('rb')",
    "p.open(encoding='utf-8')", "p.read_text(encoding='utf-8')", "p.write_text('x', encoding='utf-8')",
    "p.read_text('utf-8')", "subprocess.run(['git'], text=True, encoding='utf-8')", "subprocess.run(['git'])",
    "open(path, mode)",  # a mode only known at run time: not judged
]


@pytest.mark.parametrize("source", list(TEXT_FOUND))
def test_text_scanner_finds(source):
    assert len(text_scan(source)) == TEXT_FOUND[source]


@pytest.mark.parametrize("source", TEXT_FINE)
def test_text_scanner_leaves_explicit_encodings(source):
    assert text_scan(source) == []
