"""The constants a probe reads are the handout's (issue 39 item 2), on both sides of the tape (checker/judging/tape.py).

The child puts the handout's values back before each probe and notes a call that leaves one changed; the grader's
replay serves the handout's value whatever the child read, and notes a reading that differs. End to end (a step
that sets PERCENT or BULLET_RADIUS) is tests/corpus_attacks_judge.py's.
"""
import types

from checker.judging import tape

LAB = '''
PERCENT = 0.4
def push(depth):
    global PERCENT
    PERCENT = 0          # the attack: a later reading sees 0
    return depth * 0.4
'''


def _module():
    module = types.ModuleType("lab_under_test")
    exec(compile(LAB, "lab.py", "exec"), module.__dict__)
    return module


def probe(module, lab_path):
    """Reads PERCENT, calls push() twice, reads PERCENT again."""
    first = module.PERCENT
    pushed = [module.push(10.0), module.push(2.0)]
    return {"first": first, "pushed": pushed, "then": module.PERCENT}


def test_the_child_puts_the_handout_back_and_notes_the_call_that_changed_it():
    module = _module()
    module.PERCENT = 7.0   # the file's own value at import (an edit outside the steps)
    recorder = tape.Recorder(module, ["push"], constants={"PERCENT": 0.4})
    result = recorder.run(probe, "lab.py")
    assert result["first"] == 0.4 and result["then"] == 0   # put back before the probe; then the attack's 0
    recorded = recorder.take()
    calls = [entry for entry in recorded if entry["k"] == "call"]
    assert calls[0]["consts"] == {"PERCENT": 0} and "consts" not in calls[1]   # only the call that changed it
    assert tape.changed_constants(recorded, {"PERCENT": 0.4}) == {"push": {"PERCENT": 0}}
    assert recorder.run(lambda module, path: module.PERCENT, "lab.py") == 0.4   # and again before the next probe


def test_the_replay_serves_the_handout_value_and_notes_what_the_child_read():
    module = _module()
    recorder = tape.Recorder(module, ["push"], constants={"PERCENT": 0.4})
    recorder.run(probe, "lab.py")
    recorded = recorder.take()
    namespace = {"PERCENT": 0.4, "push": None}
    replay = tape.Replayer(namespace, ["push"], recorded)
    result = probe(replay, "lab.py")
    assert result == {"first": 0.4, "pushed": [4.0, 0.8], "then": 0.4}   # the handout's value both times
    assert replay.read_constants() == {"PERCENT": 0}                    # the child read 0 the second time
    assert replay.finished()


def test_a_forged_reading_or_a_missing_constant_is_the_handouts():
    forged = [{"k": "const", "name": "PERCENT", "value": {"t": [1, 2]}},
              {"k": "const", "name": "PERCENT", "missing": True},
              {"k": "const", "name": "NOT_IN_THE_HANDOUT", "value": 5}]
    replay = tape.Replayer({"PERCENT": 0.4}, [], forged)
    assert replay.PERCENT == 0.4 and replay.PERCENT == 0.4
    assert getattr(replay, "NOT_IN_THE_HANDOUT", "default") == "default"   # never the child's value
    assert replay.read_constants() == {"PERCENT": {"t": [1, 2]}} and replay.finished()
