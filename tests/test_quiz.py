"""The terminal quiz: its seven questions (two to compute or predict, their answers computed or measured here), and
`python -m lesson11.quiz` driven through stdin."""
import json
import os
import select
import signal
import subprocess
import sys
import time

import pytest

from lesson11 import quiz

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
QUESTIONS = quiz.load_questions()
KEY = [q["answer"] for q in QUESTIONS]


def run_quiz(stdin, *args):
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    return subprocess.run([sys.executable, "-m", "lesson11.quiz", *args], cwd=ROOT, env=env, input=stdin,
                          capture_output=True, text=True, timeout=60)


def wrong(letter):
    return "A" if letter != "A" else "B"


N = len(QUESTIONS)


def test_the_lessons_seven_questions_with_answers_and_one_line_explanations():
    assert N == 7
    topics = ["gap between their shadows", "flip the best axis", "cross(ra, n) ** 2 * a.inv_inertia",
              "jt = max(-mu * j, min(mu * j, jt))", "3000 px/s bullet", "What is k?", "leave the flip out"]
    for item, topic in zip(QUESTIONS, topics):
        assert topic in item["question"]
        assert item["answer"] in "ABCD"
        assert "\n" not in item["explanation"] and len(item["explanation"]) > 40
        assert len(set(item["choices"].values())) == 4
    assert len(set(KEY)) >= 3  # the right answers are not all in one place
    # the right choices say what the lesson says
    assert "separating axis" in QUESTIONS[0]["choices"][KEY[0]]
    assert "from A to B" in QUESTIONS[1]["choices"][KEY[1]]
    assert "turns A instead of moving it" in QUESTIONS[2]["choices"][KEY[2]]
    assert "at most mu times the normal impulse" in QUESTIONS[3]["choices"][KEY[3]]
    assert "swept paths first touch" in QUESTIONS[4]["choices"][KEY[4]]


def test_question_6_the_one_k_the_numbers_give_is_the_right_choice():
    """The k of question 6 computed by physics2d from the question's numbers: only the right choice starts with it,
    and each wrong choice is the number its stated mistake gives."""
    from pygame import Vector2
    from lesson11.physics2d import Body, box_points
    from lesson11.physics2d.response import effective_mass_inverse
    floor = Body(box_points(100, 20), (0, 40), 0)
    crate = Body(box_points(60, 40), (0, 0), 2.4)
    assert crate.inertia == 1040
    rb, normal = Vector2(20, 30), Vector2(0, -1)
    k = effective_mass_inverse(floor, crate, rb + crate.pos - floor.pos, rb, normal)
    item = QUESTIONS[5]
    starts = {letter: float(text.split(":")[0]) for letter, text in item["choices"].items()}
    assert [letter for letter, value in starts.items() if abs(value - k) < 0.005] == [item["answer"]]
    wrong = sorted(value for letter, value in starts.items() if letter != item["answer"])
    assert wrong == pytest.approx(sorted([1 / 2.4, 1 / 2.4 + 30 ** 2 / 1040, 1 / 2.4 + 20 ** 2 * 1040]), abs=0.005, rel=1e-4)
    assert "0.8013" in item["explanation"] and "299.5" in item["explanation"]


def test_question_7_the_right_choice_is_the_hint_tables_row_and_no_other_is():
    """Question 7's mistake is the Hint table's "normal_not_flipped" row (held by tests/test_symptoms.py): the
    right choice names that row's symptom, and no wrong choice names it."""
    from lesson11 import symptoms
    row = next(r for r in symptoms.TABLE if r.key == "normal_not_flipped")
    item = QUESTIONS[6]
    named = {letter: symptoms.kinds_named(text) for letter, text in item["choices"].items()}
    assert row.kind in named[item["answer"]] and "contacts" in item["choices"][item["answer"]]
    assert all(row.kind not in kinds for letter, kinds in named.items() if letter != item["answer"])


def test_no_wrong_choice_is_true_of_the_lesson():
    """Question 2's wrong choices do not describe what the lesson says the library's sat() does (takes the
    smaller of the two ways out on an axis), which would trap a careful reader; question 3 names k as the
    INVERSE effective mass, as section 5 does."""
    second = QUESTIONS[1]
    wrong_choices = [text for letter, text in second["choices"].items() if letter != second["answer"]]
    assert not any(word in text for text in wrong_choices for word in ("smaller of the two", "shorter"))
    assert "inverse effective mass" in QUESTIONS[2]["question"]
    with open(os.path.join(ROOT, "lesson11", "README.md"), encoding="utf-8") as handle:
        lesson = handle.read()
    assert "*inverse* effective mass" in lesson and "is the **inverse** of the *effective mass*" in lesson


def test_the_answer_cannot_be_told_by_its_length():
    """Distractors as long as the answer: the right choice is never more than 10 % longer than the longest
    wrong one, and it is the longest choice in at most one question (it was in 4 of 5, 138 characters
    against at most 78)."""
    longest = 0
    for item in QUESTIONS:
        right = len(item["choices"][item["answer"]])
        wrong_lengths = [len(text) for letter, text in item["choices"].items() if letter != item["answer"]]
        assert right <= 1.1 * max(wrong_lengths), item["question"]
        assert min(wrong_lengths) >= 0.8 * right, item["question"]
        longest += right > max(wrong_lengths)
    assert longest <= 1


def test_long_lines_fold_to_the_terminal(monkeypatch, capsys):
    monkeypatch.setattr(quiz.shutil, "get_terminal_size", lambda fallback=None: os.terminal_size((60, 24)))
    quiz.run_quiz(QUESTIONS[:1], ask=lambda prompt: KEY[0])
    lines = capsys.readouterr().out.splitlines()
    assert max(len(line) for line in lines) <= 59
    assert any(line.startswith("     ") for line in lines)   # a choice's second line, under its text


def test_all_right_scores_seven():
    result = run_quiz("\n".join(KEY) + "\n")
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.count("Right!") == N
    assert f"Score: {N} of {N}." in result.stdout


def test_wrong_answers_are_corrected_with_the_explanation():
    answers = [wrong(k).lower() for k in KEY]  # lower case is accepted
    result = run_quiz("\n".join(answers) + "\n")
    assert result.returncode == 0
    for item in QUESTIONS:
        said = " ".join(result.stdout.split())   # the text folded to the terminal's width, joined again
        assert f"Not quite: the answer is {item['answer']}. {item['explanation']}" in said
    assert "Right!" not in result.stdout
    assert f"Score: 0 of {N}." in result.stdout


def test_bad_input_is_asked_again_and_end_of_input_stops_cleanly():
    stdin = f"E\n\n  {KEY[0]}  \n42\n{wrong(KEY[1])}\n"  # then the input ends during question 3
    result = run_quiz(stdin)
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.count("Please answer with one letter") == 3
    assert "'E'" in result.stdout and "'42'" in result.stdout
    assert f"Question 3 of {N}" in result.stdout and f"Question 4 of {N}" not in result.stdout
    assert "end of input" in result.stdout
    assert f"Score: 1 of {N} ({N - 2} not answered)." in result.stdout


def test_empty_input_ends_with_a_zero_score():
    result = run_quiz("")
    assert result.returncode == 0 and "Traceback" not in result.stderr
    assert f"Score: 0 of {N} ({N} not answered)." in result.stdout


def test_answer_key():
    result = run_quiz("", "--answers")
    lines = result.stdout.splitlines()
    assert [line.split(":")[0] for line in lines] == [f"{n}. {k}" for n, k in enumerate(KEY, start=1)]


@pytest.mark.parametrize("content, message", [
    (None, "cannot read"),
    ("[{\"question\": ", "not valid JSON"),
    ("[]", "non-empty list"),
    (json.dumps([{"question": "q", "choices": {"A": "", "B": "", "C": "", "D": ""}, "answer": "A"}]),
     "question 1 has no 'explanation'"),
    (json.dumps([{"question": "q", "choices": {"A": "", "B": ""}, "answer": "A", "explanation": "e"}]),
     "exactly the letters A, B, C and D"),
    (json.dumps([{"question": "q", "choices": {"A": "", "B": "", "C": "", "D": ""}, "answer": "E",
                  "explanation": "e"}]), "'answer' must be one of"),
])
def test_bad_question_files_give_one_line_errors(tmp_path, content, message):
    path = tmp_path / "questions.json"
    if content is not None:
        path.write_text(content, encoding="utf-8")
    result = run_quiz("", "--questions", str(path))
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr.count("\n") == 1
    assert str(path) in result.stderr and message in result.stderr


def test_run_quiz_in_process_counts_right_and_asked(capsys):
    replies = iter(["x", KEY[0], wrong(KEY[1])])

    def ask(prompt):
        try:
            return next(replies)
        except StopIteration:
            raise EOFError from None

    assert quiz.run_quiz(QUESTIONS, ask) == (1, 2)
    out = capsys.readouterr().out
    assert "Please answer" in out and f"Score: 1 of {N} ({N - 2} not answered)." in out


def test_score_is_out_of_all_questions_even_when_some_are_unanswered():
    assert quiz.score_line(4, 4, 5) == "4 of 5 (1 not answered)"
    assert quiz.score_line(3, 5, 5) == "3 of 5"


def test_ctrl_c_in_process_prints_the_score_so_far_and_main_exits_130(capsys, monkeypatch):
    replies = iter([KEY[0], KEY[1]])

    def ask(prompt):
        try:
            return next(replies)
        except StopIteration:
            raise KeyboardInterrupt from None

    with pytest.raises(KeyboardInterrupt):
        quiz.run_quiz(QUESTIONS, ask)
    out = capsys.readouterr().out
    assert out.rstrip().splitlines()[-1] == f"Stopped (Ctrl-C). Score so far: 2 of {N} ({N - 2} not answered)."

    def interrupted(questions):
        raise KeyboardInterrupt

    monkeypatch.setattr(quiz, "run_quiz", interrupted)
    assert quiz.main([]) == 130


def read_until(stream, text, count=1, seconds=30):
    """Read the child's unbuffered stdout until `text` has appeared `count` times in all; returns all read."""
    seen, deadline = b"", time.monotonic() + seconds
    while seen.count(text.encode()) < count:
        assert time.monotonic() < deadline, f"{text!r} not seen {count} times within {seconds} s; read {seen!r}"
        if select.select([stream], [], [], 0.5)[0]:
            chunk = os.read(stream.fileno(), 4096)
            assert chunk, f"the quiz ended before {text!r}; read {seen!r}"
            seen += chunk
    return seen.decode()


def ctrl_c_as_in_a_terminal():
    """In the child before it starts: SIGINT neither ignored nor blocked, as in a terminal.

    A test runner's worker may run with SIGINT ignored or blocked, and a child inherits both;
    Python then never turns the signal into KeyboardInterrupt. (Once, in a loaded run, the quiz ran on to
    the end of its input and exited 0; this was not confirmed as the cause, but it rules this one out.)
    """
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT stands for Ctrl-C on POSIX only")
def test_ctrl_c_at_the_prompt_is_a_clean_one_line_exit_with_the_score():
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""), PYTHONUNBUFFERED="1")
    proc = subprocess.Popen([sys.executable, "-m", "lesson11.quiz"], cwd=ROOT, env=env, stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, preexec_fn=ctrl_c_as_in_a_terminal)
    try:
        proc.stdin.write((KEY[0] + "\n").encode())  # answer question 1 right, then wait at question 2
        proc.stdin.flush()
        before = read_until(proc.stdout, "Your answer (A-D): ", count=2)
        assert f"Question 2 of {N}" in before and "Right!" in before
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        proc.kill()
    assert proc.returncode == 130
    assert err == b"", err.decode()
    assert out.decode().strip().splitlines() == [f"Stopped (Ctrl-C). Score so far: 1 of {N} ({N - 1} not answered)."]
