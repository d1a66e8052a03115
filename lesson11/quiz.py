"""The lesson's quick quiz in the terminal: python -m lesson11.quiz

The lesson's multiple-choice questions (A-D), folded to the terminal's width. After each answer the quiz says whether
it was right and gives a one-line explanation; at the end it prints the score.
An answer that is not A, B, C or D is asked again; end of input (Ctrl-D, or a
closed pipe) stops the quiz cleanly with the score so far, and so does Ctrl-C
(one line, no traceback; exit status 130). The score is always out of all the
questions: "Score: 4 of 5 (1 not answered)."

The questions live in lesson11/quiz_questions.json: a list of objects with
"question", "choices" (A-D), "answer" (a letter) and "explanation".
  python -m lesson11.quiz --questions my_quiz.json   use another question file
  python -m lesson11.quiz --answers                  print the answer key and stop
"""
import argparse
import json
import os
import shutil
import sys
import textwrap

from lesson11.console import safe_output

QUESTIONS_FILE = os.path.join(os.path.dirname(__file__), "quiz_questions.json")
LETTERS = ("A", "B", "C", "D")


class QuizFileError(ValueError):
    """A question file that cannot be used; the message names the file and the problem."""


def load_questions(path=QUESTIONS_FILE):
    """Read and check a question file; returns the list of question dicts.

    Raises QuizFileError (one line, naming the file) when the file is missing,
    is not JSON, or a question lacks its text, its four choices A-D, an answer
    among them, or an explanation.
    """
    try:
        with open(path, encoding="utf-8") as handle:
            questions = json.load(handle)
    except OSError as error:
        raise QuizFileError(f"{path}: cannot read the question file ({error.strerror})") from None
    except json.JSONDecodeError as error:
        raise QuizFileError(f"{path}: not valid JSON (line {error.lineno}: {error.msg})") from None
    if not isinstance(questions, list) or not questions:
        raise QuizFileError(f"{path}: expected a non-empty list of questions")
    for number, item in enumerate(questions, start=1):
        where = f"{path}: question {number}"
        if not isinstance(item, dict):
            raise QuizFileError(f"{where} is not an object")
        for key in ("question", "choices", "answer", "explanation"):
            if key not in item:
                raise QuizFileError(f"{where} has no {key!r}")
        choices = item["choices"]
        if not isinstance(choices, dict) or sorted(choices) != list(LETTERS):
            raise QuizFileError(f"{where}: 'choices' must have exactly the letters A, B, C and D")
        if item["answer"] not in LETTERS:
            raise QuizFileError(f"{where}: 'answer' must be one of A, B, C, D, got {item['answer']!r}")
    return questions


def read_answer(ask):
    """Ask until the reply is a letter A-D (any case, spaces ignored). Returns it, or None at end of input."""
    while True:
        try:
            reply = ask("Your answer (A-D): ")
        except EOFError:
            return None
        letter = reply.strip().upper()
        if letter in LETTERS:
            return letter
        print(f"  Please answer with one letter, A, B, C or D (you typed {reply.strip()!r}).")


def wrap(text, indent=""):
    """`text` folded to the terminal's width (80 columns when it is not a terminal); later lines get `indent`."""
    width = max(40, shutil.get_terminal_size((80, 24)).columns - 1)
    return textwrap.fill(text, width=width, subsequent_indent=indent, break_on_hyphens=False)


def score_line(right, asked, total):
    """The score out of all `total` questions, e.g. "4 of 5 (1 not answered)"."""
    return f"{right} of {total}" + (f" ({total - asked} not answered)" if asked < total else "")


def run_quiz(questions, ask=input):
    """Ask every question, say what was right, and print the score. Returns (right, asked).

    Ctrl-C (KeyboardInterrupt) while a question is open prints the score so far on one
    line and is raised again, so the caller can stop with the right exit status.
    """
    right = asked = 0
    try:
        for number, item in enumerate(questions, start=1):
            print("\n" + wrap(f"Question {number} of {len(questions)}: {item['question']}"))
            for letter in LETTERS:
                print(wrap(f"  {letter}) {item['choices'][letter]}", indent="     "))
            letter = read_answer(ask)
            if letter is None:
                print("\n(end of input: stopping here)")
                break
            asked += 1
            if letter == item["answer"]:
                right += 1
                print(wrap(f"  Right! {item['explanation']}", indent="  "))
            else:
                print(wrap(f"  Not quite: the answer is {item['answer']}. {item['explanation']}", indent="  "))
    except KeyboardInterrupt:
        print(f"\nStopped (Ctrl-C). Score so far: {score_line(right, asked, len(questions))}.")
        raise
    print(f"\nScore: {score_line(right, asked, len(questions))}.")
    return right, asked


def main(argv=None):
    safe_output()
    parser = argparse.ArgumentParser(prog="python -m lesson11.quiz", description="Lesson 11 quick quiz.")
    parser.add_argument("--questions", default=QUESTIONS_FILE, help="question file (JSON)")
    parser.add_argument("--answers", action="store_true", help="print the answer key and stop")
    args = parser.parse_args(argv)
    try:
        questions = load_questions(args.questions)
    except QuizFileError as error:
        print(f"quiz: {error}", file=sys.stderr)
        return 2
    if args.answers:
        for number, item in enumerate(questions, start=1):
            print(f"{number}. {item['answer']}: {item['explanation']}")
        return 0
    print("Lesson 11 quick quiz: SAT & Rotational Collisions")
    try:
        run_quiz(questions)
    except KeyboardInterrupt:
        return 130  # the usual status after Ctrl-C; run_quiz has printed the score so far
    except BrokenPipeError:   # the reader went away (e.g. | head): stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
