"""The probes compute no reference where the student's code runs, and judge from the inputs as given (issue 35).

Each lab's solution is probed in this process as checker/isolation/child.py does it (a
tape.Recorder, tests/test_probe_tape.py `recorded`) and the tape is replayed by
checker/probing.judge as the grading parent does. The real child is a sandboxed
process; what matters here is which code runs on which side of the tape.
  - mechanism 4: no reference helper (`@reference`, checker/judging/probe_kit.py) runs in the child;
    all of them run in the grader, so the verdicts still have their answers;
  - mechanism 5: a tape event may only call a hook the probe itself installed;
  - mechanism 3: a step function that changes a body's mass, inertia, material or shape fails
    with the field named, and the references are computed from twins taken before the call;
  - mechanism 9: a check with nothing to grade fails, saying so;
  - mechanism 10: More Shapes keeps axes 0.01° apart, Ball on the Ramp's contact is on the surface.
"""
import copy
import importlib
import inspect
import os

import pytest

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

from checker import labs
from checker.judging import probe_kit, probing, tape   # noqa: E402
from checker.judging.checks import FAIL, PASS   # noqa: E402
from test_probe_tape import ROOT, function_results, lab_by_id, recorded  # noqa: E402

LAB_IDS = [lab.id for lab in labs.LABS]
from checker.authoring.lab_rules import REFERENCE_NAME   # noqa: E402 (the pattern lint-lab holds a lab to)


def _reference_helpers(module):
    """{name: function} of the module-level helpers marked @reference in `module`."""
    return {name: value for name, value in vars(module).items()
            if callable(value) and getattr(value, "__reference__", False)}


def _spy(monkeypatch, modules, log):
    """Replace every @reference helper of `modules` with one that logs (side, name) and then runs it."""
    for module in modules:
        for name, function in _reference_helpers(module).items():
            def spied(*args, _name=f"{module.__name__}.{name}", _function=function, **kwargs):
                log.append(("child" if tape._IN_CHILD[0] else "grader", _name))
                return _function(*args, **kwargs)
            monkeypatch.setattr(module, name, spied)


@pytest.mark.parametrize("lab_id", LAB_IDS)
def test_every_reference_helper_is_marked(lab_id):
    """Every probe helper named like a reference (reference_*, analytic_*, _*_reference ...) is marked @reference."""
    probes = importlib.import_module(lab_by_id(lab_id).probes)
    named = [name for name, value in vars(probes).items()
             if inspect.isfunction(value) and REFERENCE_NAME.match(name) and value.__module__ in (
                 probes.__name__, "checker.judging.probe_kit", "checker.judging.tape")]
    unmarked = [name for name in named if not getattr(getattr(probes, name), "__reference__", False)]
    assert named and not unmarked, f"{lab_id}: reference helpers not marked @reference: {unmarked}"


@pytest.mark.parametrize("lab_id", LAB_IDS)
def test_no_reference_runs_in_the_child_and_every_verdict_still_has_its_answers(lab_id, tmp_path, monkeypatch):
    lab = lab_by_id(lab_id)
    probes = importlib.import_module(lab.probes)
    log = []
    _spy(monkeypatch, (probes, probe_kit), log)
    path = os.path.join(ROOT, "solutions", f"{lab_id}.py")
    settings, result, source = recorded(lab, path, 7, tmp_path)
    assert not [entry for entry in result["tapes"].values() if "error" in entry], result["tapes"]
    assert not log, f"{lab_id}: reference helpers ran in the child: {sorted(set(log))}"
    statuses, judged = function_results(lab, path, source, settings, result)
    assert all(status == PASS for cid, (status, _) in statuses.items() if cid != "handout_unchanged"), statuses
    ran = {name for side, name in log if side == "grader"}
    assert {side for side, _ in log} == {"grader"}
    assert len(ran) >= 3, f"{lab_id}: the grader computed only {ran}"


def test_a_reference_called_in_the_child_raises():
    """The mark is not a label only: called while a Recorder runs a probe, a reference helper raises."""
    recorder = tape.Recorder(type(os)("lab"), ())
    with pytest.raises(tape.ReferenceInChild):
        recorder.run(lambda module, path: probe_kit.reference_sat([], [], "lesson"), "lab.py")
    assert not tape._IN_CHILD[0]   # and the flag is down again after the probe
    assert probe_kit.reference_sat(probe_kit.box(40, 40, (0, 0)), probe_kit.box(40, 40, (30, 0))) is not None


# ---------------------------------------------------------------- mechanism 5: the tape names a hook


def _forged_event(result, probe, hook):
    forged = copy.deepcopy(result)
    call = next(entry for entry in forged["tapes"][probe]["tape"] if entry.get("k") == "call")
    call["events"] = [{"hook": hook, "state": None, "args": {"t": [{"t": []}, {"d": {}}]}}] + list(call["events"])
    return forged


@pytest.mark.parametrize("hook", ["main", "make_crate", "sat", "__import__", ["main"]])
def test_a_tape_event_may_call_only_a_hook_the_probe_installed(hook, tmp_path, monkeypatch):
    lab = lab_by_id("tumbling_crates")
    path = os.path.join(ROOT, "solutions", "tumbling_crates.py")
    settings, result, _ = recorded(lab, path, 3, tmp_path)
    called = []
    real_exec = exec

    def starter_exec(code, namespace):   # the grader's starter namespace, with its main() watched
        real_exec(code, namespace)
        namespace["main"] = lambda *args, **kwargs: called.append("main")

    monkeypatch.setattr(probing, "exec", starter_exec, raising=False)
    for probe in ("resolve", "apply_impulse"):   # resolve installs apply_impulse; apply_impulse installs nothing
        judged = probing.judge(lab, path, settings, _forged_event(result, probe, hook))
        entry = judged["functions"][probe]
        assert not entry["ok"] and "did not put in the student's place" in entry["error"]["message"], entry
    assert not called, "the grader ran main() because the tape named it"
    judged = probing.judge(lab, path, settings, _forged_event(result, "apply_impulse", "apply_impulse"))
    assert not judged["functions"]["apply_impulse"]["ok"]   # a hook of another probe is no hook of this one
    assert probing.judge(lab, path, settings, result)["functions"]["resolve"]["ok"]


# ---------------------------------------------------------------- mechanism 3: state the function under test changed


def _lab_file(tmp_path, lab_id, replacements):
    """The lab's solution with each (old, new) made once, written to tmp_path/<lab>.py."""
    with open(os.path.join(ROOT, "solutions", f"{lab_id}.py"), encoding="utf-8") as handle:
        source = handle.read()
    for old, new in replacements:
        assert source.count(old) == 1, old
        source = source.replace(old, new)
    path = tmp_path / f"{lab_id}.py"
    path.write_text(source, encoding="utf-8")
    return str(path)


def _statuses(lab_id, path, tmp_path, seed=5):
    lab = lab_by_id(lab_id)
    settings, result, source = recorded(lab, path, seed, tmp_path)
    statuses, _ = function_results(lab, path, source, settings, result)
    return statuses


def test_a_resolve_that_zeroes_the_inertias_and_raises_friction_fails_naming_the_fields(tmp_path):
    """Issue 35's 15/17: step 4 sets inv_inertia = 0 (no spin terms to write), step 5 friction = 1e12 (no clamp)."""
    path = _lab_file(tmp_path, "tumbling_crates", [
        ("    k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia\n",
         "    a.inv_inertia = b.inv_inertia = 0.0\n"),
        ("        jt = max(-mu * j, min(mu * j, jt))\n", "        a.friction = b.friction = 1e12\n")])
    statuses = _statuses("tumbling_crates", path, tmp_path)
    for check in ("resolve_k", "resolve_friction"):
        status, message = statuses[check]
        assert status == FAIL and "resolve() changes the friction, inv_inertia of a body" in message, statuses[check]
    assert statuses["apply_impulse_spin"][0] == PASS and statuses["sat_axes"][0] == PASS


def test_the_resolve_references_come_from_the_bodies_as_given(tmp_path):
    """Without the field guard the verdict would still stand: k, mu and kt are read from twins taken before the call."""
    lab = lab_by_id("tumbling_crates")
    path = _lab_file(tmp_path, "tumbling_crates", [
        ("    k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia\n",
         "    a.inv_inertia = b.inv_inertia = 0.0\n")])
    settings, result, _ = recorded(lab, path, 5, tmp_path)
    judged = probing.judge(lab, path, settings, result)
    cases = judged["functions"]["resolve"]["data"]
    assert judged["functions"]["resolve"]["changed_fields"] == {"resolve": ["inv_inertia"]}
    assert all(case["k"]["right"] != case["k"]["no_spin"] for case in cases if case["masses"][0] and case["masses"][1])
    off = [case for case in cases if abs(case["j"] - (-(1 + case["e"]) * case["vn"] / case["k"]["right"])) > 1e-6]
    assert off, "the reference k followed the inertias the student's resolve() zeroed"


@pytest.mark.parametrize("lab_id, old, new, check, field", [
    ("ball_on_ramp", "    a.pos -= normal * (push * a.inv_mass / total)\n",
     "    a.pos -= normal * (push * a.inv_mass / total)\n    b.mass = b.inv_mass = 0.0\n", "push_out_split",
     "inertia, inv_inertia, inv_mass, mass"),   # mass 0 makes the body static in every derived field (issue 34)
    ("ball_on_ramp", "    jt = -rel.dot(t) / kt  # the impulse that would stop the slip\n",
     "    jt = -rel.dot(t) / kt  # the impulse that would stop the slip\n    b.restitution = 0.9\n",
     "friction_rolls", "restitution"),
    ("bullets", "    bullet.pos += bullet.vel * t\n", "    bullet.pos += bullet.vel * t\n    other.friction = 1.0\n",
     "swept_move_resolves", "friction"),   # (other.inertia = 1.0 on the static wall is now Body's own error)
])
def test_a_step_that_changes_a_body_field_fails_naming_it_in_every_lab(lab_id, old, new, check, field, tmp_path):
    path = _lab_file(tmp_path, lab_id, [(old, new)])
    status, message = _statuses(lab_id, path, tmp_path)[check]
    assert status == FAIL and f"changes the {field} of a body" in message, (status, message)


# ---------------------------------------------------------------- mechanism 9: nothing graded is no pass


def test_resolve_friction_fails_when_resolve_returns_before_step_4(tmp_path):
    path = _lab_file(tmp_path, "tumbling_crates", [
        ("    k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia\n", "    return\n")])
    statuses = _statuses("tumbling_crates", path, tmp_path)
    status, message = statuses["resolve_friction"]
    assert status == FAIL and "resolve() applied no impulse in any of the 10 contacts" in message
    assert "nothing was graded" in message
    assert statuses["resolve_k"][0] == FAIL


def test_resolve_friction_fails_when_no_contact_leaves_a_slip_to_grade():
    from checker.labs.tumbling_crates import checks
    cases = [{"case": "c", "friction": None, "j": 3.0, "mu": 0.5, "calls": 1, "vn": -10.0, "k": {"right": 1.0}}] * 7
    with pytest.raises(checks.Fail, match="left no slip to stop in any of the 7 contacts"):
        _run_check(checks, "resolve_friction", cases)


def _run_check(checks, check_id, data, *values):
    """Run one check's function on probe data `data` given for every probe (bypassing the probe run)."""
    from types import SimpleNamespace
    sub = SimpleNamespace(flags=(), function_steps={}, name="lab.py", source="")
    functions = {probe: {"ok": True, "data": data} for probe in ("resolve", "sat", "sat_step2")}
    return checks.CHECKS.by_id(check_id).call(sub, functions, *values)


def test_sat_normal_fails_when_no_pair_is_a_hit():
    from checker.labs.tumbling_crates import checks
    cases = [{"pair": "p", "order": "A, B", "got": None, "lesson": None, "short": None}] * 4
    with pytest.raises(checks.Fail, match="nothing was graded"):
        _run_check(checks, "sat_normal", cases, cases)


def test_an_empty_probe_is_an_error_not_a_pass():
    from checker.judging import lab_checks
    from types import SimpleNamespace
    sub = SimpleNamespace(flags=(), function_steps={}, name="lab.py")
    with pytest.raises(lab_checks.Error, match="nothing was graded"):
        lab_checks.function_data(sub, {"p": {"ok": True, "data": []}}, "p", "f", 2, None)


# ---------------------------------------------------------------- mechanism 10: two wrong answers that passed


def test_a_cosine_parallel_test_fails_and_is_named(tmp_path):
    path = _lab_file(tmp_path, "more_shapes", [
        ("        if all(abs(cross(axis, kept)) > PARALLEL for kept in axes):\n",
         "        if all(1 - abs(axis.dot(kept)) > PARALLEL for kept in axes):\n")])
    status, message = _statuses("more_shapes", path, tmp_path)["parallel_axes"]
    assert status == FAIL and "1 - |axis · kept| <= PARALLEL" in message and "0.01°" in message, message


def test_a_contact_point_halfway_into_the_overlap_fails_and_is_named(tmp_path):
    path = _lab_file(tmp_path, "ball_on_ramp", [
        ("    return center + normal * radius\n", "    return center + normal * (radius - depth / 2)\n")])
    status, message = _statuses("ball_on_ramp", path, tmp_path)["contact_on_surface"]
    assert status == FAIL and "halfway into the overlap" in message and "surface" in message, message
