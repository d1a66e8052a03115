"""Judging what a run did: the tape of a student's calls replayed in the grader, the probes' shared kit, the check
framework, steps and criteria declared as data, the one-formula rule that names a mistake, and the budget."""
